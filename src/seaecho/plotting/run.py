"""Figures made from datasets (never from private state). Headless (Agg).

- :func:`elevation_map`: a ``seaecho surface`` dataset, like the paper's Fig. 6a;
- the figures of a ``seaecho run`` dataset, after the paper's Fig. 6 (:func:`run_figures`):
  ``*_elevation.png`` sea + wake elevation (Fig. 6a) with the ship; ``*_signal.png``
  |received signal| per channel over pulse and range (Fig. 6b), for a unit-amplitude
  transmitted signal as in the paper (|raw| / sqrt(P_t)), in dB; ``*_sigma.png`` the NRCS
  sigma0 per unit horizontal area of each cell in dB for HH, HV, VH, VV (Figs. 6c-6f).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from ..constants import C0  # noqa: E402
from ..io.dataset import atomic_savefig  # noqa: E402


def elevation_map(ds: xr.Dataset, path: str | os.PathLike, time_index: int = 0) -> Path:
    """Elevation map of a surface dataset, like the paper's Fig. 6a (PNG).

    Shows sea + wake elevation [m] over x, y [m], with the turbulent wake outlined and
    the ship's position marked when the dataset has them.
    """
    z = ds["elevation"].isel(time=time_index)
    x, y = ds["x"].values, ds["y"].values
    fig, ax = plt.subplots(figsize=(6.4, 5.4), constrained_layout=True)
    lim = float(np.nanmax(np.abs(z.values))) or 1.0
    im = ax.pcolormesh(x, y, z.values, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    fig.colorbar(im, ax=ax, label="elevation z [m]")
    if "wake_mask" in ds and float(ds["wake_mask"].isel(time=time_index).max()) > 0:
        ax.contour(x, y, ds["wake_mask"].isel(time=time_index).values, levels=[0.5],
                   colors="k", linewidths=0.8, linestyles="--")
    if "ship_x" in ds:
        ax.plot(ds["ship_x"].values[time_index], ds["ship_y"].values[time_index], "k^",
                ms=7, label="ship")
        ax.legend(loc="upper right")
    ax.set_aspect("equal")
    ax.set_xlabel("x (east) [m]")
    ax.set_ylabel("y (north) [m]")
    t = float(ds["time"].values[time_index])
    ax.set_title(f"{ds.attrs.get('scene_name', '')} sea + wake elevation, t = {t:g} s")
    out = atomic_savefig(fig, path, dpi=120)
    plt.close(fig)
    return out


def _db(x: np.ndarray, floor: float = 1e-30) -> np.ndarray:
    return 10.0 * np.log10(np.maximum(x, floor))


def signal_figure(ds: xr.Dataset, path: str | os.PathLike, variable: str = "raw") -> Path:
    """|signal|^2 / P_t in dB over (range, pulse), one panel per channel (Fig. 6b)."""
    sig = ds[variable]
    p_t = float(ds.attrs.get("transmit_power_w", 1.0))
    n_ch = sig.sizes["channel"]
    fig, axes = plt.subplots(1, n_ch, figsize=(3.6 * n_ch, 3.6), squeeze=False,
                             constrained_layout=True)
    power = _db(np.abs(sig.values) ** 2 / p_t)
    vmax = float(np.max(power))
    rng = ds["range"].values
    if variable == "compressed":
        # beyond the last range of the window the compressed samples only hold pulse tails
        keep = rng <= rng[-1] - 0.5 * C0 * float(ds.attrs.get("waveform_duration_s", 0.0))
        rng, power = rng[keep], power[..., keep]
    for i, ax in enumerate(axes[0]):
        if sig.sizes["pulse"] == 1:
            ax.plot(rng, power[0, i])
            ax.set_ylabel("|r|^2 / P_t [dB]")
            ax.set_ylim(vmax - 80, vmax + 3)
        else:
            im = ax.pcolormesh(rng, ds["pulse"].values, power[:, i], vmin=vmax - 60,
                               vmax=vmax, shading="auto", cmap="viridis")
            ax.set_ylabel("pulse")
        ax.set_xlabel("range c tau / 2 [m]")
        ax.set_title(f"{variable} {str(ds['channel'].values[i])}")
    if sig.sizes["pulse"] > 1:
        fig.colorbar(im, ax=axes[0, -1], label="|r|^2 / P_t [dB]")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def sigma_figure(ds: xr.Dataset, path: str | os.PathLike) -> Path:
    """NRCS sigma0_mn per unit horizontal area of each cell [dB] of the sigma-map pulse,
    HH, HV, VH, VV (Figs. 6c-6f)."""
    s = ds["sigma0"]
    x, y = ds["x_cell"].values, ds["y_cell"].values
    fig, axes = plt.subplots(2, 2, figsize=(9.5, 8.0), constrained_layout=True)
    vals = _db(s.values, 1e-12)
    vmax = float(np.max(vals))
    for ax, i in zip(axes.ravel(), range(4), strict=True):
        im = ax.pcolormesh(x, y, vals[i], vmin=vmax - 60, vmax=vmax, shading="auto",
                           cmap="magma")
        ax.set_aspect("equal")
        ax.set_title(f"sigma0 {str(ds['polarisation'].values[i])} [dB]")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    fig.colorbar(im, ax=axes, shrink=0.8,
                 label="sigma0_mn per horizontal area, visibility included [dB]")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def elevation_figure(ds: xr.Dataset, path: str | os.PathLike) -> Path:
    """Sea + wake elevation with the platforms' horizontal positions (Fig. 6a)."""
    z = ds["elevation"].values
    x, y = ds["x"].values, ds["y"].values
    fig, ax = plt.subplots(figsize=(6.4, 5.4), constrained_layout=True)
    lim = float(np.max(np.abs(z))) or 1.0
    im = ax.pcolormesh(x, y, z, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    fig.colorbar(im, ax=ax, label="elevation z [m]")
    if float(ds["wake_mask"].max()) > 0:
        ax.contour(x, y, ds["wake_mask"].values, levels=[0.5], colors="k",
                   linewidths=0.8, linestyles="--")
    if "ship_position" in ds:
        p = ds["ship_position"].values[int(ds.attrs.get("sigma_map_pulse", 0))]
        ax.plot(p[0], p[1], "k^", ms=7, label="ship")
        ax.legend(loc="upper right")
    ax.set_aspect("equal")
    ax.set_xlabel("x (east) [m]")
    ax.set_ylabel("y (north) [m]")
    ax.set_title("sea + wake elevation")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def run_figures(ds: xr.Dataset, stem: str | os.PathLike) -> list[Path]:
    """All the figures a dataset allows, named ``<stem>_<what>.png``."""
    stem = str(stem)
    out = [signal_figure(ds, stem + "_signal.png"),
           signal_figure(ds, stem + "_compressed.png", "compressed")]
    if "sigma0" in ds:
        out += [elevation_figure(ds, stem + "_elevation.png"),
                sigma_figure(ds, stem + "_sigma.png")]
    return out


__all__ = ["elevation_figure", "elevation_map", "run_figures", "sigma_figure", "signal_figure"]
