"""What moves the crawling cell: the graded run with one ingredient changed at a time
(the driver of `scripts/study crawling-mechanism`; its header says what it writes).

Every variant is examples/crawling/crawling.toml as shipped (17 cells, graded by Eq. 18,
passive, linear stiffness law, surface tension, damping 5e5 /s) with one change. The
drift velocity is the slope of the centroid's y over the run's last quarter
(crawling_convergence.measure)."""
import json
import os
import sys

import crawling_convergence as C
from study_runs import study_parser, write_results, load_scene, run_scene, study_load

SHIPPED = "examples/crawling/crawling.toml"


def _cell(scene):
    return scene["body"][0]


def _substrate(scene):
    return scene["body"][1]


def _contact(scene):
    return next(t for t in scene["term"] if t["type"] == "contact")


def _set(path, value):
    """A change that sets one key: path is (getter, key)."""
    getter, key = path

    def change(scene):
        getter(scene)[key] = value
    return change


def _no_tension(scene):
    scene["term"] = [t for t in scene["term"] if t["type"] != "surface_tension"]


def _slope(a):
    def change(scene):
        m = _substrate(scene)["material"]
        m["grade_a"], m["grade_b"] = a, 0.5
    return change


def _material(key):
    return (lambda s: _cell(s)["material"], key)


# name: (what changes, the change). Eq. 18's slope 4 with offset 0.5 is the shipped run.
VARIANTS = {
    "shipped": ("as shipped: Eq. 18 slope 4, passive, linear law, tension, damping 5e5 /s", lambda s: None),
    "contractile": ("activity zeta = -2 kPa (0.2 mu, contractile along h)", _set(_material("zeta"), -2e3)),
    "extensile": ("activity zeta = +2 kPa (extensile along h)", _set(_material("zeta"), 2e3)),
    "uniform_adhesion": ("stiffness_law = none: eps the same everywhere", _set((_contact, "stiffness_law"), "none")),
    "no_tension": ("no surface tension (both terms removed)", _no_tension),
    "slope0": ("Eq. 18 slope 0 (factor 0.5 everywhere)", _slope(0.0)),
    "slope1": ("Eq. 18 slope 1", _slope(1.0)),
    "slope2": ("Eq. 18 slope 2", _slope(2.0)),
    "slope8": ("Eq. 18 slope 8", _slope(8.0)),
    "adhesion_x2": ("eps x 2 (adhesion energy 1.3e-3 J/m^2 at the 3 s0 cutoff)",
                    _set((_contact, "epsilon"), 2 * 3.265e-15)),
    "adhesion_x4": ("eps x 4 (2.6e-3 J/m^2)", _set((_contact, "epsilon"), 4 * 3.265e-15)),
    "damping_div10": ("damping 5e4 /s instead of 5e5", _set((lambda s: s["integrator"], "damping"), 5e4)),
}
SLOPES = {"slope0": 0.0, "slope1": 1.0, "slope2": 2.0, "shipped": 4.0, "slope8": 8.0}
CSV_COLUMNS = ["variant", "change", "status", "drift_m", "velocity_m_per_s", "velocity_earlier_m_per_s",
               "drift_x_m", "t_end_s", "particles", "steps", "wall_s"]


def variant(name):
    scene = load_scene(SHIPPED)
    VARIANTS[name][1](scene)
    return scene


def run_status(folder):
    """"completed", or how the run stopped (summary.json's status and the diagnosis)."""
    summary = json.load(open(os.path.join(folder, "summary.json")))
    if summary["status"] == "completed":
        return "completed"
    return f"{summary['status']} at t = {summary['simulated_time'] * 1e6:.2f} us"


def table(rows, loads):
    base = next(r for r in rows if r["variant"] == "shipped")
    lines = ["| variant | change | run | drift along y at the end [nm] | velocity, last quarter [nm/us] | "
             "quarter before [nm/us] | velocity / shipped | wall [s] |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['variant']} | {r['change']} | {r['status']} | {r['drift_m'] * 1e9:.2f} | "
                     f"{r['velocity_m_per_s'] * 1e3:.3f} | {r['velocity_earlier_m_per_s'] * 1e3:.3f} | "
                     f"{r['velocity_m_per_s'] / base['velocity_m_per_s']:.2f} | {r['wall_s']:.0f} |")
    lines.append("")
    lines.append(f"- machine load (1-minute average) after the runs: {', '.join(sorted(set(loads)))}")
    return "\n".join(lines) + "\n"


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    by = {r["variant"]: r for r in rows}
    names = [n for n in SLOPES if n in by]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot([SLOPES[n] for n in names], [by[n]["velocity_m_per_s"] * 1e3 for n in names], "o-",
            label="last quarter of the run")
    ax.plot([SLOPES[n] for n in names], [by[n]["velocity_earlier_m_per_s"] * 1e3 for n in names], "s--",
            label="quarter before")
    ax.set_xlabel("Eq. 18 slope (factor slope y / L0 + 0.5)")
    ax.set_ylabel("drift velocity along y [nm/us]")
    ax.axhline(0.0, color="grey", lw=0.8)
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title("Crawling: drift velocity against the stiffness gradient")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv=None):
    parser = study_parser("the crawling cell with one ingredient changed at a time")
    parser.add_argument("--only", nargs="*", help="run only these variants (and the shipped one)")
    args = parser.parse_args(argv)
    names = [n for n in VARIANTS if not args.only or n == "shipped" or n in args.only]
    rows, loads = [], []
    for name in names:
        scene = variant(name)
        folder = run_scene(args.rkpm, scene, os.path.join(args.out, name), args.threads, allow_unstable=True)
        r = C.measure(name, scene["body"][0]["cloud"]["cells"], folder, scene)
        r.update(variant=name, change=VARIANTS[name][0], status=run_status(folder))
        rows.append(r)
        loads.append(study_load(folder))
        print(f"{name}: drift {r['drift_m'] * 1e9:.2f} nm, velocity {r['velocity_m_per_s'] * 1e3:.3f} nm/us "
              f"(before: {r['velocity_earlier_m_per_s'] * 1e3:.3f}), {r['wall_s']:.0f} s", flush=True)
    write_results(args.out, "crawling_mechanism", rows, CSV_COLUMNS, table(rows, loads),
                  lambda path: plot(rows, path))
    return 0


if __name__ == "__main__":
    sys.exit(main())
