"""molsurf.areas() over a trajectory: coordinates (frames, atoms, 3), radii (atoms,)."""
import numpy as np
import pytest

import molsurf


@pytest.fixture(scope="module")
def trajectory(data_dir):
    """1crn's atoms in five frames: the file's coordinates jiggled (seeded), one frame translated."""
    s = molsurf.read_structure(data_dir / "1crn.pdb")
    rng = np.random.default_rng(31)
    frames = [s.centres + rng.normal(scale=0.25, size=s.centres.shape) for _ in range(4)]
    frames.append(frames[1] + np.array([12.5, -3.25, 7.0]))  # frame 4: frame 1 moved
    return np.ascontiguousarray(frames), s.radii


def test_shapes_and_type(trajectory):
    xyz, radii = trajectory
    t = molsurf.areas(coords=xyz, radii=radii, probe=1.4)
    assert isinstance(t, molsurf.TrajectoryAreas)
    assert len(t) == t.frames == 5 and t.atoms == len(radii)
    assert t.area_per_atom.shape == (5, len(radii)) and t.area_per_atom.dtype == np.float64
    assert t.area.shape == t.volume.shape == (5,) and t.area.dtype == t.volume.dtype == np.float64
    assert np.allclose(t.area_per_atom.sum(axis=1), t.area, rtol=1e-12, atol=0)
    assert np.all(t.area > 0) and np.all(t.volume > 0)
    assert not t.area_per_atom.flags.writeable
    assert t.probe == 1.4 and not t.outer_only


def test_each_frame_equals_single_frame_call(trajectory):
    xyz, radii = trajectory
    for probe, outer_only in [(1.4, False), (0.0, False), (1.4, True)]:
        t = molsurf.areas(coords=xyz, radii=radii, probe=probe, outer_only=outer_only)
        for k in range(len(xyz)):
            one = molsurf.areas(centres=xyz[k], radii=radii, probe=probe, outer_only=outer_only)
            assert isinstance(one, molsurf.Areas)
            assert t.area[k] == one.area and t.volume[k] == one.volume  # the same bits
            assert np.array_equal(t.area_per_atom[k], one.area_per_atom)


def test_coords_names_and_positional(trajectory):
    xyz, radii = trajectory
    by_coords = molsurf.areas(coords=xyz, radii=radii)
    for other in (molsurf.areas(centres=xyz, radii=radii), molsurf.areas(xyz, radii=radii)):
        assert np.array_equal(other.area_per_atom, by_coords.area_per_atom)
        assert np.array_equal(other.volume, by_coords.volume)
    # Two-dimensional coordinates under either name still give one frame's Areas.
    single = molsurf.areas(coords=xyz[2], radii=radii)
    assert isinstance(single, molsurf.Areas) and single.area == by_coords.area[2]
    assert molsurf.areas(xyz[2], radii=radii).area == single.area
    # Other layouts and float32 are converted, as a float64 C-ordered copy would be.
    strided = molsurf.areas(coords=np.asfortranarray(xyz), radii=radii)
    assert np.array_equal(strided.area_per_atom, by_coords.area_per_atom)
    xyz32 = xyz.astype(np.float32)
    assert np.array_equal(molsurf.areas(coords=xyz32, radii=radii).area,
                          molsurf.areas(coords=xyz32.astype(np.float64), radii=radii).area)


def test_thread_count_does_not_change_a_bit(trajectory):
    xyz, radii = trajectory
    one = molsurf.areas(coords=xyz, radii=radii, threads=1)
    two = molsurf.areas(coords=xyz, radii=radii, threads=2)
    assert one.threads == 1 and two.threads == 2
    assert np.array_equal(one.area_per_atom, two.area_per_atom)
    assert np.array_equal(one.area, two.area) and np.array_equal(one.volume, two.volume)
    assert np.array_equal(molsurf.areas(coords=xyz, radii=radii, threads=0).area_per_atom, one.area_per_atom)


