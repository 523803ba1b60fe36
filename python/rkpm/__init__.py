"""rkpm from Python: scenes, runs and fields as NumPy arrays.

    import rkpm
    sim = rkpm.Simulation.from_file("examples/rbc/rbc.toml", threads=2)
    sim.run()                          # as `rkpm run`: frames, history.csv, summary.json
    print(sim.summary()["status"])
    xyz = sim.positions("cell")        # (n, 3) current positions, as the frames write them

docs/guide/python.md describes the whole interface.
"""
from ._rkpm import SceneError, SetupError, Simulation, Unstable, params
from .scene_toml import dumps as scene_to_toml


def _from_dict(scene, threads=0, name="scene.toml"):
    """A simulation from a scene given as a dict (the TOML file's structure: tables as
    dicts, arrays of tables such as `body` and `term` as lists of dicts)."""
    return Simulation.from_string(scene_to_toml(scene), name=name, threads=threads)


Simulation.from_dict = staticmethod(_from_dict)

__all__ = ["Simulation", "SceneError", "SetupError", "Unstable", "params", "scene_to_toml"]
