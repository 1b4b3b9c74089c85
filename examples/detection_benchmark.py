"""Detection benchmark: CA, GO, SO and OS CFAR (and a user's detector) on simulated sea
clutter with small point targets, as ROC curves and P_D at a fixed P_FA.

Run: ``python examples/detection_benchmark.py [--quick] [--out DIR]`` (default
``docs/figures``). A monostatic X-band radar (10 GHz, 150 MHz: 1 m range resolution,
rectangular 0.6 x 0.14 m antenna, 10 W, noise figure 3 dB) at 400 m and 5 deg grazing
looks upwind over an evolving Elfouhaily sea (64 m tile, 0.5 m grid) with five point
targets of 0.001 to 0.1 m^2 at 0.5 m height spread in range across the tile; one pulse
every 50 ms (the clutter's speckle decorrelates between pulses), 16 pulses. Scenes: wind
U19.5 = 6 and 10 m/s; seeds 1-3 (``--quick``: one scene, one seed, 8 pulses). The range
profiles (HH) of all runs are pooled: ``seaecho.roc`` sweeps each detector's threshold
(P_FA over the background cells, P_D over the opportunities: a target in a pulse; one
the truth hides, behind a crest, is left out) and
``seaecho.detect`` runs each CFAR at its design P_FA = 1e-3 (measured P_FA per cell).
Writes ``detection_roc.png`` (ROC curves), ``detection_pd.png`` (P_D per target at
P_FA = 1e-3) and ``detection_benchmark.csv``; prints the tables docs/detection.md quotes.
"""

from __future__ import annotations

import argparse
import csv
import time
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy import ndimage  # noqa: E402

import seaecho  # noqa: E402
from seaecho.detection import CFAR  # noqa: E402
from seaecho.warnings import SeaechoWarning  # noqa: E402

RCS_M2 = (0.001, 0.003, 0.01, 0.03, 0.1)
X_M = (-24.0, -12.0, 0.0, 12.0, 24.0)
PFA = 1e-3
TRAIN, GUARD = 8, 2


def scene(seed: int, wind_m_s: float, n_pulses: int, prf_hz: float = 20.0,
          targets: list[dict] | None = None, name: str = "detection-benchmark"):
    """The benchmark's scene (module docstring); ``targets`` replaces its five."""
    g = np.radians(5.0)
    pos = [-400.0 * np.cos(g), 0.0, 400.0 * np.sin(g)]
    if targets is None:
        targets = [{"name": f"{rcs:g} m2", "position_m": [x, 0.0, 0.5], "rcs_m2": rcs}
                   for x, rcs in zip(X_M, RCS_M2, strict=True)]
    return seaecho.parse_scene({
        "name": f"{name}-u{wind_m_s:g}-s{seed}",
        "sea": {"spectrum": "elfouhaily", "spreading": "elfouhaily",
                "wind_speed_m_s": wind_m_s, "size_x_m": 64.0, "nx": 128},
        "run": {"seed": seed},
        "scattering": {"model": "blend", "sea_motion": "evolving"},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 180e6, "prf_hz": prf_hz,
                  "n_pulses": n_pulses, "sea_update_pulses": 1, "channels": ["HH"],
                  "thermal_noise": True, "noise_figure_db": 3.0, "transmit_power_w": 10.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 150e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": pos, "antenna": {
            "pattern": "rectangular", "width_m": 0.6, "height_m": 0.14,
            "look_at_m": [0, 0, 0]}},
        "targets": targets,
    })


def median_detector(power):
    """A user's detector: the power over the median of the 21 cells around it along
    range (no design P_FA: only its ROC is measured)."""
    med = ndimage.median_filter(power, size=(1, 2 * (TRAIN + GUARD) + 1), mode="constant",
                                cval=np.nan)
    with np.errstate(divide="ignore", invalid="ignore"):
        return power / med


