"""Shared helpers of the Python module's tests (registered with ctest in tests/CMakeLists.txt).

The tests compare the module with the command line: LENSLAB_CLI names the `lenslab` binary
of the same build. They run from the source root, so scene paths are the ones a user types.
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(__file__).resolve().parents[2]


@pytest.fixture(autouse=True)
def _in_source_root(monkeypatch):
    monkeypatch.chdir(SOURCE_DIR)


def run_cli(*args, check=True):
    """Runs `lenslab ARGS`; the completed process (stdout and stderr as text)."""
    cli = os.environ.get("LENSLAB_CLI")
    if not cli:
        pytest.skip("LENSLAB_CLI is not set (ctest sets it to the built lenslab)")
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True,
                          cwd=SOURCE_DIR)
    if check and done.returncode != 0:
        raise AssertionError(f"lenslab {' '.join(map(str, args))}: {done.stderr}")
    return done


def cli_json(*args):
    return json.loads(run_cli(*args).stdout)


def cli_error(*args):
    """The message of a failing command, without its "lenslab: error: " prefix."""
    done = run_cli(*args, check=False)
    assert done.returncode != 0
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("lenslab: error: "), done.stderr
    return line[len("lenslab: error: "):]
