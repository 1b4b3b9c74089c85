"""Dual co-polarised decomposition: the non-polarised part of a measured sea NRCS.

Eq BR1 (:mod:`seaecho.scattering.breaking`) writes the co-polarised NRCS of the sea as a
polarised part, the regular (Bragg and specular) surface, plus a non-polarised part, the
breaking zones, which is the same in HH and VV at backscatter (eq BR6):

.. math::
    \\sigma_{pp} = \\sigma^{R}_{pp} + NP,\\qquad NP = q\\,\\sigma_{wb},\\qquad
    \\sigma^{R}_{pp} = (1 - q)\\,\\sigma^{reg}_{pp}                              (CP1)

The polarisation difference carries the regular part only, and the regular part's own
polarisation ratio ``p = sigma^R_hh / sigma^R_vv`` is a property of the scattering
model (two-scale Bragg: a function of the incidence, the permittivity and the tilts), so
one pair of measured co-polarised values gives both parts: the decomposition of
Kudryavtsev, Chapron, Myasoedov, Collard & Johannessen (2013) into a polarised and a
non-polarised part (used again by Kudryavtsev et al. 2019); CP2-CP3 are the algebra of
CP1 (only the article's abstract and bibliographic record were read here, Ifremer
Archimer 00149/26042: they name its three quantities, the polarisation difference, the
polarisation ratio and the non-polarised component; its equation numbers are not
quoted):

.. math::
    PD = \\sigma_{vv} - \\sigma_{hh} = \\sigma^{R}_{vv}\\,(1 - p)                  (CP2)

    \\sigma^{R}_{vv} = \\frac{PD}{1 - p},\\qquad NP = \\sigma_{vv} - \\sigma^{R}_{vv}
    = \\frac{\\sigma_{hh} - p\\,\\sigma_{vv}}{1 - p}                              (CP3)

seaecho uses it to ask what non-polarised part a published pair of co-polarised levels
(Nathanson's tables, the GIT and NRL models) implies, given seaecho's own Bragg ratio,
and to compare that with KHCC03's ``q sigma_wb`` (``examples/xband_spectrum_comparison.py``,
docs/scattering.md). A pair whose VV/HH exceeds the Bragg ratio's inverse
(``sigma_hh < p sigma_vv``) has no non-negative NP: CP3 then returns the negative value,
which says that the pair is more polarised than the model's Bragg scattering.

Symbols -> names: sigma_vv, sigma_hh -> ``sigma_vv``, ``sigma_hh`` [m^2/m^2]; p ->
``bragg_ratio`` [-]; NP -> the first value returned; sigma^R_vv -> the second.

References
----------
.. [1] Kudryavtsev, V. N., Chapron, B., Myasoedov, A. G., Collard, F. and Johannessen,
   J. A. (2013). On dual co-polarized SAR measurements of the ocean surface. *IEEE
   Geosci. Remote Sens. Lett.* 10(4), 761-765, doi:10.1109/LGRS.2012.2222341.
.. [2] Kudryavtsev, V., Hauser, D., Caudal, G. and Chapron, B. (2003). A semiempirical
   model of the normalized radar cross-section of the sea surface, 1. Background model.
   *J. Geophys. Res.* 108(C3), 8054 (eq 1: the split of eq CP1).
.. [3] Kudryavtsev, V., Fan, S., Zhang, B., Mouche, A. and Chapron, B. (2019). On
   quad-polarized SAR measurements of the ocean surface. *IEEE Trans. Geosci. Remote
   Sens.* 57(11), 8362-8370.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def non_polarised_component(
    sigma_vv: ArrayLike, sigma_hh: ArrayLike, bragg_ratio: ArrayLike
) -> tuple[NDArray, NDArray]:
    """Non-polarised part ``NP`` and polarised VV part of a co-polarised pair (eq CP3).

    Parameters
    ----------
    sigma_vv, sigma_hh : array_like
        Co-polarised NRCS at backscatter [m^2/m^2] (linear, >= 0), broadcast together.
    bragg_ratio : array_like
        ``p = sigma^R_hh / sigma^R_vv`` of the polarised (regular-surface) scattering
        [-], in [0, 1): the HH/VV ratio of the Bragg model at the same geometry.

    Returns
    -------
    np_part : ndarray
        ``NP = (sigma_hh - p sigma_vv) / (1 - p)`` [m^2/m^2] (negative when the pair is
        more polarised than the Bragg ratio allows).
    regular_vv : ndarray
        ``sigma^R_vv = (sigma_vv - sigma_hh) / (1 - p)`` [m^2/m^2].

    Raises
    ------
    ValueError
        ``bragg_ratio`` outside [0, 1), or a negative or non-finite NRCS.

    References
    ----------
    .. [1] Kudryavtsev et al. (2013); module docstring (CP1-CP3).
    """
    vv = np.asarray(sigma_vv, dtype=float)
    hh = np.asarray(sigma_hh, dtype=float)
    p = np.asarray(bragg_ratio, dtype=float)
    for name, a in (("sigma_vv", vv), ("sigma_hh", hh)):
        if not np.all(np.isfinite(a) & (a >= 0.0)):
            raise ValueError(f"{name} = {a!r} m^2/m^2: must be finite and >= 0")
    if not np.all(np.isfinite(p) & (p >= 0.0) & (p < 1.0)):
        raise ValueError(f"bragg_ratio = {p!r}: must be in [0, 1) (HH/VV of Bragg scattering)")
    regular_vv = (vv - hh) / (1.0 - p)  # Eq CP2-CP3
    return vv - regular_vv, regular_vv  # Eq CP3


__all__ = ["non_polarised_component"]
