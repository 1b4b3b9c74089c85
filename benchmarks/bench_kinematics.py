"""Benchmark: the evolving sea's particle kinematics and the ways to transform them.

Run: ``python benchmarks/bench_kinematics.py [--grid 512] [--repeat 30]``. On Simulation
2's wind sea (no ship), CPU ms per call (``time.process_time``, median of ``--repeat``,
on the calling thread one call after the other, as ``profile_pulse.py --no-prefetch``
runs them):

- ``Sea.state`` (slopes left lazy, as a ray-traced simulation asks) and then
  ``Sea.kinematics`` of the same time (which shares its travelling waves), for the three
  requests of ``Simulation._kinematics``: the displacement alone, with the vertical
  acceleration (breaking zones), with the whole acceleration (a block of pulses);
- the inverse transform of the displacement's two half-plane spectra, five ways:
  ``scipy.fft.irfft2`` of the stack (the code before), the same with the transform along y
  worked in the scratch array (``SeaSurface._irfft_scratch``, the code now), the same with
  one worker, one full-plane complex ``ifft2`` of the two fields packed as ``D_x + j D_y``
  (their Hermitian spectra combined: the real and imaginary parts of the output), and
  ``irfft2`` in float32; with each one's largest difference from the first, relative to
  the field's largest value;
- eq BR10's band velocity (``Sea.band_velocity``, the waves ``|K| >= k_mod`` = 2.09 rad/m
  of 10 GHz), the code before (forward ``rfft2`` of the state's three velocity fields,
  band-pass, ``irfft2``) and now (the band's spectra from the travelling waves, one
  batched inverse transform in scratch), measured alternately, with their largest
  difference relative to the velocity's largest value; "shared": the travelling waves
  of that time already made (as after ``Sea.kinematics`` in a simulation).

The load average is printed: on a shared machine compare alternately (docs/performance.md).
"""

from __future__ import annotations

import argparse
import os
import pickle
import time
from pathlib import Path

import numpy as np
import scipy.fft
from _smoke import GRID, add_option

