"""Fixtures of the Python module's tests (run by ctest as `python3 -m pytest tests/python`).

The environment names what the build made: PYTHONPATH holds build/python (the built package, never the sources),
SEMSLAM_CLI the command-line tool (to compare against), SEMSLAM_SHARED_DATA the shared datasets (tests that need
them skip, saying so, where they are absent).
"""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("SEMSLAM_CLI")
    if not path or not os.path.exists(path):
        pytest.fail("SEMSLAM_CLI must name the built semslam tool (ctest sets it)")

    def run(*arguments, cwd=None):
        return subprocess.run([path, *map(str, arguments)], check=True, capture_output=True, text=True, cwd=cwd)

    return run


@pytest.fixture(scope="session")
def shared_data():
    return os.environ.get("SEMSLAM_SHARED_DATA", "")


def require_data(shared_data, relative):
    path = os.path.join(shared_data, relative)
    if not os.path.exists(path):
        pytest.skip(f"needs ../shared/data/{relative}, which is absent")
    return path
