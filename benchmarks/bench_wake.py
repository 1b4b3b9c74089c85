"""Benchmark of the wake stage: Kelvin wake fields and turbulent-wake mask per call.

Run: ``python benchmarks/bench_wake.py``. Prints, for named grid sizes, the best and
median wall time of ``KelvinWake.fields`` (elevation, slopes, dz/dt at a new time) and
of ``turbulent_wake_mask``, the number of plane waves used, and the peak Python-heap
memory of one call (tracemalloc; finufft's own C buffers are not counted). The paper's
10 m motor boat at 10 kt (L 10 m, B 4 m, T 1.5 m), heading 35 deg, at the tile centre.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import os
import time
import tracemalloc

import numpy as np
from _smoke import add_option

from seaecho.constants import KNOT
from seaecho.wake import KelvinWake, Ship, turbulent_wake_mask

CASES = [
    ("256x256, 64 m (paper sim 1)", 256, 64.0),
    ("512x512, 128 m (paper sims 2-3)", 512, 128.0),
    ("512x512, 500 m (paper sim 4)", 512, 500.0),
    ("1024x1024, 256 m", 1024, 256.0),
    ("2048x2048, 512 m", 2048, 512.0),
]
REPEATS = 7


def _time(fn, repeats: int = REPEATS) -> tuple[float, float]:
    times = []
    for i in range(repeats):
        t0 = time.perf_counter()
        fn(i)
        times.append(time.perf_counter() - t0)
    return min(times), float(np.median(times))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_option(ap)
    cases = CASES[:1] if ap.parse_args().smoke else CASES
    print(f"load average: {os.getloadavg()}")
    ship = Ship(10.0, 4.0, 1.5, 10.0 * KNOT, np.deg2rad(35.0), (0.0, 0.0))
    wake = KelvinWake(ship)
    print(
        f"{'case':34s} {'fields best/median [ms]':>24s} {'mask best [ms]':>15s} "
        f"{'waves':>6s} {'peak heap [MiB]':>16s}"
    )
    for name, n, tile in cases:
        dx = tile / n
        x = (np.arange(n) - n / 2) * dx
        y = x.copy()
        wake.fields(x, y, 0.0)  # warm-up: node set cached for this grid
        best, med = _time(lambda i, x=x, y=y: wake.fields(x, y, 0.1 * i))
        mbest, _ = _time(lambda i, x=x, y=y: turbulent_wake_mask(ship, x, y, 0.1 * i))
        theta, _ = wake.plane_waves(0.9 * np.pi / dx, np.hypot(tile, tile) / 2 + 5.0)
        tracemalloc.start()
        wake.fields(x, y, 1.234)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        print(
            f"{name:34s} {1e3 * best:11.1f} / {1e3 * med:9.1f} {1e3 * mbest:15.1f} "
            f"{theta.size:6d} {peak / 2**20:16.1f}"
        )


if __name__ == "__main__":
    main()
