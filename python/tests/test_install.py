"""`pip install .` (pyproject.toml, setup.py) into a fresh virtual environment made with
`python3 -m venv --system-site-packages` (numpy from Debian), offline and without build isolation,
from a copy of the sources the package needs and the build tree under test: imported from another
directory, the installed module finds its bundled models and derives what the command derives, and
`python3 -m unidyn` is the command line."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import unidyn

ROOT = pathlib.Path(__file__).parents[2]


def test_pip_install_into_a_virtual_environment(tmp_path, command):
    if shutil.which("cmake") is None:
        pytest.skip("no cmake")
    build = pathlib.Path(unidyn.__file__).resolve().parents[2]  # BUILD/python/unidyn/__init__.py
    source = tmp_path / "source"
    (source / "python").mkdir(parents=True)
    for name in ("pyproject.toml", "setup.py", "README.md"):
        shutil.copy2(ROOT / name, source / name)
    shutil.copytree(ROOT / "models", source / "models")
    shutil.copytree(ROOT / "python" / "unidyn", source / "python" / "unidyn",
                    ignore=shutil.ignore_patterns("__pycache__"))
    environment = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(environment)],
                   check=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "UNIDYN_MODELS")}
    env.update(UNIDYN_BUILD_DIR=str(build), PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    python = str(environment / "bin" / "python")
    done = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-deps",
                           str(source)], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    run = subprocess.run([python, "-c", "import os, unidyn; print(unidyn.__file__); "
                          "print(os.environ['UNIDYN_MODELS']); "
                          "print(unidyn.load('double-pendulum').derive(), end='')"],
                         cwd=elsewhere, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    where, models, text = run.stdout.split("\n", 2)
    # the module and the bundled models it reads are the installed package's
    for path in (where, models):
        assert pathlib.Path(path).resolve().is_relative_to(environment.resolve()), path
    assert text == command("derive", "double-pendulum")
    cli = subprocess.run([python, "-m", "unidyn", "derive", "double-pendulum"], cwd=elsewhere,
                         env=env, capture_output=True, text=True)
    assert cli.returncode == 0 and cli.stdout == text, cli.stderr
