"""Speed of the per-facet scattering (all four channels, blend model).

Run: ``python benchmarks/bench_scattering.py``. Prints, for named sizes, the best of
several runs of ``facet_sigma`` (blend, all channels) and ``facet_amplitudes`` with the
numpy and the Dr.Jit (LLVM) backends, the machine load, and the peak resident memory.
Target: 262,144 facets (a 512 x 512 sea) in <= 0.1 s on the 2-core machine.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from _memory import peak_rss_mb
from _smoke import add_option

from seaecho.constants import C0
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.scattering.facet import (
    FacetModel,
    _drjit_available,
    facet_amplitudes,
    facet_sigma,
)
from seaecho.scattering.spectrum_table import BraggSpectrumTable

SIZES = {"64x64": 64 * 64, "256x256": 256 * 256, "512x512": 512 * 512}
REPEATS = 7


def geometry(n: int, seed: int = 1):
    """Facets of a rough sea tile seen by a bistatic pair (Tx 3 km west, Rx 2 km south)."""
    rng = np.random.default_rng(seed)
    zx, zy = rng.normal(0.0, 0.1, (2, n))
    normal = np.stack([-zx, -zy, np.ones(n)], -1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    centre = np.column_stack([rng.uniform(-500, 500, (n, 2)), np.zeros(n)])
    tx = np.array([-3000.0, 0.0, 500.0])
    rx = np.array([0.0, -2000.0, 300.0])
    n_i = centre - tx
    n_i /= np.linalg.norm(n_i, axis=-1, keepdims=True)
    n_s = rx - centre
    n_s /= np.linalg.norm(n_s, axis=-1, keepdims=True)
    return n_i, n_s, normal


def best_time(fn, repeats: int = REPEATS) -> float:
    fn()  # warm-up (JIT compilation, caches)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_option(ap)
    smoke = ap.parse_args().smoke
    sizes = {"16x16": 16 * 16} if smoke else SIZES
    repeats = 1 if smoke else REPEATS
    f = 10e9
    k = 2 * np.pi * f / C0
    eps = complex(sea_water_permittivity(f, 20.0, 35.0))
    spec = DirectionalSpectrum(u19_5=5.0)
    t0 = time.perf_counter()
    table = BraggSpectrumTable(spec.height_spectrum, k / 3, 20 * k)
    t_table = time.perf_counter() - t0
    print(f"load average (1, 5, 15 min): {os.getloadavg()}, cpus: {os.cpu_count()}")
    print(f"BraggSpectrumTable (1024 x 360, Elfouhaily): {t_table * 1e3:.1f} ms once per "
          "sea state")
    backends = ["numpy"] + (["drjit"] if _drjit_available() else [])
    rng = np.random.default_rng(0)
    for name, n in sizes.items():
        n_i, n_s, normal = geometry(n)
        area = np.full(n, 4.0)
        for backend in backends:
            args = (n_i, n_s, normal, FacetModel(k, eps, table, 0.005, 0.004, model="blend"))

            def sig(args=args, backend=backend):
                return facet_sigma(*args, backend=backend)

            def amp(args=args, area=area, backend=backend):
                n_i_, n_s_, normal_, sea = args
                return facet_amplitudes(n_i_, n_s_, normal_, area, sea, rng, backend=backend)

            ts = best_time(sig, repeats if n <= 65536 or backend == "drjit" else 3)
            ta = best_time(amp, repeats if n <= 65536 or backend == "drjit" else 3)
            print(f"{name:>8} ({n:7d} facets) {backend:>5}: facet_sigma {ts * 1e3:8.1f} ms"
                  f"   facet_amplitudes {ta * 1e3:8.1f} ms")
    peak = peak_rss_mb()
    print(f"peak resident memory: {peak:.0f} MiB")
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
