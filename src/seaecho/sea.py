"""The sea of a scene: a random wind sea plus the ship's wake, at any time.

This joins the ocean stage (:mod:`seaecho.ocean`) and the wake stage
(:mod:`seaecho.wake`); :func:`seaecho.build.build_sea` makes the sea of a scene. Later
stages (tracing, radar) take its :class:`SurfaceState` arrays.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .ocean.spectra import DirectionalSpectrum
from .ocean.surface import SeaSurface


@dataclass(frozen=True)
class SurfaceState:
    """Sea + wake on the grid at one time. Arrays shaped (ny, nx) unless stated."""

    t: float  #: time [s]
    x: NDArray[np.float64]  #: x coordinates (nx,) [m]
    y: NDArray[np.float64]  #: y coordinates (ny,) [m]
    elevation: NDArray[np.float64]  #: z, sea + wake [m]
    slope_x: NDArray[np.float64]  #: dz/dx, sea + wake [-]
    slope_y: NDArray[np.float64]  #: dz/dy, sea + wake [-]
    velocity: NDArray[np.float64]  #: surface velocity (u, v, w), (ny, nx, 3) [m/s]
    wake_elevation: NDArray[np.float64]  #: the Kelvin wake's own height [m]
    wake_mask: NDArray[np.float64]  #: turbulent wake, 0 (none) .. 1 (short waves damped)


class Sea:
    """The sea of a scene: surface realisation (seeded) and optional ship wake.

    Parameters
    ----------
    surface : SeaSurface
        The wind sea.
    ship : seaecho.wake.Ship or None
        The ship whose wake is added.
    kelvin_wake : bool
        Add the Kelvin wake heights (else only the turbulent-wake mask).
    turbulent_wake_length : float or None
        Length of the turbulent wake [m] (None: the wake stage's default).
    """

    def __init__(self, surface: SeaSurface, ship=None, kelvin_wake: bool = True,
                 turbulent_wake_length: float | None = None) -> None:
        self.surface = surface
        self.ship = ship
        self.turbulent_wake_length = turbulent_wake_length
        self._wake = None
        if ship is not None and kelvin_wake:
            from .wake import KelvinWake

            self._wake = KelvinWake(ship)

    @property
    def spectrum(self) -> DirectionalSpectrum:
        return self.surface.spectrum

    @property
    def x(self) -> NDArray[np.float64]:
        return self.surface.x

    @property
    def y(self) -> NDArray[np.float64]:
        return self.surface.y

    def state(self, t: float = 0.0) -> SurfaceState:
        """Sea + wake at time ``t`` [s]."""
        f = self.surface.fields(t)
        shape = f.elevation.shape
        wake_z = np.zeros(shape)
        mask = np.zeros(shape)
        elevation, slope_x, slope_y = f.elevation, f.slope_x, f.slope_y
        velocity = f.velocity
        if self._wake is not None:
            w = self._wake.fields(self.x, self.y, t)
            wake_z = w.elevation
            elevation = elevation + w.elevation
            slope_x = slope_x + w.slope_x
            slope_y = slope_y + w.slope_y
            velocity = velocity.copy()
            velocity[..., 2] += w.dzdt
        if self.ship is not None:
            from .wake import turbulent_wake_mask

            mask = turbulent_wake_mask(self.ship, self.x, self.y, t,
                                       length=self.turbulent_wake_length)
        return SurfaceState(
            t=float(t), x=self.x, y=self.y, elevation=elevation, slope_x=slope_x,
            slope_y=slope_y, velocity=velocity, wake_elevation=wake_z,
            wake_mask=np.asarray(mask, dtype=np.float64),
        )


__all__ = ["Sea", "SurfaceState"]
