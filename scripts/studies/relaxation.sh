#!/usr/bin/env bash
# Cost of relaxation to equilibrium per variant (FIRE, nested levels, ...) against N.
# docs/verification/relaxation.md: the cost of reaching static equilibrium with
# each relaxation variant against particle count. For the red-blood-cell ladder
# (examples/rbc/rbc.toml at several face_cells, its layers or the given ones) and for the contact scene
# examples/spread_cell/spread_cell.toml, every variant runs to the scene's own
# criterion; the study records steps, force evaluations (coarse levels included),
# wall time and where the run landed (h_min/h_max for the RBC, and how far its
# h_min/h_max and its thickness profile are from the finest RBC run of the same variant:
# the convergence criteria), fits the exponent of wall time and of force evaluations
# against particle count per variant, and writes out/relaxation/{relaxation.csv,
# relaxation-cost.png, table.md}; the default ladder also rewrites
# docs/figures/relaxation-cost.png and the table of docs/verification/relaxation.md.
# Usage: scripts/study relaxation [--coarse] [FACE_CELLS[:LAYERS]...]
#   --coarse: face_cells 12 and 20, variants "nested example" (a few minutes); docs untouched.
#   FACE_CELLS default 12 20 32 48 64 (4,330 to 122,890 particles at the example's 5
#   layers; with plain FIRE the two largest take about an hour each on 2 cores);
#   FACE_CELLS:LAYERS sets the wall's layers too (docs/verification/rbc.md, "How the driver is placed in a five-layer wall"). RKPM_VARIANTS selects variants
#   (default "fire nested example"; also "measured", "mass_scaling", "contact" and
#   "fire2"). Every variant is plain FIRE plus its own keys: the scenes' relaxation keys
#   (nested_levels, contact_mass_scaling) are taken out first, and "example" puts back
#   the RBC example's own (nested levels and contact mass scaling); "example3" the same
#   with a third, coarser level (0.1875 of face_cells), for clouds past 1e5 particles;
#   "exact" the example's keys and the Newton-Krylov finish to 3e-5 mu, ten times below
#   the scene's criterion (the exact rest state of each cloud, RBC only). A run whose
#   directory holds a summary.json is kept, so the study can be completed in several
#   sittings.
set -euo pipefail
script_name="study relaxation"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/relaxation
update_docs=0
default_variants="fire nested example"
if [ "${1:-}" = --coarse ]; then
  shift; face_cells=(12 20); default_variants="nested example"
elif [ $# -gt 0 ]; then
  face_cells=("$@")
else
  face_cells=(12 20 32 48 64); [ -z "${RKPM_VARIANTS:-}" ] && update_docs=1
fi
read -r -a variants <<< "${RKPM_VARIANTS:-$default_variants}"
threads=${OMP_NUM_THREADS:-2}
rkpm_need gnuplot python3
rkpm=$(rkpm_program)
mkdir -p "$out"

# The [integrator] lines each variant adds to the scene.
variant_keys() {
  case $1 in
    fire) echo "" ;;
    measured) echo 'stable_step = "measured"' ;;
    nested) echo 'nested_levels = [0.375, 0.625]' ;;
    mass_scaling) echo 'mass_scaling = true' ;;
    contact) echo 'contact_mass_scaling = true' ;;
    example) printf '%s\n' 'nested_levels = [0.375, 0.625]' 'contact_mass_scaling = true' ;;
    example3) printf '%s\n' 'nested_levels = [0.1875, 0.375, 0.625]' 'contact_mass_scaling = true' ;;
    exact) printf '%s\n' 'nested_levels = [0.375, 0.625]' 'contact_mass_scaling = true' \
             'relax_finish = "newton_krylov"' 'finish_force_tol = 3e-5' ;;
    fire2) echo 'relax_method = "fire2"' ;;
    *) echo "study relaxation: unknown variant '$1' (fire, measured, nested, mass_scaling, contact, example, example3, exact, fire2)" >&2; exit 2 ;;
  esac
}

