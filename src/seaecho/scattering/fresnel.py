"""Fresnel reflection coefficients of a flat interface with a lossy medium.

Time convention ``exp(+j omega t)``: ``eps_r = eps' - j eps''``. The square root
``sqrt(eps_r - sin^2 theta)`` is taken on numpy's principal branch, whose imaginary part is
then <= 0: the transmitted wave decays away from the interface.

References
----------
.. [1] Born, M. and Wolf, E. (1999). *Principles of Optics*, 7th ed., sec. 1.5.2.
.. [2] Ulaby, F. T. and Long, D. G. (2014). *Microwave Radar and Radiometric Remote
   Sensing*, sec. 2-8 (eqs 2.113-2.114, with the same sign conventions as here).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY


def reflection(xp, cos_theta: Any, eps_r: Any) -> tuple[Any, Any]:
    r"""Fresnel reflection coefficients ``R_h`` (TE) and ``R_v`` (TM), any namespace.

    .. math::
        R_h = \frac{\cos\theta - \sqrt{\varepsilon_r - \sin^2\theta}}
                   {\cos\theta + \sqrt{\varepsilon_r - \sin^2\theta}}, \qquad
        R_v = \frac{\varepsilon_r\cos\theta - \sqrt{\varepsilon_r - \sin^2\theta}}
                   {\varepsilon_r\cos\theta + \sqrt{\varepsilon_r - \sin^2\theta}}
        \qquad \text{(R1, R2)}

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    cos_theta : real array
        Cosine of the local incidence angle [-], clipped here to [0, 1].
    eps_r : complex array or constant
        Relative permittivity ``eps' - j eps''`` [-].

    Returns
    -------
    r_h, r_v : complex arrays [-]

    References
    ----------
    .. [1] Born and Wolf (1999), eqs 1.5.(21a), (21b) (with ``n^2 = eps_r``).
    """
    c = xp.clip(cos_theta, 0.0, 1.0)
    # Transmitted normal wavenumber over k, decaying branch (principal square root).
    root = xp.sqrt(eps_r - (1.0 - c * c))
    # Eq R1 (TE, horizontal); the denominators vanish only for eps_r = 1 at grazing
    # incidence (no interface), where R = 0.
    den_h = c + root
    zh = xp.abs2(den_h) < xp.tiny
    r_h = xp.select(zh, 0.0, (c - root) / xp.select(zh, 1.0, den_h))
    # Eq R2 (TM, vertical).
    den_v = eps_r * c + root
    zv = xp.abs2(den_v) < xp.tiny
    r_v = xp.select(zv, 0.0, (eps_r * c - root) / xp.select(zv, 1.0, den_v))
    return r_h, r_v


def fresnel_coefficients(cos_theta: ArrayLike, eps_r: ArrayLike) -> tuple[NDArray, NDArray]:
    """Fresnel reflection coefficients ``R_h`` (TE) and ``R_v`` (TM) (eqs R1, R2).

    In the forward scattering alignment bases of :mod:`seaecho.geometry.frames` (in
    (h, v) order) the field reflected by a flat facet is ``diag(R_h, R_v)`` times the
    incident field: at normal incidence on a perfect conductor ``R_h = -1``, ``R_v = +1``.
    Formula: :func:`reflection`.

    Parameters
    ----------
    cos_theta : array_like
        Cosine of the local incidence angle [-], clipped to [0, 1] (grazing gives
        ``R = -1`` for both).
    eps_r : array_like of complex
        Relative permittivity ``eps' - j eps''`` [-].

    Returns
    -------
    r_h, r_v : ndarray of complex

    References
    ----------
    .. [1] Born and Wolf (1999), eqs 1.5.(21a), (21b) (with ``n^2 = eps_r``).
    """
    c = np.asarray(cos_theta, dtype=float)
    eps = np.asarray(eps_r, dtype=complex)
    r_h, r_v = reflection(NUMPY, c, eps)
    return np.asarray(r_h, dtype=complex), np.asarray(r_v, dtype=complex)


__all__ = ["fresnel_coefficients", "reflection"]
