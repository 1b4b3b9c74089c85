"""The sea as a mirror for a hull's echo: image method over the mean sea plane.

A wave reaching a hull may have bounced on the sea first, and its echo may bounce on the
sea on its way to the receiver. Over a mean sea plane ``z = z0`` these legs are straight
lines from the *images* of the transmitter and the receiver, ``T' = (x, y, 2 z0 - z)``
(:func:`mirror`), crossing the plane at the specular point (:func:`plane_crossing`). At
that point the field is multiplied, in the forward-scattering-alignment bases of the
incident and reflected directions (:mod:`seaecho.geometry.frames`, normal +z), by

.. math::
    \\Gamma_{h,v}(\\psi) = R_{h,v}(\\sin\\psi)\\,\\rho_s(\\psi) \\qquad \\text{(M1)}

with ``R_h``, ``R_v`` the Fresnel coefficients of sea water at the local incidence angle
``pi/2 - psi`` (:func:`seaecho.scattering.fresnel.fresnel_coefficients`; permittivity
from :mod:`seaecho.ocean.seawater`) and ``rho_s`` the specular (coherent) reduction
factor of a rough sea of rms height ``sigma_h`` at grazing angle ``psi``
(:func:`specular_reduction`), with ``g = k sigma_h sin psi``:

.. math::
    \\rho_s = \\exp(-2 g^2) \\quad\\text{(Ament 1953)}, \\qquad
    \\rho_s = \\exp(-2 g^2)\\, I_0(2 g^2) \\quad
    \\text{(Miller, Brown and Vegh 1984)} \\qquad \\text{(M2)}

The second accounts for the non-Gaussian (sinusoid-like) distribution of sea heights and
is the one Blake (1986) recommends for the sea; both tend to 1 at grazing incidence.
What is approximated: the reflection is that of the *mean* plane (the coherent field);
the diffuse (incoherent) forward scatter of the rough sea, the curvature of the Earth
and the shadowing of the specular region by the waves are not modelled.

References
----------
.. [1] Ament, W. S. (1953). Toward a theory of reflection by a rough surface. *Proc.
   IRE* 41(1), 142-146.
.. [2] Miller, A. R., Brown, R. M. and Vegh, E. (1984). New derivation for the
   rough-surface reflection coefficient and for the distribution of sea-wave
   elevations. *IEE Proc. H* 131(2), 114-116.
.. [3] Blake, L. V. (1986). *Radar Range-Performance Analysis*, Artech House, ch. 6
   (pattern-propagation factor over the sea).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..scattering.fresnel import fresnel_coefficients

__all__ = ["ROUGHNESS_MODELS", "mirror", "plane_crossing", "sea_reflection",
           "specular_reduction"]

#: Rough-surface specular reduction factors (eq M2).
ROUGHNESS_MODELS = ("miller-brown-vegh", "ament", "none")


def specular_reduction(grazing: ArrayLike, sigma_h: float, k: float,
                       model: str = "miller-brown-vegh") -> NDArray[np.float64]:
    """Coherent reflection factor of a rough sea ``rho_s`` (eq M2).

    Parameters
    ----------
    grazing : array_like
        Grazing angle psi at the specular point [rad], in [0, pi/2].
    sigma_h : float
        Rms height of the sea surface [m].
    k : float
        Electromagnetic wavenumber 2 pi / lambda [rad/m].
    model : {'miller-brown-vegh', 'ament', 'none'}
        Eq M2's second form (default), its first, or 1 (a smooth sea).

    Returns
    -------
    ndarray
        rho_s in [0, 1] [-].

    References
    ----------
    .. [1] Ament (1953); Miller, Brown and Vegh (1984); Blake (1986), ch. 6.
    """
    if model not in ROUGHNESS_MODELS:
        raise ValueError(f"model = {model!r}: allowed {', '.join(ROUGHNESS_MODELS)}")
    if not (np.isfinite(sigma_h) and sigma_h >= 0):
        raise ValueError(f"sigma_h = {sigma_h}: must be >= 0 [m]")
    psi = np.asarray(grazing, dtype=np.float64)
    if model == "none":
        return np.ones_like(psi)
    g2 = (k * sigma_h * np.sin(psi)) ** 2
    if model == "ament":
        return np.exp(-2.0 * g2)
    from scipy.special import i0e

    # exp(-2 g^2) I0(2 g^2) = i0e(2 g^2), finite for any g
    return i0e(2.0 * g2)


def sea_reflection(grazing: ArrayLike, eps_r: complex, sigma_h: float, k: float,
                   model: str = "miller-brown-vegh") -> tuple[NDArray, NDArray]:
    """Specular reflection coefficients of the rough sea ``Gamma_h, Gamma_v`` (eq M1).

    Parameters
    ----------
    grazing : array_like
        Grazing angle at the specular point [rad].
    eps_r : complex
        Sea-water relative permittivity ``eps' - j eps''`` [-].
    sigma_h : float
        Rms sea height [m].
    k : float
        Wavenumber [rad/m].
    model : str
        Roughness factor (:func:`specular_reduction`).

    Returns
    -------
    gamma_h, gamma_v : complex ndarrays
        In the FSA bases (normal +z) of the incident and reflected directions [-].
    """
    psi = np.asarray(grazing, dtype=np.float64)
    r_h, r_v = fresnel_coefficients(np.sin(psi), eps_r)
    rho = specular_reduction(psi, sigma_h, k, model)
    return r_h * rho, r_v * rho


def mirror(points: ArrayLike, z0: float = 0.0) -> NDArray[np.float64]:
    """Image of points (..., 3) in the plane ``z = z0`` [m]."""
    p = np.array(points, dtype=np.float64)
    p[..., 2] = 2.0 * z0 - p[..., 2]
    return p


def plane_crossing(origin: ArrayLike, direction: ArrayLike, z0: float = 0.0
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Where rays ``origin + t direction`` cross the plane ``z = z0``.

    Parameters
    ----------
    origin, direction : array_like (..., 3)
        Ray origins [m] and unit directions [-].
    z0 : float
        Plane height [m].

    Returns
    -------
    point : ndarray (..., 3)
        Crossing points [m] (NaN where the ray is parallel to the plane).
    t : ndarray
        Distances along the rays [m] (negative: behind the origin).
    """
    o = np.asarray(origin, dtype=np.float64)
    d = np.asarray(direction, dtype=np.float64)
    dz = d[..., 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(dz != 0.0, (z0 - o[..., 2]) / dz, np.nan)
    return o + t[..., None] * d, t