def main(argv=None) -> list[Path]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="one scene, one seed, 8 pulses")
    ap.add_argument("--out", default="docs/figures", help="output folder")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    winds, seeds, n_pulses = ((6.0,), (1,), 8) if args.quick else ((6.0, 10.0), (1, 2, 3),
                                                                     16)
    t0 = time.perf_counter()
    runs = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SeaechoWarning)
        for w in winds:
            for s in seeds:
                runs.append(seaecho.simulate(scene(s, w, n_pulses), progress=False))
    t_sim = time.perf_counter() - t0
    detectors = {k.upper(): CFAR(k, TRAIN, GUARD) for k in ("ca", "go", "so", "os")}
    detectors["median (user)"] = median_detector
    curves = {name: seaecho.roc(runs, d) for name, d in detectors.items()}
    names = [f"{r:g} m2" for r in RCS_M2]
    rows = []
    for name, c in curves.items():
        # the threshold of the pooled background's P_FA = 1e-3 (the ROC's point)
        ok = c["pfa"] <= PFA
        thr = float(c["threshold"][ok].min()) if ok.any() else float("inf")
        # the visible opportunities: one the truth hides (behind a crest) is no miss
        seen = c["opportunity_visible"]
        peaks, objs = c["opportunity_peak"][seen], c["opportunity_object"][seen]
        pd_obj = [float(np.mean(peaks[objs == n] > thr)) if (objs == n).any() else np.nan
                  for n in names]  # (a target hidden in every look: no P_D)
        row = {"detector": name,
               "pd_all": float(np.mean(peaks > thr)) if peaks.size else np.nan,
               **{f"pd_{n}": p for n, p in zip(names, pd_obj, strict=True)}}
        if name in ("CA", "GO", "SO", "OS"):
            measured = []
            for ds in runs:
                det, truth = seaecho.detect(ds, cfar=name.lower(), pfa=PFA, train=TRAIN,
                                            guard=GUARD)
                sc = seaecho.score(det, truth)
                measured.append((sc["pfa_cell"] * det.attrs["cells_tested"],
                                 det.attrs["cells_tested"], sc["pd"]))
            m = np.array(measured)
            row["pfa_measured_at_design"] = float(m[:, 0].sum() / m[:, 1].sum())
            row["pd_at_design"] = float(m[:, 2].mean())
        else:
            row["pfa_measured_at_design"] = float("nan")
            row["pd_at_design"] = float("nan")
        rows.append(row)
    # Figures
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for name, c in curves.items():
        keep = c["pfa"] > 0
        ax.semilogx(c["pfa"][keep], c["pd"][keep], label=name)
    ax.axvline(PFA, color="0.6", lw=0.8, ls="--")
    ax.set(xlabel="P_FA per cell (background cells)", ylabel="P_D (target in a pulse)",
           title=f"ROC, {len(runs)} runs x {n_pulses} pulses, HH range profiles",
           xlim=(1e-4, 1), ylim=(0, 1.02))
    ax.legend(fontsize=8)
    fig.tight_layout()
    p_roc = out / "detection_roc.png"
    fig.savefig(p_roc, dpi=110)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for row in rows:
        ax.semilogx(RCS_M2, [row[f"pd_{n}"] for n in names], "o-", label=row["detector"])
    ax.set(xlabel="target RCS [m^2]", ylabel=f"P_D at P_FA = {PFA:g}",
           title="P_D per target at a fixed P_FA", ylim=(0, 1.02))
    ax.legend(fontsize=8)
    fig.tight_layout()
    p_pd = out / "detection_pd.png"
    fig.savefig(p_pd, dpi=110)
    plt.close(fig)
    p_csv = out / "detection_benchmark.csv"
    with open(p_csv, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for row in rows:
            w.writerow({k: (f"{v:.4f}" if isinstance(v, float) and np.isfinite(v) else
                            "" if isinstance(v, float) else v) for k, v in row.items()})
    c0 = next(iter(curves.values()))
    hidden = c0["opportunity_object"][~c0["opportunity_visible"]]
    print(f"{len(runs)} runs x {n_pulses} pulses simulated in {t_sim:.0f} s; "
          f"{c0['n_background']} background cells, {c0['n_opportunities']} visible "
          f"opportunities, {c0['n_hidden']} hidden by the truth ("
          + (", ".join(f"{n} {int((hidden == n).sum())}" for n in names
                       if (hidden == n).any()) or "none") + ")")
    head = "| detector | " + " | ".join(names) + " | all | P_FA at design 1e-3 | P_D at design |"
    print(head)
    print("|" + "---|" * (len(names) + 4))
    for row in rows:
        cells = [f"{row[f'pd_{n}']:.2f}" for n in names]
        pm = row["pfa_measured_at_design"]
        print(f"| {row['detector']} | " + " | ".join(cells) + f" | {row['pd_all']:.2f} | "
              + (f"{pm:.2g}" if np.isfinite(pm) else "-") + " | "
              + (f"{row['pd_at_design']:.2f}" if np.isfinite(row['pd_at_design']) else "-")
              + " |")
    return [p_roc, p_pd, p_csv]


if __name__ == "__main__":
    main()
