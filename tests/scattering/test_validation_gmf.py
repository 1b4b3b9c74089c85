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
and 35 psu, Elfouhaily spectrum (the tests near the end: the Romeiser, Alpers & Wismann
1997 spectrum; at the end: the sea a scene gets by default, the Kudryavtsev et al. 2003
spectrum), U19.5 from U10 by seaecho.ocean.wind. The tolerances are
what the models reach; the disagreements that remain are asserted as such so that they stay visible.
"""

import functools

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
from seaecho.build import sea_spectrum
from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.geometry.shadowing import smith_lambda, smith_nu
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.twoscale import TWO_SCALE_CUT_RATIO, slope_variances
from seaecho.ocean.wind import u19_5_from_u10
from seaecho.scattering.models import sea_sigma
from seaecho.scattering.validity import SPMValidityWarning

LOOKS_DEG = (0.0, 90.0, 180.0, 270.0)  # relative to upwind


def _db(x):
    return 10.0 * np.log10(x)


def _seaecho(model, f_hz, u10, inc_deg, cut_ratio=TWO_SCALE_CUT_RATIO, spectrum="elfouhaily"):
    """Look-averaged monostatic sigma0 (..., 4) of a seaecho mean-plane model."""
    eps = sea_water_permittivity(f_hz, 20.0, 35.0)
    spec = DirectionalSpectrum(spectrum=spectrum,  # wind blows towards +x
                               u19_5=float(u19_5_from_u10(u10)))
    th = np.radians(np.atleast_1d(np.asarray(inc_deg, dtype=float)))[:, None]
    # A look at angle a from upwind: the radar looks towards pi + a (against the wind).
    phi_i = np.pi + np.radians(LOOKS_DEG)[None, :]
    s = sea_sigma(model, th + 0 * phi_i, phi_i, th + 0 * phi_i, phi_i + np.pi, f_hz, spec, eps,
                  cut_ratio=cut_ratio)
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
    visible: VV/HH is therefore 8-12 dB where Nathanson gives 4-7 dB. What causes it is
    examined by the two tests below and in docs/scattering.md ("X-band VV: diagnosis"):
    it is the E97 spectrum's level at the X-band Bragg waves; with the RAW97 spectrum VV
    is within 0.6 dB of the published models (tests at the end of this file). E97 was the
    default spectrum; the default is now K03, whose values
    ``test_default_sea_xband_against_published_models`` holds."""
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


# --- X-band VV: diagnosis of the excess over Nathanson's table ----------------------------

DIAGNOSIS_POINTS = [(2, 10.0), (3, 10.0), (5, 10.0), (2, 30.0), (3, 30.0), (5, 30.0)]


