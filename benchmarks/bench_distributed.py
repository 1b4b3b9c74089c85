"""Benchmark of distributed runs: ``python benchmarks/bench_distributed.py``.

1. A run of ``--pulses`` (400) pulses of the paper's Simulation 2 (airborne SAR, sea held
   for the whole acquisition, shadowing re-traced every 0.1 s = 22 pulses, ray traced) on
   a ``--grid`` (256) grid: serially in this process, then on local Dask clusters of
   ``--workers`` (1 2) worker processes. Wall time, CPU time (this process and the
   workers), speed-up over the serial run, and a check that every file has the serial
   run's bytes.
2. The overhead of a Dask task: ``--tasks`` empty tasks on the cluster.
3. Per-block costs for the cluster estimate, at ``--cost-grids`` (256 512): a pulse
   inside a refresh block, the extra cost of the first pulse of a block (occlusion
   traced), the sea surface synthesis of a held block, peak memory; and the estimate of a
   10^4-pulse, 2048 x 2048 SAR run on a cluster (facets scale linearly: checked between
   the two grids).

The machine is shared: the load average and CPU times are printed with the wall times.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006), "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import os
import resource
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np
from _memory import peak_rss_mb
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def _scene(grid: int, pulses: int):
    from seaecho.config import load_scene
    from seaecho.config.overrides import with_overrides

    scene = with_overrides(load_scene(SIM2), {
        "sea.nx": grid, "radar.n_pulses": pulses, "radar.sea_update_pulses": pulses,
        "radar.sigma_map_pulse": pulses // 2})
    return scene.model_copy(update={"image": None})


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def _worker_cpu() -> float:
    return _cpu()


def _worker_rss_mb() -> float:
    return peak_rss_mb()


def _load() -> str:
    return "load {:.1f} {:.1f} {:.1f}".format(*os.getloadavg())


def _warm(scene, base_dir):
    """Imports, Dr.Jit kernels and BVH code paths of a worker process (each process
    compiles its kernels once)."""
    from seaecho.simulation import Simulation

    warnings.simplefilter("ignore")
    Simulation(scene, base_dir=base_dir).pulse(0)


def _noop(i):
    return i


def bench_runs(grid: int, pulses: int, workers: list[int], block: int | None,
               tasks: int) -> None:
    from seaecho import distributed
    from seaecho.simulation import Simulation

    scene = _scene(grid, pulses)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = Simulation(scene, base_dir=SIM2.parent)
            sim.pulse(0)  # JIT compilation and BVH: not timed (each worker pays its own)
        from seaecho.io.run import block_size

        size = block_size(sim.block_edges(), block)
        print(f"\n1. {pulses} pulses, {grid} x {grid} grid, {len(sim.radar.channels)} channels "
              f"x {sim.radar.window.n_samples} samples, blocks of {size} pulses "
              f"({-(-pulses // size)} tasks), {os.cpu_count()} cores; {_load()}")
        t, c = time.perf_counter(), _cpu()
        serial = sim.run(tmp / "serial.nc", progress=False, chunk=block)
        wall0, cpu0 = time.perf_counter() - t, _cpu() - c
        print(f"   serial        wall {wall0:7.1f} s  cpu {cpu0:7.1f} s  "
              f"({1e3 * wall0 / pulses:.0f} ms/pulse)  {_load()}")
        for n in workers:
            t_start = time.perf_counter()
            with distributed.cluster(n) as client:
                start = time.perf_counter() - t_start
                t = time.perf_counter()
                client.run(_warm, scene, str(SIM2.parent))  # imports, JIT kernels
                warm = time.perf_counter() - t
                w0 = sum(client.run(_worker_cpu).values())
                t, c = time.perf_counter(), _cpu()
                out = distributed.run(scene, tmp / f"w{n}.nc", client=client,
                                      base_dir=SIM2.parent, block=block, progress=False,
                                      simulation=sim)
                wall, cpu = time.perf_counter() - t, _cpu() - c
                wcpu = sum(client.run(_worker_cpu).values()) - w0
                rss = max(client.run(_worker_rss_mb).values())
                same = out.read_bytes() == serial.read_bytes()
                print(f"   {n} worker{'s' if n > 1 else ' '}     wall {wall:7.1f} s  cpu "
                      f"{cpu:5.1f} s client + {wcpu:7.1f} s workers  speed-up "
                      f"{wall0 / wall:4.2f}  (cluster start {start:4.1f} s, warm-up {warm:4.1f} s "
                      f"not counted)  worker peak "
                      f"RSS {rss:5.0f} MB  same bytes as serial: {same}  {_load()}")
                t = time.perf_counter()
                client.gather(client.map(_noop, range(tasks), pure=False))
                per_task = (time.perf_counter() - t) / tasks
                print(f"   {n} worker{'s' if n > 1 else ' '}     {tasks} empty tasks: "
                      f"{1e3 * per_task:.2f} ms per task")


def bench_costs(grids: list[int], repeat: int = 3) -> dict:
    """Per-pulse and per-block costs at each grid [s]: pulse (inside a refresh block),
    trace (extra of a block's first pulse), surface (held sea synthesis)."""
    from seaecho.simulation import Simulation

    print(f"\n3. per-block costs (best of {repeat}; cpu = this process's CPU time); {_load()}")
    out = {}
    for g in grids:
        rss0 = peak_rss_mb()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = Simulation(_scene(g, 400), base_dir=SIM2.parent)
            sim.pulse(0)
        pulse, trace, surface = [], [], []
        for r in range(repeat):
            p = 22 * (r + 1)  # the first pulse of a refresh block: occlusion traced
            c = _cpu()
            sim.pulse(p)
            trace.append(_cpu() - c)
            c = _cpu()
            sim.pulse(p + 1)
            pulse.append(_cpu() - c)
            c = _cpu()
            sim.sea.state(float(r))
            surface.append(_cpu() - c)
        rss = peak_rss_mb() - rss0
        res = {"pulse": min(pulse), "trace": max(min(trace) - min(pulse), 0.0),
               "surface": min(surface), "facets": 2 * (g - 1) ** 2, "rss_mb": rss}
        out[g] = res
        print(f"   {g:5d}^2 grid ({res['facets']:9d} facets): pulse {res['pulse']:6.3f} s, "
              f"occlusion trace +{res['trace']:6.3f} s per refresh, surface "
              f"{res['surface']:6.3f} s per held sea, peak RSS +{rss:5.0f} MB")
    return out


def estimate(costs: dict, pulses: int = 10_000, grid: int = 2048, nodes: int = 32,
             cores: int = 16, refresh_pulses: int = 22, block: int = 16,
             task_overhead: float = 5e-3) -> None:
    """The 10^4-pulse 2048^2 SAR run on a cluster, from the largest measured grid scaled
    by the number of facets."""
    g = max(costs)
    c = costs[g]
    scale = 2 * (grid - 1) ** 2 / c["facets"]
    pulse, trace = c["pulse"] * scale, c["trace"] * scale
    surface = c["surface"] * (grid / g) ** 2 * np.log(grid) / np.log(g)
    n_tasks = -(-pulses // block)
    # a task traces the occlusion at its first pulse and at each refresh inside it
    task = block * pulse + (1 + block // refresh_pulses) * trace + task_overhead
    cpu = n_tasks * task
    workers = nodes * cores
    rounds = -(-n_tasks // workers)
    # each worker builds its simulation once: the held sea (a surface synthesis)
    wall = rounds * task + surface
    print(f"\n   estimate: {pulses} pulses, {grid}^2 grid ({2 * (grid - 1) ** 2} facets), "
          f"scaled x{scale:.0f} from {g}^2: {pulse:.2f} s per pulse, "
          f"+{trace:.2f} s per occlusion refresh ({refresh_pulses} pulses), "
          f"{surface:.1f} s per surface synthesis")
    print(f"   CPU {cpu / 3600:.1f} h in all; on {nodes} nodes x {cores} cores = {workers} "
          f"one-thread workers, {n_tasks} tasks of {block} pulses = {rounds} rounds of "
          f"{task:.0f} s: wall ~{wall / 60:.1f} min (memory {c['rss_mb'] * scale / 1024:.1f} "
          f"GB per worker)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulses", type=int, default=400)
    ap.add_argument("--grid", type=int, default=256)
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--block", type=int, default=None, help="pulses per block")
    ap.add_argument("--tasks", type=int, default=500, help="empty tasks timed")
    ap.add_argument("--cost-grids", type=int, nargs="+", default=[256, 512])
    ap.add_argument("--skip-runs", action="store_true", help="only the per-block costs")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # a small grid with a coarse hull trace, a few pulses, one worker
        global SIM2
        SIM2 = small_scene(SIM2, pulses=10**6)
        args.pulses, args.grid, args.workers, args.tasks = 4, GRID, [1], 10
        args.cost_grids = [GRID]
    if not args.skip_runs:
        bench_runs(args.grid, args.pulses, args.workers, args.block, args.tasks)
    estimate(bench_costs(args.cost_grids))


if __name__ == "__main__":
    main()
