"""unidyn.load, derive, simulate and rhs: against the command's own output (bit for bit), against
equations derived independently here, and as an array API (shapes, errors, threads)."""

import io
import math
import os
import threading
import time

import numpy as np
import pytest

import unidyn

DOUBLE_PENDULUM = """unidyn: 1
name: two rods
parameters: {m1: 1.0, m2: 2.0, l1: 1.5, l2: 0.7, g: 9.81}
coordinates: [theta1, theta2]
particles:
  P1: {mass: m1, position: "l1*[sin(theta1), -cos(theta1), 0]"}
  P2: {mass: m2, position: "P1.position + l2*[sin(theta2), -cos(theta2), 0]"}
forces:
  - gravity: -g*E2
initial: {theta1: 1.0, theta2: 2.0}
"""


def double_pendulum_accelerations(th1, th2, w1, w2, m1, m2, l1, l2, g):
    """The planar double pendulum's Lagrange equations, derived by hand (absolute angles from the
    downward vertical):
      (m1 + m2) l1 θ1'' + m2 l2 cos(θ1 − θ2) θ2'' = −m2 l2 sin(θ1 − θ2) θ2'² − (m1 + m2) g sin θ1
      l1 cos(θ1 − θ2) θ1'' + l2 θ2'' = l1 sin(θ1 − θ2) θ1'² − g sin θ2"""
    c, s = math.cos(th1 - th2), math.sin(th1 - th2)
    M = np.array([[(m1 + m2) * l1, m2 * l2 * c], [l1 * c, l2]])
    f = np.array([-m2 * l2 * s * w2**2 - (m1 + m2) * g * math.sin(th1),
                  l1 * s * w1**2 - g * math.sin(th2)])
    return np.linalg.solve(M, f)


def test_load_a_bundled_model_a_file_and_a_text(tmp_path):
    by_name = unidyn.load("double-pendulum")
    assert by_name.name == "Planar double pendulum"
    assert by_name.coordinates == ["theta1", "theta2"]
    assert by_name.parameters == {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81}
    path = tmp_path / "two-rods.yaml"
    path.write_text(DOUBLE_PENDULUM)
    assert unidyn.load(path).parameters["l1"] == 1.5
    assert unidyn.load(DOUBLE_PENDULUM).name == "two rods"
    assert unidyn.load("rolling-disk").constraints == ["height", "pi1", "pi2"]


def test_load_a_urdf_file(tmp_path):
    """A URDF file is imported (`unidyn import`) and loaded as the model it becomes; a file it
    refuses is a ModelError at the file's line and column."""
    examples = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "urdf")
    arm = unidyn.load(os.path.join(examples, "three-link-arm.urdf"))
    assert arm.name == "three_link_arm"
    assert arm.coordinates == ["shoulder", "elbow", "wrist"]
    assert arm.constraints == []
    limited = unidyn.load(os.path.join(examples, "three-link-arm.urdf"), limits=True)
    assert limited.constraints == ["elbow_lower", "elbow_upper", "wrist_lower", "wrist_upper"]
    with pytest.raises(ValueError, match="--limits applies to URDF and MJCF files"):
        unidyn.load("double-pendulum", limits=True)
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a"><inertial><mass value="-1"/>'
                   '</inertial></link>\n</robot>\n')
    with pytest.raises(unidyn.ModelError) as error:
        unidyn.load(str(bad))
    assert (error.value.line, error.value.column) == (2, 41)
    assert "a mass must be positive" in str(error.value)


def test_model_errors_carry_file_line_and_column(tmp_path):
    bad = DOUBLE_PENDULUM.replace("l2*[sin(theta2)", "l3*[sin(theta2)")
    with pytest.raises(unidyn.ModelError) as error:
        unidyn.load(bad)
    # line 7, the column of "l3" in it (1-based)
    line = bad.splitlines()[6]
    assert (error.value.file, error.value.line, error.value.column) == (
        "<string>", 7, line.index("l3") + 1)
    assert "unknown name 'l3'" in str(error.value)
    assert isinstance(error.value, ValueError)
    path = tmp_path / "bad.yaml"
    path.write_text(bad)
    with pytest.raises(unidyn.ModelError) as error:
        unidyn.load(path)
    assert str(error.value).startswith(f"{path}:7:{line.index('l3') + 1}: ")
    with pytest.raises(ValueError, match="neither a model file nor a bundled model"):
        unidyn.load("no-such-model")


def test_derive_is_the_commands_text(command):
    top = unidyn.load("heavy-top")
    assert top.derive() == command("derive", "heavy-top")
    assert top.derive(method="kane", format="latex") == command(
        "derive", "heavy-top", "--method", "kane", "--format", "latex")
    with pytest.raises(ValueError, match="--method must be"):
        top.derive(method="hamilton")


