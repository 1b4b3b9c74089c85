"""Smith's shadowing function (Smith 1967) and its bistatic forms (Bourlier et al. 2002)."""

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import erfc

from seaecho.geometry.shadowing import (
    directional_slope_std,
    height_cdf,
    smith_bistatic,
    smith_conditional,
    smith_lambda,
    smith_monostatic,
    smith_nu,
)


def test_lambda_matches_its_definition_and_limits():
    """Lambda(nu) = (exp(-nu^2)/(sqrt(pi) nu) - erfc(nu))/2 (Smith 1967)."""
    nu = np.array([0.05, 0.3, 1.0, 2.0, 3.0])
    naive = 0.5 * (np.exp(-nu**2) / (np.sqrt(np.pi) * nu) - erfc(nu))
    np.testing.assert_allclose(smith_lambda(nu), naive, rtol=1e-10)
    assert smith_lambda(np.inf) == 0.0
    assert smith_lambda(0.0) == np.inf
    # small-nu asymptote 1/(2 sqrt(pi) nu) - 1/2 (expand exp and erfc at 0)
    assert smith_lambda(1e-4) == pytest.approx(1 / (2 * np.sqrt(np.pi) * 1e-4) - 0.5, rel=1e-6)
    assert np.all(np.diff(smith_lambda(np.linspace(0.01, 5, 200))) < 0)


def test_height_average_of_conditional_is_one_over_one_plus_lambda():
    """Integral of F(zeta)^Lambda over the Gaussian height pdf = 1 / (1 + Lambda) (Smith 1967)."""
    sigma_h = 0.7

    def pdf(z):
        return np.exp(-0.5 * (z / sigma_h) ** 2) / (np.sqrt(2 * np.pi) * sigma_h)

    for lam in (0.05, 0.4, 2.0):
        val, _ = quad(lambda z, lam=lam: pdf(z) * smith_conditional(lam, z, sigma_h),
                      -10 * sigma_h, 10 * sigma_h)
        assert val == pytest.approx(1.0 / (1.0 + lam), rel=1e-8)


def test_monostatic_limits():
    # normal incidence: nothing shadowed; grazing: everything shadowed
    assert smith_monostatic(0.0, 0.2) == pytest.approx(1.0)
    assert smith_monostatic(np.pi / 2, 0.2) == pytest.approx(0.0, abs=1e-12)
    th = np.linspace(0.1, 1.5, 30)
    assert np.all(np.diff(smith_monostatic(th, 0.2)) <= 0)  # 1 to float precision near nadir
    assert np.all(smith_monostatic(1.3, 0.1) > smith_monostatic(1.3, 0.3))


def test_bistatic_reduces_to_monostatic():
    cov = np.diag([0.02, 0.01])
    for theta, az in ((1.2, 0.3), (1.45, -2.0)):
        sigma = directional_slope_std(cov, az)
        assert smith_bistatic(theta, az, theta, az, cov) == pytest.approx(
            smith_monostatic(theta, sigma), rel=1e-12)


def test_bistatic_opposite_sides_closed_form():
    """Opposite azimuths: facing both = P(-mu2 < s < mu1), shadowing 1/(1 + L1 + L2)."""
    cov = np.diag([0.03, 0.03])
    t1, t2 = 1.35, 1.2
    s = np.sqrt(0.03)
    l1 = smith_lambda(smith_nu(t1, s))
    l2 = smith_lambda(smith_nu(t2, s))
    facing = 0.5 * erfc(-1 / np.tan(t1) / (np.sqrt(2) * s)) - 0.5 * erfc(
        1 / np.tan(t2) / (np.sqrt(2) * s))
    assert smith_bistatic(t1, 0.0, t2, np.pi, cov) == pytest.approx(
        facing / (1 + l1 + l2), rel=1e-9)


def test_directional_slope_and_cdf():
    cov = np.array([[0.04, 0.01], [0.01, 0.02]])
    assert directional_slope_std(cov, 0.0) == pytest.approx(0.2)
    assert directional_slope_std(cov, np.pi / 2) == pytest.approx(np.sqrt(0.02))
    assert height_cdf(0.0, 1.0) == pytest.approx(0.5)
    with pytest.raises(ValueError, match="sigma"):
        smith_nu(1.0, 0.0)


def _flat_facets(tx, rx):
    from seaecho.geometry.facets import analytic_facets

    x = np.arange(4.0)
    z = np.zeros((4, 4))
    return analytic_facets(x, x, z, z, z, None, tx, rx, shadowing="none")


def test_subfacet_shadowing_closed_forms():
    """Eq T7 on a flat sea: backscatter 1/(1 + Lambda), forward 1/(1 + L_i + L_s)
    (Smith 1967; Sancer 1969), isotropic sub-facet slopes."""
    from seaecho.geometry.facets import subfacet_shadowing

    mss = 0.02
    tx = np.array([-1000.0, 1.5, 100.0])
    f = _flat_facets(tx, tx)
    s = subfacet_shadowing(f, mss, mss, 0.3)
    lam = smith_lambda(smith_nu(f.theta_i, np.sqrt(mss)))
    np.testing.assert_allclose(s, 1 / (1 + lam), rtol=1e-12)
    rx = np.array([1000.0, 1.5, 300.0])
    f = _flat_facets(tx, rx)
    s = subfacet_shadowing(f, mss, mss, 0.3)
    lam_s = smith_lambda(smith_nu(f.theta_s, np.sqrt(mss)))
    np.testing.assert_allclose(s, 1 / (1 + lam + lam_s), rtol=1e-12)
    # nadir: no shadowing; transmitter below the horizon of the facet: fully shadowed
    assert subfacet_shadowing(_flat_facets([1.5, 1.5, 500.0], [1.5, 1.5, 500.0]),
                              mss, mss, 0.0) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="mss_upwind"):
        subfacet_shadowing(f, 0.0, mss, 0.0)
