"""molsurf.surface(): the arrays and measures equal the command line's on the same input, the
per-atom and per-residue areas add up, results are views that keep their memory alive, and the
GIL is released while a surface is computed."""
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
    assert crambin.area == pytest.approx(report["area"], rel=1e-12)
    assert crambin.volume == pytest.approx(report["volume"], rel=1e-12)
    assert len(crambin.faces) == report["faces"] and len(crambin.vertices) == report["vertices"]
    assert len(crambin.components) == len(report["components"])
    for mine, theirs in zip(crambin.components, report["components"]):
        assert mine.cavity == (theirs["kind"] == "cavity")
        assert mine.faces == theirs["faces"]
        assert mine.area == pytest.approx(theirs["area"], rel=1e-12)
        assert abs(mine.volume) == pytest.approx(theirs["volume"], rel=1e-12)
    assert crambin.quality.min_angle_deg == pytest.approx(report["quality"]["min_angle_deg"], rel=1e-12)
    assert crambin.quality.below_5deg == report["quality"]["faces_below_5deg"]
    assert crambin.cleanup["collapses"] == report["cleanup"]["collapses"]
    assert crambin.structure.report["kept"] == report["input"]["atoms"]


def test_per_atom_and_per_residue_areas_equal_the_csv_tables(crambin, cli_run):
    with open(cli_run["atoms"]) as f:
        atoms = list(csv.DictReader(f))
    assert len(atoms) == len(crambin.area_per_atom) == len(crambin.structure)
    assert np.allclose(crambin.area_per_atom, [float(row["area"]) for row in atoms], atol=1e-4)
    assert list(crambin.structure.atom_names) == [row["atom_name"] for row in atoms]
    with open(cli_run["residues"]) as f:
        residues = list(csv.DictReader(f))
    table = crambin.area_per_residue
    assert len(table) == len(residues)
    assert list(table["residue_number"]) == [int(row["residue_number"]) for row in residues]
    assert list(table["residue_name"]) == [row["residue_name"] for row in residues]
    assert np.allclose(table["area"], [float(row["area"]) for row in residues], atol=1e-4)


def test_per_atom_areas_sum_to_the_total(crambin):
    assert crambin.area_per_atom.sum() == pytest.approx(crambin.area, rel=1e-12)
    assert crambin.area_per_residue["area"].sum() == pytest.approx(crambin.area, rel=1e-12)
    assert crambin.area_per_residue["atoms"].sum() == len(crambin.structure)
    assert sum(c.area for c in crambin.components) == pytest.approx(crambin.area, rel=1e-12)
    assert sum(c.volume for c in crambin.components) == pytest.approx(crambin.volume, rel=1e-12)


def test_geometry_is_a_read_only_view_that_outlives_the_surface(data_dir):
    surface = molsurf.surface(data_dir / "1crn.pdb", threads=1)
    vertices, faces, area = surface.vertices, surface.faces, surface.area_per_atom
    expected = np.array(vertices)  # a copy
    for array in (vertices, faces, area, surface.atom_of_face):
        assert not array.flags.writeable
        with pytest.raises(ValueError):
            array[0] = 0
    del surface
    assert np.array_equal(vertices, expected)  # the view keeps the surface's memory alive
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
    assert surface.area == pytest.approx(expected["area"], rel=1e-12)
    assert surface.volume == pytest.approx(expected["volume"], rel=1e-12)
    assert all(not c.cavity for c in surface.components)


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


def test_the_gil_is_released_while_computing(data_dir):
    structure = molsurf.read_structure(data_dir / "1ubq.pdb")
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start_ticks = ticks
    try:
        surface = molsurf.surface(structure, threads=1)
    finally:
        done.set()
        counter.join()
    assert surface.area > 0
    # With the GIL held for the whole computation the counter could not have advanced.
    assert ticks - start_ticks > 5
    # Two surfaces in two Python threads give the same result as one after the other.
    results = [None, None]

    def run(i):
        results[i] = molsurf.surface(structure, threads=1)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
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
