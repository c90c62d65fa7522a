"""unidyn.sweep: serial, on a thread pool and on a Dask cluster of two worker processes, the same
runs bit for bit; a worker killed in the middle loses no run and duplicates none; each run the same
as the model's own simulate with its values."""

import os
import signal
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import unidyn

# 200 runs of the double pendulum: a grid of its first angle times its lower mass
SETTINGS = [{"theta1": 0.05 + 0.01 * i, "m2": 0.5 + 0.1 * j} for i in range(40) for j in range(5)]


def same(a, b):
    """Two sweeps equal bit for bit (the NaN of a run without rows equal to itself)."""
    return (np.array_equal(a.ok, b.ok) and np.array_equal(a.final, b.final, equal_nan=True)
            and a.messages == b.messages and np.array_equal(a.events, b.events))


@pytest.fixture(scope="module")
def serial():
    return unidyn.sweep("double-pendulum", SETTINGS, t_end=0.3)


def test_each_run_is_the_models_own(serial):
    model = unidyn.load("double-pendulum")
    assert len(serial) == 200 and serial.ok.all()
    for k in (0, 77, 199):
        run = model.simulate(t_end=0.3, set=SETTINGS[k])
        assert np.array_equal(serial.final[k], run.data[-1])
    assert serial["t"].tolist() == [0.3] * 200
    table = serial.to_pandas()
    assert table.shape[0] == 200 and list(table["m2"][:5]) == [0.5, 0.6, 0.7, 0.8, 0.9]


def test_a_failed_start_is_that_runs_record():
    runs = unidyn.sweep("heavy-top", [{"theta": 0.0}, {"theta": 0.2}], t_end=0.1)
    assert runs.ok.tolist() == [False, True]
    assert "gimbal lock" in runs.messages[0]
    assert np.isnan(runs.final[0]).all() and not np.isnan(runs.final[1]).any()


def test_threads_give_the_serial_sweep(serial):
    with ThreadPoolExecutor(max_workers=2) as pool:
        assert same(unidyn.sweep("double-pendulum", SETTINGS, executor=pool, t_end=0.3), serial)


def test_dask_two_processes_and_a_worker_killed(serial):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert same(unidyn.sweep("double-pendulum", SETTINGS, executor=client, t_end=0.3,
                                 chunk=10), serial)

        # again, with one worker's process killed while the chunks run (runs of 30 s, so that
        # the kill at 0.5 s lands in the middle): its chunks run again elsewhere
        model = unidyn.load("double-pendulum")
        before = set(client.run(os.getpid).values())
        victim = min(before)

        def kill_soon():
            time.sleep(0.5)
            os.kill(victim, signal.SIGKILL)

        killer = threading.Thread(target=kill_soon)
        start = time.monotonic()
        killer.start()
        survived = unidyn.sweep(model, SETTINGS, executor=client, t_end=30, chunk=5)
        elapsed = time.monotonic() - start
        killer.join()
        assert elapsed > 0.6, "the sweep ended before the worker was killed"
        client.wait_for_workers(2, timeout=60)
        assert victim not in set(client.run(os.getpid).values())
    assert same(survived, unidyn.sweep(model, SETTINGS, t_end=30, chunk=5))
