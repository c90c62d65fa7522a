"""Models built in Python: unidyn.load(dict) with the YAML's keys and model.to_yaml(), and
model.with_parameters(...) — against the double pendulum's equations derived by hand
(test_model.py) and the commands' own reading of the same model as text."""

import math
import pickle

import numpy as np
import pytest
import yaml

import unidyn
from test_model import DOUBLE_PENDULUM, double_pendulum_accelerations

# the double pendulum of test_model.py, as a dict built in code
PENDULUM = {
    "unidyn": 1,
    "name": "two rods",
    "parameters": {"m1": 1.0, "m2": 1.0, "l1": 1.5, "l2": 0.7, "g": 9.81},
    "coordinates": ["theta1", "theta2"],
    "particles": {
        "P1": {"mass": "m1", "position": "l1*[sin(theta1), -cos(theta1), 0]"},
        "P2": {"mass": "m2", "position": "P1.position + l2*[sin(theta2), -cos(theta2), 0]"},
    },
    "forces": [{"gravity": "-g*E2"}],
    "initial": {"theta1": 1.0, "theta2": 2.0},
}


def states(count=20):
    rng = np.random.default_rng(11)
    return rng.uniform(-3, 3, (count, 2)), rng.uniform(-2, 2, (count, 2))


def test_a_model_from_a_dict():
    model = unidyn.load(PENDULUM)
    assert model.coordinates == ["theta1", "theta2"] and model.parameters["l1"] == 1.5
    q, qd = states()
    qdd, _ = model.rhs(q, qd)
    for k in range(len(q)):
        expected = double_pendulum_accelerations(*q[k], *qd[k], **PENDULUM["parameters"])
        assert np.allclose(qdd[k], expected, rtol=1e-12, atol=1e-12)
    # its YAML, read again, and the same model written as a text, derive the same equations
    assert yaml.safe_load(model.to_yaml()) == PENDULUM
    assert unidyn.load(model.to_yaml()).derive() == model.derive()
    assert unidyn.load(DOUBLE_PENDULUM).derive() == model.derive()


def test_a_mistake_in_a_dict_is_named_by_its_line_in_the_yaml():
    broken = {**PENDULUM, "forces": [{"gravity": "-g*E2 +"}]}
    text = yaml.safe_dump(broken, sort_keys=False, default_flow_style=None)
    line = next(k for k, row in enumerate(text.splitlines(), 1) if "-g*E2 +" in row)
    with pytest.raises(unidyn.ModelError) as error:
        unidyn.load(broken)
    assert error.value.line == line


def test_parameters_by_name_without_reading_again():
    base = unidyn.load(PENDULUM)
    heavy = base.with_parameters(m2=3.0, l2=0.5)
    assert heavy._model is base._model  # the same compiled model: nothing read again
    assert heavy.parameters["m2"] == 3.0 and base.parameters["m2"] == 1.0
    q, qd = states()
    qdd, _ = heavy.rhs(q, qd)
    p = {**PENDULUM["parameters"], "m2": 3.0, "l2": 0.5}
    for k in range(len(q)):
        assert np.allclose(qdd[k], double_pendulum_accelerations(*q[k], *qd[k], **p),
                           rtol=1e-12, atol=1e-12)
    # a call's own `set` still overrides; runs see them as the command's --set does
    again, _ = heavy.rhs(q, qd, set={"m2": 1.0})
    assert np.array_equal(again[:, 0], base.rhs(q, qd, set={"l2": 0.5})[0][:, 0])
    run = heavy.simulate(t_end=0.5)
    assert np.array_equal(run.data, base.simulate(t_end=0.5, set={"m2": 3.0, "l2": 0.5}).data)
    with pytest.raises(ValueError, match="no parameter mass"):
        base.with_parameters(mass=2)
    # to another process with them; a sweep of it runs with them
    moved = pickle.loads(pickle.dumps(heavy))
    assert moved.parameters == heavy.parameters
    swept = unidyn.sweep(heavy, [{"theta1": 0.5}, {"theta1": 0.7}], t_end=0.5)
    direct = unidyn.sweep(base, [{"theta1": 0.5, "m2": 3.0, "l2": 0.5},
                                 {"theta1": 0.7, "m2": 3.0, "l2": 0.5}], t_end=0.5)
    assert np.array_equal(swept.final, direct.final)
    assert math.isfinite(swept.final[0, 1])
