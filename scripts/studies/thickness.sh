#!/usr/bin/env bash
# Red-blood-cell relaxation at several wall thicknesses: shape against Evans-Fung.
# The scene (examples/rbc/rbc.toml) as shipped with only [body.cloud] thickness
# changed, each run to convergence (nested levels included); shape metrics against
# Evans-Fung, steps and wall time. Writes out/thickness/{study.csv, table.md,
# profiles.png}; the default thicknesses also rewrite docs/figures/rbc-thickness-* and
# the thickness table of docs/verification/rbc.md. About 5 minutes on 2 cores.
# Usage: scripts/study thickness [--coarse] [THICKNESSES_UM...]
#   --coarse: 0.3 and 0.5 um at face_cells 12 (about a minute); docs untouched.
#   THICKNESSES_UM default 0.3 0.4 0.5 0.75 (the seed gives 0.5 and "about 0.3").
#   RKPM_FACE_CELLS=N runs the shell at face_cells N instead of the scene's.
#   RKPM_MAX_STEPS caps each run's steps on its own cloud (default 10000): a wall that
#   does not come to rest within it is reported as not converged.
#   A directory that already holds a summary.json is kept, so the study can be
#   completed in several sittings.
set -euo pipefail
script_name="study thickness"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/thickness
update_docs=0
if [ "${1:-}" = --coarse ]; then
  shift; thicknesses=(0.3 0.5); : "${RKPM_FACE_CELLS:=12}"
