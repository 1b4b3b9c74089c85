"""The fused sea echo of held Simulation 2 pulses alone: CPU time per pulse and a digest.

``Simulation.sea_echo`` (the fused kernel of ``seaecho.radar.resident``: trace, kernel,
compaction, host views) of consecutive held pulses, after two warm-up pulses: median and
least CPU time and median wall time per pulse, the number of echoes, and a sha256 of
their delays and amplitudes (to check that a change keeps the bytes). To compare two
versions of the code, run it with each first on ``PYTHONPATH``, alternately.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import time
import warnings
from pathlib import Path

import numpy as np
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulses", type=int, default=20, help="pulses timed")
    ap.add_argument("--first", type=int, default=40, help="first warm-up pulse")
    add_option(ap)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    path = SIM2
    if args.smoke:
        path, args.pulses, args.first = small_scene(SIM2, grid=GRID, pulses=10**6), 1, 0
    sim = Simulation(load_scene(path), base_dir=path.parent)
    sim.sea_echo(args.first)
    sim.sea_echo(args.first + 1)
    digest = hashlib.sha256()
    cpu, wall, n = [], [], 0
    for p in range(args.first + 2, args.first + 2 + args.pulses):
        w, c = time.perf_counter(), time.process_time()
        echo = sim.sea_echo(p).echo
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
        n = np.size(echo.tau)
        digest.update(np.ascontiguousarray(echo.tau).tobytes())
        for a in echo.amplitudes:
            digest.update(np.ascontiguousarray(a).tobytes())
    print(f"bench_sea_kernel: {path.stem}, {sim.sea.surface.shape[0]}^2 sea, pulses "
          f"{args.first + 2}-{args.first + 1 + args.pulses}: CPU median "
          f"{1e3 * np.median(cpu):.1f} ms (least {1e3 * min(cpu):.1f}), wall median "
          f"{1e3 * np.median(wall):.1f} ms; {n} echoes; sha256 {digest.hexdigest()[:16]}; "
          f"load {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