SIM2 = Path(__file__).resolve().parents[1] / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def cpu_ms(fn, repeat: int) -> float:
    """Median CPU time of ``fn()`` over ``repeat`` calls after one warm-up [ms]."""
    fn()
    times = []
    for _ in range(repeat):
        c = time.process_time()
        fn()
        times.append(time.process_time() - c)
    return 1e3 * float(np.median(times))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=512, help="sea grid points per side")
    ap.add_argument("--repeat", type=int, default=30)
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:
        args.grid, args.repeat = GRID, 2

    from seaecho.build import build_sea
    from seaecho.config import load_scene
    from seaecho.sea import _displacement_factors

    scene = load_scene(SIM2)
    scene = scene.model_copy(update={"ship": None, "objects": [],
                                     "sea": scene.sea.model_copy(update={"nx": args.grid})})
    sea = build_sea(scene)
    sea.lazy_slopes = True
    surface = sea.surface
    print(f"bench_kinematics: {SIM2.stem}, {surface.shape[1]} x {surface.shape[0]} sea, "
          f"no ship; {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}")
    print("  CPU ms per call, median of", args.repeat)
    clock = iter(range(10**9))
    from seaecho.sea import SurfaceKinematics

    requests = [("displacement", False), ("displacement + a_z", "vertical"),
                ("displacement + acceleration", True)]
    if "acceleration_z" not in SurfaceKinematics.__dataclass_fields__:  # older code
        del requests[1]
    for label, acc in requests:
        state_ms, kin_ms = [], []

        def both(acc=acc, state_ms=state_ms, kin_ms=kin_ms):
            t = 1e-3 * next(clock)  # a new surface each time
            c = time.process_time()
            sea.state(t)
            c1 = time.process_time()
            sea.kinematics(t, acceleration=acc)
            state_ms.append(c1 - c)
            kin_ms.append(time.process_time() - c1)

        cpu_ms(both, args.repeat)
        print(f"  {'Sea.state':32s} {1e3 * np.median(state_ms[1:]):8.2f}   then "
              f"Sea.kinematics, {label:28s} {1e3 * np.median(kin_ms[1:]):8.2f}")

    # the displacement's two spectra, transformed five ways
    t = 0.37
    plus, minus = surface._travelling(t)
    jx, jy = _displacement_factors(surface)
    spectra = np.stack([jx * (plus + minus), jy * (plus + minus)])
    ny, nx = surface.shape
    work = np.empty_like(spectra)

    def irfft2(spec, workers=-1):
        return scipy.fft.irfft2(spec, s=(ny, nx), norm="forward", workers=workers)

    def in_scratch():
        np.copyto(work, spectra)  # the code writes the spectra there in any case
        return surface._irfft_scratch(work)

    def one_worker():
        np.copyto(work, spectra)
        w = scipy.fft.ifft(work, axis=-2, norm="forward", overwrite_x=True, workers=1)
        return scipy.fft.irfft(w, n=nx, axis=-1, norm="forward", workers=1)

    # full plane of each Hermitian spectrum: S(-K) = conj(S(K)) fills kx < 0
    iy = (-np.arange(ny)) % ny
    ix = (-np.arange(nx // 2 + 1, nx)) % nx

    def packed():
        full = np.empty((2, ny, nx), complex)
        full[:, :, : nx // 2 + 1] = spectra
        full[:, :, nx // 2 + 1:] = np.conj(spectra[:, iy][:, :, ix])
        return split(scipy.fft.ifft2(full[0] + 1j * full[1], norm="forward", workers=-1))

    full = np.empty((2, ny, nx), complex)
    full[:, :, : nx // 2 + 1] = spectra
    full[:, :, nx // 2 + 1:] = np.conj(spectra[:, iy][:, :, ix])
    both_fields = full[0] + 1j * full[1]
    single = spectra.astype(np.complex64)

    def split(c):
        return np.stack([c.real, c.imag])

    ref = irfft2(spectra)
    scale = np.abs(ref).max()
    ways = [("irfft2 of the stack (before)", lambda: irfft2(spectra)),
            ("along y in scratch (now)", in_scratch),
            ("the same, one worker", one_worker),
            ("packed D_x + j D_y, ifft2", packed),
            ("the same, the plane ready", lambda: split(scipy.fft.ifft2(
                both_fields, norm="forward", workers=-1))),
            ("irfft2 in float32", lambda: irfft2(single))]
    if not hasattr(surface, "_irfft_scratch"):  # older code
        del ways[1]
    for label, fn in ways:
        out = fn()
        err = np.abs(out.astype(np.float64) - ref).max() / scale
        print(f"  {label:32s} {cpu_ms(fn, args.repeat):8.2f}   largest difference "
              f"{err:.1e} of max |D| = {scale:.3f} m")
    bench_band_velocity(sea, args.repeat)


def band_velocity_before(surface, v, k_min: float):
    """Eq BR10's band velocity as the code before computed it: forward transforms of the
    state's velocity ``v`` (ny, nx, 3), band-pass, inverse transforms."""
    ny, nx = surface.shape
    k2 = surface._kx ** 2 + surface._ky ** 2
    spec = scipy.fft.rfft2(np.moveaxis(v, -1, 0), axes=(-2, -1), workers=-1)
    spec = np.where(k2 >= k_min * k_min, spec, 0.0)
    out = scipy.fft.irfft2(spec, s=(ny, nx), axes=(-2, -1), workers=-1)
    return np.moveaxis(out, 0, -1)


def bench_band_velocity(sea, repeat: int) -> None:
    """Eq BR10's band velocity before and now, alternately (CPU ms, median)."""
    surface, k_mod = sea.surface, 2.09
    if not hasattr(surface, "band_velocity"):  # older code
        return
    t = 0.61
    v = sea.state(t).velocity
    ref = band_velocity_before(surface, v, k_mod)
    now = sea.band_velocity(t, k_mod)
    scale = np.abs(v).max()
    print(f"  eq BR10 band velocity, k_mod = {k_mod} rad/m: largest difference now - "
          f"before {np.abs(now - ref).max() / scale:.1e} of max |v| = {scale:.3f} m/s")
    clock = iter(range(1, 10**9))
    times: dict[str, list[float]] = {"before": [], "now, shared": [], "now, fresh": []}
    fresh = pickle.loads(pickle.dumps(surface))  # a copy that keeps no time's waves
    fresh.share_travelling = False
    for _ in range(repeat + 1):
        for label, fn in (("before", lambda: band_velocity_before(surface, v, k_mod)),
                          ("now, shared", lambda: sea.band_velocity(t, k_mod))):
            c = time.process_time()
            fn()
            times[label].append(time.process_time() - c)
        tf = t + 1e-3 * next(clock)  # a time whose travelling waves are not kept
        c = time.process_time()
        fresh.band_velocity(tf, k_mod)
        times["now, fresh"].append(time.process_time() - c)
    for label, ts in times.items():
        print(f"  {'band velocity, ' + label:32s} {1e3 * np.median(ts[1:]):8.2f}")


if __name__ == "__main__":
    main()
