"""The solvent-excluded surface from Python: surface(..., surface='ses')."""
import math

import numpy as np
import pytest

import molsurf


def test_one_atom_ses_is_its_van_der_waals_sphere():
    s = molsurf.surface(centres=np.array([[0.0, 0.0, 0.0]]), radii=np.array([1.7]), surface="ses")
    assert s.check.valid
    assert abs(s.area - 4 * math.pi * 1.7**2) / (4 * math.pi * 1.7**2) < 0.005
    # No exact SES values yet: area is the facets'.
    assert s.area == s.facet_area


def test_ses_lies_between_vdw_and_sas(tmp_path):
    centres = np.array([[0.0, 0.0, 0.0], [3.5, 0.0, 0.0], [1.7, 2.9, 0.0]])
    radii = np.array([1.7, 1.5, 1.6])
    vdw = molsurf.surface(centres=centres, radii=radii, surface="vdw")
    ses = molsurf.surface(centres=centres, radii=radii, surface="ses")
    sas = molsurf.surface(centres=centres, radii=radii)
    assert vdw.facet_volume < ses.facet_volume < sas.facet_volume
    assert sum(ses.area_per_atom) == pytest.approx(ses.area, rel=1e-9)
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
