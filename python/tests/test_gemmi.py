"""A gemmi.Structure (Debian's python3-gemmi) is handed over without a file: it gives the same
atoms and the same surface as its file, under the same selection keywords."""
import numpy as np
import pytest

import molsurf

gemmi = pytest.importorskip("gemmi")


def test_gemmi_structure_gives_the_same_surface_as_its_file(crambin, data_dir):
    st = gemmi.read_structure(str(data_dir / "1crn.pdb"))
    from_gemmi = molsurf.surface(st)
    assert np.array_equal(from_gemmi.vertices, crambin.vertices)
    assert np.array_equal(from_gemmi.faces, crambin.faces)
    assert np.array_equal(from_gemmi.atom_of_face, crambin.atom_of_face)
    assert from_gemmi.area == crambin.area and from_gemmi.volume == crambin.volume
    assert np.array_equal(from_gemmi.area_per_atom, crambin.area_per_atom)
    assert np.array_equal(from_gemmi.structure.radii, crambin.structure.radii)
    assert from_gemmi.facet_area == crambin.facet_area
    areas = molsurf.areas(st)
    assert areas.area == crambin.area and np.array_equal(areas.area_per_atom, crambin.area_per_atom)


def test_selection_keywords_apply_to_a_gemmi_structure(data_dir):
    path = data_dir / "1j8k.cif"
    st = gemmi.read_structure(str(path))
    for options in ({"model": 3, "hydrogens": True}, {"model": 20}, {"chains": "A", "hetatm": False}):
        from_file = molsurf.read_structure(path, **options)
        from_gemmi = molsurf.read_structure(st, **options)
        assert len(from_gemmi) == len(from_file)
        assert np.array_equal(from_gemmi.centres, from_file.centres)
        assert np.array_equal(from_gemmi.radii, from_file.radii)
        assert list(from_gemmi.atom_names) == list(from_file.atom_names)
        assert from_gemmi.report["model_used"] == from_file.report["model_used"]
        assert from_gemmi.report["dropped_hydrogen"] == from_file.report["dropped_hydrogen"]
    surface = molsurf.surface(st, model=3)
    assert surface.structure.report["model_used"] == 3
    areas = molsurf.areas(st, model=3)
    assert areas.structure.report["model_used"] == 3 and areas.area == surface.area
    assert np.array_equal(surface.vertices, molsurf.surface(path, model=3).vertices)
    # Coordinates are those gemmi holds: move an atom in memory, and the surface follows.
    st[2][0][0][0].pos = gemmi.Position(100.0, 100.0, 100.0)
    assert molsurf.surface(st, model=3).area > surface.area
    with pytest.raises(molsurf.Error, match="model 42 not found"):
        molsurf.surface(st, model=42)


def test_gemmi_atoms_equal_the_readers(data_dir):
    st = gemmi.read_structure(str(data_dir / "1crn.pdb"))
    structure = molsurf.read_structure(data_dir / "1crn.pdb")
    positions = np.array([[a.pos.x, a.pos.y, a.pos.z] for r in st[0][0] for a in r])
    assert np.array_equal(structure.centres, positions)
