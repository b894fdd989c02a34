"""meshio 7 (Debian python3-meshio) reads every format of ours it supports, and finds
what our report says: the same points, triangles and area, and in ASCII PLY and gmsh
files the atom of each face. FEniCS and bempp-cl read surfaces through meshio, so this
is their door too. The areas compared are the facets' (the report's facet_area; its area
and --per-atom's area column are the true spheres'). meshio cannot read .vtp or POLYDATA
.vtk (its limit, docs/formats.md), nor binary PLY with a face property: its binary reader
takes face properties as whole columns, so our per-face tag needs --ascii."""
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
    # The facets' area (the report's "area" is the true spheres'). Exact formats give back our
    # doubles; STL's float32 moves the area by ~1e-7 relative.
    assert face_area.sum() == pytest.approx(run.report["facet_area"], rel=1e-12 if exact else 1e-5)
    assert face_area.min() > 0


def ascii_ply_facets(path):
    """Our own reading of one of our ASCII PLY files (not meshio's): the facets' area per atom,
    from each face's vertices and its `tag` property (the atom)."""
    lines = path.read_text().splitlines()
    end = lines.index("end_header")
    counts = {line.split()[1]: int(line.split()[2]) for line in lines[:end] if line.startswith("element ")}
    assert lines[end - 1] == "property int tag", lines[:end]
    vertices = np.array([line.split()[:3] for line in lines[end + 1:end + 1 + counts["vertex"]]], dtype=float)
    rows = np.array([line.split() for line in lines[end + 1 + counts["vertex"]:]], dtype=np.int64)
    assert rows.shape == (counts["face"], 5) and np.all(rows[:, 0] == 3)
    return vertices, rows[:, 1:4], rows[:, 4]


@pytest.fixture(scope="module")
def crambin_facets(run_molsurf, data_dir):
    """1crn's surface, the facets' area per atom: the reference for the per-face atoms meshio
    reads (--per-atom's area column is the true spheres', not the facets')."""
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "reference.ply", "--ascii")
    vertices, faces, tags = ascii_ply_facets(run.output)
    assert len(faces) == run.report["faces"] and len(vertices) == run.report["vertices"]
    per_atom = np.bincount(tags, weights=area(vertices, faces), minlength=len(run.atom_area))
    assert len(per_atom) == len(run.atom_area) == run.report["input"]["atoms"]
    assert per_atom.sum() == pytest.approx(run.report["facet_area"], rel=1e-12)
    # --per-atom's area column (every bit) sums to the true spheres' area, not the facets'.
    assert sum(run.atom_area) == pytest.approx(run.report["area"], rel=1e-12)
    assert run.report["area"] != pytest.approx(run.report["facet_area"], rel=1e-6)
    return run.report, per_atom


@pytest.mark.parametrize("name,options,key", [("t.ply", ["--ascii"], "tag"), ("t.msh", [], "atom")])
def test_meshio_gets_the_atom_of_each_face(run_molsurf, data_dir, crambin_facets, name, options, key):
    report, facet_area_per_atom = crambin_facets
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", name, *options)
    assert run.report["facet_area"] == report["facet_area"]  # the same surface as the reference
    mesh = read(run.output)
    faces = triangles(mesh)
    assert key in mesh.cell_data, f"{key} not among {list(mesh.cell_data)}"
    tags = np.concatenate([data for block, data in zip(mesh.cells, mesh.cell_data[key])
                           if block.type == "triangle"]).astype(int)
    assert len(tags) == len(faces)
    if key == "atom":
        tags = tags - 1  # gmsh's $ElementData "atom" counts from 1
    # The area of the faces meshio gives each atom is that atom's facet area (the same doubles:
    # both files hold exact coordinates).
    per_atom = np.bincount(tags, weights=area(np.asarray(mesh.points, float), faces),
                           minlength=len(facet_area_per_atom))
    assert per_atom == pytest.approx(facet_area_per_atom, abs=1e-9)


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