# run_case TAG SCENE_FILE VARIANT: the scene with the variant's keys, run to its criterion.
# The copy lives in OUT_DIR, so the files the scene names (file = "...") are made
# absolute against the directory of the original.
run_case() {
  local tag=$1 scene=$2 variant=$3 keys dir
  keys=$(variant_keys "$variant")
  dir=$(cd "$(dirname "$scene")" && pwd)
  [ -f "$out/$tag/summary.json" ] && { echo "$tag: done before, kept"; return; }
  # The scene's own relaxation keys go; the variant's come after [integrator].
  awk -v keys="$keys" -v dir="$dir" '
    /^file = "[^\/]/ { sub(/^file = "/, "file = \"" dir "/") }
    /^(nested_levels|contact_mass_scaling) *=/ { next }
    { print }
    /^\[integrator\]/ && keys != "" { print keys }' "$scene" > "$out/$tag.toml"
  echo "$tag: running"
  OMP_NUM_THREADS=$threads "$rkpm" run "$out/$tag.toml" --out "$out/$tag" --quiet || echo "$tag: exit $?"
}

for variant in "${variants[@]}"; do
  for res in "${face_cells[@]}"; do
    # FACE_CELLS or FACE_CELLS:LAYERS; without layers the example's own, and the tag as before.
    fc=${res%%:*}; tag=fc$fc; layers_edit=()
    if [[ $res == *:* ]]; then tag=fc${fc}l${res##*:}; layers_edit=(-e "s/^layers = .*/layers = ${res##*:}/"); fi
    sed -e "s/^face_cells = .*/face_cells = $fc/" "${layers_edit[@]}" "$here/examples/rbc/rbc.toml" > "$out/rbc_$tag.base.toml"
    run_case "rbc_${tag}_$variant" "$out/rbc_$tag.base.toml" "$variant"
  done
  # The contact scene's imported substrate cannot be coarsened: no nested levels there.
  # Imported clouds have no coarser levels.
  case $variant in nested|example|example3|exact) ;; *) run_case "spread_cell_$variant" "$here/examples/spread_cell/spread_cell.toml" "$variant" ;; esac
done

PYTHONPATH="$here/scripts/lib" python3 - "$out" "${variants[@]}" <<'PY'
import csv, glob, json, math, os, sys
import rbc_profile
out, variants = sys.argv[1], sys.argv[2:]

rows = []
for path in sorted(glob.glob(f"{out}/*/summary.json")):
    tag = os.path.basename(os.path.dirname(path))
    scene, variant = ("rbc", tag.split("_", 2)[2]) if tag.startswith("rbc_") else ("spread_cell", tag.split("_", 2)[2])
    if variant not in variants:
        continue
    s = json.load(open(path))
    levels = s.get("nested_levels", [])
    shape = s.get("shape", {})
    rows.append(dict(
        scene=scene, variant=variant, particles=s["total_particles"], steps=s["steps"],
        level_steps=sum(l["steps"] for l in levels),
        force_evaluations=s.get("force_evaluations", s["steps"] + 1) + sum(l.get("force_evaluations", l["steps"] + 1) for l in levels),
        wall_s=round(s["wall_time"], 1), status=s["status"], converged=s.get("converged", ""),
        h_ratio=round(shape["h_min_over_h_max"], 3) if shape else "",
        contact_pairs=s.get("wall_contact cell inner", {}).get("max_active_pairs", ""),
        h_exact=shape.get("h_min_over_h_max"),
        profile=rbc_profile.read(os.path.dirname(path), shape["diameter"]) if shape else None))
if not rows:
    sys.exit("study relaxation: no finished runs")
