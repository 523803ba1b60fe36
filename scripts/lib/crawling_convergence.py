"""The crawling scene's drift at several resolutions of cell and substrate together (the
driver of `scripts/study crawling-convergence`; its header says what it writes).

Each resolution is examples/crawling/crawling.toml with the cell's `cells` (odd, so that
the surface-normal director is defined at the centre) and the block's cells scaled with
it (lateral and vertical spacing kept at the shipped ratio to the cell's, 1.59), the
contact law unchanged (s0 = 0.75 um: the block's spacing stays below 1.25 s0). At each,
the graded substrate (Eq. 18, stiffer towards +y), the uniform one (the graded mean) and
the mirrored gradient. A run folder that already holds a summary.json is kept.

With --long, the graded runs alone go on to LONG_T_END (2.5 times the shipped 12 us),
so that the drift velocity's approach to steady is seen at every resolution; the
controls are exact by symmetry (mirrored) or zero to round-off (uniform) at 12 us and
are not repeated.

With --split, the graded run to LONG_T_END with the cell and the substrate resolved
independently (SPLIT_RUNS): the cell at 17 cells across on blocks from the shipped 40 to
68 cells across, and at 29 on the coarsest and finest of them, and the shipped pair with
the cell's start moved along y by a quarter, a half and three quarters of the block's
spacing: which body's resolution, which ratio of the two clouds' spacings and which
registry of the two lattices moves the crawl. The runs that match the
ladder's pairs are the --long runs (their folders are shared).

With --registry, the ladder to LONG_T_END with the cell's start at REGISTRY_SHIFTS of the
block's spacing along y at every resolution: the velocity averaged over the two lattices'
registry, with the standard error of that mean (--cells limits the resolutions). The
unshifted runs are the --long runs, the 17-cell shifted ones --split's.

With --fine, what sets the crawl's velocity and its resolution dependence (`fine_runs`):
the ladder on a block 0.5 s0 apart along x and y (100 x 100 cells, its cells along z
refined with the cell), its coarsest with the cell's start moved by half that spacing,
the two finest on a block also 0.5 s0 apart along z, and the cell at 17 and 29 cells on
blocks of 4 to 7 cells along z (the --split runs). Each row gets the contact energy at the
end and the velocity of an overdamped cell under the force that energy implies
(`overdamped_velocity`)."""
import csv
import json
import math
import os
import sys

import numpy as np

from convergence_fit import richardson
from contact_theory import cutoff_or_default
from layered_contact import adhesion_ratio, cloud_layer_spacings
from study_runs import study_parser, write_results, load_scene, run_scene, study_load, study_wall_seconds

SCENE = "examples/crawling/crawling.toml"
# run: (grade_a, grade_b) of Eq. 18's factor grade_a (y - y_min) / L0 + grade_b.
RUNS = {"graded": (4.0, 0.5), "uniform": (0.0, 2.5), "mirrored": (-4.0, 4.5)}
FULL_CELLS = (17, 21, 25, 29)
COARSE_CELLS = (17, 21)
SHIPPED_CELLS = 17
LONG_T_END = 30e-6
REGISTRY_SHIFTS = (0.0, 0.25, 0.5, 0.75)
# (cells across the cell, the block's cells along x and y (its cells along z follow), the
# cell's start moved along y by this fraction of the block's spacing)
SPLIT_RUNS = ((17, 40, 0.0), (17, 44, 0.0), (17, 48, 0.0), (17, 52, 0.0), (17, 56, 0.0), (17, 60, 0.0), (17, 64, 0.0),
              (17, 68, 0.0), (29, 40, 0.0), (29, 68, 0.0), (17, 40, 0.25), (17, 40, 0.5), (17, 40, 0.75))
CSV_COLUMNS = ["run", "cells", "particles", "drift_m", "velocity_m_per_s", "wall_s", "substrate_cells",
               "velocity_earlier_m_per_s", "drift_x_m", "t_end_s", "steps", "energy_error"]


def variant(cells, grading, t_end=None, block_cells=None, shift=0.0, substrate=None):
    """The scene at `cells` across the cell, the block refined with it (or with
    `block_cells` along x and y, its cells along z in the shipped proportion, or with the
    cells `substrate` = [x, y, z]), the cell's start moved along y by `shift` block
    spacings, and `grading` (run to `t_end` when given, else the shipped 12 us)."""
    scene = load_scene(SCENE)
    if t_end is not None:
        scene["integrator"]["t_end"] = t_end
    cell, block = scene["body"]
    shipped = block["cloud"]["cells"]
    cell["cloud"]["cells"] = cells
    scale = cells / SHIPPED_CELLS if block_cells is None else block_cells / shipped[0]
    block["cloud"]["cells"] = [round(n * scale) for n in shipped]
    if substrate is not None:
        block["cloud"]["cells"] = list(substrate)
    cell["cloud"]["center"][1] += shift * block["cloud"]["size"][1] / block["cloud"]["cells"][1]
    block["material"]["grade_a"], block["material"]["grade_b"] = grading
    scene["scene"]["name"] = f"crawling_c{cells}"
    return scene


