"""Sea-clutter Doppler centroid and width against what measurements show: X band at low
grazing, and C and X band at moderate incidence against published Doppler model functions.

Run: ``python examples/xband_doppler_measured.py [OUTDIR] [--grazing DEG | --gmf |
--breaking | --quick-spread]`` (default ``docs/figures``, 10 deg).
Monostatic 10 GHz radar 1 km from the tile, looking upwind at 10 deg grazing, the sea of
``sea_doppler.py`` (Elfouhaily spectrum, the default Longuet-Higgins spreading with s = 1:
the waves travel with the wind) on a 128 m tile with a 1 m grid, the default scattering
model (``blend+breaking``) and
the default sea motion (``"auto"``: the sea is renewed within the run, so it evolves),
geometry every 8 pulses, PRF 500 Hz, 96 pulses, wind U19.5 = 5, 8 and 12 m/s. Prints, per
wind and channel, the clutter Doppler centroid and rms width (eq DP2 of docs/dynamics.md),
in Hz and as line-of-sight velocity ``lambda f / 2``, beside the references:

* the Bragg line ``f_B`` (first-order Bragg waves travelling towards the radar; Crombie
  1955, Wright 1968),
* the VV peak of the low-grazing Doppler model of Trizna (1985), fitted to measured VV
  spectra: the Bragg phase speed plus the orbital velocity of the long waves plus the
  wind drift of the surface. The drift is 3 % of U10 along the wind (AMS Glossary of
  Meteorology; Wu 1975), which the simulation now carries too (the default ``[sea]
  wind_drift = "auto"`` is ``"3pct"`` on this evolving sea); the Bragg line plus the
  drift's Doppler ``2 (0.03 U10) cos(psi) / lambda`` is printed (the orbital term is not
  tabulated by these references),
* the measured orderings: HH centroids above VV at low grazing (Trizna 1985; Lee et al.
  1995), the speed of the "faster-than-Bragg" scatterers increasing with the wind (Lee et
  al. 1996, data at winds of 3.8-10.3 m/s), widths growing with the wind (the orbital
  velocities; Walker 2001).

Writes ``dynamics_doppler_measured.csv``.

``--gmf``: the moderate-incidence comparison with the published Doppler model functions
(``tests/validation/doppler_references.py``): the same sea and radar at 35 deg incidence
(the middle of both GMFs' domains), U19.5 = 5, 8, 12 m/s upwind and 8 m/s crosswind and
downwind, and 8 m/s upwind with the centro-symmetric Elfouhaily spreading, three seeds
each, at 5.5 GHz against CDOP (Mouche et al. 2012, C band, VV and
HH, Hz) and at 10 GHz against the TanDEM-X finding of Elyouncha et al. (2021) that the
wind sea's Doppler velocity is about 0.15 U10 cos(phi) (horizontal). Writes
``dynamics_doppler_gmf.csv``; about 3 minutes of CPU. ``--gmf --no-drift``: the same with
``[sea] wind_drift = "none"`` (the default before the drift was: no surface drift), the
default-spreading cases only; writes ``dynamics_doppler_gmf_nodrift.csv``.

``--quick-spread``: the quick test's case (X band, 8 m/s upwind, 35 deg, a 64 m tile)
over seeds 1-16 with 24 and 48 pulses: the centroids' mean and seed-to-seed standard
deviation; writes ``dynamics_doppler_quick_spread.csv``; about a minute of CPU.

``--breaking``: the effect of breaking at low grazing against Hwang, Sletten & Toporkov
(2008), *J. Geophys. Res.* 113, C09017 (X band, winds 7-15 m/s, grazing 1.4-5.5 deg):
breaking makes the Doppler velocity of both polarisations "about 50% faster". The same
sea at 3 deg grazing, U19.5 = 8 and 12 m/s upwind, with and without breaking zones (model
``blend+breaking`` against ``blend``), two seeds. Writes ``dynamics_doppler_breaking.csv``.
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
    CDOP_FREQUENCY_HZ,
    cdop_hz,
    xband_wave_doppler_m_s,
)
from sea_doppler import F, cell_width_hz, composite_prediction, run_spectra  # noqa: E402

from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.wind import SURFACE_DRIFT_OVER_U10, u10_from_u19_5  # noqa: E402
from seaecho.processing.doppler import doppler_moments, doppler_spectrum  # noqa: E402
from seaecho.scattering.dynamics import bragg_frequency  # noqa: E402

GRAZING_DEG = 10.0
WINDS = (5.0, 8.0, 12.0)  # U19.5 [m/s]
#: Surface drift as a fraction of U10 (AMS Glossary of Meteorology; Wu 1975), the drift
#: Trizna (1985) and Walker (2001) add to the Bragg speed: the default wind drift's law
DRIFT_FRACTION = SURFACE_DRIFT_OVER_U10
N_PULSES = 96


def write_csv(outdir: str, name: str, header: list[str], rows: list[list]) -> Path:
    """Write ``rows`` under ``header`` to ``outdir/name`` (made if missing); its path."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / name
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(rows)
    print(f"wrote {path}")
    return path


