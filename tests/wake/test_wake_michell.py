"""Michell thin-ship amplitude and wave resistance against published formulas.

Normalisation chain checked here (see docs/wake.md):

* eq W8 (closed form for the Wigley hull) against a direct quadrature of eq W5 over
  the hull offsets (two independent evaluations of the same integral);
* eq W6 (Havelock's energy-flux formula, Newman 1977 section 6.18) with the amplitude of
  eq W5 against Michell's integral in its classical published form
  R = 4 rho g^2 / (pi V^2) int_1^inf (P^2 + Q^2) lambda^2 / sqrt(lambda^2 - 1) dlambda
  (Michell 1898; Wehausen 1973), computed by independent quadrature;
* eq W6 with the point-source amplitude of eq W9 against Havelock's (1932) closed form
  for a submerged source, R = rho m^2 k0^2 / (4 pi) exp(-k0 h) [K0(k0 h) + K1(k0 h)]
  (m the volume flux; = 4 pi rho k0^2 m'^2 ... with m' = m / 4 pi).
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.special import k0 as bessel_k0
from scipy.special import k1 as bessel_k1

from seaecho.constants import G
from seaecho.wake import (
    havelock_wave_resistance,
    submerged_source_amplitude,
    wigley_amplitude,
    wigley_wave_resistance,
    wigley_wetted_surface,
)

RHO = 1000.0


def _wigley_offsets_fx(x, z, length, beam, draft):
    """df/dx of the Wigley hull by central differences of the offsets f(x, z) (eq W7)."""
    h = 1e-6 * length

    def f(xx):
        return 0.5 * beam * (1 - (2 * xx / length) ** 2) * (1 - (z / draft) ** 2)

    return (f(x + h) - f(x - h)) / (2 * h)


def _pq_quadrature(lam, k0, length, beam, draft, n=400):
    """P + iQ = int int f_x exp(k0 lam^2 z + i k0 lam x) dx dz by Gauss-Legendre."""
    xg, wg = np.polynomial.legendre.leggauss(n)
    x = 0.5 * length * xg
    wx = 0.5 * length * wg
    z = -0.5 * draft * (xg + 1)
    wz = 0.5 * draft * wg
    xx, zz = np.meshgrid(x, z, indexing="ij")
    fx = _wigley_offsets_fx(xx, zz, length, beam, draft)
    lam = np.atleast_1d(lam)
    ex = np.exp(1j * k0 * np.outer(lam, x))  # (nl, nx)
    ez = np.exp(k0 * np.outer(lam**2, z))  # (nl, nz)
    return np.sum(((ex * wx) @ fx) * ez * wz, axis=1)


@pytest.mark.parametrize("fn", [0.25, 0.35, 0.5, 0.8])
def test_wigley_closed_form_matches_direct_quadrature(fn):
    length, beam, draft = 2.0, 0.2, 0.125
    speed = fn * np.sqrt(G * length)
    k0 = G / speed**2
    theta = np.array([0.0, 0.3, 0.7, 1.0, 1.2])
    lam = 1 / np.cos(theta)
    pq = _pq_quadrature(lam, k0, length, beam, draft)
    expected = (2 * k0 / np.pi) * lam**3 * pq  # eq W5
    got = wigley_amplitude(theta, length, beam, draft, speed)
    np.testing.assert_allclose(got, expected, rtol=1e-6, atol=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize("fn", [0.3, 0.5, 1.0])
def test_havelock_form_equals_michell_integral(fn):
    """Michell's integral in the published lambda form (Michell 1898; Wehausen 1973)."""
    length, beam, draft = 1.0, 0.1, 0.0625  # the standard Wigley proportions
    speed = fn * np.sqrt(G * length)
    k0 = G / speed**2
    # lambda = cosh(u): dlambda / sqrt(lambda^2 - 1) = du
    # the integrand decays like lambda^-4 = cosh(u)^-4: beyond u = 5 it is < 1e-7 of its peak
    u = np.linspace(0.0, 5.0, 6001)
    lam = np.cosh(u)
    pq = _pq_quadrature(lam, k0, length, beam, draft, n=240)
    michell = 4 * RHO * G**2 / (np.pi * speed**2) * np.trapezoid(np.abs(pq) ** 2 * lam**2, u)
    havelock = wigley_wave_resistance(length, beam, draft, speed, rho=RHO)
    assert havelock == pytest.approx(michell, rel=1e-4)


@pytest.mark.parametrize("k0h", [0.3, 1.0, 2.5])
def test_submerged_source_matches_havelock_closed_form(k0h):
    speed, m = 2.0, 0.05  # [m/s], volume flux [m^3/s]
    k0 = G / speed**2
    depth = k0h / k0
    u = np.linspace(-6.0, 6.0, 40001)
    theta = np.arctan(np.sinh(u))
    amp = submerged_source_amplitude(theta, m, depth, speed)
    r = havelock_wave_resistance(theta, amp, speed, rho=RHO)
    # Havelock (1932): R = rho m^2 k0^2 / (4 pi) e^{-k0 h} [K0(k0 h) + K1(k0 h)]
    closed = RHO * m**2 * k0**2 / (4 * np.pi) * np.exp(-k0h) * (bessel_k0(k0h) + bessel_k1(k0h))
    assert r == pytest.approx(closed, rel=1e-4)


def test_wigley_wetted_surface_closed_limit():
    """A flat plate (B -> 0) of L x T wets 2 L T (both sides)."""
    assert wigley_wetted_surface(10.0, 1e-6, 1.0) == pytest.approx(20.0, rel=1e-9)


@settings(max_examples=25, deadline=None)
@given(
    theta=st.floats(-1.5, 1.5),
    beam=st.floats(0.1, 3.0),
    fn=st.floats(0.1, 2.0),
)
def test_amplitude_even_imaginary_and_linear_in_beam(theta, beam, fn):
    """Fore-aft symmetric hull: A purely imaginary, even in theta; thin-ship: A ~ B."""
    length, draft = 10.0, 1.0
    speed = fn * np.sqrt(G * length)
    a = wigley_amplitude(np.array([theta, -theta]), length, beam, draft, speed)
    assert np.isfinite(a).all()
    assert abs(a[0] - a[1]) <= 1e-12 * max(abs(a[0]), 1e-300)
    assert abs(a[0].real) <= 1e-12 * max(abs(a[0]), 1e-300)
    a2 = wigley_amplitude(theta, length, 2 * beam, draft, speed)
    assert a2 == pytest.approx(2 * a[0], rel=1e-12, abs=1e-300)


def test_invalid_amplitude_inputs():
    with pytest.raises(ValueError, match="speed"):
        wigley_amplitude(0.0, 10.0, 1.0, 1.0, 0.0)
    with pytest.raises(ValueError, match="theta"):
        wigley_amplitude(np.pi / 2, 10.0, 1.0, 1.0, 3.0)