# At zero load JKR's contact radius grows as w^(1/3), so the contact energy, w times the
# patch's area, as w^(5/3): the exponent that maps the layered bodies' adhesion energy
# error onto the contact energy and the velocity.
CONTACT_ENERGY_EXPONENT = 5.0 / 3.0
# --fine's own runs: (cells across the cell, the block's cells [x, y, z], the cell's start
# moved along y by this fraction of the block's spacing, the group the row belongs to);
# `fine_runs` adds the matched ladder's registry runs.
FINE_RUNS = ((17, (100, 100, 4), 0.0, "fine x, y"), (21, (100, 100, 5), 0.0, "fine x, y"),
             (25, (100, 100, 6), 0.0, "fine x, y"), (29, (100, 100, 7), 0.0, "fine x, y"),
             (17, (100, 100, 4), 0.5, "registry"),
             (25, (100, 100, 12), 0.0, "fine x, y, z"), (29, (100, 100, 12), 0.0, "fine x, y, z"),
             (17, (40, 40, 4), 0.0, "split"), (17, (48, 48, 5), 0.0, "split"), (17, (56, 56, 6), 0.0, "split"),
             (17, (68, 68, 7), 0.0, "split"), (29, (40, 40, 4), 0.0, "split"), (29, (68, 68, 7), 0.0, "split"))


def fine_runs():
    """FINE_RUNS, then the matched ladder's runs at every registry shift (--registry's)."""
    matched = {cells: tuple(variant(cells, RUNS["graded"])["body"][1]["cloud"]["cells"]) for cells in FULL_CELLS}
    return FINE_RUNS + tuple((cells, matched[cells], shift, "matched")
                             for cells in FULL_CELLS for shift in REGISTRY_SHIFTS)


def history(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("time", "centroid_x", "centroid_y", "energy_error")}


def slope(t, y, lo, hi):
    """The least-squares slope of y(t) over lo <= t <= hi."""
    m = (t >= lo) & (t <= hi)
    return float(np.polyfit(t[m], y[m], 1)[0])


def measure(run, cells, folder, scene):
    """The CSV row of one run: drift along y at the end, the drift velocity over the last
    quarter of the run and over the quarter before (steady when they agree)."""
    h = history(folder)
    summary = json.load(open(os.path.join(folder, "summary.json")))
    t, y = h["time"], h["centroid_y"] - h["centroid_y"][0]
    T = t[-1]
    return {"run": run, "cells": cells, "particles": summary["total_particles"], "drift_m": float(y[-1]),
            "velocity_m_per_s": slope(t, y, 0.75 * T, T), "wall_s": study_wall_seconds(folder),
            "substrate_cells": "x".join(str(n) for n in scene["body"][1]["cloud"]["cells"]),
            "velocity_earlier_m_per_s": slope(t, y, 0.5 * T, 0.75 * T),
            "drift_x_m": float(h["centroid_x"][-1] - h["centroid_x"][0]), "t_end_s": float(T),
            "steps": summary["steps"], "energy_error": float(abs(h["energy_error"][-1]))}


def estimates(rows):
    """Richardson estimates of the graded drift and velocity over the cell's spacing."""
    graded = [r for r in rows if r["run"] == "graded"]
    if len(graded) < 3:
        return {}
    h = [10e-6 / r["cells"] for r in graded]
    return {key: richardson(h, [r[key] for r in graded]) for key in ("drift_m", "velocity_m_per_s")}


def richardson_line(name, e, scale, unit, error_bar=""):
    """A table's bullet for the Richardson estimate `e` of `name`, in `unit` (its SI value
    times `scale`), or why there is none."""
    if e.monotone:
        return (f"- Richardson estimate of {name}: {e.q_inf * scale:.3f} +- {e.gci * scale:.3f} {unit}{error_bar}, "
                f"observed order {e.order:.2f}")
    return (f"- {name}: the three finest do not converge monotonically (spread x 1.25: {e.gci * scale:.3f} {unit}); "
            f"no Richardson estimate")


