"""The wind sea's particle kinematics (``seaecho.sea.surface_kinematics``).

Against the closed form: linear (Airy) waves, Lamb (1932), art. 228-229. A wave of
elevation ``z = A cos(K.r - omega t + phi)`` on water of depth d moves the surface particle
at rest position r horizontally by ``D = -(K / |K|) A coth(|K| d) sin(K.r - omega t + phi)``
and vertically by z; both oscillate at omega, so the acceleration is ``-omega^2 (D, z)``;
omega^2 = (g K + sigma K^3) tanh(K d) (eq 15). A sea of a few such waves (cells of the grid
along +K and along -K, on the kx = 0 column, a standing pair) is synthesised and compared
with the sum of the closed forms at every node, to float64 round-off.

And against the definition, to the byte: each field is the inverse real FFT of its
spectrum (``j (K / K) coth(K d) z_hat``, ``-omega^2`` times those and ``z_hat``), whatever
else is asked for in the same batched transform, and the transform worked in scratch
arrays (``SeaSurface._irfft_scratch``) gives the bytes of ``scipy.fft.irfft2``; arrays
returned are never overwritten by a later call (pooled scratch), from several threads.
"""

from __future__ import annotations

import threading

import numpy as np
import pytest
import scipy.fft

from seaecho.ocean.dispersion import angular_frequency
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.sea import _displacement_factors, surface_kinematics, vertical_acceleration

SPEC = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=7.0, s=2.0)
SHAPE = (32, 48)  # (ny, nx)
SIZE = (30.0, 40.0)  # (Lx, Ly) [m]
#: grid cells (iy, ix) in FFT order with energy: along +x, oblique, towards -y, on the
#: kx = 0 column, and the partner of the oblique one (a standing component)
CELLS = [(0, 3), (5, 2), (SHAPE[0] - 4, 1), (3, 0), (SHAPE[0] - 5, SHAPE[1] - 2)]


def _plane_wave_sea(depth: float | None) -> SeaSurface:
    psi = np.zeros(SHAPE)
    for j, cell in enumerate(CELLS):
        psi[cell] = 0.02 * (1.0 + j)  # [m^4]
    return SeaSurface(SPEC, SIZE, SHAPE, np.random.default_rng(7), depth=depth,
                      cell_spectrum=psi)


def _airy(surface: SeaSurface, t: float, depth: float | None):
    """(z, D_x, D_y) [m] and (a_x, a_y, a_z) [m/s^2] at every node: the sum of Lamb's
    art. 228 waves of the realisation's components (each half-plane cell: a wave along +K
    of complex amplitude w a and one along -K of w b, at the grid's origin); each
    particle's motion is harmonic at its wave's omega, a = -omega^2 (D, z)."""
    kx, ky, _, a, b, weight = surface.components(slope_fraction=0.0, height_fraction=0.0)
    x, y = np.meshgrid(surface.x, surface.y)
    z = np.zeros(SHAPE)
    dx, dy = np.zeros(SHAPE), np.zeros(SHAPE)
    acc = np.zeros((3, *SHAPE))
    for kx_, ky_, a_, b_, w_ in zip(kx, ky, a, b, weight, strict=True):
        k = np.hypot(kx_, ky_)
        omega = angular_frequency(k, depth)  # eq 15
        coth = 1.0 if depth is None else 1.0 / np.tanh(k * depth)
        kr = kx_ * x + ky_ * y
        for amp, sign in ((w_ * a_, 1.0), (w_ * b_, -1.0)):
            if amp == 0:
                continue
            # along sign K: z = A cos(sign K.r - omega t + phi), A e^{j phi} = amp (for
            # sign = -1 the conjugate phase: Re[b e^{j omega t} e^{j K.r}])
            phase = sign * kr - omega * t + sign * np.angle(amp)
            zw = abs(amp) * np.cos(phase)
            # Lamb art. 228: D = -(K'/|K'|) A coth(K d) sin(phase), K' = sign K
            d = -abs(amp) * coth * np.sin(phase)
            dxw, dyw = sign * kx_ / k * d, sign * ky_ / k * d
            z += zw
            dx += dxw
            dy += dyw
            acc -= omega**2 * np.stack([dxw, dyw, zw])
    return z, dx, dy, acc