elif [ $# -gt 0 ]; then
  thicknesses=("$@")
else
  thicknesses=(0.3 0.4 0.5 0.75); [ -z "${RKPM_FACE_CELLS:-}" ] && update_docs=1
fi
threads=${OMP_NUM_THREADS:-2}
rkpm_need gnuplot python3
rkpm=$(rkpm_program)
mkdir -p "$out"

tags=()
for t in "${thicknesses[@]}"; do
  tag="T${t}um${RKPM_FACE_CELLS:+_fc$RKPM_FACE_CELLS}"
  tags+=("$tag")
  [ -f "$out/$tag/summary.json" ] && { echo "$tag: done before, kept"; continue; }
  sed -e "s/^thickness = .*/thickness = ${t}e-6/" -e "s/^name = \"rbc\"/name = \"rbc_$tag\"/" \
      -e "s/^max_steps = .*/max_steps = ${RKPM_MAX_STEPS:-10000}/" \
      ${RKPM_FACE_CELLS:+-e "s/^face_cells = .*/face_cells = $RKPM_FACE_CELLS/"} \
      "$here/examples/rbc/rbc.toml" > "$out/$tag.toml"
  echo "$tag: running"
  OMP_NUM_THREADS=$threads "$rkpm" run "$out/$tag.toml" --out "$out/$tag" --quiet || echo "$tag: exit $?"
done

load=$(cut -d' ' -f1-3 /proc/loadavg)
python3 - "$out" "$threads" "$load" "${tags[@]}" <<'PY'
import csv, json, sys
out, threads, load, tags = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
rows = []
for tag in tags:
    try:
        s = json.load(open(f"{out}/{tag}/summary.json"))
    except OSError:
        continue
    sh = s["shape"]
    levels = s.get("nested_levels", [])
    rows.append(dict(tag=tag, thickness_um=float(tag[1:].split("um")[0]), particles=s["total_particles"],
                     level_steps="+".join(str(l["steps"]) for l in levels), steps=s["steps"],
                     wall_s=s["wall_time"], converged=s.get("converged"), h_ratio=sh["h_min_over_h_max"],
                     r_hmax=sh["r_hmax_over_R"], rms_ef=sh["rms_vs_evans_fung_over_D"], updown=sh["updown_asymmetry"],
                     reduced_volume=sh["reduced_volume"], diameter_um=sh["diameter"] * 1e6,
                     gap_um=sh["inner_gap_centre"] * 1e6, wall_centre_um=sh["wall_thickness_centre"] * 1e6,
                     biconcave=sh["biconcave"], matches_evans_fung=sh.get("matches_evans_fung")))
if not rows:
    sys.exit("no finished runs")
rows.sort(key=lambda r: r["thickness_um"])
keys = list(rows[0].keys())
with open(f"{out}/study.csv", "w") as f:
    f.write(",".join(keys) + "\n")
    for r in rows:
        f.write(",".join(str(r[k]) for k in keys) + "\n")
with open(f"{out}/table.md", "w") as f:
    f.write(f"Measured by `scripts/study thickness`, {threads} threads, load average after the "
            f"runs {load}. Criteria of the scene: h_min/h_max <= 0.5, r(h_max)/R in 0.55-0.85, RMS <= 5 % of D, "
            "up-down <= 5 %.\n\n")
    f.write("| T [um] | particles | steps (levels + own cloud) | wall [s] | converged | h_min/h_max | r(h_max)/R | "
            "RMS vs Evans-Fung [% of D] | up-down [%] | reduced volume | D [um] | fluid on the axis [um] | "
            "wall on the axis [um] | biconcave | all four criteria |\n")
    f.write("|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n")
    for r in rows:
        steps = f"{r['level_steps']} + {r['steps']:,}" if r["level_steps"] else f"{r['steps']:,}"
        f.write(f"| {r['thickness_um']:g} | {r['particles']:,} | {steps} | {r['wall_s']:.0f} | "
                f"{'yes' if r['converged'] else 'no'} | {r['h_ratio']:.3f} | {r['r_hmax']:.3f} | "
                f"{100 * r['rms_ef']:.1f} | {100 * r['updown']:.1f} | {r['reduced_volume']:.3f} | "
                f"{r['diameter_um']:.2f} | {r['gap_um']:.3f} | {r['wall_centre_um']:.3f} | "
                f"{'yes' if r['biconcave'] else 'no'} | "
                f"{ {True: 'yes', False: 'no'}.get(r['matches_evans_fung'], '-')} |\n")
print(open(f"{out}/table.md").read())
# Thickness profiles h(r), each beside its own Evans-Fung curve (scaled to its diameter),
# in units of the run's diameter, for the plot.
with open(f"{out}/profiles.dat", "w") as f:
    for r in rows:
        D = r["diameter_um"] * 1e-6
        f.write(f"# T = {r['thickness_um']:g} um\n")
        for p in csv.DictReader(open(f"{out}/{r['tag']}/shape_profile.csv")):
            f.write(f"{2 * float(p['r']) / D} {float(p['thickness']) / D} {float(p['evans_fung']) / D}\n")
        f.write("\n\n")
with open(f"{out}/profiles.titles", "w") as f:
    f.write(" ".join(f"{r['thickness_um']:g}" for r in rows))
PY

titles=($(cat "$out/profiles.titles"))
plot="plot"
for i in "${!titles[@]}"; do
  plot+=" \"$out/profiles.dat\" index $i using 1:2 with linespoints title \"T = ${titles[$i]} um\","
done
plot+=" \"$out/profiles.dat\" index 0 using 1:3 with lines dashtype 2 lc rgb \"black\" title \"Evans-Fung\""
gnuplot <<EOF
set terminal png size 900,600 noenhanced
set key outside right
set grid
set output "$out/profiles.png"
set xlabel "2 r / D"
set ylabel "thickness h(r) / D"
$plot
EOF
echo "wrote $out/study.csv, $out/table.md, $out/profiles.png"
if [ "$update_docs" = 1 ]; then
  cp "$out/study.csv" "$here/docs/figures/rbc-thickness-study.csv"
  cp "$out/profiles.png" "$here/docs/figures/rbc-thickness-profiles.png"
  rkpm_replace_generated "$here/docs/verification/rbc.md" "$out/table.md" "scripts/study thickness -->"
  echo "updated docs/figures/rbc-thickness-* and docs/verification/rbc.md"
fi
