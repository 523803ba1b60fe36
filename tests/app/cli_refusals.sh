#!/usr/bin/env bash
# Hostile input at the command line: each case must end with its documented exit code
# and a message that names the option, file or quantity, never a crash, a hang or a
# non-finite number in the output (docs/guide/running.md, "Exit codes").
# Usage: cli_refusals.sh RKPM_PROGRAM SOURCE_DIR
set -uo pipefail
rkpm=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect CODE TEXT -- COMMAND...: COMMAND exits with CODE and its output contains TEXT.
expect() {
  local code=$1 text=$2
  shift 3
  local out status
  out=$(timeout 120 "$@" 2>&1)
  status=$?
  if [ "$status" != "$code" ]; then
    echo "FAIL: $* exited $status, expected $code"; echo "$out" | tail -5; failures=$((failures + 1))
  elif ! grep -qF -- "$text" <<<"$out"; then
    echo "FAIL: $* printed no '$text'"; echo "$out" | tail -5; failures=$((failures + 1))
  else
    echo "ok: exit $code, '$text'"
  fi
}

sag="$source_dir/examples/sag/sag.toml"
expect 2 "--threads 100000: more than this machine allows" -- "$rkpm" run "$sag" --out "$work/t" --threads 100000
expect 2 "--max-steps" -- "$rkpm" run "$sag" --out "$work/m" --max-steps 99999999999999999999999

# A .geo that defines no entity: Gmsh throws a std::string from its bounding box.
geo_scene() {  # geo_scene NAME GEO_TEXT: a scene of one body meshed from NAME.geo
  printf '%s' "$2" >"$work/$1.geo"
  cat >"$work/$1.toml" <<TOML
[scene]
name = "$1"
[integrator]
mode = "relax"
[[body]]
name = "b"
[body.cloud]
generator = "gmsh"
file = "$1.geo"
mesh_size = 0.5
scale = 1e-6
[body.material]
model = "neo_hookean"
mu = 1000
lambda = 4000
TOML
}
geo_scene empty ""
expect 2 "empty.geo" -- "$rkpm" check "$work/empty.toml"
expect 2 "empty.geo" -- "$rkpm" run "$work/empty.toml" --out "$work/empty_run"
# A .geo that would end the process or run a command is refused, and writes nothing.
geo_scene quits $'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\nExit;\n'
expect 2 "line 3: 'Exit' is not allowed in an untrusted .geo script" -- "$rkpm" run "$work/quits.toml" --out "$work/quits_run"
[ -e "$work/quits_run" ] && { echo "FAIL: the refused run wrote $work/quits_run"; failures=$((failures + 1)); }
geo_scene calls $'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\nSystemCall "touch '"$work"'/pwned";\n'
expect 2 "'SystemCall' is not allowed" -- "$rkpm" check "$work/calls.toml"
[ -e "$work/pwned" ] && { echo "FAIL: the .geo script ran its command"; failures=$((failures + 1)); }

# A body force beyond the table's bound is refused with the key; a modulus that
# overflows the stress: exit 3 naming the step, the body, the particle and the field,
# and no infinity written to history.csv.
sed -e 's/acceleration = .*/acceleration = [0.0, 0.0, -1e300]/' "$sag" >"$work/huge_load.toml"
expect 2 "acceleration = [0, 0, -1e+300]: expected an array of 3 reals, each in" -- "$rkpm" check "$work/huge_load.toml"
cat >"$work/overflow.toml" <<'TOML'
[scene]
name = "overflow"
[integrator]
t_end = 1e-6
[[body]]
name = "cell"
[body.cloud]
generator = "sphere"
radius = 2e-6
cells = 4
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
zeta = -1e300
[body.director]
initial = "surface_normal"
TOML
expect 3 "non-finite value reached the output at step 0 (t = 0 s): body 'cell', particle" -- \
  "$rkpm" run "$work/overflow.toml" --out "$work/overflow" --quiet
if [ ! -s "$work/overflow/history.csv" ]; then
  echo "FAIL: the overflowing run wrote no history.csv to check"; failures=$((failures + 1))
elif grep -qiE "inf|nan" "$work/overflow/history.csv"; then
  echo "FAIL: history.csv holds a non-finite value"; failures=$((failures + 1))
fi

# Contact between clouds the law cannot hold: a substrate grid of 2.5 s0 is refused at
# set-up naming s0; a cell declared inside the block before the first step. Neither
# writes its output folder.
adhesion="$source_dir/examples/adhesion/adhesion.toml"
sed -e 's/cells = \[40, 40, 4\]/cells = [20, 20, 4]/' "$adhesion" >"$work/coarse_substrate.toml"
expect 2 "coarse_substrate.toml:62: [term] s0 = 7.5e-07: expected an equilibrium distance that holds the clouds apart" -- \
  "$rkpm" run "$work/coarse_substrate.toml" --out "$work/coarse_substrate" --quiet
sed -e 's/center = \[0.0, 0.0, 10.1776e-6\]/center = [0.0, 0.0, 8.5e-6]/' "$adhesion" >"$work/overlap.toml"
expect 2 "body 'cell' starts inside body 'substrate'" -- "$rkpm" run "$work/overlap.toml" --out "$work/overlap" --quiet
for refused in coarse_substrate overlap; do
  [ -e "$work/$refused" ] && { echo "FAIL: the refused run wrote $work/$refused"; failures=$((failures + 1)); }
done

echo "$failures failure(s)"
[ "$failures" = 0 ]
