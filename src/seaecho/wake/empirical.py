"""Empirical ship-wave heights and the breaking limit of wave steepness.

Thin-ship (Michell) theory gives the shape of the Kelvin pattern exactly but not the
heights of the waves of real hulls: it assumes a slender hull (it overpredicts for beamy
ones, B/L = 0.4 for the paper's boat) and the Wigley form's sharp waterline corners feed
short divergent waves of undiminished amplitude. Two published results bring the heights
back to what is measured:

**Kriebel & Seelig (2005)**, an empirical model fitted to the maximum wave heights of 16
data sets (model tests and full-scale ships), at lateral distance ``y`` from the sailing
line:

.. math::
    \\frac{g H_m}{V^2} = \\beta\\,(F^* - 0.1)^2 \\left(\\frac{y}{L}\\right)^{-1/3},\\quad
    \\beta = 1 + 8\\tanh^3\\!\\left[0.45\\left(\\frac{L}{L_e} - 2\\right)\\right],\\quad
    F^* = F \\exp\\left(\\alpha\\frac{T}{h}\\right)                                 (E1)

``F = V / sqrt(g L)`` the length Froude number, ``L_e`` the length of the bow entrance
(``beta = 1`` for fine bows, up to 9 for blunt ones), ``alpha = 2.35 (1 - C_B)`` with the
block coefficient ``C_B``, ``T`` the draft, ``h`` the depth (deep water: ``F* = F``). The
data cover ``0.1 <= F* <= 0.5`` and ``beta (F* - 0.1)^2 <= 0.4``. The ``y^(-1/3)`` decay is
that of the cusp waves (Havelock 1908). For the Wigley hull of the wake model the entrance
is half the length (``beta = 1``) and ``C_B = 4/9``.

**Limiting steepness** of a deep-water wave: crest-to-trough height over wavelength
``H / lambda <= 0.1412`` (Williams 1981; Michell 1893 gave 0.142), i.e. a linear wave of
amplitude ``a`` breaks once ``a k > pi 0.1412 = 0.4436`` (E2).

References
----------
.. [1] Kriebel, D. L. and Seelig, W. N. (2005). An empirical model for ship-generated
   waves. *Proc. 5th Int. Symp. Ocean Wave Measurement and Analysis (WAVES 2005)*,
   Madrid.
.. [2] Havelock, T. H. (1908). The propagation of groups of waves in dispersive media,
   with application to waves on water produced by a travelling disturbance. *Proc. R.
   Soc. A* 81, 398-430.
.. [3] Michell, J. H. (1893). The highest waves in water. *Phil. Mag.* 36, 430-437.
.. [4] Williams, J. M. (1981). Limiting gravity waves in water of finite depth. *Phil.
   Trans. R. Soc. A* 302, 139-188.
.. [5] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import G

#: Limiting steepness H / lambda of a deep-water Stokes wave [-] (Williams 1981).
STOKES_LIMIT_STEEPNESS = 0.1412
#: Slope a k of a linear wave at the limiting steepness, pi * 0.1412 [-] (eq E2).
BREAKING_SLOPE = np.pi * STOKES_LIMIT_STEEPNESS
#: Block coefficient of the Wigley hull (parabolic waterlines and sections) [-].
WIGLEY_BLOCK_COEFFICIENT = 4.0 / 9.0
#: Range of the modified Froude number covered by the data of Kriebel & Seelig (2005).
KRIEBEL_SEELIG_FROUDE_RANGE = (0.1, 0.5)


def kriebel_seelig_height(
    length: float,
    speed: float,
    y: ArrayLike,
    entrance_ratio: float = 2.0,
    block_coefficient: float = WIGLEY_BLOCK_COEFFICIENT,
    draft: float = 0.0,
    depth: float = np.inf,
    g: float = G,
) -> NDArray:
    """Maximum ship-wave height ``H_m`` at lateral distance ``y`` (eq E1) [m].

    Parameters
    ----------
    length : float
        Waterline length L [m].
    speed : float
        Ship speed V [m/s].
    y : array_like
        Distance from the sailing line [m], > 0.
    entrance_ratio : float
        ``L / L_e`` (2 for the Wigley hull) [-].
    block_coefficient : float
        ``C_B`` [-].
    draft : float
        T [m] (used with a finite ``depth`` only).
    depth : float
        Water depth h [m]; ``inf`` for deep water.
    g : float
        Gravity [m/s^2].

    Returns
    -------
    ndarray
        H_m [m]; 0 where ``F* <= 0.1`` (below the model's threshold of wave making).

    References
    ----------
    .. [1] Kriebel & Seelig (2005).
    """
    y = np.asarray(y, dtype=float)
    if np.any(y <= 0.0):
        raise ValueError("y: distances from the sailing line must be > 0 m")
    f = speed / np.sqrt(g * length)
    alpha = 2.35 * (1.0 - block_coefficient)
    f_star = f * np.exp(alpha * draft / depth) if np.isfinite(depth) else f
    beta = 1.0 + 8.0 * np.tanh(0.45 * (entrance_ratio - 2.0)) ** 3
    # Eq E1.
    bf = beta * np.maximum(f_star - 0.1, 0.0) ** 2
    return bf * (y / length) ** (-1.0 / 3.0) * speed**2 / g


__all__ = ["BREAKING_SLOPE", "KRIEBEL_SEELIG_FROUDE_RANGE", "STOKES_LIMIT_STEEPNESS",
           "WIGLEY_BLOCK_COEFFICIENT", "kriebel_seelig_height"]
