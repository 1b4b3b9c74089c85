"""Lines of sight: a target behind a wave crest, a hull below the horizon.

References: the geometry of a straight ray over a regular wave crest (the line from the
antenna tangent to the crest profile); the radar horizon sqrt(2 k a)(sqrt(h1) + sqrt(h2))
(eq E2 of seaecho.geometry.earth; Skolnik, *Introduction to Radar Systems*, 3rd ed.
2001, chapter 8) and the hidden height (d - sqrt(2 k a h1))^2 / (2 k a) beyond the
horizon (the tangent ray's height above the sphere at the distance d - sqrt(2 k a h1)
past its tangent point, eq E3).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from seaecho.geometry.earth import SphericalEarth, effective_radius, horizon_range
from seaecho.tracing.hull_echo import horizon_mask
from seaecho.tracing.scene import segments_blocked
from seaecho.tracing.tracer import FacetTracer

R43 = effective_radius(4.0 / 3.0)


def test_target_behind_a_regular_wave_crest_is_hidden_and_above_it_seen():
    # one wavelength of a regular wave, crest H = 2 m at x = 0, troughs at +-L/2; the
    # antenna 10 m up, 300 m before the crest (grazing over the crest ~1.5 deg)
    lam, h_crest, h_radar, x_r = 100.0, 2.0, 10.0, -300.0
    k = 2 * np.pi / lam
    x = np.linspace(-lam / 2, lam / 2, 801)
    y = np.linspace(-10.0, 10.0, 41)

    def z(u):
        return 0.5 * h_crest * (1 + np.cos(k * u))

    def dz(u):
        return -0.5 * h_crest * k * np.sin(k * u)

    tracer = FacetTracer(x, y, np.broadcast_to(z(x), (y.size, x.size)).copy())
    # the line from the antenna tangent to the crest profile: touches it at x* where
    # (z(x*) - h) / (x* - x_r) = z'(x*); a target at x_t is hidden below that line
    xs = brentq(lambda u: (z(u) - h_radar) / (u - x_r) - dz(u), 0.0, lam / 4)
    x_t = lam / 2  # the next trough
    z_star = h_radar + dz(xs) * (x_t - x_r)
    psi = np.degrees(np.arctan(-dz(xs)))
    assert 1.0 < psi < 2.0 and 0.3 < z_star < 1.0
    radar = np.array([x_r, 0.0, h_radar])
    targets = np.array([[x_t, 0.0, z_star - 0.02], [x_t, 0.0, z_star + 0.02],
                        [x_t, 0.0, z_star + 1.0]])
    hidden = segments_blocked([tracer.sea.mi_scene], radar, targets)
    assert hidden.tolist() == [True, False, False]


@pytest.mark.parametrize("h_target", [0.0, 10.0])
def test_hull_centre_just_inside_and_beyond_the_horizon(h_target):
    earth = SphericalEarth(R43)
    tx = earth.position(np.array([0.0, 0.0, 25.0]))
    d_h = float(horizon_range(25.0, h_target, R43))  # eq E2
    pts = np.array([[0.995 * d_h, 0.0, h_target], [1.005 * d_h, 0.0, h_target]])
    on, seen = horizon_mask(earth, pts, tx, tx)
    assert seen.tolist() == [True, False]
    assert on == pytest.approx(earth.position(pts))


def test_hull_part_below_the_horizon_line_is_hidden():
    # a mast 5 km beyond the 25 m antenna's sea-level horizon: the part below the hidden
    # height (d - sqrt(2 k a h1))^2 / (2 k a) = 1.47 m is hidden, the rest seen
    earth = SphericalEarth(R43)
    tx = earth.position(np.array([0.0, 0.0, 25.0]))
    d = float(horizon_range(25.0, 0.0, R43)) + 5000.0
    hidden_height = (d - np.sqrt(2 * R43 * 25.0)) ** 2 / (2 * R43)
    z = hidden_height * np.array([0.9, 0.98, 1.02, 1.5, 5.0])
    pts = np.column_stack([np.zeros(5), np.full(5, d), z])
    _, seen = horizon_mask(earth, pts, tx, tx)
    assert hidden_height == pytest.approx(1.47, abs=0.01)
    assert seen.tolist() == [False, False, True, True, True]
    # a sea-bounce centre (delay-equivalent position below the sea) is tested by |z|
    _, seen = horizon_mask(earth, pts * [1, 1, -1], tx, tx)
    assert seen.tolist() == [False, False, True, True, True]


@pytest.mark.slow
def test_a_traced_hull_beyond_the_horizon_is_silent():
    """A 0.5 m trihedral (SBR) 2 m up at 0.8 and 1.2 horizon ranges of a 25 m antenna on the
    4/3 Earth: heard inside, silent beyond (its whole height below the horizon line)."""
    d_h = float(horizon_range(25.0, 2.5, R43))

    def echoes(d, earth="spherical"):
        sim = _reflectors(d, earth, (0.0,))
        return sim.hulls.echoes(sim.radar.geometry(0), 0)

    assert len(echoes(0.8 * d_h)) == 1  # hidden height 0.35 m: the reflector is seen
    assert echoes(1.2 * d_h) == []
    assert len(echoes(1.2 * d_h, "flat")) == 1  # the Earth hides it, not the trace


def _reflectors(d: float, earth: str, xs: tuple[float, ...]):
    """A 25 m isotropic antenna looking north and 0.5 m trihedrals (SBR, no sea multipath)
    2 m up at ``(x, d)`` [m] for each x of ``xs``: the Simulation, its disk cache off."""
    from pathlib import Path

    from seaecho.config import parse_scene
    from seaecho.simulation import Simulation
    from seaecho.targets.cache import ArrayCache

    mesh = str(Path(__file__).resolve().parents[2] / "scenes" / "meshes"
               / "trihedral_0p5m.ply")
    scene = parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 1, "sea_clutter": False,
                  "thermal_noise": False, "channels": ["HH"],
                  "window_start_m": d - 200.0, "window_end_m": d + 200.0,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, 0.0, 25.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "propagation": {"earth": earth},
        "objects": [{"name": f"reflector{i}", "file": mesh, "position_m": (x, d, 2.0),
                     "orientation_deg": (-90.0, 35.26, 45.0), "scatterer": True,
                     "sea_multipath": False} for i, x in enumerate(xs)]})
    sim = Simulation(scene)
    sim.hulls.disk_cache = ArrayCache.disabled()
    return sim


def test_every_hull_is_heard_after_one_on_the_sphere():
    """Two 0.5 m trihedrals (SBR) inside the horizon of a 25 m antenna on the 4/3 Earth:
    both echo (the horizon mask of the first hull once rebound the name of the beams'
    test, so that the second hull called an array: TypeError)."""
    sim = _reflectors(0.6 * float(horizon_range(25.0, 2.5, R43)), "spherical",
                      (-50.0, 50.0))
    assert len(sim.hulls.echoes(sim.radar.geometry(0), 0)) == 2
    assert len(sim.hulls.echoes(sim.radar.geometry(0), 0, seen=lambda corners: True)) == 2
