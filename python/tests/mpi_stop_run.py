"""Run by test_mpi.py under mpirun: rank 1's progress callback stops the run at step 5
(as Ctrl-C reaching one rank first would); rank 0 saves where its run stopped to ARGV[2]."""
import json
import sys

from mpi4py import MPI

import rkpm

scene, out_json, out_dir = sys.argv[1], sys.argv[2], sys.argv[3]
rank = MPI.COMM_WORLD.Get_rank()


def progress(step, time):
    if rank == 1 and step == 5:
        raise KeyboardInterrupt


sim = rkpm.Simulation.from_file(scene, threads=1)
try:
    sim.run(out=out_dir, progress=progress)
    raised = False
except KeyboardInterrupt:
    raised = True
if rank == 0:
    with open(out_json, "w") as f:
        json.dump({"rank0_raised": raised, "steps": sim.step_count, "status": sim.summary()["status"]}, f)
