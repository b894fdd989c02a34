"""molsurf.surface(): the arrays and measures equal the command line's on the same input (the true
spheres' area, volume, shells and per-atom areas as its report and CSV tables give them, the facets'
as its facet_area, facet_volume and components), the per-atom and per-residue areas add up, results
are views that keep their memory alive, and the GIL is released while a surface is computed."""
import _thread
import csv
import json
import subprocess
import threading
import time

import numpy as np
import pytest

import molsurf


@pytest.fixture(scope="module")
def cli_run(cli, data_dir, tmp_path_factory):
    """The molsurf command on 1crn.pdb: its surface file, JSON report and CSV tables."""
    out = tmp_path_factory.mktemp("cli")
    files = {"mesh": out / "1crn.vtp", "json": out / "1crn.json", "atoms": out / "atoms.csv",
             "residues": out / "residues.csv"}
    subprocess.run([str(cli), "-q", str(data_dir / "1crn.pdb"), "-o", str(files["mesh"]), "--json", str(files["json"]),
                    "--per-atom", str(files["atoms"]), "--per-residue", str(files["residues"])], check=True)
    return files


def test_arrays_equal_the_command_lines_surface(crambin, cli_run):
    written = molsurf.read_mesh(cli_run["mesh"])  # .vtp keeps every double exactly
    assert crambin.vertices.shape == written.vertices.shape
    assert np.array_equal(crambin.vertices, written.vertices)
    assert np.array_equal(crambin.faces, written.faces)
    assert np.array_equal(crambin.atom_of_face, written.tags)
    assert crambin.vertices.dtype == np.float64 and crambin.vertices.shape[1] == 3
    assert crambin.faces.dtype == np.int32 and crambin.faces.shape[1] == 3
    assert crambin.atom_of_face.dtype == np.int32 and crambin.atom_of_face.shape == (len(crambin.faces),)


def test_measures_equal_the_command_lines_report(crambin, cli_run):
    report = json.loads(cli_run["json"].read_text())
    # area and volume: the true spheres' (exact); facet_*: the mesh's.
    assert crambin.area == report["area"] and crambin.volume == report["volume"]  # to the last bit
    assert crambin.facet_area == pytest.approx(report["facet_area"], rel=1e-12)
    assert crambin.facet_volume == pytest.approx(report["facet_volume"], rel=1e-12)
    assert len(crambin.faces) == report["faces"] and len(crambin.vertices) == report["vertices"]
    assert len(crambin.components) == len(report["components"])
    for mine, theirs in zip(crambin.components, report["components"]):
        assert mine.cavity == (theirs["kind"] == "cavity")
        assert mine.faces == theirs["faces"]
        assert mine.area == pytest.approx(theirs["area"], rel=1e-12)
        assert abs(mine.volume) == pytest.approx(theirs["volume"], rel=1e-12)
    assert crambin.arrangement == {k: v for k, v in report["arrangement"].items() if k != "seconds"}
    assert crambin.quality.min_angle_deg == pytest.approx(report["quality"]["min_angle_deg"], rel=1e-12)
    assert crambin.quality.below_5deg == report["quality"]["faces_below_5deg"]
    assert crambin.cleanup["collapses"] == report["cleanup"]["collapses"]
    assert crambin.structure.report["kept"] == report["input"]["atoms"]


def assert_shells_equal_the_reports(shells, reported):
    assert len(shells) == len(reported)
    for mine, theirs in zip(shells, reported):
        assert mine.kind == theirs["kind"] and mine.cavity == (theirs["kind"] == "cavity")
        assert mine.area == theirs["area"] and mine.volume == theirs["volume"]
        assert list(mine.centroid) == theirs["centroid"]
        assert mine.atoms.dtype == np.int32 and list(mine.atoms) == theirs["atoms"]
        assert mine.mesh_component == theirs.get("mesh_component")
        assert mine.to_dict()["atoms"] == theirs["atoms"]


