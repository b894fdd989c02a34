"""meshio 7 (Debian python3-meshio) reads every format of ours it supports, and finds
what our report says: the same points, triangles and area, and in ASCII PLY and gmsh
files the atom of each face. FEniCS and bempp-cl read surfaces through meshio, so this
is their door too. meshio cannot read .vtp or POLYDATA .vtk (its limit, docs/formats.md),
nor binary PLY with a face property: its binary reader takes face properties as whole
columns, so our per-face tag needs --ascii."""
import warnings

import numpy as np
import pytest

meshio = pytest.importorskip("meshio", reason="meshio is not installed (Debian: python3-meshio)")


def triangles(mesh):
    """The triangles, whatever other cells (points, lines) a format adds."""
    blocks = [block.data for block in mesh.cells if block.type == "triangle"]
    assert blocks, f"no triangles among {[b.type for b in mesh.cells]}"
    return np.concatenate(blocks)


def area(points, faces):
    corners = points[faces]
    return np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1) / 2


def read(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # numpy deprecation notes inside meshio
        return meshio.read(path)


# (output name, options, coordinates exact, vertices shared as ours)
FORMATS = [
    ("s.ply", ["--ascii"], True, True),
    ("s.off", [], True, True),
    ("s.obj", [], True, True),
    ("s.msh", [], True, True),
    ("s.stl", [], False, False),
    ("s.stl", ["--ascii"], False, False),
]


@pytest.mark.parametrize("name,options,exact,shared", FORMATS,
                         ids=[n + ("-ascii" if o else "") for n, o, _, _ in FORMATS])
def test_meshio_reads_what_the_report_says(run_molsurf, data_dir, name, options, exact, shared):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", name, *options)
    mesh = read(run.output)
    faces = triangles(mesh)
    assert len(faces) == run.report["faces"]
    if shared:
        assert len(mesh.points) == run.report["vertices"]
    face_area = area(np.asarray(mesh.points, dtype=float), faces)
    # Exact formats give back our doubles; STL's float32 moves the area by ~1e-7 relative.
    assert face_area.sum() == pytest.approx(run.report["area"], rel=1e-12 if exact else 1e-5)
    assert face_area.min() > 0


@pytest.mark.parametrize("name,options,key", [("t.ply", ["--ascii"], "tag"), ("t.msh", [], "atom")])
def test_meshio_gets_the_atom_of_each_face(run_molsurf, data_dir, name, options, key):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", name, *options)
    mesh = read(run.output)
    faces = triangles(mesh)
    assert key in mesh.cell_data, f"{key} not among {list(mesh.cell_data)}"
    tags = np.concatenate([data for block, data in zip(mesh.cells, mesh.cell_data[key])
                           if block.type == "triangle"]).astype(int)
    assert len(tags) == len(faces)
    if key == "atom":
        tags = tags - 1  # gmsh's $ElementData "atom" counts from 1
    # The area of the faces of each atom is that atom's area in --per-atom.
    per_atom = np.bincount(tags, weights=area(np.asarray(mesh.points, float), faces),
                           minlength=len(run.atom_area))
    assert per_atom == pytest.approx(np.array(run.atom_area), abs=6e-5)


def test_meshio_gets_one_gmsh_physical_group_per_component(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "c.msh")
    mesh = read(run.output)
    physical = np.concatenate([data for block, data in zip(mesh.cells, mesh.cell_data["gmsh:physical"])
                               if block.type == "triangle"]).astype(int)
    components = run.report["components"]
    assert sorted(set(physical)) == list(range(1, len(components) + 1))
    # Named as in the report: the outer surface first, then the cavities by decreasing area.
    names = {int(tag): name for name, (tag, dim) in mesh.field_data.items() if dim == 2}
    assert names[1] == "outer"
    assert [names[k] for k in range(2, len(components) + 1)] == [f"cavity-{k}" for k in range(1, len(components))]
    points = np.asarray(mesh.points, float)
    for k, component in enumerate(components, start=1):
        assert area(points, triangles(mesh)[physical == k]).sum() == pytest.approx(component["area"], rel=1e-9)
