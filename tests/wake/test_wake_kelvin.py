"""Kelvin wake pattern measured from generated wake images.

Every check here measures the property from the synthesised height field (not from the
code's constants): the cusp half-angle asin(1/3) = 19.47 deg (Kelvin 1887; Newman 1977,
section 6.17), the transverse wavelength 2 pi V^2 / g and the divergent wavelength
2 pi V^2 cos^2(theta) / g (paper section IV-B), the energy per unit length of the
pattern against Parseval's theorem applied to eq W4, and the steady translation with the
ship (eqs W1, W12).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.constants import G
from seaecho.wake import KELVIN_HALF_ANGLE, KelvinWake, Ship, kelvin_crest_lines
from seaecho.warnings import SamplingWarning

SPEED = 3.0  # [m/s]: lambda_0 = 5.77 m, so the 256 m image holds ~40 transverse waves
X_SHIP = 120.0
DX = 0.5
N = 512


@pytest.fixture(scope="module")
def image():
    """A thin ship (B/L = 0.1) sailing towards +x; wake over 240 m behind it (Michell's
    heights as they are: these tests check the linear theory)."""
    ship = Ship(length=10.0, beam=1.0, draft=0.6, speed=SPEED, heading=0.0, position0=(X_SHIP, 0))
    wake = KelvinWake(ship, amplitude="michell", breaking_limit=False)
    x = (np.arange(N) - N / 2) * DX
    y = x.copy()
    f = wake.fields(x, y, 0.0)
    return wake, x, y, f


def test_kelvin_half_angle_measured_from_image(image):
    """Edge of the wedge, tracked over distance: its slope is tan(19.47 deg).

    Across a cusp line the wave envelope follows an Airy function, |Ai(-s)|, whose value
    on the geometric caustic (s = 0) is 0.355 / 0.536 = 0.66 of its maximum. The edge is
    taken where the rms envelope falls to 0.66 of its peak on the outer side; its position
    is fitted by a straight line over 60-230 m behind midship, so that the (unknown)
    virtual origin of the wedge (near the bow) drops out. Tolerance 0.3 deg: the fit
    residual and the 0.5 m pixel give ~0.1 deg.
    """
    wake, x, y, f = image
    z = f.elevation
    xs = X_SHIP - x
    lam0 = 2 * np.pi * SPEED**2 / G
    centres = np.arange(60.0, 235.0, 10.0)
    edges = []
    for xc in centres:
        band = np.abs(xs - xc) <= lam0
        rms = np.sqrt((z[:, band] ** 2).mean(axis=1))
        side = []
        for sign in (1, -1):
            m = sign * y > 0
            yy, r = np.abs(y[m]), rms[m]
            o = np.argsort(yy)
            yy, r = yy[o], r[o]
            i = np.argmax(r)
            thr = 0.66 * r[i]
            j = i + np.argmax(r[i:] < thr)
            side.append(np.interp(thr, [r[j], r[j - 1]], [yy[j], yy[j - 1]]))
        edges.append(np.mean(side))
    slope, intercept = np.polyfit(centres, np.array(edges), 1)
    angle = np.arctan(slope)
    assert np.degrees(angle) == pytest.approx(np.degrees(np.arcsin(1 / 3)), abs=0.3)
    # the wedge starts near the bow (x' = -L/2 = -5 m), not at the stern
    assert -intercept / slope == pytest.approx(-5.0, abs=3.0)


def test_no_waves_outside_the_wedge(image):
    """Energy outside 25 deg from the track (far behind the ship) is < 1 % of inside."""
    wake, x, y, f = image
    xs = X_SHIP - x
    xx = np.broadcast_to(xs[None, :], f.elevation.shape)
    yy = np.broadcast_to(y[:, None], f.elevation.shape)
    far = xx > 80
    ang = np.degrees(np.arctan2(np.abs(yy), xx + 5.0))
    inside = np.mean(f.elevation[far & (ang < KELVIN_HALF_ANGLE * 180 / np.pi)] ** 2)
    outside = np.mean(f.elevation[far & (ang > 25.0)] ** 2)
    assert outside < 0.01 * inside


def test_transverse_wavelength_measured_on_track(image):
    """Peak of the zero-padded spectrum of the centreline profile: 2 pi V^2 / g.

    On the track only theta = 0 is stationary in eq W4, so the profile is the transverse
    wave system. The 190 m profile (33 waves), Hann-windowed and zero-padded to 2^16
    points, locates the peak to ~0.1 %; tolerance 0.5 %.
    """
    wake, x, y, f = image
    xs = X_SHIP - x
    prof = f.elevation[np.argmin(np.abs(y))]
    sel = (xs > 40) & (xs < 230)
    p = prof[sel] * np.hanning(sel.sum())
    n = 1 << 16
    spec = np.abs(np.fft.rfft(p, n))
    k = 2 * np.pi * np.fft.rfftfreq(n, DX)
    lam = 2 * np.pi / k[np.argmax(spec)]
    assert lam == pytest.approx(2 * np.pi * SPEED**2 / G, rel=5e-3)


def test_transverse_wave_amplitude_and_phase_on_track_match_stationary_phase(image):
    """Far behind the ship, on the track, eq W4 by stationary phase at theta = 0
    (Kelvin 1887; Newman 1977, section 6.17):

        z(x', 0) ~ Re[A(0) sqrt(2 pi / (k0 x')) exp(-i k0 x' - i pi/4)]

    A least-squares fit of sqrt(2 pi / (k0 x')) (a cos k0 x' + b sin k0 x') to the
    centreline of the image over 100-235 m must give |a - i b| = |A(0)| (1 %; the next
    term of the expansion is O(1 / (k0 x')) ~ 0.5 %) and its phase -arg(A(0) e^{-i pi/4})
    (0.05 rad).
    """
    wake, x, y, f = image
    xs = X_SHIP - x
    k0 = G / SPEED**2
    prof = f.elevation[np.argmin(np.abs(y))]
    sel = (xs > 100) & (xs < 235)
    s = np.sqrt(2 * np.pi / (k0 * xs[sel]))
    design = np.stack([s * np.cos(k0 * xs[sel]), s * np.sin(k0 * xs[sel])], axis=1)
    (a, b), *_ = np.linalg.lstsq(design, prof[sel], rcond=None)
    a0 = complex(wake.amplitude(0.0))
    assert abs(a - 1j * b) == pytest.approx(abs(a0), rel=0.01)
    dphi = np.angle((a - 1j * b) * (a0 * np.exp(-1j * np.pi / 4)))
    assert abs(dphi) < 0.05


def test_divergent_wavelength_measured_in_a_patch(image):
    """Local spectrum 15 deg off the track: a divergent wave with lambda = lambda_0 cos^2.

    At polar angle alpha inside the wedge, stationary phase of eq W4 selects the wave
    angles tan(theta) = (1 +- sqrt(1 - 8 tan^2 alpha)) / (4 tan alpha) (Newman 1977,
    section 6.17): 57.0 deg (divergent) and 19.0 deg (transverse) at alpha = 15 deg.
    The divergent peak of the 2-D spectrum of a 24 m patch 220 m behind the ship must sit
    near that angle (+-3 deg: the patch spans alpha = 15 +- 3 deg, over which the
    stationary angle moves by several degrees, and the wedge's origin is uncertain by
    half a ship length), and its wavelength must equal 2 pi V^2 cos^2(theta) / g at the
    *measured* angle to 2 % (14 divergent wavelengths in the patch, zero-padded 10x).
    """
    wake, x, y, f = image
    alpha = np.radians(15.0)
    xc = 220.0
    ix = np.argmin(np.abs((X_SHIP - x) - xc))
    iy = np.argmin(np.abs(y - (xc + 5.0) * np.tan(alpha)))
    half = 24
    patch = f.elevation[iy - half : iy + half, ix - half : ix + half]
    win = np.outer(np.hanning(2 * half), np.hanning(2 * half))
    m = 512
    spec = np.abs(np.fft.fft2(patch * win, (m, m)))
    kk = 2 * np.pi * np.fft.fftfreq(m, DX)
    ky, kx = np.meshgrid(kk, kk, indexing="ij")
    kmag = np.hypot(kx, ky)
    k0 = G / SPEED**2
    spec[kmag < 1.6 * k0] = 0.0  # keep the divergent system (k0 sec^2 57 deg = 3.4 k0)
    i, j = np.unravel_index(np.argmax(spec), spec.shape)
    # wave angle to the track (ship sails +x, x' = -x): cos(theta) = |k_x| / |k|
    theta = np.arccos(abs(kx[i, j]) / kmag[i, j])
    t = np.tan(alpha)
    theta_sp = np.arctan((1 + np.sqrt(1 - 8 * t**2)) / (4 * t))
    assert np.degrees(theta) == pytest.approx(np.degrees(theta_sp), abs=3.0)
    lam = 2 * np.pi / kmag[i, j]
    assert lam == pytest.approx(2 * np.pi * SPEED**2 * np.cos(theta) ** 2 / G, rel=0.02)


def test_energy_per_unit_length_matches_parseval(image):
    """Mean over x' of int z^2 dy equals pi int |A|^2 / (dq/dtheta) dtheta.

    With q = k0 sec^2(theta) sin(theta) the transverse wavenumber, Parseval's theorem
    applied to eq W4 on a cut x' = const gives the mean (over x', which removes the
    cross terms) of int z^2 dy = pi int |A(theta)|^2 / (dq/dtheta) dtheta, with
    dq/dtheta = k0 (1 + sin^2 theta) / cos^3 theta (Newman 1977, section 6.18). The image
    is band-limited with a taper between 0.7 k_c and k_c: the measured value must lie
    between the predictions cut at those two wavenumbers (they differ by 2 %).
    """
    wake, x, y, f = image
    xs = X_SHIP - x
    sel = (xs > 150) & (xs < 230)  # 14 transverse wavelengths
    measured = (f.elevation[:, sel] ** 2).sum(axis=0).mean() * DX
    k0 = G / SPEED**2
    kc = 0.9 * np.pi / DX

    def predicted(k_top):
        th_max = np.arccos(np.sqrt(k0 / k_top))
        th = np.linspace(-th_max, th_max, 100001)
        dq = k0 * (1 + np.sin(th) ** 2) / np.cos(th) ** 3
        return np.pi * np.trapezoid(np.abs(wake.amplitude(th)) ** 2 / dq, th)

    lo, hi = predicted(0.7 * kc), predicted(kc)
    assert lo * 0.995 <= measured <= hi * 1.005


def test_nufft_and_direct_synthesis_agree():
    ship = Ship(10.0, 4.0, 1.5, 5.144, np.deg2rad(35.0), (20.0, 10.0))
    wake = KelvinWake(ship)
    x = (np.arange(96) - 48) * 1.0
    y = (np.arange(80) - 40) * 1.0 + 3.0
    a = wake.fields(x, y, 2.0, method="nufft")
    b = wake.fields(x, y, 2.0, method="direct")
    scale = np.abs(b.elevation).max()
    assert scale > 0.05
    for name in ("elevation", "slope_x", "slope_y", "dzdt"):
        ref = getattr(b, name)
        np.testing.assert_allclose(getattr(a, name), ref, atol=1e-5 * np.abs(ref).max())


def test_wake_moves_with_the_ship():
    """z(r, t) = z(r - V t, 0): shift the grid with the ship (eqs W1, W12)."""
    heading = np.deg2rad(35.0)
    ship = Ship(10.0, 4.0, 1.5, 5.144, heading, (0.0, 0.0))
    wake = KelvinWake(ship, k_max=3.0)
    x = np.linspace(-80, 20, 101)
    y = np.linspace(-70, 30, 91)
    t = 7.3
    d = ship.velocity * t
    moved = wake.fields(x + d[0], y + d[1], t, method="direct")
    ref = wake.fields(x, y, 0.0, method="direct")
    scale = np.abs(ref.elevation).max()
    np.testing.assert_allclose(moved.elevation, ref.elevation, atol=1e-6 * scale)
    np.testing.assert_allclose(moved.dzdt, ref.dzdt, atol=1e-6 * np.abs(ref.dzdt).max())
    # and the pattern really moved: at fixed points it changed
    still = wake.fields(x, y, t, method="direct")
    assert np.abs(still.elevation - ref.elevation).max() > 0.3 * scale


def test_dzdt_and_slopes_match_finite_differences():
    """dz/dt (eq W12) against a centred time difference; slopes against d/dx, d/dy."""
    ship = Ship(10.0, 4.0, 1.5, 5.144, np.deg2rad(35.0), (10.0, 5.0))
    wake = KelvinWake(ship, k_max=2.0)
    x = np.linspace(-60, 0, 61)
    y = np.linspace(-50, 0, 51)
    t, dt = 1.0, 1e-3
    f = wake.fields(x, y, t, method="direct")
    zp = wake.fields(x, y, t + dt, method="direct").elevation
    zm = wake.fields(x, y, t - dt, method="direct").elevation
    scale = np.abs(f.dzdt).max()
    np.testing.assert_allclose(f.dzdt, (zp - zm) / (2 * dt), atol=1e-4 * scale)
    h = 1e-4
    zxp = wake.fields(x + h, y, t, method="direct").elevation
    zxm = wake.fields(x - h, y, t, method="direct").elevation
    zyp = wake.fields(x, y + h, t, method="direct").elevation
    zym = wake.fields(x, y - h, t, method="direct").elevation
    sx = np.abs(f.slope_x).max()
    np.testing.assert_allclose(f.slope_x, (zxp - zxm) / (2 * h), atol=1e-5 * sx)
    np.testing.assert_allclose(f.slope_y, (zyp - zym) / (2 * h), atol=1e-5 * sx)


def test_nothing_ahead_of_the_bow_and_symmetric_about_the_track():
    ship = Ship(10.0, 2.0, 1.0, 4.0, 0.0, (0.0, 0.0))
    wake = KelvinWake(ship)
    x = (np.arange(256) - 128) * 0.5
    y = (np.arange(256) - 128) * 0.5
    f = wake.fields(x, y, 0.0)
    assert np.all(f.elevation[:, x > 5.0] == 0.0)
    # y -> -y: grid y[1:] is symmetric about 0
    z = f.elevation[1:]
    np.testing.assert_allclose(z, z[::-1], atol=1e-6 * np.abs(z).max())  # NUFFT eps 1e-7


def test_crest_lines_eq16_envelope_is_kelvin_angle():
    """Eq 16 (corrected): the crest curves' envelope makes asin(1/3) with the track and
    consecutive transverse crests are 2 pi V^2 / g apart (Newman 1977, section 6.17)."""
    theta = np.linspace(0, np.pi / 2, 200001)
    x, y = kelvin_crest_lines(3, 5.0, theta)
    assert np.max(np.arctan2(y, x)) == pytest.approx(np.arcsin(1 / 3), abs=1e-8)
    x1, _ = kelvin_crest_lines(1, 5.0, 0.0)
    x2, _ = kelvin_crest_lines(2, 5.0, 0.0)
    assert x2 - x1 == pytest.approx(2 * np.pi * 25.0 / G, rel=1e-12)


def test_zero_speed_and_unresolvable_grid():
    ship0 = Ship(10.0, 2.0, 1.0, 0.0)
    x = np.linspace(-10, 10, 16)
    assert np.all(KelvinWake(ship0).fields(x, x, 3.0).elevation == 0)
    fast = Ship(10.0, 2.0, 1.0, 15.0)  # lambda_0 = 144 m
    coarse = np.linspace(-500, 500, 11)  # 100 m cells
    with pytest.warns(SamplingWarning, match="cannot resolve"):
        f = KelvinWake(fast).fields(coarse, coarse, 0.0)
    assert np.all(f.elevation == 0)


def test_bad_arguments():
    ship = Ship(10.0, 2.0, 1.0, 4.0)
    with pytest.raises(ValueError, match="k_max"):
        KelvinWake(ship, k_max=-1.0)
    wake = KelvinWake(ship)
    with pytest.raises(ValueError, match="method"):
        wake.fields(np.arange(8.0), np.arange(8.0), 0.0, method="fft")
    with pytest.raises(ValueError, match="uniformly"):
        wake.fields(np.array([0.0, 1.0, 3.0, 4.0]), np.arange(4.0), 0.0, method="nufft")


@settings(max_examples=15, deadline=None)
@given(
    heading=st.floats(-np.pi, np.pi),
    px=st.floats(-40.0, 40.0),
    py=st.floats(-40.0, 40.0),
    fn=st.floats(0.3, 1.0),  # resolved on the 1 m grid: k0 = 0.1 / fn^2 < 0.7 k_c
    t=st.floats(0.0, 10.0),
)
def test_fields_finite_and_zero_ahead_of_the_bow(heading, px, py, fn, t):
    """Any heading, position, speed and time: finite fields, zero ahead of the bow (W11),
    and dz/dt = -V . grad z (W12) exactly."""
    ship = Ship(10.0, 1.0, 0.6, fn * np.sqrt(G * 10.0), heading, (px, py))
    x = (np.arange(64) - 32) * 1.0
    f = KelvinWake(ship).fields(x, x, t)
    for a in (f.elevation, f.slope_x, f.slope_y, f.dzdt):
        assert a.shape == (64, 64) and np.isfinite(a).all()
    xs, _ = ship.to_ship_frame(x[None, :], x[:, None], t)
    assert np.all(f.elevation[xs <= -5.0] == 0.0)
    vx, vy = ship.velocity
    np.testing.assert_allclose(f.dzdt, -(vx * f.slope_x + vy * f.slope_y), atol=1e-15)