def table(rows, est, loads):
    lines = ["| cells | substrate cells | particles | run | drift along y [nm] | velocity, last quarter [nm/us] | "
             "quarter before [nm/us] | drift along x [nm] | steps | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['cells']} | {r['substrate_cells']} | {r['particles']:,} | {r['run']} | "
                     f"{r['drift_m'] * 1e9:.2f} | {r['velocity_m_per_s'] * 1e3:.3f} | "
                     f"{r['velocity_earlier_m_per_s'] * 1e3:.3f} | {r['drift_x_m'] * 1e9:.2g} | {r['steps']} | "
                     f"{r['wall_s']:.0f} |")
    lines.append("")
    by = {(r["run"], r["cells"]): r for r in rows}
    cells = sorted({r["cells"] for r in rows})
    for c in (c for c in cells if ("uniform", c) in by and ("mirrored", c) in by):
        g, u, m = by[("graded", c)], by[("uniform", c)], by[("mirrored", c)]
        lines.append(f"- {c} cells: |uniform| / |graded| drift {abs(u['drift_m']) / abs(g['drift_m']):.2g}, "
                     f"mirrored / graded {m['drift_m'] / g['drift_m']:.4f} (criteria: < 0.1; -1)")
    if len(cells) >= 2:
        a, b = by[("graded", cells[-2])], by[("graded", cells[-1])]
        for key, name in (("drift_m", "drift"), ("velocity_m_per_s", "velocity")):
            d = abs(b[key] - a[key]) / abs(b[key])
            lines.append(f"- graded {name}, two finest: {a[key] * 1e9 if key == 'drift_m' else a[key] * 1e3:.3f} and "
                         f"{b[key] * 1e9 if key == 'drift_m' else b[key] * 1e3:.3f} "
                         f"{'nm' if key == 'drift_m' else 'nm/us'}, {100 * d:.1f} % apart (criterion: within 10 %): "
                         f"{'met' if d <= 0.1 else 'not met'}")
    for key, e in est.items():
        scale, unit = (1e9, "nm") if key == "drift_m" else (1e3, "nm/us")
        lines.append(richardson_line(f"the graded {key.split('_')[0]}", e, scale, unit,
                                     " (finest run's grid convergence index)"))
    lines.append(f"- machine load (1-minute average) after the runs: {', '.join(sorted(set(loads)))}")
    return "\n".join(lines) + "\n"


def plot(rows, est, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for run, marker in zip(RUNS, "o^v"):
        mine = [r for r in rows if r["run"] == run]
        if not mine:
            continue
        axes[0].plot([r["particles"] for r in mine], [r["drift_m"] * 1e9 for r in mine], marker + "-", label=run)
    axes[0].set_xscale("log")
    axes[0].set_xlabel("particles (cell and substrate)")
    axes[0].set_ylabel("drift along y at the end [nm]")
    axes[0].axhline(0.0, color="grey", lw=0.8)
    axes[0].legend()
    graded = [r for r in rows if r["run"] == "graded"]
    e = est.get("drift_m")
    if e is not None and e.monotone:
        reference, label = e.q_inf, f"|drift - Richardson estimate ({e.q_inf * 1e9:.2f} nm)|"
    else:
        reference, label = graded[-1]["drift_m"], "|drift - finest run's drift| (no Richardson estimate)"
    shown = [r for r in graded if r["drift_m"] != reference]
    axes[1].loglog([r["wall_s"] for r in shown], [abs(r["drift_m"] - reference) * 1e9 for r in shown], "o-",
                   label=label)
    if e is not None:
        axes[1].errorbar([graded[-1]["wall_s"]], [abs(graded[-1]["drift_m"] - reference) * 1e9 or e.gci * 1e9],
                         yerr=[[0.0], [e.gci * 1e9]], fmt="none", ecolor="grey", capsize=4,
                         label="finest run's grid convergence index" if e.monotone
                         else "spread of the three finest x 1.25")
    axes[1].set_xlabel("wall time of the graded run [s], 2 threads")
    axes[1].set_ylabel("estimated error of the graded drift [nm]")
    axes[1].grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=8)
    fig.suptitle("Crawling on a graded substrate: drift against resolution and run time")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def spacings(scene):
    """The cell's and the block's lateral particle spacings [m] of a crawling scene."""
    cell, block = scene["body"]
    return (2.0 * cell["cloud"]["radius"] / cell["cloud"]["cells"],
            block["cloud"]["size"][0] / block["cloud"]["cells"][0])


