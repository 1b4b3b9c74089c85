"""The ship that makes the wake: hull dimensions and a straight, constant-speed track.

Frames
------
World frame: x east, y north, z up (docs/conventions.md). The ship sails towards the azimuth
``heading`` (counter-clockwise from +x) at speed ``V``; its hull centre (midship) is at

.. math::

    \\mathbf{p}(t) = \\mathbf{p}_0 + V t\\,(\\cos h, \\sin h)                     (W1)

Ship frame (used by the wake theory, :mod:`seaecho.wake.kelvin`): origin at midship,
``x'`` along the track pointing *behind* the ship (downstream in the ship's frame, where
the water streams past at speed V in +x'), ``y'`` completing a right-handed frame with z up:

.. math::

    x' = -(\\mathbf{r} - \\mathbf{p}(t))\\cdot\\hat{\\mathbf{h}}, \\qquad
    y' = -(\\mathbf{r} - \\mathbf{p}(t))\\cdot\\hat{\\mathbf{n}}, \\qquad
    \\hat{\\mathbf{h}} = (\\cos h, \\sin h),\\;
    \\hat{\\mathbf{n}} = (-\\sin h, \\cos h).                                  (W2)

The bow is at x' = -L/2 and the stern at x' = +L/2.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import G
from .film import DEFAULT_WAKE_FILM_ELASTICITY

#: Default length of the turbulent wake strip, in ship lengths (a modelling choice,
#: docs/wake.md).
DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS = 20.0
#: Kelvin-wake height models: empirical (Kriebel & Seelig 2005) or Michell's theory.
WAKE_AMPLITUDE_MODELS = ("kriebel-seelig", "michell")


@dataclass(frozen=True)
class Ship:
    """A ship sailing in a straight line at constant speed (eq W1).

    Parameters
    ----------
    length : float
        Waterline length L [m], > 0.
    beam : float
        Beam B [m], 0 < B < L.
    draft : float
        Draft T [m], > 0.
    speed : float
        Speed through the water V [m/s], >= 0.
    heading : float
        Course the ship sails towards, counter-clockwise from +x (east) [rad].
    position0 : tuple of float
        (x, y) of the hull centre (midship) at t = 0 [m].
    turbulent_wake_length : float or None
        Length of the turbulent (damped) wake strip behind the stern [m]; None for the
        default of 20 ship lengths.
    wake_amplitude : {"kriebel-seelig", "michell"}
        Heights of the Kelvin wake (:class:`seaecho.wake.KelvinWake`).
    wake_breaking_limit : bool
        Cap the Kelvin wake's waves at the breaking steepness.
    turbulent_wake_film_contrast_db : float or None
        Persistent Bragg contrast of the wake's surfactant film C_f [dB] (<= 0; eq W15),
        overriding the Marangoni model; None (default) takes C_f from the film's
        elasticity at ``bragg_wavenumber`` (eqs W16, W17).
    turbulent_wake_film_elasticity : float
        Dilational modulus of the wake's surfactant film E [N/m] (>= 0; eq W16).
    bragg_wavenumber : float or None
        The radar's Bragg wavenumber k_B at the scene [rad/m] (>= 0), at which the film's
        contrast is evaluated (eq W17); set by :mod:`seaecho.build` from the scene's
        carrier and geometry. None (no radar): without an override, the wake's damping
        is the turbulent part alone.
    """

    length: float
    beam: float
    draft: float
    speed: float
    heading: float = 0.0
    position0: tuple[float, float] = (0.0, 0.0)
    turbulent_wake_length: float | None = None
    wake_amplitude: str = "kriebel-seelig"
    wake_breaking_limit: bool = True
    turbulent_wake_film_contrast_db: float | None = None
    turbulent_wake_film_elasticity: float = DEFAULT_WAKE_FILM_ELASTICITY
    bragg_wavenumber: float | None = None
    _p0: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for name in ("length", "beam", "draft"):
            value = getattr(self, name)
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"Ship.{name} = {value!r} m: must be a finite number > 0")
        if self.beam >= self.length:
            raise ValueError(
                f"Ship.beam = {self.beam!r} m must be smaller than Ship.length = {self.length!r} m"
            )
        if not np.isfinite(self.speed) or self.speed < 0.0:
            raise ValueError(f"Ship.speed = {self.speed!r} m/s: must be a finite number >= 0")
        if not np.isfinite(self.heading):
            raise ValueError(f"Ship.heading = {self.heading!r} rad: must be finite")
        p0 = np.asarray(self.position0, dtype=np.float64)
        if p0.shape != (2,) or not np.all(np.isfinite(p0)):
            raise ValueError(f"Ship.position0 = {self.position0!r}: must be two finite numbers [m]")
        if self.turbulent_wake_length is not None and not (
            np.isfinite(self.turbulent_wake_length) and self.turbulent_wake_length >= 0.0
        ):
            raise ValueError(
                f"Ship.turbulent_wake_length = {self.turbulent_wake_length!r} m: must be >= 0"
            )
        if self.wake_amplitude not in WAKE_AMPLITUDE_MODELS:
            raise ValueError(f"Ship.wake_amplitude = {self.wake_amplitude!r}: choose from "
                             f"{WAKE_AMPLITUDE_MODELS}")
        c_f = self.turbulent_wake_film_contrast_db
        if c_f is not None and not (np.isfinite(c_f) and c_f <= 0.0):
            raise ValueError(f"Ship.turbulent_wake_film_contrast_db = {c_f!r} dB: must be "
                             "<= 0 (or None for the Marangoni film model)")
        e = self.turbulent_wake_film_elasticity
        if not (np.isfinite(e) and e >= 0.0):
            raise ValueError(f"Ship.turbulent_wake_film_elasticity = {e!r} N/m: must be a "
                             "finite number >= 0")
        k_b = self.bragg_wavenumber
        if k_b is not None and not (np.isfinite(k_b) and k_b >= 0.0):
            raise ValueError(f"Ship.bragg_wavenumber = {k_b!r} rad/m: must be >= 0 (or None)")
        object.__setattr__(self, "position0", (float(p0[0]), float(p0[1])))
        object.__setattr__(self, "_p0", p0)

    @property
    def direction(self) -> NDArray[np.float64]:
        """Unit vector of the heading, h_hat = (cos h, sin h) [-], shape (2,)."""
        return np.array([np.cos(self.heading), np.sin(self.heading)])

    @property
    def velocity(self) -> NDArray[np.float64]:
        """Velocity over ground V h_hat [m/s], shape (2,) (eq W1)."""
        return self.speed * self.direction

    def position(self, t: float) -> NDArray[np.float64]:
        """Hull centre at time ``t`` [s]: p0 + V t h_hat [m], shape (2,) (eq W1)."""
        return self._p0 + self.velocity * float(t)

    @property
    def froude_number(self) -> float:
        """Length Froude number Fn = V / sqrt(g L) [-]."""
        return self.speed / np.sqrt(G * self.length)

    @property
    def wake_length(self) -> float:
        """Length of the turbulent wake strip behind the stern [m] (default 20 L)."""
        if self.turbulent_wake_length is None:
            return DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS * self.length
        return self.turbulent_wake_length

    def to_ship_frame(
        self, x: ArrayLike, y: ArrayLike, t: float
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """World coordinates -> ship-frame coordinates (x', y') (eq W2).

        Parameters
        ----------
        x, y : array_like
            World coordinates [m], broadcast together.
        t : float
            Time [s].

        Returns
        -------
        xs, ys : ndarray
            Distance behind midship along the track, and the transverse coordinate [m].
        """
        p = self.position(t)
        dx = np.asarray(x, dtype=np.float64) - p[0]
        dy = np.asarray(y, dtype=np.float64) - p[1]
        c, s = np.cos(self.heading), np.sin(self.heading)
        xs = -(dx * c + dy * s)
        ys = -(-dx * s + dy * c)
        return xs, ys


__all__ = ["DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS", "WAKE_AMPLITUDE_MODELS", "Ship"]
