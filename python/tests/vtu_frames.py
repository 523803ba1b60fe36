"""Reads the point fields of a frame rkpm wrote (VTK XML, appended raw data, zlib
blocks with UInt64 headers): an independent check of the module's arrays."""
import re
import struct
import zlib

import numpy as np


def read_point_fields(path):
    data = open(path, "rb").read()
    start = data.index(b'<AppendedData encoding="raw">') + len(b'<AppendedData encoding="raw">')
    start = data.index(b"_", start) + 1
    header = data[:start].decode("latin-1")
    fields = {}
    for match in re.finditer(r"<DataArray ([^>]*)/>", header):
        attributes = dict(re.findall(r'(\w+)="([^"]*)"', match.group(1)))
        if attributes.get("format") != "appended" or attributes["type"] != "Float64":
            continue
        at = start + int(attributes["offset"])
        blocks, _, _ = struct.unpack_from("<3Q", data, at)
        sizes = struct.unpack_from(f"<{blocks}Q", data, at + 24)
        at += 24 + 8 * blocks
        raw = b""
        for size in sizes:
            raw += zlib.decompress(data[at:at + size])
            at += size
        values = np.frombuffer(raw, dtype="<f8")
        components = int(attributes.get("NumberOfComponents", "1"))
        fields[attributes.get("Name", "Points")] = values.reshape(-1, components) if components > 1 else values
    return fields