def split_table(rows, scenes, loads):
    """The generated Markdown of --split: the crawl with each body resolved on its own."""
    s0 = load_scene(SCENE)["term"][0]["s0"]
    lines = ["| cells across the cell | substrate cells | substrate spacing / s0 | substrate spacing / cell spacing | "
             "start moved along y [substrate spacings] | particles | velocity, last quarter [nm/us] | "
             "quarter before [nm/us] | drift along y [nm] | steps | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for (_, _, shift), r, scene in zip(SPLIT_RUNS, rows, scenes):
        cell, block = spacings(scene)
        lines.append(f"| {r['cells']} | {r['substrate_cells']} | {block / s0:.3f} | {block / cell:.3f} | {shift:g} | "
                     f"{r['particles']:,} | {r['velocity_m_per_s'] * 1e3:.3f} | "
                     f"{r['velocity_earlier_m_per_s'] * 1e3:.3f} | {r['drift_m'] * 1e9:.2f} | {r['steps']} | "
                     f"{r['wall_s']:.0f} |")
    v = {run: r["velocity_m_per_s"] for run, r in zip(SPLIT_RUNS, rows)}
    coarse = (17, 40, 0.0)
    lines.append("")
    for run, name in (((17, 68, 0.0), "the substrate alone"), ((29, 40, 0.0), "the cell alone"),
                      ((29, 68, 0.0), "both")):
        lines.append(f"- refining {name} (cell 17 -> 29 cells, block 40 -> 68): velocity x {v[run] / v[coarse]:.3f} "
                     f"({100 * (v[run] / v[coarse] - 1):+.1f} %)")
    for label, runs in (("the cell at 17 cells on the eight blocks", [k for k in SPLIT_RUNS if k[0] == 17 and k[2] == 0]),
                        ("the cell at 17 cells on the 40-cell block, its start at four places",
                         [k for k in SPLIT_RUNS if k[:2] == (17, 40)])):
        values = np.array([v[k] for k in runs]) * 1e3
        lines.append(f"- {label}: velocity {values.mean():.2f} nm/us on average, from {values.min():.2f} to "
                     f"{values.max():.2f} (standard deviation {values.std(ddof=1):.2f}, "
                     f"{100 * values.std(ddof=1) / values.mean():.0f} %)")
    lines.append(f"- machine load (1-minute average) after the runs: {', '.join(sorted(set(loads)))}")
    return "\n".join(lines) + "\n"


def split_plot(rows, scenes, path):
    """The steady velocity against the ratio of the block's spacing to the cell's, one
    line per cell resolution."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.4))
    for cells, marker in ((17, "o-"), (29, "s-")):
        mine = [(spacings(scene), r) for (c, _, shift), r, scene in zip(SPLIT_RUNS, rows, scenes)
                if c == cells and shift == 0.0]
        ax.plot([b / c for (c, b), _ in mine], [r["velocity_m_per_s"] * 1e3 for _, r in mine], marker,
                label=f"cell {cells} cells across")
    moved = [(spacings(scene), r) for (_, _, shift), r, scene in zip(SPLIT_RUNS, rows, scenes) if shift]
    if moved:
        ax.plot([b / c for (c, b), _ in moved], [r["velocity_m_per_s"] * 1e3 for _, r in moved], "o", mfc="none",
                color="C0", label="cell 17, its start moved by 1/4, 1/2, 3/4 of the block's spacing")
    ax.set_xlabel("substrate spacing / cell spacing")
    ax.set_ylabel(f"drift velocity over the last quarter of {LONG_T_END * 1e6:g} us [nm/us]")
    ax.legend(fontsize=8, loc="upper center")
    ax.grid(True, alpha=0.3)
    ax.set_title("Crawl with the cell and the substrate resolved independently")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def run_long_graded(args, cells, block_cells=None, shift=0.0, substrate=None):
    """The graded run to LONG_T_END at `cells`, on the matched block or another
    (`block_cells` or `substrate`), the cell's start moved by `shift` block spacings
    (`variant`), in a folder named by what differs from the ladder (shared by --long,
    --split, --registry and --fine); returns its row (with its folder), its scene and the
    load after it."""
    scene = variant(cells, RUNS["graded"], LONG_T_END, block_cells, shift, substrate)
    block = scene["body"][1]["cloud"]["cells"]
    if block == variant(cells, RUNS["graded"])["body"][1]["cloud"]["cells"]:
        substrate = ""
    elif block == variant(cells, RUNS["graded"], block_cells=block[0])["body"][1]["cloud"]["cells"]:
        substrate = f"_b{block[0]}"
    else:
        substrate = "_b" + "x".join(map(str, block))
    name = f"graded_c{cells}{substrate}" + (f"_y{shift:g}" if shift else "") + f"_t{LONG_T_END * 1e6:g}us"
    folder = run_scene(args.rkpm, scene, os.path.join(args.out, name), args.threads)
    row = dict(measure("graded", cells, folder, scene), folder=folder)
    print(f"cell {cells}, substrate {row['substrate_cells']}, start moved {shift:g}: velocity "
          f"{row['velocity_m_per_s'] * 1e3:.3f} nm/us, {row['wall_s']:.0f} s", flush=True)
    return row, scene, study_load(folder)


def run_split(args):
    rows, scenes, loads = zip(*(run_long_graded(args, *run) for run in SPLIT_RUNS))
    write_results(args.out, "crawling_convergence_split", rows, CSV_COLUMNS, split_table(rows, scenes, loads),
                  lambda path: split_plot(rows, scenes, path))
    return 0


def registry_means(rows):
    """Per resolution: (cells, particles, mean velocity, its standard error, the wall time
    of all its runs) over the registries run."""
    out = []
    for cells in sorted({r["cells"] for r in rows}):
        mine = [r for r in rows if r["cells"] == cells]
        v = np.array([r["velocity_m_per_s"] for r in mine])
        error = v.std(ddof=1) / math.sqrt(len(v)) if len(v) > 1 else math.nan
        out.append((cells, mine[0]["particles"], float(v.mean()), float(error), sum(r["wall_s"] for r in mine)))
    return out


def registry_table(rows, shifts, loads):
    """The generated Markdown of --registry."""
    lines = ["| cells | substrate cells | particles | start moved along y [substrate spacings] | "
             "velocity, last quarter [nm/us] | quarter before [nm/us] | drift along y [nm] | wall [s] |",
             "|---|---|---|---|---|---|---|---|"]
    for shift, r in zip(shifts, rows):
        lines.append(f"| {r['cells']} | {r['substrate_cells']} | {r['particles']:,} | {shift:g} | "
                     f"{r['velocity_m_per_s'] * 1e3:.3f} | {r['velocity_earlier_m_per_s'] * 1e3:.3f} | "
                     f"{r['drift_m'] * 1e9:.2f} | {r['wall_s']:.0f} |")
    means = registry_means(rows)
    lines.append("")
    for cells, particles, mean, error, wall in means:
        lines.append(f"- {cells} cells ({particles:,} particles): velocity over the registries {mean * 1e3:.3f} "
                     f"+- {error * 1e3:.3f} nm/us (standard error of the mean), {wall:.0f} s of runs")
    if len(means) >= 2:
        (_, _, a, ea, _), (_, _, b, eb, _) = means[-2], means[-1]
        d = abs(b - a) / abs(b)
        lines.append(f"- two finest means: {a * 1e3:.3f} and {b * 1e3:.3f} nm/us, {100 * d:.1f} % apart, "
                     f"their standard errors {100 * ea / abs(a):.0f} % and {100 * eb / abs(b):.0f} % "
                     f"(criterion: within 10 %): {'met' if d <= 0.1 else 'not met'}")
    if len(means) >= 3:
        e = richardson([10e-6 / m[0] for m in means], [m[2] for m in means])
        lines.append(richardson_line("the mean velocity", e, 1e3, "nm/us"))
    lines.append(f"- machine load (1-minute average) after the runs: {', '.join(sorted(set(loads)))}")
    return "\n".join(lines) + "\n"


def registry_plot(rows, path):
    """Each registry's velocity and their mean with its standard error against the
    cell's spacing (left), and the mean's standard error against the wall time of a
    resolution's runs (right)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    axes[0].plot([10.0 / r["cells"] for r in rows], [r["velocity_m_per_s"] * 1e3 for r in rows], "o", mfc="none",
                 color="grey", label="one registry")
    means = registry_means(rows)
    axes[0].errorbar([10.0 / m[0] for m in means], [m[2] * 1e3 for m in means], yerr=[m[3] * 1e3 for m in means],
                     fmt="s-", capsize=4, label="mean over the registries +- standard error")
    axes[0].set_xlabel("the cell's particle spacing [um]")
    axes[0].set_ylabel(f"drift velocity, last quarter of {LONG_T_END * 1e6:g} us [nm/us]")
    axes[0].legend(fontsize=8)
    axes[0].grid(True, alpha=0.3)
    axes[1].loglog([m[4] for m in means], [m[3] / m[2] for m in means], "s-")
    for cells, _, mean, error, wall in means:
        axes[1].annotate(f"{cells} cells", (wall, error / mean), fontsize=8)
    axes[1].set_xlabel("wall time of a resolution's runs [s], 2 threads")
    axes[1].set_ylabel("standard error of the mean / mean")
    axes[1].grid(True, which="both", alpha=0.3)
    fig.suptitle("Crawling velocity averaged over the two lattices' registry")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def run_registry(args):
    runs = [(cells, shift) for cells in args.cells or FULL_CELLS for shift in REGISTRY_SHIFTS]
    rows, _, loads = zip(*(run_long_graded(args, cells, shift=shift) for cells, shift in runs))
    shifts = [shift for _, shift in runs]
    write_results(args.out, "crawling_convergence_registry", rows, CSV_COLUMNS, registry_table(rows, shifts, loads),
                  lambda path: registry_plot(rows, path))
    return 0


