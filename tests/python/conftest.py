"""Fixtures of the Python module's tests (run by ctest as python.pytest, which
sets PYTHONPATH to the built module and REEB_BINARY to the command line)."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
DATASETS = SOURCE / "datasets"


@pytest.fixture(scope="session")
def reeb():
    """Runs the built `reeb` command; returns its completed process."""
    binary = os.environ.get("REEB_BINARY")
    if not binary:
        pytest.fail("REEB_BINARY is not set: run the tests through ctest (python.pytest)")

    def run(*args, check=True):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, check=check)

    return run


@pytest.fixture(scope="session")
def collection(reeb, tmp_path_factory):
    """The embedded meshes of datasets/ indexed by `reeb index` (one class per mesh pair)."""
    folder = tmp_path_factory.mktemp("collection")
    path = folder / "datasets.h5"
    reeb("index", DATASETS, "-o", path, "--threads", "1")
    return path
