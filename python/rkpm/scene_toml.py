"""A scene given as a dict, written as the TOML text the scene loader reads.

Tables are dicts, arrays of tables lists of dicts (`body`, `term`, a body's
`boundary`), values bools, numbers, strings or lists of them. The loader then
validates the text as it validates a file, with the same messages.
"""
import json
import math


def _value(value, where):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: JSON's escapes are TOML's
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v, where) for v in value) + "]"
    raise TypeError(f"scene key {where}: a {type(value).__name__} cannot be written as TOML; "
                    "expected a bool, number, string or list of them")


def _is_table_list(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, dict) for v in value)


def _table(lines, path, table):
    # Plain keys first: after a sub-table's header they would belong to it.
    for key, value in table.items():
        if not isinstance(value, dict) and not _is_table_list(value):
            lines.append(f"{key} = {_value(value, '.'.join(path + [key]))}")
    for key, value in table.items():
        if isinstance(value, dict):
            lines.append("")
            lines.append(f"[{'.'.join(path + [key])}]")
            _table(lines, path + [key], value)
        elif _is_table_list(value):
            for item in value:
                lines.append("")
                lines.append(f"[[{'.'.join(path + [key])}]]")
                _table(lines, path + [key], item)


def dumps(scene):
    """The TOML text of a scene dict."""
    if not isinstance(scene, dict):
        raise TypeError(f"a scene is a dict of tables, got a {type(scene).__name__}")
    lines = []
    _table(lines, [], scene)
    return "\n".join(lines).lstrip("\n") + "\n"