def overdamped_velocity(folder, scene):
    """The contact term's energy E at the end of a graded run, and the velocity of an
    overdamped cell under the force that energy implies. With the linear stiffness law
    every pair's eps follows the substrate's modulus, so a rigid shift dy of the cell
    changes E by E (d ln mu / dy) dy, with mu's factor grade_a (y - y_min) / L0 + grade_b
    (Eq. 18) taken at the cell's start (it moves less than 0.2 um); the damping c resists
    the cell's mass m with c m v. Returns (E [J], v [m/s])."""
    summary = json.load(open(os.path.join(folder, "summary.json")))
    energy = summary["contact cell substrate"]["energy"]
    cell, block = scene["body"]
    a, b = block["material"]["grade_a"], block["material"]["grade_b"]
    length = block["cloud"]["size"][1]
    along = (cell["cloud"]["center"][1] - block["cloud"]["origin"][1]) / length
    log_gradient = (a / length) / (a * along + b)
    mass = cell["density"] * 4.0 / 3.0 * math.pi * cell["cloud"]["radius"] ** 3
    return energy, -energy * log_gradient / (scene["integrator"]["damping"] * mass)


def layered_ratio(scene):
    """The adhesion energy of flat bodies with the scene's layer spacings
    (layered_contact.cloud_layer_spacings) over the continuum's (adhesion_ratio)."""
    cell, block = scene["body"]
    term = scene["term"][0]
    s0 = term["s0"]
    return adhesion_ratio(*cloud_layer_spacings(cell["cloud"], block["cloud"]), term["epsilon"], s0,
                          math.sqrt(term["beta"][0] * term["beta"][1]), cutoff_or_default(term.get("cutoff"), s0))


