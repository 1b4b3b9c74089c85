"""The GPU machine's set-up: versions, Dr.Jit's back ends, cufinufft against a direct sum.

Run first by ``tools/gpu/run.sh`` (docs/performance.md, section 4).
"""

from __future__ import annotations

import subprocess
import sys
import time

import numpy as np


def main() -> None:
    print("python", sys.version.split()[0], "numpy", np.__version__)
    print(subprocess.run(["nvidia-smi", "--query-gpu=name,memory.total,driver_version",
                          "--format=csv,noheader"], capture_output=True,
                         text=True).stdout.strip())
    import drjit as dr

    print("drjit", dr.__version__, "CUDA", dr.has_backend(dr.JitBackend.CUDA))
    try:
        print("LLVM back end:", dr.has_backend(dr.JitBackend.LLVM))
    except Exception as exc:  # noqa: BLE001 - reported, not fatal
        print("LLVM back end: error", exc)
    import mitsuba as mi

    mi.set_variant("cuda_ad_mono_polarized")
    print("mitsuba", mi.__version__, mi.variant())
    t = time.perf_counter()
    import cufinufft
    import cupy as cp

    rng = np.random.default_rng(1)
    k, n = 20000, 210
    x = rng.uniform(-np.pi, np.pi, k)
    c = rng.normal(size=k) + 1j * rng.normal(size=k)
    plan = cufinufft.Plan(1, (n,), n_trans=1, eps=1e-9, isign=-1, dtype="complex128",
                          modeord=1)
    plan.setpts(cp.asarray(x))
    f = plan.execute(cp.asarray(c)).get()
    modes = np.fft.fftfreq(n, 1.0 / n)
    ref = np.exp(-1j * np.outer(modes, x)) @ c
    print(f"cufinufft {cufinufft.__version__}: type 1, {k} points, {n} modes, rel. error "
          f"{np.abs(f - ref).max() / np.abs(ref).max():.1e} in {time.perf_counter() - t:.1f} s")


if __name__ == "__main__":
    main()
