"""Platforms: position, velocity and attitude of a transmitter or receiver at any time.

A platform follows a nominal trajectory (fixed, straight line, or piecewise-linear
waypoints) with a nominal attitude; an optional first-order Gauss-Markov perturbation of
path and attitude, drawn from the scene's seed, gives the true track that drives the
simulation (paper section IV-C: "noise can eventually be introduced in the carrier's
dynamics"). The nominal track is kept beside it for the processing that comes later.

Frames (docs/conventions.md): world x east, y north, z up. Body frame x forward, y left,
z up. The attitude (yaw psi, pitch theta, roll phi) turns body vectors into world vectors:

.. math::

    R = R_z(\\psi) \\, R_y(-\\theta) \\, R_x(\\phi)                                    (P1)

yaw counter-clockwise from +x, pitch positive nose up, roll positive right wing down.

Everything is vectorised over time: ``state(t)`` takes any array of times.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] A. Gelb (ed.), *Applied Optimal Estimation*, MIT Press, 1974, section 3.8
   (first-order Gauss-Markov process).
.. [2] B. L. Stevens, F. L. Lewis, *Aircraft Control and Simulation*, 2nd ed., Wiley, 2003,
   section 1.3 (Euler angles, z-y-x rotation sequence).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..geometry.earth import SphericalEarth


@dataclass(frozen=True)
class PlatformState:
    """Kinematic state of a platform at times t (leading shape ``t.shape``).

    Attributes
    ----------
    position : ndarray (..., 3)
        Position in the world frame [m].
    velocity : ndarray (..., 3)
        Velocity in the world frame [m/s].
    attitude : ndarray (..., 3)
        (yaw, pitch, roll) [rad], conventions of eq (P1).
    rotation : ndarray (..., 3, 3)
        Body-to-world rotation matrix R of eq (P1): ``world = R @ body``.
    """

    position: NDArray[np.float64]
    velocity: NDArray[np.float64]
    attitude: NDArray[np.float64]
    rotation: NDArray[np.float64]


def rotation_matrix(yaw: ArrayLike, pitch: ArrayLike, roll: ArrayLike) -> NDArray[np.float64]:
    """Body-to-world rotation R = Rz(yaw) Ry(-pitch) Rx(roll), eq (P1).

    Parameters
    ----------
    yaw, pitch, roll : array_like
        Euler angles [rad] (broadcast together).

    Returns
    -------
    ndarray (..., 3, 3)
        Rotation matrices; ``R @ [1, 0, 0]`` is the body's forward axis in the world.

    References
    ----------
    Stevens & Lewis (2003), section 1.3, with a nose-up positive pitch in a z-up frame.
    """
    psi, theta, phi = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in
                                            (yaw, pitch, roll)))
    cy, sy = np.cos(psi), np.sin(psi)
    cp, sp = np.cos(theta), np.sin(theta)
    cr, sr = np.cos(phi), np.sin(phi)
    # Eq (P1) multiplied out: Rz(psi) @ Ry(-theta) @ Rx(phi)
    r = np.empty(psi.shape + (3, 3))
    r[..., 0, 0] = cy * cp
    r[..., 0, 1] = -sy * cr - cy * sp * sr
    r[..., 0, 2] = sy * sr - cy * sp * cr
    r[..., 1, 0] = sy * cp
    r[..., 1, 1] = cy * cr - sy * sp * sr
    r[..., 1, 2] = -cy * sr - sy * sp * cr
    r[..., 2, 0] = sp
    r[..., 2, 1] = cp * sr
    r[..., 2, 2] = cp * cr
    return r


def gauss_markov(n: int, sigma: ArrayLike, phi: float, rng: np.random.Generator
                 ) -> NDArray[np.float64]:
    """Samples of a stationary first-order Gauss-Markov process on a regular grid.

    x_0 ~ N(0, sigma^2) and x_{k+1} = phi x_k + sigma sqrt(1 - phi^2) w_k, w_k ~ N(0, 1),
    the exact discretisation of dx/dt = -x/tau + w(t) with phi = exp(-dt/tau)
    (Gelb 1974, section 3.8).

    Parameters
    ----------
    n : int
        Number of samples.
    sigma : array_like (m,)
        Stationary standard deviation of each of m independent components [any unit].
    phi : float
        One-step correlation exp(-dt / tau) [-], in [0, 1).
    rng : numpy.random.Generator
        Source of the draws.

    Returns
    -------
    ndarray (n, m)
    """
    from scipy.signal import lfilter

    sigma = np.atleast_1d(np.asarray(sigma, dtype=float))
    w = rng.standard_normal((n, sigma.size))
    # Start in the stationary law, then the AR(1) recursion (one IIR filter, no loop)
    w[0] *= 1.0 / np.sqrt(1.0 - phi**2)
    x = lfilter([np.sqrt(1.0 - phi**2)], [1.0, -phi], w, axis=0)
    return x * sigma


class Platform:
    """A transmitter or receiver platform: nominal trajectory plus optional perturbation.

    ``state(t)`` gives the true (perturbed) track, ``nominal_state(t)`` the planned one
    (:func:`seaecho.build.build_radar` makes the platforms of a scene).
    """

    def __init__(
        self,
        times: NDArray[np.float64],
        positions: NDArray[np.float64],
        *,
        yaw: float | None = None,
        pitch: float = 0.0,
        roll: float = 0.0,
        perturbation: tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]
        | None = None,
        earth: SphericalEarth | None = None,
    ) -> None:
        """Piecewise-linear nominal path through ``positions`` at ``times``.

        Parameters
        ----------
        times : ndarray (k,)
            Increasing knot times [s]; one knot means a fixed platform. Outside the knots
            the path is extrapolated along the first/last segment.
        positions : ndarray (k, 3)
            Positions at the knots [m].
        yaw : float or None
            Nominal yaw [rad]; None: along the horizontal velocity of each segment.
        pitch, roll : float
            Nominal pitch and roll [rad].
        perturbation : (t_grid (n,), dpos (n, 3) [m], datt (n, 3) [rad]) or None
            Path and attitude errors on a regular grid, linearly interpolated.
        earth : SphericalEarth or None
            A spherical Earth: the path above is in the scene's Earth-following
            coordinates (x, y along the surface, z height above it) and the states are
            returned in the Cartesian frame tangent at the origin
            (:class:`seaecho.geometry.earth.SphericalEarth`, eq E4): positions mapped,
            velocities and the body-to-world rotation turned by the local tilt; the
            attitude angles stay those relative to the local level. None: flat Earth.
        """
        times = np.asarray(times, dtype=float).reshape(-1)
        positions = np.asarray(positions, dtype=float).reshape(-1, 3)
        if times.size != positions.shape[0]:
            raise ValueError(f"{times.size} times but {positions.shape[0]} positions")
        if times.size > 1 and np.any(np.diff(times) <= 0):
            raise ValueError("times must increase strictly")
        self._t = times
        self._p = positions
        if times.size > 1:
            self._v = np.diff(positions, axis=0) / np.diff(times)[:, None]
        else:
            self._v = np.zeros((1, 3))
        self._yaw = yaw
        self._pitch = float(pitch)
        self._roll = float(roll)
        self._pert = perturbation
        self._earth = earth

    def _on_earth(self, st: PlatformState) -> PlatformState:
        """The state in the tangent frame of a spherical Earth (eq E4), or as it is."""
        if self._earth is None:
            return st
        tilt = self._earth.tilt(st.position)
        return PlatformState(self._earth.position(st.position),
                             np.einsum("...ij,...j->...i", tilt, st.velocity),
                             st.attitude, tilt @ st.rotation)

    # ------------------------------------------------------------------ nominal track
    def _segment(self, t: NDArray[np.float64]) -> NDArray[np.intp]:
        if self._t.size == 1:
            return np.zeros(t.shape, dtype=np.intp)
        return np.clip(np.searchsorted(self._t, t, side="right") - 1, 0, self._t.size - 2)

    def nominal_state(self, t: ArrayLike) -> PlatformState:
        """Nominal (planned) state at times ``t`` [s], any shape."""
        return self._on_earth(self._nominal(t))

    def _nominal(self, t: ArrayLike) -> PlatformState:
        t = np.asarray(t, dtype=float)
        k = self._segment(t)
        velocity = self._v[k]
        position = self._p[k] + velocity * (t - self._t[k])[..., None]
        if self._yaw is None:
            # Yaw along the horizontal velocity; 0 at rest
            speed_h = np.hypot(velocity[..., 0], velocity[..., 1])
            yaw = np.where(speed_h > 0, np.arctan2(velocity[..., 1], velocity[..., 0]), 0.0)
        else:
            yaw = np.full(t.shape, self._yaw)
        attitude = np.stack([yaw, np.full(t.shape, self._pitch),
                             np.full(t.shape, self._roll)], axis=-1)
        return PlatformState(position, velocity, attitude,
                             rotation_matrix(attitude[..., 0], attitude[..., 1],
                                             attitude[..., 2]))

    # --------------------------------------------------------------------- true track
    def state(self, t: ArrayLike) -> PlatformState:
        """True state at times ``t`` [s]: nominal plus the Gauss-Markov perturbation."""
        nominal = self._nominal(t)
        if self._pert is None:
            return self._on_earth(nominal)
        t = np.asarray(t, dtype=float)
        grid, dpos, datt = self._pert
        step = grid[1] - grid[0]
        u = np.clip((t - grid[0]) / step, 0.0, grid.size - 1.0)
        i = np.minimum(np.floor(u).astype(np.intp), grid.size - 2)
        f = (u - i)[..., None]
        # Linear interpolation of the errors; their velocity is the segment's slope
        inside = ((t >= grid[0]) & (t <= grid[-1]))[..., None]
        position = nominal.position + (1 - f) * dpos[i] + f * dpos[i + 1]
        velocity = nominal.velocity + np.where(inside, (dpos[i + 1] - dpos[i]) / step, 0.0)
        attitude = nominal.attitude + (1 - f) * datt[i] + f * datt[i + 1]
        rotation = rotation_matrix(attitude[..., 0], attitude[..., 1], attitude[..., 2])
        return self._on_earth(PlatformState(position, velocity, attitude, rotation))

    @property
    def is_perturbed(self) -> bool:
        """Whether the true track differs from the nominal one."""
        return self._pert is not None


def draw_perturbation(
    t_span: tuple[float, float], rng: np.random.Generator, *, step: float,
    position_sigma: ArrayLike, position_tau: float, attitude_sigma: ArrayLike,
    attitude_tau: float,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Path and attitude errors on a regular grid covering ``t_span`` (Gauss-Markov).

    Parameters
    ----------
    t_span : (float, float)
        Time interval to cover [s].
    rng : numpy.random.Generator
        Source of the draws (the scene's ``"platform"`` stream).
    step : float
        Grid step [s].
    position_sigma : array_like (3,)
        Stationary standard deviation of the path error along x, y, z [m].
    position_tau : float
        Correlation time of the path error [s].
    attitude_sigma : array_like (3,)
        Stationary standard deviation of the (yaw, pitch, roll) error [rad].
    attitude_tau : float
        Correlation time of the attitude error [s].

    Returns
    -------
    t_grid : ndarray (n,) [s]
    dpos : ndarray (n, 3) [m]
    datt : ndarray (n, 3) [rad] (yaw, pitch, roll)
    """
    t0, t1 = float(t_span[0]), float(t_span[1])
    n = int(np.ceil((t1 - t0) / step)) + 2
    if n > 50_000_000:
        raise ValueError(f"perturbation grid of {n} steps: the step {step} s is too small "
                         f"for a span of {t1 - t0} s (at most 5e7 steps)")
    t_grid = t0 + step * np.arange(n)
    dpos = gauss_markov(n, position_sigma, np.exp(-step / position_tau), rng)
    datt = gauss_markov(n, attitude_sigma, np.exp(-step / attitude_tau), rng)
    return t_grid, dpos, datt


__all__ = [
    "Platform",
    "PlatformState",
    "draw_perturbation",
    "gauss_markov",
    "rotation_matrix",
]
