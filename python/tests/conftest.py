import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("COVSIM_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
COVSIM = os.environ.get("COVSIM_PROGRAM", str(SOURCE / "build" / "apps" / "covsim"))


@pytest.fixture
def scenarios():
    return SOURCE / "scenarios"


@pytest.fixture
def cli():
    """Runs the covsim program; returns its stdout."""
    def run(*args):
        return subprocess.run([COVSIM, *map(str, args)], check=True, capture_output=True,
                              text=True).stdout
    return run
