"""Scaling with the sea grid: time per pulse and peak memory, 128^2 to 2048^2 nodes.

Run: ``python benchmarks/bench_scaling.py [--grids 128 256 512 1024 2048] [--pulses 4]``.

Simulation 2 (128 m tile, quad-pol, ray traced with the boat, shadowing refreshed every
0.1 s) on grids of n x n nodes (2 (n - 1)^2 facets). Each grid runs in a process of its
own: set-up (scene, sea synthesis, tracer and BVH, two warm-up pulses), then ``--pulses``
pulses with the sea held (Simulation 2 as published) and ``--pulses`` with a new sea every
pulse; wall and CPU time per pulse (pulse + range compression, median), and the process's
peak resident memory. On a shared machine the wall time is inflated; the CPU time and the
memory are the steadier figures. The load average is printed with each line.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"

CHILD = """
import json, os, resource, statistics, sys, time, warnings
warnings.simplefilter("ignore")
from seaecho.config import load_scene
from seaecho.simulation import Simulation

path, n, pulses = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
out = {"load": os.getloadavg()[0]}
for label, update in (("held", 160), ("new", 1)):
    scene = load_scene(path)
    scene = scene.model_copy(update={
        "sea": scene.sea.model_copy(update={"nx": n}),
        "radar": scene.radar.model_copy(update={"sea_update_pulses": update})})
    t0 = time.perf_counter()
    sim = Simulation(scene, base_dir=os.path.dirname(path))
    for p in (40, 41):
        sim.compress(sim.pulse(p))
    out[label + "_setup_s"] = time.perf_counter() - t0
    wall, cpu = [], []
    for p in range(42, 42 + pulses):
        w, c = time.perf_counter(), time.process_time()
        sim.compress(sim.pulse(p))
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    out[label + "_wall"] = statistics.median(wall)
    out[label + "_cpu"] = statistics.median(cpu)
    del sim
out["peak_rss_mib"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps(out))
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grids", type=int, nargs="+", default=[128, 256, 512, 1024, 2048])
    ap.add_argument("--pulses", type=int, default=4)
    add_option(ap)
    args = ap.parse_args()
    scene = SIM2
    if args.smoke:  # a small grid with a coarse hull trace, one pulse
        scene = small_scene(SIM2, pulses=10**6)
        args.grids, args.pulses = [GRID], 1
    print(f"bench_scaling: Simulation 2, quad-pol, refresh 0.1 s; {os.cpu_count()} CPUs")
    print(f"  {'grid':>6s} {'facets':>10s} | {'held sea: wall':>14s} {'CPU':>7s} | "
          f"{'new sea: wall':>13s} {'CPU':>7s} [ms/pulse] | {'set-up':>7s} "
          f"{'peak RSS':>9s} | load")
    failed = []
    for n in args.grids:
        res = subprocess.run([sys.executable, "-c", CHILD, str(scene), str(n),
                              str(args.pulses)], capture_output=True, text=True)
        if res.returncode != 0:
            print(f"  {n:6d}: failed\n{res.stderr[-2000:]}")
            failed.append(n)
            continue
        r = json.loads(res.stdout.strip().splitlines()[-1])
        facets = 2 * (n - 1) ** 2
        print(f"  {n:6d} {facets:10d} | {1e3 * r['held_wall']:14.0f} {1e3 * r['held_cpu']:7.0f}"
              f" | {1e3 * r['new_wall']:13.0f} {1e3 * r['new_cpu']:7.0f}            | "
              f"{r['held_setup_s']:6.1f}s {r['peak_rss_mib']:7.0f}MiB | {r['load']:.2f}",
              flush=True)
    if failed:
        sys.exit(f"bench_scaling: grids {failed} failed")


if __name__ == "__main__":
    main()
