"""Height field -> triangle mesh -> facets (shared by the ray-traced and analytic modes).

What a facet is
---------------
A facet is one triangle of the sea mesh. The mesh has one vertex per grid node
``(x[i], y[j], z[j, i])`` (``nx * ny`` vertices, the node layout of the ocean stage, arrays
shaped ``(ny, nx)``) and two triangles per grid cell, ``(nx - 1) * (ny - 1) * 2`` facets in
all (522 242 for 512 x 512). With ``P(j, i)`` the vertex of node ``(j, i)``, the cell
``(j, i)`` is split along its diagonal from ``P(j, i)`` to ``P(j+1, i+1)``::

    triangle 0: P(j, i), P(j, i+1),   P(j+1, i+1)      (below the diagonal)
    triangle 1: P(j, i), P(j+1, i+1), P(j+1, i)        (above the diagonal)

both counter-clockwise seen from above, so that their normals point up (+z). Facets are
numbered ``(j * (nx - 1) + i) * 2 + k``; an array of facet values reshapes to
``(ny - 1, nx - 1, 2)``. The periodic tile is not closed on itself: the mesh covers
``x[0]..x[-1]`` by ``y[0]..y[-1]``.

The facet's centroid, area and normal are those of the flat triangle (computed in float64);
its velocity is the mean of its three vertices' velocities, i.e. the velocity of the
centroid under linear interpolation.

The formulas (:func:`triangle`, :func:`vertex_mean`) are written over an array namespace
(:mod:`seaecho.backend`): :func:`facet_geometry` evaluates them with numpy on the grid's
slices, :func:`facet_geometry_in` in a Dr.Jit kernel that gathers each facet's vertices
from the node arrays (the fused per-pulse sea kernel, ``seaecho.radar.resident``), with the
same numbers.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..backend import NUMPY, Vec3

__all__ = [
    "facet_count",
    "facet_geometry",
    "facet_geometry_in",
    "grid_faces",
    "grid_vertices",
    "to_facets",
    "triangle",
    "vertex_mean",
]


def facet_count(nx: int, ny: int) -> int:
    """Number of facets (triangles) of an ``nx`` by ``ny`` node grid [-]."""
    return 2 * (nx - 1) * (ny - 1)


def _check_grid(x: np.ndarray, y: np.ndarray, z: np.ndarray) -> None:
    if x.ndim != 1 or y.ndim != 1 or x.size < 2 or y.size < 2:
        raise ValueError(f"x, y must be 1-D with >= 2 nodes, got shapes {x.shape}, {y.shape}")
    if z.shape[:2] != (y.size, x.size):
        raise ValueError(f"array shaped {z.shape} does not match (ny, nx) = ({y.size}, {x.size})")
    if np.any(np.diff(x) <= 0) or np.any(np.diff(y) <= 0):
        raise ValueError("x and y must be strictly increasing [m]")


def grid_vertices(x: np.ndarray, y: np.ndarray, elevation: np.ndarray,
                  dtype: type = np.float64, out: np.ndarray | None = None) -> np.ndarray:
    """Mesh vertices of a height field.

    Parameters
    ----------
    x : (nx,) array
        Node abscissae [m].
    y : (ny,) array
        Node ordinates [m].
    elevation : (ny, nx) array
        Surface elevation z [m].
    dtype : numpy dtype
        Output type (float32 for Mitsuba, float64 for our own geometry).
    out : (ny, nx, 3) array, optional
        Written in place when given (no allocation per time step).

    Returns
    -------
    (ny, nx, 3) array
        Vertex positions [m], vertex ``j * nx + i`` at ``[j, i]``.
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    elevation = np.asarray(elevation)
    _check_grid(x, y, elevation)
    if out is None:
        out = np.empty((y.size, x.size, 3), dtype=dtype)
    out[..., 0] = x[None, :]
    out[..., 1] = y[:, None]
    out[..., 2] = elevation
    return out


