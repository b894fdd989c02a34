"""The examples under examples/ run, and what they write is checked against the library."""
import csv
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import molsurf


def run_example(source_dir, name, cwd, *args):
    # The example imports the molsurf module these tests import, from any working directory.
    path = os.pathsep.join(filter(None, [os.path.dirname(os.path.abspath(molsurf.__file__)),
                                         os.environ.get("PYTHONPATH")]))
    run = subprocess.run([sys.executable, str(source_dir / "examples" / name), *map(str, args)], cwd=cwd,
                         capture_output=True, text=True, env={**os.environ, "PYTHONPATH": path, "MPLBACKEND": "Agg"})
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_residue_sasa_over_nmr_models(source_dir, data_dir, tmp_path):
    pytest.importorskip("matplotlib")
    pytest.importorskip("gemmi")
    # Six of the 20 models keep the test short; the example's default is all of them.
    out = run_example(source_dir, "residue_sasa_nmr.py", tmp_path, "--models", 6)
    assert "1j8k.cif: 6 models" in out
    png = tmp_path / "1j8k_residue_sasa.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import matplotlib.image
    assert matplotlib.image.imread(str(png)).shape[:2] == (400, 1000)
    with open(tmp_path / "1j8k_residue_sasa.csv") as f:
        rows = list(csv.DictReader(f))
    model_1 = molsurf.surface(data_dir / "1j8k.cif").area_per_residue  # exact: the same as areas()
    assert len(rows) == len(model_1) > 80
    for row, residue in zip(rows, model_1):
        assert int(row["residue_number"]) == residue["residue_number"]
        assert row["residue_name"] == residue["residue_name"]
        # Model 1's area lies within the range over the models (printed to 4 decimals).
        assert float(row["min_area"]) - 1e-4 <= residue["area"] <= float(row["max_area"]) + 1e-4
        assert float(row["min_area"]) <= float(row["mean_area"]) <= float(row["max_area"])


def test_surface_to_meshio_msh(source_dir, data_dir, tmp_path, crambin):
    meshio = pytest.importorskip("meshio")
    out = run_example(source_dir, "surface_to_meshio.py", tmp_path)
    assert f"{len(crambin.faces)} triangles" in out
    assert f"area {crambin.facet_area:.2f} Å²" in out and f"true spheres: {crambin.area:.2f} Å²" in out
    msh = tmp_path / "1crn.msh"
    mesh = meshio.read(msh)
    assert np.allclose(mesh.points, crambin.vertices, rtol=0, atol=1e-9)
    triangles = mesh.cells_dict["triangle"]
    assert np.array_equal(triangles, crambin.faces)
    assert np.array_equal(mesh.cell_data_dict["gmsh:physical"]["triangle"], crambin.atom_of_face + 1)
    # molsurf's own reader takes the file too, and it is still a valid closed surface.
    back = molsurf.read_mesh(msh)
    assert len(back.faces) == len(crambin.faces)
    assert molsurf.check(back).valid


def test_trajectory_sasa_over_nmr_models(source_dir, data_dir, tmp_path):
    gemmi = pytest.importorskip("gemmi")
    out = run_example(source_dir, "trajectory_sasa.py", tmp_path, "--models", 5, "--threads", 2)
    assert "1j8k.cif: 5 models" in out
    # Each model's printed SASA is molsurf.areas() on that model alone (the same selection).
    st = gemmi.read_structure(str(data_dir / "1j8k.cif"))
    numbers = [int(model.name) for model in st][:5]
    rows = {int(line.split()[0]): line.split()[1:] for line in out.splitlines() if line.split()[:1] and line.split()[0].isdigit()}
    assert sorted(rows) == numbers
    for number in numbers:
        single = molsurf.areas(st, model=number)
        assert rows[number] == [f"{single.area:.2f}", f"{single.volume:.2f}"]


def test_md_interop_frames_from_mdtraj_or_mdanalysis(source_dir, data_dir, tmp_path):
    pytest.importorskip("gemmi")
    engines = [e for e, module in (("mdtraj", "mdtraj"), ("mdanalysis", "MDAnalysis"))
               if __import__("importlib").util.find_spec(module)]
    if not engines:
        pytest.skip("neither MDTraj nor MDAnalysis is installed")
    out = run_example(source_dir, "md_interop.py", tmp_path, "--engine", engines[0])
    assert "1j8k.cif: 20 frames, 1402 atoms" in out
    rows = [line.split() for line in out.splitlines() if line.strip() and line.split()[0].isdigit()]
    assert [int(r[0]) for r in rows] == list(range(20))
    # Each frame's area is that of the model read by molsurf itself (float32 coordinates in between).
    for frame in (0, 19):
        model = molsurf.read_structure(data_dir / "1j8k.cif", model=frame + 1, hydrogens=True, keep_water=True)
        assert float(rows[frame][1]) == pytest.approx(molsurf.areas(model).area, abs=0.02)


def test_sweep_with_dask_one_row_per_structure_and_failures_recorded(source_dir, data_dir, tmp_path):
    pytest.importorskip("dask")
    bad = tmp_path / "broken.pdb"
    bad.write_text("not a structure\n")
    files = [data_dir / "1crn.pdb", data_dir / "1ubq.pdb", bad]
    out = run_example(source_dir, "sweep_dask.py", tmp_path, *files, "-o", tmp_path / "sweep.csv", "--workers", 2)
    assert "3 structures, 1 failed" in out
    with open(tmp_path / "sweep.csv") as f:
        rows = list(csv.DictReader(f))
    assert [row["file"] for row in rows] == [str(f) for f in files]
    for row, path in zip(rows[:2], files[:2]):
        expected = molsurf.areas(path)
        assert row["status"] == "ok"
        assert float(row["area"]) == pytest.approx(expected.area, abs=1e-3)
        assert float(row["volume"]) == pytest.approx(expected.volume, abs=1e-3)
        assert int(row["atoms"]) == len(expected.area_per_atom)
    assert rows[2]["status"].startswith("failed: ")


def test_sweep_with_snakemake_one_job_per_structure(source_dir, data_dir, tmp_path, cli):
    snakemake = shutil.which("snakemake")
    if snakemake is None:
        pytest.skip("snakemake not installed (Debian: snakemake)")
    structures = tmp_path / "pdb"
    structures.mkdir()
    for name in ["1crn.pdb", "1ubq.pdb"]:
        shutil.copy(data_dir / name, structures / name)
    run = subprocess.run([snakemake, "-s", str(source_dir / "examples" / "Snakefile"), "-j", "2", "--config",
                          f"structures={structures}/", f"molsurf={cli}", f"out={tmp_path / 'out'}/"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    with open(tmp_path / "out" / "summary.csv") as f:
        rows = list(csv.DictReader(f))
    assert [os.path.basename(row["file"]) for row in rows] == ["1crn.pdb", "1ubq.pdb"]
    for row in rows:
        expected = molsurf.areas(row["file"])
        assert float(row["area"]) == pytest.approx(expected.area, rel=1e-12)
        assert (tmp_path / "out" / (os.path.basename(row["file"])[:-4] + ".vtp")).stat().st_size > 0
