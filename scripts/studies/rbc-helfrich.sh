#!/usr/bin/env bash
# Red-blood-cell mid-surface against Helfrich's minimum and Evans-Fung, rim included.
# Runs the default scene (examples/rbc/rbc.toml as shipped) and the finest cloud of
# `scripts/study rbc` (64:5, 122,890 particles, made the same way), and measures each
# run's mid-surface (the material surface halfway through the wall, from the last frame;
# scripts/lib/rbc_midsurface.py) as an axisymmetric meridian: reduced volume,
# h_min/h_max, r(h_max)/R, profile RMS against Evans-Fung over D
# (scripts/lib/rbc_profile.py), bending energy E / (8 pi kappa) at C0 = 0 and the
# meridian curvature at the equator and its largest value over the rim (from the bins
# and from a fit to the particles; both also on the reference spheroid, where they are
# known), for the outer surface too. Against: Helfrich's oblate (discocyte) minimum at the
# same reduced volume (scripts/lib/helfrich.py; at the default run's and at the finest
# run's) and Evans-Fung, both scaled to the run's diameter. Writes
# out/rbc-helfrich/{rbc_helfrich.csv, rbc_helfrich.png, table.md, summary.txt}; the full
# run also writes docs/figures/rbc_helfrich.{csv,png} and the generated table of
# docs/verification/rbc.md ("Against Helfrich's model"). About 4 minutes on 2 cores:
# the runs take about 60 s and 165 s, the Helfrich minima and the measures about 3 s.
# Usage: scripts/study rbc-helfrich [--coarse]
#   --coarse: one 12:5 run (4,330 particles) instead of the two, compared the same way
#   (about 15 s); docs untouched.
#   A run directory that already holds a summary.json is kept (delete it to rerun).
#   RKPM_BIN names a built rkpm to run instead of building one in RKPM_BUILD_DIR.
set -euo pipefail
script_name="study rbc-helfrich"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/rbc-helfrich
coarse=0
update_docs=1
for arg in "$@"; do
  case "$arg" in
    --coarse) coarse=1; update_docs=0 ;;
    *) rkpm_die "unknown argument $arg (expected --coarse)" ;;
  esac
done
rkpm_need gnuplot
rkpm_need_python_modules numpy scipy
threads=${OMP_NUM_THREADS:-2}
rkpm=$(rkpm_program)
mkdir -p "$out"

