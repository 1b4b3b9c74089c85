"""Figures of an image dataset, after the paper's Figs. 7-9 (made from the file only).

- ``*_sigma0.png``: sigma0 [dB] per channel on one common dB scale (``*_rcs.png``:
  |image|^2 [dBm^2] instead when there is no sea, for point targets) (the largest
  99.9th percentile of the valid pixels of all channels, rounded up to 5 dB, down to
  ``dynamic_range_db`` below it), with the tile outline, the ship's position and the
  wake arms outlined when the dataset has them;
- ``*_sigma0_filtered.png``: the same for the speckle-filtered intensities, when present;
- ``*_pauli.png``: the Pauli RGB composite (R = |HH - VV|/sqrt 2, G = |HV + VH|/sqrt 2,
  B = |HH + VV|/sqrt 2 in the back-scattering alignment, ``imaging.speckle``), the three
  amplitudes on one linear scale (filtered when present), so that a colour says which
  mechanism dominates.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..io.dataset import atomic_savefig  # noqa: E402

__all__ = ["common_db_scale", "image_figures", "pauli_figure", "sigma0_figure"]

def _db(x: np.ndarray) -> np.ndarray:
    with np.errstate(divide="ignore", invalid="ignore"):
        return 10.0 * np.log10(np.where(x > 0, x, np.nan))


def common_db_scale(values_db: np.ndarray, valid: np.ndarray, dynamic_range_db: float
                    ) -> tuple[float, float]:
    """(vmin, vmax) [dB]: the largest per-channel 99.9th percentile of the valid pixels,
    rounded up to 5 dB, and ``dynamic_range_db`` below it."""
    tops = []
    for v in values_db:
        sel = v[valid & np.isfinite(v)]
        if sel.size:
            tops.append(np.percentile(sel, 99.9))
    vmax = 5.0 * np.ceil(max(tops) / 5.0) if tops else 0.0
    return vmax - dynamic_range_db, vmax


def _overlay(ax, img) -> None:
    x, y = img["x"].values, img["y"].values
    if "tile" in img and img["tile"].values.any() and not img["tile"].values.all():
        ax.contour(x, y, img["tile"].values, levels=[0.5], colors="w", linewidths=0.6,
                   linestyles=":")
    if "kelvin_wake" in img and img["kelvin_wake"].values.any():
        ax.contour(x, y, img["kelvin_wake"].values, levels=[0.5], colors="c",
                   linewidths=0.5, alpha=0.6)
    if "ship_x_m" in img.attrs:
        ax.plot(img.attrs["ship_x_m"], img.attrs["ship_y_m"], marker="^", color="r",
                ms=6, ls="none", label="ship (hull centre)")
        ax.legend(loc="upper right", fontsize=7)
    if "target_position" in img:
        p = img["target_position"].values
        ax.plot(p[:, 0], p[:, 1], "o", mfc="none", mec="r", ms=9, label="targets")


def sigma0_figure(img, path: str | os.PathLike, variable: str = "sigma0",
                  dynamic_range_db: float = 50.0) -> Path:
    """sigma0 [dB] per channel on a common scale (Figs. 7-9 of the paper); ``variable =
    "rcs"`` shows |image|^2 [dBm^2] instead (point targets: the peak is the RCS)."""
    if variable == "rcs":
        vals = _db(np.abs(img["image"].values) ** 2)
    else:
        vals = _db(img[variable].values)
    valid = img["valid"].values.astype(bool)
    vmin, vmax = common_db_scale(vals, valid, dynamic_range_db)
    n = vals.shape[0]
    cols = 2 if n == 4 else n
    rows = int(np.ceil(n / cols))
    x, y = img["x"].values, img["y"].values
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 4.2 * rows), squeeze=False,
                             constrained_layout=True)
    im = None
    for k, ax in enumerate(axes.ravel()):
        if k >= n:
            ax.set_visible(False)
            continue
        im = ax.pcolormesh(x, y, np.where(valid, vals[k], np.nan), vmin=vmin, vmax=vmax,
                           cmap="gray", shading="auto")
        _overlay(ax, img)
        ax.set_aspect("equal")
        ax.set_title(f"{str(img['channel'].values[k])}  ({variable}, track "
                     f"{img.attrs.get('track', '?')})", fontsize=9)
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
    label = "|image|^2 [dBm^2]" if variable == "rcs" else f"{variable} [dB]"
    fig.colorbar(im, ax=axes, shrink=0.85, label=label)
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def pauli_figure(img, path: str | os.PathLike, variable: str = "pauli") -> Path:
    """Pauli RGB composite: amplitudes sqrt(power) on one linear scale (the 99th
    percentile of the three over the valid pixels is full brightness)."""
    amp = np.sqrt(np.nan_to_num(img[variable].values))
    valid = img["valid"].values.astype(bool)
    sel = amp[:, valid]
    top = float(np.percentile(sel, 99.0)) if sel.size else 1.0
    rgb = np.clip(amp / (top if top > 0 else 1.0), 0.0, 1.0)
    rgb = np.moveaxis(rgb, 0, -1) * valid[..., None]
    x, y = img["x"].values, img["y"].values
    fig, ax = plt.subplots(figsize=(6.0, 5.4), constrained_layout=True)
    ax.imshow(rgb, origin="lower", extent=(x[0] - 0.5 * (x[1] - x[0]),
                                           x[-1] + 0.5 * (x[1] - x[0]),
                                           y[0] - 0.5 * (y[1] - y[0]),
                                           y[-1] + 0.5 * (y[1] - y[0])),
              interpolation="nearest")
    _overlay(ax, img)
    ax.set_title(f"Pauli RGB (BSA): R |HH-VV|, G |HV+VH|, B |HH+VV|; full scale "
                 f"{10 * np.log10(top * top) if top > 0 else 0:.0f} dB", fontsize=8)
    ax.set_xlabel("x (east) [m]")
    ax.set_ylabel("y (north) [m]")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def image_figures(img, stem: str | os.PathLike, dynamic_range_db: float = 50.0
                  ) -> list[Path]:
    """Every figure of an image dataset, written as ``<stem>_<name>.png``."""
    stem = str(stem)
    if "tile" not in img:  # no sea: point targets, shown in RCS
        out = [sigma0_figure(img, f"{stem}_rcs.png", "rcs", dynamic_range_db)]
    else:
        out = [sigma0_figure(img, f"{stem}_sigma0.png", dynamic_range_db=dynamic_range_db)]
    if "sigma0_filtered" in img:
        out.append(sigma0_figure(img, f"{stem}_sigma0_filtered.png", "sigma0_filtered",
                                 dynamic_range_db))
    if "pauli" in img:
        name = "pauli_filtered" if "pauli_filtered" in img else "pauli"
        out.append(pauli_figure(img, f"{stem}_pauli.png", name))
    return out
