"""The module under test is the build tree's (PYTHONPATH=build/python, set by ctest); the command
`unidyn` of the same build is $UNIDYN_EXECUTABLE, for comparisons with what it prints."""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def command():
    """Runs `unidyn ARGS...`; returns its standard output (a non-zero exit fails the test)."""
    executable = os.environ.get("UNIDYN_EXECUTABLE")
    if not executable:
        pytest.skip("UNIDYN_EXECUTABLE is not set (ctest sets it)")

    def run(*args):
        done = subprocess.run([executable, *args], capture_output=True, text=True, check=False)
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run
