"""Backprojection pieces: band-limited upsampling, delays and Doppler against closed forms,
and the Dr.Jit kernel against the numpy reference."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.imaging.backprojection import (
    PulseBlock,
    backproject,
    backproject_drjit,
    backproject_numpy,
    delays,
    doppler,
    upsample,
)
from seaecho.imaging.windows import AzimuthWindow
from seaecho.radar.equation import time_of_flight


def test_upsampling_is_the_band_limited_interpolation():
    # A sinc of bandwidth 0.8 f_s centred in the window: band-limited, so the upsampled
    # samples are the sinc at the intermediate times (Cumming & Wong 2005, section 2.6)
    n, b, t0 = 256, 0.8, 127.3
    m = np.arange(n)
    y = np.sinc(b * (m - t0)) * np.exp(0.3j)
    up = upsample(y, 8)
    t = np.arange(8 * n) / 8.0
    np.testing.assert_allclose(up[::8], y, atol=2e-6)
    ref = np.sinc(b * (t - t0)) * np.exp(0.3j)
    inner = (t > 40) & (t < n - 40)  # away from the ends (the sinc's tails are cut there)
    assert np.max(np.abs(up[inner] - ref[inner])) < 5e-3
    with pytest.raises(ValueError, match="upsampling factor"):
        upsample(y, 0)


def test_delays_are_the_echo_models_time_of_flight():
    rng = np.random.default_rng(3)
    x = rng.uniform(-50, 50, (7, 3))
    tx = np.array([[-900.0, -300.0, 800.0], [-900.0, -299.0, 800.0]])
    rx = np.array([[-400.0, 200.0, 300.0], [-400.0, 201.0, 300.0]])
    v = np.array([[30.0, 200.0, -5.0], [30.0, 200.0, -5.0]])
    tau = delays(x, tx, rx, v)
    for p in range(2):
        t_t, t_r, _ = time_of_flight(tx[p], x, np.zeros_like(x), rx[p], v[p])
        np.testing.assert_allclose(tau[:, p], t_t + t_r, rtol=0, atol=1e-16)
    # monostatic, receiver at rest: 2 R / c
    tau0 = delays(x, tx, tx, np.zeros_like(tx))
    np.testing.assert_allclose(tau0, 2 * np.linalg.norm(x[:, None] - tx[None], axis=-1) / C0,
                               rtol=1e-15)


def test_doppler_of_a_monostatic_squint():
    # f_D = 2 v sin(squint) / lambda for a radar flying along y (Willis 2005, eq 3.23 with
    # r_t = r_r); zero at broadside, positive ahead
    lam, v = 0.03, 150.0
    p = np.array([[-1000.0, 0.0, 0.0]])
    vel = np.array([[0.0, v, 0.0]])
    sq = np.deg2rad([0.0, 3.0, -7.0])
    x = np.stack([np.zeros(3), 1000.0 * np.tan(sq), np.zeros(3)], axis=-1)
    f = doppler(x, p, p, vel, vel, lam)[:, 0]
    np.testing.assert_allclose(f, 2 * v * np.sin(sq) / lam, atol=1e-9)


@pytest.mark.parametrize("kind", ["none", "hamming", "taylor"])
def test_drjit_kernel_matches_numpy(kind):
    rng = np.random.default_rng(7)
    n_b, n_c, n_s, u = 24, 4, 300, 8
    fs, t0, fc = 120e6, 2 * 850.0 / C0, 9.6e9  # the window cuts some pixels
    data = rng.standard_normal((n_b, n_c, n_s)) + 1j * rng.standard_normal((n_b, n_c, n_s))
    t = np.arange(n_b)[:, None]
    tx = np.array([-700.0, -200.0, 600.0]) + t * [0.0, 0.4, 0.0]
    rx = np.array([-600.0, 100.0, 500.0]) + t * [0.3, 0.3, 0.0]
    vt, vr = np.tile([0.0, 200.0, 0.0], (n_b, 1)), np.tile([150.0, 150.0, 0.0], (n_b, 1))
    # Doppler centroids near the scene centre's, so that the band (eq B4) cuts the pixels
    fdc = doppler(np.zeros((1, 3)), tx, rx, vt, vr, C0 / fc)[0] + rng.uniform(-100, 100, n_b)
    block = PulseBlock(upsample(data, u), t0, fs * u, tx, rx, vt, vr, fdc,
                       rng.uniform(0.5, 1.0, n_b))
    x = np.stack([rng.uniform(-40, 40, 500), rng.uniform(-40, 40, 500),
                  rng.uniform(-1, 1, 500)], axis=-1)
    win = AzimuthWindow.named(kind, 400.0)
    a, wa = backproject_drjit(x, block, fc, win, max_pixels=128)  # several tiles
    b, wb = backproject_numpy(x, block, fc, win)
    np.testing.assert_allclose(wa, wb, rtol=1e-5, atol=1e-5)
    assert np.all(wb[1] <= wb[0] + 1e-12) and np.any(wb[1] < wb[0])
    assert np.count_nonzero(b[0]) > 200  # most pixels inside the window and the band
    assert np.count_nonzero(b[0]) < 500  # and some cut by the band
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-5 * np.abs(b).max())
    with pytest.raises(ValueError, match="backend"):
        backproject(x, block, fc, win, backend="cuda")


def test_backprojection_on_a_gpu_without_one_is_a_clear_error(monkeypatch):
    # The kernel follows the Mitsuba variant: asking for CUDA where there is none is a
    # ValueError before any work (not a failure inside the loop).
    from seaecho import backend

    monkeypatch.setattr(backend, "cuda_available", lambda: False)
    block = PulseBlock(np.zeros((1, 1, 8), np.complex64), 0.0, 1e8, np.zeros((1, 3)),
                       np.zeros((1, 3)), np.zeros((1, 3)), np.zeros((1, 3)), np.zeros(1),
                       np.ones(1))
    with pytest.raises(ValueError, match="no CUDA GPU"):
        backproject(np.zeros((1, 3)), block, 1e10, AzimuthWindow.named("none", 100.0),
                    variant="cuda_ad_mono_polarized")