# label:default (the scene as shipped) or label:face_cells:layers, made from the scene
# as scripts/studies/rbc.sh makes its clouds (only the resolution and the name differ).
if [ "$coarse" = 1 ]; then runs=(rkpm_coarse:12:5); else runs=(rkpm_default:default rkpm_finest:64:5); fi
specs=()
for spec in "${runs[@]}"; do
  label=${spec%%:*}; res=${spec#*:}
  if [ "$res" = default ]; then
    tag=default; scene=$here/examples/rbc/rbc.toml
  else
    fc=${res%%:*}; ly=${res##*:}; tag="fc${fc}_l${ly}"; scene=$out/$tag.toml
    sed -e "s/^face_cells = .*/face_cells = $fc/" -e "s/^layers = .*/layers = $ly/" \
        -e "s/^name = \"rbc\"/name = \"rbc_$tag\"/" "$here/examples/rbc/rbc.toml" > "$scene"
  fi
  if [ -f "$out/$tag/summary.json" ]; then
    echo "$tag: done before, kept"
  else
    echo "$tag: running"
    start=$(date +%s.%N)
    OMP_NUM_THREADS=$threads "$rkpm" run "$scene" --out "$out/$tag" --quiet || rkpm_die "$tag: rkpm exited with $?"
    # The wall time as the study saw it (set-up and output included) and the load
    # average right after (the machine may be shared), kept with the run.
    awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f\n", b - a }' > "$out/$tag/study_wall_seconds"
    cut -d' ' -f1-3 /proc/loadavg > "$out/$tag/study_load"
  fi
  specs+=("$label|$out/$tag|$scene")
done

PYTHONPATH="$here/scripts/lib" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 - "$out" "$threads" "${specs[@]}" \
  <<'PY' | tee "$out/summary.txt"
import json
import sys

import numpy as np

import helfrich as H
import rbc_midsurface as M
import rbc_profile

out, threads, specs = sys.argv[1], sys.argv[2], sys.argv[3:]
UM = 1e6
NAMES = {"rkpm_default": "default run", "rkpm_finest": "finest cloud", "rkpm_coarse": "coarse run"}
# The fit of r(z) at the equator takes the particles within this reference angle of it
# (about +-0.25 um of the mid-surface): wide enough to average the cloud's azimuthal
# scatter (a few nm), narrow enough that r = R + c2 z^2 + c4 z^4 holds (on the reference
# spheroid the fit gives the exact curvature).
BAND = np.pi / 16


def fmt(x, digits=3):
    return "-" if x is None else f"{x:.{digits}f}"


def measure(shell, name, reference=False):
    """The measures of one surface of a run (current or reference) from its meridian in
    bins of face_cells / 2 per quarter meridian (fine: about one particle row per bin at
    the rim) and of face_cells / 3 (coarse: the check of the binning)."""
    r, z = shell.rz(name, reference)
    r, z = r * UM, z * UM
    fine, coarse = shell.spec["face_cells"] // 2, shell.spec["face_cells"] // 3
    R, Z, counts = M.meridian(r, z, shell.psi, fine)
    Rc, Zc, _ = M.meridian(r, z, shell.psi, coarse)
    m = H.profile_measures(R, Z)
    profile, updown = M.thickness_profile(R, Z)
    k_max, k_max_z, k_eq = M.rim_curvature(R, Z)
    kc_max, kc_max_z, kc_eq = M.rim_curvature(Rc, Zc)
    D = 2.0 * r.max()   # as the shape report: twice the largest distance from the axis
    return {"v": m["reduced_volume"], "E": m["energy_over_8pi_kappa"], "hr": m["h_min_over_h_max"],
            "rr": m["r_hmax_over_R"], "D": D, "profile": (D, profile), "updown": updown,
            "E_coarse": H.profile_measures(Rc, Zc)["energy_over_8pi_kappa"],
            "k3": k_eq, "k3_coarse": kc_eq, "k_fit": M.equator_fit_curvature(r, z, shell.psi, BAND)[0],
            "k_max": (k_max, k_max_z), "k_max_coarse": (kc_max, kc_max_z),
            "bins": (fine, coarse), "min_count": int(counts.min()), "curve": (R, Z)}


def evans_fung_profile(D):
    return (D, [(x, float(H.evans_fung_thickness(x, D))) for x in np.linspace(0.0, 0.5 * D, 801)])


def helfrich_curve(shape, D, n=4001):
    """The shape's generating curve scaled to diameter D [um]."""
    r, z = shape.curve(n)
    scale = 0.5 * D / r.max()
    return scale * r, scale * z


def helfrich_profile(shape):
    points, _ = M.thickness_profile(*shape.curve(4001))
    return (2.0 * shape.curve(4001)[0].max(), points)


def reference_rim(r, z):
    """Curvature at the equator and the largest over the rim of a dense analytic curve."""
    k_max, z_max, k_eq = M.rim_curvature(r, z)
    return {"k_eq": k_eq, "k_max": (k_max, z_max)}


def spheroid_energy(a, c):
    """E / (8 pi kappa) of the spheroid with semi-axes a, a, c from its analytic meridian
    (4001 points): the exact value the binned reference meridian is checked against."""
    t = np.linspace(0.0, np.pi, 4001)
    r, z = a * np.sin(t), c * np.cos(t)
    r[0] = r[-1] = 0.0
    return H.profile_measures(r, z)["energy_over_8pi_kappa"]


runs = []
for spec in specs:
    label, run_dir, scene = spec.split("|")
    shell = M.Shell(run_dir, scene)
    summary = json.load(open(f"{run_dir}/summary.json"))
    try:
        wall = float(open(f"{run_dir}/study_wall_seconds").read())
        load = open(f"{run_dir}/study_load").read().strip()
    except OSError:
        wall = load = None
    run = {"label": label, "name": NAMES.get(label, label), "shell": shell, "particles": summary["total_particles"],
           "wall": wall, "load": load, "res": f"{shell.spec['face_cells']}:{shell.spec['layers']}",
           "outer_v_report": summary["shape"]["reduced_volume"]}
    for name in ("mid", "midpoint", "outer"):
        run[name] = measure(shell, name)
    run["mid_ref"] = measure(shell, "mid", reference=True)
    run["outer_ref"] = measure(shell, "outer", reference=True)
    a_mid, c_mid = shell.reference_mid_axes()
    a, _, c = shell.spec["semi_axes"]
    run["mid_ref"].update(k_exact=a_mid / c_mid ** 2 / UM, E_exact=spheroid_energy(a_mid, c_mid))
    run["outer_ref"].update(k_exact=a / c ** 2 / UM, E_exact=spheroid_energy(a, c))
    # The wall (inner to outer) and its part outside the mid-surface, along the columns,
    # at the equator, 20 degrees of reference angle above it (past the ridge) and on the
    # axis: where the ridge of the outer surface comes from.
    half_bin = 0.25 * np.pi / shell.spec["face_cells"]
    run["wall_profile"] = [(deg, shell.distance("inner", "outer", np.radians(deg), half_bin) * UM,
                    shell.distance("mid", "outer", np.radians(deg), half_bin) * UM,
                    float(np.mean(shell.rz("mid")[1][np.abs(shell.psi - np.radians(deg)) <= half_bin])) * UM)
                   for deg in (90, 70, 0)]
    runs.append(run)
    print(f"{label}: {run['particles']:,} particles ({run['res']}), frame {shell.frame}; "
          f"mid-surface bins {run['mid']['bins']}, fewest samples in a bin {run['mid']['min_count']}, "
          f"up-down asymmetry {run['mid']['updown']:.1e}")

first = runs[0]
# Helfrich's oblate minimum at each run's mid-surface reduced volume, and its rim and
# Evans-Fung's at that run's mid-surface diameter.
ef = H.evans_fung_measures()
ef_profile = evans_fung_profile(H.EVANS_FUNG_D_UM)
for run in runs:
    mid = run["mid"]
    h = run["helfrich"] = H.minimise(mid["v"], "oblate")
    run["h_measures"] = h.measures()
    run["h_rms_ef"] = rbc_profile.rms_distance(helfrich_profile(h), ef_profile)
    run["h_rim"] = reference_rim(*helfrich_curve(h, mid["D"], 20001))
    run["ef_rim"] = reference_rim(*H.evans_fung_curve(20001, diameter=mid["D"]))
    mid["rms_ef"] = rbc_profile.rms_distance(mid["profile"], evans_fung_profile(mid["D"]))
    mid["rms_h"] = rbc_profile.rms_distance(mid["profile"], helfrich_profile(h))
    for name in ("midpoint", "outer"):
        s = run[name]
        s["rms_ef"] = rbc_profile.rms_distance(s["profile"], evans_fung_profile(s["D"]))
hel = first["helfrich"]
try:
    stomatocyte = H.minimise(hel.v, "stomatocyte").energy
except RuntimeError as err:
    stomatocyte = None
    print(f"no stomatocyte at v = {hel.v:.4f}: {err}")

# The CSV users' scripts read: the columns and rows (runs, helfrich, evans_fung) as fixed.
with open(f"{out}/rbc_helfrich.csv", "w") as f:
    f.write("shape,reduced_volume,h_min_over_h_max,r_hmax_over_R,rms_vs_evans_fung_over_D,"
            "bending_energy_over_8pi_kappa\n")
    for run in runs:
        m = run["mid"]
        f.write(f"{run['label']},{m['v']:.6f},{m['hr']:.6f},{m['rr']:.6f},{m['rms_ef']:.6f},{m['E']:.6f}\n")
    hm = first["h_measures"]
    f.write(f"helfrich,{hel.v:.6f},{hm['h_min_over_h_max']:.6f},{hm['r_hmax_over_R']:.6f},"
            f"{first['h_rms_ef']:.6f},{hel.energy:.6f}\n")
    f.write(f"evans_fung,{ef['reduced_volume']:.6f},{ef['h_min_over_h_max']:.6f},{ef['r_hmax_over_R']:.6f},"
            f"{0.0:.6f},{ef['energy_over_8pi_kappa']:.6f}\n")

# Plot data: the first run's mid-surface (and its outer and inner surfaces for context),
# Helfrich's minimum at its reduced volume and Evans-Fung, all at the mid-surface's
# diameter, as full cross-sections z(r) in um.
D0 = first["mid"]["D"]


def write_section(path, r, z):
    with open(path, "w") as f:
        for sign in (1.0, -1.0):
            for x, y in zip(sign * np.asarray(r), z):
                f.write(f"{x:.6f} {y:.6f}\n")
            f.write("\n")


write_section(f"{out}/plot_mid.dat", *first["mid"]["curve"])
write_section(f"{out}/plot_outer.dat", *first["outer"]["curve"])
write_section(f"{out}/plot_inner.dat", *measure(first["shell"], "inner")["curve"])
write_section(f"{out}/plot_helfrich.dat", *helfrich_curve(hel, D0, 2001))
write_section(f"{out}/plot_evans_fung.dat", *H.evans_fung_curve(2001, diameter=D0))
with open(f"{out}/plot_labels.txt", "w") as f:
    f.write(f"{first['mid']['v']:.3f} {D0:.2f} {first['particles']:,}\n")

# The generated part of docs/verification/rbc.md.
lines = []
walls = ", ".join(f"{r['res']} {r['wall']:.0f} s (load average after it {r['load']})" if r["wall"] is not None
                  else f"{r['res']} (run earlier, not timed)" for r in runs)
lines.append(f"Measured by `scripts/study rbc-helfrich`, {threads} threads; wall time of each `rkpm run` "
             f"(set-up and output included): {walls}. "
             f"A surface's D is twice its largest distance from the axis; the references are scaled to the "
             f"mid-surface's D of the run they are compared with.")
lines.append("")
lines.append("| shape | reduced volume | h_min/h_max | r(h_max)/R | RMS vs Evans-Fung [% of D] | "
             "RMS vs Helfrich at the same v [% of D] | E / (8 pi kappa) | curvature at the equator [1/um] | "
             "largest curvature over the rim [1/um] | D [um] |")
lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")


def run_row(title, s, rms_h):
    return (f"| {title} | {s['v']:.3f} | {s['hr']:.3f} | {s['rr']:.3f} | {100 * s['rms_ef']:.1f} | {rms_h} | "
            f"{s['E']:.3f} | {s['k_fit']:.2f} ({s['k3']:.2f}) | {s['k_max'][0]:.2f} at z = {round(s['k_max'][1], 2) + 0.0:+.2f} um | "
            f"{s['D']:.2f} |")


for run in runs:
    lines.append(run_row(f"{run['name']} ({run['res']}, {run['particles']:,} particles), mid-surface", run["mid"],
                         f"{100 * run['mid']['rms_h']:.1f}"))
for run in runs:
    h, hm, rim = run["helfrich"], run["h_measures"], run["h_rim"]
    lines.append(f"| Helfrich's oblate minimum at the {run['name']}'s v | {h.v:.3f} | {hm['h_min_over_h_max']:.3f} | "
                 f"{hm['r_hmax_over_R']:.3f} | {100 * run['h_rms_ef']:.1f} | 0 | {h.energy:.3f} | "
                 f"{rim['k_eq']:.2f} | {rim['k_max'][0]:.2f} at z = {round(rim['k_max'][1], 2) + 0.0:+.2f} um | {run['mid']['D']:.2f} |")
rim = first["ef_rim"]
lines.append(f"| Evans-Fung | {ef['reduced_volume']:.3f} | {ef['h_min_over_h_max']:.3f} | {ef['r_hmax_over_R']:.3f} | "
             f"0 | {100 * rbc_profile.rms_distance(ef_profile, helfrich_profile(hel)):.1f} (at the {first['name']}'s v) | "
             f"{ef['energy_over_8pi_kappa']:.3f} | {rim['k_eq']:.2f} | {rim['k_max'][0]:.2f} at z = {round(rim['k_max'][1], 2) + 0.0:+.2f} um | "
             f"{D0:.2f} |")
lines.append(run_row(f"{first['name']}, midpoint of the inner and outer surfaces", first["midpoint"], "-"))
lines.append(run_row(f"{first['name']}, outer surface (the shape report's)", first["outer"], "-"))
lines.append("")
stom = (f"{stomatocyte:.3f}, below the oblate minimum's {hel.energy:.3f}" if stomatocyte is not None
        else "not found")
lines.append(f"Curvatures of a run: at the equator, the fit of r(z) over +-{np.degrees(BAND):.2f} degrees of "
             f"reference angle with the three-point estimate of the fine bins in brackets; the largest over the "
             f"rim (where the surface's normal is within 45 degrees of horizontal), three-point, fine bins; "
             f"negative where the meridian is concave. The references' on their dense analytic curves. "
             f"Helfrich's stomatocyte at v = {hel.v:.3f}: E / (8 pi kappa) = {stom}. The wall along a column "
             f"(inner to outer surface), and in brackets its part outside the mid-surface (reference "
             f"{first['shell'].spec['thickness'] * UM:.3f} and {0.5 * first['shell'].spec['thickness'] * UM:.3f} um): "
             + "; ".join(f"{r['name']} " + ", ".join(
                 f"{w:.3f} ({o:.3f}) um {'at the equator' if deg == 90 else 'on the axis' if deg == 0 else f'at {deg} deg (z = {z:.2f} um)'}"
                 for deg, w, o, z in r["wall_profile"]) for r in runs)
             + f". The outer surface's reduced volume "
             f"by the shape report (its polyhedral surface): {first['outer_v_report']:.3f}; from its meridian as "
             f"here: {first['outer']['v']:.3f}.")
lines.append("")
lines.append("How well the binned meridian gives the energy and the curvature: each surface in both bin widths, "
             "and the reference (undeformed) shell's surfaces, spheroids whose energy and curvature at the equator "
             "(a / c^2) are known.")
lines.append("")
lines.append("| surface | bins per quarter meridian | E / (8 pi kappa), fine / coarse bins | exact | "
             "curvature at the equator, three-point, fine / coarse bins [1/um] | fit of r(z) [1/um] | exact | "
             "largest over the rim, fine / coarse bins [1/um] |")
lines.append("|---|---|---:|---:|---:|---:|---:|---:|")
for run in runs:
    for key, what in (("mid", "mid-surface"), ("mid_ref", "mid-surface, reference"), ("midpoint", "midpoint"),
                      ("outer", "outer"), ("outer_ref", "outer, reference")):
        s = run[key]
        lines.append(f"| {run['res']} {what} | {s['bins'][0]} / {s['bins'][1]} | {s['E']:.3f} / {s['E_coarse']:.3f} | "
                     f"{fmt(s.get('E_exact'))} | {s['k3']:.2f} / {s['k3_coarse']:.2f} | {s['k_fit']:.2f} | "
                     f"{fmt(s.get('k_exact'), 2)} | {s['k_max'][0]:.2f} / {s['k_max_coarse'][0]:.2f} |")
lines.append("")
with open(f"{out}/table.md", "w") as f:
    f.write("\n".join(lines) + "\n")
print("\n".join(lines))
print(f"wrote {out}/rbc_helfrich.csv")
PY

read -r v0 d0 n0 < "$out/plot_labels.txt"
# The same curves twice: the whole cross-section, and the rim magnified.
curves="'$out/plot_outer.dat' with lines lc rgb '#bbbbbb' lw 1 title 'rkpm wall (outer and inner surfaces)', \
  '$out/plot_inner.dat' with lines lc rgb '#bbbbbb' lw 1 notitle, \
  '$out/plot_evans_fung.dat' with lines lc rgb '#1b9e77' lw 3 title 'Evans-Fung', \
  '$out/plot_helfrich.dat' with lines lc rgb '#d95f02' lw 3 title 'Helfrich minimum (oblate), same v', \
  '$out/plot_mid.dat' with linespoints lc rgb '#3b3bb3' lw 2 pt 7 ps 0.6 title 'rkpm mid-surface, $n0 particles'"
gnuplot <<EOF
set terminal png size 1600,700 noenhanced font ",13"
set output "$out/rbc_helfrich.png"
set multiplot
set grid
set xlabel "r [um]"
set ylabel "z [um]"
set origin 0, 0
set size 0.66, 1
set size ratio -1
set title "cross-sections at v = $v0, scaled to D = $d0 um"
set key top center vertical opaque
set xrange [-5.2:5.2]
set yrange [-2.4:4.4]
plot $curves
set origin 0.64, 0
set size 0.36, 1
set size ratio -1
set title "the rim, magnified"
unset key
set xrange [3.2:5.0]
set yrange [-1.5:1.5]
plot $curves
unset multiplot
EOF
echo "wrote $out/rbc_helfrich.csv, $out/rbc_helfrich.png, $out/table.md, $out/summary.txt"
if [ "$update_docs" = 1 ]; then
  cp "$out/rbc_helfrich.csv" "$here/docs/figures/rbc_helfrich.csv"
  cp "$out/rbc_helfrich.png" "$here/docs/figures/rbc_helfrich.png"
  rkpm_replace_generated "$here/docs/verification/rbc.md" "$out/table.md" "scripts/study rbc-helfrich -->"
  echo "updated docs/figures/rbc_helfrich.{csv,png} and docs/verification/rbc.md"
fi
