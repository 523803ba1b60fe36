#!/usr/bin/python3
"""The red blood cell at several wall thicknesses, from Python.

Runs examples/rbc/rbc.toml with only [body.cloud] thickness changed (each run to
convergence, nested levels included, as `rkpm run` does), collects the shape report
against Evans-Fung, and writes OUT/study.csv, OUT/table.md and OUT/profiles.png
(matplotlib). `scripts/study thickness` is this script plus the docs update.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/rbc_thickness_sweep.py 0.3 0.5

A run folder that already holds a summary.json is kept, so a sweep can be completed in
several sittings; a run that stops (unstable, or refused at set-up) is a row of the
table with the reason. The default thicknesses (0.3 0.4 0.5 0.75 1.0 um) take about
13 minutes on 2 cores.
"""
import argparse
import csv
import json
import os
import sys
import tomllib

import rkpm

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "rbc", "rbc.toml")
# The scene's criteria (examples/rbc/README.md), for the table's heading.
CRITERIA = "h_min/h_max <= 0.5, r(h_max)/R in 0.55-0.85, RMS <= 5 % of D, up-down <= 5 %"


def scene_at(thickness_um, tag, face_cells, max_steps):
    """The shipped scene as a dict, with the wall's thickness (and optionally the cloud
    and the step cap) changed."""
    with open(SCENE, "rb") as f:
        scene = tomllib.load(f)
    scene["scene"]["name"] = f"rbc_{tag}"
    scene["integrator"]["max_steps"] = max_steps
    cloud = scene["body"][0]["cloud"]
    cloud["thickness"] = thickness_um * 1e-6
    if face_cells:
        cloud["face_cells"] = face_cells
    return scene


def run_one(thickness_um, tag, folder, args):
    """Runs one thickness into `folder` unless it has run there before; returns its summary
    and its thickness profile."""
    if os.path.exists(os.path.join(folder, "summary.json")):
        print(f"{tag}: done before, kept")
    else:
        print(f"{tag}: running", flush=True)
        sim = rkpm.Simulation.from_dict(scene_at(thickness_um, tag, args.face_cells, args.max_steps),
                                        threads=args.threads)
        sim.run(out=folder)
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(folder, "shape_profile.csv"), newline="") as f:
        profile = list(csv.DictReader(f))
    return summary, profile


def row_of(thickness_um, tag, s):
    sh = s["shape"]
    levels = s.get("nested_levels", [])
    return dict(tag=tag, thickness_um=thickness_um, particles=s["total_particles"],
                level_steps="+".join(str(level["steps"]) for level in levels), steps=s["steps"],
                wall_s=s["wall_time"], converged=s.get("converged"), h_ratio=sh["h_min_over_h_max"],
                r_hmax=sh["r_hmax_over_R"], rms_ef=sh["rms_vs_evans_fung_over_D"], updown=sh["updown_asymmetry"],
                reduced_volume=sh["reduced_volume"], diameter_um=sh["diameter"] * 1e6,
                gap_um=sh["inner_gap_centre"] * 1e6, wall_centre_um=sh["wall_thickness_centre"] * 1e6,
                biconcave=sh["biconcave"], matches_evans_fung=sh.get("matches_evans_fung"))


def yes_no(value):
    return {True: "yes", False: "no"}.get(value, "-")