def test_simulate_is_the_commands_run(command):
    top = unidyn.load("heavy-top")
    run = top.simulate(t_end=1, set={"m": 2.0, "theta": 0.4})
    csv = np.loadtxt(io.StringIO(command("simulate", "heavy-top", "--t-end", "1", "--set", "m=2",
                                         "--set", "theta=0.4")), delimiter=",", skiprows=1)
    assert run.ok and len(run) == 101 == csv.shape[0]
    # the CSV's shortest round-trip numbers read back as the same doubles
    assert np.array_equal(run.data, csv)
    assert run["theta"][0] == 0.4
    assert run.t[-1] == 1.0
    assert run.summary.startswith("Heavy symmetric top (Lagrange top): simulated from t = 0 to 1")
    frame = run.to_pandas()
    assert list(frame.columns) == run.columns and frame.shape == run.data.shape


def test_simulate_with_dop853_follows_dopri5():
    top = unidyn.load("heavy-top")
    eighth, fifth = top.simulate(t_end=1, method="dop853"), top.simulate(t_end=1)
    assert "(dop853)" in eighth.summary and "(dopri5)" in fifth.summary
    assert eighth.data.shape == fifth.data.shape
    # both at the model's rtol 1e-12: the same motion to far below the plot's resolution
    assert np.max(np.abs(eighth.data - fifth.data)) < 1e-8


def test_simulate_keeps_events_and_refuses_bad_options():
    ball = unidyn.load("bouncing-ball").simulate(t_end=2)
    impacts = [t for t, what in ball.events if "impact" in what]
    # dropped from h, the first impact at t1 = sqrt(2 h / g) (§2.10)
    h, g = ball["z"][0], unidyn.load("bouncing-ball").parameters["g"]
    assert impacts and abs(impacts[0] - math.sqrt(2 * h / g)) < 1e-9
    with pytest.raises(ValueError, match="t_end must be positive"):
        unidyn.load("bouncing-ball").simulate(t_end=-1)
    with pytest.raises(ValueError, match="nosuch"):
        unidyn.load("bouncing-ball").simulate(set={"nosuch": 1})
    with pytest.raises(KeyError, match="no column 'nosuch'"):
        ball["nosuch"]


def test_rhs_against_the_double_pendulum_derived_by_hand():
    model = unidyn.load(DOUBLE_PENDULUM)
    rng = np.random.default_rng(7)
    q, qd = rng.uniform(-3, 3, (50, 2)), rng.uniform(-2, 2, (50, 2))
    p = dict(m1=1.0, m2=3.0, l1=1.5, l2=0.7, g=9.81)
    qdd, lam = model.rhs(q, qd, set={"m2": 3.0})
    assert qdd.shape == (50, 2) and lam.shape == (50, 0)
    for k in range(50):
        expected = double_pendulum_accelerations(*q[k], *qd[k], **p)
        assert np.allclose(qdd[k], expected, rtol=1e-12, atol=1e-12)
    # one state at a time: the same numbers as the batch
    one, _ = model.rhs(q[3], qd[3], set={"m2": 3.0})
    assert one.shape == (2,) and np.array_equal(one, qdd[3])
    with pytest.raises(ValueError, match="must both be of 2 values"):
        model.rhs([0.1, 0.2, 0.3], [0, 0, 0])
    with pytest.raises(ValueError, match="not a parameter"):
        model.rhs(q, qd, set={"theta1": 1.0})


def test_rhs_multipliers_of_a_constrained_model():
    # the Cartesian spherical pendulum at rest hanging: the rod holds the weight, R = λ ∂Ψ/∂r = 2λr
    model = unidyn.load("spherical-pendulum-cartesian")
    p = model.parameters
    qdd, lam = model.rhs([0, 0, -p["L"]], [0, 0, 0])
    assert np.allclose(qdd, 0, atol=1e-12)
    assert lam.shape == (1,) and abs(2 * lam[0] * -p["L"] - p["m"] * p["g"]) < 1e-12


def test_work_runs_without_the_interpreters_lock():
    model = unidyn.load("double-pendulum")
    states = np.zeros((400_000, 2))
    ticks = []
    worker = threading.Thread(target=lambda: model.rhs(states, states))
    start = time.perf_counter()
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    # the main thread kept running Python while the batch was evaluated
    assert time.perf_counter() - start > 0.02 and len(ticks) > 5


def test_threads_share_one_compiled_model():
    model = unidyn.load("heavy-top")
    runs = [None] * 4

    def run(k):
        runs[k] = model.simulate(t_end=0.5, set={"m": 1.0 + k})

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(4):
        assert np.array_equal(runs[k].data, model.simulate(t_end=0.5, set={"m": 1.0 + k}).data)


def test_ctrl_c_ends_a_simulation_at_once():
    """Ctrl-C during simulate raises KeyboardInterrupt within a fraction of a second (it used to take
    effect only after the whole run: the Kepler problem to t = 1e5 takes about 12 s)."""
    import os
    import signal

    model = unidyn.load("kepler")
    model.simulate(t_end=1.0)  # compiled first
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        model.simulate(t_end=1e5, output_step=1e5)
    timer.join()
    assert time.monotonic() - start < 2.0