@pytest.mark.parametrize(("ss", "grazing"), DIAGNOSIS_POINTS)
def test_xband_vv_excess_lies_in_the_bragg_part(ss, grazing):
    """Where the X-band VV excess over Nathanson's table comes from (docs/scattering.md,
    "X-band VV: diagnosis"), at 10 and 30 deg grazing:

    * the two-scale (Bragg) part alone already exceeds the table (measured 2.2-7.5 dB);
      the breaking zones add less than 0.7 dB to VV (measured 0.04-0.55 dB), as
      KHCC03's non-polarised sigma_wb q must where Bragg VV is 10-20 dB above HH;
    * the scale split is not the cause: cutting at k/4, the d = 1/4 of Kudryavtsev et al.
      (2005), instead of k/3 moves VV by less than 0.2 dB (measured <= 0.1 dB);
    * the tilt average is not the cause: the untilted SPM is within 1.2 dB of the two-scale
      model (measured 0.2-0.9 dB);
    * the missing shadowing of the mean-plane models is not the cause: Smith's (1967)
      factor 1 / (1 + Lambda) for the slopes of K < k/3 is above -0.3 dB at 10 deg in
      every look (measured -0.06 to -0.15 dB; it is -1.5 to -2 dB at 3 deg).

    A mistake that made breaking polarised, or the tilt average or the split wrong, breaks
    these bounds."""
    u10 = SEA_STATE_WIND[ss]
    inc = 90.0 - grazing
    two_scale = _db(_seaecho("two-scale", 9.3e9, u10, [inc])[0, 3])
    with_breaking = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [inc])[0, 3])
    quarter = _db(_seaecho("two-scale", 9.3e9, u10, [inc], cut_ratio=0.25)[0, 3])
    with pytest.warns(SPMValidityWarning):  # the whole sea is no small perturbation
        flat = _db(_seaecho("spm", 9.3e9, u10, [inc])[0, 3])
    assert two_scale - NATHANSON_XBAND[("V", ss)][grazing] > 1.5
    assert 0.0 <= with_breaking - two_scale < 0.7
    assert abs(quarter - two_scale) < 0.2
    assert abs(flat - two_scale) < 1.2
    spec = DirectionalSpectrum(u19_5=float(u19_5_from_u10(u10)))
    k = 2.0 * np.pi * 9.3e9 / C0
    mss_u, mss_c = slope_variances(spec, 0.0, TWO_SCALE_CUT_RATIO * k)
    look = np.radians(LOOKS_DEG)
    rms = np.sqrt(mss_u * np.cos(look) ** 2 + mss_c * np.sin(look) ** 2)
    shadow_db = -10.0 * np.log10(1.0 + smith_lambda(smith_nu(np.radians(inc), rms)))
    assert np.all(shadow_db > (-0.3 if grazing == 10.0 else -0.01))


@pytest.mark.parametrize("ss", [2, 3, 4, 5])
def test_nathanson_vv_at_30_deg_grazing_lies_below_cmod5n(ss):
    """Nathanson's 9.3 GHz VV at 30 deg grazing (60 deg incidence) against CMOD5.N at
    58 deg, the edge of its validity (Hersbach 2010), for the winds of the sea states:

    * the two references disagree: Nathanson is 3-6.5 dB below CMOD5.N (measured
      3.4-5.8 dB);
    * seaecho at C band, 58 deg, is within 2 dB of CMOD5.N (measured 0.2-1.7 dB above),
      the tolerance of the 30-50 deg comparison;
    * seaecho's VV at 60 deg hardly depends on the frequency between 5.3 and 9.3 GHz
      (X band minus C band within 0.5 dB, measured 0 to +0.3 dB): the Elfouhaily
      saturation spectrum is nearly flat between the two Bragg wavenumbers, 188 and
      338 rad/m (ratio 1.12-1.18).

    So at 30 deg grazing most of seaecho's 5-7.5 dB excess over Nathanson is the
    disagreement of Nathanson with CMOD5.N; for both references to hold, the saturation
    spectrum would have to fall by a factor of about 2-4 between 188 and 338 rad/m."""
    u10 = SEA_STATE_WIND[ss]
    cmod = _db(np.mean([cmod5n(u10, p, 58.0) for p in LOOKS_DEG]))
    nathanson = NATHANSON_XBAND[("V", ss)][30.0]
    assert 3.0 < cmod - nathanson < 6.5
    c_band = _db(_seaecho("two-scale+breaking", 5.3e9, u10, [58.0])[0, 3])
    x_band = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [60.0])[0, 3])
    assert abs(c_band - cmod) < 2.0
    assert abs(x_band - c_band) < 0.5


# --- X band with the Romeiser, Alpers & Wismann (1997) spectrum -------------------------

XBAND_GRAZING_DEG = (5.0, 10.0, 20.0, 30.0)
XBAND_POINTS = [(ss, g) for ss in (2, 3, 4, 5) for g in XBAND_GRAZING_DEG]


