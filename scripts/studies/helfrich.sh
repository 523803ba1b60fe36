#!/usr/bin/env bash
# Helfrich's spontaneous-curvature model: least bending energy of vesicle branches vs v.
# Runs the reference solver scripts/lib/helfrich.py (Python, no rkpm build): the
# minimal energy E / (8 pi kappa) of the prolate, oblate (discocyte) and stomatocyte
# branches at C0 = 0 for reduced volumes v from 0.55 to 1, each branch by continuation,
# with h_min/h_max and r(h_max)/R of every shape; the convergence of the energies as the
# expansion is refined; the transition volumes against Seifert, Berndl & Lipowsky,
# Phys. Rev. A 44, 1182 (1991) (prolate/oblate 0.652, oblate/stomatocyte 0.592); the
# Evans-Fung red blood cell's reduced volume and energy, and the oblate minimum at that
# reduced volume. Writes out/helfrich/{branches.csv, branches.png, summary.txt}; the full
# run also writes docs/figures/helfrich_branches.{csv,png}. About 35 s on 1 core.
# Usage: scripts/study helfrich [--coarse]
#   --coarse: v in steps of 0.05, fewer modes, no refinement table (about 7 s);
#   docs untouched.
set -euo pipefail
script_name="study helfrich"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/helfrich
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
mkdir -p "$out"

PYTHONPATH="$here/scripts/lib" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 - "$out" "$coarse" <<'PY' | tee "$out/summary.txt"
import sys
import time

import numpy as np

import helfrich as H

out, coarse = sys.argv[1], sys.argv[2] == "1"
step = 0.05 if coarse else 0.01
modes = {"prolate": 16, "oblate": 16, "stomatocyte": 48} if coarse else \
    {b: H.default_modes(b) for b in H.BRANCHES}
t0 = time.time()
rows, shapes = [], {}

# Prolate and oblate from the sphere down; the stomatocyte from v = 0.55 up, until the
# minimiser started from the last stomatocyte ends up-down symmetric (the branch ends).
down = np.round(np.arange(1.0, 0.55 - 1e-9, -step), 6)
up = np.round(np.arange(0.55, 1.0 + 1e-9, step), 6)
for branch, vs in (("prolate", down), ("oblate", down), ("stomatocyte", up)):
    found, why = H.sweep(branch, vs, modes=modes[branch])
    shapes[branch] = found
    for s in found:
        m = s.measures()
        rows.append((s.v, branch, s.energy, m["h_min_over_h_max"], m["r_hmax_over_R"]))
    print(f"{branch}: {len(found)} shapes, v {found[0].v:.2f} to {found[-1].v:.2f}, M = {modes[branch]}"
          + (f"; stopped: {why}" if why else ""))
sto = shapes["stomatocyte"]
if len(sto) < len(up):
    lo, hi = H.branch_end("stomatocyte", sto[-1].v, up[len(sto)], modes=modes["stomatocyte"], xtol=1e-3)
    print(f"the stomatocyte branch ends between v = {lo:.4f} and {hi:.4f}")

with open(f"{out}/branches.csv", "w") as f:
    f.write("v,branch,energy_over_8pi_kappa,h_min_over_h_max,r_hmax_over_R\n")
    for v, b, e, hr, rr in sorted(rows, key=lambda r: (H.BRANCHES.index(r[1]), r[0])):
        f.write(f"{v:.4f},{b},{e:.10f},{hr:.6f},{rr:.6f}\n")
for b in H.BRANCHES:     # one file per branch for gnuplot
    with open(f"{out}/{b}.dat", "w") as f:
        for v, bb, e, hr, rr in sorted(r for r in rows if r[1] == b):
            f.write(f"{v} {e} {hr} {rr}\n")

# Refinement: the energy at M modes of Eq. (6) against the finest M, at six points.
if not coarse:
    print("\nrefinement: |E(M) - E(finest M)| / E(finest M)")
    ladders = {"prolate": (8, 16, 24, 32, 48), "oblate": (8, 16, 24, 32, 48), "stomatocyte": (32, 48, 64, 96)}
    for branch, v in (("prolate", 0.65), ("oblate", 0.56), ("oblate", 0.65), ("stomatocyte", 0.56),
                      ("stomatocyte", 0.59), ("stomatocyte", 0.65)):
        energies, start = [], None
        for m in ladders[branch]:
            start = H.minimise(v, branch, modes=m, start=start)
            energies.append(start.energy)
        fine = energies[-1]
        cells = ", ".join(f"M={m}: {abs(e - fine) / fine:.1e}" for m, e in zip(ladders[branch][:-1], energies))
        print(f"  {branch:11s} v={v:.2f}  E(M={ladders[branch][-1]})={fine:.10f}  {cells}")

