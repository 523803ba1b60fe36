#!/usr/bin/python3
"""Tutorial: a cell adhering to an elastic substrate (seed section 4.2), built in Python.

The scene of examples/adhesion/adhesion.toml written as a Python dict: a passive
liquid-crystal-elastomer sphere released just above a Mooney-Rivlin block, pulled down
by the coarse-grained Lennard-Jones contact (seed Eq. 12-14), with surface tension on
both (Eq. 15-17). The run writes frames for ParaView as `rkpm run` does; the script
then plots the contact radius and the cell's height against time from the run's
history, and prints the patch's particles from the position arrays.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/adhesion_tutorial.py

About 70 s on 2 cores at the shipped resolution; `--coarse` runs a coarser cell for the
first 3 us (the substrate keeps its spacing: a coarser one lets the cell fall through,
examples/adhesion/README.md) to try things on.
"""
import argparse
import os

import numpy

import rkpm

MICRON = 1e-6


def adhesion_scene(cell_cells=22, substrate_cells=(40, 40, 4), t_end=8e-6):
    """The seed's adhesion example as a dict: the TOML file's tables as dicts, its arrays
    of tables ([[body]], [[term]]) as lists. Every key is in the parameter reference
    (rkpm.params())."""
    s0 = 0.75 * MICRON            # the potential's length: the substrate's spacing / 1.25
    radius = 5 * MICRON
    # Released 200 nm beyond the flat-body equilibrium gap 0.6368 s0 (examples/adhesion/README.md).
    lowest_point = 0.6368 * s0 + 0.2 * MICRON
    block_height = 4.5 * MICRON
    cell = {
        "name": "cell",
        "density": 1000.0,
        "cloud": {"generator": "sphere", "center": [0.0, 0.0, block_height + lowest_point + radius],
                  "radius": radius, "cells": cell_cells},
        "material": {"model": "lce", "mu": 1e4, "bulk": 1e5, "s": 2.0, "kappa": 1e-11},
        "director": {"initial": "surface_normal", "boundary": "normal"},
    }
    substrate = {
        "name": "substrate",
        "density": 1000.0,
        "cloud": {"generator": "block", "origin": [-18.75 * MICRON, -18.75 * MICRON, 0.0],
                  "size": [37.5 * MICRON, 37.5 * MICRON, block_height], "cells": list(substrate_cells)},
        "material": {"model": "mooney_rivlin", "c1": 2.126e3, "c2": 1.7e2, "lambda": 1.7e5},
        "boundary": [{"surface": "zmin", "type": "fixed"}],
    }
    return {
        "scene": {"name": "adhesion_tutorial",
                  "description": "LCE sphere landing on and adhering to a Mooney-Rivlin block (seed 4.2)"},
        "integrator": {"mode": "dynamic", "t_end": t_end, "damping": 5e5},
        "output": {"every": 0.25e-6},
        "body": [cell, substrate],
        "term": [
            {"type": "contact", "bodies": ["cell", "substrate"], "s0": s0, "epsilon": 3.265e-15,
             "beta": [1e18, 1e18], "report_surface": "zmax"},
            {"type": "surface_tension", "body": "cell", "gamma": 1e-3},
            {"type": "surface_tension", "body": "substrate", "surface": "zmax", "gamma": 1e-3},
        ],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "adhesion_tutorial"))
    parser.add_argument("--coarse", action="store_true", help="14 cells across the cell, 3 us")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()

    scene = adhesion_scene(cell_cells=14, t_end=3e-6) if args.coarse else adhesion_scene()
    sim = rkpm.Simulation.from_dict(scene, threads=args.threads)
    print("bodies:", sim.bodies)

    def progress(step, time):  # called after every step; Ctrl-C stops the run cleanly
        if step % 200 == 0:
            print(f"  step {step:6d}  t = {time / MICRON:.2f} us", flush=True)

    sim.run(out=args.out, progress=progress)
    summary = sim.summary()
    print("status:", summary["status"], " steps:", summary["steps"], f" wall time: {summary['wall_time']:.1f} s")

    # The history: one row per frame, the contact term's columns included.
    h = sim.history()
    t_us = h["time"] / MICRON
    print(f"contact radius at the end: {h['contact_radius'][-1] / MICRON:.2f} um, "
          f"smallest gap {h['min_gap'][-1] / MICRON:.3f} um")

    # The fields as arrays: the cell's particles within 1.2 s0 of the block's top face.
    x = sim.positions("cell")
    top = sim.positions("substrate")[:, 2].max()
    near = x[:, 2] - top < 1.2 * scene["term"][0]["s0"]
    print(f"cell particles near the substrate: {int(near.sum())} of {len(x)}; "
          f"their largest distance from the axis {numpy.hypot(x[near, 0], x[near, 1]).max() / MICRON:.2f} um")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (radius_axes, height_axes) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    radius_axes.plot(t_us, h["contact_radius"] / MICRON, "o-", ms=3)
    radius_axes.set_ylabel("contact radius [um]")
    radius_axes.grid(True)
    height_axes.plot(t_us, h["centroid_z"] / MICRON, "o-", ms=3, color="C1")
    height_axes.set_ylabel("cell centroid height [um]")
    height_axes.set_xlabel("time [us]")
    height_axes.grid(True)
    fig.suptitle("A cell adhering to a Mooney-Rivlin substrate (seed 4.2)")
    figure = os.path.join(args.out, "contact_radius.png")
    fig.savefig(figure, dpi=100)
    print("wrote", figure, "and", os.path.join(args.out, "frames.pvd"), "(open it in ParaView)")


if __name__ == "__main__":
    main()