@pytest.mark.parametrize("depth", [None, 1.5])
@pytest.mark.parametrize("t", [0.0, 1.37])
def test_plane_waves_follow_airy_kinematics(depth, t):
    """Lamb (1932), art. 228-229: displacement and acceleration of a few plane waves."""
    surface = _plane_wave_sea(depth)
    z, dx, dy, acc = _airy(surface, t, depth)
    scale = np.abs(z).max()
    assert scale > 0.01 and np.abs(dx).max() > 0.01  # the waves are there [m]
    np.testing.assert_allclose(surface.elevation(t), z, rtol=0, atol=1e-12 * scale)
    kin = surface_kinematics(surface, t)
    np.testing.assert_allclose(kin.displacement[..., 0], dx, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(kin.displacement[..., 1], dy, rtol=0, atol=1e-12 * scale)
    a_scale = np.abs(acc).max()
    for i in range(3):
        np.testing.assert_allclose(kin.acceleration[..., i], acc[i], rtol=0,
                                   atol=1e-12 * a_scale)
    assert kin.acceleration_z is not None
    assert kin.acceleration_z.tobytes() == np.ascontiguousarray(
        kin.acceleration[..., 2]).tobytes()


def _random_sea(**kw) -> SeaSurface:
    return SeaSurface(SPEC, (64.0, 48.0), (96, 128), np.random.default_rng(3), **kw)


@pytest.mark.parametrize("kw", [{}, {"depth": 4.0}, {"current": (0.4, -0.3)}])
def test_each_field_is_the_inverse_fft_of_its_spectrum(kw):
    # the definition, to the byte: whatever else the batched transform carries
    s = _random_sea(**kw)
    t = 0.37
    plus, minus = s._travelling(t)
    z_hat = plus + minus
    jx, jy = _displacement_factors(s)
    w2 = -s._omega ** 2
    ny, nx = s.shape

    def irfft2(spec):
        return scipy.fft.irfft2(spec, s=(ny, nx), norm="forward")

    want_d = [irfft2(jx * z_hat), irfft2(jy * z_hat)]
    want_a = [irfft2(w2 * (jx * z_hat)), irfft2(w2 * (jy * z_hat)), irfft2(w2 * z_hat)]
    full = surface_kinematics(s, t)
    vertical = surface_kinematics(s, t, acceleration="vertical")
    alone = surface_kinematics(s, t, acceleration=False)
    for kin in (full, vertical, alone):
        for i in range(2):
            assert kin.displacement[..., i].tobytes() == want_d[i].tobytes()
    for i in range(3):
        assert np.ascontiguousarray(full.acceleration[..., i]).tobytes() == want_a[i].tobytes()
    assert vertical.acceleration is None and alone.acceleration is None
    assert alone.acceleration_z is None
    assert vertical.acceleration_z.tobytes() == want_a[2].tobytes()
    assert vertical_acceleration(s, t).tobytes() == want_a[2].tobytes()
    assert surface_kinematics(s, t, np.bool_(True)).acceleration.tobytes() == \
        full.acceleration.tobytes()
    with pytest.raises(ValueError, match="acceleration"):
        surface_kinematics(s, t, acceleration="horizontal")


@pytest.mark.parametrize("dtype", [np.complex64, np.complex128])
@pytest.mark.parametrize("stack", [(), (1,), (3,), (5,)])
def test_transform_in_scratch_equals_irfft2(dtype, stack):
    s = _random_sea()
    rng = np.random.default_rng(11)
    spec = (rng.standard_normal((*stack, *s._a.shape))
            + 1j * rng.standard_normal((*stack, *s._a.shape))).astype(dtype)
    want = scipy.fft.irfft2(spec, s=s.shape, axes=(-2, -1), norm="forward")
    got = s._irfft_scratch(spec.copy())
    assert got.dtype == want.dtype and got.tobytes() == want.tobytes()


def test_returned_fields_survive_later_calls_and_threads():
    # the scratch arrays are pooled: what a call returned is never written again
    s = _random_sea()
    first = surface_kinematics(s, 0.5)
    kept = (first.displacement.copy(), first.acceleration.copy())
    f_first = s.fields(0.5, slopes=False)
    z_kept = f_first.elevation.copy()
    times = (1.0, 2.0, 3.0, 4.0)
    out: dict = {}
    threads = [threading.Thread(target=lambda t=t: out.__setitem__(
        t, surface_kinematics(s, t, acceleration="vertical"))) for t in times]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    s.fields(0.9)
    assert first.displacement.tobytes() == kept[0].tobytes()
    assert first.acceleration.tobytes() == kept[1].tobytes()
    assert f_first.elevation.tobytes() == z_kept.tobytes()
    for t in times:
        serial = surface_kinematics(s, t, acceleration="vertical")
        assert out[t].displacement.tobytes() == serial.displacement.tobytes()
        assert out[t].acceleration_z.tobytes() == serial.acceleration_z.tobytes()


def test_evolving_pulses_use_the_kinematics_computed_ahead(monkeypatch):
    # Simulation.pulses starts the next pulse's sea state and kinematics on threads
    # (prefetch_surface) before the current pulse reads its own (_block_quantities): each
    # surface's kinematics is computed once, on a thread but for the first pulse's; the
    # bytes of such pulses are those of each pulse alone (test_simulation.py, the next
    # sea computed ahead)
    from seaecho.simulation import Simulation
    from test_simulation import _raytraced_scene

    sim = Simulation(_raytraced_scene(0.0, sea_update_pulses=1))
    assert sim.evolving and sim._resident is not None
    times = []
    kinematics = sim.sea.kinematics

    def spy(t, acceleration=True):
        times.append((t, threading.current_thread() is threading.main_thread()))
        return kinematics(t, acceleration)

    monkeypatch.setattr(sim.sea, "kinematics", spy)
    for p in range(4):  # as Simulation.pulses orders them
        state = sim.surface_state(p)
        sim.prefetch_surface(p + 1)
        held = sim._block_quantities(p, state, 1)
        assert held["t"] == state.t
    sim._kinematics_ahead[sim.surface_time(4)].result()  # started by pulse 3
    assert len({t for t, _ in times}) == len(times) == 5  # once per surface
    assert sorted(main for _, main in times) == [False] * 4 + [True]
