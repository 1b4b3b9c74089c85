"""Kirchhoff / small-perturbation blend of the paper (eqs 10-11), after Thorsos & Jackson.

.. math::
    \\sigma_{nn} = (1 - w_1)\\sigma_{nn,SP} + w_1\\sigma_{nn,K}, \\qquad
    \\sigma_{nm} = (1 - w_2)\\sigma_{nm,SP} + w_2\\sigma_{nm,K} \\qquad \\text{(B1, B2)}

.. math::
    \\log_{10} w_1(\\beta) = -\\left(\\frac{\\beta}{6\\pi}\\right)^8, \\qquad
    \\log_{10} w_2(\\beta) = -\\left(\\frac{\\beta}{20\\pi}\\right)^{1.5} \\qquad \\text{(B3, B4)}

``beta`` is the angle between the (local) surface normal and ``q = k (n_s - n_i)``, **in
degrees** (``docs/scattering.md``): ``w1 = 0.1`` at ``beta = 6 pi = 18.85 deg``, the
paper's "Kirchhoff valid within +-20 deg of specular"; ``w2 = 0.1`` at
``beta = 20 pi = 62.8 deg``. Co-polarised channels (HH, VV) use ``w1``, cross-polarised
(HV, VH) ``w2``.

References
----------
.. [1] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper"), eqs 10-11 (section III-C).
.. [2] Thorsos, E. I. and Jackson, D. R. (1989). The validity of the perturbation
   approximation for rough surface scattering using a Gaussian roughness spectrum.
   *J. Acoust. Soc. Am.* 86(1), 261-277.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Mat2

#: Channels that are co-polarised, in the order HH, HV, VH, VV.
CO_POLARISED = np.array([True, False, False, True])

_LN10 = math.log(10.0)


def blend_weights(beta_deg: ArrayLike, *, xp=None) -> tuple[NDArray, NDArray]:
    """Kirchhoff weights ``w1`` (co-pol) and ``w2`` (cross-pol) of eqs B3-B4 [-].

    Parameters
    ----------
    beta_deg : array_like
        Angle between the surface normal and ``q`` [deg], >= 0.
    xp : array namespace, optional
        Namespace of ``beta_deg`` (:mod:`seaecho.backend`), numpy by default; the facet
        kernels call this same formula on Dr.Jit arrays.

    Returns
    -------
    w1, w2 : arrays
        In (0, 1]; 1 at specular.

    References
    ----------
    .. [1] Paper eqs 10-11.
    """
    if xp is None:
        xp = NUMPY
        beta_deg = np.asarray(beta_deg, dtype=float)
    b = xp.abs(beta_deg)
    # Eq B3: log10 w1 = -(beta / 6 pi)^8
    w1 = xp.exp(-_LN10 * (b * (1.0 / (6.0 * math.pi))) ** 8)
    # Eq B4: log10 w2 = -(beta / 20 pi)^1.5
    w2 = xp.exp(-_LN10 * (b * (1.0 / (20.0 * math.pi))) ** 1.5)
    return w1, w2


def kirchhoff_weights(xp, beta_deg: Any) -> Mat2:
    """Kirchhoff weight of each channel (eqs B1-B2): ``w1`` on HH, VV and ``w2`` on HV, VH."""
    w1, w2 = blend_weights(beta_deg, xp=xp)
    return Mat2(w1, w2, w2, w1)


def channel_weights(beta_deg: ArrayLike) -> NDArray:
    """Kirchhoff weight per channel, shape (..., 4), HH, HV, VH, VV (eqs B1-B4)."""
    w = kirchhoff_weights(NUMPY, np.asarray(beta_deg, dtype=float))
    return np.stack(np.broadcast_arrays(*w.flat()), axis=-1)


def blend(sigma_spm: ArrayLike, sigma_kirchhoff: ArrayLike, beta_deg: ArrayLike) -> NDArray:
    """Apply eqs B1-B2 channel by channel.

    Parameters
    ----------
    sigma_spm, sigma_kirchhoff : array_like, shape (..., 4)
        Scattering coefficients of both models [m^2/m^2], HH, HV, VH, VV.
    beta_deg : array_like, shape (...)
        Angle between normal and ``q`` [deg].

    Returns
    -------
    ndarray, shape (..., 4)

    References
    ----------
    .. [1] Paper eqs 10-11.
    """
    w = channel_weights(beta_deg)
    return (1.0 - w) * np.asarray(sigma_spm) + w * np.asarray(sigma_kirchhoff)


__all__ = ["CO_POLARISED", "blend", "blend_weights", "channel_weights", "kirchhoff_weights"]
