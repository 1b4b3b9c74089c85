"""Facets seen from a transmitter and a receiver: the result container and the analytic mode.

Both facet modes return a :class:`Facets` (plain numpy arrays, one row per facet, facets
as defined in :mod:`seaecho.geometry.mesh`):

- ``raytraced`` (:mod:`seaecho.tracing`): triangle normals of the mesh, lit/seen from the
  facing test plus shadow rays cast on Sionna RT / Mitsuba against the sea and the scene's
  objects (0 or 1 per facet);
- ``analytic`` (:func:`analytic_facets`): normals from the ocean stage's analytic slopes,
  no ray tracing; every facing facet visible (``shadowing="none"``) or weighted by Smith's
  statistical shadowing probability given its height (``shadowing="smith"``, eqs T3, T5,
  T6 of :mod:`seaecho.geometry.shadowing`), a number in [0, 1].

The radar stage multiplies each facet's scattered power by ``visibility`` (lit from the
transmitter *and* seen from the receiver).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, fields
from typing import Any, Literal

import numpy as np

from ..backend import NUMPY, Boundary
from . import frames as _frames
from .bistatic import azimuths, ranges
from .mesh import facet_geometry, grid_vertices, to_facets
from .shadowing import directional_slope_std, height_cdf, smith_lambda, smith_nu

_BACKSCATTER_TOL = 1e-9

__all__ = ["FRAME_NAMES", "Facets", "analytic_facets", "facet_frames", "facet_frames_in",
           "frames_of_facets", "smith_weights", "subfacet_shadowing"]

#: Keys of :func:`facet_frames`, in order.
FRAME_NAMES = ("r_tx", "r_rx", "n_i", "n_s", "theta_i", "theta_s", "phi", "theta_i_global",
               "theta_s_global", "phi_global", "rot_i", "rot_s")


@dataclass(frozen=True)
class Facets:
    """Per-facet geometry and visibility for one time step (all arrays numpy, float64).

    Attributes
    ----------
    mode : str
        ``"raytraced"`` or ``"analytic"``.
    time_s : float
        Time of the surface and platform positions [s].
    visibility_time_s : float
        Time at which ``lit``/``seen`` were computed [s] (earlier than ``time_s`` when the
        refresh interval reuses them, see ``docs/tracing.md``).
    grid_shape : tuple
        ``(ny - 1, nx - 1, 2)``: per-facet arrays reshape to it (:meth:`as_grid`).
    centroid : (N, 3)
        Facet centroids [m].
    area : (N,)
        Facet areas [m^2].
    normal : (N, 3)
        Unit facet normals [-].
    velocity : (N, 3)
        Centroid velocities [m/s].
    r_tx, r_rx : (N,)
        Ranges transmitter -> facet, facet -> receiver [m] (float64).
    n_i, n_s : (N, 3)
        Unit directions transmitter -> facet, facet -> receiver [-].
    theta_i, theta_s, phi : (N,)
        Local bistatic angles about the facet normal [rad] (phi = phi_s - phi_i).
    theta_i_global, theta_s_global, phi_global : (N,)
        The same about the mean-plane normal +z [rad].
    rot_i, rot_s : (N, 2, 2)
        Rotations from the global to the local polarisation bases of the incident and
        scattered waves, (h, v) order (:func:`seaecho.geometry.frames.tilt_rotation`):
        ``S_global = frames.to_global(S_local, rot_i, rot_s)`` (eq F4 there).
    lit, seen : (N,)
        Illuminated by the transmitter / visible from the receiver, in [0, 1] [-].
    visibility : (N,)
        Lit and seen (jointly) [-]: the weight of the facet's echo.
    extra : dict
        Optional per-facet arrays (e.g. ``"subfacet_shadowing"``, eq T7).
    """

    mode: str
    time_s: float
    visibility_time_s: float
    grid_shape: tuple[int, int, int]
    centroid: np.ndarray
    area: np.ndarray
    normal: np.ndarray
    velocity: np.ndarray
    r_tx: np.ndarray
    r_rx: np.ndarray
    n_i: np.ndarray
    n_s: np.ndarray
    theta_i: np.ndarray
    theta_s: np.ndarray
    phi: np.ndarray
    theta_i_global: np.ndarray
    theta_s_global: np.ndarray
    phi_global: np.ndarray
    rot_i: np.ndarray
    rot_s: np.ndarray
    lit: np.ndarray
    seen: np.ndarray
    visibility: np.ndarray
    extra: dict = field(default_factory=dict)

    @property
    def n_facets(self) -> int:
        """Number of facets N."""
        return int(self.area.shape[0])

    def as_grid(self, name: str) -> np.ndarray:
        """A per-facet array reshaped to ``(ny - 1, nx - 1, 2, ...)`` (cells, triangle)."""
        a = getattr(self, name)
        return a.reshape(self.grid_shape + a.shape[1:])

    def cell_mean(self, name: str) -> np.ndarray:
        """Mean of a per-facet quantity over the two triangles of each cell ``(ny-1, nx-1)``."""
        return self.as_grid(name).mean(axis=2)

    def array_names(self) -> list[str]:
        """Names of the per-facet arrays."""
        return [f.name for f in fields(self) if isinstance(getattr(self, f.name), np.ndarray)]


def frames_of_facets(xp, centroid: Any, normal: Any, p_tx: Any, p_rx: Any,
                     monostatic: bool) -> dict[str, Any]:
    """Ranges, directions, local and global angles and basis rotations of facets.

    Eq G1 (:func:`seaecho.geometry.bistatic.ranges`), the local angles
    (:func:`seaecho.geometry.frames.bistatic_angles`), the global angles
    (:func:`seaecho.geometry.bistatic.azimuths`) and the rotations of eq F3 from the
    global (+z) to the facets' polarisation bases (:func:`seaecho.geometry.frames.tilt`),
    over an array namespace (:mod:`seaecho.backend`): the numpy :func:`facet_frames` and
    the tracing stage's Dr.Jit kernel both evaluate this function.

    Returns
    -------
    dict
        Namespace values under the names of :data:`FRAME_NAMES`.
    """
    r_tx, r_rx, n_i, n_s = ranges(xp, centroid, p_tx, p_rx, monostatic)
    theta_i, theta_s, phi = _frames.bistatic_angles(xp, n_i, n_s, normal)
    tig, tsg, phig = azimuths(xp, n_i, n_s)
    rot_i, rot_s = _frames.tilt(xp, n_i, n_s, normal, xp.vec(0.0, 0.0, 1.0))
    return dict(zip(FRAME_NAMES, (r_tx, r_rx, n_i, n_s, theta_i, theta_s, phi, tig, tsg,
                                  phig, rot_i, rot_s), strict=True))


def facet_frames_in(xp, centroid: np.ndarray, normal: np.ndarray, tx: np.ndarray,
                    rx: np.ndarray) -> dict[str, np.ndarray]:
    """:func:`frames_of_facets` of numpy facets, evaluated in namespace ``xp``.

    One kernel in Dr.Jit (the Tx/Rx positions as opaque per-pulse constants, so that a
    new position does not recompile it); numpy arrays in and out.
    """
    tx = np.asarray(tx, dtype=np.float64).reshape(3)
    rx = np.asarray(rx, dtype=np.float64).reshape(3)
    n = np.shape(centroid)[0]
    io = Boundary(xp, n)
    out = frames_of_facets(xp, io.vec3(centroid), io.vec3(normal), xp.vconst(tx),
                           xp.vconst(rx), bool(np.array_equal(tx, rx)))
    return dict(zip(FRAME_NAMES, io.numpy(*out.values()), strict=True))


def facet_frames(centroid: np.ndarray, normal: np.ndarray, tx: np.ndarray, rx: np.ndarray
                 ) -> dict[str, np.ndarray]:
    """Ranges, directions, local/global angles and basis rotations of facets (numpy).

    Parameters
    ----------
    centroid : (N, 3) array
        Facet centroids [m].
    normal : (N, 3) array
        Unit facet normals [-].
    tx, rx : (3,) arrays
        Transmitter and receiver positions [m].

    Returns
    -------
    dict
        ``r_tx, r_rx, n_i, n_s, theta_i, theta_s, phi, theta_i_global, theta_s_global,
        phi_global, rot_i, rot_s`` (see :class:`Facets`). Formula:
        :func:`frames_of_facets`.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        out = facet_frames_in(NUMPY, centroid, normal, tx, rx)
    if np.any(out["r_tx"] == 0.0):
        raise ValueError("the transmitter lies on a facet centroid (zero range)")
    if np.any(out["r_rx"] == 0.0):
        raise ValueError("the receiver lies on a facet centroid (zero range)")
    return out


