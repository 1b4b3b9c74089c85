"""Cost of a traffic scene with ten ships: run as ``python benchmarks/bench_traffic.py``.

``scenes/coastal_traffic_xband.toml`` (the coastal VTS radar, X band, scanning) with its
four ships and six more (ten hulls with hull echoes: a 30 m coaster, a 25 m ferry, a 20 m
tug, three identical 15 m fishing boats, one of them turning on waypoints, and four
identical 12 m launches), at the scene's ray density (2 rays per wavelength):

1. start-up: the simulation's construction (sea, ships' wakes, hull models, trace
   schedules and the plan of shared traces);
2. the traces at the first pulse: every hull's signature, with the number of SBR traces
   made (identical hulls at the same aspect share one; ``--no-share`` traces each);
3. per pulse, once the signatures are cached: the median of ``--repeat`` pulses of the
   whole pulse and of the hull echoes alone (ten hulls' centres through the radar kernel,
   moved with their tracks and their motion in the waves), the beam away from the sea.

Timings on a shared machine are noisy: the load average (1, 5, 15 min) is printed with
them. ``--smoke`` traces at 1 ray per wavelength and times one pulse.
"""

from __future__ import annotations

import argparse
import os
import time
import warnings
from pathlib import Path

import numpy as np
from _memory import peak_rss_mb
from _smoke import RAYS_PER_WAVELENGTH, add_option

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_traffic_xband.toml"

#: The six ships added to the scene's four (positions east/north of the origin [m]).
MORE = [
    {"name": "ferry", "length_m": 25.0, "beam_m": 7.0, "draft_m": 2.0, "speed_kn": 14.0,
     "heading_deg": 200.0, "position_m": (1500.0, 1200.0)},
    {"name": "tug", "length_m": 20.0, "beam_m": 6.0, "draft_m": 2.5, "speed_kn": 9.0,
     "heading_deg": 90.0, "position_m": (3000.0, -300.0)},
    {"name": "fishing-2", "length_m": 15.0, "beam_m": 5.0, "draft_m": 1.5, "speed_kn": 8.0,
     "heading_deg": 45.0, "position_m": (1800.0, 300.0)},
    {"name": "fishing-3", "length_m": 15.0, "beam_m": 5.0, "draft_m": 1.5, "speed_kn": 8.0,
     "heading_deg": 45.0, "position_m": (1830.0, 280.0)},
    {"name": "pilot-3", "length_m": 12.0, "beam_m": 3.5, "draft_m": 1.0, "speed_kn": 15.0,
     "heading_deg": 150.0, "position_m": (2290.0, -740.0)},
    {"name": "pilot-4", "length_m": 12.0, "beam_m": 3.5, "draft_m": 1.0, "speed_kn": 15.0,
     "heading_deg": 150.0, "position_m": (2350.0, -735.0)},
]


def _load() -> str:
    return "load {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _rss_mb() -> float:
    return peak_rss_mb()


def scene(rays: float | None = None, ships: int = 10):
    """The traffic scene with ``ships`` ships (4 to 10), traced at ``rays`` per
    wavelength (None: the scene's)."""
    from seaecho.config import load_scene, parse_scene
    from seaecho.config.loading import scene_to_toml_dict

    data = scene_to_toml_dict(load_scene(SCENE))
    extra = [{**s, "hull_echo": True, "hull_rays_per_wavelength": 2.0} for s in MORE]
    data["ships"] = (data["ships"] + extra)[:ships]
    if rays is not None:
        for s in data["ships"]:
            s["hull_rays_per_wavelength"] = rays
    return parse_scene(data)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--ships", type=int, default=10, help="4 to 10")
    ap.add_argument("--no-share", action="store_true",
                    help="trace every hull (no shared traces between identical hulls)")
    add_option(ap)
    args = ap.parse_args()
    os.environ["SEAECHO_CACHE"] = "off"  # time the traces, not the disk cache
    from seaecho.simulation import Simulation

    repeat = 1 if args.smoke else args.repeat
    sc = scene(RAYS_PER_WAVELENGTH if args.smoke else None, args.ships)
    print(f"cores: {os.cpu_count()}  ships: {len(sc.all_ships)}  [{_load()}]")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t0 = time.perf_counter()
        sim = Simulation(sc, base_dir=SCENE.parent)
        t_init = time.perf_counter() - t0
        hulls = sim.hulls
        if args.no_share:
            hulls.donors = {}
        n = len(hulls.hulls)
        traced = n - sum(1 for (i, r) in hulls.donors if r == 0)
        print(f"1. start-up (sea, wakes, hull models, schedules, share plan): "
              f"{t_init:.2f} s  [{_load()}]")
        t0 = time.perf_counter()
        rays = hits = 0
        for i in range(n):
            sig = hulls.signature(i, 0)
            if hulls.donors.get((i, 0)) is None:
                rays, hits = rays + sig.n_rays, hits + sig.n_hits
        t_trace = time.perf_counter() - t0
        refreshes = sum(len(h.schedule) for h in hulls.hulls)
        print(f"2. first signatures of {n} hulls: {traced} SBR traces, {t_trace:.1f} s "
              f"({rays:,d} rays, {hits:,d} hits); refreshes over the run "
              f"{refreshes}, of which shared {len(hulls.donors)}; peak RSS "
              f"{_rss_mb():.0f} MB  [{_load()}]")
        # pulses with the beam away from the sea tile (sea skipped), served by the
        # cached signatures
        radar = sim.radar
        pulses = [p for p in range(radar.n_pulses // 4, radar.n_pulses)
                  if sim.sea_skipped(p)][:repeat]
        for p in pulses:  # their signatures (the turning boat's next trace): not timed
            for i in range(n):
                hulls.signature(i, p)
        sim.pulse(pulses[0])  # JIT of the kernels: not timed
        t_pulse, t_hull = [], []
        for p in pulses:
            geo = radar.geometry(p)
            t0 = time.perf_counter()
            sim.pulse(p)
            t1 = time.perf_counter()
            hulls.echoes(geo, p)
            t2 = time.perf_counter()
            t_pulse.append(t1 - t0)
            t_hull.append(t2 - t1)
        centres = sum(len(hulls.signature(i, pulses[0]).centres) for i in range(n))
        print(f"3. per pulse (median of {len(pulses)}, sea skipped): pulse "
              f"{np.median(t_pulse) * 1e3:.1f} ms, of which hull echoes "
              f"{np.median(t_hull) * 1e3:.1f} ms ({centres:,d} centres)  [{_load()}]")


if __name__ == "__main__":
    main()
