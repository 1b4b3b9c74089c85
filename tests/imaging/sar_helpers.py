"""Small SAR scenes for the imaging tests: point targets without sea (cheap), one sea tile.

The monostatic stripmap geometry: platform at 500 m altitude and 500 m ground range west
of the origin (theta_i = 45 deg, R = 707 m), flying north at 100 m/s, PRF 500 Hz (0.2 m
between pulses), 10 GHz. The LFM pulse has B = 150 MHz, T = 4 us (time-bandwidth 600, so
that its compressed pulse is close to sinc(B t)), f_s = 180 MHz. Isotropic antennas leave
the processed aperture uniform: all N pulses, L = N v / PRF.
"""

from __future__ import annotations

import numpy as np

from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.simulation import Simulation

CARRIER = 10.0e9
WAVELENGTH = C0 / CARRIER
BANDWIDTH = 150.0e6
SPEED = 100.0
PRF = 500.0
ALTITUDE = 500.0
GROUND_RANGE = 500.0
SLANT_RANGE = float(np.hypot(ALTITUDE, GROUND_RANGE))
INCIDENCE = float(np.arctan2(GROUND_RANGE, ALTITUDE))


def radar_section(n_pulses: int, **over) -> dict:
    r = {"carrier_frequency_hz": CARRIER, "sampling_rate_hz": 180.0e6, "prf_hz": PRF,
         "n_pulses": n_pulses, "start_time_s": -0.5 * (n_pulses - 1) / PRF,
         "transmit_power_w": 100.0, "channels": ["HH", "HV", "VH", "VV"],
         "sea_clutter": False, "thermal_noise": False,
         "window_start_m": SLANT_RANGE - 40.0, "window_end_m": SLANT_RANGE + 40.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": BANDWIDTH, "duration_s": 4.0e-6}}
    r.update(over)
    return r


def point_scene(targets: list[dict], n_pulses: int = 128, antenna: dict | None = None,
                transmitter: dict | None = None, receiver: dict | None = None,
                seed: int = 1, image: dict | None = None, **radar):
    """A scene of point targets (no sea) seen by the stripmap SAR of the module docstring,
    or by the given platforms."""
    # Broadside (Doppler centroid 0): right of the north-flying platform, 45 deg down
    ant = antenna or {"pattern": "isotropic", "azimuth_deg": -90.0, "depression_deg": 45.0}
    tx = transmitter or {"motion": "linear",
                         "position_m": (-GROUND_RANGE, 0.0, ALTITUDE),
                         "velocity_m_s": (0.0, SPEED, 0.0), "antenna": ant}
    data = {
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 32.0, "nx": 32},
        "run": {"seed": seed},
        "radar": radar_section(n_pulses, **radar),
        "transmitter": tx,
        "targets": targets,
    }
    if receiver is not None:
        data["receiver"] = receiver
    if image is not None:
        data["image"] = image
    return parse_scene(data)


def simulate(scene, path) -> str:
    """Run the scene's simulation into ``path`` (netCDF) and return the path."""
    Simulation(scene).run(path, progress=False)
    return str(path)


def line(origin, direction, half_length: float, step: float) -> tuple[np.ndarray, np.ndarray]:
    """Points along a straight cut through ``origin``: (positions along it, (N, 3))."""
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    s = np.arange(-half_length, half_length + 0.5 * step, step)
    return s, np.asarray(origin, dtype=float)[None, :] + s[:, None] * d[None, :]
