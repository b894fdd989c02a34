"""Meshes made in NumPy: checked, joined by the exact Boolean engine, written and read back."""
import numpy as np
import pytest

import molsurf


def box(lo, hi):
    """An axis-aligned box as (vertices, faces), faces counter-clockwise seen from outside."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    vertices = np.array([[x, y, z] for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)], dtype=float)
    faces = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                      [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return vertices, faces


def test_a_numpy_box_is_a_valid_closed_surface():
    v, f = box((0, 0, 0), (1, 2, 3))
    check = molsurf.check(v, f)
    assert check.valid and check.closed and check.manifold and check.oriented and not check.empty
    assert check.volume == pytest.approx(6.0)
    assert check.area == pytest.approx(22.0)
    assert check.to_dict()["defects"] == []
    assert molsurf.Mesh(v, f).volume == pytest.approx(6.0)


def test_defects_are_reported():
    v, f = box((0, 0, 0), (1, 1, 1))
    open_box = molsurf.check(v, f[:-1])
    assert not open_box.valid and open_box.boundary_edges == 3
    assert any("boundary" in d for d in open_box.defects)
    inside_out = molsurf.check(v, f[:, ::-1])
    assert not inside_out.valid and inside_out.inward_components == 1


@pytest.mark.parametrize("op", ["union", "intersection", "difference"])
def test_boolean_of_numpy_boxes_round_trips_through_check(op):
    a = box((0, 0, 0), (1, 1, 1))
    b = box((0.5, 0.25, 0.25), (1.5, 0.75, 1.25))  # volume 0.5; 0.5 x 0.5 x 0.75 inside a
    overlap = 0.5 * 0.5 * 0.75
    expected = {"union": 1 + 0.5 - overlap, "intersection": overlap, "difference": 1 - overlap}
    result = molsurf.boolean(op, a, b)
    assert isinstance(result, molsurf.Mesh)
    check = molsurf.check(result.vertices, result.faces)
    assert check.valid and not check.empty
    assert check.volume == pytest.approx(expected[op], rel=1e-12)
    # The result is a valid operand again: feed it back in.
    again = molsurf.boolean("union", result, box((2, 0, 0), (3, 1, 1)))
    assert molsurf.check(again).valid
    assert again.volume == pytest.approx(expected[op] + 1, rel=1e-12)


def test_boolean_of_boxes_touching_at_an_edge_moves_b_and_warns():
    # The exact union holds two sheets touching along the edge: no rounding of it is valid,
    # so b is moved by about 1e-10 and a warning says so; the result is valid.
    a = box((0, 0, 0), (1, 1, 1))
    b = box((1, 1, 0), (2, 2, 1))
    with pytest.warns(UserWarning, match="moved by"):
        result = molsurf.boolean("union", a, b)
    check = molsurf.check(result)
    assert check.valid and check.contact_pairs == 0
    assert check.volume == pytest.approx(2.0, rel=1e-9)
    # Overlapping boxes: nothing to move, no warning.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert molsurf.check(molsurf.boolean("union", a, box((0.5, 0.5, 0), (2, 2, 1)))).valid


def test_boolean_refuses_an_open_operand():
    v, f = box((0, 0, 0), (1, 1, 1))
    with pytest.raises(molsurf.Error, match="a: not a valid closed surface"):
        molsurf.boolean("union", (v, f[:-1]), (v + 0.5, f))
    with pytest.raises(molsurf.Error, match="op"):
        molsurf.boolean("xor", (v, f), (v + 0.5, f))


def test_mesh_write_and_read_back(tmp_path):
    v, f = box((0, 0, 0), (1, 1, 1))
    tags = np.arange(12, dtype=np.int32)
    mesh = molsurf.Mesh(v, f, tags)
    for name in ("m.vtp", "m.ply", "m.off", "m.obj", "m.msh"):
        mesh.write(tmp_path / name)
        back = molsurf.read_mesh(tmp_path / name)
        assert np.array_equal(back.vertices, mesh.vertices), name
        assert np.array_equal(back.faces, mesh.faces), name
    assert np.array_equal(molsurf.read_mesh(tmp_path / "m.vtp").tags, tags)


def test_surface_mesh_feeds_the_engine(crambin):
    mesh = crambin.mesh
    assert np.array_equal(mesh.tags, crambin.atom_of_face)
    centre = crambin.vertices.mean(axis=0)
    cut = molsurf.boolean("intersection", mesh, box(centre - 5, centre + 5))
    assert molsurf.check(cut).valid
    assert 0 < cut.volume < 1000.0 + 1e-9
