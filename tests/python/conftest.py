"""Shared fixtures of the Python API's tests: the dashbed command line to compare with, the
source tree's worlds, and runs both sides share."""

import os
import pathlib
import subprocess

import pytest

import dashbed

ROOT = pathlib.Path(__file__).resolve().parents[2]
ONE_CUBE = ROOT / "tests/python/one_cube.yaml"


def run_cli(*args, cwd=None, expect=0):
    """Runs the dashbed command line (DASHBED_CLI); asserts the exit code; returns what finished."""
    binary = os.environ.get("DASHBED_CLI")
    assert binary, "DASHBED_CLI must name the dashbed binary (ctest sets it)"
    done = subprocess.run([binary, *map(str, args)], cwd=cwd, capture_output=True, text=True)
    assert done.returncode == expect, f"dashbed {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}"
    return done


def cli(*args, cwd=None, expect=0):
    """The command line's standard output (run_cli)."""
    return run_cli(*args, cwd=cwd, expect=expect).stdout


@pytest.fixture(scope="session")
def one_cube_world():
    return dashbed.World.load(str(ONE_CUBE))


@pytest.fixture(scope="session")
def one_cube_plan(one_cube_world):
    result = dashbed.plan(one_cube_world, seed=1)
    assert result.status == "solved", result.reason
    return result.plan
