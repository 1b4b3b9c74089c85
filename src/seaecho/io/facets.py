"""Facets as an xarray dataset, and maps of them as PNG (``seaecho trace`` / ``compare``).

Dataset layout: per-facet arrays on the dimensions ``("y_cell", "x_cell", "triangle")``
(the cell ``(j, i)`` between nodes ``j, j+1`` and ``i, i+1``, its two triangles, facet
numbering of :mod:`seaecho.geometry.mesh`), vectors on a last dimension ``xyz``, basis
rotations on ``("pol_to", "pol_from")`` with labels ``h, v``. Angles in radians
(``units`` attributes), ranges in metres, float64.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..geometry.facets import Facets
from .dataset import atomic_savefig

__all__ = ["facets_dataset", "facet_maps", "visibility_summary"]

_UNITS = {
    "centroid": "m", "area": "m2", "normal": "1", "velocity": "m s-1", "r_tx": "m",
    "r_rx": "m", "n_i": "1", "n_s": "1", "theta_i": "rad", "theta_s": "rad", "phi": "rad",
    "theta_i_global": "rad", "theta_s_global": "rad", "phi_global": "rad", "rot_i": "1",
    "rot_s": "1", "lit": "1", "seen": "1", "visibility": "1",
}
_LONG = {
    "centroid": "facet centroid", "area": "facet area", "normal": "unit facet normal",
    "velocity": "facet centroid velocity", "r_tx": "range transmitter to facet (float64)",
    "r_rx": "range facet to receiver (float64)", "n_i": "unit direction transmitter to facet",
    "n_s": "unit direction facet to receiver",
    "theta_i": "local incidence angle from the facet normal",
    "theta_s": "local scattering angle from the facet normal",
    "phi": "local azimuth difference phi_s - phi_i about the facet normal",
    "theta_i_global": "incidence angle from +z", "theta_s_global": "scattering angle from +z",
    "phi_global": "azimuth difference phi_s - phi_i about +z",
    "rot_i": "global-to-local basis rotation of the incident wave, (h, v) order",
    "rot_s": "global-to-local basis rotation of the scattered wave, (h, v) order",
    "lit": "lit by the transmitter (facing and not shadowed), or its probability",
    "seen": "seen from the receiver (facing and not masked), or its probability",
    "visibility": "lit and seen",
}


def facets_dataset(f: Facets, x: np.ndarray, y: np.ndarray, tx: np.ndarray, rx: np.ndarray,
                   attrs: dict | None = None):
    """An :class:`xarray.Dataset` of facets.

    Parameters
    ----------
    f : Facets
        The facets.
    x, y : arrays
        Node coordinates (nx,), (ny,) [m].
    tx, rx : (3,) arrays
        Transmitter and receiver positions [m].
    attrs : dict, optional
        Extra global attributes (e.g. :func:`seaecho.io.dataset.scene_attrs`).
    """
    import xarray as xr

    dims = ("y_cell", "x_cell", "triangle")
    data = {}
    for name in f.array_names():
        a = f.as_grid(name)
        extra = ()
        if a.ndim == 4:
            extra = ("xyz",)
        elif a.ndim == 5:
            extra = ("pol_to", "pol_from")
        data[name] = xr.Variable(dims + extra, a, attrs={"units": _UNITS.get(name, "1"),
                                                          "long_name": _LONG.get(name, name)})
    coords = {
        "x_cell": ("x_cell", 0.5 * (x[1:] + x[:-1]), {"units": "m"}),
        "y_cell": ("y_cell", 0.5 * (y[1:] + y[:-1]), {"units": "m"}),
        "triangle": ("triangle", np.array([0, 1])),
        "xyz": ("xyz", np.array(["x", "y", "z"])),
        "pol_to": ("pol_to", np.array(["h", "v"])),
        "pol_from": ("pol_from", np.array(["h", "v"])),
    }
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({
        "title": "seaecho facets seen from the transmitter and the receiver",
        "facet_mode": f.mode, "time_s": f.time_s, "visibility_time_s": f.visibility_time_s,
        "tx_position_m": np.asarray(tx, dtype=float), "rx_position_m": np.asarray(rx, dtype=float),
        "facet_definition": "two triangles per grid cell split along the (j,i)-(j+1,i+1) "
                            "diagonal; see seaecho.geometry.mesh",
    })
    if attrs:
        ds.attrs.update(attrs)
    return ds


def visibility_summary(f: Facets) -> dict[str, float]:
    """Area-weighted fractions lit from Tx, seen from Rx, and both [-]."""
    w = f.area / f.area.sum()
    return {"lit_fraction_tx": float(w @ f.lit), "seen_fraction_rx": float(w @ f.seen),
            "visible_fraction": float(w @ f.visibility)}


def facet_maps(f: Facets, x: np.ndarray, y: np.ndarray, path: str | os.PathLike,
               title: str = "") -> Path:
    """PNG maps (cell means of the two triangles): lit, seen, local incidence, local
    scattering angle [deg]."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ext = (x[0], x[-1], y[0], y[-1])
    fig, axes = plt.subplots(2, 2, figsize=(10, 8.5), constrained_layout=True)
    panels = [("lit", "lit from Tx [-]", "gray", (0, 1)),
              ("seen", "seen from Rx [-]", "gray", (0, 1)),
              ("theta_i", "local incidence theta_i [deg]", "viridis", None),
              ("theta_s", "local scattering theta_s [deg]", "viridis", None)]
    for ax, (name, label, cmap, lim) in zip(axes.ravel(), panels, strict=True):
        a = f.cell_mean(name)
        if name.startswith("theta"):
            a = np.degrees(a)
        vmin, vmax = lim if lim else (np.nanpercentile(a, 1), np.nanpercentile(a, 99))
        im = ax.imshow(a, origin="lower", extent=ext, cmap=cmap, vmin=vmin, vmax=vmax,
                       interpolation="nearest")
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
        ax.set_title(label)
        fig.colorbar(im, ax=ax, shrink=0.85)
    fig.suptitle(title or f"{f.mode} facets at t = {f.time_s:g} s")
    out = atomic_savefig(fig, path, dpi=110)
    plt.close(fig)
    return out
