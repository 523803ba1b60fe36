#!/usr/bin/env bash
# Red-blood-cell relaxation at several particle counts: shape against the finest run.
# The same scene (examples/rbc/rbc.toml) at several resolutions (face_cells / layers
# of the shell), each run to convergence; shape metrics, steps and wall time; error
# against Evans-Fung and against the finest run. Writes out/rbc/{study.csv, *.png,
# table.md}; the default ladder also rewrites docs/figures/rbc-study* and the table of
# docs/verification/rbc.md. About 15 minutes on 2 cores for the default ladder.
# Usage: scripts/study rbc [--coarse] [RESOLUTIONS...]
#   --coarse: 12:5 and 20:5 only (about a minute); docs untouched.
#   RESOLUTIONS are face_cells:layers pairs, default 12:5 20:5 32:5 48:5 64:5
#   (4,330 / 12,010 / 30,730 / 69,130 / 122,890 particles): the wall keeps its 5
#   layers (the driver acts on the inner or outer half of the wall, so the layer
#   count changes the active bending moment itself) and the surface is refined.
#   A directory that already holds a summary.json is kept, so the study can be
#   completed in several sittings.
set -euo pipefail
script_name="study rbc"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/rbc
update_docs=0
if [ "${1:-}" = --coarse ]; then
  shift; resolutions=(12:5 20:5)
