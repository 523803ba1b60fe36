"""rkpm from Python: scenes, runs and fields as NumPy arrays.

    import rkpm
    sim = rkpm.Simulation.from_file("examples/rbc/rbc.toml", threads=2)
    sim.run()                          # as `rkpm run`: frames, history.csv, summary.json
    print(sim.summary()["status"])
    xyz = sim.positions("cell")        # (n, 3) current positions, as the frames write them

docs/guide/python.md describes the whole interface.
"""
from . import _rkpm
from ._rkpm import SceneError, SetupError, Simulation, Unstable, params


def _join_mpi_if_launched():
    """Under mpirun, every rank runs each simulation's share, as the rkpm program does:
    mpi4py initialises MPI (and finalises it at exit) and rkpm joins its world."""
    if not _rkpm._launched_by_mpi():
        return
    try:
        from mpi4py import MPI  # noqa: F401  (initialises MPI)
    except ImportError as e:
        raise ImportError("rkpm was started by an MPI launcher but mpi4py is missing: install python3-mpi4py "
                          "(scripts/install-deps.sh does), or run without mpirun") from e
    _rkpm._join_mpi()


_join_mpi_if_launched()
from .scene_toml import dumps as scene_to_toml


def _from_dict(scene, threads=0, name="scene.toml"):
    """A simulation from a scene given as a dict (the TOML file's structure: tables as
    dicts, arrays of tables such as `body` and `term` as lists of dicts)."""
    return Simulation.from_string(scene_to_toml(scene), name=name, threads=threads)


def _history(self):
    """history.csv of the last run() as a dict of column name -> float64 array (one
    entry per history row: every frame, and the last step)."""
    import csv
    import os

    import numpy

    path = os.path.join(self.out_dir, "history.csv")
    if not self.out_dir or not os.path.exists(path):
        raise RuntimeError(f"history(): no history.csv in '{self.out_dir}'; call run() first")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], rows[1:]
    return {name: numpy.array([float(r[k]) for r in values]) for k, name in enumerate(header)}


def _director(self, body):
    """(n, 3) director h of an LCE body (a read-only view), None for other bodies: the
    field the LCE material declares under that name (material_field)."""
    return self.material_field(body, "director")


Simulation.from_dict = staticmethod(_from_dict)
Simulation.director = _director
Simulation.history = _history

__all__ = ["Simulation", "SceneError", "SetupError", "Unstable", "params", "scene_to_toml"]
