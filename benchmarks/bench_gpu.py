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
"""

from __future__ import annotations

import argparse
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


def run(variant: str, pulses: int, warmup: int, refresh: float, update: int,
        out: str | None, profile: bool) -> dict:
    """Time the pulses of one variant in this process; save the samples to ``out``."""
    import numpy as np

    timer = None
    if profile:
        from profile_pulse import Timer, install

        timer = Timer()
        found = install(timer)
    t0 = time.perf_counter()
    sim = _simulation(variant, refresh, update)
    first = 40
    for p in range(first, first + warmup):
        sim.compress(sim.pulse(p))
    setup = time.perf_counter() - t0
    if timer is not None:
        timer.reset()
    import drjit as dr

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
    if out:
        np.save(out, np.stack(samples))
    stages = []
    if timer is not None:
        stages = [(label, 1e3 * timer.wall[label] / pulses, depth) for label, _, depth in found
                  if label in timer.wall]
    return {"variant": variant, "setup_s": setup, "wall": wall, "cpu": cpu,
            "kernels_ms": {k: v / pulses for k, v in kernels.items()}, "stages": stages}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulses", type=int, default=50)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--refresh", type=float, default=0.1,
                    help="[tracing] refresh_interval_s [s]")
    ap.add_argument("--update", type=int, default=160, help="[radar] sea_update_pulses")
    ap.add_argument("--no-cpu", action="store_true", help="skip the CPU comparison")
    ap.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # Simulation 2 on a small grid, one pulse after none
        global SIM2
        SIM2 = small_scene(SIM2, grid=GRID, pulses=10**6)
        args.pulses, args.warmup = 1, 0
    if args.child:  # the CPU comparison, in its own process (one variant per process)
        r = run(args.child[0], args.pulses, args.warmup, args.refresh, args.update,
                args.child[1], profile=False)
        print(json.dumps(r))
        return
    from seaecho.backend import cuda_available

    if not cuda_available():
        if args.smoke:  # the CPU half, which runs anywhere
            r = run("llvm_ad_mono_polarized", args.pulses, args.warmup, args.refresh,
                    args.update, None, profile=True)
            print(f"bench_gpu --smoke: no CUDA GPU; CPU (llvm) set-up {r['setup_s']:.1f} s, "
                  f"{len(r['wall'])} pulse(s), {1e3 * statistics.median(r['wall']):.1f} ms")
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
    with tempfile.TemporaryDirectory() as d:
        gpu_out = str(Path(d) / "gpu.npy")
        g = run("cuda_ad_mono_polarized", args.pulses, args.warmup, args.refresh,
                args.update, gpu_out, profile=True)
        w = np.array(g["wall"]) * 1e3
        print(f"\n  GPU: set-up {g['setup_s']:.1f} s; per pulse median {np.median(w):.2f} ms, "
              f"min {w.min():.2f}, max {w.max():.2f} ms (host CPU "
              f"{1e3 * statistics.median(g['cpu']):.2f} ms)")
        print(f"  {'stage':44s} {'wall [ms]':>10s}")
        for label, ms, depth in g["stages"]:
            print(f"  {'  ' * depth + label:44s} {ms:10.2f}")
        print("  Dr.Jit kernel history, device time per pulse: " + ", ".join(
            f"{k} {v:.2f} ms" for k, v in sorted(g["kernels_ms"].items())))
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
