"""A scanning radar that skips the sea outside its beam (``[radar] sea_gain_floor_db``,
docs/scanning.md) writes the serial bytes on a Dask cluster: the skip is a function of
(scene, pulse), whatever pulse a worker starts at."""

from __future__ import annotations

import warnings

import pytest

from seaecho import distributed
from seaecho.config import parse_scene
from seaecho.simulation import Simulation


def _scanning_scene():
    """A 0.5 m aperture turning at 60 rpm (3.6 deg per pulse at 100 Hz) 2 km south of a
    32 m tile, an evolving sea renewed every 3 pulses."""
    return parse_scene({
        "sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 16}, "run": {"seed": 5},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 100.0, "n_pulses": 9, "sea_update_pulses": 3,
                  "transmit_power_w": 25e3, "channels": ["HH"], "thermal_noise": True,
                  "sea_gain_floor_db": -40.0,
                  "waveform": {"kind": "pulse", "duration_s": 1e-7}},
        "transmitter": {"position_m": (0.0, -2000.0, 30.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "rectangular", "width_m": 0.5, "height_m": 0.1,
            "depression_deg": 0.9,
            "scan": {"mode": "rotating", "rate_rpm": 60.0, "start_deg": 7.0}}}})


@pytest.mark.slow
def test_skipping_scan_on_workers_writes_the_serial_bytes(tmp_path, client):
    sc = _scanning_scene()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SPM's validity at X band
        sim = Simulation(sc)
        skipped = [sim.sea_skipped(p) for p in range(9)]
        assert any(skipped) and not all(skipped)
        serial = sim.run(tmp_path / "serial.nc", progress=False)
        nc = distributed.run(sc, tmp_path / "dask.nc", client=client, block=2,
                             progress=False)
    assert nc.read_bytes() == serial.read_bytes()
