"""Sea-clutter Doppler centroids against published measurement-derived Doppler model
functions (docs/dynamics.md, "Against measurements: moderate incidence";
``examples/xband_doppler_measured.py --gmf`` and ``--breaking``).

References (``tests/validation/doppler_references.py``, where the provenance is given):

* CDOP: Mouche, A. A. et al. (2012). On the use of Doppler shift for sea surface wind
  retrieval from SAR. *IEEE Trans. Geosci. Remote Sens.* 50(7), 2901-2909: the C-band
  (5.5 GHz) geophysical Doppler of ENVISAT ASAR, VV and HH, 17-42 deg incidence.
* Elyouncha, A., Eriksson, L. E. B. et al. (2021). Empirical relationship between the
  Doppler centroid derived from X-band spaceborne InSAR data and wind vectors. *IEEE
  Trans. Geosci. Remote Sens.*: TanDEM-X, the wind sea's Doppler velocity is "about 15%
  of the radial wind speed" (horizontal), the Bragg waves' part "~0.2 m/s", agreement
  with other models "within 0.2 m/s", ``|DC_VV| - |DC_HH| < 0``.
* Hwang, P. A., Sletten, M. A. and Toporkov, J. V. (2008). Breaking wave contribution to
  low grazing angle radar backscatter from the ocean surface. *J. Geophys. Res.* 113,
  C09017: X band, winds 7-15 m/s, grazing 1.4-5.5 deg: breaking makes the Doppler
  velocity of both polarisations "about 50% faster".

Tolerance: 0.2 m/s of horizontal surface velocity, the published spread between the X-band
GMF and the other models and data sets (Elyouncha et al.), i.e. 4.2 Hz at 5.5 GHz and
7.7 Hz at 10 GHz at 35 deg incidence, plus two standard deviations of the simulation's
own realisations (three seeds of a 128 m tile for 0.19 s each; in the quick test, two
standard errors of the mean over eight seeds of a 64 m tile).

Known disagreements, kept visible (strict xfails; docs/dynamics.md gives the numbers): on
the default sea (Longuet-Higgins spreading) with the default surface drift (3 % of U10
where the sea evolves: AMS Glossary of Meteorology; Wu 1975), 17 of the 20
moderate-incidence comparisons agree (14 without the drift); VV at C band and 5 m/s is
0.64 of CDOP, HH at C band and 12 m/s 1.31 of it and VV at X band downwind 0.75 of the
published value (no hydrodynamic modulation of the short waves by the long ones; the
sub-facet waves' tilt uncorrelated with their orbital velocity); the Bragg line alone
(what a centro-symmetric spreading leaves) is a quarter
of CDOP. At low grazing the breaking
zones speed the HH centroid up 3.0-3.5x for the measured ~1.5x (VV: 1.5x, as measured),
while they move as the published model's breakers do (Hansen et al. 2012 eqs 5 and 19).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))
sys.path.insert(0, str(ROOT / "tests" / "validation"))

from doppler_references import (  # noqa: E402
    CDOP_FREQUENCY_HZ,
    XBAND_BRAGG_SPEED_M_S,
    XBAND_GMF_SPREAD_M_S,
    cdop_hz,
)

from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.ocean.wind import u10_from_u19_5  # noqa: E402
from seaecho.scattering.dynamics import bragg_frequency, travel_fraction  # noqa: E402

INC_DEG = 35.0


def _tol_hz(freq_hz: float, inc_deg: float = INC_DEG) -> float:
    """The published 0.2 m/s (horizontal) as a Doppler shift [Hz]."""
    return XBAND_GMF_SPREAD_M_S * 2.0 * np.sin(np.radians(inc_deg)) / (C0 / freq_hz)


def _bragg_centroid_hz(freq_hz: float, inc_deg: float, look_deg: float, u19_5: float,
                       spreading: str = "longuet-higgins") -> float:
    """The composite model's Bragg centroid (2 p+ - 1) f_B [Hz] (eq D3; Thompson 1989)."""
    k_b = 2.0 * (2.0 * np.pi * freq_hz / C0) * np.sin(np.radians(inc_deg))
    # the radar looks along -x from the east when it looks upwind (wind towards +x): the
    # Bragg waves that approach it travel along +x
    az = np.radians(look_deg)
    spec = DirectionalSpectrum("elfouhaily", spreading, u19_5)
    p = float(travel_fraction(spec, k_b * np.cos(az), k_b * np.sin(az),
                              float(u10_from_u19_5(u19_5))))
    return (2.0 * p - 1.0) * float(bragg_frequency(k_b))


