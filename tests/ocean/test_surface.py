"""Surface synthesis (eq 12) and evolution (eq 15) against the spectrum and closed forms."""

import numpy as np
import pytest

from seaecho.constants import G
from seaecho.ocean.dispersion import angular_frequency, phase_speed
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface


def _surface(spec, size=(64.0, 64.0), shape=(128, 128), seed=0, **kw):
    return SeaSurface(spec, size, shape, np.random.default_rng(seed), **kw)


@pytest.mark.parametrize("name", ["pierson-moskowitz", "jonswap", "elfouhaily"])
def test_variance_matches_resolved_integral(name):
    """E z^2 = iint over the resolved band of Psi (docs/ocean.md, synthesis).

    The sample variance of one realisation fluctuates (few independent modes carry the
    peak); over 24 seeds the standard error of the mean is ~3 % here, so 10 % is > 3 sigma.
    The resolved integral itself is checked against an independent polar quadrature.
    """
    spec = DirectionalSpectrum(name, "longuet-higgins", u19_5=6.0, fetch=50e3, s=2.0,
                               wind_direction=0.4)
    variances = [_surface(spec, seed=s).elevation(1.5).var() for s in range(24)]
    surf = _surface(spec)
    assert np.mean(variances) == pytest.approx(surf.resolved_variance, rel=0.10)
    # the square band minus the DC cell, integrated in polar coordinates
    k = np.geomspace(1e-3, np.pi / surf.dx * np.sqrt(2), 4000)[:, None]
    psi = np.linspace(-np.pi, np.pi, 1440, endpoint=False)[None, :]
    kx, ky = k * np.cos(psi), k * np.sin(psi)
    inside = (np.abs(kx) < np.pi / surf.dx - surf.dkx / 2) & (
        np.abs(ky) < np.pi / surf.dy - surf.dky / 2)
    inside &= ~((np.abs(kx) < surf.dkx / 2) & (np.abs(ky) < surf.dky / 2))
    integrand = np.where(inside, spec(kx, ky) * k, 0.0).sum(axis=1) * (2 * np.pi / 1440)
    band = np.trapezoid(integrand, k[:, 0])
    assert surf.resolved_variance == pytest.approx(band, rel=0.03)


def test_pierson_moskowitz_hs_full_band():
    """A tile and grid that hold almost the whole PM spectrum give Hs = 0.209 U^2 / g
    (Pierson & Moskowitz 1964, in the standard wavenumber form of docs/ocean.md).

    U = 3 m/s: peak wavelength 8.6 m; a 200 m tile on 256 x 256 resolves K from
    0.03 to 4 rad/m, which holds 99.8 % of the variance. 16 seeds: standard error of the
    mean variance ~2.5 %, so 8 % on the variance (4 % on Hs) is > 3 sigma.
    """
    u = 3.0
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=u)
    var = np.mean([_surface(spec, (200.0, 200.0), (256, 256), seed=s).elevation(0.0).var()
                   for s in range(16)])
    hs_closed = 2 * np.sqrt(0.0081 / 0.74) * u**2 / G
    assert 4 * np.sqrt(var) == pytest.approx(hs_closed, rel=0.04)


