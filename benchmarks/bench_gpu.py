"""Per-pulse time of Simulation 2 on a CUDA GPU (the device-resident pulse).

Run on a machine with an NVIDIA GPU, Mitsuba's ``cuda_ad_mono_polarized`` variant and
cufinufft (``pip install cufinufft``, or ``pip install seaecho[gpu]``)::

    python benchmarks/bench_gpu.py [--pulses 50] [--refresh 0.1] [--update 160]

What it does:

1. builds Simulation 2 (512 x 512 sea, quad-pol, ray traced) with ``[tracing] variant =
   "cuda_ad_mono_polarized"``: the facet geometry, visibility, scattering, radar equation
   and the NUFFT accumulation of each pulse run on the GPU
   (``seaecho.radar.resident.ResidentSea``, ``seaecho.radar.echo.accumulate_cuda``); only
   the pulse's samples come back;
2. times ``--pulses`` pulses (pulse + range compression, as ``Simulation.run``) after
   ``--warmup`` pulses (kernel compilation, BVH, first uploads), and prints the median,
   minimum and maximum per pulse, the stage table of ``benchmarks/profile_pulse.py``
   (stage times include the GPU work they wait for), and Dr.Jit's kernel history: GPU
   time of the JIT kernels per pulse;
3. runs the same pulses on the CPU (``llvm_ad_mono_polarized``) in a second process and
   compares: the samples must agree to the NUFFT tolerance (cufinufft sums with atomic
   additions, so not bit for bit), and the CPU time per pulse is printed beside.

Target: <= 5 ms per pulse on one H100 for this size (refresh and sea update as given).

Two more measurements, each in a process of its own (one Mitsuba variant per process):

- ``--sbr``: the boat's SBR hull trace of Simulation 2 (no signature cache) on the
  variant of ``--variant`` (default: CUDA when there is a GPU), traced twice in the
  process (the first with the kernels' compilation, the second with the kernels
  cached), at the default ray batch and at ``--sbr-batch``; printed: wall and CPU time,
  the time in ray casts, in shadow rays and the rest (numpy), and Dr.Jit's kernel
  history (launches, compilations and their time);
- ``--scan``: the coastal revolution (``scenes/coastal_vts_xband.toml``, 2500 pulses at
  24 rpm) on the variant: every ``--stride``-th pulse timed and the time extrapolated to
  the revolution, as ``benchmarks/bench_scan.py`` does; real time is 2.5 s.

``--save DIR`` keeps the GPU pulses' samples (``gpu_freeze{0,1}.npy``) for a comparison
with the CPU's on another machine (``--child llvm_ad_mono_polarized FILE`` there).
"""

from __future__ import annotations

import argparse
import functools
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"
SCAN = ROOT / "scenes" / "coastal_vts_xband.toml"
sys.path.insert(0, str(Path(__file__).resolve().parent))


def _device() -> str:
    try:
        out = subprocess.run(["nvidia-smi", "--query-gpu=name,memory.total,driver_version",
                              "--format=csv,noheader"], capture_output=True, text=True,
                             timeout=20)
        return out.stdout.strip() or "unknown GPU"
    except (OSError, subprocess.SubprocessError):
        return "unknown GPU (no nvidia-smi)"