# --- fast: the composite model's Doppler (the physics) against the published values ---

def test_bragg_phase_speed_is_the_tandem_x_bragg_contribution():
    # Elyouncha et al.: the Bragg waves contribute "~0.2 m/s" to the X-band Doppler
    # velocity over TanDEM-X's incidences (about 20-45 deg); seaecho's Bragg line
    # (eq D1, the dispersion relation with surface tension) at 10 GHz
    for inc in (20.0, 30.0, 45.0):
        k_b = 2.0 * (2.0 * np.pi * 10e9 / C0) * np.sin(np.radians(inc))
        c_b = 2.0 * np.pi * float(bragg_frequency(k_b)) / k_b  # horizontal phase speed
        assert c_b == pytest.approx(XBAND_BRAGG_SPEED_M_S, abs=0.1)


def test_composite_bragg_centroid_against_cdop_crosswind_and_sign():
    u19_5 = 8.0
    u10 = float(u10_from_u19_5(u19_5))
    tol = _tol_hz(CDOP_FREQUENCY_HZ)
    up, cross, down = (_bragg_centroid_hz(CDOP_FREQUENCY_HZ, INC_DEG, look, u19_5)
                       for look in (0.0, 90.0, 180.0))
    for pol in ("VV", "HH"):
        c_up, c_cross, c_down = (float(cdop_hz(INC_DEG, u10, look, pol))
                                 for look in (0.0, 90.0, 180.0))
        # crosswind: no mean Doppler, within the published spread (CDOP: +1.0 VV,
        # -1.6 HH Hz; the Bragg waves run both ways equally)
        assert abs(cross - c_cross) < tol
        # the sign follows the wind's component along the look
        assert up > 0 < c_up and down < 0 > c_down
    # the Bragg line alone is 0.24-0.40 of CDOP upwind and downwind (6.1 Hz against
    # 15-26 Hz at U10 = 7.6 m/s): the wave Doppler dominates (Elyouncha et al.), and a
    # model without it (the centro-symmetric spreading) falls short (docs/dynamics.md)
    assert 0.2 < up / float(cdop_hz(INC_DEG, u10, 0.0, "VV")) < 0.4


@pytest.mark.xfail(strict=True, reason="no hydrodynamic modulation, wind drift or sub-facet "
                   "tilt-velocity correlation: the Bragg line is a quarter of CDOP upwind "
                   "(docs/dynamics.md)")
def test_composite_bragg_centroid_within_published_spread_of_cdop_upwind():
    u19_5 = 8.0
    u10 = float(u10_from_u19_5(u19_5))
    up = _bragg_centroid_hz(CDOP_FREQUENCY_HZ, INC_DEG, 0.0, u19_5)
    assert abs(up - float(cdop_hz(INC_DEG, u10, 0.0, "VV"))) < _tol_hz(CDOP_FREQUENCY_HZ)


# --- fast: the full simulation, one small case ------------------------------------------

#: the quick case (``xband_doppler_measured.QUICK_*``): X band, 8 m/s upwind, 35 deg
#: incidence, a 64 m tile over 24 pulses (0.048 s at 500 Hz, three geometry updates), the
#: centroid averaged over seeds 1-8. Its scatter is the sea's realisation, not the CPI's:
#: over seeds 1-16 the HH centroid has mean 49.2 Hz and sd 6.87 Hz with 24 pulses, 49.6
#: and 7.02 Hz with 48 (the version before: one seed), VV 37.6 and 5.18 / 5.14 Hz
#: (``examples/xband_doppler_measured.py --quick-spread``); so half the pulses per seed buy
#: twice the seeds for the same CPU time without moving the centroid.
QUICK_SEEDS = tuple(range(1, 9))
#: sd of one seed's centroid [Hz] (seeds 1-16 of the quick case, above)
QUICK_SD_HH_HZ = 6.87
QUICK_SD_VV_HZ = 5.18
#: standard error of the mean over the quick seeds [Hz]: sd / sqrt(8) = 2.43 (HH), 1.83
#: (VV); the allowance adds two of them to the published spread (7.7 Hz): 12.6 Hz (HH),
#: 11.4 Hz (VV), where one seed needed 13 + 7.7 = 20.7 Hz
QUICK_SE_HH_HZ = QUICK_SD_HH_HZ / np.sqrt(len(QUICK_SEEDS))
QUICK_SE_VV_HZ = QUICK_SD_VV_HZ / np.sqrt(len(QUICK_SEEDS))


