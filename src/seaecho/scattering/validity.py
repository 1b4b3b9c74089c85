"""Validity warnings of the scattering models (subclasses of ``ValidityWarning``).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from ..warnings import ValidityWarning


class SPMValidityWarning(ValidityWarning):
    """Small perturbation model used with roughness too large for the radar wavenumber.

    First-order SPM needs ``k h < 0.3`` for the rms height ``h`` of the roughness it
    describes (Ulaby, Moore and Fung 1982, Vol. II, sec. 12-3; Thorsos and Jackson 1989).
    """


class KirchhoffValidityWarning(ValidityWarning):
    """Kirchhoff / geometric optics used far from the specular direction.

    The stationary-phase (specular point) solution of eq 7 misses the diffuse (Bragg)
    part away from specular; the paper (sec. III-B) bounds its use to about +-20 deg of
    the specular direction.
    """


__all__ = ["KirchhoffValidityWarning", "SPMValidityWarning"]
