"""Identical hulls share traces (seaecho.tracing.hull_echo, module docstring).

Exact case: two identical boats placed so that the second one's geometry is the first
one's turned by 90 deg about the vertical through the radar see the same signature up to
that rotation (the scattering matrix in FSA bases does not change under a rotation about
the vertical): the shared trace gives the second boat the RCS and the echo its own trace
gives, and the run traces one hull instead of two.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.config import parse_scene
from seaecho.simulation import Simulation


def _boat(name, position, heading):
    return {"name": name, "length_m": 8.0, "beam_m": 2.5, "draft_m": 0.8, "speed_kn": 6.0,
            "heading_deg": heading, "position_m": position, "hull_echo": True,
            "kelvin_wake": False}


def _scene(ships):
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 32.0, "nx": 32},
        "ships": ships,
        "radar": {"carrier_frequency_hz": 1.3e9, "sampling_rate_hz": 50e6, "prf_hz": 500.0,
                  "n_pulses": 3, "sea_clutter": False, "thermal_noise": False,
                  "channels": ["HH", "VV"], "window_start_m": 250.0, "window_end_m": 350.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 40e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": (0.0, 0.0, 30.0),
                        "antenna": {"pattern": "isotropic", "look_at_m": (300.0, 0.0, 0.0)}},
    })


@pytest.fixture
def no_disk_cache(monkeypatch):
    monkeypatch.setenv("SEAECHO_CACHE", "off")


@pytest.mark.slow
def test_a_rotated_twin_takes_the_first_hulls_trace(no_disk_cache):
    ships = [_boat("a", (300.0, 0.0), 90.0), _boat("b", (0.0, 300.0), 180.0)]
    shared = Simulation(_scene(ships))
    assert shared.hulls.donors == {(1, 0): (0, 0)}
    own = Simulation(_scene(ships))
    own.hulls.donors = {}
    sa, so = shared.hulls.signature(1, 0), own.hulls.signature(1, 0)
    # the same scattering centres (positions within the float rounding of the rotation)
    order_a = np.lexsort(np.round(sa.centres.position, 6).T)
    order_o = np.lexsort(np.round(so.centres.position, 6).T)
    np.testing.assert_allclose(sa.centres.position[order_a], so.centres.position[order_o],
                               atol=1e-6)
    # amplitudes within the single-precision ray casts (1e-5 of the largest)
    scale = np.abs(so.centres.s).max()
    np.testing.assert_allclose(sa.centres.s[order_a], so.centres.s[order_o], rtol=0,
                               atol=1e-4 * scale)
    for p in range(3):
        a, b = shared.pulse(p), own.pulse(p)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-4 * np.abs(b).max())


def test_the_rotated_twin_is_planned_to_share(no_disk_cache):
    ships = [_boat("a", (300.0, 0.0), 90.0), _boat("b", (0.0, 300.0), 180.0)]
    assert Simulation(_scene(ships)).hulls.donors == {(1, 0): (0, 0)}


def test_no_sharing_across_different_hulls_or_aspects(no_disk_cache):
    # another size, or the same boat seen broadside instead of bow-on: own traces
    ships = [_boat("a", (300.0, 0.0), 90.0), {**_boat("b", (0.0, 300.0), 180.0),
                                              "length_m": 9.0}]
    assert Simulation(_scene(ships)).hulls.donors == {}
    ships = [_boat("a", (300.0, 0.0), 90.0), _boat("b", (0.0, 300.0), 90.0)]
    assert Simulation(_scene(ships)).hulls.donors == {}


def test_a_hull_in_the_way_keeps_its_own_trace(no_disk_cache):
    # the second boat right behind the first on the line of sight: same aspect, but the
    # first one is near its legs to the radar
    ships = [_boat("a", (280.0, 0.0), 90.0), _boat("b", (320.0, 0.0), 90.0)]
    sim = Simulation(_scene(ships))
    assert not sim.hulls._free(1, 0)
    assert sim.hulls.donors == {}


@pytest.mark.slow
def test_a_hull_outside_the_beams_is_skipped(no_disk_cache):
    # [radar] sea_gain_floor_db applies to each hull: a boat behind a 2 m antenna looking
    # the other way has no echo; with the floor off it has one
    def scene(floor):
        d = _scene([_boat("a", (300.0, 0.0), 90.0)]).model_dump(exclude_unset=True)
        d["radar"]["sea_gain_floor_db"] = floor
        d["transmitter"]["antenna"] = {"pattern": "rectangular", "width_m": 2.0,
                                       "height_m": 0.5, "look_at_m": (-300.0, 0.0, 0.0)}
        return parse_scene(d)

    on, off = Simulation(scene(-60.0)), Simulation(scene("off"))
    geo = on.radar.geometry(0)
    assert on.hulls.echoes(geo, 0, seen=on._hull_seen(0)) == []
    assert off._hull_seen(0) is None
    assert len(off.hulls.echoes(geo, 0)) == 1
    assert np.abs(on.pulse(0)).max() == 0.0  # no noise, nothing else in the scene
