"""Resolution cells of a radar: slant range, ground range of a bistatic pair, azimuth of
a synthetic aperture.

- slant-range resolution (R1): ``delta_r = c / (2 B)`` for a waveform of bandwidth B
  (the main lobe of the compressed pulse; Skolnik 2008, ch. 8);
- ground-range resolution of a bistatic pair (R2): ``delta_g = c / (B |grad_h (r_t +
  r_r)|)``, the delay resolution 1 / B over the horizontal gradient of the bistatic range
  sum, ``grad (r_t + r_r) = -(u_t + u_r)`` with ``u`` the unit vectors from each platform
  towards the point; monostatic at grazing psi it is ``c / (2 B cos psi)``, in the
  bistatic plane ``c / (2 B cos(beta / 2))`` (Willis 2005, ch. 8; Cardillo 1990);
- azimuth resolution of a synthetic aperture (R3): ``delta_a = lambda R / (2 L)`` for an
  aperture of length L (the flight across the line of sight over the acquisition, or, if
  shorter, the beam's footprint ``lambda R / D`` of an antenna of length D, which gives
  D / 2 in stripmap; Cumming and Wong 2005, ch. 4).

References
----------
M. I. Skolnik, *Radar Handbook*, 3rd ed., McGraw-Hill, 2008.
N. J. Willis, *Bistatic Radar*, 2nd ed., SciTech, 2005.
G. P. Cardillo, "On the use of the gradient to determine bistatic SAR resolution",
*Antennas and Propagation Society International Symposium*, 1990, 1032-1035.
I. G. Cumming and F. H. Wong, *Digital Processing of Synthetic Aperture Radar Data*,
Artech House, 2005.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import C0

#: Below this horizontal gradient of the range sum [-] the pair has no ground resolution
#: (a point straight below a monostatic radar).
_FLAT_GRADIENT = 1e-9


def slant_range_resolution(bandwidth: float) -> float:
    """Slant-range resolution c / (2 B) [m] of a waveform of bandwidth B [Hz] (eq R1)."""
    return C0 / (2 * bandwidth)


def range_sum_gradient(u_tx: ArrayLike, u_rx: ArrayLike) -> NDArray[np.float64]:
    """Horizontal gradient of the bistatic range sum r_t + r_r at a point [-] (eq R2):
    ``-(u_t + u_r)`` projected on the ground, ``u_t``, ``u_r`` (3,) the unit vectors
    from the transmitter and the receiver towards the point. Shape (2,)."""
    grad = -(np.asarray(u_tx, dtype=np.float64) + np.asarray(u_rx, dtype=np.float64))
    return grad[:2]


def ground_range_resolution(bandwidth: float, u_tx: ArrayLike, u_rx: ArrayLike
                            ) -> tuple[float, NDArray[np.float64]] | None:
    """Ground-range resolution c / (B |grad_h (r_t + r_r)|) [m] of a bistatic pair and the
    ground direction it is measured along (unit (2,) vector) (eq R2), or None where the
    range sum has no horizontal gradient.

    Parameters
    ----------
    bandwidth : float
        Waveform bandwidth B [Hz].
    u_tx, u_rx : (3,) arrays
        Unit vectors from the transmitter and from the receiver towards the point [-]
        (the same vector twice for a monostatic radar).
    """
    grad = range_sum_gradient(u_tx, u_rx)
    gh = float(np.hypot(grad[0], grad[1]))
    if gh <= _FLAT_GRADIENT:
        return None
    return C0 / (bandwidth * gh), grad / gh


def synthetic_aperture(velocity: ArrayLike, line_of_sight: ArrayLike, duration: float
                       ) -> float:
    """Length L [m] of the synthetic aperture flown over ``duration`` [s] at ``velocity``
    (3,) [m/s]: the speed across the unit line of sight (3,) times the duration (eq R3)."""
    v = np.asarray(velocity, dtype=np.float64)
    los = np.asarray(line_of_sight, dtype=np.float64)
    return float(np.linalg.norm(v - np.dot(v, los) * los)) * duration


def footprint_length(wavelength: float, slant_range: float, antenna_length: float
                     ) -> float:
    """Azimuth footprint lambda R / D [m] of an antenna of length D [m] at range R [m]:
    the longest aperture that sees a point (eq R3, stripmap)."""
    return wavelength * slant_range / antenna_length


def azimuth_resolution(wavelength: float, slant_range: float, aperture: float) -> float:
    """Azimuth resolution lambda R / (2 L) [m] of a synthetic aperture of length L [m] at
    range R [m] and wavelength lambda [m] (eq R3)."""
    return wavelength * slant_range / (2 * aperture)


__all__ = ["azimuth_resolution", "footprint_length", "ground_range_resolution",
           "range_sum_gradient", "slant_range_resolution", "synthetic_aperture"]
