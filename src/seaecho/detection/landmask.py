"""Land blanking: the cells of a PPI whose ground point lies on the chart's land.

A coastal radar does not declare its land: its detector blanks the cells whose ground
position lies inside the coastline polygons of the chart, usually with a margin
outward from the shore (the range and azimuth spread of the land's echo past the
waterline, the chart's error). A blanked cell is not tested: it yields no plot, counts
in no false-alarm rate and no opportunity (docs/detection.md, "Land blanking"). The
same cells are kept out of the training windows of the sea next to the shore by a
land-censored CFAR (:meth:`seaecho.detection.cfar.CFAR.censored`), so that the land does
not lift the threshold over a target beside it; the blanking must then cover the spread
of the land's echo onto the sea, which the land in the windows used to mask.

The test is geometric, per cell: inside one of the polygons (even-odd rule of
:class:`matplotlib.path.Path`), or within ``margin_m`` of one of their edges (the
distance from a point to a segment). The land's echo spreads past its cells by the
radar's own resolution: in azimuth over the two-way beam, in range over the compressed
pulse; :func:`spread` blanks the sea cells it reaches, a dilation of the mask on the
polar grid by a number of rays and gates (:func:`spread_bins`; the extents from the
run's antenna and waveform, :func:`seaecho.io.detections.land_spread`). No physics law
is involved here.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["land_mask", "spread", "spread_bins"]

#: cells per block of the distance-to-edges test (bounds its (cells, edges) arrays)
_BLOCK = 1 << 16


def land_mask(cell_xy_m: ArrayLike, outlines_m: Sequence[ArrayLike],
              margin_m: float = 0.0) -> NDArray[np.bool_]:
    """Cells on the land, or within ``margin_m`` of its shore.

    Parameters
    ----------
    cell_xy_m : array_like
        (..., 2) ground position (x, y) of each cell [m] (non-finite: never land).
    outlines_m : sequence of array_like
        Closed polygons, each (k, 2) vertices (x, y) [m] in order (the last joins the
        first), k >= 3.
    margin_m : float
        Distance outward from the shore still blanked [m], >= 0.

    Returns
    -------
    ndarray of bool
        (...) True where the cell is blanked.
    """
    from matplotlib.path import Path

    xy = np.asarray(cell_xy_m, dtype=float)
    if xy.shape[-1:] != (2,):
        raise ValueError(f"cell_xy_m of shape {xy.shape}: the last axis must be (x, y)")
    if not (np.isfinite(margin_m) and margin_m >= 0.0):
        raise ValueError(f"margin_m = {margin_m}: the land mask's margin must be >= 0 m")
    flat = xy.reshape(-1, 2)
    out = np.zeros(flat.shape[0], bool)
    ok = np.all(np.isfinite(flat), axis=1)
    for poly in outlines_m:
        v = np.asarray(poly, dtype=float)
        if v.ndim != 2 or v.shape[1] != 2 or v.shape[0] < 3:
            raise ValueError(f"land outline of shape {v.shape}: a polygon is (k >= 3, 2)")
        lo, hi = v.min(axis=0) - margin_m, v.max(axis=0) + margin_m
        near = np.flatnonzero(ok & np.all((flat >= lo) & (flat <= hi), axis=1))
        if not near.size:
            continue
        p = flat[near]
        hit = Path(v, closed=False).contains_points(p)
        if margin_m > 0.0:
            a, b = v, np.roll(v, -1, axis=0)  # the edges, the closing one included
            ab = b - a
            len2 = np.maximum((ab ** 2).sum(axis=1), 1e-300)
            for s in range(0, p.shape[0], _BLOCK):  # blocks of cells, every edge at once
                q = p[s:s + _BLOCK, None, :] - a[None]
                t = np.clip((q * ab[None]).sum(-1) / len2, 0.0, 1.0)
                d2 = ((q - t[..., None] * ab[None]) ** 2).sum(-1).min(axis=1)
                hit[s:s + _BLOCK] |= d2 <= margin_m ** 2
        out[near] |= hit
    return out.reshape(xy.shape[:-1])


def spread_bins(extent: float, spacing: float) -> int:
    """Bins of ``spacing`` a land cell's echo reaches on each side, out to ``extent``
    (same unit) from the land: floor(extent / spacing + 1/2).

    A land cell holds land anywhere within half a bin of its centre, so its echo reaches
    the centres within ``extent`` + spacing / 2 of it: the nearest whole number of bins
    to extent / spacing (0 for an extent under half a bin).
    """
    if not (np.isfinite(extent) and extent >= 0 and np.isfinite(spacing) and spacing > 0):
        raise ValueError(f"extent = {extent}, spacing = {spacing}: need extent >= 0 and "
                         "spacing > 0")
    return int(np.floor(extent / spacing + 0.5 + 1e-9))


def spread(mask: ArrayLike, azimuth_bins: int, range_bins: int,
           circular: bool = False) -> NDArray[np.bool_]:
    """The cells within ``azimuth_bins`` rays and ``range_bins`` gates of a masked cell.

    A binary dilation of the (azimuth, range) mask by the rectangle of (2 azimuth_bins
    + 1) x (2 range_bins + 1) cells (:func:`scipy.ndimage.maximum_filter`, separable);
    along azimuth it wraps when ``circular`` (a full revolution: the last ray beside the
    first), else it stops at the first and last rays, as it does at the first and last
    gates. More rays than the sweep holds cover the whole ring.

    Parameters
    ----------
    mask : array_like of bool
        (azimuth, range) cells blanked.
    azimuth_bins, range_bins : int
        Cells each side reached along azimuth (rows) and range (columns), >= 0.
    circular : bool
        Whether the rows close a revolution.

    Returns
    -------
    ndarray of bool
        (azimuth, range) the mask and its spread.
    """
    from scipy.ndimage import maximum_filter

    m = np.asarray(mask, dtype=bool)
    if m.ndim != 2:
        raise ValueError(f"mask of shape {m.shape}: an (azimuth, range) grid")
    na, nr = int(azimuth_bins), int(range_bins)
    if na < 0 or nr < 0:
        raise ValueError(f"azimuth_bins = {na}, range_bins = {nr}: need >= 0")
    if (na == 0 and nr == 0) or not m.any():
        return m.copy()
    if circular and 2 * na + 1 >= m.shape[0]:  # the whole ring at the land's gates
        return maximum_filter(np.broadcast_to(m.any(axis=0), m.shape), size=(1, 2 * nr + 1),
                              mode="constant", cval=False)
    return maximum_filter(m, size=(2 * na + 1, 2 * nr + 1),
                          mode=("wrap" if circular else "constant", "constant"), cval=False)
