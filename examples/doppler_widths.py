"""X-band sea-clutter Doppler widths at the conditions of published measurements.

Run: ``python examples/doppler_widths.py [OUTDIR]`` (default ``docs/figures``).

The radar and sea of ``examples/xband_doppler_measured.py`` (monostatic 10 GHz radar 1 km
from the tile, the default sea: Elfouhaily spectrum with the Longuet-Higgins spreading,
128 m tile on a 1 m grid, the default model ``blend+breaking``, the default sea motion,
which evolves this sea, and the default surface drift; geometry every 8 pulses, PRF
500 Hz, 96 pulses) at the grazing angles of the published X-band Doppler measurements
listed in ``tests/validation/doppler_references.py`` (``WIDTH_MEASUREMENTS``): 3 deg
(Hwang, Sletten & Toporkov 2008: 1.4-5.5 deg; Lee et al. 1996, LOGAN, DSTO-TR-2864: low
grazing), 10 deg and 30 deg (Rosenberg 2014: 15-45 deg; Johnsen 2015: 3-56 deg); upwind
at U19.5 = 5, 8 and 12 m/s (seeds 1 and 2), crosswind and downwind at 8 m/s (seed 1).

Per case and channel: the rms width of the clutter Doppler spectrum (eq DP2 of
docs/dynamics.md) in Hz and as line-of-sight velocity ``lambda w / 2`` [m/s]; the
composite-surface width ``sqrt(sigma_orb^2 + 4 p+ p- f_B^2)`` (``sea_doppler.py``); the
power-weighted mean width of a single 0.75 m range cell's spectrum over the 0.19 s
(``sea_doppler.cell_width_hz``: without the spread of the centroids from cell to cell,
which widens the clutter spectrum summed over the cells); the
sea's ``H_s / T_p`` (significant height over peak period of the wave spectrum) and the
ratio of the velocity width to it, which Hicks et al. (1960) found constant for X-band
clutter (the proportionality of the width to H/T, quoted second-hand; its coefficient
was not read). No published width was found as a number, so the "published" column
names the measurements whose conditions the row matches, for a future comparison.

Writes ``dynamics_doppler_widths.csv`` and prints the table of docs/dynamics.md; about
3 minutes of CPU (24 runs).
"""

from __future__ import annotations

import csv
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "validation"))

from doppler_references import (  # noqa: E402
    WIDTH_MEASUREMENTS,
    hicks_velocity_scale_m_s,
)
from xband_doppler_measured import F, simulate  # noqa: E402

from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.dispersion import angular_frequency  # noqa: E402
from seaecho.ocean.limits import significant_height  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.ocean.wind import u10_from_u19_5  # noqa: E402

#: (grazing [deg], U19.5 [m/s], look [deg]: 0 upwind, 90 crosswind, 180 downwind, seeds)
WIDTH_CASES = tuple(
    case for g in (3.0, 10.0, 30.0) for case in (
        (g, 5.0, 0.0, (1, 2)), (g, 8.0, 0.0, (1, 2)), (g, 12.0, 0.0, (1, 2)),
        (g, 8.0, 90.0, (1,)), (g, 8.0, 180.0, (1,))))
LOOKS = {0.0: "up", 90.0: "cross", 180.0: "down"}


def sea_scales(u19_5: float) -> tuple[float, float]:
    """Significant height H_s [m] and peak period T_p [s] of the default sea's wave
    spectrum (Elfouhaily et al. 1997, fully developed) at U19.5 [m/s]."""
    spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", u19_5)
    t_p = 2.0 * np.pi / float(angular_frequency(spec.peak_wavenumber()))
    return significant_height(spec), t_p


def _in(value: float, rng) -> bool:
    """Is ``value`` in a published range (a (lo, hi) tuple; "low"/"small" grazing: up to
    10 deg; None: not stated, so not matched)?"""
    if rng is None:
        return False
    if isinstance(rng, str):
        return rng in ("low", "small") and value <= 10.0
    return rng[0] <= value <= rng[1]


def matching_measurements(grazing_deg: float, u10: float) -> list[str]:
    """Short names of the ``WIDTH_MEASUREMENTS`` whose grazing angles include
    ``grazing_deg`` and whose winds, where stated, include ``u10``."""
    out = []
    for m in WIDTH_MEASUREMENTS:
        wind = m["wind_m_s"]
        wind_ok = not isinstance(wind, tuple) or wind[0] <= u10 <= wind[1]
        if _in(grazing_deg, m["grazing_deg"]) and wind_ok:
            out.append(m["short"])
    return out


