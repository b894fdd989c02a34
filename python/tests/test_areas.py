"""molsurf.areas(): the exact areas and volumes of the true spheres with no mesh (molsurf
--areas-only). They equal the command's report and CSV tables, the same numbers of
molsurf.surface() (one arrangement), and closed forms for one and two spheres; the GIL is released
while they are computed."""
import csv
import json
import math
import subprocess

import numpy as np
import pytest

import molsurf


def shells_equal(a, b, mesh_components=True):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert x.kind == y.kind and x.area == y.area and x.volume == y.volume
        assert np.array_equal(x.centroid, y.centroid) and np.array_equal(x.atoms, y.atoms)
        if mesh_components:
            assert x.mesh_component == y.mesh_component
    return True


def test_areas_equal_the_surfaces_true_sphere_numbers(crambin, data_dir):
    areas = molsurf.areas(data_dir / "1crn.pdb")
    # The same arrangement of the same spheres: equal to the last bit.
    assert areas.area == crambin.area and areas.volume == crambin.volume
    assert np.array_equal(areas.area_per_atom, crambin.area_per_atom)
    assert np.array_equal(areas.area_per_residue, crambin.area_per_residue)
    assert shells_equal(areas.shells, crambin.shells, mesh_components=False)
    assert all(s.mesh_component is None for s in areas.shells)
    assert [s.mesh_component for s in crambin.shells] == [0, 1]
    assert areas.arrangement == crambin.arrangement
    assert np.array_equal(areas.structure.centres, crambin.structure.centres)
    assert areas.probe == 1.4 and not areas.outer_only and areas.threads >= 1 and areas.seconds >= 0
    # The facets are a different (approximate) thing.
    assert areas.area != crambin.facet_area
    # outer_only: the same as surface(outer_only=True).
    outer = molsurf.areas(data_dir / "1crn.pdb", outer_only=True)
    outer_surface = molsurf.surface(data_dir / "1crn.pdb", outer_only=True)
    assert outer.area == outer_surface.area and outer.volume == outer_surface.volume
    assert np.array_equal(outer.area_per_atom, outer_surface.area_per_atom)
    assert [s.kind for s in outer.shells] == ["outer"] and outer.outer_only


@pytest.mark.parametrize("options,flags", [({}, []), ({"probe": 0.0}, ["--probe", "0"]),
                                           ({"outer_only": True, "probe": 1.0}, ["--outer-only", "--probe", "1"]),
                                           ({"chains": "A,C", "radius_set": "bondi"},
                                            ["--chains", "A,C", "--radius-set", "bondi"])],
                         ids=["defaults", "probe0", "outer-only", "selection"])
def test_areas_equal_the_command_lines_areas_only(cli, data_dir, tmp_path, options, flags):
    structure = data_dir / ("2hhb.cif" if "chains" in options else "1ubq.pdb")
    report, atoms, residues = tmp_path / "r.json", tmp_path / "atoms.csv", tmp_path / "residues.csv"
    subprocess.run([str(cli), "-q", "--areas-only", str(structure), "--json", str(report), "--per-atom", str(atoms),
                    "--per-residue", str(residues), *flags], check=True)
    expected = json.loads(report.read_text())
    areas = molsurf.areas(structure, **options)
    assert expected["areas_only"]
    assert areas.area == expected["area"] and areas.volume == expected["volume"]  # to the last bit
    assert len(areas.shells) == len(expected["shells"])
    for mine, theirs in zip(areas.shells, expected["shells"]):
        assert mine.kind == theirs["kind"]
        assert mine.area == theirs["area"] and mine.volume == theirs["volume"]
        assert list(mine.centroid) == theirs["centroid"]
        assert list(mine.atoms) == theirs["atoms"] and mine.mesh_component is None
        assert "mesh_component" not in theirs
    assert areas.arrangement == {k: v for k, v in expected["arrangement"].items() if k != "seconds"}
    # The CSV tables, printed to the last bit (shortest round-trip).
    with open(atoms) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(areas.structure) == expected["input"]["atoms"]
    assert list(areas.area_per_atom) == [float(row["area"]) for row in rows]
    with open(residues) as f:
        rows = list(csv.DictReader(f))
    table = areas.area_per_residue
    assert list(table["chain"]) == [row["chain"] for row in rows]
    assert list(table["area"]) == [float(row["area"]) for row in rows]
    assert areas.area_per_atom.sum() == pytest.approx(areas.area, rel=1e-12)


def test_areas_of_raw_spheres_and_of_a_structure_agree(data_dir):
    structure = molsurf.read_structure(data_dir / "1ubq.pdb")
    from_path = molsurf.areas(data_dir / "1ubq.pdb")
    from_structure = molsurf.areas(structure)
    from_arrays = molsurf.areas(centres=structure.centres, radii=structure.radii)
    # Lists and float32 are converted like surface()'s arrays.
    from_lists = molsurf.areas(centres=structure.centres.tolist(), radii=list(structure.radii))
    for other in (from_structure, from_arrays, from_lists):
        assert other.area == from_path.area and other.volume == from_path.volume
        assert np.array_equal(other.area_per_atom, from_path.area_per_atom)
    assert from_arrays.structure.report["radius_set"] == "given"
    # The probe is added to the radii: probe p on radii r is probe 0 on r + p.
    grown = molsurf.areas(centres=structure.centres, radii=structure.radii + 1.4, probe=0)
    assert grown.area == pytest.approx(from_path.area, rel=1e-12)
    assert grown.volume == pytest.approx(from_path.volume, rel=1e-12)


