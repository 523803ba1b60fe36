"""Running scenes for a study from Python: a scene file read into a dict, changed, written
as TOML (the module rkpm's writer, python/rkpm/scene_toml.py, which needs no build) and
run by an rkpm program, with the wall time and the machine's load kept beside the run."""
import os
import subprocess
import sys
import time
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python", "rkpm"))
import scene_toml  # noqa: E402


def load_scene(relative_path):
    """The scene file at `relative_path` from the top of the repository, as a dict."""
    with open(os.path.join(ROOT, relative_path), "rb") as f:
        return tomllib.load(f)


UNSTABLE = 3  # rkpm's exit code for a run stopped with a diagnosis (docs/guide/running.md)


def run_scene(rkpm, scene, folder, threads, allow_unstable=False):
    """Writes `scene` to folder.toml and runs it into `folder`, unless the folder holds a
    summary.json (a run done before is kept: delete the folder to rerun). The study's
    wall time (set-up and output included) goes to folder/study_wall_seconds and the
    1-, 5- and 15-minute load averages after the run to folder/study_load. With
    `allow_unstable`, a run that stops with a diagnosis (exit 3; its summary.json says
    so) is kept as a result; any other failure raises."""
    if os.path.exists(os.path.join(folder, "summary.json")):
        print(f"{folder}: done before, kept", flush=True)
        return folder
    os.makedirs(folder, exist_ok=True)
    with open(folder + ".toml", "w") as f:
        f.write(scene_toml.dumps(scene))
    print(f"{folder}: running", flush=True)
    start = time.monotonic()
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_WAIT_POLICY="passive")
    done = subprocess.run([rkpm, "run", folder + ".toml", "--out", folder, "--threads", str(threads), "--quiet"],
                          env=env)
    if done.returncode != 0 and not (allow_unstable and done.returncode == UNSTABLE):
        raise subprocess.CalledProcessError(done.returncode, done.args)
    with open(os.path.join(folder, "study_wall_seconds"), "w") as f:
        f.write(f"{time.monotonic() - start:.2f}\n")
    with open(os.path.join(folder, "study_load"), "w") as f:
        f.write(" ".join(open("/proc/loadavg").read().split()[:3]) + "\n")
    return folder


def study_wall_seconds(folder):
    return float(open(os.path.join(folder, "study_wall_seconds")).read())


def study_load(folder):
    """The 1-minute load average after the run."""
    return open(os.path.join(folder, "study_load")).read().split()[0]


def write_rows(rows, columns, path):
    """A study's CSV: `columns` of each row dict, floats to 6 significant digits."""
    import csv
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: (f"{r[k]:.6g}" if isinstance(r[k], float) else r[k]) for k in columns})


def study_parser(description):
    """The arguments every study driver takes (scripts/lib/common.sh, rkpm_python_study):
    --rkpm the program, --out the folder for the runs and results, --threads."""
    import argparse
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--rkpm", required=True, help="the rkpm program")
    parser.add_argument("--out", required=True, help="folder for the runs and the results")
    parser.add_argument("--threads", type=int, default=2)
    return parser


def write_results(out, stem, rows, columns, table_text, plot):
    """A study's results in `out`: STEM.csv (`write_rows`), table.md and STEM.png drawn by
    plot(path); prints the table."""
    write_rows(rows, columns, os.path.join(out, f"{stem}.csv"))
    with open(os.path.join(out, "table.md"), "w") as f:
        f.write(table_text)
    plot(os.path.join(out, f"{stem}.png"))
    print(table_text)