def test_shells_equal_the_command_lines_report(crambin, cli_run):
    report = json.loads(cli_run["json"].read_text())
    shells = crambin.shells
    assert_shells_equal_the_reports(shells, report["shells"])
    # 1crn at probe 1.4: one outer surface and one small cavity, each followed by a mesh component.
    assert [s.kind for s in shells] == ["outer", "cavity"]
    assert report["cavities"] == 1
    assert crambin.component_shells == [0, 1]
    for k, shell in enumerate(shells):
        component = crambin.components[shell.mesh_component]
        assert component.cavity == shell.cavity and crambin.component_shells[shell.mesh_component] == k
        # The facets follow the true shell closely (within 0.5 % of area at density 2 on the outer
        # surface; a cavity of 1 A^2 is cut coarsely, so only within 10 % there).
        assert component.area == pytest.approx(shell.area, rel=5e-3 if not shell.cavity else 0.1)
    # A shell's lining atoms are exactly the atoms with exposed area on it.
    assert shells[1].centroid.shape == (3,) and shells[1].centroid.dtype == np.float64
    lining = np.union1d(shells[0].atoms, shells[1].atoms)
    assert np.array_equal(lining, np.flatnonzero(crambin.area_per_atom > 0))


def test_per_atom_and_per_residue_areas_equal_the_csv_tables(crambin, cli_run):
    with open(cli_run["atoms"]) as f:
        atoms = list(csv.DictReader(f))
    assert len(atoms) == len(crambin.area_per_atom) == len(crambin.structure)
    # The CSV's area column is the true spheres' per-atom area, printed to the last bit.
    assert list(crambin.area_per_atom) == [float(row["area"]) for row in atoms]
    assert list(crambin.structure.atom_names) == [row["atom_name"] for row in atoms]
    with open(cli_run["residues"]) as f:
        residues = list(csv.DictReader(f))
    table = crambin.area_per_residue
    assert len(table) == len(residues)
    assert list(table["residue_number"]) == [int(row["residue_number"]) for row in residues]
    assert list(table["residue_name"]) == [row["residue_name"] for row in residues]
    assert list(table["area"]) == [float(row["area"]) for row in residues]


def test_per_atom_areas_sum_to_the_total(crambin):
    # The true spheres' numbers.
    assert crambin.area_per_atom.sum() == pytest.approx(crambin.area, rel=1e-12)
    assert crambin.area_per_residue["area"].sum() == pytest.approx(crambin.area, rel=1e-12)
    assert crambin.area_per_residue["atoms"].sum() == len(crambin.structure)
    assert sum(s.area for s in crambin.shells) == pytest.approx(crambin.area, rel=1e-12)
    assert sum(-s.volume if s.cavity else s.volume for s in crambin.shells) == pytest.approx(crambin.volume,
                                                                                             rel=1e-12)
    # The facets' numbers.
    assert crambin.facet_area_per_atom.sum() == pytest.approx(crambin.facet_area, rel=1e-12)
    assert crambin.facet_area_per_residue["area"].sum() == pytest.approx(crambin.facet_area, rel=1e-12)
    assert sum(c.area for c in crambin.components) == pytest.approx(crambin.facet_area, rel=1e-12)
    assert sum(c.volume for c in crambin.components) == pytest.approx(crambin.facet_volume, rel=1e-12)
    # The faces tagged with an atom carry its facet area.
    corners = crambin.vertices[crambin.faces]
    face_area = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1) / 2
    per_atom = np.bincount(crambin.atom_of_face, weights=face_area, minlength=len(crambin.structure))
    assert np.allclose(per_atom, crambin.facet_area_per_atom, rtol=1e-12, atol=1e-12)
    assert face_area.sum() == pytest.approx(crambin.facet_area, rel=1e-12)