def grid_faces(nx: int, ny: int) -> np.ndarray:
    """Vertex indices of the facets of an ``nx`` by ``ny`` node grid.

    Returns
    -------
    (2 (nx-1) (ny-1), 3) uint32 array
        Counter-clockwise (seen from +z) vertex indices, facet order of the module docstring.
    """
    i, j = np.meshgrid(np.arange(nx - 1, dtype=np.uint32), np.arange(ny - 1, dtype=np.uint32))
    v00 = j * nx + i
    v10 = v00 + 1
    v01 = v00 + nx
    v11 = v01 + 1
    faces = np.empty((ny - 1, nx - 1, 2, 3), dtype=np.uint32)
    faces[..., 0, :] = np.stack([v00, v10, v11], axis=-1)
    faces[..., 1, :] = np.stack([v00, v11, v01], axis=-1)
    return faces.reshape(-1, 3)


def _corners(v: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The four corners P(j,i), P(j,i+1), P(j+1,i+1), P(j+1,i) of every cell."""
    return v[:-1, :-1], v[:-1, 1:], v[1:, 1:], v[1:, :-1]


def _divide(xp, v: Any, s: Any) -> Any:
    """A vector divided by a scalar, component by component (a true division in every
    namespace; Dr.Jit would multiply a vector by the reciprocal)."""
    return xp.vec(v.x / s, v.y / s, v.z / s)


def vertex_mean(xp, p00: Any, p11: Any, other: Any) -> Any:
    """Mean of a node quantity over a facet's vertices, ``(P00 + P11 + other) / 3``.

    ``other`` is P10 for triangle 0, P01 for triangle 1 (namespace values; vectors, or
    scalar arrays).
    """
    s = p00 + p11 + other
    three = xp.const(3.0)
    return _divide(xp, s, three) if xp.is_vector(s) else s / three


def triangle(xp, p00: Any, p10: Any, p11: Any, p01: Any, upper: Any
             ) -> tuple[Any, Any, Any]:
    """Centroid [m], twice the area [m^2] and unit normal [-] of a cell's triangle.

    Triangle 0 is (P00, P10, P11), triangle 1 (``upper``) is (P00, P11, P01); for a
    triangle (A, B, C) the vector ``(B - A) x (C - A)`` is normal to it with length twice
    its area, pointing up for these counter-clockwise triangles.

    Parameters
    ----------
    xp : array namespace
    p00, p10, p11, p01 : vectors
        The cell's corners P(j, i), P(j, i+1), P(j+1, i+1), P(j+1, i) [m].
    upper : bool or namespace Bool
        Which triangle (a Python bool, or one per entry).
    """
    d11 = p11 - p00
    if isinstance(upper, bool):
        cross = xp.cross(d11, p01 - p00) if upper else xp.cross(p10 - p00, d11)
        other = p01 if upper else p10
    else:
        cross = xp.select(upper, xp.cross(d11, p01 - p00), xp.cross(p10 - p00, d11))
        other = xp.select(upper, p01, p10)
    twice_area = xp.sqrt(xp.dot(cross, cross))
    return vertex_mean(xp, p00, p11, other), twice_area, _divide(xp, cross, twice_area)


def to_facets(node_values: np.ndarray) -> np.ndarray:
    """Mean of a node quantity over the three vertices of each facet.

    Parameters
    ----------
    node_values : (ny, nx, ...) array
        A quantity at the grid nodes (a velocity, a slope, ...).

    Returns
    -------
    (N, ...) array
        Its value at the facet centroids under linear interpolation, N = 2 (nx-1) (ny-1)
        (:func:`vertex_mean`).
    """
    a = np.asarray(node_values)
    p00, p10, p11, p01 = _corners(a)
    out = np.empty((a.shape[0] - 1, a.shape[1] - 1, 2) + a.shape[2:], dtype=np.result_type(a, 1.0))
    out[:, :, 0] = vertex_mean(NUMPY, p00, p11, p10)
    out[:, :, 1] = vertex_mean(NUMPY, p00, p11, p01)
    return out.reshape((-1,) + a.shape[2:])


def facet_geometry(vertices: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centroid, area and unit normal of every facet of a grid mesh (float64).

    Parameters
    ----------
    vertices : (ny, nx, 3) array
        Vertex positions [m] (:func:`grid_vertices`).

    Returns
    -------
    centroid : (N, 3) array
        Facet centroids [m].
    area : (N,) array
        Facet areas [m^2].
    normal : (N, 3) array
        Unit normals [-], oriented towards +z for a height field.

    Notes
    -----
    :func:`triangle` on the cells' corners; the triangles of :func:`grid_faces` are
    counter-clockwise from above, so the normals point up.
    """
    v = np.asarray(vertices, dtype=np.float64)
    corners = [Vec3(c[..., 0], c[..., 1], c[..., 2]) for c in _corners(v)]
    shape = (v.shape[0] - 1, v.shape[1] - 1, 2)
    centroid, normal = np.empty(shape + (3,)), np.empty(shape + (3,))
    twice_area = np.empty(shape)
    for k in (0, 1):
        c, t, nrm = triangle(NUMPY, *corners, bool(k))
        twice_area[:, :, k] = t
        for j in range(3):
            centroid[:, :, k, j] = c[j]
            normal[:, :, k, j] = nrm[j]
    twice_area = twice_area.reshape(-1)
    if np.any(twice_area <= 0.0):
        raise ValueError("degenerate facet (zero area): vertices must form a height field")
    return centroid.reshape(-1, 3), 0.5 * twice_area, normal.reshape(-1, 3)


def facet_geometry_in(xp, x: Any, y: Any, elevation: Any, velocity: Any, nx: int, ny: int,
                      node_fields: dict[str, Any] | None = None) -> dict[str, Any]:
    """:func:`facet_geometry` and the facets' velocities (:func:`to_facets`) in a kernel.

    Each facet gathers its vertices from the node arrays, so only the nodes need to be
    on the device (a quarter of the per-facet arrays' size).

    Parameters
    ----------
    xp : Dr.Jit namespace
    x, y : namespace arrays (nx,), (ny,)
        Node coordinates [m].
    elevation : namespace array (ny nx,)
        Node heights [m], row-major (node (j, i) at j nx + i).
    velocity : namespace vector (ny nx,)
        Node velocities [m/s].
    nx, ny : int
        Grid nodes per row and per column.
    node_fields : dict, optional
        Further node quantities (namespace arrays (ny nx,), row-major): each is returned
        under its key as its facet mean (:func:`to_facets`, the same operations).

    Returns
    -------
    dict
        ``centroid`` [m], ``area`` [m^2], ``normal`` [-], ``velocity`` [m/s] of the
        2 (nx - 1) (ny - 1) facets, in the order of the module docstring, and the facet
        means of ``node_fields``.
    """
    j = xp.arange(facet_count(nx, ny))
    cell = j // 2
    upper = (j - cell * 2) == 1
    iy = cell // (nx - 1)
    ix = cell - iy * (nx - 1)
    v00 = iy * nx + ix
    v11 = v00 + (nx + 1)
    v_other = xp.select(upper, v00 + nx, v00 + 1)
    x0, x1 = xp.gather(x, ix), xp.gather(x, ix + 1)
    y0, y1 = xp.gather(y, iy), xp.gather(y, iy + 1)
    p00 = xp.vec(x0, y0, xp.gather(elevation, v00))
    p10 = xp.vec(x1, y0, xp.gather(elevation, v00 + 1))
    p11 = xp.vec(x1, y1, xp.gather(elevation, v11))
    p01 = xp.vec(x0, y1, xp.gather(elevation, v00 + nx))
    centroid, twice_area, normal = triangle(xp, p00, p10, p11, p01, upper)

    def node(v, idx):
        return xp.vec(*(xp.gather(c, idx) for c in (v.x, v.y, v.z)))

    vel = vertex_mean(xp, node(velocity, v00), node(velocity, v11), node(velocity, v_other))
    out = dict(centroid=centroid, area=0.5 * twice_area, normal=normal, velocity=vel)
    for name, f in (node_fields or {}).items():
        out[name] = vertex_mean(xp, xp.gather(f, v00), xp.gather(f, v11),
                                xp.gather(f, v_other))
    return out
