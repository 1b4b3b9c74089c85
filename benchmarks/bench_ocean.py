"""Benchmark: sea surface synthesis and evolution.

Run: ``python benchmarks/bench_ocean.py [--repeat N]``. Prints, for named grid sizes,
the time to synthesise a realisation (spectrum on the grid + random amplitudes), to evolve
it to a new time (elevation only, and elevation + slopes + velocities), and peak memory.
Targets on the 2-core reference machine: synthesis + evolution <= 50 ms at 512 x 512 and
<= 1 s at 2048 x 2048.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from _memory import peak_rss_mb
from _smoke import GRID, add_option

from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface

SIZES = {"512x512": (512, 500.0), "1024x1024": (1024, 500.0), "2048x2048": (2048, 1000.0)}


def best_of(func, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = func()
        times.append(time.perf_counter() - t0)
    return min(times), out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--spectrum", default="elfouhaily")
    add_option(parser)
    args = parser.parse_args()
    sizes = SIZES
    if args.smoke:
        sizes, args.repeat = {f"{GRID}x{GRID}": (GRID, 50.0)}, 1
    spec = DirectionalSpectrum(args.spectrum, "elfouhaily", u19_5=10.0, wind_direction=0.5)
    print(f"cores: {os.cpu_count()}, load: {os.getloadavg()[0]:.2f}, spectrum: {args.spectrum}")
    print(f"{'grid':>10} {'synth [ms]':>11} {'evolve z [ms]':>14} {'z+slopes+vel [ms]':>18} "
          f"{'synth+evolve [ms]':>18} {'peak RSS [MiB]':>15}")
    for name, (n, size) in sizes.items():
        t_syn, surf = best_of(
            lambda n=n, size=size: SeaSurface(spec, (size, size), (n, n),
                                              np.random.default_rng(0)), args.repeat)
        t_z, _ = best_of(lambda surf=surf: surf.elevation(12.3), args.repeat)
        t_all, _ = best_of(lambda surf=surf: surf.fields(12.3), args.repeat)
        rss = peak_rss_mb()
        print(f"{name:>10} {t_syn * 1e3:11.1f} {t_z * 1e3:14.1f} {t_all * 1e3:18.1f} "
              f"{(t_syn + t_z) * 1e3:18.1f} {rss:15.0f}")


if __name__ == "__main__":
    main()
