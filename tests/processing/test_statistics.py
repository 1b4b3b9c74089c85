"""Clutter amplitude statistics: K closed forms, estimators on synthetic clutter, fits.

Closed forms from Ward, Tough & Watts, *Sea Clutter* (2013), ch. 4 (K intensity density
and moments); the z log z estimator of Blacknell & Tough (2001); the empirical shape law
of Watts & Wicks (1990).
"""

import numpy as np
import pytest
from scipy import integrate

from seaecho.processing.statistics import (
    fit_k,
    fit_rayleigh,
    fit_weibull,
    k_intensity_moment,
    k_intensity_pdf,
    k_intensity_samples,
    k_shape_empirical,
    k_shape_moments,
    k_shape_zlogz,
)


@pytest.mark.parametrize("nu", [0.3, 1.0, 4.5])
def test_k_pdf_normalised_and_moments_closed_form(nu):
    """int p = 1 and <z^n> = mu^n n! Gamma(nu+n) / (nu^n Gamma(nu)) for n = 1, 2, 3."""
    mu = 2.5

    def mom(n):
        f = lambda z: z**n * k_intensity_pdf(z, nu, mu)  # noqa: E731
        return sum(integrate.quad(f, a, b, limit=400)[0]
                   for a, b in ((0, 1e-6), (1e-6, mu), (mu, 50 * mu), (50 * mu, np.inf)))

    assert mom(0) == pytest.approx(1.0, rel=1e-6)
    for n in (1, 2, 3):
        assert mom(n) == pytest.approx(float(k_intensity_moment(n, nu, mu)), rel=1e-5)
    assert float(k_intensity_moment(2, nu, mu)) == pytest.approx(2 * mu**2 * (1 + 1 / nu))


def test_k_pdf_special_cases():
    """nu = 1/2: p(z) = exp(-sqrt(2 z / mu)) / sqrt(2 mu z) (K_{1/2} elementary); nu -> inf:
    the exponential (Rayleigh amplitude) density."""
    mu = 1.7
    z = np.linspace(0.01, 20, 300)
    np.testing.assert_allclose(k_intensity_pdf(z, 0.5, mu),
                               np.exp(-np.sqrt(2 * z / mu)) / np.sqrt(2 * mu * z), rtol=1e-10)
    np.testing.assert_allclose(k_intensity_pdf(z, 1e5, mu), np.exp(-z / mu) / mu, rtol=2e-3)


@pytest.mark.parametrize("nu", [0.3, 1.0, 3.0, 10.0])
def test_estimators_recover_nu_on_synthetic_clutter(nu):
    """200 000 K samples (gamma texture x exponential speckle): z log z within 5 %
    (nu <= 3) / 12 % (nu = 10), moments within 10 % / 25 %, ML within 5 % / 12 %."""
    rng = np.random.default_rng(int(nu * 100))
    z = k_intensity_samples(nu, 3.0, 200_000, rng)
    tol = 0.05 if nu <= 3 else 0.12
    assert k_shape_zlogz(z) == pytest.approx(nu, rel=tol)
    assert k_shape_moments(z) == pytest.approx(nu, rel=0.10 if nu <= 3 else 0.25)
    fit = fit_k(z[:40_000])
    assert fit.nu == pytest.approx(nu, rel=tol)
    assert fit.mean == pytest.approx(3.0, rel=0.03)


def test_rayleigh_clutter_has_large_nu():
    """Exponential intensity (Rayleigh amplitude) is the nu -> infinity limit."""
    z = np.random.default_rng(5).exponential(2.0, 200_000)
    assert k_shape_zlogz(z) > 50 or k_shape_zlogz(z) == np.inf


def test_rayleigh_and_weibull_fits_recover_parameters():
    rng = np.random.default_rng(9)
    e = rng.rayleigh(1.3, 100_000)
    assert fit_rayleigh(e).sigma == pytest.approx(1.3, rel=0.01)
    w = 0.8 * rng.weibull(1.4, 100_000)
    fw = fit_weibull(w)
    assert fw.shape == pytest.approx(1.4, rel=0.02)
    assert fw.scale == pytest.approx(0.8, rel=0.02)
    # On spiky K clutter the K fit beats Rayleigh in likelihood.
    z = k_intensity_samples(0.5, 1.0, 20_000, rng)
    ll_k = fit_k(z).log_likelihood
    ll_r = fit_rayleigh(np.sqrt(z)).log_likelihood - np.sum(np.log(2 * np.sqrt(z)))
    assert ll_k > ll_r


def test_empirical_shape_law_structure():
    """Watts & Wicks (1990) law: nu grows as grazing^(2/3) and area^(5/8); HH clutter is
    spikier than VV by 10^0.70; a look along or across the swell changes log10(nu) by
    -1/3 or +1/3."""
    nu = k_shape_empirical(1.0, 1000.0, "VV")
    assert k_shape_empirical(8.0, 1000.0, "VV") == pytest.approx(4 * nu)
    assert k_shape_empirical(1.0, 1000.0 * 2**8, "VV") == pytest.approx(32 * nu)
    assert k_shape_empirical(1.0, 1000.0, "HH") == pytest.approx(nu / 10**0.70)
    assert k_shape_empirical(1.0, 1000.0, "VV", 0.0) == pytest.approx(nu / 10 ** (1 / 3))
    assert k_shape_empirical(1.0, 1000.0, "VV", np.pi / 2) == pytest.approx(nu * 10 ** (1 / 3))
    with pytest.raises(ValueError, match="pol"):
        k_shape_empirical(1.0, 100.0, "HV")


def test_bad_samples_are_refused():
    with pytest.raises(ValueError, match="finite and > 0"):
        k_shape_zlogz([1.0, -1.0, 2.0])
    with pytest.raises(ValueError, match="at least two"):
        k_shape_moments([1.0])


def test_large_order_bessel_expansion_parity():
    """Parity: the Debye expansion used for nu - 1 >= 50 agrees with scipy's kve to 1e-6
    where both are finite."""
    from scipy import special

    from seaecho.processing.statistics import _log_kv

    x = np.array([2.0, 5.0, 40.0, 150.0, 600.0])
    for v in (50.0, 75.0, 140.0):
        np.testing.assert_allclose(_log_kv(v, x), np.log(special.kve(v, x)) - x, rtol=1e-6)