def test_averaged_periodogram_matches_spectrum():
    """The periodogram of generated surfaces, averaged over seeds, equals the height
    spectrum W(K) = (Psi(K) + Psi(-K)) / 2 per cell (Wiener-Khinchin; each cell's
    estimate is chi-square with 2 x 64 degrees of freedom: 12 % standard error, and
    averaging over annuli of many cells brings it to a few %)."""
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=8.0, wind_direction=1.0)
    size, n = (100.0, 100.0), (64, 64)
    acc = 0.0
    for seed in range(64):
        z = _surface(spec, size, n, seed=seed).elevation(3.0)
        acc = acc + np.abs(np.fft.fft2(z) / z.size) ** 2
    periodogram = acc / 64
    dk = 2 * np.pi / size[0]
    kx = 2 * np.pi * np.fft.fftfreq(n[0], size[0] / n[0])
    kxg, kyg = np.meshgrid(kx, kx, indexing="xy")
    expected = spec.height_spectrum(kxg, kyg) * dk * dk
    kmag = np.hypot(kxg, kyg)
    for lo, hi in [(0.2, 0.5), (0.5, 1.0), (1.0, 2.0), (2.0, 3.0)]:
        ring = (kmag >= lo) & (kmag < hi) & (np.abs(kxg) < np.pi / (size[0] / n[0]) - 1e-9)
        ring &= np.abs(kyg) < np.pi / (size[0] / n[0]) - 1e-9
        assert periodogram[ring].sum() == pytest.approx(expected[ring].sum(), rel=0.08)


def test_dispersion_deep_and_shallow_limits():
    """omega^2 = g K tanh(K d) (eq 15; Lamb 1932 art. 228): deep water omega^2 -> g K,
    shallow water omega -> K sqrt(g d)."""
    k = np.array([0.05, 0.1, 1.0])
    np.testing.assert_allclose(angular_frequency(k, depth=1e4, surface_tension=0.0) ** 2,
                               G * k, rtol=1e-12)
    np.testing.assert_allclose(angular_frequency(k, depth=None, surface_tension=0.0) ** 2,
                               G * k, rtol=1e-12)
    d = 0.01
    np.testing.assert_allclose(angular_frequency(k, depth=d, surface_tension=0.0),
                               k * np.sqrt(G * d), rtol=1e-4)
    assert phase_speed(0.0, depth=10.0) == pytest.approx(np.sqrt(G * 10.0))


def test_capillary_gravity_minimum_phase_speed():
    """With capillarity the phase speed has its minimum c_m = 0.23 m/s at k_m = 370 rad/m
    (wavelength 1.7 cm), the values Elfouhaily et al. (1997) use (their eq 29)."""
    k = np.linspace(100, 1000, 90001)
    c = phase_speed(k)
    assert k[np.argmin(c)] == pytest.approx(370.0, rel=0.01)
    assert c.min() == pytest.approx(0.23, rel=0.01)


def test_single_mode_moves_at_phase_speed():
    """A narrow downwind sea: each Fourier mode travels at omega(K) / K (eq 15).

    With s = 60 spreading the upwind-travelling partner of a downwind mode is ~1e-30 of
    it, so the mode's complex amplitude turns as exp(-j omega t); its phase advance over
    dt gives omega, which must equal sqrt(g K tanh(K d)) to 1e-6."""
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=6.0, s=60.0)
    depth = 8.0
    surf = _surface(spec, (128.0, 128.0), (64, 64), depth=depth, surface_tension=0.0)
    z0, z1 = surf.elevation(0.0), surf.elevation(0.37)
    f0, f1 = np.fft.fft2(z0), np.fft.fft2(z1)
    iy, ix = 0, 5  # K = (5 dk, 0), along the wind
    k = 5 * 2 * np.pi / 128.0
    omega = -np.angle(f1[iy, ix] / f0[iy, ix]) / 0.37
    assert omega == pytest.approx(np.sqrt(G * k * np.tanh(k * depth)), rel=1e-6)
    # in space: the crest pattern of that mode shifts by c t
    c = phase_speed(k, depth=depth, surface_tension=0.0)
    assert c == pytest.approx(omega / k, rel=1e-6)


#: Round-off of the derived fields relative to their largest spectral component: float64,
#: and float32 (an FFT of 2^16 points rounds at ~1e-7 of the field; module docstring).
ROUND_OFF = {"double": 1e-9, "single": 2e-6}


