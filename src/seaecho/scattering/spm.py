"""First-order small perturbation model (SPM), bistatic and fully polarimetric.

Paper eqs 8-9 with the spectrum convention of this project: the *height* spectrum ``W``
[m^4] of the frozen surface, centro-symmetric, normalised so that its integral over
``dkx dky`` is the height variance ``<z^2>`` (``DirectionalSpectrum.height_spectrum``).
With this normalisation

.. math::
    \\sigma_{mn} = 16\\pi k^4 \\cos^2\\theta_i \\cos^2\\theta_s\\, |\\alpha_{mn}|^2\\,
    W(\\mathbf k'), \\qquad
    \\mathbf k' = k(\\sin\\theta_s\\cos\\phi_s - \\sin\\theta_i\\cos\\phi_i,\\;
                    \\sin\\theta_s\\sin\\phi_s - \\sin\\theta_i\\sin\\phi_i)
    \\qquad \\text{(S1, S2)}

The paper's eq 8 writes ``8 k^4`` for the roughness spectrum of Ulaby, Moore and Fung
(1982), which is ``(2 pi)^-1`` times the Fourier transform of the correlation
coefficient and so integrates to ``2 pi`` (times ``<z^2>`` when the height variance is
factored out): ``8 x 2 pi = 16 pi`` for ``W``. At backscatter eq S1 is the standard
Bragg formula ``sigma0 = 16 pi k^4 cos^4 theta |g|^2 W(2 k sin theta, 0)`` for a spectrum
normalised to ``<z^2>``. ``docs/scattering.md`` derives the prefactor for a perfectly
conducting surface from the boundary condition, and a test checks it against an
independent first-order solution.

The polarimetric coefficients ``alpha_mn`` (m scattered, n incident, forward scattering
alignment of :mod:`.frames`, ``phi = phi_s - phi_i``, ``r = sqrt(eps - sin^2 theta)``):

.. math::
    \\alpha_{hh} &= \\frac{(\\varepsilon-1)\\cos\\phi}
                   {(\\cos\\theta_i + r_i)(\\cos\\theta_s + r_s)}\\\\
    \\alpha_{hv} &= \\frac{(\\varepsilon-1)\\, r_i \\sin\\phi}
                   {(\\varepsilon\\cos\\theta_i + r_i)(\\cos\\theta_s + r_s)}\\\\
    \\alpha_{vh} &= \\frac{(\\varepsilon-1)\\, r_s \\sin\\phi}
                   {(\\cos\\theta_i + r_i)(\\varepsilon\\cos\\theta_s + r_s)}\\\\
    \\alpha_{vv} &= \\frac{(\\varepsilon-1)(\\varepsilon\\sin\\theta_i\\sin\\theta_s
                   - r_i r_s\\cos\\phi)}{(\\varepsilon\\cos\\theta_i + r_i)
                   (\\varepsilon\\cos\\theta_s + r_s)} \\qquad \\text{(S3-S6)}

(Tsang, Kong and Ding 2000, sec. 5.2 in their notation; Khenchaf 2001, sec. 2; Ulaby,
Moore and Fung 1982, sec. 12-3). ``tests/scattering/test_spm.py`` checks them, complex
values and relative signs included, against an independent numerical first-order
boundary-value solution (dielectric) and the perfect-conductor expansion.

References
----------
.. [1] Rice, S. O. (1951). Reflection of electromagnetic waves from slightly rough
   surfaces. *Commun. Pure Appl. Math.* 4, 351-378.
.. [2] Valenzuela, G. R. (1978). Theories for the interaction of electromagnetic and
   oceanic waves - a review. *Boundary-Layer Meteorol.* 13, 61-85.
.. [3] Ulaby, F. T., Moore, R. K. and Fung, A. K. (1982). *Microwave Remote Sensing*,
   Vol. II, sec. 12-3.
.. [4] Tsang, L., Kong, J. A. and Ding, K.-H. (2000). *Scattering of Electromagnetic
   Waves: Theories and Applications*, Wiley, ch. 5.
.. [5] Khenchaf, A. (2001). Bistatic scattering and depolarization by randomly rough
   surfaces: application to the natural rough surfaces in X-band. *Waves Random Media*
   11(2), 61-89.
.. [6] Plant, W. J. (1990). Bragg scattering of electromagnetic waves from the air/sea
   interface. In *Surface Waves and Fluxes*, Vol. II, Kluwer, 41-108.
.. [7] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary, Mat2
from ..geometry import frames

#: Height spectrum callable: ``W(kx, ky) -> [m^4]`` for world-frame wavenumbers [rad/m].
HeightSpectrum = Callable[[NDArray, NDArray], NDArray]

#: Below this local cosine the transmitter (receiver) is behind the plane: no Bragg echo.
_BEHIND = 1e-12


# ------------------------------------------------------------- formulas (any namespace)
def alpha(xp, cos_i: Any, sin_i: Any, cos_s: Any, sin_s: Any, cos_phi: Any, sin_phi: Any,
          eps_r: Any) -> Mat2:
    r"""Bistatic first-order SPM polarimetric coefficients ``alpha_mn`` (eqs S3-S6).

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    cos_i, sin_i, cos_s, sin_s : real arrays
        Cosines and sines of the local incidence and scattering angles [-].
    cos_phi, sin_phi : real arrays
        Cosine and sine of ``phi = phi_s - phi_i`` [-].
    eps_r : complex
        Relative permittivity ``eps' - j eps''`` [-].

    Returns
    -------
    Mat2 of complex
        ``[[alpha_hh, alpha_hv], [alpha_vh, alpha_vv]]`` (m received, n transmitted) [-].

    References
    ----------
    .. [1] Tsang, Kong and Ding (2000), sec. 5.2; Khenchaf (2001), sec. 2.
    """
    return _alpha(xp, cos_i, sin_i * sin_i, cos_s, sin_s * sin_s, sin_i * sin_s, cos_phi,
                  sin_phi, eps_r)


def _alpha(xp, cos_i: Any, sin2_i: Any, cos_s: Any, sin2_s: Any, sin_is: Any, cos_phi: Any,
           sin_phi: Any, eps_r: Any) -> Mat2:
    """Eqs S3-S6 (:func:`alpha`) from ``sin^2 theta_i``, ``sin^2 theta_s`` and
    ``sin theta_i sin theta_s`` [-].

    The four denominators are products of ``d^h_i = cos_i + r_i``, ``d^v_i = eps cos_i +
    r_i`` and their scattered twins; their inverses come from one complex reciprocal of
    ``D = d^h_i d^v_i d^h_s d^v_s`` (``1 / (d^h_i d^h_s) = d^v_i d^v_s / D``, ...), the
    same quantities with one division instead of four. ``|D|`` lies between 80 and 4e6 for
    sea and fresh water from 1 to 100 GHz at -2 to 30 deg C (eq W1 of
    :mod:`seaecho.ocean.seawater`, every local angle): its squared modulus, which the
    reciprocal forms, stays far inside float32's range.
    """
    r_i = xp.sqrt(eps_r - sin2_i)
    r_s = xp.sqrt(eps_r - sin2_s)
    dh_i = cos_i + r_i
    dh_s = cos_s + r_s
    dv_i = eps_r * cos_i + r_i
    dv_s = eps_r * cos_s + r_s
    e = (eps_r - 1.0) * (1.0 / ((dh_i * dv_i) * (dh_s * dv_s)))  # (eps - 1) / D
    return Mat2(
        cos_phi * (dv_i * dv_s * e),  # Eq S3: HH
        r_i * sin_phi * (dh_i * dv_s * e),  # Eq S4: HV (receive h, transmit v)
        r_s * sin_phi * (dv_i * dh_s * e),  # Eq S5: VH (receive v, transmit h)
        (eps_r * sin_is - r_i * r_s * cos_phi) * (dh_i * dh_s * e),  # Eq S6: VV
    )


def bragg_matrix(xp, k: Any, eps_r: Any, cos_i: Any, cos_s: Any, cos_phi: Any,
                 sin_phi: Any, a_i: Mat2 | None = None, a_s: Mat2 | None = None,
                 roughness: Any = 1.0) -> Mat2:
    r"""Bragg amplitude matrix of a (tilted) plane in the global bases (eq S7).

    .. math::
        \mathsf B = 4\sqrt{\pi}\, k^2 \cos\theta_i'\cos\theta_s'\;
        \mathsf A_s^T \boldsymbol\alpha' \mathsf A_i, \qquad
        \sigma_{mn} = |B_{mn}|^2\, W(\mathbf k'_\perp) \qquad \text{(S7)}

    with the local angles (primes) of :func:`seaecho.geometry.frames.local_geometry`, the
    rotations ``A_i, A_s`` of eq F3 (omitted: the local bases are the global ones), and 0
    where the transmitter or the receiver is behind the plane. ``roughness`` multiplies
    the amplitude (``sqrt(W)`` [m^2] gives ``sigma = |B|^2`` directly).

    Returns
    -------
    Mat2 of complex
        [rad^2/m^2] (``roughness = 1``): ``sigma = |B|^2 W`` with ``W`` [m^4].

    References
    ----------
    .. [1] Khenchaf and Airiau (2000); Valenzuela (1968).
    """
    lit = (cos_i > _BEHIND) & (cos_s > _BEHIND)
    ci = xp.clip(cos_i, 0.0, 1.0)
    cs = xp.clip(cos_s, 0.0, 1.0)
    s2_i, s2_s = 1.0 - ci * ci, 1.0 - cs * cs  # sin^2 of the local angles
    a = _alpha(xp, ci, s2_i, cs, s2_s, xp.sqrt(s2_i * s2_s), cos_phi, sin_phi, eps_r)
    if a_i is not None:
        a = frames.global_matrix(a, a_i, a_s)  # eq F4
    # Eq S7 prefactor (eq S1 as an amplitude).
    return a * xp.select(lit, (4.0 * math.sqrt(math.pi)) * k * k * ci * cs * roughness, 0.0)


def bragg_vector(xp, n_i: Any, n_s: Any, N: Any, k: Any) -> tuple[Any, Any]:
    """Bragg wave vector of a (tilted) plane: horizontal components of ``q_t`` [rad/m].

    ``q_t = k ((n_s - n_i) - ((n_s - n_i) . N) N)``, the part of ``q`` tangent to the
    plane (eq S2; small-tilt approximation for the spectrum argument of eq S7).
    """
    d = n_s - n_i
    qt = (d - xp.dot(d, N) * N) * k
    return qt.x, qt.y


def azimuth_cos_sin(xp, x_s: Any, y_s: Any) -> tuple[Any, Any]:
    """``cos phi, sin phi`` of the local azimuth ``phi = atan2(y_s, x_s)`` [-]."""
    inv = 1.0 / xp.sqrt(x_s * x_s + y_s * y_s)
    return x_s * inv, y_s * inv


# ---------------------------------------------------------------------- numpy API
def spm_alpha(theta_i: ArrayLike, theta_s: ArrayLike, phi: ArrayLike,
              eps_r: ArrayLike) -> NDArray:
    """Bistatic first-order SPM polarimetric coefficients ``alpha_mn`` (eqs S3-S6).

    Parameters
    ----------
    theta_i, theta_s : array_like
        Incidence and scattering angles from the (local) normal [rad], in [0, pi/2].
    phi : array_like
        ``phi_s - phi_i`` [rad].
    eps_r : array_like of complex
        Relative permittivity ``eps' - j eps''`` [-].

    Returns
    -------
    ndarray of complex, shape (..., 2, 2)
        ``[[alpha_hh, alpha_hv], [alpha_vh, alpha_vv]]`` (m received, n transmitted).
        Formula: :func:`alpha`.

    References
    ----------
    .. [1] Tsang, Kong and Ding (2000), sec. 5.2; Khenchaf (2001), sec. 2.
    """
    ti = np.asarray(theta_i, dtype=float)
    ts = np.asarray(theta_s, dtype=float)
    ph = np.asarray(phi, dtype=float)
    eps = np.asarray(eps_r, dtype=complex)
    a = alpha(NUMPY, np.cos(ti), np.sin(ti), np.cos(ts), np.sin(ts), np.cos(ph), np.sin(ph),
              eps)
    return frames._np_mat(a.map(lambda c: np.asarray(c, dtype=complex)))


def spm_matrix(n_i: ArrayLike, n_s: ArrayLike, k: ArrayLike, eps_r: ArrayLike,
               normal: ArrayLike = frames.Z_HAT) -> tuple[NDArray, NDArray]:
    """Bragg amplitude matrix in the global bases and the Bragg wave vector (eq S7).

    For a (tilted) plane of normal ``normal`` the SPM is evaluated in the local frame
    (:func:`frames.local_angles`), then rotated into the global (+z) FSA bases with
    eq F4 (Valenzuela 1968; Khenchaf and Airiau 2000), :func:`bragg_matrix`; the Bragg
    vector ``k'_perp`` is the horizontal part of ``q`` tangent to the plane
    (:func:`bragg_vector`). Geometries with the transmitter or the receiver behind the
    plane give 0.

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    k : array_like
        Electromagnetic wavenumber [rad/m].
    eps_r : array_like of complex
        Relative permittivity [-].
    normal : array_like, shape (..., 3)
        Unit normal of the (local) plane [-].

    Returns
    -------
    b : ndarray of complex, shape (..., 2, 2)
        [rad^2/m^2], (h, v) order, global bases: ``sigma = |b|^2 W`` with ``W`` [m^4].
    k_bragg : ndarray, shape (..., 2)
        Bragg wave vector (kx, ky) [rad/m].

    References
    ----------
    .. [1] Khenchaf and Airiau (2000); Valenzuela (1968).
    """
    io = Boundary(NUMPY)
    vi, vs = io.vec3(n_i), io.vec3(n_s)
    nn_arr = np.asarray(normal, dtype=float)
    nn = io.vec3(nn_arr)
    z = io.vec3(frames.Z_HAT)
    k = np.asarray(k, dtype=float)
    eps = np.asarray(eps_r, dtype=complex)
    cos_i, cos_s, x_s, y_s = frames.local_geometry(NUMPY, vi, vs, nn)
    cos_phi, sin_phi = azimuth_cos_sin(NUMPY, x_s, y_s)
    rot = (None, None) if np.allclose(nn_arr, frames.Z_HAT) else frames.tilt(NUMPY, vi, vs,
                                                                             nn, z)
    b = bragg_matrix(NUMPY, k, eps, cos_i, cos_s, cos_phi, sin_phi, *rot)
    kx, ky = bragg_vector(NUMPY, vi, vs, nn, k)
    shape = np.broadcast_shapes(np.shape(n_i), np.shape(n_s), nn_arr.shape)[:-1]
    b = frames._np_mat(b.map(lambda c: np.broadcast_to(np.asarray(c, dtype=complex), shape)))
    return b, np.stack(np.broadcast_arrays(kx, ky), axis=-1)


def spm_sigma(theta_i: ArrayLike, phi_i: ArrayLike, theta_s: ArrayLike, phi_s: ArrayLike,
              k: ArrayLike, eps_r: ArrayLike, spectrum: HeightSpectrum) -> NDArray:
    """Mean-plane bistatic SPM scattering coefficients (paper eqs 8-9; eqs S1-S6).

    Parameters
    ----------
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad] (:func:`frames.directions_from_angles`).
    k : array_like
        Electromagnetic wavenumber [rad/m].
    eps_r : array_like of complex
        Sea-water permittivity [-].
    spectrum : callable
        Height spectrum ``W(kx, ky)`` [m^4], world frame, integral ``<z^2>``
        (``DirectionalSpectrum.height_spectrum``).

    Returns
    -------
    ndarray, shape (..., 4)
        ``sigma_mn`` [m^2/m^2] in the order HH, HV, VH, VV.

    References
    ----------
    .. [1] Paper eqs 8-9; Khenchaf (2001); Tsang, Kong and Ding (2000).
    """
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    b, kb = spm_matrix(n_i, n_s, k, eps_r)
    w = np.asarray(spectrum(kb[..., 0], kb[..., 1]), dtype=float)
    s = (b.real**2 + b.imag**2) * w[..., None, None]
    return s.reshape(s.shape[:-2] + (4,))


__all__ = ["HeightSpectrum", "alpha", "azimuth_cos_sin", "bragg_matrix", "bragg_vector",
           "spm_alpha", "spm_matrix", "spm_sigma"]
