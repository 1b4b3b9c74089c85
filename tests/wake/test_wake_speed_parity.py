"""Parity of the wake's faster evaluations with the plain formulas they replace.

The Kelvin wake's elevation and both slopes come out of two non-uniform FFTs (two real
fields packed into one complex transform with the mirrored plane waves) instead of three:
checked against the exact separable sum (``method="direct"``) to the transform's
tolerance. The near-field window (eq W11) and the turbulent strip and damping (eqs
W13-W15) are evaluated on their transition band and core only: checked to the byte
against the same formulas evaluated on every grid point, here written out as in
docs/wake.md.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.wake import KelvinWake, Ship, turbulent_wake_mask, turbulent_wake_strip


def _ship(heading_deg=35.0, position=(20.0, 10.0)):
    return Ship(10.0, 4.0, 1.5, 5.144, np.deg2rad(heading_deg), position)


@pytest.mark.parametrize("t", [0.0, 2.0])
def test_packed_nufft_equals_the_direct_sum_to_its_tolerance(t):
    # The direct method sums every plane wave on every point (exact to rounding): a
    # packed field put in the wrong part (x slope for y slope) or a missing 1/2 on the
    # mirrored waves would be off by the field itself
    wake = KelvinWake(_ship())
    x = (np.arange(96) - 48) * 1.0
    y = (np.arange(80) - 40) * 1.0 + 3.0
    a = wake.fields(x, y, t, method="nufft")
    b = wake.fields(x, y, t, method="direct")
    for name in ("elevation", "slope_x", "slope_y", "dzdt"):
        ref = getattr(b, name)
        assert np.abs(ref).max() > 0.01
        np.testing.assert_allclose(getattr(a, name), ref, rtol=0,
                                   atol=1e-6 * np.abs(ref).max())


def test_plane_waves_are_kept_per_band_and_spacing():
    # The weights are a pure function of (k_cut, ds): the second call returns the same
    # values as the first, and copies (a caller writing into them changes nothing)
    wake = KelvinWake(_ship())
    th1, w1 = wake.plane_waves(5.0, 150.0)
    w1[:] = 0.0
    th2, w2 = wake.plane_waves(5.0, 150.0)
    fresh = KelvinWake(_ship()).plane_waves(5.0, 150.0)
    assert th2.tobytes() == fresh[0].tobytes() and w2.tobytes() == fresh[1].tobytes()


def test_near_field_window_equals_eq_w11_everywhere():
    wake = KelvinWake(_ship())
    xs = np.concatenate([np.linspace(-30.0, 40.0, 7001), [-5.0, 0.0, 13.0]])
    w, dw = wake.near_field_window(xs)
    span = wake.ship.length + 0.5 * wake.transverse_wavelength
    s = np.clip((xs + 0.5 * wake.ship.length) / span, 0.0, 1.0)
    inside = (s > 0.0) & (s < 1.0)
    w_ref = 0.5 * (1.0 - np.cos(np.pi * s))  # Eq W11
    dw_ref = np.where(inside, 0.5 * np.pi / span * np.sin(np.pi * s), 0.0)
    assert w.tobytes() == w_ref.tobytes() and dw.tobytes() == dw_ref.tobytes()
    assert 0 < inside.sum() < xs.size


def _dense_strip(ship, x, y, t, lt, w0):
    """Eqs W13-W14 on every grid point."""
    def step(s):
        return np.sin(0.5 * np.pi * np.clip(s, 0.0, 1.0)) ** 2

    xs, ys = ship.to_ship_frame(x[None, :], y[:, None], t)
    xi = xs - 0.5 * ship.length
    w = w0 * (1.0 + np.maximum(xi, 0.0) / w0) ** 0.2  # Eq W13
    delta = 0.25 * w
    along = step(xi / w0) * step((lt - xi) / (0.2 * lt))
    across = step((0.5 * w + 0.5 * delta - np.abs(ys)) / delta)
    return along * across, xs


@pytest.mark.parametrize(("heading_deg", "t", "lt", "w0"),
                         [(35.0, 0.0, 200.0, 4.0), (-70.0, 3.0, 37.0, 4.0),
                          (180.0, 0.4, 1000.0, 2.0)])
def test_turbulent_strip_and_mask_equal_the_dense_formulas(heading_deg, t, lt, w0):
    ship = _ship(heading_deg, (16.4, 11.5))
    x = (np.arange(300) - 150) * 0.5
    y = (np.arange(250) - 125) * 0.5 + 0.1
    strip, xs = _dense_strip(ship, x, y, t, lt, w0)
    assert 0 < np.count_nonzero(strip) < strip.size
    assert turbulent_wake_strip(ship, x, y, t, lt, w0).tobytes() == strip.tobytes()
    c_f = -3.0
    xi = np.maximum(xs - 0.5 * ship.length, 0.0)
    d_t = (1.0 + xi / w0) ** -0.6  # Eq W15
    d_f = 1.0 - 10.0 ** (c_f / 10.0)
    mask = strip * (1.0 - (1.0 - d_t) * (1.0 - d_f))
    got = turbulent_wake_mask(ship, x, y, t, lt, w0, film_contrast_db=c_f)
    assert got.tobytes() == mask.tobytes()


def _sim2_sea(nx):
    from pathlib import Path

    from seaecho.build import build_sea
    from seaecho.config import load_scene

    scene = load_scene(Path(__file__).resolve().parents[2] / "scenes"
                       / "paper_sim2_sar_128m_wind55.toml")
    return build_sea(scene.model_copy(update={"sea": scene.sea.model_copy(
        update={"nx": nx})}))


def test_sea_state_with_the_wake_on_a_thread_has_the_serial_bytes(monkeypatch):
    # Simulation 2's sea and boat on 64 x 64: the wake computed on its own thread while
    # the wind sea is synthesised gives the serial state to the byte
    from seaecho import sea as sea_module

    sea = _sim2_sea(64)
    monkeypatch.setattr(sea_module, "THREAD_MIN_NODES", 10**9)
    serial = sea.state(0.25)
    monkeypatch.setattr(sea_module, "THREAD_MIN_NODES", 1)
    threaded = sea.state(0.25)
    assert np.any(serial.wake_mask) and np.any(serial.wake_elevation)
    for name in ("elevation", "slope_x", "slope_y", "velocity", "wake_elevation",
                 "wake_mask"):
        assert getattr(threaded, name).tobytes() == getattr(serial, name).tobytes(), name


def test_an_error_of_the_wake_thread_reaches_the_caller(monkeypatch):
    from seaecho import sea as sea_module

    sea = _sim2_sea(64)
    monkeypatch.setattr(sea_module, "THREAD_MIN_NODES", 1)

    def boom(*args, **kwargs):
        raise RuntimeError("wake failed")

    monkeypatch.setattr(sea._wakes[0], "fields", boom)
    with pytest.raises(RuntimeError, match="wake failed"):
        sea.state(0.0)


def test_line_height_by_nufft_equals_the_direct_sum():
    """Parity: the crest-to-trough height along y' = +-y (the scale of the empirical
    amplitude, eq E1 against Michell's field) by a type-1 NUFFT equals the direct sum of
    eq W4 on the same line samples, to 1e-10, on both sides of the track."""
    from seaecho.wake.kelvin import KELVIN_HALF_ANGLE, _nodes

    ship = Ship(length=10.0, beam=4.0, draft=0.6, speed=5.0, heading=0.3)
    w = KelvinWake(ship)
    for k_cut, y in [(6.0, 10.0), (14.0, 25.0)]:
        theta, dtheta = _nodes(float(w.k0), k_cut, 0.01, w.taper_fraction)
        weights = w.amplitude(theta) * dtheta
        lam0 = w.transverse_wavelength
        x0 = 0.5 * ship.length + 0.5 * lam0
        xs = np.arange(x0, x0 + y / np.tan(KELVIN_HALF_ANGLE) + 8.0 * lam0,
                       0.5 * np.pi / k_cut)
        kappa = w.k0 / np.cos(theta) ** 2
        kx, ky = kappa * np.cos(theta), kappa * np.sin(theta)
        direct = []
        for side in (1.0, -1.0):
            z = (np.exp(-1j * (np.outer(xs, kx) + side * y * ky[None, :])) @ weights).real
            direct.append(z.max() - z.min())
        assert w.line_height(theta, weights, y, k_cut) == pytest.approx(max(direct),
                                                                         rel=1e-10)
