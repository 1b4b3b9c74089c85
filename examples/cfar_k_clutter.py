"""CA-CFAR's false alarms in simulated sea clutter against the closed forms for K clutter.

Run: ``python examples/cfar_k_clutter.py [--quick] [OUTDIR]`` (default ``docs/figures``).
Rerunnable on any version of the code: docs/detection.md's "CFAR in simulated K clutter"
comes from here.

The clutter is that of ``clutter_statistics.py`` (a real-aperture 10 GHz radar, isotropic
antenna, looking upwind at 1 and 3 deg grazing over an evolving Elfouhaily sea, U19.5 =
10 m/s, 128 m tile, 1 m grid, ray-traced shadowing, breaking zones; 0.75 m range cells,
3 m by keeping a quarter of the band; one pulse every 50 ms). Per grazing angle,
resolution and channel (HH, VV):

* the K shape nu of the cells' intensities (maximum likelihood, eq ST5 of
  docs/scattering.md, on the pooled cells normalised by their mean; also the moments
  estimator <z^2>/<z>^2 = 2 (1 + 1/nu), eq ST3, Ward, Tough & Watts 2013 ch. 4, and
  "z log z", eq ST4, Blacknell & Tough 2001), beside the empirical
  law of Watts & Wicks as restated by Ward, Tough & Watts (eq ST6, no swell; A_c =
  resolution / cos(grazing) x tile width);
* a 1-D CA-CFAR along range (N = 2 x 4, 2 x 8, 2 x 16 training cells, 2 guard cells each
  side, windows inside the tile) at the design P_FA = 1e-2 and 1e-3 of exponential
  noise (eq D1): the measured false-alarm rate, with its exact binomial 95 % interval;
* the two closed forms that bracket it (``seaecho.detection.theory.pfa_ca_k``): the
  texture constant over the window (P_FA = design, eq D1) and an independent texture
  in every cell (eq D8 with the measured nu), and the threshold multiplier that eq D8
  needs to hold the design (its excess over eq D1's multiplier, in dB: the CFAR's
  threshold loss in spiky clutter without spatial correlation).

Writes ``cfar_k_clutter.csv`` and ``cfar_k_clutter.png`` (measured P_FA / design against
nu, with the eq D8 curves).
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

import numpy as np
from scipy import stats

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))

import clutter_statistics as cs  # noqa: E402

from seaecho.detection import CFAR  # noqa: E402
from seaecho.detection.theory import pfa_ca, pfa_ca_k, scale_for_pfa  # noqa: E402
from seaecho.processing.statistics import (  # noqa: E402
    fit_k,
    k_shape_empirical,
    k_shape_moments,
    k_shape_zlogz,
)

GRAZING_DEG = (1.0, 3.0)
FRACTIONS = (1, 4)  # 0.75 m and 3 m cells
TRAIN = (4, 8, 16)  # each side
GUARD = 2
PFA = (1e-2, 1e-3)
N_PULSES = 120


def binomial_interval(k: int, n: int, level: float = 0.95) -> tuple[float, float]:
    """Exact (Clopper-Pearson) interval of a binomial proportion."""
    a = 1.0 - level
    lo = stats.beta.ppf(a / 2, k, n - k + 1) if k > 0 else 0.0
    hi = stats.beta.ppf(1 - a / 2, k + 1, n - k) if k < n else 1.0
    return float(lo), float(hi)


def measure(power: np.ndarray, train: int, pfa: float) -> tuple[int, int]:
    """False alarms and tested cells of a CA-CFAR over ``power`` (pulse, range)."""
    cf = CFAR("ca", train, GUARD)
    stat = cf(power)
    tested = np.isfinite(stat)
    return int((stat[tested] > cf.scale(pfa)).sum()), int(tested.sum())


def rows_for(grazing_deg: float, n_pulses: int) -> list[dict]:
    cs.N_PULSES = n_pulses
    t = time.perf_counter()
    sim, rc, r, _ = cs.simulate(grazing_deg)
    print(f"grazing {grazing_deg} deg: {n_pulses} pulses in {time.perf_counter() - t:.0f} s",
          flush=True)
    rows = []
    for frac in FRACTIONS:
        x = cs.coarser(rc, frac)
        rr = r[:: max(1, int(round(1.2 * frac)))] if frac > 1 else r
        half = 0.5 * cs.SIZE * np.cos(np.radians(grazing_deg)) - 2.0 * frac
        cells = np.abs(rr - cs.RANGE_M) < half
        for ci, ch in enumerate(sim.radar.channel_names):
            if ch not in ("HH", "VV"):
                continue
            p = np.abs(x[:, ci][:, cells]) ** 2
            nu = float(fit_k((p / p.mean()).ravel()).nu)
            nu_mom, nu_zlz = float(k_shape_moments(p.ravel())), float(k_shape_zlogz(p.ravel()))
            area = 0.75 * frac / np.cos(np.radians(grazing_deg)) * cs.SIZE
            nu_law = float(k_shape_empirical(grazing_deg, area, ch))
            for tr in TRAIN:
                n = 2 * tr
                if p.shape[1] < 2 * (tr + GUARD) + 1:
                    continue
                for pfa in PFA:
                    k, m = measure(p, tr, pfa)
                    lo, hi = binomial_interval(k, m)
                    a = scale_for_pfa(pfa_ca, pfa, n)
                    nu_q = min(nu, 100.0)
                    ind = float(pfa_ca_k(a, n, nu_q))
                    a_k = scale_for_pfa(pfa_ca_k, pfa, n, nu_q)
                    rows.append({
                        "grazing_deg": grazing_deg, "resolution_m": 0.75 * frac,
                        "channel": ch, "cell_area_m2": round(area, 1),
                        "nu_ml": round(nu, 3), "nu_moments": round(nu_mom, 3),
                        "nu_zlogz": round(nu_zlz, 3), "nu_watts_wicks": round(nu_law, 3),
                        "train_n": n,
                        "design_pfa": pfa, "tested": m, "alarms": k,
                        "measured_pfa": k / m, "ci_low": lo, "ci_high": hi,
                        "pfa_constant_texture": pfa,
                        "pfa_independent_texture": ind,
                        "threshold_loss_independent_db": 10 * np.log10(a_k / a)})
                    print(f"  {0.75 * frac:4.2f} m {ch} nu {nu:6.2f} N {n:2d} design "
                          f"{pfa:.0e}: measured {k / m:.2e} [{lo:.1e}, {hi:.1e}] "
                          f"({k}/{m}); independent texture {ind:.2e}", flush=True)
    return rows


def plot(rows: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(PFA), figsize=(6.0 * len(PFA), 4.4),
                             constrained_layout=True)
    nus = np.geomspace(0.1, 100.0, 40)
    for ax, pfa in zip(np.atleast_1d(axes), PFA, strict=True):
        for tr, c in zip(TRAIN, ("C0", "C1", "C2"), strict=True):
            n = 2 * tr
            a = scale_for_pfa(pfa_ca, pfa, n)
            ax.plot(nus, [float(pfa_ca_k(a, n, v)) / pfa for v in nus], color=c,
                    label=f"independent texture, N = {n} (eq D8)")
            sel = [q for q in rows if q["design_pfa"] == pfa and q["train_n"] == n]
            for q in sel:
                mk = "o" if q["channel"] == "HH" else "s"
                ax.errorbar(q["nu_ml"], q["measured_pfa"] / pfa,
                            yerr=[[(q["measured_pfa"] - q["ci_low"]) / pfa],
                                  [(q["ci_high"] - q["measured_pfa"]) / pfa]],
                            fmt=mk, color=c, mfc="none" if q["resolution_m"] > 1 else c,
                            ms=5, capsize=2)
        ax.axhline(1.0, color="k", lw=0.8, label="texture constant over the window (D1)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("K shape nu (ML fit of the simulated clutter)")
        ax.set_ylabel("P_FA / design")
        ax.set_title(f"CA-CFAR at design P_FA = {pfa:g} (o HH, s VV; filled 0.75 m, "
                     "open 3 m)", fontsize=9)
        ax.grid(alpha=0.3, which="both")
    np.atleast_1d(axes)[0].legend(fontsize=7)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", nargs="?", default=str(ROOT / "docs" / "figures"))
    ap.add_argument("--quick", action="store_true", help="3 deg only, 16 pulses")
    a = ap.parse_args(argv)
    out = Path(a.outdir)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for g in ((3.0,) if a.quick else GRAZING_DEG):
        rows += rows_for(g, 16 if a.quick else N_PULSES)
    with open(out / "cfar_k_clutter.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plot(rows, out / "cfar_k_clutter.png")
    print("| grazing | cell (A_c) | HH nu ML / moments / z log z / ST6 | "
          "VV nu ML / moments / z log z / ST6 |")
    print("|---|---|---|---|")
    shapes = {(q["grazing_deg"], q["resolution_m"], q["channel"]): q for q in rows}
    for g, res in sorted({(k[0], k[1]) for k in shapes}):
        h, v = shapes[(g, res, "HH")], shapes[(g, res, "VV")]
        def cell(q):
            return (f"{q['nu_ml']:.2f} / {q['nu_moments']:.2f} / {q['nu_zlogz']:.2f} / "
                    f"{q['nu_watts_wicks']:.2f}")
        print(f"| {g:g} deg | {res:g} m ({h['cell_area_m2']:.0f} m^2) | {cell(h)} | "
              f"{cell(v)} |")
    return rows


if __name__ == "__main__":
    main()
