"""Bad input raises molsurf.Error (a RuntimeError) with the library's own FILE[:LINE] message,
the one the molsurf command prints."""
import subprocess

import numpy as np
import pytest

import molsurf


def cli_message(cli, *args):
    run = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)
    assert run.returncode == 1
    return run.stderr.strip()


def test_error_is_a_runtime_error():
    assert issubclass(molsurf.Error, RuntimeError)


def test_missing_file_names_it(tmp_path):
    missing = tmp_path / "missing.pdb"
    with pytest.raises(molsurf.Error, match="missing.pdb: file not found"):
        molsurf.surface(missing)
    with pytest.raises(molsurf.Error, match="missing.pdb: file not found"):
        molsurf.read_structure(str(missing))


def test_malformed_record_gives_the_command_lines_message(tmp_path, cli):
    bad = tmp_path / "bad.pdb"
    bad.write_text("ATOM      1  N   THR A   1      17.047  xx.xxx   3.625  1.00 13.79           N\n")
    with pytest.raises(molsurf.Error) as raised:
        molsurf.surface(bad)
    message = str(raised.value)
    assert message.startswith(f"{bad}:1: ATOM record: y coordinate")
    assert message in cli_message(cli, bad, "-o", tmp_path / "out.vtp")


def test_selection_errors(data_dir):
    with pytest.raises(molsurf.Error, match="model 99 not found"):
        molsurf.read_structure(data_dir / "1j8k.cif", model=99)
    with pytest.raises(molsurf.Error, match="no atoms left after filtering"):
        molsurf.read_structure(data_dir / "1crn.pdb", chains="Z")
    with pytest.raises(molsurf.Error, match="radius_set"):
        molsurf.read_structure(data_dir / "1crn.pdb", radius_set="vdw")


def test_bad_options_and_arrays():
    centres = np.zeros((2, 3))
    with pytest.raises(molsurf.Error, match="method"):
        molsurf.surface(centres=centres, radii=[1.5, 1.5], method="fast")
    with pytest.raises(molsurf.Error, match="probe"):
        molsurf.surface(centres=centres, radii=[1.5, 1.5], probe=-1)
    with pytest.raises(molsurf.Error, match=r"centres: expected an array of shape \(N, 3\)"):
        molsurf.surface(centres=np.zeros((2, 2)), radii=[1.5, 1.5])
    with pytest.raises(molsurf.Error, match="radii: expected one per centre"):
        molsurf.surface(centres=centres, radii=[1.5])
    with pytest.raises(molsurf.Error, match="radius"):
        molsurf.surface(centres=centres, radii=[1.5, 0.0], probe=0)  # a sphere of radius 0
    with pytest.raises(molsurf.Error, match="sphere faces|max"):
        molsurf.surface(centres=centres, radii=[1.5, 1.5], max_faces=10)
    with pytest.raises(molsurf.Error, match="nothing to compute"):
        molsurf.surface()
    with pytest.raises(TypeError):
        molsurf.surface(42)


@pytest.mark.parametrize("function", [molsurf.areas, molsurf.surface], ids=["areas", "surface"])
def test_bad_spheres_raise_molsurf_error(function):
    centres = np.zeros((2, 3))
    centres[1, 0] = 3
    bad = [
        (dict(centres=[[0, 0, np.nan], [3, 0, 0]], radii=[1.5, 1.5]), r"^centres\[0, 2\]: nan is not a finite number$"),
        (dict(centres=[[0, 0, 0], [np.inf, 0, 0]], radii=[1.5, 1.5]), r"^centres\[1, 0\]: inf is not a finite number$"),
        (dict(centres=[[0, 0, 0], [-1e17, 0, 0]], radii=[1.5, 1.5]), r"^centres\[1, 0\]: -1e\+17 is out of range .*below 1e16"),
        (dict(centres=centres, radii=[1.5, -0.5]), r"^radii\[1\]: -0.5 is negative; a radius is 0 or more"),
        (dict(centres=centres, radii=[np.nan, 1.5]), r"^radii\[0\]: nan is not a finite number$"),
        (dict(centres=centres, radii=[np.inf, 1.5]), r"^radii\[0\]: inf is not a finite number$"),
        (dict(centres=np.zeros((2, 2)), radii=[1.5, 1.5]), r"centres: expected an array of shape \(N, 3\), got \(2, 2\)"),
        (dict(centres=np.zeros(3), radii=[1.5]), r"centres: expected an array of shape \(N, 3\), got \(3,\)"),
        (dict(centres=centres, radii=[1.5]), r"radii: expected one per centre, shape \(2,\), got \(1,\)"),
        (dict(centres=centres, radii=[[1.5, 1.5]]), r"radii: expected one per centre"),
        (dict(centres=[["a", "b", "c"]], radii=[1.0]), r"centres: not convertible to a numeric array"),
        (dict(centres=centres), r"centres and radii go together"),
        (dict(radii=[1.5, 1.5]), r"centres and radii go together"),
        (dict(centres=centres, radii=[1.5, 1.5], probe=-1), r"probe"),
        (dict(centres=centres, radii=[1.5, 1.5], probe=np.nan), r"probe"),
        (dict(centres=centres, radii=[1.5, 1.5], probe=np.inf), r"probe"),
        (dict(centres=centres, radii=[1.5, 1.5], threads=-1), r"threads"),
        (dict(structure="data/pdb/1crn.pdb", centres=centres, radii=[1.5, 1.5]), r"either a structure or centres"),
        (dict(), r"nothing to compute"),
    ]
    for arguments, message in bad:
        with pytest.raises(molsurf.Error, match=message):
            function(**arguments)
    with pytest.raises(TypeError):
        function(42)


def test_areas_selection_and_file_errors(data_dir, tmp_path):
    with pytest.raises(molsurf.Error, match="missing.pdb: file not found"):
        molsurf.areas(tmp_path / "missing.pdb")
    with pytest.raises(molsurf.Error, match="no atoms left after filtering"):
        molsurf.areas(data_dir / "1crn.pdb", chains="Z")
    with pytest.raises(molsurf.Error, match="radius_set"):
        molsurf.areas(data_dir / "1crn.pdb", radius_set="vdw")


def test_bad_mesh_input(tmp_path):
    with pytest.raises(molsurf.Error, match=r"^faces\[0, 2\]: vertex index 7 out of range \(0\.\.2\)$"):
        molsurf.check(np.zeros((3, 3)), [[0, 1, 7]])
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(molsurf.Error, match="broken.off"):
        molsurf.read_mesh(broken)