# Transitions at C0 = 0 (SBL: 0.652 and 0.592).
v_po = H.crossing("prolate", "oblate", 0.62, 0.68, modes_a=modes["prolate"], modes_b=modes["oblate"])
v_os = H.crossing("oblate", "stomatocyte", 0.57, 0.61, modes_a=modes["oblate"], modes_b=modes["stomatocyte"])
e_po = H.minimise(v_po, "oblate", modes=modes["oblate"]).energy
e_os = H.minimise(v_os, "oblate", modes=modes["oblate"]).energy
print("\ntransitions at C0 = 0 (Seifert, Berndl & Lipowsky 1991 in brackets):")
print(f"  prolate/oblate      v = {v_po:.4f} (0.652), E/(8 pi kappa) = {e_po:.5f}")
print(f"  oblate/stomatocyte  v = {v_os:.4f} (0.592), E/(8 pi kappa) = {e_os:.5f}")
if not coarse:
    v_os48 = H.crossing("oblate", "stomatocyte", 0.57, 0.61, modes_b=48)
    print(f"  oblate/stomatocyte with M = 48 for the stomatocyte: v = {v_os48:.4f}")

# Evans-Fung and the minima at its reduced volume.
ef = H.evans_fung_measures()
v_ef = ef["reduced_volume"]
ob = H.minimise(v_ef, "oblate", modes=modes["oblate"])
mo = ob.measures()
print(f"\nEvans-Fung: v = {v_ef:.4f}, E/(8 pi kappa) = {ef['energy_over_8pi_kappa']:.4f}, "
      f"h_min/h_max = {ef['h_min_over_h_max']:.4f}, r(h_max)/R = {ef['r_hmax_over_R']:.4f}")
print(f"oblate minimum at v = {v_ef:.4f}: E/(8 pi kappa) = {ob.energy:.4f}, "
      f"h_min/h_max = {mo['h_min_over_h_max']:.4f}, r(h_max)/R = {mo['r_hmax_over_R']:.4f}")
for b in ("prolate", "stomatocyte"):
    try:
        print(f"{b} minimum at v = {v_ef:.4f}: E/(8 pi kappa) = {H.minimise(v_ef, b, modes=modes[b]).energy:.4f}")
    except RuntimeError as err:
        print(f"{b} at v = {v_ef:.4f}: {err}")
# Cross-sections at v_EF in units of R0 (both of area 4 pi R0^2) for the plot.
r, z = ob.curve(801)
np.savetxt(f"{out}/oblate_at_ef.dat", np.c_[np.r_[r, -r[::-1]], np.r_[z, z[::-1]]])
r, z = H.evans_fung_curve(801)
scale = np.sqrt(4.0 * np.pi / ef["area"])
np.savetxt(f"{out}/evans_fung.dat", scale * np.c_[np.r_[r, -r[::-1]], np.r_[z, z[::-1]]])
with open(f"{out}/evans_fung_point.dat", "w") as f:
    f.write(f"{v_ef} {ef['energy_over_8pi_kappa']} {ef['h_min_over_h_max']} {ef['r_hmax_over_R']}\n")
print(f"\n{time.time() - t0:.0f} s")
PY

v_ef=$(awk '{ printf "%.3f", $1 }' "$out/evans_fung_point.dat")
gnuplot <<EOF
set terminal png size 1500,500 noenhanced
set output "$out/branches.png"
set multiplot layout 1,3
set grid
set xlabel "reduced volume v"
set ylabel "E / (8 pi kappa)"
set title "least bending energy, C0 = 0"
set key bottom left
set xrange [0.54:1.01]
plot "$out/prolate.dat" using 1:2 with linespoints pt 7 ps 0.5 title "prolate", \
     "$out/oblate.dat" using 1:2 with linespoints pt 7 ps 0.5 title "oblate (discocyte)", \
     "$out/stomatocyte.dat" using 1:2 with linespoints pt 7 ps 0.5 title "stomatocyte", \
     "$out/evans_fung_point.dat" using 1:2 with points pt 5 ps 1.5 title "Evans-Fung"
set ylabel "shape measure"
set title "oblate branch"
set key bottom right
set yrange [0:1.05]
plot "$out/oblate.dat" using 1:3 with linespoints pt 7 ps 0.5 title "h_min/h_max", \
     "" using 1:4 with linespoints pt 7 ps 0.5 title "r(h_max)/R", \
     "$out/evans_fung_point.dat" using 1:3 with points pt 5 ps 1.5 title "Evans-Fung h_min/h_max", \
     "" using 1:4 with points pt 9 ps 1.5 title "Evans-Fung r(h_max)/R"
set title "cross-sections at v = $v_ef, both of area 4 pi R0^2"
set xlabel "r / R0"
set ylabel "z / R0"
set xrange [-1.4:1.4]
set yrange [-0.7:1.0]
set size ratio -1
set key top center
plot "$out/oblate_at_ef.dat" with lines lw 2 title "oblate minimum", \
     "$out/evans_fung.dat" with lines lw 2 title "Evans-Fung"
unset multiplot
EOF
echo "wrote $out/branches.csv, $out/branches.png, $out/summary.txt"
if [ "$update_docs" = 1 ]; then
  cp "$out/branches.csv" "$here/docs/figures/helfrich_branches.csv"
  cp "$out/branches.png" "$here/docs/figures/helfrich_branches.png"
  echo "updated docs/figures/helfrich_branches.{csv,png}"
fi