def test_xband_upwind_centroids_against_tandem_x_quick():
    from xband_doppler_measured import (
        QUICK_N,
        QUICK_N_PULSES,
        QUICK_SIZE_M,
        QUICK_U19_5_M_S,
        F,
        published_centroids_hz,
        simulate,
    )

    u10 = float(u10_from_u19_5(QUICK_U19_5_M_S))
    sims = [simulate(QUICK_U19_5_M_S, 90.0 - INC_DEG, QUICK_N_PULSES, QUICK_SIZE_M, QUICK_N,
                     0.0, seed, F) for seed in QUICK_SEEDS]
    ref = published_centroids_hz("X", u10, 0.0, INC_DEG)[0]  # 43.4 Hz (1.13 m/s)
    hh = np.array([s["centroid_hh_hz"] for s in sims])
    vv = np.array([s["centroid_vv_hz"] for s in sims])
    # the seeds scatter as measured (else the standard errors below do not hold): a
    # sample sd of 8 draws exceeds 1.9 sd with probability below 1e-3 (chi-square, 7 dof)
    assert np.std(hh, ddof=1) < 1.9 * QUICK_SD_HH_HZ
    assert np.std(vv, ddof=1) < 1.9 * QUICK_SD_VV_HZ
    # HH and VV within the published spread (0.2 m/s: 7.7 Hz) plus two standard errors of
    # the mean over the seeds (seeds 1-8: HH 49.55, VV 38.0 Hz for 43.4)
    assert abs(hh.mean() - ref) < _tol_hz(F) + 2.0 * QUICK_SE_HH_HZ
    assert abs(vv.mean() - ref) < _tol_hz(F) + 2.0 * QUICK_SE_VV_HZ
    # |DC_VV| < |DC_HH| (Elyouncha et al.: the polarisation difference is negative)
    assert hh.mean() > vv.mean()
    # VV above the Bragg line (the wave Doppler dominates)
    assert vv.mean() > sims[0]["bragg_centroid_hz"]


# --- slow: the comparison of docs/dynamics.md --------------------------------------------

@pytest.fixture(scope="module")
def gmf_rows(tmp_path_factory):
    import csv

    from xband_doppler_measured import GMF_CASES, gmf_comparison

    path = gmf_comparison(str(tmp_path_factory.mktemp("gmf")), cases=GMF_CASES[:5])
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    for r in rows:
        for k, v in r.items():
            if k not in ("band", "spreading"):
                r[k] = float(v)
    return rows


#: (band, U19.5, look, channel) where the simulated centroid falls short of the published
#: one by more than the tolerance (docs/dynamics.md): VV at C band and 5 m/s upwind (with
#: the default surface drift; six cases before it) and VV at X band downwind (0.75 of the
#: published value, 0.9 Hz outside since the breakers ride on the long waves only, eq
#: BR10; 0.4 Hz inside before), and where it exceeds it: HH at C band and 12 m/s upwind
SHORT = {("C", 5.0, 0.0, "vv"), ("X", 8.0, 180.0, "vv")}
OVER = {("C", 12.0, 0.0, "hh")}


def _allowed_hz(r, ch):
    return _tol_hz(r["frequency_hz"], r["incidence_deg"]) + 2.0 * r[f"centroid_{ch}_std_hz"]


@pytest.mark.slow
def test_moderate_incidence_centroids_against_cdop_and_tandem_x(gmf_rows):
    for r in gmf_rows:
        key = (r["band"], r["u19_5_m_s"], r["look_deg"])
        for ch in ("vv", "hh"):
            sim, ref = r[f"centroid_{ch}_hz"], r[f"published_{ch}_hz"]
            if key + (ch,) in SHORT:
                # the known shortfall: between the Bragg line plus drift and the published
                # value, at least a third of the latter
                assert abs(r["bragg_centroid_hz"]) < abs(sim) < abs(ref)
                assert abs(sim) > abs(ref) / 3.0
            elif key + (ch,) in OVER:
                # the known excess: above the published value, below 1.5 times it
                assert abs(ref) < abs(sim) < 1.5 * abs(ref)
            else:
                assert abs(sim - ref) < _allowed_hz(r, ch), (key, ch, sim, ref)
        if r["look_deg"] != 90.0:
            # |DC_VV| < |DC_HH| (CDOP; Elyouncha et al.)
            assert abs(r["centroid_hh_hz"]) > abs(r["centroid_vv_hz"])


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="no hydrodynamic modulation: VV at C band and 5 m/s "
                   "is 0.65 of CDOP; HH at C band and 12 m/s 1.33 of it (docs/dynamics.md)")
