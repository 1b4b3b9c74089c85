"""seaecho's mean-plane sea models against published measurements and empirical models.

References (implemented in ``tests/reference_models.py`` with provenance notes):

* CMOD5.N, C-band VV (Hersbach 2010, ECMWF Tech. Memo. 620);
* the C-band polarisation ratio of Mouche, Hauser, Daloze & Guerin (2005), IEEE TGRS
  43(4), 753-769;
* Nathanson's X-band tables (Radar Design Principles, 2nd ed., 1991) as tabulated by
  Gregers-Hansen & Mital (2012, NRL/MR/5310--12-9346);
* the GIT model (Horst, Dyer & Tuley 1978) and the NRL model (Gregers-Hansen & Mital
  2012).

Monostatic, sigma0 averaged over the four looks upwind, crosswind (2) and downwind
(the references are azimuth averages or are averaged the same way), sea water at 20 degC
and 35 psu, Elfouhaily spectrum, U19.5 from U10 by seaecho.ocean.wind. The tolerances are
what the models reach; the disagreements that remain are asserted as such so that they stay visible.
"""

import numpy as np
import pytest

from reference_models import (
    NATHANSON_XBAND,
    SEA_STATE_WIND,
    cmod5n,
    git_sigma0,
    mouche_pr,
    nrl_sigma0,
)
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.wind import u19_5_from_u10
from seaecho.scattering.models import sea_sigma

LOOKS_DEG = (0.0, 90.0, 180.0, 270.0)  # relative to upwind


def _db(x):
    return 10.0 * np.log10(x)


def _seaecho(model, f_hz, u10, inc_deg):
    """Look-averaged monostatic sigma0 (..., 4) of a seaecho mean-plane model."""
    eps = sea_water_permittivity(f_hz, 20.0, 35.0)
    spec = DirectionalSpectrum(u19_5=float(u19_5_from_u10(u10)))  # wind blows towards +x
    th = np.radians(np.atleast_1d(np.asarray(inc_deg, dtype=float)))[:, None]
    # A look at angle a from upwind: the radar looks towards pi + a (against the wind).
    phi_i = np.pi + np.radians(LOOKS_DEG)[None, :]
    s = sea_sigma(model, th + 0 * phi_i, phi_i, th + 0 * phi_i, phi_i + np.pi, f_hz, spec, eps)
    return s.mean(axis=1)


def test_nrl_reference_implementation():
    """The NRL model reproduces the value of MATLAB's seareflectivity example (Radar
    Toolbox documentation, R2021a): sea state 2, 10 deg, 30 GHz, H: 2.1555e-04."""
    assert 10 ** (nrl_sigma0(30.0, 2, 10.0, "H") / 10) == pytest.approx(2.1555e-4, rel=1e-4)


@pytest.mark.parametrize("u10", [5.0, 10.0, 15.0])
def test_cband_vv_against_cmod5n(u10):
    """C-band VV, incidence 30-50 deg: two-scale + breaking within 2 dB of CMOD5.N
    (measured: 0.1-1.6 dB). At 20 deg the two-scale model is 3-6 dB low (its Kirchhoff
    part is missing in the two-scale sum): kept visible."""
    inc = np.array([30.0, 40.0, 50.0])
    ours = _db(_seaecho("two-scale+breaking", 5.3e9, u10, inc)[:, 3])
    ref = _db(np.mean([cmod5n(u10, p, inc) for p in LOOKS_DEG], axis=0))
    np.testing.assert_array_less(np.abs(ours - ref), 2.0)
    low = _db(_seaecho("two-scale+breaking", 5.3e9, u10, [20.0])[0, 3])
    ref20 = _db(np.mean([cmod5n(u10, p, 20.0) for p in LOOKS_DEG]))
    assert 2.0 < ref20 - low < 7.0


@pytest.mark.parametrize("u10", [5.0, 10.0, 15.0])
def test_cband_polarisation_ratio_against_mouche(u10):
    """VV/HH at 30-50 deg within 2 dB of Mouche et al. (2005) (measured: 0-1.5 dB);
    breaking moves the ratio towards the measurement at 40 deg (1.3-1.9 dB too large
    without it)."""
    inc = np.array([30.0, 40.0, 50.0])
    with_wb = _seaecho("two-scale+breaking", 5.3e9, u10, inc)
    without = _seaecho("two-scale", 5.3e9, u10, inc)
    ref = _db(np.mean([mouche_pr(inc, p) for p in LOOKS_DEG], axis=0))
    pr = _db(with_wb[:, 3] / with_wb[:, 0])
    pr0 = _db(without[:, 3] / without[:, 0])
    np.testing.assert_array_less(np.abs(pr - ref), 2.0)
    assert abs(pr[1] - ref[1]) < abs(pr0[1] - ref[1])


# (sea state, grazing deg) points of Nathanson's 9.3 GHz table at 10 and 30 deg.
NATHANSON_POINTS = [(2, 10.0), (3, 10.0), (4, 10.0), (5, 10.0), (2, 30.0), (3, 30.0),
                    (4, 30.0), (5, 30.0)]


@pytest.mark.parametrize(("ss", "grazing"), NATHANSON_POINTS)
def test_xband_hh_against_nathanson(ss, grazing):
    """X-band HH at 10 and 30 deg grazing: two-scale + breaking within 3 dB of Nathanson's
    table; without breaking HH is 4-14 dB low at 10 deg (the gap breaking fills)."""
    u10 = SEA_STATE_WIND[ss]
    ours = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [90.0 - grazing])[0, 0])
    ref = NATHANSON_XBAND[("H", ss)][grazing]
    assert abs(ours - ref) < 3.0
    if grazing == 10.0:
        regular = _db(_seaecho("two-scale", 9.3e9, u10, [80.0])[0, 0])
        assert ref - regular > 4.0


@pytest.mark.parametrize(("ss", "grazing"), NATHANSON_POINTS)
def test_xband_vv_against_nathanson_known_excess(ss, grazing):
    """X-band VV: seaecho's Bragg part (Elfouhaily spectrum at the X-band Bragg waves) is
    2-7 dB above Nathanson's table at 10-30 deg grazing. Known disagreement, kept
    visible: VV/HH is therefore 8-12 dB where Nathanson gives 4-7 dB."""
    u10 = SEA_STATE_WIND[ss]
    ours = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [90.0 - grazing])[0, 3])
    ref = NATHANSON_XBAND[("V", ss)][grazing]
    assert 1.0 < ours - ref < 8.0


@pytest.mark.parametrize("grazing", [5.0, 10.0, 20.0, 30.0])
@pytest.mark.parametrize("ss", [2, 3, 5])
def test_xband_hh_against_git_and_nrl(ss, grazing):
    """X-band HH, 5-30 deg grazing: within 4 dB of both GIT (look-averaged, wind U10) and
    the NRL model (sea state)."""
    u10 = SEA_STATE_WIND[ss]
    ours = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [90.0 - grazing])[0, 0])
    git = np.mean([git_sigma0(9.3, u10, grazing, "H", p) for p in LOOKS_DEG])
    assert abs(ours - git) < 4.0
    assert abs(ours - nrl_sigma0(9.3, ss, grazing, "H")) < 4.0