def test_exact_and_facet_areas_are_close_but_not_the_same(crambin):
    # Within 0.5 % at density 2 (docs/accuracy.md), but the facets' own numbers.
    assert crambin.area != crambin.facet_area and crambin.volume != crambin.facet_volume
    assert crambin.facet_area == pytest.approx(crambin.area, rel=5e-3)
    assert crambin.facet_volume == pytest.approx(crambin.volume, rel=5e-3)
    # An atom with facets has true exposed area; big patches agree closely.
    exact, facets = crambin.area_per_atom, crambin.facet_area_per_atom
    assert np.all(exact[facets > 0.5] > 0)
    big = exact > 20
    assert np.allclose(facets[big], exact[big], rtol=0.05)


def test_geometry_is_a_read_only_view_that_outlives_the_surface(data_dir):
    surface = molsurf.surface(data_dir / "1crn.pdb", threads=1)
    vertices, faces, area = surface.vertices, surface.faces, surface.area_per_atom
    facet_area = surface.facet_area_per_atom
    expected = np.array(vertices)  # a copy
    expected_area = np.array(area)
    for array in (vertices, faces, area, facet_area, surface.atom_of_face):
        assert not array.flags.writeable
        with pytest.raises(ValueError):
            array[0] = 0
    del surface
    assert np.array_equal(vertices, expected)  # the view keeps the surface's memory alive
    assert np.array_equal(area, expected_area) and facet_area.sum() > area.sum() > 0
    assert faces.max() < len(vertices) and faces.min() >= 0


def test_structure_arrays_and_the_same_surface_from_raw_arrays(crambin, data_dir):
    structure = molsurf.read_structure(data_dir / "1crn.pdb")
    assert len(structure) == 327
    assert structure.centres.shape == (327, 3) and structure.centres.dtype == np.float64
    assert structure.radii.shape == (327,) and np.all(structure.radii > 1)
    assert structure.elements[0] == "N" and structure.atom_names[1] == "CA"
    assert structure.residue_names[0] == "THR" and structure.residue_numbers[0] == 1
    assert set(structure.chains) == {"A"}
    from_arrays = molsurf.surface(centres=structure.centres, radii=structure.radii)
    assert np.array_equal(from_arrays.vertices, crambin.vertices)
    assert np.array_equal(from_arrays.faces, crambin.faces)
    assert from_arrays.area == crambin.area and from_arrays.volume == crambin.volume
    assert from_arrays.facet_area == crambin.facet_area
    assert np.array_equal(from_arrays.area_per_atom, crambin.area_per_atom)
    from_structure = molsurf.surface(structure)
    assert from_structure.area == crambin.area


def test_options_follow_the_command_line(data_dir, cli, tmp_path):
    options = dict(probe=0.0, density=1.0, outer_only=True, method="pairwise", cleanup=False)
    surface = molsurf.surface(str(data_dir / "1crn.pdb"), **options)
    report = tmp_path / "r.json"
    subprocess.run([str(cli), "-q", str(data_dir / "1crn.pdb"), "-o", str(tmp_path / "s.vtp"), "--json", str(report),
                    "--probe", "0", "--density", "1", "--outer-only", "--method", "pairwise", "--no-cleanup"],
                   check=True)
    expected = json.loads(report.read_text())
    assert surface.method == "pairwise" and surface.cleanup is None
    assert surface.area == expected["area"] and surface.volume == expected["volume"]  # to the last bit
    assert surface.facet_area == pytest.approx(expected["facet_area"], rel=1e-12)
    assert surface.facet_volume == pytest.approx(expected["facet_volume"], rel=1e-12)
    assert all(not c.cavity for c in surface.components)
    assert_shells_equal_the_reports(surface.shells, expected["shells"])


