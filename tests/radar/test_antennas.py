"""Antennas: normalisation, peak directivity, polarisation ports, pointing.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.radar.antennas import (
    Antenna,
    antenna_axes,
    aperture_field,
    aperture_radiated_power,
    builtin_gain,
    port_states,
    wave_basis,
)

LAM = C0 / 10e9


def _sphere_integral(gain_fn, n_theta=1500, n_phi=3000):
    """Midpoint rule in (theta, phi) about the world z axis: an independent quadrature
    (different pole, rule and nodes) from the Gauss-Legendre one of the module."""
    th = (np.arange(n_theta) + 0.5) * np.pi / n_theta
    ph = (np.arange(n_phi) + 0.5) * 2 * np.pi / n_phi
    total = 0.0
    for i in range(0, n_theta, 100):
        t = th[i:i + 100, None]
        d = np.stack(np.broadcast_arrays(np.sin(t) * np.cos(ph), np.sin(t) * np.sin(ph),
                                         np.cos(t)), axis=-1)
        total += np.sum(gain_fn(d) * np.sin(t))
    return total * (np.pi / n_theta) * (2 * np.pi / n_phi)


@pytest.mark.parametrize("pattern,size", [("rectangular", (0.18, 0.14)),
                                          ("rectangular", (0.05, 0.12)),
                                          ("isotropic", None), ("dipole", None),
                                          ("hw_dipole", None)])
def test_directivity_integrates_to_4pi(pattern, size):
    # Directivity is normalised so that its integral over the sphere is 4 pi
    # (Balanis 2016, eq 2-16). Checked with an independent midpoint rule.
    w, h = size if size else (None, None)
    ant = Antenna(pattern, LAM, w, h)
    integral = _sphere_integral(ant.gain_local)
    # hw_dipole: Balanis's 1.643 is rounded (exact 1.6409...), 0.2 % off
    tol = 3e-3 if pattern == "hw_dipole" else 1e-3
    assert integral == pytest.approx(4 * np.pi, rel=tol)


@pytest.mark.parametrize("w,h,tol_db", [(0.18, 0.14, 0.15), (1.0, 0.5, 0.05),
                                        (4.0, 0.3, 0.05)])
def test_peak_directivity_large_aperture(w, h, tol_db):
    # Uniform rectangular aperture: D0 -> 4 pi A / lambda^2 for a, b >> lambda
    # (Balanis 2016, eq 12-38). The paper's 18 x 14 cm at 10 GHz is only ~6 x 5
    # wavelengths, so its obliquity factor lifts D0 by ~0.13 dB (Sionna RT's own
    # evaluation of this aperture gave 25.6 dBi against 25.5).
    d0 = Antenna("rectangular", LAM, w, h).peak_gain
    expected = 4 * np.pi * w * h / LAM**2
    assert 10 * np.log10(d0 / expected) == pytest.approx(0.0, abs=tol_db)


def test_rectangular_first_null_and_half_power():
    # Uniform line source: first null at sin(theta) = lambda / a, half-power at
    # a u / lambda = 0.443 (Balanis 2016, section 12.5; sinc^2 = 0.5 at 0.4429)
    a = 1.0
    u_null = LAM / a
    d = np.array([np.sqrt(1 - u_null**2), u_null, 0.0])
    assert aperture_field(d, a, 0.5, LAM) == pytest.approx(0.0, abs=1e-12)
    u3 = 0.44295 * LAM / a
    d3 = np.array([np.sqrt(1 - u3**2), u3, 0.0])
    f3 = aperture_field(d3, a, 0.5, LAM) / (0.5 * (1 + d3[0]))
    assert f3**2 == pytest.approx(0.5, abs=1e-4)


def test_tr38901_peak_8dbi():
    # 3GPP TR 38.901 Table 7.3-1: maximum directional gain 8 dBi at boresight
    assert 10 * np.log10(builtin_gain("tr38901", np.array([1.0, 0, 0]))) == pytest.approx(8.0)


def test_antenna_axes_look_down():
    b = np.array([1.0, 0.0, -1.0])
    a = antenna_axes(b, np.array([0, 0, 1.0]))
    np.testing.assert_allclose(a[:, 0], b / np.sqrt(2))
    np.testing.assert_allclose(a[:, 1], [0, 1, 0], atol=1e-15)  # width stays horizontal
    assert a[2, 2] > 0  # height axis points up-ish
    np.testing.assert_allclose(a.T @ a, np.eye(3), atol=1e-12)
    # nadir-looking: falls back to world y for the width
    a2 = antenna_axes(np.array([0, 0, -1.0]), np.array([0, 0, 1.0]))
    np.testing.assert_allclose(a2.T @ a2, np.eye(3), atol=1e-12)


def test_circular_ports_orthonormal_and_handedness():
    n = np.array([0.3, -0.2, -0.9])
    n /= np.linalg.norm(n)
    h, v = wave_basis(n, np.array([0, 0, 1.0]))
    e = port_states("circular", h, v, None)
    gram = np.conj(e) @ e.T
    np.testing.assert_allclose(gram, np.eye(2), atol=1e-12)
    # IEEE RHC with exp(+j w t): Re{E e^{jwt}} turns from v to h, and v x h = n (right
    # hand about the propagation direction)
    r = e[0]
    e0 = np.real(r)
    e90 = np.real(r * np.exp(1j * np.pi / 2))
    assert np.dot(np.cross(e0, e90), n) > 0.49


def test_cross_polar_isolation():
    h, v = np.array([0, 1.0, 0]), np.array([0, 0, -1.0])
    e = port_states("hv", h, v, 30.0)
    # leakage into the other port is -30 dB in power, and each port is unit norm
    assert abs(np.vdot(v, e[0])) ** 2 / abs(np.vdot(h, e[0])) ** 2 == pytest.approx(1e-3)
    np.testing.assert_allclose(np.linalg.norm(e, axis=-1), 1.0)


def test_normalisation_depends_on_size_in_wavelengths_only():
    # The pattern of eq (A1) depends on a / lambda and b / lambda only
    a, b = 0.18, 0.14
    base = aperture_radiated_power(a, b, LAM)
    assert aperture_radiated_power(2 * a, 2 * b, 2 * LAM) == pytest.approx(base, rel=1e-12)


def test_normalisation_huygens_element_limit():
    # An aperture much smaller than the wavelength radiates as a Huygens element, the
    # cardioid F = (1 + cos theta) / 2 of eq (A1)'s obliquity factor (Balanis 2016,
    # section 12.2): the integral of F^2 over the sphere is the closed form
    # 2 pi int_-1^1 (1 + x)^2 / 4 dx = 4 pi / 3, a peak directivity of 3 (4.77 dBi).
    # Dropping the obliquity factor would give 4 pi (directivity 1).
    assert aperture_radiated_power(1e-9, 1e-9, LAM) == pytest.approx(4 * np.pi / 3,
                                                                      rel=1e-13)
    assert Antenna("rectangular", LAM, 1e-9, 1e-9).peak_gain == pytest.approx(3.0, rel=1e-13)


@pytest.mark.parametrize("a", [0.05, 0.18, 1.0, 4.0])
def test_normalisation_line_source_closed_form(a):
    # A line source (height -> 0) of eq (A1): with the polar axis along the width,
    # u = cos(alpha), r^2 = 1 - u^2, the azimuthal integral of the obliquity factor is
    # int_0^2pi (1 + r cos phi)^2 / 4 dphi = pi (3 - u^2) / 4, so
    #   int |F|^2 dOmega = pi/4 int_-1^1 (3 - u^2) sinc^2(A u) du, A = a / lambda,
    # and with int_0^X sinc^2 = Si(2 pi X) / pi - sin^2(pi X) / (pi^2 X) (Si the sine
    # integral, Abramowitz and Stegun 5.2.1) and int u^2 sinc^2(A u) = int sin^2(pi A u)
    # / (pi A)^2:
    #   = pi/4 [ 3 (2/A) (Si(2 pi A)/pi - sin^2(pi A)/(pi^2 A))
    #            - (1 - sin(2 pi A)/(2 pi A)) / (pi A)^2 ].
    from scipy.special import sici

    big_a = a / LAM
    x = np.pi * big_a
    expected = np.pi / 4 * (3 * (2 / big_a) * (sici(2 * x)[0] / np.pi - np.sin(x)**2 / (np.pi * x))
                            - (1 - np.sin(2 * x) / (2 * x)) / x**2)
    assert aperture_radiated_power(a, 1e-9, LAM) == pytest.approx(expected, rel=1e-12)
    # the same aperture turned by 90 deg about its boresight radiates the same power
    assert aperture_radiated_power(1e-9, a, LAM) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("a,b,previous", [
    (0.18, 0.14, 3.463425398952479e-02), (4.0, 0.5, 4.471245068493546e-04),
    (1.0, 0.5, 1.785224282379548e-03), (0.05, 0.12, 1.411911699288574e-01),
    (4.0, 4.0, 5.610572211728849e-05)])
def test_normalisation_parity_with_product_rule(a, b, previous):
    # Parity: the previous implementation (Gauss-Legendre in the polar angle from the
    # boresight x trapezoid in azimuth, 8 nodes per lambda / a + 96, converged to about
    # 1e-12) gave these integrals; eq (A3)'s rule agrees within its stated 1e-12.
    assert aperture_radiated_power(a, b, LAM) == pytest.approx(previous, rel=3e-12)
    assert aperture_radiated_power(b, a, LAM) == pytest.approx(previous, rel=3e-12)
