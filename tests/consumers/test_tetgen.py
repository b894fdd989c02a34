"""tetgen 1.5 (Debian tetgen) reads our .off and ASCII .ply, and its own exact
self-intersection test (-d) finds none. (Binary PLY makes tetgen 1.5 abort: give it
--ascii, docs/formats.md.)"""
import shutil
import subprocess

import pytest

tetgen = shutil.which("tetgen")
pytestmark = pytest.mark.skipif(tetgen is None, reason="tetgen is not installed (Debian: tetgen)")


def detect_intersections(path):
    result = subprocess.run([tetgen, "-d", str(path)], capture_output=True, text=True, timeout=1200)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    return result.stdout


@pytest.mark.parametrize("name,options", [("s.off", []), ("s.ply", ["--ascii"])], ids=["off", "ascii-ply"])
def test_tetgen_finds_no_intersection(run_molsurf, data_dir, name, options):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", name, *options)
    output = detect_intersections(run.output)
    assert "No faces are intersecting." in output, output[-2000:]


@pytest.mark.long
@pytest.mark.parametrize("name,options", [("s.off", []), ("s.ply", ["--ascii"])], ids=["off", "ascii-ply"])
def test_tetgen_finds_no_intersection_on_haemoglobin(run_molsurf, data_dir, name, options):
    run = run_molsurf(data_dir / "pdb" / "2hhb.pdb", name, *options)
    output = detect_intersections(run.output)
    assert "No faces are intersecting." in output, output[-2000:]