def _xband_references(ss, grazing):
    """{model: (HH, VV)} [dB] of the published X-band models (9.3 GHz): GIT (look-averaged,
    wind U10), NRL (sea state) and Nathanson's table where it has the grazing angle."""
    u10 = SEA_STATE_WIND[ss]
    out = {"GIT": tuple(np.mean([git_sigma0(9.3, u10, grazing, p, a) for a in LOOKS_DEG])
                        for p in "HV"),
           "NRL": tuple(float(nrl_sigma0(9.3, ss, grazing, p)) for p in "HV")}
    if grazing in NATHANSON_XBAND[("H", ss)]:
        out["Nathanson"] = tuple(NATHANSON_XBAND[(p, ss)][grazing] for p in "HV")
    return out


def _outside(value, refs):
    """How far [dB] ``value`` lies outside the span of the published values (0 inside)."""
    return max(min(refs) - value, value - max(refs), 0.0)


@pytest.mark.parametrize(("ss", "grazing"), XBAND_POINTS)
def test_xband_levels_with_raw97_against_published_models(ss, grazing):
    """X band, 5-30 deg grazing, sea states 2-5, two-scale + breaking with the RAW97
    spectrum: HH and VV within 3 dB of the span of the published models (GIT, NRL,
    Nathanson; measured: HH 0-2.9 dB outside it, VV 0-0.5 dB). With the Elfouhaily
    spectrum VV lies 2.8-6.4 dB above that span (the excess of the tests above); RAW97
    removes it."""
    refs = _xband_references(ss, grazing)
    ours = _db(_seaecho("two-scale+breaking", 9.3e9, SEA_STATE_WIND[ss], [90.0 - grazing],
                        spectrum="romeiser")[0])
    assert _outside(ours[0], [hh for hh, _ in refs.values()]) < 3.0
    assert _outside(ours[3], [vv for _, vv in refs.values()]) < 3.0


@pytest.mark.parametrize(("ss", "grazing"), XBAND_POINTS)
def test_xband_polarisation_ratio_with_raw97(ss, grazing):
    """X-band VV/HH with RAW97 against the published models' VV/HH (GIT, NRL, Nathanson):

    * at 5-10 deg grazing within 2 dB of their span (measured 0-1.6 dB outside; E97:
      3.1-5.8 dB above);
    * at 20-30 deg, a known remaining disagreement, kept visible: VV/HH is 0-4.8 dB
      above their span (4 of the 8 points more than 2 dB: sea state 2 at 20 and 30 deg,
      3 at 20, 4 at 30; E97: 2.7-7.2 dB), because the two-scale Bragg HH at 60-70 deg incidence is
      11-17 dB below VV with either spectrum and the breaking zones' HH (KHCC03) does not
      fill the gap there (docs/scattering.md);
    * everywhere RAW97's ratio is closer to the references than E97's."""
    refs = _xband_references(ss, grazing)
    u10 = SEA_STATE_WIND[ss]
    ratios = [vv - hh for hh, vv in refs.values()]
    new = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [90.0 - grazing],
                       spectrum="romeiser")[0])
    old = _db(_seaecho("two-scale+breaking", 9.3e9, u10, [90.0 - grazing])[0])
    pr_new, pr_old = new[3] - new[0], old[3] - old[0]
    if grazing <= 10.0:
        assert _outside(pr_new, ratios) < 2.0
    else:
        assert pr_new - max(ratios) < 5.0
    assert _outside(pr_new, ratios) < _outside(pr_old, ratios)


