"""Canonical scatterers as triangle meshes: flat plate, dihedral, trihedral, sphere.

Their radar cross sections have closed forms in the optical region (Knott, Shaeffer and
Tuley 1993, table 6.1), which the tests of the hull-echo stage compare against; the
calibration scene ``scenes/calibration_trihedral.toml`` uses the trihedral written by
``tools/make_vessel_mesh.py``. Meshes are returned as ``(vertices (V, 3) float64 [m],
faces (F, 3) int64)``; plates are open (one layer of triangles, reflecting on both
sides).

References
----------
.. [1] Knott, E. F., Shaeffer, J. F. and Tuley, M. T. (1993). *Radar Cross Section*,
   2nd ed., Artech House, table 6.1 (RCS of simple shapes).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["dihedral", "rectangular_plate", "sphere", "trihedral"]

Mesh = tuple[NDArray[np.float64], NDArray[np.int64]]


def _check(name: str, value: float) -> None:
    if not (np.isfinite(value) and value > 0):
        raise ValueError(f"{name} = {value}: must be a positive length [m]")


def rectangular_plate(a: float, b: float) -> Mesh:
    """Flat plate ``a`` (along x) by ``b`` (along y) in the plane z = 0, centred on the origin.

    Parameters
    ----------
    a, b : float
        Side lengths [m].

    Returns
    -------
    vertices, faces
        Two triangles, normal +z.
    """
    _check("a", a)
    _check("b", b)
    v = np.array([[-a / 2, -b / 2, 0.0], [a / 2, -b / 2, 0.0], [a / 2, b / 2, 0.0],
                  [-a / 2, b / 2, 0.0]])
    return v, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)


def dihedral(a: float, b: float) -> Mesh:
    """Right-angle dihedral: faces z = 0 (0 <= x <= a) and x = 0 (0 <= z <= a), fold along y.

    Each face is ``a`` wide (away from the fold) and ``b`` long (along the fold, y in
    [-b/2, b/2]). The opening faces the direction (1, 0, 1) / sqrt(2), where its
    monostatic RCS peaks at ``8 pi a^2 b^2 / lambda^2`` (Knott et al. 1993, table 6.1).

    Parameters
    ----------
    a, b : float
        Face width and fold length [m].
    """
    _check("a", a)
    _check("b", b)
    h = b / 2
    v = np.array([[0.0, -h, 0.0], [a, -h, 0.0], [a, h, 0.0], [0.0, h, 0.0],   # floor z = 0
                  [0.0, -h, a], [0.0, h, a]])                                 # wall x = 0
    f = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 5], [0, 5, 4]], dtype=np.int64)
    return v, f


def trihedral(a: float) -> Mesh:
    """Triangular trihedral corner reflector: apex at the origin, edges ``a`` along x, y, z.

    Three right isosceles triangles on the planes x = 0, y = 0, z = 0. Its symmetry axis
    (1, 1, 1) / sqrt(3) is the direction of its peak monostatic RCS
    ``4 pi a^4 / (3 lambda^2)`` (Knott et al. 1993, table 6.1).

    Parameters
    ----------
    a : float
        Edge length [m].
    """
    _check("a", a)
    v = np.array([[0.0, 0.0, 0.0], [a, 0.0, 0.0], [0.0, a, 0.0], [0.0, 0.0, a]])
    f = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1]], dtype=np.int64)
    return v, f


def sphere(radius: float, subdivisions: int = 5) -> Mesh:
    """Icosphere of ``radius`` centred on the origin (closed, outward normals).

    A facetted sphere scatters like the smooth one (optical limit ``pi a^2``) when its
    facets are small against the first Fresnel zone: the sagitta of a facet of size s,
    ``s^2 / (8 a)``, must stay well below ``lambda / 8`` (two-way phase under pi/2).

    Parameters
    ----------
    radius : float
        [m].
    subdivisions : int
        Icosahedron subdivisions (20 * 4**n triangles), 0..7.
    """
    import trimesh

    _check("radius", radius)
    if not (isinstance(subdivisions, int | np.integer) and 0 <= subdivisions <= 7):
        raise ValueError(f"subdivisions = {subdivisions}: must be an integer in 0..7")
    m = trimesh.creation.icosphere(subdivisions=int(subdivisions), radius=float(radius))
    return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)
