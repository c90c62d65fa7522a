"""The notebooks of examples/notebooks run, cell by cell, in a Jupyter kernel (nbclient and
ipykernel, Debian's python3-nbclient and python3-ipykernel), in a scratch directory: a cell that
raises fails the test. They are kept without outputs, so that the repository holds what a user
runs, not a past run's pictures."""

import pathlib

import pytest

NOTEBOOKS = sorted((pathlib.Path(__file__).parents[2] / "examples" / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_the_notebook_runs(path, tmp_path, monkeypatch):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    notebook = nbformat.read(path, as_version=4)
    for cell in notebook.cells:
        if cell.cell_type == "code":
            assert not cell.outputs and cell.execution_count is None, "kept with outputs"
    # the kernel, a process of this environment, imports the module under test (PYTHONPATH as
    # ctest sets it); its plots are images in the cells' outputs (the inline backend)
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # (ipykernel's debugger notes)
    client = nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    shown = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.outputs]
    kinds = {kind for output in shown for kind in output.get("data", {})}
    # the equations as LaTeX, the model and the report as HTML, the plots as images
    assert {"text/latex", "text/html", "image/png"} <= kinds
    assert list(tmp_path.iterdir()) == [], "a notebook left a file behind"
