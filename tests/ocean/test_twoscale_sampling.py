"""Two-scale split statistics and the paper's sampling advice (section IV-A, eqs 13-14).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import warnings

import numpy as np
import pytest

from seaecho.ocean.sampling import check_sampling, peak_band, pm_shape, suggest_sampling
from seaecho.ocean.spectra import PM_A0, DirectionalSpectrum
from seaecho.ocean.twoscale import height_variance, slope_variances, unresolved_statistics
from seaecho.warnings import SamplingWarning


def test_pm_tail_slope_variance_closed_form():
    """Far above the peak, PM's S_1d = (a0/2) K^-3, so the slope variance of the band
    (k1, k2) is (a0/2) ln(k2/k1) and its height variance a0/4 (k1^-2 - k2^-2). With the
    s = 1 Longuet-Higgins spreading, int cos^2(psi) cos^2(psi/2)/pi dpsi = 1/2: the slope
    variance splits equally upwind and crosswind."""
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=5.0, s=1.0)
    up, cross = slope_variances(spec, 20.0, 200.0)
    assert up + cross == pytest.approx(PM_A0 / 2 * np.log(10.0), rel=1e-3)
    assert up == pytest.approx(cross, rel=1e-6)
    assert height_variance(spec, 20.0, 200.0) == pytest.approx(
        PM_A0 / 4 * (20.0**-2 - 200.0**-2), rel=1e-3)


def test_unresolved_statistics_of_a_grid():
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=8.0)
    stats = unresolved_statistics(spec, dx=0.125, dy=0.125, k_max=70.0)
    assert stats.k_grid == pytest.approx(np.pi / 0.125)
    assert stats.mss_upwind > stats.mss_crosswind > 0
    assert stats.mss == pytest.approx(sum(slope_variances(spec, stats.k_grid, 70.0)))
    assert unresolved_statistics(spec, 1.0, 1.0, k_max=2.0).mss == 0.0


@pytest.mark.parametrize("a", [0.5, 1.7, 3.0])
def test_eq14_invariant(a):
    """Eq 14: f(K a^2, U) = f(K, a U) / a^6 for the PM shape of eq 13."""
    k = np.geomspace(0.01, 10, 50)
    np.testing.assert_allclose(pm_shape(k * a**2, 6.0), pm_shape(k, a * 6.0) / a**6, rtol=1e-12)


def test_peak_band_scales_as_u_minus_2():
    lo1, hi1 = peak_band(5.0)
    lo2, hi2 = peak_band(10.0)
    assert lo1 / lo2 == pytest.approx(4.0) and hi1 / hi2 == pytest.approx(4.0)
    # the band holds the PM peak sqrt(2 b0/3) g / U^2
    from seaecho.ocean.spectra import pierson_moskowitz_peak
    assert lo1 < pierson_moskowitz_peak(5.0) < hi1


def test_suggested_tile_for_the_papers_sea_state_3():
    """For U19.5 = 4.53 m/s the paper simulated a 64 m tile (section V-A); its rule (a
    quarter of the -3 dB width as wavenumber step) gives 67 m."""
    advice = suggest_sampling(4.53, frequency=10e9)
    assert advice.tile_size == pytest.approx(64.0, rel=0.08)
    # at 10 GHz the unresolved PM tail keeps k h_res = 0.3 for dx ~ 0.1 m
    k_radar = 2 * np.pi * 10e9 / 299_792_458.0
    h_res = np.sqrt(PM_A0) / (2 * advice.k_cut)
    assert k_radar * h_res == pytest.approx(0.3)


def _sea(size_x_m=500.0, nx=64):
    """(spectrum, size, shape) of a U19.5 = 10 m/s Elfouhaily sea on a square tile."""
    spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", u19_5=10.0)
    return spec, (size_x_m, size_x_m), (nx, nx)


def test_sampling_warnings():
    with pytest.warns(SamplingWarning, match="peak wavelength"):
        check_sampling(*_sea(size_x_m=40.0))
    with pytest.warns(SamplingWarning, match="coarse against the radar wavelength"):
        check_sampling(*_sea(size_x_m=500.0, nx=64), frequency=10e9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_sampling(*_sea(size_x_m=500.0, nx=8192), frequency=1e9)


def test_empty_band_has_zero_variance():
    """An integral over an empty band is 0: a grid finer than the band's upper limit
    (k_cut = pi / dx >= k_max) leaves no unresolved waves, not an error."""
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=8.0)
    assert height_variance(spec, 10.0, 1.0) == 0.0
    assert height_variance(spec, 3.0, 3.0) == 0.0
    assert slope_variances(spec, 10.0, 1.0) == (0.0, 0.0)
    with pytest.raises(ValueError, match="finite"):
        height_variance(spec, 1.0, np.inf)
