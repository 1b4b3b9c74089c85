"""Benchmark of multistatic runs: run as ``python benchmarks/bench_multistatic.py``.

What a receiver adds to a run of one transmitter and several receivers
(``[[receivers]]``, docs/multistatic.md), against a whole bistatic run. On
``scenes/multistatic_ship_3rx.toml`` (64 m sea on 256 x 256, 4 channels, ray traced,
occlusion refreshed every 0.1 s), with the sea renewed every pulse (``sea_update_pulses
= 1``, as Simulation 1: the shared work counts most) and held over the aperture (the
scene's 128: the SAR case):

1. CPU time per pulse of the scene with its first 1, 2 and 3 receivers, and of the three
   receivers' bistatic runs one after the other (nothing shared): the incremental cost of
   a receiver is ``(T(3) - T(1)) / 2``; a whole run is ``T(1)``.
2. The shared work, timed alone once per sea update or occlusion refresh: the sea's
   synthesis (``Sea.state``: spectrum, wake, the surface's FFTs), the facets' geometry,
   the speckle draws (``facet_gaussians`` of the ``speckle``, ``speckle-tilt`` and
   ``breaking`` streams), and the transmitter's occlusion trace (BVH build and shadow
   rays).

CPU time (``time.process_time``, all threads) is reported, as the machine is shared; the
load average is printed. ``--smoke``: a 16 m tile on 64 x 64, 3 pulses, seconds.

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

from _smoke import add_option

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "multistatic_ship_3rx.toml"


def _load() -> str:
    return "load {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _scene(n_receivers: int, update: int, pulses: int, smoke: bool):
    from seaecho.config import load_scene, with_overrides

    sc = load_scene(SCENE)
    changes = {"radar.n_pulses": pulses, "radar.start_time_s": 0.0,
               "radar.sea_update_pulses": min(update, pulses), "radar.sigma_map_pulse": 0}
    if smoke:
        changes.update({"sea.size_x_m": 16.0, "sea.nx": 64, "ship.position_m": [1.0, 0.7],
                        "targets.0.position_m": [1.0, 0.7, 1.0]})
    sc = with_overrides(sc, changes)
    return sc.model_copy(update={"receivers": sc.receivers[:n_receivers]})


def _per_pulse(sim, pulses: int) -> float:
    """CPU seconds per pulse of ``sim.pulses`` over pulses 1..n-1 (pulse 0 warms up)."""
    sim.pulses(0, 1)
    t = time.process_time()
    sim.pulses(1, pulses)
    return (time.process_time() - t) / (pulses - 1)


def bench_receivers(update: int, pulses: int, smoke: bool) -> dict:
    from seaecho.build import receiver_scene
    from seaecho.multistatic import simulation_of

    out = {}
    for n in (1, 2, 3):
        out[n] = _per_pulse(simulation_of(_scene(n, update, pulses, smoke), SCENE.parent), pulses)
    sc = _scene(3, update, pulses, smoke)
    out["separate"] = sum(_per_pulse(simulation_of(receiver_scene(sc, i), SCENE.parent), pulses)
                          for i in range(3))
    return out


def bench_shared(smoke: bool) -> dict:
    """CPU seconds of each piece of shared work, once."""
    from seaecho.multistatic import simulation_of
    from seaecho.rng import facet_gaussians

    sim = simulation_of(_scene(3, 1, 2, smoke), SCENE.parent)
    lead = sim.receivers[0]
    sim.pulses(0, 1)  # warm up (kernels compiled, tracer built)
    out = {}
    t = time.process_time()
    st = lead.sea.state(1.0e-3)
    out["sea synthesis (Sea.state)"] = time.process_time() - t
    engine = lead.engine
    t = time.process_time()
    centroid, _, normal, _ = engine.geometry(st)
    out["facet geometry"] = time.process_time() - t
    n = centroid.shape[0]
    model = lead.sea_model
    xp = lead._draw_namespace()
    draws = [("speckle", 2)]
    if model.tilt is not None:
        draws.append(("speckle-tilt", len(model.tilt.slopes)))
    if model.breaking is not None:
        draws.append(("breaking", 1))
    for block in (98, 99):  # the first compiles the kernels for these sizes
        t = time.process_time()
        for stream, k in draws:
            facet_gaussians(n, k, lead.radar.seed, stream, block, xp=xp)
        out["speckle draws"] = time.process_time() - t
    tracer = engine.tracer
    t = time.process_time()
    tracer.set_surface(st.elevation)
    out["sea BVH build"] = time.process_time() - t
    tx = lead.radar.tx.state(1.0e-3).position
    t = time.process_time()
    tracer.to_numpy(tracer.occluded(centroid, normal, tx, device=True))
    out["transmitter occlusion rays"] = time.process_time() - t
    return out


def main(argv: list[str] | None = None) -> dict:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_option(p)  # --smoke: a 16 m tile on 64 x 64, 3 pulses, seconds
    p.add_argument("--pulses", type=int, default=None, help="pulses timed per case + 1")
    args = p.parse_args(argv)
    pulses = args.pulses or (3 if args.smoke else 6)
    warnings.simplefilter("ignore")
    print(f"bench_multistatic ({'smoke' if args.smoke else SCENE.name}), {_load()}")
    results = {}
    for label, update in (("sea renewed every pulse", 1), ("sea held", 10_000)):
        r = bench_receivers(update, pulses, args.smoke)
        inc = (r[3] - r[1]) / 2
        print(f"  {label}: CPU per pulse, 1 receiver {1e3 * r[1]:.1f} ms, 2: "
              f"{1e3 * r[2]:.1f} ms, 3: {1e3 * r[3]:.1f} ms; the 3 bistatic runs one "
              f"after the other {1e3 * r['separate']:.1f} ms; a receiver adds "
              f"{1e3 * inc:.1f} ms ({100 * inc / r[1]:.0f} % of a whole run)")
        results[label] = r
    shared = bench_shared(args.smoke)
    print("  shared work, once per sea update / occlusion refresh (CPU): " + ", ".join(
        f"{k} {1e3 * v:.1f} ms" for k, v in shared.items()))
    print(f"  {_load()}")
    results["shared"] = shared
    return results


if __name__ == "__main__":
    main()
