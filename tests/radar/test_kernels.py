"""The fused Dr.Jit radar kernel against the numpy reference (two independent codes)."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.radar.system import RadarSystem


def _scene(tx_ant, rx_ant, channels, roll=0.0):
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.4e9, "sampling_rate_hz": 100e6, "prf_hz": 1e3,
                  "sea_clutter": False, "channels": channels, "window_start_m": 100.0,
                  "window_end_m": 600.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 50e6, "duration_s": 1e-6}},
        "transmitter": {"motion": "linear", "position_m": (-200, 30, 150),
                        "velocity_m_s": (5, 60, -1), "roll_deg": roll, "antenna": tx_ant},
        "receiver": {"motion": "linear", "position_m": (120, -40, 40),
                     "velocity_m_s": (-3, 2, 0), "antenna": rx_ant},
    })


RECT = {"pattern": "rectangular", "width_m": 0.3, "height_m": 0.1, "look_at_m": (0, 0, 0)}
CASES = [
    (RECT, RECT, ["HH", "HV", "VH", "VV"], 0.0),
    ({**RECT, "basis": "circular", "cross_polar_isolation_db": 25.0},
     {**RECT, "basis": "slant"}, ["PR", "PL", "MR", "ML"], 7.0),
    ({"pattern": "tr38901", "look_at_m": (0, 0, 0)},
     {"pattern": "hw_dipole", "azimuth_deg": 170.0, "depression_deg": 10.0}, ["VV", "HV"],
     -12.0),
    ({"pattern": "dipole", "look_at_m": (0, 0, 0)},
     {"pattern": "isotropic", "look_at_m": (0, 0, 0), "basis": "circular"}, ["RH", "LV"],
     0.0),
]


@pytest.mark.parametrize("tx_ant,rx_ant,channels,roll", CASES)
def test_drjit_kernel_matches_numpy(tx_ant, rx_ant, channels, roll):
    sc = _scene(tx_ant, rx_ant, channels, roll)
    fast = RadarSystem(build_radar(sc), backend="drjit")
    ref = RadarSystem(build_radar(sc), backend="numpy")
    rng = np.random.default_rng(4)
    k = 5000
    p = np.column_stack([rng.uniform(-40, 40, k), rng.uniform(-40, 40, k),
                         rng.uniform(-2, 2, k)])
    p[0] = (-200, 30, 0)  # straight below the transmitter: degenerate basis
    v = rng.normal(0, 2, (k, 3))
    s = rng.normal(size=(k, 2, 2)) + 1j * rng.normal(size=(k, 2, 2))
    for pulse in (0, 7):
        geo = fast.geometry(pulse)
        a = fast.scatterer_echo(geo, p, v, s, directions=True)
        b = ref.scatterer_echo(geo, p, v, s)
        np.testing.assert_allclose(a.tau, b.tau, rtol=1e-14)
        np.testing.assert_allclose(a.r_t, b.r_t, rtol=1e-13)
        np.testing.assert_allclose(a.n_i, b.n_i, atol=1e-13)
        np.testing.assert_allclose(a.n_s, b.n_s, atol=1e-13)
        np.testing.assert_allclose(a.g_t, b.g_t, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(a.g_r, b.g_r, rtol=1e-9, atol=1e-12)
        scale = np.abs(b.amplitudes).max()
        # the carrier phase (1e4 cycles) is reduced mod 1 in the kernel: ~1e-12 rad apart
        np.testing.assert_allclose(a.amplitudes, b.amplitudes, rtol=1e-9, atol=1e-9 * scale)


@pytest.mark.parametrize("pattern", ["rectangular", "isotropic", "dipole", "hw_dipole",
                                     "tr38901"])
def test_antenna_gain_formula_agrees_between_namespaces(pattern):
    # The same gain function (eq A1 and the built-ins) on numpy and on Dr.Jit, at the
    # singular directions: boresight (sinc 0/0), along the antenna's z axis (dipole
    # nulls, 0/0 of the half-wave dipole), backwards, and random ones. Relative 1e-12.
    from seaecho import backend
    from seaecho.backend import NUMPY, Boundary
    from seaecho.radar.antennas import Antenna
    from seaecho.radar.kernels import antenna_gain

    if not backend.drjit_available():
        pytest.skip("Dr.Jit LLVM backend unavailable")
    ant = Antenna(pattern, 0.032, 0.3 if pattern == "rectangular" else None,
                  0.1 if pattern == "rectangular" else None)
    rng = np.random.default_rng(8)
    d = rng.normal(size=(300, 3))
    d[:6] = [[1, 0, 0], [0, 0, 1], [0, 0, -1], [-1, 0, 0], [0, 1, 0], [1, 1e-9, -1e-9]]
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    axes = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    axes[:, 2] *= np.linalg.det(axes)  # right-handed
    world = d @ axes.T  # so that axes^T world = d
    out = []
    for xp in (NUMPY, backend.drjit_namespace()):
        io = Boundary(xp, d.shape[0])
        (g,) = io.numpy(antenna_gain(xp, ant, io.vec3(world), axes))
        out.append(g)
    assert np.all(np.isfinite(out[1]))
    # TR 38.901's azimuth cut is undefined on its z axis (phi = atan2 of rounding noise)
    keep = np.hypot(d[:, 0], d[:, 1]) > 1e-6 if pattern == "tr38901" else slice(None)
    np.testing.assert_allclose(out[1][keep], out[0][keep], rtol=1e-12,
                               atol=1e-14 * out[0].max())
    np.testing.assert_allclose(out[0][keep], ant.gain_local(d)[keep], rtol=1e-11,
                               atol=1e-14 * out[0].max())
