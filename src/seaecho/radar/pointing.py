"""How an antenna's axes follow its platform: fixed mounting, a tracked point, or a scan.

A look-at antenna is aimed at a reference time from the platform's nominal track and then
stays fixed to its platform (stripmap: the platform's attitude errors move the beam),
unless it keeps the point on its boresight at every pulse (spotlight). An antenna pointed
by angles is fixed in the body frame (x forward, y left, z up): boresight azimuth
counter-clockwise from body x, depression below the body horizontal plane.

A scanning antenna (:class:`Scan`) turns about the body z axis (the platform's deck
normal), as a marine radar's pedestal does: its boresight azimuth, counter-clockwise
from body x, is

.. math::

    \\alpha(t) = \\alpha_0 - \\Omega t \\quad\\text{(rotating)},\\qquad
    \\alpha(t) = \\alpha_1 - \\Omega\\,\\mathrm{tri}(t) \\quad\\text{(sector)}          (S1)

with Omega = 2 pi rpm / 60 [rad/s] and t the time since t = 0 of the scene (not since
the first pulse): the antenna turns clockwise seen from above (the azimuth decreases
counter-clockwise, i.e. the bearing clockwise from north increases), as marine radars
turn. A sector scan sweeps
clockwise from alpha_1 to alpha_2 (a width W = (alpha_1 - alpha_2) mod 2 pi) and back:
tri(t) = s for s = Omega t mod 2W / Omega below W / Omega, else 2 W / Omega - s (the
boresight angle turned from alpha_1). Its depression below the body horizontal plane is
fixed; the platform's attitude (roll, pitch, yaw, Gauss-Markov errors) then turns the
whole pedestal at every pulse: axes_world = R(t) axes_body(alpha(t)). A sweep is one
revolution (rotating: sweep k covers Omega t in [2 pi k, 2 pi (k + 1))) or one pass of a
sector (sector: Omega t in [k W, (k + 1) W)); the scan period is 2 pi / Omega (rotating)
or 2 W / Omega (sector: the time between two passes of the same direction in the same
sense).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .antennas import antenna_axes
from .platforms import Platform, PlatformState


@dataclass(frozen=True)
class Scan:
    """A scanning antenna's motion about the body z axis, eq (S1).

    Attributes
    ----------
    mode : {'rotating', 'sector'}
    rate : float
        Angular rate Omega [rad/s], > 0 (clockwise seen from above).
    depression : float
        Boresight depression below the body horizontal plane [rad].
    start : float
        Boresight azimuth at t = 0, counter-clockwise from body x [rad] (rotating;
        the sector's alpha_1 for a sector scan).
    width : float
        Sector width W [rad] (sector), in (0, 2 pi].
    """

    mode: str
    rate: float
    depression: float
    start: float = 0.0
    width: float = 2.0 * np.pi

    def __post_init__(self) -> None:
        if self.mode not in ("rotating", "sector"):
            raise ValueError(f"mode = {self.mode!r}: allowed 'rotating', 'sector'")
        if not self.rate > 0:
            raise ValueError(f"rate = {self.rate} rad/s: must be > 0")
        if not 0 < self.width <= 2.0 * np.pi:
            raise ValueError(f"width = {self.width} rad: must be in (0, 2 pi]")

    @classmethod
    def sector(cls, rate: float, depression: float, from_: float, to: float) -> Scan:
        """Sector scan clockwise from azimuth ``from_`` to ``to`` [rad] (counter-clockwise
        from body x) and back."""
        width = float(np.mod(from_ - to, 2.0 * np.pi)) or 2.0 * np.pi
        return cls("sector", rate, depression, float(from_), width)

    @property
    def period(self) -> float:
        """Scan period [s]: one revolution 2 pi / Omega, or a sector's 2 W / Omega."""
        return (2.0 * np.pi if self.mode == "rotating" else 2.0 * self.width) / self.rate

    def turned(self, t: ArrayLike) -> NDArray[np.float64]:
        """Angle the boresight has turned clockwise from its azimuth at t = 0 [rad]
        (rotating: Omega t; sector: Omega tri(t), in [0, W])."""
        s = self.rate * np.asarray(t, dtype=float)
        if self.mode == "rotating":
            return s
        s = np.mod(s, 2.0 * self.width)
        return np.where(s < self.width, s, 2.0 * self.width - s)

    def azimuth(self, t: ArrayLike) -> NDArray[np.float64]:
        """Boresight azimuth alpha(t), counter-clockwise from body x, in (-pi, pi] [rad],
        eq (S1)."""
        a = self.start - self.turned(t)
        return np.angle(np.exp(1j * a))

    def sweep(self, t: ArrayLike) -> NDArray[np.int64]:
        """Index of the sweep at times t [s] (a revolution, or one pass of a sector)."""
        s = self.rate * np.asarray(t, dtype=float)
        span = 2.0 * np.pi if self.mode == "rotating" else self.width
        # a pulse within 1e-9 of a turn of a sweep's start opens it (rounding of rate t)
        return np.floor(s / span + 1.0e-9).astype(np.int64)

    def axes_body(self, t: ArrayLike) -> NDArray[np.float64]:
        """Antenna axes in the body frame at times t: (..., 3, 3), columns boresight,
        width, height."""
        a = self.azimuth(t)
        c = np.cos(self.depression)
        b = np.stack([c * np.cos(a), c * np.sin(a),
                      np.full(np.shape(a), -np.sin(self.depression))], axis=-1)
        return antenna_axes(b, np.array([0.0, 0.0, 1.0]))


@dataclass(frozen=True)
class Pointing:
    """How an antenna's axes follow its platform.

    Attributes
    ----------
    axes_body : ndarray (3, 3) or None
        Antenna axes in the body frame (fixed mounting).
    look_at : ndarray (3,) or None
        World point kept on the boresight at every pulse (spotlight).
    scan : Scan or None
        A scanning antenna (rotating or sector, eq S1).
    """

    axes_body: NDArray[np.float64] | None = None
    look_at: NDArray[np.float64] | None = None
    scan: Scan | None = None

    @property
    def scan_period(self) -> float | None:
        """The scan period [s] (:attr:`Scan.period`), None for an antenna that does not
        scan."""
        return None if self.scan is None else self.scan.period

    @classmethod
    def aimed_at(cls, target: ArrayLike, platform: Platform, t_ref: float,
                 track: bool = False) -> Pointing:
        """Boresight on a world point [m]: aimed at time ``t_ref`` [s] from the nominal
        track and then fixed to the platform, or kept on the point (``track``)."""
        target = np.asarray(target, dtype=float).reshape(3)
        if track:
            return cls(look_at=target)
        nominal = platform.nominal_state(t_ref)
        r = nominal.rotation
        axes_world = antenna_axes(target - nominal.position, r[:, 2])
        return cls(axes_body=r.T @ axes_world)

    @classmethod
    def by_angles(cls, azimuth: float, depression: float) -> Pointing:
        """Boresight fixed in the body frame: azimuth from body x, depression below the
        body horizontal plane [rad]."""
        b = np.array([np.cos(depression) * np.cos(azimuth),
                      np.cos(depression) * np.sin(azimuth), -np.sin(depression)])
        return cls(axes_body=antenna_axes(b, np.array([0.0, 0.0, 1.0])))

    def axes(self, state: PlatformState, t: ArrayLike | None = None
             ) -> NDArray[np.float64]:
        """Antenna axes in the world (columns boresight, width, height) for the states
        at times ``t`` [s] (needed by a scan; shape ``state``'s leading shape)."""
        if self.scan is not None:
            if t is None:
                raise ValueError("a scanning antenna's axes need the time t")
            return state.rotation @ self.scan.axes_body(t)
        if self.look_at is not None:
            return antenna_axes(self.look_at - state.position, state.rotation[..., :, 2])
        return state.rotation @ self.axes_body


__all__ = ["Pointing", "Scan"]
