"""The roofline of the internal force and the portable and native builds side by side,
from the scaling study's CSV files (scripts/study scaling, scripts/study scaling
--native; docs/verification/performance.md).

Usage: roofline.py --portable CSV [--native CSV] --png PNG --table MD

The roofline: a kernel that moves B bytes and makes W floating-point operations
cannot take less than max(B / bandwidth, W / peak); its intensity W / B says which
ceiling holds it. The CSV rows carry the counted operations (force_flops), the bytes
(traffic_bytes), the measured time (force_2t_s) and the machine's ceilings as the
study measured them (triad_gb_per_s, peak_vector_gflops, peak_scalar_gflops)."""
import argparse
import csv
import math

GEOMETRIES = ["block", "sphere", "shell"]
TITLES = {"block": "Mooney-Rivlin block", "sphere": "LCE sphere", "shell": "RBC shell"}


def read(path):
    """The measured rows of a scaling CSV, keyed by (geometry, particles)."""
    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            if r["status"] == "ok":
                rows[(r["geometry"], int(float(r["particles"])))] = r
    return rows


def value(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return math.nan


def ceilings(rows):
    """(triad GB/s, vector peak GFLOP/s, scalar peak GFLOP/s, ISA) of a study."""
    r = next(iter(rows.values()))
    return value(r, "triad_gb_per_s"), value(r, "peak_vector_gflops"), value(r, "peak_scalar_gflops"), r.get("isa", "?")


def fmt(v, digits=3):
    if not math.isfinite(v):
        return "-"
    if v == 0:
        return "0"
    d = max(0, digits - 1 - int(math.floor(math.log10(abs(v)))))
    return f"{v:.{d}f}"


def percent(v):
    return f"{100 * v:.0f} %" if math.isfinite(v) else "-"


def side_by_side(portable, native):
    """The markdown table of the two builds at the sizes both measured."""
    lines = [
        "| geometry | particles | step, 2 threads [ms]: portable / native | ratio | internal force [ms]: "
        "portable / native | ratio | of the bandwidth bound: portable / native | GFLOP/s: portable / native |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for (geometry, n), p in sorted(portable.items(), key=lambda kv: (GEOMETRIES.index(kv[0][0]), kv[0][1])):
        q = native.get((geometry, n))
        if q is None:
            continue
        step = (value(p, "step_2t_s"), value(q, "step_2t_s"))
        force = (value(p, "force_2t_s"), value(q, "force_2t_s"))
        lines.append(
            f"| {geometry} | {n:,} | {fmt(1e3 * step[0])} / {fmt(1e3 * step[1])} | {fmt(step[1] / step[0])} | "
            f"{fmt(1e3 * force[0])} / {fmt(1e3 * force[1])} | {fmt(force[1] / force[0])} | "
            f"{percent(value(p, 'bandwidth_fraction'))} / {percent(value(q, 'bandwidth_fraction'))} | "
            f"{fmt(value(p, 'gflops_2t'))} / {fmt(value(q, 'gflops_2t'))} |")
    return "\n".join(lines)


def largest(rows, geometry):
    sizes = [n for (g, n) in rows if g == geometry]
    return rows[(geometry, max(sizes))] if sizes else None


def plot(builds, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8.5, 6))
    x = [10 ** (k / 20) for k in range(-30, 31)]  # 0.03 .. 30 flop/B
    colours = {"block": "tab:blue", "sphere": "tab:orange", "shell": "tab:green"}
    markers = ["o", "s"]
    styles = ["-", "--"]
    for b, (label, rows) in enumerate(builds):
        bw, vector, scalar, isa = ceilings(rows)
        ax.plot(x, [min(bw * i, vector) for i in x], styles[b], color="black", lw=1.5,
                label=f"{label}: triad {bw:.1f} GB/s, {isa} peak {vector:.1f} GFLOP/s")
        ax.axhline(scalar, ls=styles[b], color="gray", lw=1,
                   label=f"{label}: scalar peak {scalar:.1f} GFLOP/s")
        for g in GEOMETRIES:
            r = largest(rows, g)
            if r is None:
                continue
            ax.plot(value(r, "intensity_flop_per_byte"), value(r, "gflops_2t"), markers[b], color=colours[g],
                    ms=9, mfc="none" if b else colours[g],
                    label=f"{TITLES[g]}, {int(float(r['particles'])):,} particles ({label})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("arithmetic intensity of the internal force [flop / byte moved]")
    ax.set_ylabel("GFLOP/s (2 threads)")
    ax.set_title("Roofline of the internal force (operations counted from the kernels, stress left out)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--portable", required=True)
    ap.add_argument("--native")
    ap.add_argument("--png", required=True)
    ap.add_argument("--table", required=True)
    args = ap.parse_args()
    portable = read(args.portable)
    builds = [("portable", portable)]
    text = []
    if args.native:
        native = read(args.native)
        builds.append(("native", native))
        _, _, _, isa = ceilings(native)
        text.append(f"The portable build (SSE2) and the build for this machine (`-DRKPM_NATIVE=ON`, {isa}), "
                    "each from its own run of the scaling study; a ratio below 1 is the native build faster. "
                    "The two runs were made one after the other, so the machine's load may differ "
                    "(each run's page header says how loaded it was).\n")
        text.append(side_by_side(portable, native))
    else:
        text.append("No native run yet (`scripts/study scaling --native`).")
    plot(builds, args.png)
    with open(args.table, "w") as f:
        f.write("\n".join(text) + "\n")


if __name__ == "__main__":
    main()
