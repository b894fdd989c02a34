"""MSMS .vert/.face read the way the published readers read them, re-implemented here
from their documented behaviour (docs/formats.md):

- PyGBe (pygbe/util/read_data.py): numpy.loadtxt of each whole file, coordinates from
  the first three columns, faces from the first three, 1-based, with v2 and v3 swapped for
  every surface type but `internal_cavity`; its normal of a face is cross(v1-v0, v0-v2).
  One closed surface per file: --split-components --no-header.
- MaSIF (source/input_output/read_msms.py): the count from the third line, then per row
  the closest atom (field 8) and the atom's name (field 10), split on "_" into chain,
  residue number, insertion code, residue name and atom name.
- TABI-PB's older Fortran reader drops faces under 1e-5 A^2 (and faces whose centroid is
  within 0.0032 A of one of the ten before), which would open holes; TABI-PB's node-patch
  reader takes each vertex's normal as its element's.
"""
import numpy as np
import pytest


def pygbe_read(stem, surface_type):
    vertex = np.loadtxt(f"{stem}.vert", dtype=float)[:, 0:3]
    faces = np.loadtxt(f"{stem}.face", dtype=int)
    triangle = faces[:, :3] if surface_type == "internal_cavity" else faces[:, (0, 2, 1)]
    return vertex, triangle - 1


def pygbe_normals(vertex, triangle):
    l0 = vertex[triangle[:, 1]] - vertex[triangle[:, 0]]
    l2 = vertex[triangle[:, 0]] - vertex[triangle[:, 2]]
    normal = np.cross(l0, l2)
    area = np.linalg.norm(normal, axis=1) / 2
    return normal / (2 * area[:, None]), area


def test_pygbe_reads_one_closed_surface_per_file(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "p.vert", "--split-components", "--no-header")
    components = run.report["components"]
    assert [c["kind"] for c in components] == ["outer"] + ["cavity"] * (len(components) - 1)
    assert len(components) >= 2, "1crn at the default probe has a cavity: the test needs one"
    stems = [run.directory / "p.outer"] + [run.directory / f"p.cavity-{k}" for k in range(1, len(components))]
    for stem, component in zip(stems, components):
        # Cavity files are outward on their own, so they are dielectric interfaces for
        # PyGBe (internal_cavity is for MSMS's cavity files, which face the other way).
        vertex, triangle = pygbe_read(stem, "dielectric_interface")
        assert len(triangle) == component["faces"]
        normal, area = pygbe_normals(vertex, triangle)
        assert area.min() > 0, f"{stem}: a zero-area panel, which PyGBe drops"
        assert area.sum() == pytest.approx(component["area"], rel=2e-3)  # 3 decimals
        # PyGBe's normals point out of the region each surface encloses (as with MSMS's
        # files): the divergence theorem gives that region's volume, positive.
        centroid = vertex[triangle].mean(axis=1)
        volume = np.sum(np.einsum("ij,ij->i", centroid - centroid.mean(axis=0), normal) * area) / 3
        assert volume == pytest.approx(component["volume"], rel=0.05, abs=0.05)
        assert volume > 0



def test_pygbe_reads_the_ses_with_its_patch_columns_and_its_stern_layer(run_molsurf, data_dir, tmp_path):
    stern = tmp_path / "s_stern"
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "s.vert", "--surface", "ses", "--no-header",
                      "--stern", f"{stern}.vert")
    vertex, triangle = pygbe_read(run.directory / "s", "dielectric_interface")
    assert len(triangle) == run.report["faces"]
    rows = np.loadtxt(run.directory / "s.vert")
    faces = np.loadtxt(run.directory / "s.face", dtype=int)
    assert set(np.unique(rows[:, 8]).astype(int)) == {1, 2, 3}  # toroidal, reentrant, contact
    assert set(np.unique(faces[:, 3])) == {1, 2, 3}
    assert np.abs(np.linalg.norm(rows[:, 3:6], axis=1) - 1).max() < 0.003
    # The analytic normals point the way PyGBe's face normals do (out of the solid).
    normal, area = pygbe_normals(vertex, triangle)
    # Compared as directions: the mean of three corners' unit normals is shorter than 1
    # where they spread (a face of the coarse mesh across a crease).
    corner_mean = rows[:, 3:6][triangle].mean(axis=1)
    corner_mean /= np.linalg.norm(corner_mean, axis=1)[:, None]
    assert np.sum(area * np.einsum("ij,ij->i", normal, corner_mean)) > 0.95 * area.sum()
    stern_vertex, stern_triangle = pygbe_read(stern, "dielectric_interface")
    _, stern_area = pygbe_normals(stern_vertex, stern_triangle)
    assert len(stern_triangle) == run.report["stern"]["faces"]
    assert stern_area.sum() == pytest.approx(run.report["stern"]["facet_area"], rel=2e-3)  # 3 decimals

def test_masif_reads_atom_names(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "m.vert")
    lines = (run.directory / "m.vert").read_text().rstrip().split("\n")
    count = int(lines[2].split()[0])
    rows = [line.split() for line in lines[3:]]
    assert count == len(rows) == run.report["vertices"]
    atoms = [line.split(",") for line in (run.directory / "m.vert.atoms.csv").read_text().splitlines()[1:]]
    for fields in rows:
        vertex = [float(x) for x in fields[0:3]]
        normal = [float(x) for x in fields[3:6]]
        assert abs(np.linalg.norm(normal) - 1) < 0.003
        closest = int(fields[7])
        chain, residue_number, insertion, residue_name, atom_name = fields[9].split("_")
        # The name is that of the closest atom (CSV: index,serial,chain,res,resnum,ins,atom,...).
        _, _, csv_chain, csv_residue, csv_number, csv_insertion, csv_atom = atoms[closest - 1][:7]
        assert (chain, residue_name, int(residue_number), atom_name) == (csv_chain, csv_residue, int(csv_number), csv_atom)
        assert insertion == ("x" if csv_insertion == "_" else csv_insertion)
        assert int(fields[8]) == 3  # contact face
        assert len(vertex) == 3


def tabi_fortran_dropped_faces(stem):
    vertex = np.loadtxt(f"{stem}.vert", skiprows=3, usecols=(0, 1, 2))
    face = np.loadtxt(f"{stem}.face", skiprows=3, usecols=(0, 1, 2), dtype=int) - 1
    corners = vertex[face]
    area = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1) / 2
    centroid = corners.mean(axis=1)
    close = np.zeros(len(face), dtype=bool)
    for back in range(1, 11):
        d = np.sum((centroid[back:] - centroid[:-back]) ** 2, axis=1)
        close[back:] |= d < 1e-5
    return int(np.sum((area < 1e-5) | close))


def test_tabi_pb_drops_no_face_of_crambin(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "1crn.pdb", "t.vert")
    assert tabi_fortran_dropped_faces(run.directory / "t") == 0


@pytest.mark.long
def test_tabi_pb_drops_no_face_of_haemoglobin(run_molsurf, data_dir):
    run = run_molsurf(data_dir / "pdb" / "2hhb.pdb", "t.vert")
    assert tabi_fortran_dropped_faces(run.directory / "t") == 0
