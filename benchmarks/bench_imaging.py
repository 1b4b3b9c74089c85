"""Benchmark of SAR image formation: run as ``python benchmarks/bench_imaging.py``.

1. Backprojection of Simulation 2: 160 pulses onto a 0.5 m grid over the 128 m tile
   (256 x 256 pixels), 4 channels, Dr.Jit LLVM kernel and numpy reference; best / mean of
   ``--repeat`` runs, throughput in pixel-pulses per second (each one interpolates and
   accumulates the 4 channels). The raw data are simulated first (``--raw`` reuses a
   file), and the same raw file serves every repetition.
2. The whole image (``seaecho.imaging.focus.focus``: reading, upsampling,
   backprojection, calibration, products) with the scene's own [image] grid.
3. End to end (``--end-to-end``): ``seaecho run`` of Simulation 2 (raw + image), and of
   Simulation 4 with ``--sim4``; wall time and peak RSS of the subprocess.

Timings on a shared machine are noisy: the load average is printed with them.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

from _smoke import add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"
SIM4 = ROOT / "scenes" / "paper_sim4_sar_500m_u10.toml"


def _load() -> str:
    return "load average " + " / ".join(f"{v:.2f}" for v in os.getloadavg())


def _simulate(scene_path: Path, out: Path) -> None:
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        Simulation(load_scene(scene_path), base_dir=scene_path.parent).run(out,
                                                                             progress=False)


def bench_backprojection(raw: Path, repeat: int) -> None:
    import numpy as np
    import xarray as xr

    from seaecho.config.image import ImageConfig
    from seaecho.imaging.focus import ImageGrid, RawData, _Processor

    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        ds = ds.load()
    grid = ImageGrid.from_extent((-64.0, 64.0, -64.0, 64.0), 0.5)
    points = grid.points()
    print(f"\n[1] backprojection, Simulation 2: {grid.shape[0]} x {grid.shape[1]} pixels x "
          f"{ds.sizes['pulse']} pulses x {ds.sizes['channel']} channels ({_load()})")
    for backend in ("drjit", "numpy"):
        proc = _Processor(RawData(ds), ImageConfig(pixel_m=0.5), backend)
        if backend == "drjit":
            proc.backproject(points, block_pulses=160)  # compile once, not timed
        times, bp = [], []
        for _ in range(repeat if backend == "drjit" else 1):
            tm: dict = {}
            t = time.perf_counter()
            proc.backproject(points, block_pulses=160, timings=tm)
            times.append(time.perf_counter() - t)
            bp.append(tm["backprojection"])
        n = points.shape[0] * ds.sizes["pulse"]
        print(f"  {backend:6s} kernel best {min(bp):.3f} s / mean {np.mean(bp):.3f} s, "
              f"with reading + upsampling {min(times):.3f} s; "
              f"{n / min(bp):.3g} pixel-pulses/s ({4 * n / min(bp):.3g} channel "
              f"interpolations/s), per pulse {1e3 * min(bp) / ds.sizes['pulse']:.2f} ms "
              f"[{_load()}]")


def bench_focus(raw: Path, scene_path: Path, repeat: int) -> None:
    import numpy as np

    from seaecho.config import load_scene
    from seaecho.imaging.focus import focus

    cfg = load_scene(scene_path).image
    focus(raw, cfg)  # warm: compilation, the antenna integral, imports
    rows = []
    for _ in range(repeat):
        tm: dict = {}
        t = time.perf_counter()
        img = focus(raw, cfg, timings=tm)
        tm["total"] = time.perf_counter() - t
        rows.append(tm)
    print(f"\n[2] whole image of {scene_path.name}: {img.sizes['y']} x {img.sizes['x']} "
          f"pixels of {cfg.pixel_m} m, {rows[0]['pulses']} pulses ({_load()})")
    for key in ("read_upsample", "backprojection", "calibration", "products", "total"):
        v = [r[key] for r in rows]
        print(f"  {key:15s} best {min(v):.3f} s / mean {np.mean(v):.3f} s")


def bench_end_to_end(scene_path: Path, tmp: Path) -> None:
    out = tmp / (scene_path.stem + ".nc")
    before = _load()
    t = time.perf_counter()
    cmd = [sys.executable, "-m", "seaecho", "run", str(scene_path), "-o", str(out), "-q",
           "--no-figures"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t
    rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    if proc.returncode != 0:
        print(proc.stderr)
        raise SystemExit(proc.returncode)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("wrote")]
    print(f"\n[3] end to end, seaecho run {scene_path.name} (raw + image, no figures): "
          f"{wall:.1f} s wall, peak RSS {rss:.0f} MB (load before {before}, after "
          f"{_load()})")
    for ln in lines:
        print(f"  {ln}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--raw", type=Path, help="reuse this raw dataset of Simulation 2")
    ap.add_argument("--end-to-end", action="store_true", help="also time seaecho run")
    ap.add_argument("--sim4", action="store_true", help="and Simulation 4 end to end")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # Simulations 2 and 4 on small grids, 2 pulses, coarse images
        global SIM2, SIM4
        SIM2, SIM4 = small_scene(SIM2), small_scene(SIM4)
        args.repeat = 1
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        raw = args.raw
        if raw is None:
            raw = tmp / "sim2.nc"
            t = time.perf_counter()
            _simulate(SIM2, raw)
            print(f"simulated Simulation 2 raw data in {time.perf_counter() - t:.1f} s "
                  f"({_load()})")
        bench_backprojection(raw, args.repeat)
        bench_focus(raw, SIM2, max(1, args.repeat // 2))
        if args.end_to_end:
            bench_end_to_end(SIM2, tmp)
        if args.sim4:
            bench_end_to_end(SIM4, tmp)


if __name__ == "__main__":
    main()
