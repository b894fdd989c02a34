"""The solvent-excluded surface from Python: surface(..., surface='ses')."""
import csv
import math
import subprocess

import numpy as np
import pytest

import molsurf


def test_one_atom_ses_is_its_van_der_waals_sphere():
    s = molsurf.surface(centres=np.array([[0.0, 0.0, 0.0]]), radii=np.array([1.7]), surface="ses")
    assert s.check.valid
    assert abs(s.area - 4 * math.pi * 1.7**2) / (4 * math.pi * 1.7**2) < 0.005
    # area is the patches' (exact: the sphere's), facet_area the mesh's.
    assert s.area == s.ses_patches["area"] and s.volume == s.ses_patches["volume"]
    assert s.area == pytest.approx(4 * math.pi * 1.7**2, rel=1e-9)
    assert s.area != s.facet_area


def test_ses_lies_between_vdw_and_sas(tmp_path):
    centres = np.array([[0.0, 0.0, 0.0], [3.5, 0.0, 0.0], [1.7, 2.9, 0.0]])
    radii = np.array([1.7, 1.5, 1.6])
    vdw = molsurf.surface(centres=centres, radii=radii, surface="vdw")
    ses = molsurf.surface(centres=centres, radii=radii, surface="ses")
    sas = molsurf.surface(centres=centres, radii=radii)
    assert vdw.facet_volume < ses.facet_volume < sas.facet_volume
    assert sum(ses.area_per_atom) == pytest.approx(ses.ses_patches["area"], rel=1e-9)
    assert sum(ses.facet_area_per_atom) == pytest.approx(ses.facet_area, rel=1e-9)
    written = ses.write(tmp_path / "ses.off")
    assert written and written[0].exists()


def test_ses_refuses_probe_zero():
    with pytest.raises(molsurf.Error):
        molsurf.surface(centres=np.array([[0.0, 0.0, 0.0]]), radii=np.array([1.7]), surface="ses", probe=0)
    with pytest.raises(molsurf.Error):
        molsurf.surface(centres=np.array([[0.0, 0.0, 0.0]]), radii=np.array([1.7]), surface="torus")
    # As the command line's --surface vdw --probe 2: the vdW surface is the one at probe 0.
    with pytest.raises(molsurf.Error, match="probe 0"):
        molsurf.surface(centres=np.array([[0.0, 0.0, 0.0]]), radii=np.array([1.7]), surface="vdw", probe=2.0)


def test_ses_patches_are_msms_types_with_unit_normals_and_its_files_carry_them(tmp_path):
    centres = np.array([[0.0, 0.0, 0.0], [3.6, 0.0, 0.0], [1.8, 3.6 * math.sqrt(3) / 2, 0.0]])
    radii = np.array([1.6, 1.6, 1.6])
    s = molsurf.surface(centres=centres, radii=radii, surface="ses")
    p = s.patches()
    assert p["vertex_type"].shape == (len(s.vertices),)
    assert p["face_type"].shape == (len(s.faces),)
    assert set(np.unique(p["vertex_type"])) == {1, 2, 3}  # toroidal, reentrant, contact
    assert np.allclose(np.linalg.norm(p["vertex_normal"], axis=1), 1.0, atol=1e-12)
    assert p["vertex_atom"].min() >= 0 and p["vertex_atom"].max() < 3
    # The files carry what patches() gives: PyGBe's reading, numbers only.
    s.write(tmp_path / "ses.vert", msms_header=False)
    vert = np.loadtxt(tmp_path / "ses.vert")
    face = np.loadtxt(tmp_path / "ses.face", dtype=int)
    assert np.array_equal(vert[:, 8].astype(int), p["vertex_type"])
    assert np.array_equal(vert[:, 7].astype(int), p["vertex_atom"] + 1)
    assert np.array_equal(face[:, 3], p["face_type"])
    assert np.array_equal(face[:, 4], p["face_number"] + 1)
    # Analytical faces: contact patches 0-2 (their atoms), tori 3-5, then the probe positions.
    assert np.array_equal(np.unique(p["face_number"][p["face_type"] == 3]), [0, 1, 2])
    assert np.array_equal(np.unique(p["face_number"][p["face_type"] == 1]), [3, 4, 5])
    assert len(np.unique(p["face_number"][p["face_type"] == 2])) == 2  # the probes above and below
    assert np.abs(vert[:, 3:6] - p["vertex_normal"]).max() <= 5e-4 + 1e-12
    with pytest.raises(molsurf.Error, match="solvent-excluded"):
        molsurf.surface(centres=centres, radii=radii).patches()


