"""The module under mpirun with mpi4py: a scene runs on 2 ranks as the rkpm program does,
and the fields read from Python are the one-process run's, bit for bit, in its numbering."""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import rkpm

HERE = os.path.dirname(os.path.abspath(__file__))
MPIRUN = shutil.which("mpirun")


@pytest.mark.skipif(MPIRUN is None, reason="mpirun is not installed")
def test_two_ranks_give_the_one_process_fields(sag_scene, tmp_path):
    pytest.importorskip("mpi4py")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    subprocess.run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-n", "2", sys.executable,
                    os.path.join(HERE, "mpi_sag_run.py"), sag_scene, str(tmp_path / "ranks.npz"),
                    str(tmp_path / "ranks")], env=env, check=True, timeout=300)
    distributed = np.load(tmp_path / "ranks.npz")
    assert int(distributed["ranks"]) == 2
    assert (tmp_path / "ranks" / "summary.json").exists()

    sim = rkpm.Simulation.from_file(sag_scene, threads=1)
    sim.run(out=str(tmp_path / "one"))
    assert int(distributed["steps"]) == sim.summary()["steps"]
    for name in ("positions", "displacement", "velocity", "J", "von_mises"):
        np.testing.assert_array_equal(distributed[name], getattr(sim, name)("block"), err_msg=name)


@pytest.mark.skipif(MPIRUN is None, reason="mpirun is not installed")
def test_a_stop_on_one_rank_stops_every_rank_at_the_same_step(sag_scene, tmp_path):
    pytest.importorskip("mpi4py")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    subprocess.run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-n", "2", sys.executable,
                    os.path.join(HERE, "mpi_stop_run.py"), sag_scene, str(tmp_path / "stop.json"),
                    str(tmp_path / "ranks")], env=env, check=True, timeout=300)
    result = json.loads((tmp_path / "stop.json").read_text())
    # Rank 0's own callback never asked to stop: it stopped with rank 1, at its step.
    assert result == {"rank0_raised": False, "steps": 5, "status": "interrupted"}
