"""Hostile arrays and jobs (issue 34): every one is a molsurf.Error with the command's
message where the command has one, refused before memory is spent, and Ctrl-C stops a
surface() in the middle of its union."""
import os
import subprocess
import sys
import textwrap
import threading
import time
import _thread

import numpy as np
import pytest

import molsurf

CENTRES = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0]])
RADII = np.array([1.5, 1.5])


@pytest.mark.parametrize("function", [molsurf.areas, molsurf.surface], ids=["areas", "surface"])
@pytest.mark.parametrize(
    "centres, radii",
    [
        (CENTRES.astype(bool), RADII),
        (CENTRES.astype(complex) + 1j, RADII),
        (CENTRES.astype(str), RADII),
        (CENTRES.astype(object), RADII),
        (CENTRES, RADII.astype(complex)),
        (CENTRES, np.array([True, True])),
        (CENTRES, np.array(["1.5", "1.5"])),
    ],
    ids=["bool", "complex", "str", "object", "complex radii", "bool radii", "str radii"],
)
def test_non_numeric_arrays_are_refused_not_converted(function, centres, radii):
    with pytest.raises(molsurf.Error, match=r"(centres|radii): not convertible to a numeric array"):
        function(centres=centres, radii=radii)


@pytest.mark.parametrize("function", [molsurf.areas, molsurf.surface], ids=["areas", "surface"])
def test_masked_entries_are_refused(function):
    masked = np.ma.masked_invalid([[0.0, 0.0, np.nan], [3.0, 0.0, 0.0]])
    with pytest.raises(molsurf.Error, match="centres: the array has masked entries"):
        function(centres=masked, radii=RADII)
    # A masked array with nothing masked is its data.
    assert function(centres=np.ma.masked_array(CENTRES), radii=RADII, probe=0).area == pytest.approx(
        function(centres=CENTRES, radii=RADII, probe=0).area)


def test_float_face_indices_and_wide_tags_are_refused():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert molsurf.check(vertices, faces).valid
    # As a file's reader refuses '0.7' where an index belongs: the entry named, in its words.
    with pytest.raises(molsurf.Error, match=r"^faces\[0, 0\]: expected an integer, found '0.7'$"):
        molsurf.check(vertices, faces + 0.7)
    with pytest.raises(molsurf.Error, match=r"^faces\[0, 0\]: expected an integer, found '0.0'$"):
        molsurf.check(vertices, faces.astype(float))  # whole, but floats: no index
    with pytest.raises(molsurf.Error, match=r"faces: .* bool"):
        molsurf.check(vertices, faces.astype(bool))
    with pytest.raises(molsurf.Error, match=r"tags: tags\[2\] is 4294967296, beyond 32 bits"):
        molsurf.Mesh(vertices, faces, tags=[0, 1, 2**32, 3])
    mesh = molsurf.Mesh(vertices, faces, tags=[0, 1, -1, 2**31 - 1])
    assert list(mesh.tags) == [0, 1, -1, 2**31 - 1]


def test_a_tiny_radius_gets_the_commands_message(cli, tmp_path):
    tiny = tmp_path / "tiny.xyzr"
    tiny.write_text("0 0 0 1e-310\n")
    run = subprocess.run([str(cli), tiny, "--probe", "0", "-o", tmp_path / "t.vtp"], capture_output=True, text=True)
    assert run.returncode == 1
    expected = "has radius 1e-310: its sphere (radius + probe) is below 1e-06 A, too small to triangulate"
    assert expected in run.stderr
    with pytest.raises(molsurf.Error, match=r"atoms: atom 1 \(serial 1\) has radius 1e-310: its sphere"):
        molsurf.surface(centres=[[0, 0, 0]], radii=[1e-310], probe=0)


def test_ten_million_atoms_are_refused_before_any_atom_is_built():
    n = 10**7
    with pytest.raises(molsurf.Error, match=r"atoms: the spheres would have .* faces before the union"):
        molsurf.surface(centres=np.zeros((n, 3)), radii=np.full(n, 1.5))


def test_more_threads_than_the_process_can_start_are_capped_with_a_warning(tmp_path):
    script = textwrap.dedent("""
        import resource, warnings
        resource.setrlimit(resource.RLIMIT_AS, (4_000_000_000, resource.RLIM_INFINITY))
        import molsurf
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            s = molsurf.surface(centres=[[0, 0, 0], [2, 0, 0]], radii=[1.5, 1.5], threads=1024)
        print(s.threads, [str(w.message) for w in caught])
    """)
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
    assert run.returncode == 0, run.stderr
    assert "libgomp" not in run.stderr
    threads = int(run.stdout.split()[0])
    assert 1 <= threads < 1024
    assert "threads: 1024 threads asked for, but this process can start only" in run.stdout
    assert f"using {threads}, half of them" in run.stdout


def test_ctrl_c_stops_surface_inside_the_union():
    # 60 000 atoms in a box at density 6: the union alone takes minutes on two cores. The
    # interrupt comes after a second; with signals looked at only between stages, the call
    # would end with the union, minutes later. The bound below is not a speed figure: it
    # only tells "inside the union" from "after it".
    rng = np.random.default_rng(34)
    n = 60_000
    centres = rng.random((n, 3)) * 80
    timer = threading.Timer(1.0, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            molsurf.surface(centres=centres, radii=np.full(n, 1.7), density=6)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 20
    # The module is usable afterwards.
    assert molsurf.surface(centres=CENTRES, radii=RADII).area > 0