def test_moderate_incidence_centroids_all_within_published_spread(gmf_rows):
    for r in gmf_rows:
        for ch in ("vv", "hh"):
            assert abs(r[f"centroid_{ch}_hz"] - r[f"published_{ch}_hz"]) < _allowed_hz(r, ch)


@pytest.fixture(scope="module")
def breaking_rows(tmp_path_factory):
    import csv

    from xband_doppler_measured import breaking_comparison

    path = breaking_comparison(str(tmp_path_factory.mktemp("breaking")))
    with open(path) as fh:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(fh)]


@pytest.mark.slow
def test_breaking_speeds_up_both_polarisations_at_low_grazing(breaking_rows):
    # Hwang et al. (2008): breaking increases "significantly the Doppler velocity of both
    # polarizations"
    for r in breaking_rows:
        assert r["ratio_vv"] > 1.2 and r["ratio_hh"] > 1.2
        assert r["centroid_hh_breaking_hz"] > r["centroid_vv_breaking_hz"]


@pytest.mark.slow
def test_breaking_speeds_vv_up_about_fifty_percent(breaking_rows):
    # "about 50% faster": read here as 1.25-1.75 (the abstract gives no scatter); with the
    # default surface drift and the breakers' mean velocity VV gives 1.55-1.56
    for r in breaking_rows:
        assert 1.25 < r["ratio_vv"] < 1.75


@pytest.mark.slow
def test_breaking_zones_move_at_the_fronts_velocity_plus_the_long_waves_orbital(
        breaking_rows):
    # HH at 3 deg grazing is the breaking zones' (docs/scattering.md: +17 dB over the
    # regular surface), so its centroid is their Doppler (eq BR10): the fronts' mean
    # velocity relative to the water (Hansen et al. 2012 eq 19), plus the mean orbital
    # velocity where the zones sit of the long waves (k < k_wb / 10; eq BR8, closed form
    # on a Gaussian sea, the zones placed on the 1 m grid's crests), plus the surface
    # drift: 1.84 and 2.18 m/s at U10 = 7.6 and 11.3 m/s (measured 1.86 and 2.23). For
    # comparison (docs/dynamics.md): K05's linear modulation (BR9) gives 1.68 and 2.02,
    # and Hwang, Sletten & Toporkov (2008, C02003) measured X-band sea spikes at low
    # grazing moving at 2.0-2.6 m/s for winds of 7-14.5 m/s.
    from xband_doppler_measured import F

    from seaecho.ocean.wind import SURFACE_DRIFT_OVER_U10
    from seaecho.scattering.breaking import (
        breaking_statistics,
        modulating_wavenumber_limit,
        placement_orbital_velocity,
    )

    k_r = 2.0 * np.pi * F / C0
    for r in breaking_rows:
        u10 = float(u10_from_u19_5(r["u19_5_m_s"]))
        st = breaking_statistics(u10, k_r)
        spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", r["u19_5_m_s"])
        k_grid = np.pi / 1.0  # the comparison's 1 m grid
        orbital = placement_orbital_velocity(spec, st.q, k_grid, 0.0,
                                             k_velocity=modulating_wavenumber_limit(st.k_wb))
        budget = st.mean_velocity + orbital + SURFACE_DRIFT_OVER_U10 * u10
        grazing = np.radians(r["grazing_deg"])
        v_hh = C0 / F * r["centroid_hh_breaking_hz"] / 2.0 / np.cos(grazing)
        assert v_hh == pytest.approx(budget, rel=0.06)


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="the breaking zones move as the published model's "
                   "(Hansen et al. 2012 eqs 5 and 19; 1.9-2.2 m/s, near the 2.0-2.6 m/s of "
                   "sea spikes measured by Hwang et al. 2008), but the simulated HH without "
                   "breaking is the Bragg line, drift and tilt alone (0.5-0.7 m/s): HH "
                   "speeds up 3.0-3.5x (3.52, 2.99) for the measured ~1.5x "
                   "(docs/dynamics.md)")
def test_breaking_speeds_hh_up_about_fifty_percent(breaking_rows):
    for r in breaking_rows:
        assert 1.25 < r["ratio_hh"] < 1.75
