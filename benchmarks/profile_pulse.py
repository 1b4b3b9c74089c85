"""Per-stage profile of a Simulation 2 pulse: wall time and CPU time of each stage.

Run: ``python benchmarks/profile_pulse.py [--pulses 8] [--refresh 0.1] [--update 160]
[--motion held|evolving] [--model blend+breaking]``.

The stages are the functions a pulse calls, timed by wrapping them (whatever is present
in this version of the code: the same script profiles the reference path and the fused
one). Each line gives the wall time and the CPU time (``time.process_time``: every thread
of the process, so Dr.Jit's and finufft's workers count) per pulse; nested stages are
indented and included in their parent. ``--reference`` runs the reference path (one
kernel per stage, numpy between them) instead of the fused pulse
(``seaecho.radar.resident``).

Stages that run on threads of their own (the ship's wake beside the ocean's synthesis in
``Sea.state``, the next pulse's sea computed ahead as ``Simulation.pulses`` does:
``--no-prefetch`` turns that off) overlap others: their CPU time counts every thread
during their interval. ``--update 1`` draws a new sea every pulse (which the scene's
``sea_motion = "auto"`` evolves; ``--motion held`` holds it within each pulse);
``--freeze on`` replays the fused kernel with ``drjit.freeze``.

On a shared machine the wall time is inflated by the other processes; the CPU time is
the steadier figure (``docs/performance.md``). The load average is printed with it.
"""

from __future__ import annotations

import argparse
import functools
import importlib
import os
import sys
import time
import warnings
from pathlib import Path

from _memory import peak_rss_mb
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"

#: (module, attribute path, label, depth): the functions timed, where they exist.
STAGES = [
    ("seaecho.simulation", "Simulation.pulse", "pulse (end to end, no compression)", 0),
    ("seaecho.sea", "Sea.state", "sea state (ocean + wake)", 1),
    ("seaecho.ocean.surface", "SeaSurface.fields", "ocean synthesis (FFTs)", 2),
    ("seaecho.wake.kelvin", "KelvinWake.fields", "Kelvin wake", 2),
    ("seaecho.wake.turbulent", "turbulent_wake_mask", "turbulent wake mask", 2),
    ("seaecho.simulation", "Simulation._block_quantities", "speckle draws + wake mask", 1),
    ("seaecho.sea", "Sea.kinematics", "particle kinematics (evolving)", 2),
    ("seaecho.sea", "Sea.band_velocity", "breakers' band velocity (eq BR10)", 2),
    ("seaecho.scattering.dynamics", "EvolvingSpeckle.anchor", "speckle anchors (evolving)",
     2),
    ("seaecho.scattering.facet", "speckle_draws", "speckle draws (numpy)", 2),
    ("seaecho.scattering.facet", "circular_gaussians", "speckle draws, further (numpy)", 2),
    ("seaecho.rng", "facet_gaussians", "speckle draws (Philox4x32)", 2),
    ("seaecho.tracing.engine", "FacetEngine.geometry", "facet geometry (per held sea)", 1),
    ("seaecho.tracing.engine", "FacetEngine.facets", "facets (frames + visibility)", 1),
    ("seaecho.tracing.tracer", "FacetTracer.set_surface", "BVH rebuild", 2),
    ("seaecho.tracing.tracer", "FacetTracer.occluded", "shadow rays", 2),
    ("seaecho.tracing.engine", "FacetEngine.occlusion", "occlusion (refresh)", 2),
    ("seaecho.radar.resident", "ResidentSea.echo", "fused sea echo (one kernel)", 1),
    ("seaecho.radar.resident", "ResidentSea.load", "upload held sea", 2),
    ("seaecho.radar.resident", "ResidentSea._nodes", "upload nodes (per sea state)", 2),
    ("seaecho.radar.resident", "ResidentSea._terms", "trace the kernel (Python)", 2),
    ("seaecho.radar.resident", "ResidentSea._frozen_terms", "replay the frozen kernel", 2),
    ("seaecho.backend", "DrJitNamespace.count", "wait for the kernel", 2),
    ("seaecho.scattering.facet", "speckled_facet_amplitudes", "scattering P1-P4", 1),
    ("seaecho.radar.system", "RadarSystem.scatterer_echo", "radar equation", 1),
    ("seaecho.tracing.hull_echo", "HullEchoes.echoes", "hull echoes", 1),
    ("seaecho.radar.system", "RadarSystem.receive", "receive (accumulation)", 1),
    ("seaecho.radar.echo", "accumulate", "NUFFT + iFFT", 2),
    ("seaecho.simulation", "Simulation.compress", "range compression", 0),
]


