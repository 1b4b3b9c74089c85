"""Maps of a facet dataset (``seaecho trace``, :func:`seaecho.io.facets.facets_dataset`):
lit, seen, local incidence and scattering angles; and the figures of ``seaecho compare``
(ray-traced against analytic facets). Headless (Agg)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..io.dataset import atomic_savefig
from ..io.facets import node_extent


def facet_maps(ds, path: str | os.PathLike, title: str = "") -> Path:
    """PNG maps of a facet dataset (:func:`facets_dataset`), cell means of the two
    triangles: lit, seen, local incidence, local scattering angle [deg]."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ext = node_extent(ds)
    fig, axes = plt.subplots(2, 2, figsize=(10, 8.5), constrained_layout=True)
    panels = [("lit", "lit from Tx [-]", "gray", (0, 1)),
              ("seen", "seen from Rx [-]", "gray", (0, 1)),
              ("theta_i", "local incidence theta_i [deg]", "viridis", None),
              ("theta_s", "local scattering theta_s [deg]", "viridis", None)]
    for ax, (name, label, cmap, lim) in zip(axes.ravel(), panels, strict=True):
        a = ds[name].values.mean(axis=-1)
        if name.startswith("theta"):
            a = np.degrees(a)
        vmin, vmax = lim if lim else (np.nanpercentile(a, 1), np.nanpercentile(a, 99))
        im = ax.imshow(a, origin="lower", extent=ext, cmap=cmap, vmin=vmin, vmax=vmax,
                       interpolation="nearest")
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
        ax.set_title(label)
        fig.colorbar(im, ax=ax, shrink=0.85)
    fig.suptitle(title or f"{ds.attrs['facet_mode']} facets at t = {ds.attrs['time_s']:g} s")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out


def compare_figures(ds, out: Path) -> list[Path]:
    """Figures of ``seaecho compare`` (a dataset of :func:`seaecho.api.compare`) in the
    folder ``out``: ``compare_visibility.png``, lit-and-seen maps of the ray-traced and
    analytic facets and their difference, and ``compare_angles.png``, histograms of the
    per-facet angle differences [deg] (facets visible in both modes)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ext = node_extent(ds)
    vis = ds["visibility"]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    for ax, (a, title, cmap, lim) in zip(axes, [
            (vis.sel(mode="raytraced").values, "ray-traced: lit and seen", "gray", (0, 1)),
            (vis.sel(mode="analytic").values,
             f"analytic ({ds.attrs['shadowing']}): lit and seen", "gray", (0, 1)),
            ((vis.sel(mode="analytic") - vis.sel(mode="raytraced")).values,
             "analytic - ray-traced", "RdBu_r", (-1, 1))], strict=True):
        im = ax.imshow(a, origin="lower", extent=ext, cmap=cmap, vmin=lim[0], vmax=lim[1],
                       interpolation="nearest")
        ax.set_title(title)
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
        fig.colorbar(im, ax=ax, shrink=0.8)
    paths = [atomic_savefig(fig, out / "compare_visibility.png", dpi=100)]
    plt.close(fig)

    fig, axes = plt.subplots(1, 4, figsize=(16, 3.8), constrained_layout=True)
    for ax, name in zip(axes, ("theta_i", "theta_s", "phi", "normal"), strict=True):
        d = ds[f"{name}_difference"].values
        ax.hist(d[np.isfinite(d)], bins=100, color="C0")
        ax.set_xlabel(f"{name}: analytic - ray-traced [deg]" if name != "normal"
                      else "angle between normals [deg]")
        ax.set_yscale("log")
    fig.suptitle("per-facet differences (facets visible in both modes)")
    paths.append(atomic_savefig(fig, out / "compare_angles.png", dpi=100))
    plt.close(fig)
    return paths


__all__ = ["compare_figures", "facet_maps"]
