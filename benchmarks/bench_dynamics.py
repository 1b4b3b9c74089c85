"""Benchmark of the sea-clutter models: run as ``python benchmarks/bench_dynamics.py``.

Per-pulse cost (``Simulation.pulse`` + range compression, wall and CPU time, best / mean)
of the paper's Simulation 1 (bistatic quad-pol, ray traced; ``--grid N`` to change its
648 x 648 grid) with the sea held for all pulses (the SAR-like case, no new surface per
pulse) for the per-facet models:

1. ``blend`` without the unresolved-tilt average (the paper's facet model),
2. ``blend`` with it (eq P6, five Bragg nodes),
3. ``blend+breaking`` (eq P7) with it,

then the motion of the sea with ``blend+breaking``: held (the paper's frozen sea),
evolving with the geometry updated every ``--update`` pulses (phase centres and speckle
evolving every pulse), and evolving with a new surface every pulse. Each configuration is
timed on ``--pulses`` consecutive pulses after two warm-up pulses (JIT compilation, BVH).
The machine is shared: the load average is printed with the timings.
"""

from __future__ import annotations

import argparse
import os
import resource
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"


def _scene(grid: int | None, n: int, model: str, tilt: bool, motion: str, update: int):
    from seaecho.config import load_scene

    sc = load_scene(SIM1)
    upd = {"radar": sc.radar.model_copy(update={"n_pulses": n, "sea_update_pulses": update}),
           "scattering": sc.scattering.model_copy(update={
               "model": model, "unresolved_tilt": tilt, "sea_motion": motion})}
    if grid is not None:
        upd["sea"] = sc.sea.model_copy(update={"nx": grid})
    return sc.model_copy(update=upd)


def bench(label: str, grid: int | None, pulses: int, model: str, tilt: bool, motion: str,
          update: int) -> tuple[float, float]:
    from seaecho.simulation import Simulation

    n = pulses + 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(_scene(grid, n, model, tilt, motion, update), base_dir=SIM1.parent)
        for p in range(2):
            sim.compress(sim.pulse(p))
        wall, cpu = [], []
        for p in range(2, n):
            t0, c0 = time.perf_counter(), time.process_time()
            sim.compress(sim.pulse(p))
            wall.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
    w, c = np.array(wall), np.array(cpu)
    print(f"    {label:52s} wall {1e3 * w.min():7.0f} / {1e3 * w.mean():7.0f} ms   "
          f"CPU {1e3 * c.min():7.0f} / {1e3 * c.mean():7.0f} ms   "
          f"(load {os.getloadavg()[0]:.1f})", flush=True)
    return float(np.mean(w)), float(np.mean(c))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=None, help="grid nodes per side")
    ap.add_argument("--pulses", type=int, default=6, help="timed pulses per case")
    ap.add_argument("--update", type=int, default=16,
                    help="geometry update interval of the evolving sea [pulses]")
    a = ap.parse_args()
    g = a.grid or 648
    print(f"Simulation 1 (bistatic quad-pol, ray traced, {g} x {g} grid, "
          f"{2 * (g - 1) ** 2} facets), per pulse best / mean of {a.pulses}; "
          f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.1f}")
    big = a.pulses + 100
    print("[1] per-facet models, sea held for all pulses")
    base = bench("blend, no unresolved-tilt average (paper)", a.grid, a.pulses, "blend",
                 False, "held", big)
    tilt = bench("blend + unresolved-tilt average (eq P6)", a.grid, a.pulses, "blend", True,
                 "held", big)
    brk = bench("blend+breaking + tilt average (eqs P6-P7)", a.grid, a.pulses,
                "blend+breaking", True, "held", big)
    print(f"    breaking on: {100 * (brk[0] / tilt[0] - 1):+.0f} % wall, "
          f"{100 * (brk[1] / tilt[1] - 1):+.0f} % CPU; tilt average: "
          f"{100 * (tilt[0] / base[0] - 1):+.0f} % wall, {100 * (tilt[1] / base[1] - 1):+.0f} % "
          "CPU")
    print("[2] motion of the sea (blend+breaking, tilt average)")
    held = brk
    evo = bench(f"evolving, geometry every {a.update} pulses", a.grid, a.pulses,
                "blend+breaking", True, "evolving", a.update)
    evo1 = bench("evolving, new surface every pulse", a.grid, a.pulses, "blend+breaking",
                 True, "evolving", 1)
    held1 = bench("held, new surface every pulse (white speckle)", a.grid, a.pulses,
                  "blend+breaking", True, "held", 1)
    print(f"    evolving / held: {evo[0] / held[0]:.2f} wall, {evo[1] / held[1]:.2f} CPU; "
          f"evolving every pulse / held: {evo1[0] / held[0]:.2f} wall, "
          f"{evo1[1] / held[1]:.2f} CPU (held with a new surface per pulse: "
          f"{held1[0] / held[0]:.2f})")
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"peak RSS {rss:.0f} MiB")


if __name__ == "__main__":
    main()