def _simulation(variant: str, refresh: float, update: int):
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    scene = load_scene(SIM2)
    scene = scene.model_copy(update={
        "tracing": scene.tracing.model_copy(update={"variant": variant,
                                                    "refresh_interval_s": refresh}),
        "radar": scene.radar.model_copy(update={"sea_update_pulses": update})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Simulation(scene, base_dir=SIM2.parent)


#: Stages timed beside ``profile_pulse.STAGES`` (the GPU path's own).
GPU_STAGES = [
    ("seaecho.radar.replay", "FrozenEchoTerms.__call__", "radar equation replayed", 2),
    ("seaecho.radar.system", "RadarSystem.device_echo", "echo kept on the device", 2),
    ("seaecho.radar.echo", "accumulate_cuda_sets", "cufinufft, all sets + iFFT", 2),
]


def _synchronised(timer, variant: str) -> None:
    """Make ``timer``'s stages wait for the device before they start and before they end
    (``--sync-stages``): each stage then holds its own GPU work, not that of the stages
    before it that it waits for at its first read-back (the pulse takes longer)."""
    import drjit as dr

    from seaecho.backend import cuda_synchronize

    sync = cuda_synchronize if variant.startswith("cuda") else dr.sync_thread
    plain = timer.wrap

    def wrap(label, fn):
        def ended(*args, **kwargs):
            try:
                return fn(*args, **kwargs)
            finally:
                sync()

        timed = plain(label, ended)

        @functools.wraps(fn)
        def started(*args, **kwargs):
            sync()
            return timed(*args, **kwargs)
        return started

    timer.wrap = wrap


def run(variant: str, pulses: int, warmup: int, refresh: float, update: int,
        out: str | None, profile: bool, freezes: tuple = (None,),
        sync_stages: bool = False) -> list[dict]:
    """Time the pulses of one variant in this process, once per entry of ``freezes``
    (the fused kernel traced, False, or replayed, True; None: as the environment says),
    the same pulses each time; save the samples to ``out`` (``{freeze}`` in it replaced
    by 0 or 1); ``sync_stages``: :func:`_synchronised` stages."""
    import numpy as np

    timer = None
    if profile:
        import profile_pulse

        saved = profile_pulse.STAGES
        profile_pulse.STAGES = saved + GPU_STAGES
        timer = profile_pulse.Timer()
        if sync_stages:
            _synchronised(timer, variant)
        found = profile_pulse.install(timer)
        profile_pulse.STAGES = saved
    t0 = time.perf_counter()
    sim = _simulation(variant, refresh, update)
    import drjit as dr

    first = 40
    results = []
    for freeze in freezes:
        t1 = time.perf_counter()
        if freeze is not None and sim._resident is not None:
            sim._resident.freeze = freeze
        if freeze is not None:  # the scatterers' radar equation (the hull's) likewise
            sim.radar.freeze = freeze
        for p in range(first, first + warmup):
            sim.compress(sim.pulse(p))
        setup = time.perf_counter() - (t0 if not results else t1)
        if timer is not None:
            timer.reset()
        dr.set_flag(dr.JitFlag.KernelHistory, True)
        dr.kernel_history()
        wall, cpu, samples = [], [], []
        for p in range(first + warmup, first + warmup + pulses):
            w, c = time.perf_counter(), time.process_time()
            raw = sim.pulse(p)
            sim.compress(raw)
            wall.append(time.perf_counter() - w)
            cpu.append(time.process_time() - c)
            samples.append(raw)
        history = dr.kernel_history()
        dr.set_flag(dr.JitFlag.KernelHistory, False)
        kernels: dict[str, float] = {}
        for k in history:
            name = str(k["type"]).split(".")[-1]
            kernels[name] = kernels.get(name, 0.0) + float(k.get("execution_time", 0.0))
        frozen = bool(sim._resident is not None and sim._resident.freeze)
        if out:
            np.save(out.replace("{freeze}", str(int(frozen))), np.stack(samples))
        stages = []
        if timer is not None:
            stages = [(label, 1e3 * timer.wall[label] / pulses, depth)
                      for label, _, depth in found if label in timer.wall]
        results.append({"variant": variant, "setup_s": setup, "wall": wall, "cpu": cpu,
                        "freeze": frozen, "launches": len(history) / pulses,
                        "freeze_error": getattr(sim._resident, "freeze_error", None),
                        "echo_frozen": sim.radar.frozen(_namespace(variant)),
                        "echo_recordings": {k: r.recordings
                                            for k, r in sim.radar._replay.items()},
                        "kernels_ms": {k: v / pulses for k, v in kernels.items()},
                        "stages": stages})
    return results


def sbr(variant: str, batch: int, profile: bool = False) -> None:
    """Time the hull trace of Simulation 2 on ``variant`` (module docstring, ``--sbr``).

    The first trace goes through the signature cache (``SEAECHO_CACHE_DIR``; an empty
    one traces), so that a pulse benchmark run after it in the same cache folder finds
    the boat's signature; the others bypass it."""
    import dataclasses

    import drjit as dr

    from seaecho.targets.cache import ArrayCache
    from seaecho.tracing import sbr as sbr_module

    t0 = time.perf_counter()
    sim = _simulation(variant, 0.1, 160)
    hulls = sim.hulls
    print(f"  SBR on {variant}: simulation built in {time.perf_counter() - t0:.1f} s",
          flush=True)
    spent = {"casts": 0.0, "shadow": 0.0, "scenes": 0.0}

    def timed(fn, key):
        def wrapper(*a, **k):
            t = time.perf_counter()
            try:
                return fn(*a, **k)
            finally:
                spent[key] += time.perf_counter() - t
        return wrapper

    sbr_module._intersect = timed(sbr_module._intersect, "casts")
    sbr_module._blocked = timed(sbr_module._blocked, "shadow")
    sbr_module._mi_scene = timed(sbr_module._mi_scene, "scenes")
    hull = hulls.hulls[0]
    default = hull.options
    pulse = hulls.refresh_pulse(0, 40)
    cache = hulls.disk_cache
    runs = [("first (kernels compiled)", default.batch), ("second", default.batch)]
    if batch != default.batch:
        runs.append((f"batch {batch}", batch))
    for i, (label, b) in enumerate(runs):
        object.__setattr__(hull, "options", dataclasses.replace(default, batch=b))
        hulls.disk_cache = cache if i == 0 else ArrayCache.disabled()
        for k in spent:
            spent[k] = 0.0
        dr.set_flag(dr.JitFlag.KernelHistory, True)
        dr.kernel_history()
        prof = None
        if profile and i == 1:
            import cProfile

            prof = cProfile.Profile()
            prof.enable()
        w, c = time.perf_counter(), time.process_time()
        sig = hulls._trace(0, pulse)
        w, c = time.perf_counter() - w, time.process_time() - c
        if prof is not None:
            import pstats

            prof.disable()
            pstats.Stats(prof).sort_stats("tottime").print_stats(14)
        hist = dr.kernel_history()
        dr.set_flag(dr.JitFlag.KernelHistory, False)
        jit = [k for k in hist if str(k["type"]).endswith("JIT")]
        miss = [k for k in jit if not k.get("cache_hit", 1)]
        compile_s = sum(float(k.get("codegen_time", 0.0)) + float(k.get("backend_time", 0.0))
                        for k in jit) / 1e3
        run_s = sum(float(k.get("execution_time", 0.0)) for k in hist) / 1e3
        print(f"  SBR {label}: {w:.2f} s wall, {c:.2f} s CPU; ray casts {spent['casts']:.2f} s, "
              f"shadow rays {spent['shadow']:.2f} s, Mitsuba scenes {spent['scenes']:.2f} s, "
              f"the rest {w - spent['casts'] - spent['shadow'] - spent['scenes']:.2f} s; "
              f"{sig.n_rays} rays, "
              f"{sig.n_hits} hits; {len(hist)} launches ({len(jit)} JIT kernels, "
              f"{sum(1 for k in jit if k.get('uses_optix'))} OptiX, {len(miss)} compiled, "
              f"{compile_s:.2f} s compiling, {run_s:.2f} s running)", flush=True)
    object.__setattr__(hull, "options", default)
    hulls.disk_cache = cache


def _simulation_of(path: Path, variant: str, update: dict | None = None):
    """The simulation of the scene file ``path`` on ``variant``."""
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    scene = load_scene(path)
    scene = scene.model_copy(update={
        "tracing": scene.tracing.model_copy(update={"variant": variant}), **(update or {})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Simulation(scene, base_dir=path.parent)


#: (module, attribute path, label, depth): the stages of a pulse whose beam misses the
#: sea (``--scan --stages``), timed like ``profile_pulse.py``'s.
SCAN_STAGES = [
    ("seaecho.simulation", "Simulation.pulse", "pulse (end to end, no compression)", 0),
    ("seaecho.simulation", "Simulation.sea_skipped", "the sea's beam bound", 1),
    ("seaecho.simulation", "Simulation.pulses", "pulses (a block, as Simulation.run)", 0),
    ("seaecho.simulation", "Simulation.targets_hidden", "targets hidden (land, crests)", 1),
    ("seaecho.simulation", "Simulation.sea_echo", "sea echo", 1),
    ("seaecho.radar.system", "RadarSystem.target_echo", "targets' echo", 1),
    ("seaecho.radar.system", "RadarSystem.scatterer_echo", "radar equation (all sets)", 2),
    ("seaecho.radar.replay", "FrozenEchoTerms.__call__", "replayed", 3),
    ("seaecho.tracing.hull_echo", "HullEchoes.echoes", "hull echoes", 1),
    ("seaecho.simulation", "Simulation.land_patches", "land patches in the beam", 1),
    ("seaecho.tracing.land", "LandEchoes.echo", "land echo", 1),
    ("seaecho.radar.system", "RadarSystem.receive", "receive (accumulation, noise)", 1),
    ("seaecho.radar.echo", "accumulate", "NUFFT / direct sum + iFFT", 2),
    ("seaecho.radar.echo", "accumulate_cuda_sets", "cufinufft, all sets + iFFT", 2),
    ("seaecho.radar.system", "thermal_noise", "thermal noise", 2),
    ("seaecho.checks.guards", "check_pulse", "finite check", 1),
    ("seaecho.simulation", "Simulation.compress", "range compression", 0),
]


def scan(variant: str, stride: int, smoke: bool, stages: bool = False,
         freeze: bool | None = None) -> None:
    """Time the coastal revolution on ``variant`` (module docstring, ``--scan``);
    ``stages``: the mean time per pulse of each stage of the pulses that skip the sea;
    ``freeze``: ``RadarSystem.freeze`` (the scatterers' radar equation replayed; None:
    the default, on)."""
    import numpy as np

    from seaecho.config import load_scene

    path = small_scene(SCAN, grid=16 if smoke else 256, pulses=2500)
    scene = load_scene(path)
    timer = None
    if stages:
        import profile_pulse

        profile_pulse.STAGES, saved = SCAN_STAGES, profile_pulse.STAGES
        timer = profile_pulse.Timer()
        found = profile_pulse.install(timer)
        profile_pulse.STAGES = saved
    t0 = time.perf_counter()
    sim = _simulation_of(path, variant)
    sim.radar.freeze = freeze
    n = sim.radar.n_pulses
    pulses = np.arange(0, n, stride)
    sim.compress(sim.pulse(int(pulses[0]))[None])  # compilation, the first sea state
    setup = time.perf_counter() - t0
    skips = [bool(sim.sea_skipped(int(p))) for p in pulses]
    skipped = sum(skips)
    if stride == 1:  # the whole revolution, a sea block at a time, as Simulation.run
        if timer is not None:
            timer.reset()
        w0, c0 = time.perf_counter(), time.process_time()
        for a in range(0, n, sim.block):
            sim.pulses(a, min(a + sim.block, n))
        w, c = time.perf_counter() - w0, time.process_time() - c0
        print(f"  coastal revolution on {variant} ({scene.sea.nx}^2 sea): set-up "
              f"{setup:.1f} s; all {n} pulses ({skipped} skip the sea) by Simulation."
              f"pulses, {sim.block} at a time: {w:.2f} s wall / {c:.2f} s CPU (real time: "
              f"{n / scene.radar.prf_hz:.2f} s; load {os.getloadavg()[0]:.2f})", flush=True)
        if timer is not None:  # every pulse of the revolution, with and without the sea
            print(f"  stages, all {n} pulses (wall / CPU ms per pulse):")
            for label, _, depth in found:
                if label in timer.wall:
                    print(f"    {'  ' * depth + label:44s} {1e3 * timer.wall[label] / n:8.3f}"
                          f" {1e3 * timer.cpu[label] / n:8.3f}  "
                          f"({timer.calls[label] / n:g} calls)")
        return
    inbeam, other = [], []
    first = []  # (time, skip) of the first sampled pulse of each sea block
    w0, c0 = time.perf_counter(), time.process_time()
    last = None
    for p, skip in zip(pulses, skips, strict=True):
        t = time.perf_counter()
        sim.compress(sim.pulse(int(p))[None])
        t = time.perf_counter() - t
        if int(p) // sim.block != last:  # a new sea state (and its crests' BVH)
            first.append((t, skip))
        else:
            (other if skip else inbeam).append(t)
        last = int(p) // sim.block
    w, c = time.perf_counter() - w0, time.process_time() - c0
    # each sea block's first pulse pays its sea state once, not `stride` times
    typical = {True: float(np.median(other)) if other else 0.0,
               False: float(np.median(inbeam)) if inbeam else 0.0}
    once = stride * (sum(other) + sum(inbeam)) + sum(
        t + (stride - 1) * typical[skip] for t, skip in first)
    print(f"  revolution with each sea block's first pulse counted once: {once:.1f} s "
          f"({len(first)} blocks: {1e3 * sum(t for t, _ in first) / max(len(first), 1):.0f} "
          "ms per first pulse)", flush=True)
    if timer is not None:  # the pulses that skip the sea, stage by stage
        timer.reset()
        for p in [int(q) for q, skip in zip(pulses, skips, strict=True) if skip]:
            sim.compress(sim.pulse(p)[None])
        print(f"  stages of the {skipped} pulses that skip the sea (wall / CPU ms per "
              f"pulse; load {os.getloadavg()[0]:.2f}; radar equation replayed: "
              f"{sim.radar.frozen(_namespace(variant))}):")
        for label, _, depth in found:
            if label in timer.wall:
                print(f"    {'  ' * depth + label:44s} {1e3 * timer.wall[label] / skipped:8.3f}"
                      f" {1e3 * timer.cpu[label] / skipped:8.3f}  "
                      f"({timer.calls[label] / skipped:g} calls)")
    print(f"  coastal revolution on {variant} ({scene.sea.nx}^2 sea): set-up {setup:.1f} s; "
          f"{len(pulses)} pulses ({skipped} skip the sea) in {w:.2f} s wall / {c:.2f} s CPU; "
          f"revolution (extrapolated x {n / len(pulses):g}) {w * n / len(pulses):.1f} s wall "
          f"(real time: {n / scene.radar.prf_hz:.2f} s); per pulse: with the sea "
          f"{1e3 * float(np.median(inbeam)) if inbeam else float('nan'):.1f} ms, without "
          f"{1e3 * float(np.median(other)) if other else float('nan'):.2f} ms (medians)",
          flush=True)


def _namespace(variant: str):
    from seaecho.backend import drjit_namespace

    return drjit_namespace(variant)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulses", type=int, default=50)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--refresh", type=float, default=0.1,
                    help="[tracing] refresh_interval_s [s]")
    ap.add_argument("--update", type=int, default=160, help="[radar] sea_update_pulses")
    ap.add_argument("--no-cpu", action="store_true", help="skip the CPU comparison")
    ap.add_argument("--save", help="folder for the GPU pulses' samples (.npy)")
    ap.add_argument("--freeze", choices=("0", "1"),
                    help="SEAECHO_FREEZE of the timed pulses (default: the environment's)")
    ap.add_argument("--unbatched", action="store_true",
                    help="one cufinufft call per channel (radar.echo.CUDA_BATCH_CHANNELS "
                    "off)")
    ap.add_argument("--sync-stages", action="store_true",
                    help="each stage waits for the GPU before it starts and ends (its own "
                    "GPU work in its time; the pulse takes longer)")
    ap.add_argument("--sbr", action="store_true", help="time the SBR hull trace instead")
    ap.add_argument("--sbr-batch", type=int, default=1 << 20,
                    help="a second ray batch size of --sbr [rays]")
    ap.add_argument("--sbr-profile", action="store_true",
                    help="--sbr: cProfile of the second trace (its time is inflated)")
    ap.add_argument("--scan", action="store_true",
                    help="time the coastal revolution instead")
    ap.add_argument("--stride", type=int, default=25, help="--scan: every N-th pulse")
    ap.add_argument("--stages", action="store_true",
                    help="--scan: the stages of the pulses that skip the sea")
    ap.add_argument("--freeze-echo", choices=("0", "1"),
                    help="--scan: RadarSystem.freeze, the scatterers' radar equation "
                    "replayed (default: on)")
    ap.add_argument("--variant", help="--sbr, --scan: Mitsuba variant (default: CUDA if "
                    "there is a GPU, else LLVM)")
    ap.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # Simulation 2 on a small grid, one pulse after none
        global SIM2
        SIM2 = small_scene(SIM2, grid=GRID, pulses=10**6)
        args.pulses, args.warmup = 1, 0
    if args.child:  # the CPU comparison, in its own process (one variant per process)
        r = run(args.child[0], args.pulses, args.warmup, args.refresh, args.update,
                args.child[1], profile=False)[0]
        print(json.dumps(r))
        return
    if args.freeze is not None:
        os.environ["SEAECHO_FREEZE"] = args.freeze
    if args.unbatched:
        from seaecho.radar import echo

        echo.CUDA_BATCH_CHANNELS = False
    from seaecho.backend import cuda_available

    if args.sbr or args.scan:
        variant = args.variant or ("cuda_ad_mono_polarized" if cuda_available()
                                   else "llvm_ad_mono_polarized")
        print(f"bench_gpu: {_device()}; {os.cpu_count()} CPUs, load "
              f"{os.getloadavg()[0]:.2f}", flush=True)
        if args.sbr:
            sbr(variant, args.sbr_batch, args.sbr_profile)
        else:
            scan(variant, 1250 if args.smoke else args.stride, args.smoke, args.stages,
                 None if args.freeze_echo is None else args.freeze_echo == "1")
        return
    if not cuda_available():
        if args.smoke:  # the CPU half, which runs anywhere
            for r in run("llvm_ad_mono_polarized", args.pulses, args.warmup, args.refresh,
                         args.update, None, profile=True, freezes=(False, True)):
                print(f"bench_gpu --smoke: no CUDA GPU; CPU (llvm) set-up {r['setup_s']:.1f} "
                      f"s, {len(r['wall'])} pulse(s), {1e3 * statistics.median(r['wall']):.1f} "
                      f"ms, frozen {r['freeze']}, radar equation replayed "
                      f"{r['echo_frozen']} {r['echo_recordings']}")
            return
        sys.exit("bench_gpu: no CUDA GPU here (Dr.Jit finds no CUDA device)")
    try:
        import cufinufft  # noqa: F401
    except ImportError:
        sys.exit("bench_gpu: cufinufft is not installed (pip install cufinufft)")
    import numpy as np

    print(f"bench_gpu: {_device()}; {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}")
    print(f"  Simulation 2, 512 x 512 sea, quad-pol, refresh_interval_s = {args.refresh:g}, "
          f"sea_update_pulses = {args.update}, {args.pulses} pulses after {args.warmup}")
    freezes = (False, True) if args.freeze is None else (args.freeze == "1",)
    with tempfile.TemporaryDirectory() as d:
        gpu_out = str(Path(args.save or d) / "gpu_freeze{freeze}.npy")
        for g in run("cuda_ad_mono_polarized", args.pulses, args.warmup, args.refresh,
                     args.update, gpu_out, profile=True, freezes=freezes,
                     sync_stages=args.sync_stages):
            w = np.array(g["wall"]) * 1e3
            print(f"\n  GPU, fused kernel {'frozen (replayed)' if g['freeze'] else 'traced'}"
                  f"{'' if not g['freeze_error'] else ' (gave up: ' + g['freeze_error'] + ')'}"
                  f": set-up {g['setup_s']:.1f} s; per pulse median {np.median(w):.2f} ms, "
                  f"min {w.min():.2f}, max {w.max():.2f} ms (host CPU "
                  f"{1e3 * statistics.median(g['cpu']):.2f} ms; {g['launches']:.0f} "
                  f"launches); scatterers' radar equation replayed: {g['echo_frozen']} "
                  f"(recordings {g['echo_recordings']})", flush=True)
            print(f"  {'stage':44s} {'wall [ms]':>10s}")
            for label, ms, depth in g["stages"]:
                print(f"  {'  ' * depth + label:44s} {ms:10.2f}")
            print("  Dr.Jit kernel history, device time per pulse: " + ", ".join(
                f"{k} {v:.2f} ms" for k, v in sorted(g["kernels_ms"].items())), flush=True)
        gpu_out = gpu_out.replace("{freeze}", str(int(freezes[-1] is True)))
        if not args.no_cpu:
            cpu_out = str(Path(d) / "cpu.npy")
            res = subprocess.run([sys.executable, __file__, "--pulses", str(args.pulses),
                                  "--warmup", str(args.warmup), "--refresh",
                                  str(args.refresh), "--update", str(args.update),
                                  "--child", "llvm_ad_mono_polarized", cpu_out,
                                  *(["--smoke"] if args.smoke else [])],
                                 capture_output=True, text=True)
            if res.returncode != 0:
                sys.exit(f"CPU run failed:\n{res.stderr[-3000:]}")
            c = json.loads(res.stdout.strip().splitlines()[-1])
            a, b = np.load(gpu_out), np.load(cpu_out)
            err = np.abs(a - b).max() / np.abs(b).max()
            print(f"\n  CPU (llvm) per pulse median {1e3 * statistics.median(c['wall']):.1f} ms "
                  f"wall; GPU / CPU samples: max |difference| / max |CPU| = {err:.1e} "
                  f"({'ok' if err < 1e-8 else 'LARGER THAN 1e-8'})")


if __name__ == "__main__":
    main()