@pytest.mark.parametrize("u10", [5.0, 10.0, 15.0])
def test_cband_with_raw97_within_the_cband_tolerances(u10):
    """C band with RAW97, 30-50 deg incidence: VV within 2 dB of CMOD5.N (measured
    0-1.9 dB) and VV/HH within 2 dB of Mouche et al. (2005) (measured 0.3-2.01 dB; E97:
    0-1.5 dB): the tolerances of the E97 tests above, with the ratio 0.4-0.6 dB further
    from Mouche's than E97's. One point misses by 0.01 dB and is held to 2.05 dB so that
    the miss stays visible: 5 m/s, 40 deg, 2.01 dB since the breaking model's friction
    velocity takes von Karman's 0.41 (1.99 dB with 0.40). At 20 deg VV is 1-2 dB closer to
    CMOD5.N than E97's."""
    inc = np.array([20.0, 30.0, 40.0, 50.0])
    ours = _seaecho("two-scale+breaking", 5.3e9, u10, inc, spectrum="romeiser")
    e97 = _seaecho("two-scale+breaking", 5.3e9, u10, inc)
    cmod = _db(np.mean([cmod5n(u10, p, inc) for p in LOOKS_DEG], axis=0))
    pr = _db(np.mean([mouche_pr(inc, p) for p in LOOKS_DEG], axis=0))
    np.testing.assert_array_less(np.abs(_db(ours[1:, 3]) - cmod[1:]), 2.0)
    bound = np.array([2.0, 2.05 if u10 == 5.0 else 2.0, 2.0])  # 30, 40, 50 deg
    np.testing.assert_array_less(np.abs(_db(ours[1:, 3] / ours[1:, 0]) - pr[1:]), bound)
    assert abs(_db(ours[0, 3]) - cmod[0]) < abs(_db(e97[0, 3]) - cmod[0])


# --- X band, 5-30 deg: the non-polarised part the published models imply --------------

@pytest.mark.parametrize("ss", [2, 3, 4, 5])
def test_xband_non_polarised_part_implied_by_the_published_models(ss):
    """Where the VV/HH excess of the RAW97 tests above lies (docs/scattering.md, "X-band
    VV/HH at 20-30 deg: the non-polarised part"). The dual co-polarised decomposition
    (eq CP3, Kudryavtsev et al. 2013) of each published model's (HH, VV) with seaecho's
    look-averaged two-scale Bragg ratio HH/VV (RAW97) gives the non-polarised part NP
    that model implies; KHCC03's is ``q sigma_wb``:

    * at 5-10 deg grazing the implied NP lies within 3 dB of KHCC03's for every model
      (measured -2.6 to +2.8 dB): the breaking term is right there;
    * at 30 deg grazing every model implies more NP than KHCC03 gives (measured +1.1 to
      +9.5 dB over sea states 2-5; +3.8 to +9.5 at sea state 2): a known remaining
      disagreement, kept visible. KHCC03's sigma_wb is flat from 60 to 90 deg incidence
      (its front term eps_wb / s_wb^2), the implied NP grows by 1.0-7.1 dB from 10 to
      30 deg grazing;
    * the spectrum cannot remove it: the Bragg ratio HH/VV of E97 and RAW97 differ by
      less than 1 dB at 30 deg (measured 0.5-0.6 dB), while VV with RAW97 is already
      within 0.6 dB of the models."""
    from seaecho.constants import C0
    from seaecho.scattering.breaking import breaking_nrcs_monostatic, breaking_statistics
    from seaecho.scattering.copol import non_polarised_component

    u10 = SEA_STATE_WIND[ss]
    grazing = np.array([5.0, 10.0, 30.0])
    raw = _seaecho("two-scale", 9.3e9, u10, 90.0 - grazing, spectrum="romeiser")
    e97 = _seaecho("two-scale", 9.3e9, u10, [60.0])[0]
    ratio = raw[:, 0] / raw[:, 3]
    khcc = _db(breaking_statistics(u10, 2.0 * np.pi * 9.3e9 / C0).q
               * breaking_nrcs_monostatic(np.radians(90.0 - grazing)))
    for j, g in enumerate(grazing):
        gaps = []
        for hh, vv in _xband_references(ss, g).values():
            npc, _ = non_polarised_component(10 ** (vv / 10), 10 ** (hh / 10), ratio[j])
            gaps.append(_db(npc) - khcc[j])
        if g <= 10.0:
            assert max(abs(x) for x in gaps) < 3.0
        else:
            assert min(gaps) > (3.0 if ss == 2 else 0.5)
    assert abs(_db(ratio[2]) - _db(e97[0] / e97[3])) < 1.0