def test_outer_only_leaves_the_true_cavities_out(crambin, data_dir, cli, tmp_path):
    # As --outer-only: the cavities are left out of area, volume, shells and per-atom areas.
    surface = molsurf.surface(data_dir / "1crn.pdb", outer_only=True)
    report, atoms = tmp_path / "r.json", tmp_path / "atoms.csv"
    subprocess.run([str(cli), "-q", str(data_dir / "1crn.pdb"), "-o", str(tmp_path / "s.vtp"), "--json", str(report),
                    "--per-atom", str(atoms), "--outer-only"], check=True)
    expected = json.loads(report.read_text())
    assert surface.area == expected["area"] and surface.volume == expected["volume"]  # to the last bit
    assert surface.facet_area == pytest.approx(expected["facet_area"], rel=1e-12)
    assert_shells_equal_the_reports(surface.shells, expected["shells"])
    with open(atoms) as f:
        assert list(surface.area_per_atom) == [float(row["area"]) for row in csv.DictReader(f)]
    outer, cavity = crambin.shells
    assert [s.kind for s in surface.shells] == ["outer"] and all(not c.cavity for c in surface.components)
    assert surface.area == outer.area and surface.volume == outer.volume
    assert surface.area < crambin.area and surface.volume > crambin.volume
    assert surface.area_per_atom.sum() == pytest.approx(outer.area, rel=1e-12)
    assert crambin.area_per_atom.sum() - surface.area_per_atom.sum() == pytest.approx(cavity.area, rel=1e-9)
    only_on_the_cavity = np.setdiff1d(cavity.atoms, outer.atoms)
    assert np.all(surface.area_per_atom[only_on_the_cavity] == 0)
    assert np.all(crambin.area_per_atom[only_on_the_cavity] > 0)


def test_timings_quality_and_check(crambin):
    assert set(crambin.timings) == {"union", "cleanup", "check", "measures", "total"}
    assert all(t >= 0 for t in crambin.timings.values())
    assert crambin.timings["total"] >= crambin.timings["union"]
    assert 0 < crambin.quality.min_angle_deg < 60 and crambin.quality.faces == len(crambin.faces)
    assert crambin.check.valid and crambin.check.closed and crambin.check.self_intersections_checked
    assert crambin.method == "one-pass" and crambin.notes == []
    assert crambin.threads >= 1


def test_write_round_trips_and_checks_lossy_formats(crambin, tmp_path):
    assert crambin.write(tmp_path / "s.ply") == [tmp_path / "s.ply"]
    back = molsurf.read_mesh(tmp_path / "s.ply")
    assert np.array_equal(back.vertices, crambin.vertices) and np.array_equal(back.faces, crambin.faces)
    written = crambin.write(str(tmp_path / "s.vert"))
    assert sorted(written) == [tmp_path / "s.face", tmp_path / "s.vert"]
    assert molsurf.check(molsurf.read_mesh(tmp_path / "s.vert")).valid
    with pytest.raises(molsurf.Error, match="unknown|extension|format"):
        crambin.write(tmp_path / "s.xyz")


def test_the_gil_is_released_while_computing(data_dir, ticks_during, in_two_threads):
    structure = molsurf.read_structure(data_dir / "1ubq.pdb")
    surface, ticks = ticks_during(lambda: molsurf.surface(structure, threads=1))
    assert surface.area > 0
    # With the GIL held for the whole computation the counter could not have advanced.
    assert ticks > 5
    # Two surfaces in two Python threads give the same result as one after the other.
    results = in_two_threads(lambda: molsurf.surface(structure, threads=1))
    assert np.array_equal(results[0].vertices, surface.vertices)
    assert np.array_equal(results[1].faces, surface.faces)


def test_ctrl_c_raises_keyboard_interrupt_and_leaves_the_module_usable(data_dir):
    structure = molsurf.read_structure(data_dir / "1ubq.pdb")
    timer = threading.Timer(0.05, _thread.interrupt_main)  # as if Ctrl-C were pressed during the call
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            molsurf.surface(structure, threads=1)
            time.sleep(5)  # reached only if the call finished before the interrupt came
    finally:
        timer.cancel()
    assert molsurf.surface(structure, threads=1, density=1.0).check.valid
