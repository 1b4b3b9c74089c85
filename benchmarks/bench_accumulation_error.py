"""The echo accumulation in single precision against double, on a Simulation 2 pulse:
the error in dB of each channel's energy and per sample against an ideal ADC.

The sea echo of one pulse of Simulation 2 (the fused kernel's delays and amplitudes, as
``RadarSystem.receive`` gets them) is accumulated by eq (E2) twice,
``accumulate(..., precision="double")`` (finufft at 1e-9) and ``precision="single"``
(float32 points and amplitudes). Per channel: the relative l2 error of the raw samples,
the difference of the channel's energy [dB], the largest sample error against the
channel's full scale (its largest I or Q value), the rms error against the quantisation
noise of an ideal 16-bit converter whose full scale is that largest value (no headroom:
the most demanding case, LSB / sqrt(12) per component), the fraction of samples whose
error exceeds 1e-3 of their own magnitude, and the channel's dynamic range (largest over
smallest sample magnitude).
"""

from __future__ import annotations

import argparse
import os
import warnings
from pathlib import Path

import numpy as np
from _smoke import GRID, add_option, small_scene
from bench_accumulate import sim2_pulse

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_option(ap)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from seaecho.radar.echo import accumulate

    path = small_scene(SIM2, grid=GRID) if args.smoke else SIM2
    tau, rows, spec, window = sim2_pulse(path, 0 if args.smoke else 40)
    d = accumulate(tau, rows, spec, window, precision="double")
    s = accumulate(tau, rows, spec, window, precision="single")
    d, s = np.atleast_2d(d), np.atleast_2d(s)
    print(f"bench_accumulation_error: {path.stem}, {tau.size} scatterers, {d.shape[1]} "
          f"samples; load {os.getloadavg()[0]:.2f}")
    print(f"  {'ch':3s} {'rel l2 [dB]':>11s} {'energy [dB]':>11s} {'max err/FS [dB]':>15s} "
          f"{'rms err/16-bit q [dB]':>21s} {'err>1e-3|r|':>11s} {'range [dB]':>10s}")
    for c in range(d.shape[0]):
        e = s[c] - d[c]
        rel = np.linalg.norm(e) / np.linalg.norm(d[c])
        energy = 10.0 * np.log10(np.sum(np.abs(s[c]) ** 2) / np.sum(np.abs(d[c]) ** 2))
        fs = max(np.abs(d[c].real).max(), np.abs(d[c].imag).max())
        q16 = 2.0 * fs / 2**16 / np.sqrt(12.0)
        e_rms = np.sqrt(np.mean(e.real**2 + e.imag**2) / 2.0)
        bad = np.mean(np.abs(e) > 1e-3 * np.abs(d[c]))
        span = np.abs(d[c]).max() / np.abs(d[c]).min()
        print(f"  {c:<3d} {20 * np.log10(rel):11.1f} {energy:11.2e} "
              f"{20 * np.log10(np.abs(e).max() / fs):15.1f} "
              f"{20 * np.log10(e_rms / q16):21.1f} {bad:11.2e} {20 * np.log10(span):10.1f}")


if __name__ == "__main__":
    main()