def test_areas_do_not_depend_on_the_thread_count(data_dir):
    structure = molsurf.read_structure(data_dir / "2hhb.pdb")
    one, many = molsurf.areas(structure, threads=1), molsurf.areas(structure, threads=4)
    assert one.threads == 1 and many.threads == 4
    assert one.area == many.area and one.volume == many.volume
    assert np.array_equal(one.area_per_atom, many.area_per_atom)
    assert shells_equal(one.shells, many.shells)
    assert sum(s.cavity for s in one.shells) > 10  # haemoglobin has many small cavities


def test_closed_forms_for_one_and_two_spheres():
    one = molsurf.areas(centres=[[1.0, 2.0, 3.0]], radii=[2.0], probe=0.5)
    r = 2.5
    assert one.area == pytest.approx(4 * math.pi * r * r, rel=1e-14)
    assert one.volume == pytest.approx(4 / 3 * math.pi * r ** 3, rel=1e-14)
    (shell,) = one.shells
    assert shell.kind == "outer" and np.allclose(shell.centroid, [1, 2, 3], atol=1e-12)
    assert list(shell.atoms) == [0]

    # Two overlapping spheres: each loses a cap; the union loses the lens.
    r1, r2, d = 1.5, 2.0, 2.5
    two = molsurf.areas(centres=[[0, 0, 0], [d, 0, 0]], radii=[r1, r2], probe=0)
    h1 = (r2 - r1 + d) * (r2 + r1 - d) / (2 * d)  # height of the cap of sphere 1 inside sphere 2
    h2 = (r1 - r2 + d) * (r1 + r2 - d) / (2 * d)
    assert two.area_per_atom == pytest.approx([4 * math.pi * r1 ** 2 - 2 * math.pi * r1 * h1,
                                               4 * math.pi * r2 ** 2 - 2 * math.pi * r2 * h2], rel=1e-12)
    lens = math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)
    assert two.volume == pytest.approx(4 / 3 * math.pi * (r1 ** 3 + r2 ** 3) - lens, rel=1e-12)

    # A sphere inside another is buried; so is a sphere of radius 0; no spheres: nothing.
    nested = molsurf.areas(centres=[[0, 0, 0], [0.1, 0, 0], [5, 0, 0]], radii=[2.0, 1.0, 0.0], probe=0)
    assert list(nested.area_per_atom[1:]) == [0.0, 0.0]
    assert nested.arrangement["buried_atoms"] == 2
    empty = molsurf.areas(centres=np.zeros((0, 3)), radii=np.zeros(0))
    assert empty.area == 0 and empty.volume == 0 and empty.shells == [] and len(empty.area_per_atom) == 0


def test_a_cavity_has_its_volume_centroid_and_lining_atoms():
    # Six spheres of radius 1.7 on the axes, 2 from the origin: neighbours overlap, and each face of the
    # octahedron is closed (its centre is 1.633 from its three spheres), so the void at the centre is a
    # cavity: it holds the ball of radius 0.3 about the origin, and lies within 0.69 of it.
    centres = np.array([[2, 0, 0], [-2, 0, 0], [0, 2, 0], [0, -2, 0], [0, 0, 2], [0, 0, -2]], dtype=float)
    areas = molsurf.areas(centres=centres, radii=np.full(6, 1.7), probe=0)
    outer, cavity = areas.shells
    assert outer.kind == "outer" and cavity.kind == "cavity" and cavity.cavity
    assert np.allclose(cavity.centroid, 0, atol=1e-9)
    assert list(cavity.atoms) == list(range(6)) == list(outer.atoms)
    assert 4 / 3 * math.pi * 0.3 ** 3 < cavity.volume < 4 / 3 * math.pi * 0.69 ** 3
    assert cavity.area > 4 * math.pi * 0.3 ** 2
    # Monte Carlo over the cube around the void: the fraction outside every ball.
    points = np.random.default_rng(7).uniform(-0.7, 0.7, size=(400_000, 3))
    outside = np.all(np.linalg.norm(points[:, None, :] - centres[None], axis=2) > 1.7, axis=1)
    assert cavity.volume == pytest.approx(outside.mean() * 1.4 ** 3, rel=0.02)
    assert areas.volume == pytest.approx(outer.volume - cavity.volume, rel=1e-12)
    assert areas.area == pytest.approx(outer.area + cavity.area, rel=1e-12)
    d = cavity.to_dict()
    assert d["kind"] == "cavity" and d["atoms"] == list(range(6)) and d["mesh_component"] is None
    assert molsurf.areas(centres=centres, radii=np.full(6, 1.7), probe=0, outer_only=True).shells[0].area == outer.area


def test_results_are_read_only_views_that_outlive_their_object(data_dir):
    areas = molsurf.areas(data_dir / "1crn.pdb")
    per_atom = areas.area_per_atom
    expected = np.array(per_atom)
    assert not per_atom.flags.writeable
    with pytest.raises(ValueError):
        per_atom[0] = 1
    del areas
    assert np.array_equal(per_atom, expected)
    assert "molsurf.Areas" in repr(molsurf.areas(data_dir / "1crn.pdb"))


def test_the_gil_is_released_while_computing(data_dir, ticks_during, in_two_threads):
    structure = molsurf.read_structure(data_dir / "2hhb.pdb")
    areas, ticks = ticks_during(lambda: molsurf.areas(structure, threads=1))
    assert areas.area > 0
    assert ticks > 5  # the counter ran while the arrangement was computed
    results = in_two_threads(lambda: molsurf.areas(structure, threads=1))
    assert all(np.array_equal(r.area_per_atom, areas.area_per_atom) for r in results)
