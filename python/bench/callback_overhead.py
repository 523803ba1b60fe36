"""What driving a run from Python costs: the same scene run by the `rkpm` program and by
`Simulation.run()` with a progress callback at every step, alternately, REPEATS times
each, on THREADS threads. Prints one CSV row per run (tool, repeat, wall seconds,
steps) and ends with the medians and their ratio.

    /usr/bin/python3 python/bench/callback_overhead.py RKPM SCENE OUT_DIR REPEATS THREADS
"""
import json
import os
import statistics
import subprocess
import sys
import time

import rkpm

cli, scene, out, repeats, threads = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
env = dict(os.environ, OMP_NUM_THREADS=str(threads))
walls = {"rkpm run": [], "python, callback every step": []}
print("tool,repeat,wall_s,steps")
for k in range(repeats):
    start = time.perf_counter()
    subprocess.run([cli, "run", scene, "--out", f"{out}/cli", "--threads", str(threads), "--quiet"], check=True, env=env)
    wall = time.perf_counter() - start
    steps = json.load(open(f"{out}/cli/summary.json"))["steps"]
    walls["rkpm run"].append(wall)
    print(f"rkpm run,{k},{wall:.3f},{steps}", flush=True)

    calls = [0]

    def progress(step, t):
        calls[0] += 1

    start = time.perf_counter()
    sim = rkpm.Simulation.from_file(scene, threads=threads)
    sim.run(out=f"{out}/python", progress=progress)
    wall = time.perf_counter() - start
    assert calls[0] >= sim.summary()["steps"], "the callback ran at every step"
    walls["python, callback every step"].append(wall)
    print(f"python callback,{k},{wall:.3f},{sim.summary()['steps']}", flush=True)
    del sim

cli_median = statistics.median(walls["rkpm run"])
py_median = statistics.median(walls["python, callback every step"])
pairs = [p / c for c, p in zip(walls["rkpm run"], walls["python, callback every step"])]
print(f"# medians: rkpm run {cli_median:.2f} s, python {py_median:.2f} s, ratio {py_median / cli_median:.3f}; "
      f"pairwise ratios {', '.join(f'{r:.3f}' for r in pairs)}")
