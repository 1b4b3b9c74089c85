"""Benchmark of a scanning revolution: run as ``python benchmarks/bench_scan.py``.

The coastal VTS scene (``scenes/coastal_vts_xband.toml``: 2500 pulses per revolution at
24 rpm, a 256 m sea tile covering 7.3 deg of azimuth, the sea renewed every 250 pulses,
``sea_motion = "auto"`` resolving to evolving) on a ``--grid`` x ``--grid`` sea, with
the sea skipped where the beam does not reach the tile (``[radar] sea_gain_floor_db``,
``--floor-db``) and with it computed at every pulse (``"off"``).

It times every ``--stride``-th pulse of the revolution (0, s, 2 s, ...: the same mixture
of pulses in and out of the beam as the whole revolution; each pulse is a pure function
of the scene and its index), raw samples and range compression, and extrapolates to the
2500 pulses (the printed "revolution" is that extrapolation, said so). It prints wall
and CPU time, pulses per second, the pulses that skipped the sea, the process's peak
resident memory and the load average (the machine is shared: ``uptime``'s first
number). Run it niced: ``nice -n 10 python benchmarks/bench_scan.py --grid 64``.
"""

from __future__ import annotations

import argparse
import os
import time
import warnings
from pathlib import Path

import numpy as np
from _memory import peak_rss_mb
from _smoke import add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"


def scene_with_floor(path: Path, floor) -> object:
    """The scene file ``path`` with ``[radar] sea_gain_floor_db = floor``."""
    from seaecho.config import load_scene, parse_scene
    from seaecho.config.loading import scene_to_toml_dict

    data = scene_to_toml_dict(load_scene(path))
    data["radar"]["sea_gain_floor_db"] = floor
    return parse_scene(data)


def time_revolution(scene, pulses: np.ndarray) -> dict:
    """Wall and CPU time [s] of ``pulses`` of ``scene`` (one warm-up pulse first)."""
    from seaecho.simulation import Simulation

    sim = Simulation(scene)
    sim.compress(sim.pulse(int(pulses[0]))[None])  # JIT compilation, first sea state
    skipped = sum(sim.sea_skipped(int(p)) for p in pulses)
    t0, c0 = time.perf_counter(), time.process_time()
    for p in pulses:
        sim.compress(sim.pulse(int(p))[None])
    return {"wall_s": time.perf_counter() - t0, "cpu_s": time.process_time() - c0,
            "skipped": int(skipped), "n": len(pulses), "n_rev": sim.radar.n_pulses}


def coverage(path: Path, floors_db=(-60.0, -80.0)) -> None:
    """Print how the revolution's pulses stand with the beam over the tile of the scene
    file ``path`` (its own grid): the bound of ``Simulation.sea_gain_bound`` at every
    pulse (docs/scanning.md, eqs C1-C2)."""
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    sim = Simulation(load_scene(path))
    n = sim.radar.n_pulses
    b = np.array([sim.sea_gain_bound(p) for p in range(n)])
    db = 10.0 * np.log10(np.maximum(b, 1e-300))
    below = ", ".join(f"below {f:g} dB at {(db < f).sum()}" for f in floors_db)
    print(f"  beam over the tile ({path.name}, {n} pulses): bound 1 (beam plane across "
          f"the tile's box) at {(b >= 1.0).sum()} pulses, {below}; least "
          f"{db.min():.1f} dB", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=64, help="sea grid points per side")
    ap.add_argument("--stride", type=int, default=10, help="time every N-th pulse")
    ap.add_argument("--floor-db", type=float, default=-60.0,
                    help="sea_gain_floor_db of the skipping run [dB]")
    add_option(ap)
    a = ap.parse_args()
    grid, stride = (16, 1250) if a.smoke else (a.grid, a.stride)
    warnings.simplefilter("ignore")
    path = small_scene(SCENE, grid=grid, pulses=2500)
    print(f"bench_scan: {SCENE.name} on a {grid} x {grid} sea, every {stride}-th pulse of "
          f"the revolution (extrapolated x {stride}); load {os.getloadavg()[0]:.1f}",
          flush=True)
    coverage(path if a.smoke else SCENE)
    for floor in ("off", a.floor_db):
        scene = scene_with_floor(path, floor)
        pulses = np.arange(0, scene.radar.n_pulses, stride)
        r = time_revolution(scene, pulses)
        scale = r["n_rev"] / r["n"]
        print(f"  sea_gain_floor_db = {floor}: {r['n']} pulses ({r['skipped']} skip the "
              f"sea) in {r['wall_s']:.1f} s wall / {r['cpu_s']:.1f} s CPU, "
              f"{r['n'] / r['wall_s']:.1f} pulses/s; revolution (extrapolated) "
              f"{r['wall_s'] * scale:.0f} s wall / {r['cpu_s'] * scale:.0f} s CPU; "
              f"load {os.getloadavg()[0]:.1f}", flush=True)
    rss_mib = peak_rss_mb()
    print(f"  peak resident memory {rss_mib:.0f} MiB (both runs)", flush=True)


if __name__ == "__main__":
    main()