rows.sort(key=lambda r: (r["scene"], r["variant"], r["particles"]))
# Distance to the finest RBC run of the same variant, the measure of the convergence
# targets: the difference in h_min/h_max, and the profiles' RMS distance (rbc_profile.py).
for r in rows:
    r["h_ratio_vs_finest"] = r["profile_vs_finest"] = ""
    if r["scene"] != "rbc" or not r["profile"]:
        continue
    fine = max((q for q in rows if q["scene"] == "rbc" and q["variant"] == r["variant"] and q["profile"]),
               key=lambda q: q["particles"])
    if fine is r:
        continue
    r["h_ratio_vs_finest"] = f"{r['h_exact'] - fine['h_exact']:+.3f}"
    r["profile_vs_finest"] = f"{100 * rbc_profile.rms_distance(r['profile'], fine['profile']):.2f}"
for r in rows:
    del r["h_exact"], r["profile"]
fields = list(rows[0].keys())
with open(f"{out}/relaxation.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    w.writerows(rows)

def exponent(points):  # least-squares slope of log y against log x
    if len(points) < 2:
        return None
    lx = [math.log(x) for x, _ in points]; ly = [math.log(y) for _, y in points]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else None

with open(f"{out}/table.md", "w") as f:
    f.write("| scene | variant | particles | steps (fine) | coarse-level steps | force evaluations | wall [s] | status | "
            "h_min/h_max | minus the finest run's | profile vs the finest run [% of D] | contact pairs (max) |\n")
    f.write("|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|\n")
    for r in rows:
        f.write(f"| {r['scene']} | {r['variant']} | {r['particles']:,} | {r['steps']:,} | {r['level_steps']:,} | "
                f"{r['force_evaluations']:,} | {r['wall_s']} | {r['status']} | {r['h_ratio']} | "
                f"{r['h_ratio_vs_finest']} | {r['profile_vs_finest']} | {r['contact_pairs']} |\n")
    f.write("\n| variant | RBC sizes | exponent of wall time | exponent of force evaluations |\n|---|---|---:|---:|\n")
    for v in variants:
        pts = [r for r in rows if r["scene"] == "rbc" and r["variant"] == v]
        if len(pts) < 2:
            continue
        ew = exponent([(r["particles"], r["wall_s"]) for r in pts])
        ef = exponent([(r["particles"], r["force_evaluations"]) for r in pts])
        f.write(f"| {v} | {pts[0]['particles']:,} - {pts[-1]['particles']:,} | {ew:.2f} | {ef:.2f} |\n")
    for v in variants:
        pts = [r for r in rows if r["scene"] == "rbc" and r["variant"] == v]
        with open(f"{out}/rbc_{v}.dat", "w") as d:
            for r in pts:
                d.write(f"{r['particles']} {r['wall_s']} {r['force_evaluations']}\n")
PY

plots=""
for v in "${variants[@]}"; do
  [ -s "$out/rbc_$v.dat" ] && plots+="${plots:+, }'$out/rbc_$v.dat' using 1:2 with linespoints title '$v'"
done
if [ -n "$plots" ]; then
  gnuplot <<EOF
set terminal pngcairo size 800,560 noenhanced
set output '$out/relaxation-cost.png'
set logscale xy
set xlabel 'particles'
set ylabel 'wall time to equilibrium [s]'
set title 'RBC relaxation (examples/rbc/rbc.toml, $threads threads)'
set key top left
set grid
plot $plots
EOF
fi
echo "wrote $out/relaxation.csv, $out/table.md and $out/relaxation-cost.png"
if [ "$update_docs" = 1 ]; then
  cp "$out/relaxation-cost.png" "$here/docs/figures/relaxation-cost.png"
  { cat "$out/table.md"; echo
    echo "![wall time to equilibrium against particle count](../figures/relaxation-cost.png)"; } >"$out/block.md"
  rkpm_replace_generated "$here/docs/verification/relaxation.md" "$out/block.md" "scripts/study relaxation -->"
  echo "updated docs/figures/relaxation-cost.png and docs/verification/relaxation.md"
fi