def fine_table(rows, loads):
    """The generated Markdown of --fine: every run with its contact energy and the
    overdamped velocity that energy implies, then the checks by group."""
    size = load_scene(SCENE)["body"][1]["cloud"]["size"]
    s0 = load_scene(SCENE)["term"][0]["s0"]
    lines = ["| group | cells | substrate cells | substrate spacing x, y / z [s0] | particles | start moved "
             "[substrate spacings] | velocity, last quarter [nm/us] | quarter before [nm/us] | contact energy [fJ] | "
             "overdamped velocity from it [nm/us] | velocity / overdamped | layered w / continuum w | "
             "velocity / (w ratio)^(5/3) [nm/us] | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in (r for r in rows if r["group"] != "matched"):
        n = [int(k) for k in r["substrate_cells"].split("x")]
        lines.append(f"| {r['group']} | {r['cells']} | {r['substrate_cells']} | {size[0] / n[0] / s0:.2f} / "
                     f"{size[2] / n[2] / s0:.2f} | {r['particles']:,} | {r['start_shift']:g} | "
                     f"{r['velocity_m_per_s'] * 1e3:.3f} | {r['velocity_earlier_m_per_s'] * 1e3:.3f} | "
                     f"{-r['contact_energy_J'] * 1e15:.2f} | {r['velocity_overdamped_m_per_s'] * 1e3:.3f} | "
                     f"{r['velocity_m_per_s'] / r['velocity_overdamped_m_per_s']:.2f} | {r['layered_ratio']:.3f} | "
                     f"{r['velocity_layer_corrected_m_per_s'] * 1e3:.3f} | {r['wall_s']:.0f} |")
    lines.append("")
    group = {}
    for r in rows:
        group.setdefault(r["group"], []).append(r)
    if "registry" in group:
        moved = group["registry"][0]
        same = next(r for r in group["fine x, y"] if r["cells"] == moved["cells"])
        lines.append(f"- registry, {moved['cells']} cells on the {same['substrate_cells']} block: velocity "
                     f"{same['velocity_m_per_s'] * 1e3:.3f} and {moved['velocity_m_per_s'] * 1e3:.3f} nm/us with the "
                     f"start moved by 0 and {moved['start_shift']:g} of its spacing, "
                     f"{100 * abs(moved['velocity_m_per_s'] / same['velocity_m_per_s'] - 1):.1f} % apart")
    for name in ("fine x, y", "fine x, y, z"):
        mine = group.get(name, [])
        if len(mine) >= 2:
            a, b = mine[-2], mine[-1]
            d = abs(b["velocity_m_per_s"] - a["velocity_m_per_s"]) / abs(b["velocity_m_per_s"])
            dc = abs(b["velocity_layer_corrected_m_per_s"] - a["velocity_layer_corrected_m_per_s"]) / abs(
                b["velocity_layer_corrected_m_per_s"])
            lines.append(f"- {name}, two finest ({a['cells']} and {b['cells']} cells): velocity "
                         f"{a['velocity_m_per_s'] * 1e3:.3f} and {b['velocity_m_per_s'] * 1e3:.3f} nm/us, "
                         f"{100 * d:.1f} % apart (criterion: within 10 %): {'met' if d <= 0.1 else 'not met'}; "
                         f"contact energy {-a['contact_energy_J'] * 1e15:.2f} and "
                         f"{-b['contact_energy_J'] * 1e15:.2f} fJ; over (w ratio)^(5/3): "
                         f"{a['velocity_layer_corrected_m_per_s'] * 1e3:.3f} and "
                         f"{b['velocity_layer_corrected_m_per_s'] * 1e3:.3f} nm/us, {100 * dc:.1f} % apart")
    means = []
    for cells in sorted({r["cells"] for r in group.get("matched", [])}):
        mine = [r for r in group["matched"] if r["cells"] == cells]
        energy = np.array([-r["contact_energy_J"] for r in mine])
        v = np.mean([r["velocity_m_per_s"] for r in mine])
        v_over = np.mean([r["velocity_overdamped_m_per_s"] for r in mine])
        scale = mine[0]["layered_ratio"] ** CONTACT_ENERGY_EXPONENT
        error = np.std([r["velocity_m_per_s"] for r in mine], ddof=1) / math.sqrt(len(mine)) / scale
        means.append((cells, energy.mean(), v / v_over, v_over / energy.mean(), v / scale, error))
        lines.append(f"- matched ladder, {cells} cells ({mine[0]['substrate_cells']} block), {len(mine)} starts: "
                     f"contact energy {energy.mean() * 1e15:.2f} fJ "
                     f"(spread {100 * np.ptp(energy) / energy.mean():.1f} %), "
                     f"overdamped velocity {v_over * 1e3:.3f} nm/us, mean velocity {v * 1e3:.3f} nm/us, ratio "
                     f"{v / v_over:.2f}; layered w / continuum w {mine[0]['layered_ratio']:.3f}: contact energy over "
                     f"(w ratio)^(5/3) {energy.mean() / scale * 1e15:.2f} fJ, mean velocity over it "
                     f"{v / scale * 1e3:.3f} nm/us")
    if len(means) >= 3:
        finest = means[-3:]
        e = richardson([10e-6 / m[0] for m in finest], [m[1] for m in finest])
        lines.append(richardson_line("the matched ladder's contact energy (three finest, means of the starts)", e, 1e15,
                                     "fJ"))
        if e.monotone:
            ratio, per_energy = np.mean([m[2] for m in finest]), finest[-1][3]
            lines.append(f"- the velocity that energy implies at the three finest's mean ratio {ratio:.2f}: "
                         f"{ratio * per_energy * e.q_inf * 1e3:.2f} +- {ratio * per_energy * e.gci * 1e3:.2f} nm/us")
        corrected = [m[4] for m in finest]
        d = abs(corrected[-1] - corrected[-2]) / abs(corrected[-1])
        lines.append(f"- the matched ladder's mean velocity over (w ratio)^(5/3), three finest: "
                     f"{', '.join(f'{m[4] * 1e3:.3f} +- {m[5] * 1e3:.3f}' for m in finest)} nm/us (standard errors "
                     f"of the registry means); two finest {100 * d:.1f} % apart (criterion: within 10 %): "
                     f"{'met' if d <= 0.1 else 'not met'}")
    once = {r["folder"]: r for r in rows}.values()
    ratios = np.array([r["velocity_m_per_s"] / r["velocity_overdamped_m_per_s"] for r in once])
    lines.append(f"- velocity / overdamped velocity over the {len(ratios)} runs: {ratios.min():.2f} to "
                 f"{ratios.max():.2f}, median {np.median(ratios):.2f}")
    lines.append(f"- machine load (1-minute average) after the runs: {', '.join(sorted(set(loads)))}")
    return "\n".join(lines) + "\n"


def fine_plot(rows, path):
    """The velocity against the overdamped velocity from each run's own contact energy
    (left), and the contact energy against the layered bodies' adhesion energy at the
    run's spacings, to the power CONTACT_ENERGY_EXPONENT (right)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    markers = {"fine x, y": "s", "registry": "x", "fine x, y, z": "D", "split": "o", "matched": "."}
    for name, marker in markers.items():
        mine = [r for r in rows if r["group"] == name]
        if not mine:
            continue
        axes[0].plot([r["velocity_overdamped_m_per_s"] * 1e3 for r in mine],
                     [r["velocity_m_per_s"] * 1e3 for r in mine], marker, mfc="none", label=name)
        for r in mine:
            axes[0].annotate(str(r["cells"]), (r["velocity_overdamped_m_per_s"] * 1e3, r["velocity_m_per_s"] * 1e3),
                             fontsize=7)
    top = max(max(r["velocity_overdamped_m_per_s"], r["velocity_m_per_s"]) for r in rows) * 1.1e3
    axes[0].plot([0, top], [0, top], color="grey", lw=0.8, label="velocity = overdamped velocity")
    axes[0].set_xlabel("overdamped velocity from the run's contact energy [nm/us]")
    axes[0].set_ylabel(f"drift velocity, last quarter of {LONG_T_END * 1e6:g} us [nm/us]")
    axes[0].legend(fontsize=8)
    axes[0].grid(True, alpha=0.3)
    scaled = [r["layered_ratio"] ** CONTACT_ENERGY_EXPONENT for r in rows]
    once = {r["folder"]: (r, x) for r, x in zip(rows, scaled)}.values()
    per_unit = float(np.median([-r["contact_energy_J"] / x for r, x in once]))
    for cells, color in ((17, "C0"), (21, "C1"), (25, "C2"), (29, "C3")):
        for name, marker in markers.items():
            mine = [(x, r) for x, r in zip(scaled, rows) if r["cells"] == cells and r["group"] == name]
            if mine:
                axes[1].plot([x for x, _ in mine], [-r["contact_energy_J"] * 1e15 for _, r in mine], marker,
                             mfc="none", color=color, label=f"cell {cells} cells, {name}")
    top = max(scaled) * 1.1
    axes[1].plot([0, top], [0, per_unit * top * 1e15], color="grey", lw=0.8,
                 label=f"proportional: {per_unit * 1e15:.2f} fJ at the continuum's w")
    axes[1].set_xlabel("(layered w / continuum w)^(5/3) at the run's spacings")
    axes[1].set_ylabel("contact energy at the end [fJ]")
    axes[1].set_xlim(left=0)
    axes[1].set_ylim(bottom=0)
    axes[1].legend(fontsize=6, ncol=2)
    axes[1].grid(True, alpha=0.3)
    fig.suptitle("Crawling: the velocity follows the contact energy, which follows the layers' adhesion energy")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def run_fine(args):
    rows, loads = [], []
    for cells, substrate, shift, group in fine_runs():
        row, scene, load = run_long_graded(args, cells, shift=shift, substrate=substrate)
        row["contact_energy_J"], row["velocity_overdamped_m_per_s"] = overdamped_velocity(row["folder"], scene)
        row["start_shift"], row["group"] = shift, group
        row["layered_ratio"] = layered_ratio(scene)
        row["velocity_layer_corrected_m_per_s"] = (row["velocity_m_per_s"]
                                                   / row["layered_ratio"] ** CONTACT_ENERGY_EXPONENT)
        rows.append(row)
        loads.append(load)
    write_results(args.out, "crawling_convergence_fine", rows,
                  ["group"] + CSV_COLUMNS + ["start_shift", "contact_energy_J", "velocity_overdamped_m_per_s",
                                             "layered_ratio", "velocity_layer_corrected_m_per_s"],
                  fine_table(rows, loads), lambda path: fine_plot(rows, path))
    return 0


def main(argv=None):
    parser = study_parser("crawling drift at several resolutions")
    parser.add_argument("--coarse", action="store_true", help=f"cells {COARSE_CELLS} only")
    parser.add_argument("--long", action="store_true",
                        help=f"the graded runs only, to {LONG_T_END * 1e6:g} us (results: crawling_convergence_long)")
    parser.add_argument("--split", action="store_true",
                        help="the graded run to the long end with the cell or the substrate refined alone")
    parser.add_argument("--registry", action="store_true",
                        help="the graded runs to the long end with the cell's start at four places on the block's "
                             "lattice at every resolution")
    parser.add_argument("--cells", type=int, nargs="+",
                        help=f"resolutions of --registry (default {FULL_CELLS})")
    parser.add_argument("--fine", action="store_true",
                        help="the graded runs to the long end on blocks 0.5 s0 apart, and what sets the velocity")
    args = parser.parse_args(argv)
    if args.fine:
        return run_fine(args)
    if args.split:
        return run_split(args)
    if args.registry:
        return run_registry(args)
    rows, loads = [], []
    runs = {"graded": RUNS["graded"]} if args.long else RUNS
    t_end, suffix = (LONG_T_END, f"_t{LONG_T_END * 1e6:g}us") if args.long else (None, "")
    for cells in (COARSE_CELLS if args.coarse else FULL_CELLS):
        for run, grading in runs.items():
            scene = variant(cells, grading, t_end)
            folder = run_scene(args.rkpm, scene, os.path.join(args.out, f"{run}_c{cells}{suffix}"), args.threads)
            rows.append(measure(run, cells, folder, scene))
            loads.append(study_load(folder))
            r = rows[-1]
            print(f"{run} {cells} cells: {r['particles']:,} particles, drift {r['drift_m'] * 1e9:.2f} nm, velocity "
                  f"{r['velocity_m_per_s'] * 1e3:.3f} nm/us (before: {r['velocity_earlier_m_per_s'] * 1e3:.3f}), "
                  f"{r['wall_s']:.0f} s", flush=True)
    est = estimates(rows)
    write_results(args.out, "crawling_convergence_long" if args.long else "crawling_convergence", rows, CSV_COLUMNS,
                  table(rows, est, loads),
                  lambda path: plot(rows, est, path))
    return 0


if __name__ == "__main__":
    sys.exit(main())