def write_table(rows, path, threads):
    load = " ".join(open("/proc/loadavg").read().split()[:3])
    with open(path, "w") as f:
        f.write(f"Measured by `scripts/study thickness`, {threads} threads, load average after the "
                f"runs {load}. Criteria of the scene: {CRITERIA}.\n\n")
        f.write("| T [um] | particles | steps (levels + own cloud) | wall [s] | converged | h_min/h_max | r(h_max)/R | "
                "RMS vs Evans-Fung [% of D] | up-down [%] | reduced volume | D [um] | fluid on the axis [um] | "
                "wall on the axis [um] | biconcave | all four criteria |\n")
        f.write("|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n")
        for r in rows:
            if "failure" in r:  # a run that stopped: what it said, in place of the measures
                f.write(f"| {r['thickness_um']:g} | | stopped: {r['failure']} ||||||||||||\n")
                continue
            steps = f"{r['level_steps']} + {r['steps']:,}" if r["level_steps"] else f"{r['steps']:,}"
            f.write(f"| {r['thickness_um']:g} | {r['particles']:,} | {steps} | {r['wall_s']:.0f} | "
                    f"{yes_no(bool(r['converged']))} | {r['h_ratio']:.3f} | {r['r_hmax']:.3f} | "
                    f"{100 * r['rms_ef']:.1f} | {100 * r['updown']:.1f} | {r['reduced_volume']:.3f} | "
                    f"{r['diameter_um']:.2f} | {r['gap_um']:.3f} | {r['wall_centre_um']:.3f} | "
                    f"{yes_no(r['biconcave'])} | {yes_no(r['matches_evans_fung'])} |\n")


def plot_profiles(rows, profiles, path):
    """Thickness profiles h(r), in units of each run's diameter, with Evans-Fung."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9, 6))
    for r, profile in zip(rows, profiles):
        D = r["diameter_um"] * 1e-6
        x = [2 * float(p["r"]) / D for p in profile]
        ax.plot(x, [float(p["thickness"]) / D for p in profile], "o-", ms=3, label=f"T = {r['thickness_um']:g} um")
    D = rows[0]["diameter_um"] * 1e-6
    ax.plot([2 * float(p["r"]) / D for p in profiles[0]], [float(p["evans_fung"]) / D for p in profiles[0]],
            "k--", label="Evans-Fung")
    ax.set_xlabel("2 r / D")
    ax.set_ylabel("thickness h(r) / D")
    ax.grid(True)
    ax.legend()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("thicknesses", nargs="*", type=float, default=[0.3, 0.4, 0.5, 0.75, 1.0],
                        help="wall thicknesses [um] (default 0.3 0.4 0.5 0.75 1.0)")
    parser.add_argument("--out", default=os.path.join("out", "thickness"), help="output folder (default out/thickness)")
    parser.add_argument("--face-cells", type=int, default=0, help="the shell's face_cells (default: the scene's)")
    parser.add_argument("--max-steps", type=int, default=10000,
                        help="steps on each run's own cloud; a wall not at rest by then is reported as not converged")
    parser.add_argument("--threads", type=int, default=int(os.environ.get("OMP_NUM_THREADS", "2")))
    args = parser.parse_args()

    os.makedirs(args.out, exist_ok=True)
    rows, profiles, failures = [], [], []
    for t in sorted(args.thicknesses):
        tag = f"T{t:g}um" + (f"_fc{args.face_cells}" if args.face_cells else "")
        try:
            summary, profile = run_one(t, tag, os.path.join(args.out, tag), args)
        except (rkpm.SetupError, rkpm.Unstable) as e:
            print(f"{tag}: {e}", file=sys.stderr)
            # Kept in the table: a wall the scene cannot relax is a result too.
            failures.append(dict(tag=tag, thickness_um=t, failure=str(e).split(": body")[0].replace("|", "/")))
            continue
        rows.append(row_of(t, tag, summary))
        profiles.append(profile)
    if not rows:
        sys.exit("no finished runs")

    with open(os.path.join(args.out, "study.csv"), "w") as f:
        f.write(",".join(rows[0]) + "\n")
        for r in rows:
            f.write(",".join(str(v) for v in r.values()) + "\n")
    write_table(sorted(rows + failures, key=lambda r: r["thickness_um"]), os.path.join(args.out, "table.md"),
                args.threads)
    plot_profiles(rows, profiles, os.path.join(args.out, "profiles.png"))
    print(open(os.path.join(args.out, "table.md")).read())
    print(f"wrote {args.out}/study.csv, {args.out}/table.md, {args.out}/profiles.png")


if __name__ == "__main__":
    main()