def width_comparison(outdir: str = "docs/figures", cases=WIDTH_CASES,
                     name: str = "dynamics_doppler_widths.csv", **kw) -> Path:
    """Simulated widths at ``cases`` (``WIDTH_CASES``' form); ``kw`` go to
    ``xband_doppler_measured.simulate`` (e.g. ``size``, ``n``, ``n_pulses``)."""
    lam = C0 / F
    rows = []
    for g, u, look, seeds in cases:
        t = time.perf_counter()
        sims = [simulate(u, g, look_deg=look, seed=s, **kw) for s in seeds]
        r = {k: np.array([s[k] for s in sims]) for k in sims[0]}
        u10 = float(u10_from_u19_5(u))
        h_s, t_p = sea_scales(u)
        scale = float(hicks_velocity_scale_m_s(h_s, t_p))
        vv, hh = r["width_vv_hz"], r["width_hh_hz"]
        row = {"grazing_deg": g, "u19_5_m_s": u, "u10_m_s": round(u10, 2),
               "look_deg": look, "n_seeds": len(seeds), "hs_m": round(h_s, 3),
               "tp_s": round(t_p, 3), "hs_over_tp_m_s": round(scale, 4),
               "width_vv_hz": round(float(vv.mean()), 2),
               "width_vv_spread_hz": round(float(np.ptp(vv)) / 2.0, 2),
               "width_hh_hz": round(float(hh.mean()), 2),
               "width_hh_spread_hz": round(float(np.ptp(hh)) / 2.0, 2),
               "width_vv_m_s": round(float(vv.mean()) * lam / 2.0, 4),
               "width_hh_m_s": round(float(hh.mean()) * lam / 2.0, 4),
               "composite_width_hz": round(float(r["composite_width_hz"].mean()), 2),
               "cell_width_vv_hz": round(float(r["cell_width_vv_hz"].mean()), 2),
               "cell_width_hh_hz": round(float(r["cell_width_hh_hz"].mean()), 2),
               "hicks_ratio_vv": round(float(vv.mean()) * lam / 2.0 / scale, 3),
               "hicks_ratio_hh": round(float(hh.mean()) * lam / 2.0 / scale, 3),
               "published": "; ".join(matching_measurements(g, u10)) or "none"}
        rows.append(row)
        print(f"{g:4.0f} deg, U19.5 {u:4.1f}, {LOOKS[look]:5s}: VV {row['width_vv_hz']:5.1f}"
              f" Hz ({row['width_vv_m_s']:.2f} m/s), HH {row['width_hh_hz']:5.1f} Hz "
              f"({row['width_hh_m_s']:.2f} m/s), composite {row['composite_width_hz']:5.1f}"
              f" Hz, one cell VV {row['cell_width_vv_hz']:5.1f}, HH "
              f"{row['cell_width_hh_hz']:5.1f} Hz, H_s/T_p {scale:.3f} m/s, ratio VV "
              f"{row['hicks_ratio_vv']:.2f}, HH {row['hicks_ratio_hh']:.2f}  "
              f"({time.perf_counter() - t:.0f} s)", flush=True)
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / name
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {path}")
    return path


def markdown(path: Path) -> str:
    """The table of docs/dynamics.md from the CSV written by :func:`width_comparison`."""
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    lines = ["| grazing [deg] | U19.5 (U10) [m/s] | look | H_s / T_p [m/s] | VV width [Hz] "
             "(m/s) | HH width [Hz] (m/s) | composite [Hz] | one cell VV, HH [Hz] | "
             "width / (H_s/T_p) VV, HH | published width (conditions of) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    def pm(r, c):  # the half-range of the seeds' widths, where there are two
        return f" ± {float(r[f'width_{c}_spread_hz']):.1f}" if int(r["n_seeds"]) > 1 else ""

    for r in rows:
        lines.append(
            f"| {float(r['grazing_deg']):g} | {float(r['u19_5_m_s']):g} "
            f"({float(r['u10_m_s']):.1f}) | {LOOKS[float(r['look_deg'])]} | "
            f"{float(r['hs_over_tp_m_s']):.3f} | {float(r['width_vv_hz']):.1f}{pm(r, 'vv')} "
            f"({float(r['width_vv_m_s']):.2f}) | {float(r['width_hh_hz']):.1f}{pm(r, 'hh')} "
            f"({float(r['width_hh_m_s']):.2f}) | {float(r['composite_width_hz']):.1f} | "
            f"{float(r['cell_width_vv_hz']):.1f}, {float(r['cell_width_hh_hz']):.1f} | "
            f"{float(r['hicks_ratio_vv']):.2f}, {float(r['hicks_ratio_hh']):.2f} | "
            f"not found ({r['published']}) |")
    return "\n".join(lines)


if __name__ == "__main__":
    p = width_comparison(*sys.argv[1:])
    print(markdown(p))