def test_xband_breaking_nrcs_implied_by_the_published_models():
    """What a missing non-polarised term would have to supply (docs/scattering.md, "What
    the published models ask of the non-polarised term"). Dividing the non-polarised part
    each published model implies (eq CP3, Kudryavtsev et al. 2013; RAW97 two-scale Bragg
    ratio) by KHCC03's breaking fraction ``q`` (eq BR3) gives the breaking-zone NRCS that
    model implies, beside KHCC03's ``sigma_0wb`` (eq BR2):

    * KHCC03's ``sigma_0wb`` is flat from 60 to 85 deg incidence (its front term
      ``eps_wb / s_wb^2``, -15.8 dB; the geometric-optics term is below -45 dB there);
    * GIT's implied ``sigma_wb`` agrees across sea states 2-5 within 2.5 dB at every
      grazing angle (measured 1.7-2.2 dB) and rises by 1.5-3.5 dB from 5 to 30 deg
      grazing at every sea state (measured +2.3 to +2.6 dB): what GIT asks for scales
      with ``q``, i.e. is a breaking-zone NRCS rising towards 60 deg incidence;
    * NRL's does not scale with ``q``: its rise is > 6 dB at sea state 2 (measured
      +9.7 dB) and < 5 dB at sea state 5 (measured +3.3 dB)."""
    from seaecho.scattering.breaking import breaking_nrcs_monostatic, breaking_statistics
    from seaecho.scattering.copol import non_polarised_component

    grazing = np.array([5.0, 10.0, 20.0, 30.0])
    inc = np.radians(90.0 - grazing)
    wb0 = _db(breaking_nrcs_monostatic(inc))
    assert np.ptp(wb0) < 0.1
    assert wb0[0] == pytest.approx(_db(5.0e-3 / 0.19), abs=0.05)
    implied = {"GIT": np.empty((4, 4)), "NRL": np.empty((4, 4))}
    for i, ss in enumerate((2, 3, 4, 5)):
        u10 = SEA_STATE_WIND[ss]
        raw = _seaecho("two-scale", 9.3e9, u10, 90.0 - grazing, spectrum="romeiser")
        ratio = raw[:, 0] / raw[:, 3]
        q = breaking_statistics(u10, 2.0 * np.pi * 9.3e9 / C0).q
        for j, g in enumerate(grazing):
            for name, (hh, vv) in _xband_references(ss, g).items():
                if name in implied:
                    npc, _ = non_polarised_component(10 ** (vv / 10), 10 ** (hh / 10),
                                                     ratio[j])
                    implied[name][i, j] = _db(npc / q)
    git, nrl = implied["GIT"], implied["NRL"]
    assert np.all(np.ptp(git, axis=0) < 2.5)
    assert np.all((git[:, 3] - git[:, 0] > 1.5) & (git[:, 3] - git[:, 0] < 3.5))
    assert nrl[0, 3] - nrl[0, 0] > 6.0
    assert nrl[3, 3] - nrl[3, 0] < 5.0


def test_band_steps_of_the_references_and_of_raw97():
    """C band (5.3 GHz) against X band (9.3 GHz) at 58 deg incidence, CMOD5.N's upper
    edge (docs/scattering.md, "C band against X band"), sea states 2-5, look-averaged:

    * the X-band references lie below CMOD5.N at C band in VV (GIT by 7.7-9.8 dB, NRL by
      1.3-6.2 dB), while seaecho (two-scale + breaking, RAW97) is within 2 dB of it
      (measured 0.0-1.4 dB);
    * the references rise from C to X band (VV: GIT +1.7 to +3.4 dB, NRL +0.4 dB; HH:
      GIT +2.3 to +4.0, NRL +2.0 dB); RAW97 falls (VV -3.5 to -3.8 dB, HH -0.6 to
      -2.1 dB): a model meeting CMOD5.N at C band must fall to meet them at X band."""
    inc, grazing = 58.0, 32.0
    for ss in (2, 3, 4, 5):
        u10 = SEA_STATE_WIND[ss]
        cmod = _db(np.mean([cmod5n(u10, p, inc) for p in LOOKS_DEG]))
        ours = {f: _db(_seaecho("two-scale+breaking", f * 1e9, u10, [inc],
                                spectrum="romeiser")[0]) for f in (5.3, 9.3)}
        refs = {f: {pol: (np.mean([git_sigma0(f, u10, grazing, pol, a) for a in LOOKS_DEG]),
                          float(nrl_sigma0(f, ss, grazing, pol))) for pol in "HV"}
                for f in (5.3, 9.3)}
        assert cmod - refs[5.3]["V"][0] > 7.0
        assert cmod - refs[5.3]["V"][1] > 1.0
        assert abs(ours[5.3][3] - cmod) < 2.0
        for pol, idx in (("H", 0), ("V", 3)):
            for j in (0, 1):
                assert refs[9.3][pol][j] - refs[5.3][pol][j] > 0.2
            assert ours[9.3][idx] - ours[5.3][idx] < -0.3