def references(u19_5: float, grazing_deg: float = GRAZING_DEG) -> dict[str, float]:
    """Bragg line and the wind drift's Doppler [Hz] (monostatic, upwind)."""
    lam = C0 / F
    cos_g = np.cos(np.radians(grazing_deg))
    k_b = 2.0 * (2.0 * np.pi / lam) * cos_g
    u10 = float(u10_from_u19_5(u19_5))
    return {"f_bragg_hz": float(bragg_frequency(k_b)), "u10_m_s": u10,
            "f_drift_hz": 2.0 * DRIFT_FRACTION * u10 * cos_g / lam}


def simulate(u19_5: float, grazing_deg: float = GRAZING_DEG, n_pulses: int = N_PULSES,
             size: float = 128.0, n: int = 128, look_deg: float = 0.0, seed: int = 1,
             freq_hz: float = F, model: str = "blend+breaking",
             spreading: str | None = None, wind_drift: str | None = None
             ) -> dict[str, float]:
    """Centroid and rms width [Hz] of the HH and VV clutter Doppler spectra, and the
    composite model's Bragg centroid ``(2 p+ - 1) f_B`` [Hz] and width
    ``sqrt(sigma_orb^2 + 4 p+ p- f_B^2)`` [Hz] (``sea_doppler.py``), and the mean
    width of a single range cell's spectrum (``sea_doppler.cell_width_hz``) [Hz];
    ``look_deg`` 0: the radar looks upwind; ``spreading`` None: the default
    ``[sea] spreading``."""
    sim, f, psd, cells = run_spectra(u19_5, look_deg, 90.0 - grazing_deg, model,
                                     size=size, n=n, n_pulses=n_pulses, motion=None,
                                     seed=seed, freq_hz=freq_hz, spreading=spreading,
                                     wind_drift=wind_drift)
    cen, wid = doppler_moments(f, doppler_spectrum(f, psd, cells))
    cell = cell_width_hz(f, psd, cells)
    b_cen, b_wid = composite_prediction(sim, 90.0 - grazing_deg, look_deg)[:2]
    return {"centroid_hh_hz": float(cen[0]), "centroid_vv_hz": float(cen[1]),
            "width_hh_hz": float(wid[0]), "width_vv_hz": float(wid[1]),
            "bragg_centroid_hz": float(b_cen), "composite_width_hz": float(b_wid),
            "cell_width_hh_hz": float(cell[0]), "cell_width_vv_hz": float(cell[1])}


def horizontal_velocity_m_s(f_hz, freq_hz: float, incidence_deg: float):
    """Horizontal (ground-range) surface velocity [m/s] of a monostatic Doppler shift:
    ``lambda f_D / (2 sin(theta))``, the convention of the Doppler GMFs."""
    return (C0 / freq_hz) * np.asarray(f_hz) / (2.0 * np.sin(np.radians(incidence_deg)))


#: moderate-incidence cases: (U19.5 [m/s], look [deg], 0 = upwind, [sea] spreading: None
#: the default, Longuet-Higgins s = 1; "elfouhaily" centro-symmetric, the variant)
GMF_INCIDENCE_DEG = 35.0
GMF_CASES = ((5.0, 0.0, None), (8.0, 0.0, None), (12.0, 0.0, None), (8.0, 90.0, None),
             (8.0, 180.0, None), (8.0, 0.0, "elfouhaily"))
