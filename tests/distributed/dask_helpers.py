"""A tiny sea scene for the distributed tests."""

from __future__ import annotations

from seaecho.config import parse_scene

ANT = {"pattern": "rectangular", "width_m": 0.18, "height_m": 0.14, "look_at_m": (0, 0, 0)}


def tiny_scene(seed: int = 1, n_pulses: int = 8, wind: float = 3.0, sea: bool = True,
               **radar) -> object:
    """A 4 m sea on a 64 x 64 grid seen by a bistatic X-band radar, two targets,
    thermal noise; the sea held for 3 pulses."""
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 400e6, "prf_hz": 1e3,
         "n_pulses": n_pulses, "sea_clutter": sea, "transmit_power_w": 10.0,
         "thermal_noise": True, "sea_update_pulses": 3,
         "waveform": {"kind": "lfm", "bandwidth_hz": 200e6, "duration_s": 1e-6}}
    r.update(radar)
    return parse_scene({
        "sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": wind, "size_x_m": 4.0,
                "nx": 64},
        "run": {"seed": seed},
        "tracing": {"mode": "analytic", "shadowing": "none"},
        "radar": r,
        "transmitter": {"position_m": (-93.41, 0.0, 256.65), "antenna": ANT},
        "receiver": {"position_m": (-50.75, 0.0, 87.91), "antenna": ANT},
        "targets": [{"position_m": (0.5, 0.5, 0.2), "rcs_m2": 0.01},
                    {"position_m": (-0.5, 0.0, 0.0), "velocity_m_s": (3.0, 0, 0),
                     "s_hv": (0.1, 0.0)}],
    })