def test_ses_patches_give_its_area_and_volume_beside_the_facets():
    centres = np.array([[0.0, 0.0, 0.0], [3.6, 0.0, 0.0], [1.8, 3.6 * math.sqrt(3) / 2, 0.0]])
    radii = np.array([1.6, 1.6, 1.6])
    s = molsurf.surface(centres=centres, radii=radii, surface="ses")
    m = s.ses_patches
    assert m["area"] == pytest.approx(m["contact_area"] + m["toroidal_area"] + m["reentrant_area"], rel=1e-12)
    assert m["atom_area"].sum() == pytest.approx(m["area"], rel=1e-9)
    # Three equal atoms: equal shares, up to where the cells fall on the borders between
    # atoms' shares of a saddle or probe cap (cells are halved where the SES ends, not there).
    assert np.allclose(m["atom_area"], m["atom_area"][0], rtol=3e-3)
    # The report's area and volume are the patches'; the facets' at density 2 within half a
    # percent of them.
    assert (s.area, s.volume) == (m["area"], m["volume"])
    assert s.facet_area == pytest.approx(m["area"], rel=5e-3)
    assert s.facet_volume == pytest.approx(m["volume"], rel=5e-3)
    assert molsurf.surface(centres=centres, radii=radii).ses_patches is None


def csv_areas(path):
    with open(path, newline="") as f:
        return np.array([float(row["area"]) for row in csv.DictReader(f)])


def test_ses_area_per_atom_is_its_patches_and_the_commands_csv(cli, data_dir, tmp_path):
    s = molsurf.surface(data_dir / "1crn.pdb", surface="ses")
    patches = s.ses_patches["area"]
    area = np.asarray(s.area_per_atom)
    facets = np.asarray(s.facet_area_per_atom)
    assert area.sum() == pytest.approx(patches, rel=1e-9)
    assert s.area_per_residue["area"].sum() == pytest.approx(patches, rel=1e-9)
    assert np.array_equal(area, s.ses_patches["atom_area"])
    # The facets' stay apart: their own total, +0.35 % at density 2, and atom by atom close to
    # the patches' (the sum of the differences within 6 % of the area: measured 4.5 %, where
    # each face about 0.6 A wide counts whole to one atom; 1.2 % on a mesh 4 times as dense).
    assert facets.sum() == pytest.approx(s.facet_area, rel=1e-9)
    assert abs(facets.sum() - patches) > 1e-6 * patches
    assert facets.sum() == pytest.approx(patches, rel=0.01)
    assert np.abs(area - facets).sum() < 0.06 * patches
    assert s.facet_area_per_residue["area"].sum() == pytest.approx(s.facet_area, rel=1e-9)
    # The command's --per-atom CSV: the same doubles.
    subprocess.run([str(cli), "-q", "--surface", "ses", str(data_dir / "1crn.pdb"), "-o", str(tmp_path / "s.vtp"),
                    "--per-atom", str(tmp_path / "a.csv")], check=True)
    assert np.array_equal(csv_areas(tmp_path / "a.csv"), area)
    # outer_only: the outer surface's patches, less than the whole (crambin's SES has a cavity).
    outer = molsurf.surface(data_dir / "1crn.pdb", surface="ses", outer_only=True)
    assert outer.ses_patches["area"] < patches - 1
    assert np.asarray(outer.area_per_atom).sum() == pytest.approx(outer.ses_patches["area"], rel=1e-9)


def test_stern_layer_is_the_sas_at_its_probe_from_the_same_call(tmp_path):
    centres = np.array([[0.0, 0.0, 0.0], [3.5, 0.0, 0.0], [1.7, 2.9, 0.0]])
    radii = np.array([1.7, 1.5, 1.6])
    ses = molsurf.surface(centres=centres, radii=radii, surface="ses", stern=2.0)
    sas = molsurf.surface(centres=centres, radii=radii, probe=2.0)
    assert ses.stern is not None and ses.stern.check.valid
    assert ses.stern.area == pytest.approx(sas.area, rel=1e-12)
    assert ses.stern.volume == pytest.approx(sas.volume, rel=1e-12)
    assert molsurf.surface(centres=centres, radii=radii, surface="ses").stern is None
    written = ses.stern.write(tmp_path / "stern.ply")
    assert written and written[0].exists()
    with pytest.raises(molsurf.Error, match="stern_probe"):
        molsurf.surface(centres=centres, radii=radii, stern=-1.0)
