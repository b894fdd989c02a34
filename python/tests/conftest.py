"""Shared fixtures: where the data, the molsurf command and the examples are.

ctest sets MOLSURF_SOURCE_DIR, MOLSURF_CLI and PYTHONPATH (the build's python/ folder);
run by hand, the source tree is found from this file and the command from build/release.
"""
import os
import pathlib

import pytest

import molsurf

SOURCE_DIR = pathlib.Path(os.environ.get("MOLSURF_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA = SOURCE_DIR / "data" / "pdb"


@pytest.fixture(scope="session")
def data_dir():
    return DATA


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def cli():
    path = pathlib.Path(os.environ.get("MOLSURF_CLI", SOURCE_DIR / "build" / "release" / "molsurf"))
    if not path.exists():
        pytest.skip(f"molsurf command not built: {path}")
    return path


@pytest.fixture(scope="session")
def crambin():
    """1crn's surface with the command line's defaults, computed once for the session."""
    return molsurf.surface(DATA / "1crn.pdb")
