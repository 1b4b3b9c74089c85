"""Benchmark of the sea-clutter models: run as ``python benchmarks/bench_dynamics.py``.

Per-pulse cost (``Simulation.pulse`` + range compression, wall and CPU time, best / mean)
of the paper's Simulation 1 (bistatic quad-pol, ray traced; ``--grid N`` to change its
648 x 648 grid) with the sea held for all pulses (the SAR-like case, no new surface per
pulse) for the per-facet models:

0. The fused facet kernel alone on 522 242 facets (``--kernel-facets``) for the same
   models and for the evolving speckle.
1. ``blend`` without the unresolved-tilt average (the paper's facet model),
2. ``blend`` with it (eq P6, five Bragg nodes),
3. ``blend+breaking`` (eq P7) with it,

then the motion of the sea with ``blend+breaking``: held (the paper's frozen sea),
evolving with the geometry updated every ``--update`` pulses (phase centres and speckle
evolving every pulse), and evolving with a new surface every pulse. Each configuration is
timed on ``--pulses`` consecutive pulses after two warm-up pulses (JIT compilation, BVH).
The machine is shared: the load average is printed with the timings.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import os
import time
import warnings
from pathlib import Path

import numpy as np
from _memory import peak_rss_mb
from _smoke import GRID, add_option, small_scene

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


def bench_kernel(n: int, repeat: int) -> None:
    """The fused facet kernel alone (eqs P1-P7), best of ``repeat``, wall and CPU."""
    from seaecho.constants import C0
    from seaecho.geometry import frames
    from seaecho.ocean.spectra import DirectionalSpectrum
    from seaecho.scattering.dynamics import EvolvingSpeckle, SeaDynamics
    from seaecho.scattering.facet import (
        FacetModel,
        TiltQuadrature,
        circular_gaussians,
        speckled_facet_amplitudes,
    )
    from seaecho.scattering.spectrum_table import BraggSpectrumTable

    k = 2 * np.pi * 10e9 / C0
    rng = np.random.default_rng(0)
    th = rng.uniform(0.3, 1.4, n)
    n_i, n_s = frames.directions_from_angles(th, 0 * th, th, 0 * th + np.pi)
    z = rng.normal(scale=0.1, size=(n, 2))
    normal = np.concatenate([-z, np.ones((n, 1))], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=8.0)
    table = BraggSpectrumTable(spec.height_spectrum, k_min=10.0, k_max=20 * k)
    sea = FacetModel(k, 55.9 - 37.0j, table, 0.01, 0.007, 0.0)
    tq = TiltQuadrature.unscented(0.01, 0.007)
    names = ["specular", "bragg", "bragg1", "bragg2", "bragg3", "bragg4", "breaking"]
    draws = dict(zip(names, circular_gaussians(n, len(names), rng), strict=True))
    q = np.where(rng.uniform(size=n) < 0.01, 1.0, 0.0)
    dyn = SeaDynamics(lifetimes=dict.fromkeys(("specular", "bragg+", "bragg-", "breaking"),
                                              0.5),
                      velocity_covariance=np.diag([1e-3, 1e-3, 2e-3]),
                      breaker_velocity=np.array([1.1, 0.0, 0.0]), travel=None)
    evo = EvolvingSpeckle(dyn, 1, n, tilt_nodes=4, breaking=True)
    tilted = sea.with_(tilt=tq)
    cases = [("blend (the paper's facet model)", sea, {}, draws),
             ("+ unresolved-tilt average (P6)", tilted, {}, draws),
             ("+ breaking zones (P7)", tilted, {"breaking_fraction": q}, draws),
             ("+ evolving speckle (D2-D5)", tilted, {"breaking_fraction": q}, None)]
    print(f"[0] fused facet kernel alone (speckled amplitudes, Dr.Jit LLVM), {n} facets, "
          f"best of {repeat}")
    for label, model, kw, d in cases:
        times, cpus = [], []
        for r in range(repeat + 1):
            dd = evo.draws(0.01 * r) if d is None else d
            t0, c0 = time.perf_counter(), time.process_time()
            speckled_facet_amplitudes(n_i, n_s, normal, np.ones(n), model, draws=dd, **kw)
            if r:  # the first call compiles the kernel
                times.append(time.perf_counter() - t0)
                cpus.append(time.process_time() - c0)
        print(f"    {label:40s} wall {1e3 * min(times):7.1f} ms   CPU {1e3 * min(cpus):7.1f} ms"
              f"   (load {os.getloadavg()[0]:.1f})", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=None, help="grid nodes per side")
    ap.add_argument("--pulses", type=int, default=6, help="timed pulses per case")
    ap.add_argument("--update", type=int, default=16,
                    help="geometry update interval of the evolving sea [pulses]")
    ap.add_argument("--kernel-facets", type=int, default=522_242,
                    help="facets of the kernel-alone benchmark [0] (0: skip it)")
    ap.add_argument("--motion-only", action="store_true",
                    help="[2] only, against the held blend+breaking baseline (no [0], [1])")
    add_option(ap)
    a = ap.parse_args()
    if a.smoke:  # Simulation 1 on a small grid with a coarse hull trace, one pulse
        global SIM1
        SIM1 = small_scene(SIM1, pulses=10**6)
        a.grid, a.pulses, a.update, a.kernel_facets = GRID, 1, 1, 2048
    if a.kernel_facets and not a.motion_only:
        bench_kernel(a.kernel_facets, 5)
    g = a.grid or 648
    print(f"Simulation 1 (bistatic quad-pol, ray traced, {g} x {g} grid, "
          f"{2 * (g - 1) ** 2} facets), per pulse best / mean of {a.pulses}; "
          f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.1f}")
    big = a.pulses + 100
    if a.motion_only:
        print("[2] motion of the sea (blend+breaking, tilt average)")
        held = bench("held for all pulses (baseline)", a.grid, a.pulses, "blend+breaking",
                     True, "held", big)
        motion(a, held)
        return
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
    motion(a, brk)


def motion(a, held: tuple[float, float]) -> None:
    """[2]: the evolving sea and the held sea renewed every pulse against ``held``."""
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
    print(f"    new surface every pulse, evolving (the default, 'auto') / held (the former "
          f"default): {evo1[0] / held1[0]:.2f} wall, {evo1[1] / held1[1]:.2f} CPU")
    rss = peak_rss_mb()
    print(f"peak RSS {rss:.0f} MiB")


if __name__ == "__main__":
    main()