class Timer:
    def __init__(self) -> None:
        self.wall: dict[str, float] = {}
        self.cpu: dict[str, float] = {}
        self.calls: dict[str, int] = {}
        self.active: set[str] = set()

    def wrap(self, label: str, fn):
        @functools.wraps(fn)
        def timed(*args, **kwargs):
            if label in self.active:  # recursion: count the outer call only
                return fn(*args, **kwargs)
            self.active.add(label)
            w, c = time.perf_counter(), time.process_time()
            try:
                return fn(*args, **kwargs)
            finally:
                self.wall[label] = self.wall.get(label, 0.0) + time.perf_counter() - w
                self.cpu[label] = self.cpu.get(label, 0.0) + time.process_time() - c
                self.calls[label] = self.calls.get(label, 0) + 1
                self.active.discard(label)
        return timed

    def reset(self) -> None:
        self.wall.clear()
        self.cpu.clear()
        self.calls.clear()


def install(timer: Timer) -> list[tuple[str, str, int]]:
    """Wrap every stage present; returns (label, where, depth) of those found."""
    found = []
    for mod_name, path, label, depth in STAGES:
        try:
            mod = importlib.import_module(mod_name)
        except ImportError:
            continue
        *owners, attr = path.split(".")
        owner = mod
        for o in owners:
            owner = getattr(owner, o, None)
        if owner is None or not hasattr(owner, attr):
            continue
        fn = getattr(owner, attr)
        setattr(owner, attr, timer.wrap(label, fn))
        if not owners:  # a module-level function: also where it was imported by name
            for other in list(sys.modules.values()):
                if (getattr(other, "__name__", "").startswith("seaecho")
                        and getattr(other, attr, None) is fn):
                    setattr(other, attr, getattr(owner, attr))
        found.append((label, f"{mod_name}.{path}", depth))
    return found


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulses", type=int, default=8)
    ap.add_argument("--refresh", type=float, default=0.1,
                    help="[tracing] refresh_interval_s [s]")
    ap.add_argument("--update", type=int, default=160, help="[radar] sea_update_pulses")
    ap.add_argument("--grid", type=int, default=None, help="grid points per side")
    ap.add_argument("--reference", action="store_true",
                    help="the reference path (numpy glue between kernels)")
    ap.add_argument("--no-prefetch", action="store_true",
                    help="without the next pulse's sea computed ahead on a thread "
                    "(Simulation.prefetch_surface, as Simulation.pulses does)")
    ap.add_argument("--nufft-precision", choices=["double", "single"], default="double",
                    help="precision of the accumulation's NUFFT (seaecho.radar.echo."
                         "accumulate; the simulation's default is double)")
    ap.add_argument("--freeze", choices=["on", "off"], default=None,
                    help="replay the fused kernel with drjit.freeze (default: "
                         "seaecho.radar.resident.FREEZE, else on for CUDA only)")
    ap.add_argument("--motion", choices=["auto", "held", "evolving"], default=None,
                    help="[scattering] sea_motion (default: the scene's; 'auto' evolves "
                    "a sea renewed within the run, e.g. --update 1)")
    ap.add_argument("--model", default=None,
                    help="[scattering] model (default: the scene's; 'blend+breaking' places "
                    "breaking zones on the vertical acceleration, which an evolving sea "
                    "then synthesises with the displacement)")
    ap.add_argument("--no-ship", action="store_true",
                    help="without the ship (its wake and hull): OceanSAR's job")
    ap.add_argument("--channels", default=None,
                    help="[radar] channels, comma-separated (e.g. HH,VV; default: the "
                    "scene's)")
    ap.add_argument("--scene", type=Path, default=None,
                    help="another scene file (default: Simulation 2)")
    ap.add_argument("--first", type=int, default=40,
                    help="first warm-up pulse; the profiled ones follow the two warm-ups")
    add_option(ap)
    args = ap.parse_args()
    global SIM2
    if args.scene is not None:
        SIM2 = args.scene.resolve()
    if args.smoke:  # Simulation 2 on a small grid with a coarse hull trace, one pulse
        SIM2 = small_scene(SIM2, pulses=10**6)
        args.grid, args.pulses = GRID, 1

    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    scene = load_scene(SIM2)
    radar = {"sea_update_pulses": args.update}
    if args.channels:
        radar["channels"] = args.channels.split(",")
    update = {"radar": scene.radar.model_copy(update=radar)}
    if args.no_ship:
        update.update(ship=None, objects=[])
    if scene.tracing is not None:
        update["tracing"] = scene.tracing.model_copy(
            update={"refresh_interval_s": args.refresh})
    if args.grid:
        update["sea"] = scene.sea.model_copy(update={"nx": args.grid})
    scattering = {} if args.motion is None else {"sea_motion": args.motion}
    if args.model is not None:
        scattering["model"] = args.model
    if scattering:
        update["scattering"] = scene.scattering.model_copy(update=scattering)
    scene = scene.model_copy(update=update)
    timer = Timer()
    found = install(timer)
    if args.nufft_precision != "double":  # the receive stage's calls, still timed
        import seaecho.radar.system as system

        system.accumulate = functools.partial(system.accumulate,
                                              precision=args.nufft_precision)
    warnings.simplefilter("ignore")
    w0, c0 = time.perf_counter(), time.process_time()
    sim = Simulation(scene, base_dir=SIM2.parent)
    if args.reference:
        sim._resident = None
    elif args.freeze is not None and hasattr(sim._resident, "freeze"):
        sim._resident.freeze = args.freeze == "on"
    first = args.first
    for p in (first, first + 1):  # compilation, BVH, lazy imports: not profiled
        sim.compress(sim.pulse(p))
    setup = (time.perf_counter() - w0, time.process_time() - c0)
    timer.reset()
    pulses = range(first + 2, first + 2 + args.pulses)
    load0 = os.getloadavg()[0]
    w0, c0 = time.perf_counter(), time.process_time()
    ahead = not args.no_prefetch and hasattr(sim, "prefetch_surface")
    for p in pulses:
        if ahead and sim.sea is not None:  # as Simulation.pulses does
            sim.surface_state(p)
            sim.prefetch_surface(p + 1)
        sim.compress(sim.pulse(p))
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    n = len(pulses)
    res = sim._resident
    path = ("reference path" if res is None else
            f"fused kernel, {'frozen' if getattr(res, 'freeze', False) else 'traced'}")
    motion = "evolving" if getattr(sim, "evolving", False) else "held"
    print(f"profile_pulse: {SIM2.stem}, {scene.sea.nx}^2 sea, refresh_interval_s = "
          f"{args.refresh:g}, sea_update_pulses = {args.update}, {motion} sea, "
          f"{'no ship, ' if args.no_ship else ''}{','.join(scene.radar.channels)}, "
          f"{scene.scattering.model}, "
          f"{n} pulses, "
          f"{path}, "
          f"NUFFT {args.nufft_precision}; "
          f"{os.cpu_count()} CPUs, load {load0:.2f} -> {os.getloadavg()[0]:.2f}")
    print(f"  set-up and 2 warm-up pulses: {setup[0]:.2f} s wall, {setup[1]:.2f} s CPU")
    print(f"  {'stage':44s} {'wall [ms]':>10s} {'CPU [ms]':>10s} {'calls':>6s}")
    for label, _, depth in found:
        if label not in timer.wall:
            continue
        name = "  " * depth + label
        print(f"  {name:44s} {1e3 * timer.wall[label] / n:10.1f} "
              f"{1e3 * timer.cpu[label] / n:10.1f} {timer.calls[label] / n:6.2f}")
    print(f"  {'per pulse, all (pulse + compression)':44s} {1e3 * wall / n:10.1f} "
          f"{1e3 * cpu / n:10.1f}")
    print(f"  peak RSS {peak_rss_mb():.0f} MiB")


if __name__ == "__main__":
    main()
