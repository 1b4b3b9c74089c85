"""How an antenna's axes follow its platform: fixed mounting or a tracked point.

A look-at antenna is aimed at a reference time from the platform's nominal track and then
stays fixed to its platform (stripmap: the platform's attitude errors move the beam),
unless it keeps the point on its boresight at every pulse (spotlight). An antenna pointed
by angles is fixed in the body frame (x forward, y left, z up): boresight azimuth
counter-clockwise from body x, depression below the body horizontal plane.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .antennas import antenna_axes
from .platforms import Platform, PlatformState


@dataclass(frozen=True)
class Pointing:
    """How an antenna's axes follow its platform.

    Attributes
    ----------
    axes_body : ndarray (3, 3) or None
        Antenna axes in the body frame (fixed mounting).
    look_at : ndarray (3,) or None
        World point kept on the boresight at every pulse (spotlight).
    """

    axes_body: NDArray[np.float64] | None = None
    look_at: NDArray[np.float64] | None = None

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

    def axes(self, state: PlatformState) -> NDArray[np.float64]:
        """Antenna axes in the world (columns boresight, width, height) for one state."""
        if self.look_at is not None:
            return antenna_axes(self.look_at - state.position, state.rotation[..., :, 2])
        return state.rotation @ self.axes_body


__all__ = ["Pointing"]
