"""Shared fixtures of the Python module's tests: the `mobb` executable they compare with, and the real
mocap data (skipped when absent, a failure when MOBB_REQUIRE_DATA=1), as the C++ tests do."""
import os
import subprocess

import pytest

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def _data_dir():
    for d in (os.environ.get("MOBB_DATA"), os.path.join(SOURCE_DIR, "..", "shared", "mocap")):
        if d and os.path.isfile(os.path.join(d, "cmu", "007_01.bvh")):
            return os.path.abspath(d)
    return None


@pytest.fixture(scope="session")
def data():
    """The mocap folder (its cmu/, gltf/ subfolders)."""
    d = _data_dir()
    if d is None:
        if os.environ.get("MOBB_REQUIRE_DATA") == "1":
            pytest.fail("MOBB_REQUIRE_DATA=1 but no mocap folder found")
        pytest.skip("mocap data not found: set MOBB_DATA or put it in ../shared/mocap")
    return d


@pytest.fixture(scope="session")
def mobb_exe():
    """The `mobb` command line of the same build (MOBB_EXE, set by ctest)."""
    exe = os.environ.get("MOBB_EXE")
    if not exe or not os.path.isfile(exe):
        pytest.skip("MOBB_EXE not set: run through ctest")
    return exe


def run_cli(exe, *args, stdin=None):
    """Runs `mobb ARGS`: (exit code, stdout, stderr)."""
    p = subprocess.run([exe, *args], input=stdin, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def cli_error(exe, *args):
    """The message `mobb ARGS` prints after "error: " (it must fail with exit code 1)."""
    code, out, err = run_cli(exe, *args)
    assert code == 1, (code, err)
    assert out == ""
    line = err.strip().splitlines()[-1]
    assert line.startswith("error: "), err
    return line[len("error: "):]
