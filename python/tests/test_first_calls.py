"""Several Python threads whose very first molsurf calls run at once (a thread pool sweeping
structures, as Dask's threaded scheduler does): each gets its result, and none waits forever.
Run in a fresh interpreter, since only the first calls after import can meet this."""
import os
import subprocess
import sys

import pytest

import molsurf

SCRIPT = """
import sys, threading
import molsurf
call, paths = sys.argv[1], sys.argv[2:]
results = [None] * len(paths)
def run(i):
    results[i] = getattr(molsurf, call)(paths[i], threads=1).area
workers = [threading.Thread(target=run, args=(i,)) for i in range(len(paths))]
for w in workers:
    w.start()
for w in workers:
    w.join()
print(" ".join(repr(r) for r in results))
"""


@pytest.mark.parametrize("call", ["areas", "surface"])
def test_first_calls_from_three_threads_at_once(data_dir, tmp_path, call):
    paths = [data_dir / "1crn.pdb", data_dir / "1ubq.pdb", data_dir / "1crn.pdb"]
    env = {**os.environ, "PYTHONPATH": os.path.dirname(os.path.abspath(molsurf.__file__))}
    run = subprocess.run([sys.executable, "-c", SCRIPT, call, *map(str, paths)], capture_output=True, text=True,
                         env=env, timeout=240, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    areas = [float(a) for a in run.stdout.split()]
    expected = [getattr(molsurf, call)(p, threads=1).area for p in paths]
    assert areas == expected
