"""linearize, modes, equilibria and report from Python: the bead on the rotating hoop (φ from the
top, φ'' = (Ω² cos φ + g/R0) sin φ, O'Reilly (3.25)) against its closed forms."""

import math

import unidyn


def hoop():
    model = unidyn.load("rotating-hoop")
    p = model.parameters
    return model, p["g"], p["R0"], p["Omega"]


def test_modes_at_the_top_of_the_hoop():
    model, g, R0, Omega = hoop()
    modes = model.modes(at={"phi": 0})
    # λ² = Ω² + g/R0 at the top
    growth = math.sqrt(Omega**2 + g / R0)
    values = sorted(m["re"] for m in modes["modes"])
    assert abs(values[-1] - growth) < 1e-9 and abs(values[0] + growth) < 1e-9
    assert modes["stability"] == "unstable"
    A = model.linearize(at={"phi": 0})["A"]
    assert abs(A[1][0] - (Omega**2 + g / R0)) < 1e-9


def test_equilibria_of_the_hoop():
    model, g, R0, Omega = hoop()
    found = model.equilibria(starts=50)
    angles = sorted(round(e["coordinates"]["phi"], 9) for e in found["equilibria"])
    # the top, the bottom, and ±acos(−g/(R0 Ω²)) where the bead rides with the hoop
    side = math.acos(-g / (R0 * Omega**2))
    assert angles == sorted(round(a, 9) for a in (-side, 0.0, side, math.pi))


def test_report_writes_the_page(tmp_path):
    model, *_ = hoop()
    page = tmp_path / "hoop.html"
    said = model.report(page, t_end=0.5)
    assert said.startswith("report of Bead on a rotating hoop written to")
    assert page.read_text().startswith("<!DOCTYPE html>")


def test_a_driven_point_is_a_periodic_motion():
    # Kapitza's pendulum: the inverted position falls at Omega = 158 and stands at 250 (the
    # boundary, 198.2, is checked against the Mathieu equation in tests/analysis/floquet.cpp);
    # the same analysis over a period given for a pivot turned by a crank
    model = unidyn.load("driven-pendulum")
    falls = model.modes(at={"phi": 0}, set={"Omega": 158})
    assert falls["stability"] == "unstable"
    assert abs(falls["period"]["T"] - 2 * math.pi / 158) < 1e-15
    assert max(m["modulus"] for m in falls["multipliers"]) > 1.1
    stands = model.modes(at={"phi": 0}, set={"Omega": 250})
    assert stands["stability"] == "linearly stable"
    assert len(model.linearize(at={"phi": 0})["monodromy"]) == 2
