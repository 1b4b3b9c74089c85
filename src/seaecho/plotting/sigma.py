"""The figure of ``seaecho sigma``: the mean-plane sigma_mn of an angle sweep. Headless
(Agg)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..io.dataset import atomic_savefig

#: Axis labels of the CSV's angle columns.
_LABELS = ["theta_i [deg]", "theta_s [deg]", "phi_i [deg]", "phi_s [deg]"]


def sigma_sweep_figure(rows, varying, path: str | os.PathLike, title: str,
                       floor_db: float) -> Path:
    """sigma_mn [dB] of an angle sweep of ``seaecho sigma``: a map per channel over two
    varying angles, or the four channels' curves over one.

    Parameters
    ----------
    rows : (N, 8) array
        theta_i, theta_s, phi_i, phi_s [deg] and sigma HH, HV, VH, VV [dB], one row per
        geometry (the CSV's columns).
    varying : list of (int, array)
        The columns that vary (at most two) and their values [deg].
    path : path
        PNG file.
    title : str
    floor_db : float
        The value written for sigma = 0 [dB] (not drawn).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt


    names = ["HH", "HV", "VH", "VV"]
    db = rows[:, 4:]
    if len(varying) == 2:
        (ia, a), (ib, b) = varying
        fig, axes = plt.subplots(2, 2, figsize=(9, 7), constrained_layout=True)
        vmax = np.max(db[db > floor_db]) if np.any(db > floor_db) else 0.0
        for c, ax in enumerate(axes.flat):
            grid = db[:, c].reshape(len(a), len(b))
            im = ax.pcolormesh(b, a, grid, shading="auto", vmin=vmax - 50, vmax=vmax,
                               cmap="viridis")
            ax.set_title(f"sigma_{names[c]} [dB]")
            ax.set_xlabel(_LABELS[ib])
            ax.set_ylabel(_LABELS[ia])
        fig.colorbar(im, ax=axes, label="sigma [dB]")
    else:
        fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
        col = varying[0][0] if varying else 3
        x = rows[:, col]
        for c in range(4):
            ax.plot(x, np.where(db[:, c] > floor_db, db[:, c], np.nan), label=names[c],
                    ls="-" if c in (0, 3) else "--")
        ax.set_xlabel(_LABELS[col])
        ax.set_ylabel("sigma [dB]")
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(title, fontsize=9)
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


__all__ = ["sigma_sweep_figure"]
