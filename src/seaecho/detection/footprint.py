"""The area of sea a range cell covers: the beam's half-power width and the pulse-limited
clutter cell, for false alarms per km^2 of range profiles.

A range profile's gate at slant range R of a monostatic radar, whose beam is theta_B
wide in azimuth (one-way half-power), covers on the sea the pulse-limited cell

.. math:: A_c = R\\,\\theta_B\\,\\Delta R\\,\\sec\\psi                              (F1)

(Skolnik 2001, section 7.1: the clutter area at low grazing, there with Delta R =
c tau / 2): the beam's arc R theta_B across, the range
extent Delta R projected on the sea along range. psi is the grazing angle at the cell:
sin psi = h / R on a flat Earth, eq (E1) of :mod:`seaecho.geometry.earth` on the 4/3 Earth
(the along-range derivative of the slant range on the sphere, dR/ds = cos psi, is the same
projection). It holds while the pulse, not the elevation beam, bounds the cell (R
theta_E / sin psi > Delta R sec psi: every low-grazing marine radar).

References
----------
Skolnik, M. I. (2001). *Introduction to Radar Systems*, 3rd ed. McGraw-Hill, section 7.1
(clutter cell area) and table 9.1 (half-power widths of line sources).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

__all__ = ["clutter_cell_area", "half_power_width"]


def half_power_width(gain: Callable[[NDArray], NDArray]) -> float:
    """Full width between the half-power points of a pattern in its azimuth plane [rad].

    Parameters
    ----------
    gain : callable
        ``d_local (..., 3) -> G`` in the antenna frame (x boresight, y along the width,
        z up), e.g. :meth:`seaecho.radar.antennas.Antenna.gain_local`.

    Returns
    -------
    float
        2 a_h, a_h the smallest angle off boresight in the x-y plane where G falls to half
        its boresight value (found on a grid, then by Brent's method); 2 pi for a pattern
        that never falls to half in azimuth (omnidirectional), taken symmetric.
    """
    def g(a):
        a = np.asarray(a, dtype=float)
        return np.asarray(gain(np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], -1)),
                          dtype=float)

    peak = float(g(0.0))
    if not peak > 0:
        raise ValueError(f"gain at boresight = {peak}: no beam to measure")
    a = np.linspace(0.0, np.pi, 200001)
    below = np.flatnonzero(g(a) < 0.5 * peak)
    if below.size == 0:
        return 2.0 * np.pi
    i = int(below[0])
    a_h = brentq(lambda x: float(g(x)) - 0.5 * peak, a[i - 1], a[i], xtol=1e-13)
    return 2.0 * a_h


def clutter_cell_area(slant_range_m: ArrayLike, range_extent_m: ArrayLike,
                      azimuth_width_rad: ArrayLike, grazing_rad: ArrayLike) -> NDArray:
    """Pulse-limited area of sea in a range cell, eq (F1) [m^2].

    Parameters
    ----------
    slant_range_m : array_like
        R, slant range of the cell [m].
    range_extent_m : array_like
        Delta R, the cell's extent in slant range [m] (c / (2 B) for a resolution cell,
        the gate spacing for a gate).
    azimuth_width_rad : array_like
        theta_B, one-way half-power azimuth width of the beam [rad].
    grazing_rad : array_like
        psi, grazing angle at the cell [rad] (:func:`seaecho.geometry.earth.grazing_angle`).

    Returns
    -------
    ndarray
        A_c [m^2]; NaN where psi is not in [0, pi/2) (no sea at that range: nearer than
        the radar's height, or beyond the horizon).

    References
    ----------
    Skolnik (2001), section 7.1.
    """
    r, dr, th, psi = (np.asarray(v, dtype=float) for v in
                      (slant_range_m, range_extent_m, azimuth_width_rad, grazing_rad))
    ok = (psi >= 0.0) & (psi < 0.5 * np.pi)
    # Eq (F1): the beam's arc across, the range extent on the sea along range
    with np.errstate(invalid="ignore", divide="ignore"):
        area = r * th * dr / np.cos(psi)
    return np.where(ok, area, np.nan)