GMF_SEEDS = (1, 2, 3)


def published_centroids_hz(band: str, u10: float, look_deg: float,
                           incidence_deg: float = GMF_INCIDENCE_DEG) -> tuple[float, float]:
    """(VV, HH) Doppler centroid [Hz] of the published model for the band: CDOP at 5.5 GHz
    ("C"), ``0.15 U10 cos(phi)`` horizontal at 10 GHz ("X", both channels)."""
    if band == "C":
        return tuple(float(cdop_hz(incidence_deg, u10, look_deg, p)) for p in ("VV", "HH"))
    v = float(xband_wave_doppler_m_s(u10, look_deg))
    f = v * 2.0 * np.sin(np.radians(incidence_deg)) / (C0 / F)
    return f, f


def gmf_comparison(outdir: str = "docs/figures", seeds=GMF_SEEDS, size: float = 128.0,
                   n: int = 128, n_pulses: int = N_PULSES, cases=GMF_CASES,
                   wind_drift: str | None = None) -> Path:
    """Simulated centroids at 35 deg incidence against CDOP (5.5 GHz) and the X-band
    0.15 U10 cos(phi) (10 GHz); mean and standard deviation over ``seeds``;
    ``wind_drift`` (e.g. ``"none"``) sets ``[sea] wind_drift`` and writes
    ``dynamics_doppler_gmf_<wind_drift>.csv``."""
    rows = []
    inc = GMF_INCIDENCE_DEG
    vh = horizontal_velocity_m_s
    for band, freq in (("C", CDOP_FREQUENCY_HZ), ("X", F)):
        for u, look, spreading in cases:
            t = time.perf_counter()
            u10 = float(u10_from_u19_5(u))
            sims = [simulate(u, 90.0 - inc, n_pulses, size, n, look, s, freq,
                             spreading=spreading, wind_drift=wind_drift) for s in seeds]
            r = {k: np.array([s[k] for s in sims]) for k in sims[0]}
            vv, hh = r["centroid_vv_hz"], r["centroid_hh_hz"]
            ref_vv, ref_hh = published_centroids_hz(band, u10, look, inc)
            name = spreading or "longuet-higgins"
            print(f"{band} band, U19.5 {u:4.1f} (U10 {u10:4.1f}), look {look:5.1f}, {name}: "
                  f"VV {vv.mean():+6.1f} +- {vv.std():4.1f} Hz ({vh(vv.mean(), freq, inc):+.2f}"
                  f" m/s)  HH {hh.mean():+6.1f} +- {hh.std():4.1f} Hz  published VV "
                  f"{ref_vv:+6.1f}, HH {ref_hh:+6.1f} Hz ({vh(ref_vv, freq, inc):+.2f} m/s)"
                  f"  Bragg {r['bragg_centroid_hz'].mean():+5.1f} Hz  widths VV "
                  f"{r['width_vv_hz'].mean():5.1f}, HH {r['width_hh_hz'].mean():5.1f} Hz  "
                  f"({time.perf_counter() - t:.0f} s)", flush=True)
            rows.append([band, freq, inc, u, round(u10, 2), look, name,
                         *(round(float(x), 2) for x in (
                             vv.mean(), vv.std(), hh.mean(), hh.std(),
                             r["width_vv_hz"].mean(), r["width_hh_hz"].mean(),
                             r["bragg_centroid_hz"].mean(), ref_vv, ref_hh)),
                         *(round(float(vh(x, freq, inc)), 3)
                           for x in (vv.mean(), hh.mean(), ref_vv, ref_hh))])
    name = ("dynamics_doppler_gmf.csv" if wind_drift is None
            else f"dynamics_doppler_gmf_{wind_drift.replace('none', 'nodrift')}.csv")
    return write_csv(outdir, name, [
        "band", "frequency_hz", "incidence_deg", "u19_5_m_s", "u10_m_s", "look_deg",
        "spreading", "centroid_vv_hz", "centroid_vv_std_hz", "centroid_hh_hz",
        "centroid_hh_std_hz", "width_vv_hz", "width_hh_hz", "bragg_centroid_hz",
        "published_vv_hz", "published_hh_hz", "velocity_vv_m_s", "velocity_hh_m_s",
        "published_vv_m_s", "published_hh_m_s"], rows)


