"""Sea states whose slopes are synthesised only when read (seaecho.sea.LazySlopes).

A ray-traced pulse meshes the sea from its heights and never reads the slopes, so a
simulation in ray-traced mode asks for its sea states with ``lazy_slopes``: the slopes
(wind sea plus the Kelvin wakes) are synthesised when first read, and must be the bytes
of the state computed with them, from any thread and after pickling.
"""

import pickle
import threading

import numpy as np
import pytest

from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.sea import LazySlopes, Sea
from seaecho.simulation import Simulation
from seaecho.wake import Ship
from test_simulation import _raytraced_scene

FIELDS = ("elevation", "slope_x", "slope_y", "velocity", "wake_elevation", "wake_mask")


def _sea(ship: bool) -> Sea:
    spec = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=7.0, s=2.0)
    surface = SeaSurface(spec, (64.0, 64.0), (64, 64), np.random.default_rng(5))
    boat = Ship(length=10.0, beam=4.0, draft=1.5, speed=5.0, heading=0.6,
                position0=(0.0, 0.0)) if ship else None
    return Sea(surface, ship=boat)


def test_lazy_slopes_are_the_bytes_of_the_eager_state():
    for ship in (False, True):
        sea = _sea(ship)
        for t in (0.0, 0.45):
            eager, lazy = sea.state(t), sea.state(t, lazy_slopes=True)
            assert isinstance(lazy.slopes, LazySlopes)
            for name in FIELDS:
                assert getattr(eager, name).tobytes() == getattr(lazy, name).tobytes(), name
            again = pickle.loads(pickle.dumps(sea.state(t, lazy_slopes=True)))
            assert again.slope_y.tobytes() == eager.slope_y.tobytes()


def test_lazy_slopes_read_from_several_threads():
    sea = _sea(True)
    eager, lazy = sea.state(0.2), sea.state(0.2, lazy_slopes=True)
    out: list = []
    threads = [threading.Thread(target=lambda: out.append(lazy.slope_x)) for _ in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert all(a is out[0] for a in out)  # synthesised once
    assert out[0].tobytes() == eager.slope_x.tobytes()


@pytest.mark.slow  # a kernel compiled: about 3 s
def test_raytraced_simulation_reads_no_slopes():
    sim = Simulation(_raytraced_scene(0.0, n_pulses=2, sea_update_pulses=1))
    assert sim._lazy_slopes
    sim.pulse(1)
    st = sim.surface_state(1)
    assert isinstance(st.slopes, LazySlopes) and st.slopes._value is None
