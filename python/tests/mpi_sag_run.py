"""Run by test_mpi.py under mpirun: the sag scene on every rank, one thread each; rank 0
saves the fields it reads (the whole body, in the one-process numbering) to ARGV[2]."""
import sys

import numpy as np

import rkpm

scene, out_npz, out_dir = sys.argv[1], sys.argv[2], sys.argv[3]
sim = rkpm.Simulation.from_file(scene, threads=1)
sim.run(out=out_dir)
fields = {name: getattr(sim, name)("block") for name in ("positions", "displacement", "velocity", "J", "von_mises")}
from mpi4py import MPI  # noqa: E402  (already initialised by rkpm)

if MPI.COMM_WORLD.Get_rank() == 0:
    np.savez(out_npz, ranks=MPI.COMM_WORLD.Get_size(), steps=sim.summary()["steps"], **fields)
