"""seaecho.wake: the ship's Kelvin wake and turbulent wake strip (paper section IV-B).

- :class:`Ship`: hull dimensions and a straight constant-speed track (eq W1), or a
  :class:`~seaecho.wake.ship.Route` of legs and turns (eq W18).
- :class:`KelvinWake`: deterministic Kelvin wake from Michell's thin-ship theory
  (Wigley hull fitted to L, B, T), elevation, slopes and dz/dt at any time (eqs W4-W12).
- :func:`turbulent_wake_mask`: the damped strip behind the stern (eqs W13-W15), with the
  Marangoni damping of the wake's surfactant film (:mod:`seaecho.wake.film`, eqs W16-W17).
- :func:`narrow_v_bragg_gain`: the narrow-V wake, Bragg-scale divergent waves that raise
  the Bragg spectrum in two arms of a few degrees (:mod:`seaecho.wake.narrow_v`, N1-N7).

Theory and sources: ``docs/wake.md``.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from .film import (
    DEFAULT_WAKE_FILM_ELASTICITY,
    NU_SEA_WATER,
    film_contrast_db,
    marangoni_damping_ratio,
)
from .kelvin import KELVIN_HALF_ANGLE, KelvinWake, WakeFields, kelvin_crest_lines
from .michell import (
    havelock_wave_resistance,
    submerged_source_amplitude,
    wigley_amplitude,
    wigley_wave_resistance,
    wigley_wetted_surface,
)
from .narrow_v import narrow_v_amplitude, narrow_v_bragg_gain, narrow_v_half_angle
from .ship import Ship
from .turbulent import (
    turbulent_damping_profile,
    turbulent_wake_film_contrast_db,
    turbulent_wake_mask,
    turbulent_wake_strip,
    turbulent_wake_width,
)

__all__ = [
    "DEFAULT_WAKE_FILM_ELASTICITY",
    "KELVIN_HALF_ANGLE",
    "NU_SEA_WATER",
    "KelvinWake",
    "Ship",
    "WakeFields",
    "film_contrast_db",
    "havelock_wave_resistance",
    "kelvin_crest_lines",
    "marangoni_damping_ratio",
    "narrow_v_amplitude",
    "narrow_v_bragg_gain",
    "narrow_v_half_angle",
    "submerged_source_amplitude",
    "turbulent_damping_profile",
    "turbulent_wake_film_contrast_db",
    "turbulent_wake_mask",
    "turbulent_wake_strip",
    "turbulent_wake_width",
    "wigley_amplitude",
    "wigley_wave_resistance",
    "wigley_wetted_surface",
]