# --- The default sea of a scene (K03 spectrum) ------------------------------------------

#: (sea state, grazing [deg], channel): the default's values more than 3 dB outside the
#: span of the published X-band models, and the distance measured [dB] (all by <= 0.4 dB)
DEFAULT_LEVELS_BEYOND_3_DB = {(2, 20.0, "HH"): -3.4, (2, 10.0, "VV"): -3.3,
                              (5, 5.0, "VV"): 3.1, (5, 20.0, "VV"): 3.4}
#: (sea state, grazing [deg]): the default's VV/HH more than 2 dB above the published
#: models' span, and the distance measured [dB] (all by <= 0.9 dB)
DEFAULT_RATIOS_BEYOND_2_DB = {(3, 20.0): 2.8, (4, 20.0): 2.5, (4, 30.0): 2.9,
                              (5, 20.0): 2.2, (5, 30.0): 2.6}
#: (U10 [m/s], incidence [deg]): the default's C-band VV more than 2 dB from CMOD5.N, and
#: the difference measured [dB]
DEFAULT_CBAND_BEYOND_2_DB = {(5.0, 50.0): -2.13, (15.0, 50.0): -2.05}


@functools.cache
def _default_sigma(f_hz, u10, inc_deg):
    """Look-averaged two-scale + breaking sigma0 (n, 4) [dB] at the incidences ``inc_deg``
    (a tuple) [deg] of the sea a scene gets when its ``[sea]`` gives the wind alone
    (``seaecho.build.sea_spectrum``: the default spectrum and spreading; the water at the
    scene's default 20 degC, 35 psu)."""
    scene = parse_scene({"sea": {"wind_speed_m_s": float(u19_5_from_u10(u10)),
                                 "size_x_m": 64.0, "nx": 64}})
    spec = sea_spectrum(scene)
    eps = sea_water_permittivity(f_hz, scene.sea.temperature_c, scene.sea.salinity_psu)
    th = np.radians(np.asarray(inc_deg, dtype=float))[:, None]
    phi_i = np.pi + np.radians(LOOKS_DEG)[None, :]
    s = sea_sigma("two-scale+breaking", th + 0 * phi_i, phi_i, th + 0 * phi_i,
                  phi_i + np.pi, f_hz, spec, eps)
    return _db(s.mean(axis=1))


@functools.cache
def _e97_xband(ss):
    """Look-averaged two-scale + breaking sigma0 (4, 4) [dB] at 9.3 GHz, 5, 10, 20, 30 deg
    grazing, with the Elfouhaily spectrum named."""
    return _db(_seaecho("two-scale+breaking", 9.3e9, SEA_STATE_WIND[ss],
                        [90.0 - g for g in XBAND_GRAZING_DEG], spectrum="elfouhaily"))


def _signed(value, refs):
    """Signed distance [dB] of ``value`` to the span of ``refs`` (+ above, - below, 0 in)."""
    return value - max(refs) if value > max(refs) else min(value - min(refs), 0.0)


