"""Facets as an xarray dataset (``seaecho trace`` / ``compare``; their maps are drawn by
:mod:`seaecho.plotting.facets`).

Dataset layout: per-facet arrays on the dimensions ``("y_cell", "x_cell", "triangle")``
(the cell ``(j, i)`` between nodes ``j, j+1`` and ``i, i+1``, its two triangles, facet
numbering of :mod:`seaecho.geometry.mesh`), vectors on a last dimension ``xyz``, basis
rotations on ``("pol_to", "pol_from")`` with labels ``h, v``. Angles in radians
(``units`` attributes), ranges in metres, float64.
"""

from __future__ import annotations

import numpy as np

from ..geometry.facets import Facets

__all__ = ["facets_dataset", "node_extent", "visibility_summary"]

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


def node_extent(ds) -> tuple[float, float, float, float]:
    """(x_min, x_max, y_min, y_max) of the grid nodes [m] of a facet dataset (its cell
    centres plus half a cell on each side)."""
    xc, yc = ds["x_cell"].values, ds["y_cell"].values
    hx = 0.5 * (xc[1] - xc[0]) if xc.size > 1 else 0.5
    hy = 0.5 * (yc[1] - yc[0]) if yc.size > 1 else 0.5
    return (float(xc[0] - hx), float(xc[-1] + hx), float(yc[0] - hy), float(yc[-1] + hy))
