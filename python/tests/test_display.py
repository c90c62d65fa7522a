"""What a notebook shows (unidyn/display.py): the MIME methods IPython calls return the expected
content — the equations as the command's LaTeX, a model's table, the modes' table with the closed
form's eigenvalue, a report's own page inline — and each object stays what it was (a str, a dict)."""

import html
import math
import os
import pickle

import pytest

import unidyn


def test_derive_shows_the_commands_latex(command):
    model = unidyn.load("double-pendulum")
    equations = model.derive()
    assert isinstance(equations, str)
    assert equations == command("derive", "double-pendulum")
    latex = command("derive", "double-pendulum", "--format", "latex")
    shown = equations._repr_latex_()
    # the command's LaTeX without its comment lines and labels, the rest as it is
    expected = "\n".join(line for line in latex.splitlines() if not line.startswith("%"))
    assert shown == expected.replace("\\label{eq:theta1}", "").replace("\\label{eq:theta2}", "")
    assert shown.startswith("\\begin{align}") and "\\ddot{\\theta}_{1}" in shown
    assert model.derive(format="latex")._repr_latex_() == shown
    assert not hasattr(model.derive(format="c"), "_repr_latex_")
    # it goes to another process as its text, and still shows there
    again = pickle.loads(pickle.dumps(equations))
    assert again == equations and again._repr_latex_() == shown


def test_a_model_shows_as_a_table():
    shown = unidyn.load("rolling-disk")._repr_html_()
    assert shown.startswith("<strong>") and "<table>" in shown
    model = unidyn.load("rolling-disk")
    for name in model.coordinates + model.constraints:
        assert html.escape(name) in shown
    for name, value in model.parameters.items():
        assert f"{name} = {value:.12g}" in shown


def test_modes_show_the_eigenvalues_and_the_verdict():
    model = unidyn.load("rotating-hoop")
    p = model.parameters
    modes = model.modes(at={"phi": 0})
    assert isinstance(modes, dict)
    shown = modes._repr_html_()
    # λ = ±√(Ω² + g/R0) at the top of the hoop (O'Reilly (3.25))
    growth = math.sqrt(p["Omega"] ** 2 + p["g"] / p["R0"])
    assert f"<td>{growth:.12g}</td>" in shown and f"<td>{-growth:.12g}</td>" in shown
    assert "stability: unstable" in shown
    linear = model.linearize(at={"phi": 0})._repr_html_()
    assert "<th>der(phi)</th>" in linear and f"{p['Omega'] ** 2 + p['g'] / p['R0']:.12g}" in linear


def test_a_report_shows_its_own_page_inline(command, tmp_path):
    model = unidyn.load("rotating-hoop")
    before = set(os.listdir(tmp_path))
    report = model.report(t_end=0.5)
    assert report.startswith("report of Bead on a rotating hoop made (not saved")
    # the page is the command's, byte for byte
    path = tmp_path / "command.html"
    command("report", "rotating-hoop", "--t-end", "0.5", "-o", str(path))
    assert report.page == path.read_text(encoding="utf-8")
    shown = report._repr_html_()
    assert shown.startswith("<iframe") and 'srcdoc="' + html.escape(report.page[:500]) in shown
    assert "<!DOCTYPE" not in shown  # the page is inside the attribute, escaped
    saved = tmp_path / "saved.html"
    report.save(saved)
    assert saved.read_bytes() == path.read_bytes()
    assert set(os.listdir(tmp_path)) == before | {"command.html", "saved.html"}
    # given a path, the page is written there too, as `-o PATH` writes it
    written = model.report(tmp_path / "given.html", t_end=0.5)
    assert "written to" in written and (tmp_path / "given.html").read_bytes() == path.read_bytes()


def test_a_run_plots_its_columns():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    run = unidyn.load("double-pendulum").simulate(t_end=1)
    ax = run.plot(columns=["theta1", "theta2"])
    lines = ax.get_lines()
    assert [line.get_label() for line in lines] == ["theta1", "theta2"]
    assert (lines[1].get_ydata() == run["theta2"]).all() and (lines[0].get_xdata() == run.t).all()