@pytest.mark.parametrize(("ss", "grazing"), XBAND_POINTS)
def test_default_sea_xband_against_published_models(ss, grazing):
    """X band (9.3 GHz), 5-30 deg grazing, sea states 2-5: the sea of a scene that names
    no spectrum (the default, Kudryavtsev et al. 2003, "K03", with the default
    Longuet-Higgins spreading; docs/scattering.md, "Choice of the default") against the
    span of Nathanson's table, GIT and NRL:

    * HH and VV within 3 dB of the span, but for four values 3.1-3.4 dB outside it, kept
      visible (HH at sea state 2, 20 deg, below; VV at sea state 2, 10 deg, below, and at
      sea state 5, 5 and 20 deg, above): K03's level grows with the wind faster than the
      references';
    * VV/HH within 2 dB of their span, but for five values 2.2-2.9 dB above it (20-30 deg
      at sea states 3-5);
    * with the Elfouhaily et al. (1997) spectrum, the default before (named here), VV/HH
      is 2.8-7.2 dB above the span at every point (its VV excess,
      ``test_xband_vv_against_nathanson_known_excess``): the default's VV/HH is closer to
      the references than E97's everywhere."""
    refs = _xband_references(ss, grazing)
    j_g = XBAND_GRAZING_DEG.index(grazing)
    ours = _default_sigma(9.3e9, SEA_STATE_WIND[ss],
                          tuple(90.0 - g for g in XBAND_GRAZING_DEG))[j_g]
    for pol, idx, j in (("HH", 0, 0), ("VV", 3, 1)):
        d = _signed(ours[idx], [r[j] for r in refs.values()])
        known = DEFAULT_LEVELS_BEYOND_3_DB.get((ss, grazing, pol))
        if known is None:
            assert abs(d) <= 3.0, (pol, d)
        else:
            assert d == pytest.approx(known, abs=0.1), (pol, d)
    ratios = [vv - hh for hh, vv in refs.values()]
    d_pr = _signed(ours[3] - ours[0], ratios)
    known = DEFAULT_RATIOS_BEYOND_2_DB.get((ss, grazing))
    if known is None:
        assert abs(d_pr) <= 2.0, d_pr
    else:
        assert d_pr == pytest.approx(known, abs=0.1)
    e97 = _e97_xband(ss)[j_g]
    d_e97 = _signed(e97[3] - e97[0], ratios)
    assert d_e97 > 2.7
    assert abs(d_pr) < d_e97


@pytest.mark.parametrize("u10", [5.0, 10.0, 15.0])
def test_default_sea_cband_against_cmod5n_and_mouche(u10):
    """C band (5.3 GHz), 30-50 deg incidence, the default sea (K03): VV/HH within 2 dB of
    Mouche et al. (2005) (measured -1.2 to +0.5 dB) and VV within 2 dB of CMOD5.N (measured
    -0.05 to -1.7 dB), but at 50 deg and 5 and 15 m/s, 2.13 and 2.05 dB below it, kept
    visible (with Elfouhaily's spreading, examples/xband_spectrum_comparison.py: 2.04 dB and
    1.97 dB). K03's VV lies below CMOD5.N at every point (E97's: -1.4 to +1.6 dB)."""
    inc = np.array([30.0, 40.0, 50.0])
    ours = _default_sigma(5.3e9, u10, tuple(inc))
    cmod = _db(np.mean([cmod5n(u10, p, inc) for p in LOOKS_DEG], axis=0))
    pr = _db(np.mean([mouche_pr(inc, p) for p in LOOKS_DEG], axis=0))
    np.testing.assert_array_less(np.abs(ours[:, 3] - ours[:, 0] - pr), 2.0)
    np.testing.assert_array_less(ours[:, 3] - cmod, 0.0)
    for j, t in enumerate(inc):
        known = DEFAULT_CBAND_BEYOND_2_DB.get((u10, float(t)))
        if known is None:
            assert abs(ours[j, 3] - cmod[j]) <= 2.0
        else:
            assert ours[j, 3] - cmod[j] == pytest.approx(known, abs=0.03)
