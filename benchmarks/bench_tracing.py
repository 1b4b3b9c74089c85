"""Benchmark of the tracing stage: vertex update (BVH rebuild) and visibility + local angles.

Run ``python benchmarks/bench_tracing.py [--sizes 512 1024] [--repeat 5]``. Each size runs
in its own subprocess so that its peak resident memory (``VmHWM``, which includes
Dr.Jit / Embree buffers that ``tracemalloc`` does not see) is its own. Times are the best
of ``--repeat`` runs after a warm-up call (JIT compilation excluded; Dr.Jit caches kernels
on disk). The surface is a Gaussian random sea on a 1 m grid (rms height 0.5 m,
correlation length 8 m); Tx and Rx at low grazing angles, bistatic.

Targets (2-core CPU, 512 x 512 = 522k triangles): vertex update <= 0.2 s,
visibility from Tx and Rx with local angles <= 0.3 s.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np
from _memory import peak_rss_mb
from _smoke import GRID, add_option


def _surface(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    k = 2 * np.pi * np.fft.fftfreq(n, 1.0)
    kx, ky = np.meshgrid(k, k)
    z = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n)))
                             * np.exp(-(kx**2 + ky**2) * 64 / 8)))
    return z * 0.5 / z.std()


def _best(fn, repeat: int) -> float:
    fn()  # warm-up (JIT)
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def run_size(n: int, repeat: int, variant: str | None) -> dict:
    from seaecho.geometry.facets import facet_frames
    from seaecho.geometry.mesh import facet_geometry, grid_vertices
    from seaecho.tracing.kernels import facet_frames_drjit
    from seaecho.tracing.tracer import FacetTracer

    x = (np.arange(n) - n / 2) * 1.0
    zs = [_surface(n, s) for s in range(2)]
    # marine-radar geometry: Tx 5.7 deg above the horizon at the tile centre, Rx 11 deg,
    # 45 deg apart in azimuth (shadowing present, both visibility passes do real work)
    tx = np.array([0.0, -3.0 * n, 0.3 * n])
    rx = np.array([1.4 * n, -1.4 * n, 0.4 * n])
    t0 = time.perf_counter()
    tr = FacetTracer(x, x, zs[0], variant=variant)
    build = time.perf_counter() - t0
    k = [0]

    def update():
        k[0] ^= 1
        tr.set_surface(zs[k[0]])

    t_update = _best(update, repeat)

    def visibility():
        return tr.facets(zs[k[0]], None, tx, rx, update=False)

    t_vis = _best(visibility, repeat)
    c, _, nrm = facet_geometry(grid_vertices(x, x, zs[k[0]]))
    t_geom = _best(lambda: facet_geometry(grid_vertices(x, x, zs[k[0]])), repeat)
    t_frames_np = _best(lambda: facet_frames(c, nrm, tx, rx), repeat)
    t_frames = _best(lambda: facet_frames_drjit(c, nrm, tx, rx), repeat)
    t_rays = _best(lambda: (tr.occluded(c, nrm, tx), tr.occluded(c, nrm, rx)), repeat)
    f = visibility()
    return {
        "n": n, "triangles": int(f.n_facets), "build_s": build, "vertex_update_s": t_update,
        "visibility_and_angles_s": t_vis, "facet_geometry_s": t_geom,
        "frames_s": t_frames, "frames_numpy_s": t_frames_np, "shadow_rays_2x_all_s": t_rays,
        "lit_fraction": float(f.lit.mean()), "seen_fraction": float(f.seen.mean()),
        "peak_rss_mib": peak_rss_mb(),
    }


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", type=int, nargs="+", default=[512, 1024])
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--variant", default=None)
    p.add_argument("--child", type=int, help=argparse.SUPPRESS)
    add_option(p)
    args = p.parse_args(argv)
    if args.smoke:
        args.sizes, args.repeat = [GRID], 1
    if args.child:
        print(json.dumps(run_size(args.child, args.repeat, args.variant)))
        return 0
    print(f"load average: {os.getloadavg()}; cpus: {os.cpu_count()}")
    for n in args.sizes:
        cmd = [sys.executable, __file__, "--child", str(n), "--repeat", str(args.repeat)]
        if args.variant:
            cmd += ["--variant", args.variant]
        r = json.loads(subprocess.run(cmd, check=True, capture_output=True,
                                      text=True).stdout.strip().splitlines()[-1])
        print(f"{n} x {n} ({r['triangles']} triangles): scene build {r['build_s']:.3f} s, "
              f"vertex update {r['vertex_update_s']:.3f} s, visibility Tx+Rx with local "
              f"angles {r['visibility_and_angles_s']:.3f} s "
              f"[geometry {r['facet_geometry_s']:.3f}, frames (Dr.Jit) {r['frames_s']:.3f} "
              f"(numpy {r['frames_numpy_s']:.3f}), "
              f"2x{r['triangles']} shadow rays {r['shadow_rays_2x_all_s']:.3f}], "
              f"peak RSS {r['peak_rss_mib']:.0f} MiB "
              f"(lit {r['lit_fraction']:.3f}, seen {r['seen_fraction']:.3f})")
    print(f"load average after: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
