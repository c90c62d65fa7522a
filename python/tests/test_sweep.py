"""unidyn.sweep: serial, on a thread pool and on a Dask cluster of two worker processes, the same
runs bit for bit; a worker killed in the middle loses no run and duplicates none; each run the same
as the model's own simulate with its values."""

import os
import types
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


def largest_swing(result):
    """A reduction computed where each run is: the largest |theta1| of the run."""
    return float(np.abs(result["theta1"]).max())


def test_what_each_run_keeps():
    model = unidyn.load("double-pendulum")
    settings = SETTINGS[:6]
    direct = [model.simulate(t_end=0.3, set=s) for s in settings]
    # every row, bit for bit; a tidy table of one row per run and time
    whole = unidyn.sweep(model, settings, t_end=0.3, keep="all", chunk=4)
    for run, rows in zip(direct, whole.rows):
        assert np.array_equal(rows, run.data)
    table = whole.to_pandas()
    assert len(table) == sum(len(run) for run in direct)
    assert table[table["run"] == 5]["theta2"].tolist() == direct[5]["theta2"].tolist()
    assert (table[table["run"] == 5]["set.m2"] == settings[5]["m2"]).all()
    assert (table[table["run"] == 5]["set.theta1"] == settings[5]["theta1"]).all()
    # rows at given times: the rows of those times
    at = unidyn.sweep(model, settings, t_end=0.3, times=[0.1, 0.3])
    for run, rows in zip(direct, at.rows):
        assert np.array_equal(rows, run.data[[10, 30]])
    with pytest.raises(ValueError, match="not the time of a row"):
        unidyn.sweep(model, settings, t_end=0.3, times=[0.105])
    # a run that failed at t = 0.15 keeps its rows before, none after (as `sweep gather --times`)
    failed = types.SimpleNamespace(ok=False, t=direct[0].t[:16], data=direct[0].data[:16],
                                   columns=direct[0].columns)
    assert np.array_equal(unidyn._kept(failed, ("times", (0.1, 0.2))), direct[0].data[[10]])
    with pytest.raises(ValueError, match="not the time of a row"):
        unidyn._kept(failed, ("times", (0.105,)))
    # a reduction, on worker processes: only its value comes back
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=2) as pool:
        reduced = unidyn.sweep(model, settings, executor=pool, t_end=0.3, reduce=largest_swing)
    assert reduced.values == [largest_swing(run) for run in direct]
    assert reduced.to_pandas()["value"].tolist() == reduced.values
    with pytest.raises(ValueError, match="one of"):
        unidyn.sweep(model, settings, keep="all", reduce=largest_swing)
