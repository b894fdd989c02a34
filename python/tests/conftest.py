"""Shared fixtures: where the data, the molsurf command and the examples are.

ctest sets MOLSURF_SOURCE_DIR, MOLSURF_CLI and PYTHONPATH (the build's python/ folder);
run by hand, the source tree is found from this file and the command from build/release.
"""
import os
import pathlib
import threading
import time

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


@pytest.fixture(scope="session")
def ticks_during():
    """Runs a call while another Python thread counts millisecond ticks; returns (its result,
    the ticks). With the GIL held for the whole call the counter could not advance."""

    def run(call):
        ticks = 0
        done = threading.Event()

        def count():
            nonlocal ticks
            while not done.is_set():
                ticks += 1
                time.sleep(0.001)

        counter = threading.Thread(target=count)
        counter.start()
        start_ticks = ticks
        try:
            result = call()
        finally:
            done.set()
            counter.join()
        return result, ticks - start_ticks

    return run


@pytest.fixture(scope="session")
def in_two_threads():
    """The call's results from two Python threads running it at once."""

    def run(call):
        results = [None, None]

        def work(i):
            results[i] = call()

        workers = [threading.Thread(target=work, args=(i,)) for i in range(2)]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        return results

    return run