def test_translated_frame_same_areas(trajectory):
    xyz, radii = trajectory
    t = molsurf.areas(coords=xyz, radii=radii)
    assert np.allclose(t.area_per_atom[4], t.area_per_atom[1], rtol=0, atol=1e-12 * t.area[1])
    assert abs(t.area[4] - t.area[1]) <= 1e-12 * t.area[1]
    assert abs(t.volume[4] - t.volume[1]) <= 1e-12 * t.volume[1]


def test_two_spheres_closed_form():
    # Two spheres of radius 2 (1.5 + probe 0.5) at distance d: area 2 * 2 pi R (R + d/2).
    d = np.array([1.0, 2.5, 5.0])
    xyz = np.zeros((3, 2, 3))
    xyz[:, 1, 0] = d
    t = molsurf.areas(coords=xyz, radii=np.array([1.5, 1.5]), probe=0.5)
    R = 2.0
    expected = np.where(d < 2 * R, 2 * 2 * np.pi * R * (R + d / 2), 2 * 4 * np.pi * R * R)
    assert np.allclose(t.area, expected, rtol=1e-12)


def test_empty_trajectory():
    t = molsurf.areas(coords=np.zeros((0, 4, 3)), radii=np.ones(4))
    assert t.area_per_atom.shape == (0, 4) and t.area.shape == (0,)


@pytest.mark.parametrize("coords, radii, match", [
    (np.zeros((2, 3, 2)), np.ones(3), "coords: expected an array of shape"),
    (np.zeros((2, 3, 3, 1)), np.ones(3), "coords: expected an array of shape"),
    (np.zeros((2, 3, 3)), np.ones(4), "radii: expected one per atom"),
    (np.zeros((2, 3, 3)), np.ones((2, 3)), "radii: expected one per atom"),
    (np.zeros((2, 3, 3)), np.array([1.0, -0.5, 1.0]), r"radii\[1\]"),
    (np.zeros((2, 3, 3)), np.array([1.0, np.nan, 1.0]), r"radii\[1\]"),
    (np.zeros((2, 3, 3)), np.array([1.0, np.inf, 1.0]), r"radii\[1\]"),
])
def test_bad_input_raises(coords, radii, match):
    with pytest.raises(molsurf.Error, match=match):
        molsurf.areas(coords=coords, radii=radii)


def test_bad_coordinates_name_the_frame():
    xyz = np.zeros((3, 4, 3))
    xyz[2, 1, 0] = np.nan
    with pytest.raises(molsurf.Error, match=r"^coords\[2, 1, 0\]: nan is not a finite number$"):
        molsurf.areas(coords=xyz, radii=np.ones(4))
    xyz[2, 1, 0] = np.inf
    with pytest.raises(molsurf.Error, match=r"^coords\[2, 1, 0\]: inf is not a finite number$"):
        molsurf.areas(xyz, radii=np.ones(4))


def test_bad_arguments_raise():
    xyz, radii = np.zeros((2, 3, 3)), np.ones(3)
    with pytest.raises(molsurf.Error, match="not both"):
        molsurf.areas(coords=xyz, centres=xyz, radii=radii)
    with pytest.raises(molsurf.Error, match="given twice"):
        molsurf.areas(xyz, coords=xyz, radii=radii)
    with pytest.raises(molsurf.Error, match="go together"):
        molsurf.areas(coords=xyz)
    with pytest.raises(molsurf.Error, match="probe"):
        molsurf.areas(coords=xyz, radii=radii, probe=-1)
    with pytest.raises(molsurf.Error, match="threads"):
        molsurf.areas(coords=xyz, radii=radii, threads=-1)
    with pytest.raises(molsurf.Error, match="not convertible"):
        molsurf.areas(coords=np.array([["a", "b", "c"]] * 2, dtype=object).reshape(1, 2, 3), radii=np.ones(2))


def test_gil_released_while_frames_run(trajectory):
    import threading
    xyz, radii = trajectory
    big = np.concatenate([xyz] * 6)
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        t = molsurf.areas(coords=big, radii=radii, threads=1)
    finally:
        stop.set()
        thread.join()
    assert len(t) == 30 and len(ticks) > 3
