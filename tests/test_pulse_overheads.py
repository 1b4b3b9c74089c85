"""Per-pulse shortcuts that must not change a pulse's bytes.

Each shortcut of the Simulation 2 pulse's CPU time (docs/performance.md) is checked
against the longer way it replaces: the travelling waves kept for the kinematics of the
same time, the receive window's all-kept test by the extreme delays, the finite-output
guard on a list of channels, and no per-facet wake damping for a sea without a ship (the
damping factor sqrt(1 - 0) = 1).
"""

from __future__ import annotations

import numpy as np
import pytest

import seaecho.simulation as simulation
from seaecho.checks.guards import _finite
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.radar.echo import ReceiveWindow
from seaecho.sea import surface_kinematics
from seaecho.simulation import Simulation
from test_simulation import _raytraced_scene


def _surface() -> SeaSurface:
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=7.0, s=2.0)
    return SeaSurface(spec, (32.0, 32.0), (64, 64), np.random.default_rng(3))


def test_kept_travelling_waves_give_the_same_fields_and_kinematics():
    # The sea state and the kinematics of one time share its travelling waves: the same
    # bytes whichever is asked first, as from a surface that kept nothing
    kept = _surface()
    assert not kept.share_travelling  # a surface keeps nothing unless asked
    kept.share_travelling = True
    k1 = surface_kinematics(kept, 0.7)
    f1 = kept.fields(0.7)
    fresh = _surface()
    f2 = fresh.fields(0.7)
    assert fresh._travelling_last is None
    k2 = surface_kinematics(fresh, 0.7)
    for a, b in ((f1.elevation, f2.elevation), (f1.slope_x, f2.slope_x),
                 (f1.velocity, f2.velocity), (k1.displacement, k2.displacement),
                 (k1.acceleration, k2.acceleration)):
        assert a.tobytes() == b.tobytes()
    assert not kept.fields(0.8).elevation.tobytes() == f1.elevation.tobytes()


def test_window_keeps_all_agrees_with_the_mask():
    w = ReceiveWindow(t0=10e-6, n_samples=300, sampling_rate=100e6)
    lo, hi = w.bounds(50)
    rng = np.random.default_rng(1)
    inside = rng.uniform(lo, hi, 1000)
    inside = inside[(inside > lo) & (inside < hi)]
    for tau in (inside, np.append(inside, hi), np.append(inside, lo - 1e-9),
                np.append(inside, np.nan), inside[:0]):
        assert w.keeps_all(tau, 50) == bool(w.keep(tau, 50).all())


def test_guard_checks_a_list_of_channels_one_by_one():
    rows = [np.ones(100, complex), np.ones(100, complex)]
    assert _finite(rows)
    rows[1][7] = np.nan
    assert not _finite(rows)
    rows[1][7] = np.inf
    assert not _finite(tuple(rows))
    assert _finite([1.0, 2.0]) and not _finite([1.0, np.inf])  # plain numbers as before


@pytest.mark.slow  # two kernels compiled: about 2 s
def test_no_ship_no_damping_same_bytes(monkeypatch):
    # Without a ship the wake mask is zero: the block carries no damping (None) and the
    # pulse equals the one computed with the zero damping of every facet, to the byte
    sc = _raytraced_scene(0.0, n_pulses=2, sea_update_pulses=1)
    sim = Simulation(sc)
    assert sim._block_quantities(1, sim.surface_state(1), 1)["damping"] is None
    short = sim.pulse(1)
    monkeypatch.setattr(simulation, "_block_damping", simulation.wake_damping)
    sim = Simulation(sc)
    assert sim._block_quantities(1, sim.surface_state(1), 1)["damping"] is not None
    assert sim.pulse(1).tobytes() == short.tobytes()
