"""The Earth's curvature: effective Earth radius, grazing angle, radar horizon.

Standard atmospheric refraction bends rays down with a curvature about a quarter of the
Earth's; drawing the rays straight over an Earth of radius k a with k = 4/3 keeps their
heights (Skolnik 2001, chapter 8; Blake 1986, chapter 5, "Tropospheric Refraction").
On that sphere, with the radar at height h above the surface and a point of the surface
at slant range r:

.. math::

    \\sin\\psi = \\frac{h}{r} + \\frac{h^2}{2 k a\\, r} - \\frac{r}{2 k a}          (E1)

the grazing angle at the surface point (the law of cosines in the triangle Earth
centre, radar, point: (R + h)^2 = R^2 + r^2 + 2 R r sin psi with R = k a);

.. math::

    d_h = \\sqrt{2 k a}\\,(\\sqrt{h_1} + \\sqrt{h_2})                                (E2)

the radar horizon between heights h_1 and h_2 (the sum of the two tangent distances,
h << k a; for k = 4/3, 4.12 km sqrt(h [m]) for one end: the "radio horizon range" of
Federal Standard 1037C, R = 1.23 (sqrt(h_t) + sqrt(h_r)) NM with the heights in feet,
2.23 (sqrt(h_t) + sqrt(h_r)) NM with them in metres, "the effective Earth radius, 4/3
times the actual Earth radius, is used in deriving the formulae");

.. math::

    \\delta(d) = k a - \\sqrt{(k a)^2 - d^2} \\approx \\frac{d^2}{2 k a}             (E3)

the drop of the sphere below the tangent plane at horizontal distance d.

The scene frame on a spherical Earth (:class:`SphericalEarth`). The world frame of a
scene is the plane tangent to the (effective) sphere at the world origin, x east, y
north, z up. A scene's coordinates (x, y, z) of a platform or a target are read as the
point at great-circle distance rho = hypot(x, y) from the origin in the direction
phi = atan2(y, x), at height z above the sphere; its Cartesian position in the tangent
frame is

.. math::

    \\mathbf P = (R + z)\\,(\\sin\\beta\\cos\\phi,\\ \\sin\\beta\\sin\\phi,\\ \\cos\\beta)
        - (0, 0, R),\\qquad \\beta = \\rho / R,\\ R = k a                             (E4)

and its local vertical is turned from +z by beta about (-sin phi, cos phi, 0) (the same
rotation carries its attitude and its velocity). The sea tile lies around the origin,
where (E4) is the identity to O(rho^2 / R): the tile itself stays flat; its own drop (E3)
is at most L^2 / (8 R) at the edge of a tile of diagonal L (3.7 mm for 500 m) and is
neglected. A straight ray between two points is blocked when it passes below the sphere
(:meth:`SphericalEarth.visible`).

References
----------
.. [1] M. I. Skolnik, *Introduction to Radar Systems*, 3rd ed., McGraw-Hill, 2001,
   chapter 8 (propagation: the 4/3 effective Earth radius, the radar horizon); its
   section and equation numbers are not checked against the book here.
.. [2] L. V. Blake, *Radar Range-Performance Analysis*, Artech House, 1986, chapter 5
   ("Effects of the Earth's Atmosphere", section "Tropospheric Refraction", pp. 178-192,
   as the book's table of contents gives it; its equations are not checked here).
.. [3] IUGG mean Earth radius 6371.0088 km (Moritz, H., Geodetic Reference System 1980,
   *Bulletin Géodésique* 54, 1980).
.. [4] Federal Standard 1037C, *Telecommunications: Glossary of Telecommunication Terms*
   (1996), entry "radio horizon range (RHR)" (from Weik 1989): the numerical forms of
   (E2) for k = 4/3 (read; the entry "radar line-of-sight (LOS) equation" gives the same
   in km and statute miles, its formulas not legible in the copy read).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Mean Earth radius a [m] (IUGG, GRS 80).
EARTH_RADIUS_M = 6371.0088e3
#: Effective Earth radius factor k of the standard atmosphere (Skolnik 2001, ch. 8; FS-1037C).
STANDARD_REFRACTION_K = 4.0 / 3.0


def effective_radius(k: float = STANDARD_REFRACTION_K) -> float:
    """Effective Earth radius k a [m] (Skolnik 2001, chapter 8; Blake 1986, chapter 5).

    Parameters
    ----------
    k : float
        Effective Earth radius factor [-] (4/3: standard refraction).
    """
    if not k > 0:
        raise ValueError(f"k = {k}: the effective Earth radius factor must be > 0")
    return k * EARTH_RADIUS_M


def grazing_angle(h: ArrayLike, r: ArrayLike, radius: float) -> NDArray[np.float64]:
    """Grazing angle psi [rad] at the surface at slant range r from height h, eq (E1).

    Parameters
    ----------
    h : array_like
        Radar height above the surface [m].
    r : array_like
        Slant range [m], at least h.
    radius : float
        Effective Earth radius k a [m] (``numpy.inf``: flat Earth, sin psi = h / r).

    Returns
    -------
    ndarray
        psi [rad]; negative beyond the horizon (the point is not seen).

    References
    ----------
    Eq (E1): the law of cosines on the sphere of radius k a (module docstring).
    """
    h = np.asarray(h, dtype=float)
    r = np.asarray(r, dtype=float)
    # Eq (E1)
    s = h / r + (h * h - r * r) / (2.0 * radius * r)
    return np.arcsin(np.clip(s, -1.0, 1.0))


def horizon_range(h1: ArrayLike, h2: ArrayLike, radius: float) -> NDArray[np.float64]:
    """Radar horizon d_h [m] between heights h1 and h2 [m] over radius k a [m], eq (E2).

    References
    ----------
    Federal Standard 1037C (1996), "radio horizon range (RHR)" (k = 4/3); Skolnik
    (2001), chapter 8.
    """
    h1, h2 = np.asarray(h1, dtype=float), np.asarray(h2, dtype=float)
    if np.any(h1 < 0) or np.any(h2 < 0):
        raise ValueError("heights h1, h2 must be >= 0 m")
    # Eq (E2): the two tangent distances
    return np.sqrt(2.0 * radius) * (np.sqrt(h1) + np.sqrt(h2))


def surface_drop(d: ArrayLike, radius: float) -> NDArray[np.float64]:
    """Drop delta [m] of the sphere below the tangent plane at distance d [m], eq (E3).

    Written as d^2 / (R + sqrt(R^2 - d^2)) (no cancellation) for d <= R.
    """
    d = np.asarray(d, dtype=float)
    # Eq (E3)
    return d * d / (radius + np.sqrt(np.maximum(radius * radius - d * d, 0.0)))


@dataclass(frozen=True)
class SphericalEarth:
    """The scene frame on a sphere of effective radius R = k a (module docstring).

    Attributes
    ----------
    radius : float
        Effective radius k a [m].
    """

    radius: float

    def _angles(self, p: NDArray) -> tuple[NDArray, NDArray, NDArray]:
        rho = np.hypot(p[..., 0], p[..., 1])
        return rho / self.radius, np.arctan2(p[..., 1], p[..., 0]), rho

    def position(self, p: ArrayLike) -> NDArray[np.float64]:
        """Cartesian positions (tangent frame) of scene points (..., 3) [m], eq (E4)."""
        p = np.asarray(p, dtype=float)
        beta, phi, _ = self._angles(p)
        rz = self.radius + p[..., 2]
        s = np.sin(beta)
        # Eq (E4); (R + z) cos(beta) - R = z cos(beta) - R (1 - cos beta), no cancellation
        return np.stack([rz * s * np.cos(phi), rz * s * np.sin(phi),
                         p[..., 2] * np.cos(beta)
                         - 2.0 * self.radius * np.sin(0.5 * beta) ** 2], axis=-1)

    def tilt(self, p: ArrayLike) -> NDArray[np.float64]:
        """Rotation (..., 3, 3) from the tangent frame's axes to the local (east, north,
        up) axes of the scene points p: beta about (-sin phi, cos phi, 0) (Rodrigues)."""
        p = np.asarray(p, dtype=float)
        beta, phi, _ = self._angles(p)
        k = np.stack([-np.sin(phi), np.cos(phi), np.zeros_like(phi)], axis=-1)
        kx = np.zeros(k.shape[:-1] + (3, 3))
        kx[..., 0, 1], kx[..., 0, 2] = -k[..., 2], k[..., 1]
        kx[..., 1, 0], kx[..., 1, 2] = k[..., 2], -k[..., 0]
        kx[..., 2, 0], kx[..., 2, 1] = -k[..., 1], k[..., 0]
        s, c = np.sin(beta)[..., None, None], np.cos(beta)[..., None, None]
        return np.eye(3) + s * kx + (1.0 - c) * (kx @ kx)

    def visible(self, a: ArrayLike, b: ArrayLike) -> NDArray[np.bool_]:
        """Whether the straight segment between Cartesian points a and b (..., 3) [m]
        clears the sphere (the radar horizon of eq E2 in the limit h << R)."""
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        centre = np.array([0.0, 0.0, -self.radius])
        u, w = b - a, centre - a
        t = np.clip(np.sum(w * u, axis=-1) / np.maximum(np.sum(u * u, axis=-1), 1e-300),
                    0.0, 1.0)
        closest = a + t[..., None] * u
        # 1 um of tolerance (rounding of R ~ 1e-9 m): a point on the surface sees up to its
        # horizon
        return np.linalg.norm(closest - centre, axis=-1) >= self.radius - 1.0e-6


__all__ = ["EARTH_RADIUS_M", "STANDARD_REFRACTION_K", "SphericalEarth", "effective_radius",
           "grazing_angle", "horizon_range", "surface_drop"]
