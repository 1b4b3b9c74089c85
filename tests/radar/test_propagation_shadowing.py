"""The two-ray factor with its sea-reflected legs shadowed by the waves (eqs P5-P7 of
``seaecho.radar.propagation``): closed forms of the illuminated height density and limits.

- With 2 Lambda = m - 1 an integer, eq P5 is the density of the highest of m independent
  Gaussian heights: mean sigma / sqrt(pi) for m = 2 and 3 sigma / (2 sqrt(pi)) for m = 3
  (the expected maxima of normal samples, e.g. David & Nagaraja, *Order Statistics*,
  2003, section 3.2); for m = 2 the maximum is (X1 + X2) / 2 + |X1 - X2| / 2, a normal
  N(0, sigma^2 / 2) plus an independent half-normal of scale sigma / sqrt(2), whose
  characteristic function is exp(-q^2 sigma^2 / 2) (1 - j erfi(q sigma / 2)).
- Lambda = 0 (no shadowing, high grazing angles): Ament's exp(-2 g^2), the mean sea.
- Eq P7 with Lambda = 0: the truncated normal, mean -sigma phi(c / sigma) / Phi(c / sigma).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import erfi, ndtr
from scipy.stats import norm

from seaecho.build import build_radar, sea_slope_covariance
from seaecho.config import parse_scene
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.radar.propagation import TwoRay, illuminated_reflection, two_ray_geometry
from seaecho.targets.multipath import specular_reduction

LAM = 0.0319
EPS = complex(sea_water_permittivity(9.4e9, 20.0, 35.0))
SLOPES = ((0.02, 0.0), (0.0, 0.012))  # an upwind-crosswind slope covariance [-]


@pytest.mark.parametrize("q", [0.3, 1.0, 2.0, 3.5])
def test_two_legs_at_lambda_half_are_the_highest_of_two_heights(q):
    sigma = 0.7
    zeta_bar, rho = illuminated_reflection(0.5, sigma, q)
    assert zeta_bar == pytest.approx(sigma / np.sqrt(np.pi), rel=1e-4)
    cf = rho * np.exp(-1j * q * zeta_bar)  # the characteristic function about 0
    expected = np.exp(-0.5 * (q * sigma) ** 2) * (1.0 - 1j * erfi(q * sigma / 2.0))
    assert abs(cf - expected) < 2e-4


def test_highest_of_three_and_ament_without_shadowing():
    assert illuminated_reflection(1.0, 2.0, 0.1)[0] == pytest.approx(
        3.0 / np.sqrt(np.pi), rel=1e-4)  # 2 x 3 sigma / (2 sqrt pi)
    k, sigma_h = 2 * np.pi / LAM, 0.3
    psi = np.radians([0.5, 1.0, 3.0])
    zeta_bar, rho = illuminated_reflection(np.zeros(3), sigma_h, 2 * k * np.sin(psi))
    np.testing.assert_allclose(zeta_bar, 0.0, atol=1e-12)
    # the quadrature's error (module constants): < 1e-4 to q sigma = 2, < 1.1e-3 to 8
    np.testing.assert_allclose(rho, specular_reduction(psi, sigma_h, k, "ament"), atol=3e-4)


@pytest.mark.parametrize("ceiling", [-1.0, 0.3, 2.0])
def test_reflecting_points_lie_below_the_scatterer(ceiling):
    sigma = 1.0
    zeta_bar, _ = illuminated_reflection(0.0, sigma, 0.1, ceiling=ceiling)
    c = ceiling / sigma
    assert zeta_bar == pytest.approx(-sigma * norm.pdf(c) / ndtr(c), abs=5e-5)
    for lam in (0.3, 5.0, 200.0):  # the lit points rise with Lambda, below the ceiling
        z_lo = illuminated_reflection(lam, sigma, 0.1, ceiling=ceiling)[0]
        assert zeta_bar < z_lo < ceiling
        zeta_bar = z_lo


def test_high_grazing_is_the_mean_sea_and_low_grazing_raises_the_mirror():
    k, sigma_h = 2 * np.pi / LAM, 0.4
    plain = TwoRay(LAM, EPS, sigma_h, roughness="ament")
    shadowed = TwoRay(LAM, EPS, sigma_h, slope_cov=SLOPES)
    h1 = 35.0
    # 20-60 deg: Lambda < 1e-20, the factors of the mean sea with Ament's roughness
    d = h1 / np.tan(np.radians([20.0, 40.0, 60.0]))
    pts = np.stack([d, 0 * d, 0 * d + 5.0], -1)
    for a, b in zip(plain.factors([0, 0, h1], pts), shadowed.factors([0, 0, h1], pts),
                    strict=True):
        np.testing.assert_allclose(a, b, atol=1e-4)
    # 0.3 deg, a target 10 m up: the mirror at the mean height of the lit crests (P5,
    # the ceiling far above them), the path difference that of the raised heights
    d = np.array([(h1 + 10.0) / np.tan(np.radians(0.3))])
    psi0, _, _ = two_ray_geometry(h1, 10.0, d)
    sigma_dir = np.sqrt(SLOPES[0][0])  # looking along +x
    from seaecho.geometry.shadowing import smith_lambda, smith_nu

    lam = smith_lambda(smith_nu(np.pi / 2 - psi0, sigma_dir))
    zeta_bar, rho = illuminated_reflection(lam, sigma_h, 2 * k * np.sin(psi0))
    # nu = tan(0.3 deg) / (sqrt 2 x 0.1414) = 0.02618, Lambda = (exp(-nu^2) / (sqrt(pi)
    # nu) - erfc(nu)) / 2 = 10.28 (eq T1): the highest of 1 + 2 Lambda = 21.6 heights,
    # between the expected maxima of 21 and 22 normal samples (their integrals)
    assert lam[0] == pytest.approx(10.28, abs=0.01)
    from scipy.integrate import quad

    e_max = [quad(lambda z, m=m: z * m * norm.pdf(z) * ndtr(z) ** (m - 1), -10, 10)[0]
             for m in (21, 22)]  # 1.889, 1.910
    assert e_max[0] * sigma_h < zeta_bar[0] < e_max[1] * sigma_h
    fh, _ = shadowed.factors([0.0, 0.0, h1], np.array([[d[0], 0.0, 10.0]]))
    _, delta, _ = two_ray_geometry(h1 - zeta_bar, 10.0 - zeta_bar, d)
    from seaecho.scattering.fresnel import fresnel_coefficients

    psi, _, _ = two_ray_geometry(h1 - zeta_bar, 10.0 - zeta_bar, d)
    r_h, _ = fresnel_coefficients(np.sin(psi), EPS)
    np.testing.assert_allclose(fh, 1.0 + r_h * rho * np.exp(-1j * k * delta), rtol=1e-12)
    assert delta[0] < 2 * h1 * 10.0 / d[0] * 0.95  # lower than over the mean sea
    # a facet among the waves (0.3 m up): its mirror lies below it (eq P7)
    low = np.array([[d[0], 0.0, 0.3]])
    psi_low, _, _ = two_ray_geometry(h1, 0.3, d)
    lam_low = smith_lambda(smith_nu(np.pi / 2 - psi_low, sigma_dir))
    z7, rho7 = illuminated_reflection(lam_low, sigma_h, 2 * k * np.sin(psi_low),
                                      ceiling=0.3)
    assert z7[0] < 0.3 < zeta_bar[0]
    _, delta7, _ = two_ray_geometry(h1 - z7, 0.3 - z7, d)
    psi7, _, _ = two_ray_geometry(h1 - z7, 0.3 - z7, d)
    r_h7, _ = fresnel_coefficients(np.sin(psi7), EPS)
    np.testing.assert_allclose(shadowed.factors([0.0, 0.0, h1], low)[0],
                               1.0 + r_h7 * rho7 * np.exp(-1j * k * delta7), rtol=1e-9)


def test_scene_key_builds_the_slopes_of_the_band():
    scene = {"sea": {"wind_speed_m_s": 8.0, "wind_direction_deg": 30.0, "spreading": "elfouhaily",
                     "size_x_m": 64.0, "nx": 64},
             "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                       "prf_hz": 1000.0, "n_pulses": 1, "sea_clutter": False,
                       "waveform": {"kind": "pulse", "duration_s": 5e-8}},
             "transmitter": {"position_m": (0.0, 0.0, 20.0), "antenna": {
                 "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
             "propagation": {"multipath": "two-ray"}}
    two = build_radar(parse_scene(scene)).multipath
    c = np.asarray(two.slope_cov)
    # the upwind variance along 30 deg, the crosswind across: eigen-directions
    w, v = np.linalg.eigh(c)
    assert w[1] > w[0] > 0
    assert np.degrees(np.arctan2(v[1, 1], v[0, 1])) % 180.0 == pytest.approx(30.0)
    assert c == pytest.approx(np.asarray(sea_slope_covariance(parse_scene(scene), 9.41e9)))
    scene["propagation"]["multipath_shadowing"] = False
    assert build_radar(parse_scene(scene)).multipath.slope_cov is None


@pytest.mark.parametrize("lam", [0.0, 0.5, 10.0, 100.0])
def test_quadrature_against_a_dense_trapezoid(lam):
    """Eq P6 by 96-point Gauss-Legendre in v against a 40 001-point trapezoid in zeta:
    absolute error below 1e-4 for q sigma_ill <= 2, below 1.1e-3 up to 8."""
    z = np.linspace(-9.0, 9.0, 40001)
    dz = z[1] - z[0]
    p = (1 + 2 * lam) * norm.pdf(z) * ndtr(z) ** (2 * lam)  # (P5), sigma_h = 1
    zb = (z * p).sum() * dz
    sd = np.sqrt(((z - zb) ** 2 * p).sum() * dz)
    for qs, tol in ((0.5, 1e-4), (1.0, 1e-4), (2.0, 1e-4), (4.0, 1.1e-3), (8.0, 1.1e-3)):
        q = qs / sd
        ref = (p * np.exp(-1j * q * (z - zb))).sum() * dz
        zq, rq = illuminated_reflection(lam, 1.0, q)
        assert abs(zq - zb) < 2e-5 and abs(rq - ref) < tol, (qs, abs(rq - ref))
    assert abs(ref) < 1e-5  # at q sigma_ill = 8, where rho_ill is set to 0 beyond
