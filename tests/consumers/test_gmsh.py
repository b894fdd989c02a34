"""gmsh 4.8 (Debian gmsh) fills the space between a box and our .msh with tetrahedra: each
closed component of the surface is its own discrete surface (elementary and physical tag:
1 the outer surface, then the cavities), so a .geo can use the outer surface alone as the
hole of the solvent region. The failures this guards against: with one surface per atom,
gmsh's boundary recovery stopped on an assertion (2hhb), and with the cavity in the hole's
loop the region came out empty (1crn, "No elements in volume 1")."""
import json
import shutil
import subprocess

import numpy as np
import pytest

gmsh = shutil.which("gmsh")
pytestmark = pytest.mark.skipif(gmsh is None, reason="gmsh is not installed (Debian: gmsh)")

meshio = pytest.importorskip("meshio", reason="meshio is not installed (Debian: python3-meshio)")


def box_around(surface, points, margin, size):
    low, high = points.min(axis=0) - margin, points.max(axis=0) + margin
    corners = [(low[0] if i & 1 == 0 else high[0], low[1] if i & 2 == 0 else high[1],
                low[2] if i & 4 == 0 else high[2]) for i in range(8)]
    lines = [f'Merge "{surface.name}";', "CreateTopology;"]
    lines += [f"Point({100001 + i}) = {{{x!r}, {y!r}, {z!r}, {size}}};" for i, (x, y, z) in enumerate(corners)]
    edges = [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5), (2, 6), (3, 7)]
    lines += [f"Line({100001 + k}) = {{{100001 + a}, {100001 + b}}};" for k, (a, b) in enumerate(edges)]
    # The six sides as loops of the edges above (signed: against an edge's direction).
    sides = [(1, 6, -2, -5), (3, 8, -4, -7), (1, 10, -3, -9), (2, 12, -4, -11), (5, 11, -7, -9), (6, 12, -8, -10)]
    for k, side in enumerate(sides):
        loop = ", ".join(str((100000 + abs(e)) * (1 if e > 0 else -1)) for e in side)
        lines += [f"Curve Loop({100001 + k}) = {{{loop}}};", f"Plane Surface({100001 + k}) = {{{100001 + k}}};"]
    lines += ["Surface Loop(100001) = {100001:100006};", "Surface Loop(100002) = {1};",
              "Volume(1) = {100001, 100002};", 'Physical Volume("solvent") = {1};']
    geo = surface.with_suffix(".geo")
    geo.write_text("\n".join(lines) + "\n")
    return geo


def mesh_solvent(run, size):
    surface = run.output
    mesh = meshio.read(surface)
    geo = box_around(surface, np.asarray(mesh.points, float), 8.0, size)
    out = surface.with_name("solvent.msh")
    result = subprocess.run([gmsh, str(geo), "-3", "-format", "msh22", "-o", str(out)], capture_output=True,
                            text=True, timeout=1800, cwd=surface.parent)
    log = result.stdout[-3000:] + result.stderr[-3000:]
    assert result.returncode == 0, log
    assert "Error" not in result.stdout, log
    tets = sum(len(block.data) for block in meshio.read(out).cells if block.type == "tetra")
    assert tets > 1000, log
    return tets


def test_gmsh_fills_a_box_around_crambin_which_has_a_cavity(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "c.msh")
    assert len(run.report["components"]) > 1  # the cavity must not end up in the hole's loop
    mesh_solvent(run, 3)


@pytest.mark.long
def test_gmsh_fills_a_box_around_haemoglobin(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "2hhb.pdb", "h.msh")
    mesh_solvent(run, 6)


def test_gmsh_and_meshio_load_the_volume_mesh(molsurf_cli, data_dir, tmp_path):
    """`--volume-mesh`: gmsh reads the file back, and meshio sees the tetrahedra of each region
    and the triangles of each boundary under the physical tags docs/volume_mesh.md gives."""
    volume = tmp_path / "v.msh"
    result = subprocess.run([molsurf_cli, str(data_dir / "pdb" / "1crn.pdb"), "-q", "-o", str(tmp_path / "s.vtp"),
                             "--volume-mesh", str(volume), "--box-margin", "6", "--json", str(tmp_path / "r.json")],
                            capture_output=True, text=True, timeout=600)
    if "built without gmsh" in result.stderr:
        pytest.skip("this molsurf was built without gmsh")
    assert result.returncode == 0, result.stderr
    check = subprocess.run([gmsh, str(volume), "-0", "-o", str(tmp_path / "again.msh")], capture_output=True,
                           text=True, timeout=600)
    assert check.returncode == 0 and "Error" not in check.stdout, check.stdout[-2000:]
    mesh = meshio.read(volume)
    names = {name: int(tag) for name, (tag, dim) in mesh.field_data.items()}
    assert {"solvent", "outer", "box"} <= set(names)
    tets = [data for block, data in zip(mesh.cells, mesh.cell_data["gmsh:physical"]) if block.type == "tetra"]
    assert len(tets) > 0 and all((t == names["solvent"]).all() for t in tets)
    points = np.asarray(mesh.points, float)
    corners = np.concatenate([block.data for block in mesh.cells if block.type == "tetra"])
    a, b, c, d = (points[corners[:, k]] for k in range(4))
    volume_sum = np.abs(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))).sum() / 6
    low, high = points.min(axis=0), points.max(axis=0)
    # The solvent is the box minus what the outer surface encloses (the cavities included).
    outer = [c for c in json.loads((tmp_path / "r.json").read_text())["components"] if c["kind"] == "outer"]
    expected = np.prod(high - low) - sum(c["volume"] for c in outer)
    assert volume_sum == pytest.approx(expected, rel=1e-9)


@pytest.mark.long
def test_volume_mesh_where_the_cleanup_could_fold_faces(molsurf_cli, data_dir, tmp_path):
    """7cth: gmsh stopped on "overlapping facets" where the cleanup had folded two faces on an
    edge within 0.1 degree of each other (docs/volume_mesh.md, "Folds")."""
    volume = tmp_path / "v.msh"
    result = subprocess.run([molsurf_cli, str(data_dir / "pdb" / "7cth.cif"), "-q", "-o", str(tmp_path / "s.vtp"),
                             "--volume-mesh", str(volume)], capture_output=True, text=True, timeout=1800)
    if "built without gmsh" in result.stderr:
        pytest.skip("this molsurf was built without gmsh")
    assert result.returncode == 0, result.stderr
    mesh = meshio.read(volume)
    assert sum(len(block.data) for block in mesh.cells if block.type == "tetra") > 1_000_000
