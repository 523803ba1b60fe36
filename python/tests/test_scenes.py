"""Loading scenes: from a file, a TOML string or a dict, with the loader's own
messages raised as rkpm.SceneError; the parameter registry as data."""
import pytest

import rkpm
from conftest import bar_scene


def test_a_file_loads_and_names_its_bodies(sag_scene):
    sim = rkpm.Simulation.from_file(sag_scene, threads=1)
    assert sim.name == "sag"
    assert sim.bodies == ["block"]


def test_a_missing_file_is_a_scene_error_naming_it(tmp_path):
    missing = tmp_path / "nowhere.toml"
    with pytest.raises(rkpm.SceneError, match="nowhere.toml"):
        rkpm.Simulation.from_file(str(missing))


def test_a_wrong_key_names_the_file_line_key_and_a_suggestion():
    text = rkpm.scene_to_toml(bar_scene()).replace("cells = ", "cels = ")
    with pytest.raises(rkpm.SceneError) as error:
        rkpm.Simulation.from_string(text, name="typo.toml")
    message = str(error.value)
    assert "typo.toml:" in message and "cels" in message and "cells" in message
    assert isinstance(error.value, ValueError)


def test_an_out_of_range_value_names_the_range():
    scene = bar_scene()
    scene["body"][0]["material"]["mu"] = -1.0
    with pytest.raises(rkpm.SceneError, match=r"mu = -1: expected a real > 0"):
        rkpm.Simulation.from_dict(scene)


def test_a_dict_is_the_same_scene_as_its_toml_text():
    a = rkpm.Simulation.from_dict(bar_scene(), threads=1)
    b = rkpm.Simulation.from_string(rkpm.scene_to_toml(bar_scene()), threads=1)
    assert (a.reference_positions("bar") == b.reference_positions("bar")).all()


def test_a_value_toml_cannot_hold_is_refused_naming_the_key():
    scene = bar_scene()
    scene["body"][0]["material"]["mu"] = {1, 2}
    with pytest.raises(TypeError, match="body.material.mu"):
        rkpm.Simulation.from_dict(scene)


def test_threads_beyond_the_machine_are_refused():
    with pytest.raises(ValueError, match="threads = 100000"):
        rkpm.Simulation.from_dict(bar_scene(), threads=100000)


def test_the_parameter_registry_is_data():
    rows = rkpm.params()
    thickness = [r for r in rows if r["section"] == "body.cloud" and r["variant"] == "shell" and r["key"] == "thickness"]
    assert len(thickness) == 1
    assert thickness[0]["unit"] == "m" and thickness[0]["type"] == "real"
    mode = [r for r in rows if r["section"] == "integrator" and r["key"] == "mode"][0]
    assert mode["choices"] == ["dynamic", "relax"]