elif [ $# -gt 0 ]; then
  resolutions=("$@")
else
  resolutions=(12:5 20:5 32:5 48:5 64:5); update_docs=1
fi
threads=${OMP_NUM_THREADS:-2}
rkpm_need gnuplot python3
rkpm=$(rkpm_program)
mkdir -p "$out"

for res in "${resolutions[@]}"; do
  fc=${res%%:*}; ly=${res##*:}
  tag="fc${fc}_l${ly}"
  [ -f "$out/$tag/summary.json" ] && { echo "$tag: done before, kept"; continue; }
  sed -e "s/^face_cells = .*/face_cells = $fc/" -e "s/^layers = .*/layers = $ly/" \
      -e "s/^name = \"rbc\"/name = \"rbc_$tag\"/" "$here/examples/rbc/rbc.toml" > "$out/$tag.toml"
  echo "$tag: running"
  OMP_NUM_THREADS=$threads "$rkpm" run "$out/$tag.toml" --out "$out/$tag" --quiet || echo "$tag: exit $?"
done

PYTHONPATH="$here/scripts/lib" python3 - "$out" "${resolutions[@]}" <<'PY'
import json, math, sys
import rbc_profile
out, res = sys.argv[1], sys.argv[2:]
rows = []
for r in res:
    fc, ly = r.split(":")
    tag = f"fc{fc}_l{ly}"
    try:
        s = json.load(open(f"{out}/{tag}/summary.json"))
    except OSError:
        continue
    sh = s["shape"]
    rows.append(dict(tag=tag, particles=s["total_particles"], steps=s["steps"], wall_s=s["wall_time"],
                     converged=s.get("converged"), h_ratio=sh["h_min_over_h_max"], r_hmax=sh["r_hmax_over_R"],
                     rms_ef=sh["rms_vs_evans_fung_over_D"], updown=sh["updown_asymmetry"],
                     reduced_volume=sh["reduced_volume"], diameter_um=sh["diameter"] * 1e6,
                     profile=rbc_profile.read(f"{out}/{tag}", sh["diameter"]),
                     # The fluid left between the faces on the axis, whether they crossed, and
                     # how many particle pairs of the two faces pressed on each other at most.
                     gap_um=sh["inner_gap_centre"] * 1e6 if "inner_gap_centre" in sh else "",
                     crossed=sh.get("walls_crossed", ""),
                     contact_pairs=s.get("wall_contact cell inner", {}).get("max_active_pairs", "")))
if not rows:
    sys.exit("no finished runs")
fine = max(rows, key=lambda r: r["particles"])
for r in rows:
    r["rms_vs_finest"] = rbc_profile.rms_distance(r["profile"], fine["profile"])
# Observed order of the in-plane refinement: the change of the distance to the finest
# run between successive resolutions, against the in-plane spacing h ~ 1 / face_cells.
ordered = sorted(rows, key=lambda r: r["particles"])
for r in ordered:
    r["face_cells"] = int(r["tag"].split("_")[0][2:])
    r["rate"] = ""
for a, b in zip(ordered, ordered[1:]):
    if b is not fine and a["rms_vs_finest"] > 0 and b["rms_vs_finest"] > 0:
        b["rate"] = f"{math.log(a['rms_vs_finest'] / b['rms_vs_finest']) / math.log(b['face_cells'] / a['face_cells']):.2f}"
keys = ["tag", "particles", "steps", "wall_s", "converged", "h_ratio", "r_hmax", "rms_ef", "rms_vs_finest",
        "rate", "updown", "reduced_volume", "diameter_um", "gap_um", "crossed", "contact_pairs"]
with open(f"{out}/study.csv", "w") as f:
    f.write(",".join(keys) + "\n")
    for r in sorted(rows, key=lambda r: r["particles"]):
        f.write(",".join(str(r[k]) for k in keys) + "\n")
with open(f"{out}/table.md", "w") as f:
    f.write("| particles | face_cells:layers | steps | wall [s] | h_min/h_max | r(h_max)/R | RMS vs EF / D | "
            "RMS vs finest / D | order | up-down | reduced volume | D [um] | fluid gap on axis [um] | "
            "faces crossed | contact pairs (max) |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in ordered:
        fc, ly = r["tag"][2:].split("_l")
        f.write(f"| {r['particles']:,} | {fc}:{ly} | {r['steps']:,} | {r['wall_s']:.0f} | {r['h_ratio']:.3f} | "
                f"{r['r_hmax']:.3f} | {r['rms_ef']:.3f} | {r['rms_vs_finest']:.4f} | {r['rate'] or '-'} | "
                f"{r['updown']:.3f} | {r['reduced_volume']:.3f} | {r['diameter_um']:.2f} | "
                f"{'-' if r['gap_um'] == '' else format(r['gap_um'], '.3f')} | "
                f"{'-' if r['crossed'] == '' else ('yes' if r['crossed'] else 'no')} | "
                f"{'-' if r['contact_pairs'] == '' else format(r['contact_pairs'], ',')} |\n")
print(open(f"{out}/table.md").read())
PY

gnuplot <<EOF
set datafile separator ","
set terminal png size 900,600 noenhanced
set key outside right
set logscale x
set grid
set output "$out/study_vs_particles.png"
set xlabel "particles"
set ylabel "metric"
plot "$out/study.csv" every ::1 using 2:6 with linespoints title "h_min/h_max (EF 0.316)", \
     "" every ::1 using 2:7 with linespoints title "r(h_max)/R (EF 0.70)", \
     "" every ::1 using 2:8 with linespoints title "RMS vs Evans-Fung / D", \
     "" every ::1 using 2:9 with linespoints title "RMS vs finest / D"
set output "$out/study_vs_time.png"
set logscale xy
set key inside bottom left
set xlabel "wall time [s], 2 threads"
set ylabel "profile distance / D"
# The finest run is its own reference (distance 0): log scales leave it out.
plot "$out/study.csv" every ::1 using 4:(\$9 > 0 ? \$9 : NaN) with linespoints title "RMS vs finest run / D (error estimate)", \
     "" every ::1 using 4:8 with linespoints title "RMS vs Evans-Fung / D"
EOF
echo "wrote $out/study.csv, $out/table.md, $out/study_vs_particles.png, $out/study_vs_time.png"
if [ "$update_docs" = 1 ]; then
  cp "$out/study.csv" "$here/docs/figures/rbc-study.csv"
  cp "$out/study_vs_particles.png" "$here/docs/figures/rbc-study-vs-particles.png"
  cp "$out/study_vs_time.png" "$here/docs/figures/rbc-study-vs-time.png"
  rkpm_replace_generated "$here/docs/verification/rbc.md" "$out/table.md" "scripts/study rbc -->"
  echo "updated docs/figures/rbc-study* and docs/verification/rbc.md"
fi
