"""Land as a triangle mesh: a shore outline and a height profile.

A piece of land (``[[land]]``) is a polygon of the shore in the scene's (x, y) plane and
a height profile across it: the ground rises from the sea level at the shore to
``height`` over ``shore_width`` inland and stays there,

.. math::

    z(d) = H \\min(d / W, 1),\\qquad d \\ge 0                                   (G1)

with d the distance from the point to the outline (inside the polygon) and W the shore
width (a cliff: W of one facet). :func:`land_mesh` samples it on a square grid of
spacing ``resolution`` over the polygon's bounding box and keeps the grid cells whose
centre lies inside the polygon (even-odd rule), two triangles per cell: the shore
follows the outline to half a cell. Faces are wound so that their normals point up.

On a spherical Earth the vertices are read as the scene's Earth-following coordinates
(distance along the surface, height above it) and mapped to the tangent frame with
:meth:`seaecho.geometry.earth.SphericalEarth.position` (eq E4) by the caller.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def inside_polygon(points: ArrayLike, outline: ArrayLike) -> NDArray[np.bool_]:
    """Whether points (..., 2) [m] lie inside a polygon (V, 2) [m] (even-odd rule: the
    number of edges a horizontal ray from the point crosses is odd; in blocks of points).

    References
    ----------
    W. R. Franklin, "PNPOLY - point inclusion in polygon test" (the crossing test).
    """
    p = np.asarray(points, dtype=np.float64)
    flat = p.reshape(-1, 2)
    v = np.asarray(outline, dtype=np.float64)
    x1, y1 = v[:, 0], v[:, 1]
    x2, y2 = np.roll(x1, -1), np.roll(y1, -1)
    out = np.empty(flat.shape[0], dtype=bool)
    step = max(1, (1 << 22) // v.shape[0])
    for i in range(0, flat.shape[0], step):  # blocks of points, not a loop over points
        x, y = flat[i:i + step, 0, None], flat[i:i + step, 1, None]
        straddle = (y1 > y) != (y2 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xc = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
        out[i:i + step] = np.sum(straddle & (x < xc), axis=-1) % 2 == 1
    return out.reshape(p.shape[:-1])


def distance_to_outline(points: ArrayLike, outline: ArrayLike) -> NDArray[np.float64]:
    """Distance [m] from points (N, 2) to the closed polygon outline (V, 2) [m] (in
    blocks of points, so that memory stays ~ 2^22 point-edge pairs)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    a = np.asarray(outline, dtype=np.float64)
    ab = np.roll(a, -1, axis=0) - a
    ab2 = np.maximum(np.sum(ab * ab, axis=-1), 1e-300)
    out = np.empty(pts.shape[0])
    step = max(1, (1 << 22) // a.shape[0])
    for i in range(0, pts.shape[0], step):  # blocks of points, not a loop over points
        p = pts[i:i + step, None, :]
        t = np.clip(np.sum((p - a) * ab, axis=-1) / ab2, 0.0, 1.0)
        out[i:i + step] = np.min(np.linalg.norm(p - (a + t[..., None] * ab), axis=-1),
                                 axis=-1)
    return out


def shore_height(d: ArrayLike, height: float, shore_width: float) -> NDArray[np.float64]:
    """Ground height [m] at distance d [m] inland of the shore, eq (G1)."""
    d = np.maximum(np.asarray(d, dtype=np.float64), 0.0)
    # Eq (G1)
    return height * np.minimum(d / shore_width, 1.0)


def land_mesh(outline: ArrayLike, height: float, shore_width: float, resolution: float
              ) -> tuple[NDArray[np.float64], NDArray[np.uint32], NDArray[np.int64]]:
    """Vertices (V, 3) [m], faces (F, 3) and grid cells (F, 2) of the land inside
    ``outline``, eq (G1).

    Parameters
    ----------
    outline : array_like (N, 2)
        The shore polygon (x, y) [m], N >= 3, either winding, not closed explicitly.
    height : float
        Plateau height H above the sea level [m].
    shore_width : float
        Distance W over which the ground rises from the shore [m] (at least one cell).
    resolution : float
        Grid spacing [m].

    Returns
    -------
    vertices, faces, cells
        Only the vertices of kept cells; faces wound with upward normals; each face's
        grid cell (row, column) of the bounding box's grid.
    """
    v = np.asarray(outline, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 2 or v.shape[0] < 3:
        raise ValueError(f"outline shaped {v.shape}: need (N >= 3, 2) points [m]")
    if not (height > 0 and resolution > 0 and shore_width >= 0):
        raise ValueError("height and resolution must be > 0, shore_width >= 0 [m]")
    w = max(shore_width, resolution)
    lo, hi = v.min(axis=0), v.max(axis=0)
    nx = int(np.ceil((hi[0] - lo[0]) / resolution)) + 1
    ny = int(np.ceil((hi[1] - lo[1]) / resolution)) + 1
    x = lo[0] + resolution * np.arange(nx)
    y = lo[1] + resolution * np.arange(ny)
    centres = np.stack(np.meshgrid(x[:-1] + 0.5 * resolution, y[:-1] + 0.5 * resolution),
                       axis=-1)
    keep = inside_polygon(centres, v)  # (ny - 1, nx - 1) cells
    if not keep.any():
        raise ValueError("outline: no grid cell inside the polygon (resolution too coarse"
                         " for it)")
    jj, ii = np.nonzero(keep)
    corners = np.stack([jj * nx + ii, jj * nx + ii + 1, (jj + 1) * nx + ii + 1,
                        (jj + 1) * nx + ii], axis=-1)  # counter-clockwise seen from +z
    used, inverse = np.unique(corners, return_inverse=True)
    inverse = inverse.reshape(corners.shape)
    gx, gy = x[used % nx], y[used // nx]
    pts = np.stack([gx, gy], axis=-1)
    inland = np.where(inside_polygon(pts, v), distance_to_outline(pts, v), 0.0)
    z = shore_height(inland, height, w)
    vertices = np.stack([gx, gy, z], axis=-1)
    faces = np.concatenate([inverse[:, [0, 1, 2]], inverse[:, [0, 2, 3]]])
    cells = np.tile(np.stack([jj, ii], axis=-1), (2, 1)).astype(np.int64)
    return vertices, faces.astype(np.uint32), cells


__all__ = ["distance_to_outline", "inside_polygon", "land_mesh", "shore_height"]