#: the quick case of ``tests/validation/test_doppler_gmf.py``: X band, U19.5 = 8 m/s
#: upwind, 35 deg incidence, a 64 m tile on a 1 m grid, 24 pulses (0.048 s)
QUICK_U19_5_M_S = 8.0
QUICK_SIZE_M = 64.0
QUICK_N = 64
QUICK_N_PULSES = 24


def quick_spread(outdir: str = "docs/figures", seeds=tuple(range(1, 17)),
                 pulses=(QUICK_N_PULSES, 48)) -> Path:
    """The quick case's centroids per seed for each number of ``pulses`` and their mean
    and sample standard deviation [Hz], against the published 0.15 U10 (X band): the
    seed-to-seed spread that sets the quick test's standard error. Writes
    ``dynamics_doppler_quick_spread.csv`` (one row per pulse count and seed)."""
    inc = GMF_INCIDENCE_DEG
    ref = published_centroids_hz("X", float(u10_from_u19_5(QUICK_U19_5_M_S)), 0.0, inc)[0]
    rows = []
    for n_pulses in pulses:
        t = time.perf_counter()
        sims = [simulate(QUICK_U19_5_M_S, 90.0 - inc, n_pulses, QUICK_SIZE_M, QUICK_N, 0.0,
                         s, F) for s in seeds]
        hh = np.array([r["centroid_hh_hz"] for r in sims])
        vv = np.array([r["centroid_vv_hz"] for r in sims])
        print(f"{n_pulses} pulses, seeds {seeds[0]}-{seeds[-1]}: HH {hh.mean():.2f} sd "
              f"{hh.std(ddof=1):.2f} Hz, VV {vv.mean():.2f} sd {vv.std(ddof=1):.2f} Hz, "
              f"HH - VV sd {(hh - vv).std(ddof=1):.2f} Hz; seeds 1-8: HH "
              f"{hh[:8].mean():.2f}, VV {vv[:8].mean():.2f} Hz; published {ref:.2f} Hz  "
              f"({time.perf_counter() - t:.0f} s)", flush=True)
        rows += [[n_pulses, s, round(float(a), 2), round(float(b), 2), round(ref, 2)]
                 for s, a, b in zip(seeds, hh, vv, strict=True)]
    return write_csv(outdir, "dynamics_doppler_quick_spread.csv",
                     ["n_pulses", "seed", "centroid_hh_hz", "centroid_vv_hz",
                      "published_hz"], rows)


#: low-grazing breaking cases (Hwang, Sletten & Toporkov 2008: winds 7-15 m/s, 1.4-5.5 deg)
BREAKING_GRAZING_DEG = 3.0
BREAKING_WINDS = (8.0, 12.0)
BREAKING_SEEDS = (1, 2)


def breaking_comparison(outdir: str = "docs/figures", seeds=BREAKING_SEEDS,
                        size: float = 128.0, n: int = 128,
                        n_pulses: int = N_PULSES) -> Path:
    """Centroids at 3 deg grazing upwind with and without breaking zones, and their
    ratio, against the ~1.5 of Hwang et al. (2008)."""
    rows = []
    for u in BREAKING_WINDS:
        t = time.perf_counter()
        res = {m: [simulate(u, BREAKING_GRAZING_DEG, n_pulses, size, n, 0.0, s, F, m,
                            spreading=None)
                   for s in seeds] for m in ("blend+breaking", "blend")}
        c = {(m, ch): np.mean([r[f"centroid_{ch}_hz"] for r in res[m]])
             for m in res for ch in ("vv", "hh")}
        ratio = {ch: c[("blend+breaking", ch)] / c[("blend", ch)] for ch in ("vv", "hh")}
        print(f"U19.5 {u:4.1f}: with breaking VV {c[('blend+breaking', 'vv')]:+6.1f}, HH "
              f"{c[('blend+breaking', 'hh')]:+6.1f} Hz; without VV {c[('blend', 'vv')]:+6.1f}"
              f", HH {c[('blend', 'hh')]:+6.1f} Hz; ratio VV {ratio['vv']:.2f}, HH "
              f"{ratio['hh']:.2f} (Hwang et al. 2008: about 1.5)  "
              f"({time.perf_counter() - t:.0f} s)", flush=True)
        rows.append([u, round(float(u10_from_u19_5(u)), 2), BREAKING_GRAZING_DEG,
                     *(round(float(c[k]), 2) for k in (
                         ("blend+breaking", "vv"), ("blend+breaking", "hh"),
                         ("blend", "vv"), ("blend", "hh"))),
                     round(float(ratio["vv"]), 3), round(float(ratio["hh"]), 3)])
    return write_csv(outdir, "dynamics_doppler_breaking.csv",
                     ["u19_5_m_s", "u10_m_s", "grazing_deg", "centroid_vv_breaking_hz",
                      "centroid_hh_breaking_hz", "centroid_vv_no_breaking_hz",
                      "centroid_hh_no_breaking_hz", "ratio_vv", "ratio_hh"], rows)


