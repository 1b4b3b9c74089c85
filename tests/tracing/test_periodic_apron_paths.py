"""The periodic apron seen by both sea paths: the fused kernel (``radar.resident``) reads
the occlusion masks that the engine traces (``FacetEngine.occlusion``), so that with
``[tracing] periodic_apron`` it returns the reference path's bytes."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from seaecho import backend
from seaecho.config import parse_scene
from seaecho.radar.resident import ResidentSea
from seaecho.simulation import Simulation
from seaecho.tracing.tracer import FacetTracer

pytestmark = pytest.mark.skipif(not backend.drjit_available(),
                                reason="Dr.Jit LLVM backend unavailable")


def _scene(apron: bool):
    # a radar 10 m up, 400 m south of a 32 m tile: grazing 1.4 deg, shadows of ~15 m
    return parse_scene({
        "sea": {"wind_speed_m_s": 9.0, "size_x_m": 32.0, "nx": 32},
        "scattering": {"sea_motion": "held"},
        "tracing": {"periodic_apron": apron},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 2, "channels": ["HH"],
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, -400.0, 10.0), "antenna": {
            "pattern": "isotropic", "azimuth_deg": 90.0, "depression_deg": 0.0}}})


@pytest.mark.slow  # a parity guard of ~2.5 s (two simulations); the apron's laws: default set
def test_fused_and_reference_paths_see_the_apron():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fused, ref = (Simulation(_scene(True)) for _ in range(2))
    ref._resident = None  # the reference path: one kernel per stage, numpy between
    assert isinstance(fused._resident, ResidentSea)
    tracer = fused.engine.tracer
    assert tracer.period_m == (32.0, 32.0)
    a, b = (s.sea_echo(1).echo for s in (fused, ref))
    np.testing.assert_array_equal(a.tau, b.tau)
    np.testing.assert_array_equal(np.stack(a.amplitudes), b.amplitudes)
    assert fused.pulse(1).tobytes() == ref.pulse(1).tobytes()
    # the masks the kernel read hide more than the tile alone does
    st = fused.surface_state(1)
    hidden = tracer.to_numpy(fused.engine.occlusion(fused.radar.geometry(1).time, st)[1])
    c, _, nrm, _ = fused.engine.geometry(st)
    alone = FacetTracer(st.x, st.y, st.elevation).occluded(
        c, nrm, fused.engine.positions(0.0)[0])
    assert hidden.sum() > alone.sum() + 20 and np.all(hidden >= alone)
