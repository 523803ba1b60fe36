# Sourced by every script in scripts/ and scripts/studies/: the one convention
# (docs/development/scripts.md).
#   build folder   RKPM_BUILD_DIR, default build/ at the top of the repository; a
#                  script builds (Release) only the targets it needs, with rkpm_build.
#   a built rkpm   RKPM_BIN names an rkpm program to use instead of building one.
#   output root    RKPM_OUT, default out/ (ignored by git); a study writes its runs
#                  into RKPM_OUT/NAME/. Only a full study run rewrites docs/.
#   --help         prints the script's header comment and exits 0.
# The caller sets script_name before sourcing (the name messages start with).

rkpm_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
rkpm_build_dir=${RKPM_BUILD_DIR:-"$rkpm_root/build"}
rkpm_out_root=${RKPM_OUT:-"$rkpm_root/out"}
: "${script_name:=$(basename "$0")}"

rkpm_die() { echo "$script_name: $*" >&2; exit 1; }

# rkpm_help_if_asked "$@": the header comment (the lines after the shebang up to the
# first line that is not a comment) for -h or --help anywhere in the arguments.
rkpm_help_if_asked() {
  local arg
  for arg in "$@"; do
    if [ "$arg" = -h ] || [ "$arg" = --help ]; then
      awk 'NR == 1 && /^#!/ { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"
      exit 0
    fi
  done
}

# rkpm_build TARGET...: configures the build folder (Release) and builds only TARGETs.
rkpm_build() {
  cmake -S "$rkpm_root" -B "$rkpm_build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
  local targets=() t
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$rkpm_build_dir" -j"$(nproc)" "${targets[@]}"
}

# rkpm_program: the rkpm executable, RKPM_BIN or built here.
rkpm_program() {
  if [ -n "${RKPM_BIN:-}" ]; then
    [ -x "$RKPM_BIN" ] || rkpm_die "RKPM_BIN=$RKPM_BIN is not an executable"
    realpath "$RKPM_BIN"
  else
    # errexit does not reach into a command substitution: fail here, not with a stale binary.
    rkpm_build rkpm >&2 || rkpm_die "building rkpm in $rkpm_build_dir failed"
    echo "$(cd "$rkpm_build_dir" && pwd)/src/app/rkpm"
  fi
}

# rkpm_need COMMAND...: fails with a message naming the missing command.
rkpm_need() {
  local c
  for c in "$@"; do
    command -v "$c" >/dev/null || rkpm_die "$c is required (bash scripts/install-deps.sh installs it)"
  done
}

# rkpm_need_python_modules MODULE...: Debian's /usr/bin/python3 must import each (the
# studies' Python runs on it: a python3 first on the PATH may lack numpy or scipy).
rkpm_need_python_modules() {
  local m
  for m in "$@"; do
    /usr/bin/python3 -c "import $m" 2>/dev/null ||
      rkpm_die "/usr/bin/python3 with $m is required (bash scripts/install-deps.sh installs it)"
  done
}

# rkpm_replace_generated DOC FILE [KEY]: replaces the text between DOC's
# "<!-- BEGIN GENERATED" line (the one that also holds KEY, when a page has several
# generated blocks) and the next "<!-- END GENERATED" line with FILE's contents.
rkpm_replace_generated() {
  local doc=$1 file=$2 key=${3:-}
  grep -F '<!-- BEGIN GENERATED' "$doc" | grep -qF -- "$key" && grep -q '<!-- END GENERATED' "$doc" ||
    rkpm_die "$doc lacks the BEGIN GENERATED${key:+ ($key)} and END GENERATED markers"
  awk -v file="$file" -v key="$key" '
    index($0, "<!-- BEGIN GENERATED") && index($0, key) {
      print; while ((getline line < file) > 0) print line; skip = 1; next }
    skip && /<!-- END GENERATED/ { skip = 0 }
    !skip { print }' "$doc" > "$doc.tmp"
  mv "$doc.tmp" "$doc"
}

# rkpm_python_study DRIVER OUT STEM PAGE KEY FULL [ARGS...]: runs a study driver of
# scripts/lib (a Python file taking --rkpm --out --threads and ARGS; study_runs.py) with
# Debian's python3, writing OUT/STEM.csv, OUT/STEM.png and OUT/table.md; when FULL is 1,
# copies the CSV and PNG into docs/figures/ and puts the table into docs/PAGE's
# generated block holding KEY.
rkpm_python_study() {
  local driver=$1 out=$2 stem=$3 page=$4 key=$5 full=$6 rkpm
  shift 6
  rkpm_need_python_modules numpy scipy matplotlib
  rkpm=$(rkpm_program)
  mkdir -p "$out"
  PYTHONPATH="$rkpm_root/scripts/lib" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$rkpm_root/scripts/lib/$driver" \
    --rkpm "$rkpm" --out "$out" --threads "${RKPM_THREADS:-2}" "$@"
  if [ "$full" = 1 ]; then
    cp "$out/$stem.csv" "$out/$stem.png" "$rkpm_root/docs/figures/"
    rkpm_replace_generated "$rkpm_root/docs/$page" "$out/table.md" "$key"
  fi
}