def main(outdir: str = "docs/figures", grazing_deg: float = GRAZING_DEG) -> Path:
    """Run the three winds at ``grazing_deg`` [deg] (``--grazing G`` on the command
    line); the CSV of a grazing other than 10 deg is named after it."""
    lam = C0 / F
    rows = []
    for u in WINDS:
        t = time.perf_counter()
        ref, sim = references(u, grazing_deg), simulate(u, grazing_deg)
        trizna_vv = ref["f_bragg_hz"] + ref["f_drift_hz"]
        print(f"U19.5 {u:4.1f} (U10 {ref['u10_m_s']:4.1f}) m/s: "
              f"VV {sim['centroid_vv_hz']:+6.1f} Hz ({sim['centroid_vv_hz'] * lam / 2:+.2f} "
              f"m/s) / {sim['width_vv_hz']:5.1f} Hz   HH {sim['centroid_hh_hz']:+6.1f} Hz "
              f"({sim['centroid_hh_hz'] * lam / 2:+.2f} m/s) / {sim['width_hh_hz']:5.1f} Hz   "
              f"Bragg {ref['f_bragg_hz']:5.1f} Hz, drift {ref['f_drift_hz']:5.1f} Hz, "
              f"Bragg + drift {trizna_vv:5.1f} Hz   ({time.perf_counter() - t:.0f} s)",
              flush=True)
        rows.append([u, round(ref["u10_m_s"], 2), grazing_deg,
                     *(round(sim[k], 2) for k in ("centroid_vv_hz", "centroid_hh_hz",
                                                  "width_vv_hz", "width_hh_hz")),
                     round(ref["f_bragg_hz"], 2), round(ref["f_drift_hz"], 2)])
    name = ("dynamics_doppler_measured.csv" if grazing_deg == GRAZING_DEG
            else f"dynamics_doppler_measured_{grazing_deg:g}deg.csv")
    return write_csv(outdir, name,
                     ["u19_5_m_s", "u10_m_s", "grazing_deg", "centroid_vv_hz",
                      "centroid_hh_hz", "width_vv_hz", "width_hh_hz", "bragg_hz",
                      "drift_hz"], rows)


if __name__ == "__main__":
    args = sys.argv[1:]
    if "--gmf" in args:
        args.remove("--gmf")
        if "--no-drift" in args:  # [sea] wind_drift = "none", default-spreading cases
            args.remove("--no-drift")
            gmf_comparison(*args, cases=tuple(c for c in GMF_CASES if c[2] is None),
                           wind_drift="none")
        else:
            gmf_comparison(*args)
        sys.exit(0)
    if "--quick-spread" in args:
        args.remove("--quick-spread")
        quick_spread(*args)
        sys.exit(0)
    if "--breaking" in args:
        args.remove("--breaking")
        breaking_comparison(*args)
        sys.exit(0)
    g = GRAZING_DEG
    if "--grazing" in args:
        i = args.index("--grazing")
        g = float(args[i + 1])
        del args[i:i + 2]
    main(*args, grazing_deg=g)
