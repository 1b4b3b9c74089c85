"""Benchmark of the radar-wide sea (``[sea] coverage = "radar"``) against the window's
range: run as ``python benchmarks/bench_coverage.py``.

The coastal VTS scene (``scenes/coastal_vts_xband.toml``: 1.0 deg Taylor fan beam 35 m
up, 24 rpm, PRF 1 kHz, 2500 pulses per revolution) with its sea laid around the radar
(finest tiles of ``--grid`` x ``--grid`` nodes at 1 m), held over blocks of the scene's
250 pulses (``[scattering] sea_motion = "held"``, said so: the tiles' unit-gain echoes
of eq U1 serve a block), a window from 300 m to 3, 6 and 12 km (``--ranges``), without
targets. For each range, in a process of its own, it times ``--pulses`` consecutive
pulses (the beam turning 0.144 deg per pulse) after one warm-up pulse (which makes every
tile of its beam), raw samples and range compression, and prints the seconds per pulse,
the CPU spent making the tiles the beam reaches (eq U1) and the rest (eq U2: gains and
the sum), the tiles and facets per pulse, the process's peak resident memory
(``VmHWM``, :func:`peak_rss_mb`) and the load average (the machine is shared:
``uptime``'s first number).

A revolution is extrapolated (said so) from the timed sector of P pulses, which the beam
crosses in P x 0.144 deg: the tiles made there times 2500 / P (every tile of the
coverage is made about once per revolution and block it meets; the sector's share of
them is its share of the azimuths), plus the tiles of the beam's bound made again at each
block's start (the warm-up pulse's), plus the per-pulse rest times the revolution's
pulses: 2500 (the scene: 10 blocks) and 1000 (the speed target's revolution, the same tiles, 4
blocks). ``--revolution N`` measures instead one whole revolution of N pulses (the antenna
turning at 60 PRF / N rpm, so that N pulses make 360 deg; the same blocks of 250 pulses)
and prints it beside the estimate of ``seaecho check`` for the same scene (``--part FIRST
COUNT``: only those pulses of it, e.g. across a block's first pulse). Run it niced:
``nice -n 10 python benchmarks/bench_coverage.py``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
import warnings
from pathlib import Path

from _memory import peak_rss_mb
from _smoke import add_option

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"


def coverage_scene(path: Path, grid: int, end_m: float, pulses: int, start_m: float = 300.0,
                   revolution: bool = False):
    """The scene file ``path`` with its sea around the radar: finest tiles ``grid`` m of
    ``grid`` nodes, the window [start_m, end_m], ``pulses`` pulses, the sea held over
    its blocks, no targets; ``revolution``: the antenna turns once over the ``pulses``
    (its rate in rpm = 60 PRF / pulses)."""
    from seaecho.config import load_scene

    sc = load_scene(path)
    if revolution:
        tx = sc.transmitter
        scan = tx.antenna.scan.model_copy(update={"rate_rpm": 60.0 * sc.radar.prf_hz / pulses})
        sc = sc.model_copy(update={"transmitter": tx.model_copy(update={
            "antenna": tx.antenna.model_copy(update={"scan": scan})})})
    return sc.model_copy(update={
        "tracing": sc.tracing.model_copy(update={"subfacet_shadowing": True}),
        "sea": sc.sea.model_copy(update={"coverage": "radar", "size_x_m": float(grid),
                                         "size_y_m": None, "nx": grid, "ny": None}),
        "radar": sc.radar.model_copy(update={"window_start_m": start_m,
                                             "window_end_m": end_m, "n_pulses": pulses}),
        "scattering": sc.scattering.model_copy(update={"sea_motion": "held"}),
        "targets": ()})


def measure(grid: int, end_m: float, pulses: int) -> dict:
    """Time ``pulses`` consecutive pulses after a warm-up one (this process)."""
    from seaecho.simulation import Simulation

    warnings.simplefilter("ignore")
    sc = coverage_scene(SCENE, grid, end_m, pulses + 1)
    t0 = time.perf_counter()
    sim = Simulation(sc)
    cov = sim.coverage
    setup = time.perf_counter() - t0
    sim.compress(sim.pulse(0)[None])
    warm = cov.making_cpu_s  # every tile of the beam's bound, as at a block's start
    tiles = [len(cov.selected(p)) for p in range(1, pulses + 1)]
    facets = [cov.facet_count(p) for p in range(1, pulses + 1)]
    made, making = cov.tiles_made, cov.making_cpu_s
    t0, c0 = time.perf_counter(), time.process_time()
    echoed = 0
    for p in range(1, pulses + 1):
        sim.compress(sim.pulse(p)[None])
        echoed += cov.facets_echoed
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    making = cov.making_cpu_s - making
    return {"end_m": end_m, "setup_s": setup, "wall_s_per_pulse": wall / pulses,
            "cpu_s_per_pulse": cpu / pulses, "making_cpu_s": making, "warm_cpu_s": warm,
            "rest_cpu_s_per_pulse": (cpu - making) / pulses, "tiles": len(cov),
            "tiles_per_pulse": sum(tiles) / pulses, "facets_per_pulse": sum(facets) / pulses,
            "facets_echoed_per_pulse": echoed / pulses, "tiles_made": cov.tiles_made - made,
            "levels_m": [lv.spacing[0] for lv in cov.patchwork.levels],
            "peak_rss_mb": peak_rss_mb(),
            "load": os.getloadavg()[0]}


def revolution(grid: int, end_m: float, pulses: int, part: tuple[int, int] | None = None
               ) -> dict:
    """One whole revolution of ``pulses`` pulses, measured (this process): wall and CPU
    time, tiles made, the CPU making them, peak RSS, the load, and the estimate of
    ``seaecho check`` (:func:`seaecho.checks.resources.estimate`) for the same scene;
    ``part`` (first, count): only those pulses of it."""
    from seaecho.checks.resources import estimate
    from seaecho.simulation import Simulation

    warnings.simplefilter("ignore")
    sc = coverage_scene(SCENE, grid, end_m, pulses, revolution=True)
    est = estimate(sc, figures=False)
    t0, c0 = time.perf_counter(), time.process_time()
    sim = Simulation(sc)
    cov = sim.coverage
    first, count = part or (0, pulses)
    for p in range(first, first + count):
        sim.compress(sim.pulse(p)[None])
    return {"end_m": end_m, "pulses": pulses, "wall_s": time.perf_counter() - t0,
            "cpu_s": time.process_time() - c0, "tiles": len(cov),
            "tiles_made": cov.tiles_made, "making_cpu_s": cov.making_cpu_s,
            "peak_rss_mb": peak_rss_mb(),
            "estimate_s": est.time_s, "estimate_mb": est.peak_bytes / 2**20,
            "load": os.getloadavg()[0]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--grid", type=int, default=128, help="finest tile nodes (at 1 m)")
    ap.add_argument("--pulses", type=int, default=10, help="consecutive pulses timed")
    ap.add_argument("--ranges", type=float, nargs="+", default=[3000.0, 6000.0, 12000.0],
                    help="window ends [m]")
    ap.add_argument("--revolution", type=int, default=0, metavar="N",
                    help="instead: one whole revolution of N pulses (the antenna turning "
                         "at 60 PRF / N rpm), measured, for each range")
    ap.add_argument("--part", type=int, nargs=2, metavar=("FIRST", "COUNT"),
                    help="with --revolution: only COUNT pulses of it from FIRST")
    ap.add_argument("--one", action="store_true", help=argparse.SUPPRESS)
    add_option(ap)
    a = ap.parse_args()
    if a.smoke:
        a.grid, a.pulses, a.ranges = 32, 1, [600.0]
    if a.one:  # a child: one range
        print(json.dumps(revolution(a.grid, a.ranges[0], a.revolution, a.part)
                         if a.revolution else measure(a.grid, a.ranges[0], a.pulses)))
        return
    if a.revolution:
        print(f"finest tiles {a.grid} m x {a.grid} nodes, window from 300 m, one revolution "
              f"of {a.revolution} pulses, each range in its own process")
        for end in a.ranges:
            part = ["--part", *map(str, a.part)] if a.part else []
            out = subprocess.run([sys.executable, __file__, "--one", "--grid", str(a.grid),
                                  "--revolution", str(a.revolution), "--ranges", str(end),
                                  *part], capture_output=True, text=True, check=True)
            r = json.loads(out.stdout.strip().splitlines()[-1])
            print(f"window to {end / 1e3:g} km: {r['tiles']} tiles, {r['tiles_made']} made "
                  f"in {r['making_cpu_s']:.1f} s CPU "
                  f"({r['making_cpu_s'] / max(r['tiles_made'], 1) * 1e3:.0f} ms each); "
                  f"{'pulses ' + str(a.part) if a.part else 'revolution'} "
                  f"{r['wall_s']:.0f} s wall / "
                  f"{r['cpu_s']:.0f} s CPU (estimate {r['estimate_s']:.0f} s); peak RSS "
                  f"{r['peak_rss_mb']:.0f} MB (estimate {r['estimate_mb']:.0f} MB); load "
                  f"{r['load']:.1f}")
        return
    print(f"finest tiles {a.grid} m x {a.grid} nodes, window from 300 m, {a.pulses} "
          "consecutive pulses after a warm-up, each range in its own process")
    for end in a.ranges:
        out = subprocess.run([sys.executable, __file__, "--one", "--grid", str(a.grid),
                              "--pulses", str(a.pulses), "--ranges", str(end)],
                             capture_output=True, text=True, check=True)
        r = json.loads(out.stdout.strip().splitlines()[-1])
        share = 2500 / a.pulses  # the sector's share of a revolution's azimuths
        # + the beam's tiles made again at each block's start (250 pulses held)
        rev = {n: r["making_cpu_s"] * share + n // 250 * r["warm_cpu_s"]
               + n * r["rest_cpu_s_per_pulse"] for n in (2500, 1000)}
        print(f"window to {end / 1e3:g} km: levels {r['levels_m']} m, {r['tiles']} tiles, "
              f"{r['tiles_per_pulse']:.1f} tiles and {r['facets_per_pulse']:.0f} facets per "
              f"pulse ({r['facets_echoed_per_pulse']:.0f} echoed), {r['tiles_made']} tiles "
              f"made over the timed pulses in {r['making_cpu_s']:.1f} s CPU (the warm-up's "
              f"{r['warm_cpu_s']:.1f} s); "
              f"{r['wall_s_per_pulse'] * 1e3:.0f} ms wall / "
              f"{r['cpu_s_per_pulse'] * 1e3:.0f} ms CPU per pulse, of which "
              f"{r['rest_cpu_s_per_pulse'] * 1e3:.0f} ms gains and sum -> extrapolated "
              f"revolution {rev[2500]:.0f} s CPU (2500 pulses), {rev[1000]:.0f} s CPU "
              f"(1000 pulses); set-up {r['setup_s']:.1f} s; peak RSS "
              f"{r['peak_rss_mb']:.0f} MB; load {r['load']:.1f}")

if __name__ == "__main__":
    main()
