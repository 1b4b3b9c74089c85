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
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "facet_count",
    "facet_geometry",
    "grid_faces",
    "grid_vertices",
    "to_facets",
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


def to_facets(node_values: np.ndarray) -> np.ndarray:
    """Mean of a node quantity over the three vertices of each facet.

    Parameters
    ----------
    node_values : (ny, nx, ...) array
        A quantity at the grid nodes (a velocity, a slope, ...).

    Returns
    -------
    (N, ...) array
        Its value at the facet centroids under linear interpolation, N = 2 (nx-1) (ny-1).
    """
    a = np.asarray(node_values)
    p00, p10, p11, p01 = _corners(a)
    out = np.empty((a.shape[0] - 1, a.shape[1] - 1, 2) + a.shape[2:], dtype=np.result_type(a, 1.0))
    # centroid of triangle 0 = (P00 + P10 + P11) / 3, of triangle 1 = (P00 + P11 + P01) / 3
    s = p00 + p11
    np.add(s, p10, out=out[:, :, 0])
    np.add(s, p01, out=out[:, :, 1])
    out /= 3.0
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
    For a triangle (A, B, C) the vector ``(B - A) x (C - A)`` is normal to it with length
    twice its area; the triangles of :func:`grid_faces` are counter-clockwise from above,
    so this normal points up.
    """
    v = np.asarray(vertices, dtype=np.float64)
    p00, p10, p11, p01 = _corners(v)
    shape = (v.shape[0] - 1, v.shape[1] - 1, 2, 3)
    cross = np.empty(shape)
    d11 = p11 - p00
    cross[:, :, 0] = np.cross(p10 - p00, d11)  # triangle 0: (B - A) x (C - A)
    cross[:, :, 1] = np.cross(d11, p01 - p00)  # triangle 1
    cross = cross.reshape(-1, 3)
    twice_area = np.sqrt(np.einsum("ij,ij->i", cross, cross))
    if np.any(twice_area <= 0.0):
        raise ValueError("degenerate facet (zero area): vertices must form a height field")
    normal = cross / twice_area[:, None]
    return to_facets(v), 0.5 * twice_area, normal
