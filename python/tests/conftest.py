"""Shared helpers of the Python module's tests: the repository's paths, a small scene
as a dict, and a reader of the frames rkpm writes."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("RKPM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def bar_scene(tension=300.0, mode="relax"):
    """The embedding example's neo-Hookean bar, 1 x 0.6 x 0.6 m, pulled at both ends."""
    return {
        "scene": {"name": "python_bar"},
        "integrator": {"mode": mode, "relax_force_tol": 1e-7, "relax_velocity_tol": 1e-12},
        "body": [{
            "name": "bar",
            "cloud": {"generator": "block", "size": [1.0, 0.6, 0.6], "cells": [6, 4, 4]},
            "material": {"model": "neo_hookean", "mu": 1000.0, "lambda": 4000.0},
        }],
        "term": [
            {"type": "surface_pressure", "body": "bar", "surface": "xmin", "pressure": -tension},
            {"type": "surface_pressure", "body": "bar", "surface": "xmax", "pressure": -tension},
        ],
    }


@pytest.fixture
def sag_scene():
    return str(SOURCE / "examples" / "sag" / "sag.toml")