@pytest.mark.parametrize("precision", ["double", "single"])
def test_slopes_and_vertical_velocity_are_derivatives(precision):
    """Spectral slopes equal finite differences of z; w = dz/dt equals (z(t+h)-z(t-h))/2h,
    to the round-off of the precision the derived fields are synthesised in."""
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=5.0)
    surf = _surface(spec, (64.0, 64.0), (256, 256), precision=precision)
    tol = ROUND_OFF[precision]
    f = surf.fields(2.0)
    z = f.elevation
    dzdx = (np.roll(z, -1, axis=1) - np.roll(z, 1, axis=1)) / (2 * surf.dx)
    # a central difference multiplies mode K by sin(Kx dx) / (Kx dx) relative to the exact
    # derivative; undo that factor in Fourier space and compare everywhere
    kx = 2 * np.pi * np.fft.fftfreq(z.shape[1], surf.dx)[None, :]
    factor = np.sinc(kx * surf.dx / np.pi)
    np.testing.assert_allclose(np.fft.fft2(dzdx), np.fft.fft2(f.slope_x) * factor,
                               atol=tol * np.abs(np.fft.fft2(dzdx)).max())
    dy = (np.roll(z, -1, axis=0) - np.roll(z, 1, axis=0)) / (2 * surf.dy)
    ky = 2 * np.pi * np.fft.fftfreq(z.shape[0], surf.dy)[:, None]
    factor_y = np.sinc(ky * surf.dy / np.pi)
    np.testing.assert_allclose(np.fft.fft2(dy), np.fft.fft2(f.slope_y) * factor_y,
                               atol=tol * np.abs(np.fft.fft2(dy)).max())
    h = 1e-4
    dzdt = (surf.elevation(2.0 + h) - surf.elevation(2.0 - h)) / (2 * h)
    np.testing.assert_allclose(f.velocity[..., 2], dzdt, atol=1e-6 * np.abs(dzdt).max() + 1e-9)


def test_single_precision_fields_match_double():
    """Parity: the float32 synthesis of the slopes and velocities equals the float64 one
    to float32 round-off (1e-6 of each field's largest value); the elevation is float64 in
    both, bit for bit; every field is returned as float64."""
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=9.0)
    a = _surface(spec, (128.0, 128.0), (256, 256), seed=5, precision="single").fields(3.0)
    b = _surface(spec, (128.0, 128.0), (256, 256), seed=5, precision="double").fields(3.0)
    assert a.elevation.tobytes() == b.elevation.tobytes()
    for x, y in [(a.slope_x, b.slope_x), (a.slope_y, b.slope_y)] + [
            (a.velocity[..., i], b.velocity[..., i]) for i in range(3)]:
        assert x.dtype == np.float64 and x.shape == y.shape
        assert 0 < np.abs(x - y).max() < 1e-6 * np.abs(y).max()
    with pytest.raises(ValueError, match="precision"):
        _surface(spec, precision="half")


@pytest.mark.parametrize("precision", ["double", "single"])
def test_horizontal_orbital_velocity_deep_water(precision):
    """Linear deep-water waves: the surface particle speed equals omega a, the same
    magnitude as the vertical velocity (circular orbits; Lamb 1932 art. 229), so the
    horizontal and vertical velocity variances along a narrow downwind sea match."""
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=6.0, s=60.0)
    f = _surface(spec, (128.0, 128.0), (128, 128), surface_tension=0.0,
                 precision=precision).fields(1.0)
    u, v, w = f.velocity[..., 0], f.velocity[..., 1], f.velocity[..., 2]
    assert (u**2 + v**2).mean() == pytest.approx((w**2).mean(), rel=ROUND_OFF[precision])


def test_same_seed_same_bytes_and_bad_grid():
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=7.0)
    a = _surface(spec, seed=42).fields(5.0)
    b = _surface(spec, seed=42).fields(5.0)
    assert a.elevation.tobytes() == b.elevation.tobytes()
    assert a.velocity.tobytes() == b.velocity.tobytes()
    c = _surface(spec, seed=43).elevation(5.0)
    assert not np.array_equal(a.elevation, c)
    with pytest.raises(ValueError, match="even"):
        _surface(spec, shape=(63, 64))
