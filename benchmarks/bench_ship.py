"""Benchmark of the hull-echo stage: run as ``python benchmarks/bench_ship.py``.

1. The signature trace (SBR + PO, sea multipath) of the paper's 10 m motor boat at X band
   in Simulation 1's and Simulation 2's geometries, per refresh, at the scenes' ray
   density (4 rays per wavelength): rays launched, hits, centres, time, peak memory.
2. The same for the 80 m ship of ``scenes/ship_low_grazing_80m.toml`` at its density
   (2 rays per wavelength; ``--vessel-density`` to change it).
3. The per-pulse overhead with a cached signature (the centres through the radar kernel,
   moved rigidly) against the sea's pulse, in Simulation 2 (the SAR case: sea held for
   all pulses, shadowing re-traced every 0.1 s): medians of ``--repeat`` pulses (the
   accumulation with and without the hull interleaved three times each). The target is
   an overhead below 10 % of the sea's pulse.

Timings on a shared machine are noisy: the load average (1, 5, 15 min) is printed with
them. ``--quick`` skips the 80 m ship.

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006), "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar,
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
from _smoke import add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"
#: [[objects]] fields set in every scene (the smoke mode's coarse trace).
OBJECTS: dict = {}


def _load():
    return "load {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _rss_mb() -> float:
    return peak_rss_mb()


def _simulation(name: str, **objects):
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    scene = load_scene(SCENES / name)
    objects = {**OBJECTS, **objects}
    if objects:
        objs = tuple(o.model_copy(update=objects) for o in scene.objects)
        scene = scene.model_copy(update={"objects": objs})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Simulation(scene, base_dir=SCENES)


def bench_trace(name: str, label: str, **objects) -> None:
    sim = _simulation(name, **objects)
    hulls = sim.hulls
    sim.pulse(0)  # imports, JIT compilation, the first trace: not timed
    hulls._cache.clear()
    t = time.perf_counter()
    sig = hulls.signature(0, 0)
    dt = time.perf_counter() - t
    h = hulls.hulls[0]
    rcs = 10 * np.log10(np.maximum(sig.rcs, 1e-30))
    print(f"{label}: {h.options.rays_per_wavelength:g} rays/lambda "
          f"({sig.ray_spacing * 1e3:.2f} mm), {h.options.max_bounces} bounces, "
          f"multipath {h.multipath}")
    print(f"  trace {dt:7.2f} s  rays {sig.n_rays:>10,d}  hits {sig.n_hits:>10,d}  "
          f"centres {len(sig.centres):>8,d}  ({dt / max(sig.n_hits, 1) * 1e6:.2f} us/hit)"
          f"  peak RSS {_rss_mb():.0f} MB  [{_load()}]")
    print(f"  apparent RCS HH HV VH VV [dBsm]: {np.round(rcs, 1).tolist()}  "
          f"refreshes over the run: {len(h.schedule)}")


def bench_overhead(repeat: int) -> None:
    sim = _simulation("paper_sim2_sar_128m_wind55.toml")
    radar, hulls = sim.radar, sim.hulls
    p0 = radar.n_pulses // 2
    sim.pulse(p0)  # trace, JIT, BVH: not timed
    t_sea, t_hull, t_rsea, t_rboth = [], [], [], []
    for i in range(repeat):
        p = p0 + 1 + i  # pulses served by the same cached signature
        geo = radar.geometry(p)
        t = time.perf_counter()
        sea = sim.sea_echo(p, geo).echo
        t1 = time.perf_counter()
        hull = hulls.echoes(geo, p)
        t2 = time.perf_counter()
        for _ in range(3):  # the accumulation with and without the hull, interleaved
            t3 = time.perf_counter()
            radar.receive(p, [sea])
            t4 = time.perf_counter()
            radar.receive(p, [sea, *hull])
            t5 = time.perf_counter()
            t_rsea.append(t4 - t3)
            t_rboth.append(t5 - t4)
        t_sea.append(t1 - t)
        t_hull.append(t2 - t1)
    n = len(hulls.signature(0, p0).centres)
    med = {k: float(np.median(v)) for k, v in (("sea", t_sea), ("hull", t_hull),
                                                ("rsea", t_rsea), ("rboth", t_rboth))}
    sea_pulse = med["sea"] + med["rsea"]
    extra = med["hull"] + max(med["rboth"] - med["rsea"], 0.0)
    print(f"Simulation 2, per pulse (medians of {repeat}), cached signature of {n:,d} centres:")
    print(f"  sea: echo {med['sea'] * 1e3:.1f} ms + accumulation {med['rsea'] * 1e3:.1f} ms"
          f" = {sea_pulse * 1e3:.1f} ms")
    print(f"  hull: echo (radar kernel) {med['hull'] * 1e3:.2f} ms + extra accumulation "
          f"{max(med['rboth'] - med['rsea'], 0.0) * 1e3:.2f} ms = {extra * 1e3:.2f} ms   "
          f"overhead {100 * extra / sea_pulse:.1f} %  [{_load()}]")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="skip the 80 m ship")
    ap.add_argument("--overhead-only", action="store_true", help="only part 3")
    ap.add_argument("--vessel-density", type=float, default=None,
                    help="rays per wavelength for the 80 m ship (default: the scene's)")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # the boat of Simulation 2 on a small sea, 1 ray per wavelength, once
        global SCENES, OBJECTS
        SCENES = small_scene(SCENES / "paper_sim2_sar_128m_wind55.toml", pulses=10**6).parent
        OBJECTS = {"rays_per_wavelength": 1.0}
        bench_trace("paper_sim2_sar_128m_wind55.toml", "Boat 10 m, Simulation 2 (smoke)")
        bench_overhead(1)
        return
    print(f"cores: {os.cpu_count()}  [{_load()}]")
    if args.overhead_only:
        bench_overhead(args.repeat)
        return
    bench_trace("paper_sim1_bistatic_64m.toml", "Boat 10 m, Simulation 1 (bistatic, 20/30 deg)")
    bench_trace("paper_sim2_sar_128m_wind55.toml", "Boat 10 m, Simulation 2 (SAR, 45 deg)")
    if not args.quick:
        kw = {} if args.vessel_density is None else {"rays_per_wavelength":
                                                     args.vessel_density}
        bench_trace("ship_low_grazing_80m.toml", "Ship 80 m, low grazing (0.7 deg)", **kw)
    bench_overhead(args.repeat)


if __name__ == "__main__":
    main()
