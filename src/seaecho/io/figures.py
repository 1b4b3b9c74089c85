"""Figures made from datasets (never from private state). Headless (Agg)."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from .dataset import atomic_savefig  # noqa: E402


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


__all__ = ["elevation_map"]
