import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def curvebench_bin():
    path = os.environ.get("CURVEBENCH_BIN", str(ROOT / "build" / "harness" / "curvebench"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"curvebench executable not found at {path}: build first (bash tests/run.sh)")
    return path


@pytest.fixture
def run(curvebench_bin):
    """Runs curvebench with arguments; a hang fails the test instead of blocking CI."""

    def _run(*args, timeout=60):
        return subprocess.run([curvebench_bin, *map(str, args)], capture_output=True, text=True, timeout=timeout)

    return _run