def smith_weights(height: np.ndarray, n_i: np.ndarray, n_s: np.ndarray, sigma_h: float,
                  slope_cov: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Smith's probabilities that facets at given heights are not shadowed / masked.

    Facing is not included (multiply by the facets' facing tests).

    Parameters
    ----------
    height : (N,) array
        Facet heights above the mean plane [m].
    n_i, n_s : (N, 3) arrays
        Unit directions transmitter -> facet, facet -> receiver [-].
    sigma_h : float
        Rms height of the surface [m].
    slope_cov : (2, 2) array
        Covariance of the surface slopes (dz/dx, dz/dy) [-].

    Returns
    -------
    s_tx, s_rx, s_joint : (N,) arrays
        Not shadowed from the transmitter, not masked from the receiver, both [-]: eq T3
        for each ray, eq T5 (independent rays, exponent Lambda_tx + Lambda_rx) for the
        joint probability, or eq T6 (exponent max) where the two rays share an azimuth
        (monostatic).

    References
    ----------
    Smith (1967); Bourlier, Berginc & Saillard (2002): see
    :mod:`seaecho.geometry.shadowing`.
    """
    f = height_cdf(height, sigma_h)  # (T2)
    lams = []
    azimuths = []
    for d in (-n_i, n_s):  # directions from the facet to the transmitter / receiver
        theta = np.arccos(np.clip(d[:, 2], -1.0, 1.0))
        az = np.arctan2(d[:, 1], d[:, 0])
        below = theta > np.pi / 2  # source below the mean plane: always shadowed
        sigma = directional_slope_std(slope_cov, az)
        lam = smith_lambda(smith_nu(np.minimum(theta, np.pi / 2), sigma))  # (T1)
        lams.append(np.where(below, np.inf, lam))
        azimuths.append(az)
    lam_tx, lam_rx = lams
    same = np.abs(np.angle(np.exp(1j * (azimuths[0] - azimuths[1])))) < 1e-9
    lam_joint = np.where(same, np.maximum(lam_tx, lam_rx), lam_tx + lam_rx)  # (T6) / (T5)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = [np.where(lam == 0.0, 1.0, np.where(np.isinf(lam), 0.0, f ** lam))  # (T3)
               for lam in (lam_tx, lam_rx, lam_joint)]
    return out[0], out[1], out[2]


def subfacet_shadowing(facets: Facets, mss_upwind: float, mss_crosswind: float,
                       wind_direction: float) -> np.ndarray:
    """Smith's bistatic shadowing of the unresolved (sub-facet) slopes, per facet [-].

    The factor, averaged over the sub-facet heights and without facing test (the
    specular points and Bragg waves that scatter face both ends by construction),

    .. math:: S = \\frac{1}{1 + \\Lambda(\\nu_i) + \\Lambda(\\nu_s)}
              \\quad\\text{or}\\quad \\frac{1}{1 + \\max(\\Lambda_i, \\Lambda_s)}
              \\ \\text{(backscatter, } \\phi = \\pi)                 \\qquad (T7)

    with ``nu = cot(theta) / (sqrt(2) sigma)`` at the *local* angles theta_i, theta_s and
    sigma the sub-facet rms slope along each ray's horizontal azimuth, from the wind-aligned
    slope variances (eqs T1, T5-T6 averaged over heights).

    Parameters
    ----------
    facets : Facets
        Facets with local angles and directions.
    mss_upwind, mss_crosswind : float
        Sub-facet slope variances along / across the wind [-] (``ocean.twoscale``).
    wind_direction : float
        Direction the wind blows towards, CCW from +x [rad].

    Returns
    -------
    (N,) array
        In [0, 1]; 0 where the transmitter or the receiver is behind the facet.

    References
    ----------
    M. I. Sancer (1969); Bourlier, Berginc & Saillard (2002): see
    :mod:`seaecho.geometry.shadowing`.
    """
    if not (mss_upwind > 0 and mss_crosswind > 0):
        raise ValueError(f"mss_upwind = {mss_upwind}, mss_crosswind = {mss_crosswind}: "
                         "sub-facet slope variances must be > 0 [-]")
    cw, sw = np.cos(wind_direction), np.sin(wind_direction)
    cov = np.array([[mss_upwind * cw * cw + mss_crosswind * sw * sw,
                     (mss_upwind - mss_crosswind) * cw * sw],
                    [(mss_upwind - mss_crosswind) * cw * sw,
                     mss_upwind * sw * sw + mss_crosswind * cw * cw]])
    lams = []
    for theta, d in ((facets.theta_i, -facets.n_i), (facets.theta_s, facets.n_s)):
        sigma = directional_slope_std(cov, np.arctan2(d[:, 1], d[:, 0]))
        behind = theta >= np.pi / 2
        lam = smith_lambda(smith_nu(np.where(behind, np.pi / 2, theta), sigma))  # (T1)
        lams.append(np.where(behind, np.inf, lam))
    back = np.abs(np.abs(facets.phi) - np.pi) < _BACKSCATTER_TOL
    lam = np.where(back, np.maximum(lams[0], lams[1]), lams[0] + lams[1])
    return 1.0 / (1.0 + lam)  # (T7)


def analytic_facets(x: np.ndarray, y: np.ndarray, elevation: np.ndarray,
                    slope_x: np.ndarray, slope_y: np.ndarray, velocity: np.ndarray | None,
                    tx: np.ndarray, rx: np.ndarray | None = None, *,
                    shadowing: Literal["none", "smith"] = "smith", time_s: float = 0.0,
                    sigma_h: float | None = None, slope_cov: np.ndarray | None = None,
                    frames: Callable[..., dict] | None = None) -> Facets:
    """Facets of the analytic mode: normals from analytic slopes, no ray tracing.

    The facets are the triangles of :mod:`seaecho.geometry.mesh` (same centroids, areas
    and velocities as the ray-traced mode); the normal of a facet is
    ``(-zx, -zy, 1) / sqrt(1 + zx^2 + zy^2)`` with (zx, zy) the mean of the analytic slopes
    at its three vertices. Visibility: the facing tests (``-n_i . N > 0`` and
    ``n_s . N > 0``) times, with ``shadowing="smith"``, Smith's probability of not being
    shadowed given the facet's height (:func:`smith_weights`).

    Parameters
    ----------
    x : (nx,) array
        Node abscissae [m].
    y : (ny,) array
        Node ordinates [m].
    elevation, slope_x, slope_y : (ny, nx) arrays
        Surface elevation [m] and analytic slopes dz/dx, dz/dy [-].
    velocity : (ny, nx, 3) array or None
        Surface velocity at the nodes [m/s] (None: zero).
    tx : (3,) array
        Transmitter position [m].
    rx : (3,) array, optional
        Receiver position [m]; None for monostatic.
    shadowing : {"smith", "none"}
        Statistical shadowing weight, or facing test only.
    time_s : float
        Time of this surface [s] (recorded in the result).
    sigma_h : float, optional
        Rms height [m] for Smith's function; default the sample rms of ``elevation``
        about its mean.
    slope_cov : (2, 2) array, optional
        Slope covariance [-]; default the sample covariance of (slope_x, slope_y).
    frames : callable, optional
        Replacement for :func:`facet_frames` with the same signature and outputs (the
        tracing stage passes its Dr.Jit kernel).

    Returns
    -------
    Facets
    """
    if shadowing not in ("none", "smith"):
        raise ValueError(f"shadowing = {shadowing!r}: allowed 'none', 'smith'")
    tx = np.asarray(tx, dtype=np.float64)
    rx = tx if rx is None else np.asarray(rx, dtype=np.float64)
    vertices = grid_vertices(x, y, elevation)
    centroid, area, _ = facet_geometry(vertices)
    zx = to_facets(np.asarray(slope_x, dtype=np.float64))
    zy = to_facets(np.asarray(slope_y, dtype=np.float64))
    normal = np.stack([-zx, -zy, np.ones_like(zx)], axis=-1)
    normal /= np.sqrt(1.0 + zx * zx + zy * zy)[:, None]
    vel = (np.zeros_like(centroid) if velocity is None
           else to_facets(np.asarray(velocity, dtype=np.float64)))
    geo = (facet_frames if frames is None else frames)(centroid, normal, tx, rx)
    lit = (geo["theta_i"] < np.pi / 2).astype(np.float64)  # facing the transmitter
    seen = (geo["theta_s"] < np.pi / 2).astype(np.float64)  # facing the receiver
    joint = lit * seen
    if shadowing == "smith":
        z = np.asarray(elevation, dtype=np.float64)
        mean = float(z.mean())
        if sigma_h is None:
            sigma_h = float(z.std())
        if slope_cov is None:
            slope_cov = np.cov(np.stack([np.ravel(slope_x), np.ravel(slope_y)]))
        if sigma_h > 0 and np.all(np.diag(slope_cov) > 0):
            s_tx, s_rx, s_joint = smith_weights(centroid[:, 2] - mean, geo["n_i"], geo["n_s"],
                                                sigma_h, slope_cov)
            lit, seen, joint = lit * s_tx, seen * s_rx, joint * s_joint
    ny1, nx1 = len(y) - 1, len(x) - 1
    return Facets(mode="analytic", time_s=float(time_s), visibility_time_s=float(time_s),
                  grid_shape=(ny1, nx1, 2), centroid=centroid, area=area, normal=normal,
                  velocity=vel, lit=lit, seen=seen, visibility=joint, **geo)
