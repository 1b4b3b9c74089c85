"""The range-Doppler figure of ``seaecho doppler`` (a dataset of
:func:`seaecho.io.doppler.doppler_dataset`): one range-Doppler map per channel and the
clutter Doppler spectra with their centroids. Headless (Agg)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np


def doppler_figure(ds, path: str | os.PathLike, dynamic_range_db: float = 50.0) -> Path:
    """Range-Doppler maps (one per channel, dB) and the clutter Doppler spectra."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..io.dataset import atomic_savefig

    chans = [str(c) for c in ds["channel"].values]
    n = len(chans)
    fig, axes = plt.subplots(1, n + 1, figsize=(3.6 * (n + 1), 3.8), constrained_layout=True)
    rd = 10 * np.log10(np.maximum(ds["range_doppler"].values, 1e-300))
    top = float(np.max(rd))
    f = ds["doppler"].values
    r = ds["range"].values
    for ax, c, m in zip(axes[:n], chans, rd, strict=True):
        im = ax.imshow(m.T, origin="lower", aspect="auto", cmap="viridis",
                       extent=(f[0], f[-1], r[0], r[-1]), vmin=top - dynamic_range_db,
                       vmax=top, interpolation="nearest")
        ax.set_title(f"{c}")
        ax.set_xlabel("Doppler [Hz]")
        ax.set_ylabel("range [m]")
    fig.colorbar(im, ax=axes[n - 1], shrink=0.8, label="dB W/Hz")
    ax = axes[n]
    spec = ds["doppler_spectrum"].values
    ref = spec.max()
    for c, s, cen in zip(chans, spec, ds["doppler_centroid"].values, strict=True):
        line, = ax.plot(f, 10 * np.log10(np.maximum(s / ref, 1e-30)), label=f"{c}")
        ax.axvline(cen, color=line.get_color(), ls=":", lw=1)
    ax.set_ylim(-dynamic_range_db, 3)
    ax.set_xlabel("Doppler [Hz]")
    ax.set_ylabel("clutter spectrum [dB]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return atomic_savefig(fig, path, dpi=100)


__all__ = ["doppler_figure"]
