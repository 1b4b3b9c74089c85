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
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import frames

#: Height spectrum callable: ``W(kx, ky) -> [m^4]`` for world-frame wavenumbers [rad/m].
HeightSpectrum = Callable[[NDArray, NDArray], NDArray]


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

    References
    ----------
    .. [1] Tsang, Kong and Ding (2000), sec. 5.2; Khenchaf (2001), sec. 2.
    """
    ti = np.asarray(theta_i, dtype=float)
    ts = np.asarray(theta_s, dtype=float)
    ph = np.asarray(phi, dtype=float)
    eps = np.asarray(eps_r, dtype=complex)
    return _alpha(np.cos(ti), np.sin(ti), np.cos(ts), np.sin(ts), np.cos(ph), np.sin(ph), eps)


def _alpha(ci, si, cs, ss, cp, sp, eps) -> NDArray:
    ri = np.sqrt(eps - si * si)
    rs = np.sqrt(eps - ss * ss)
    em1 = eps - 1.0
    dhi = ci + ri
    dhs = cs + rs
    dvi = eps * ci + ri
    dvs = eps * cs + rs
    shape = np.broadcast_shapes(np.shape(ci), np.shape(cs), np.shape(cp), np.shape(eps))
    out = np.empty(shape + (2, 2), dtype=complex)
    # Eq S3: HH.
    out[..., 0, 0] = em1 * cp / (dhi * dhs)
    # Eq S4: HV (receive h, transmit v).
    out[..., 0, 1] = em1 * ri * sp / (dvi * dhs)
    # Eq S5: VH (receive v, transmit h).
    out[..., 1, 0] = em1 * rs * sp / (dhi * dvs)
    # Eq S6: VV.
    out[..., 1, 1] = em1 * (eps * si * ss - ri * rs * cp) / (dvi * dvs)
    return out


def spm_matrix(n_i: ArrayLike, n_s: ArrayLike, k: ArrayLike, eps_r: ArrayLike,
               normal: ArrayLike = frames.Z_HAT) -> tuple[NDArray, NDArray]:
    """Bragg amplitude matrix in the global bases and the Bragg wave vector.

    For a (tilted) plane of normal ``normal`` the SPM is evaluated in the local frame
    (:func:`frames.local_angles`), then rotated into the global (+z) FSA bases with
    eq F4 (Valenzuela 1968; Khenchaf and Airiau 2000):

    .. math::
        \\mathsf B = 4\\sqrt{\\pi}\\, k^2 \\cos\\theta_i'\\cos\\theta_s'\\;
        \\mathsf A_s^T \\boldsymbol\\alpha' \\mathsf A_i, \\qquad
        \\sigma_{mn} = |B_{mn}|^2\\, W(\\mathbf k'_\\perp) \\qquad \\text{(S7)}

    where primes are local quantities and ``k'_perp`` the horizontal components of the
    part of ``q = k (n_s - n_i)`` tangent to the plane (the Bragg vector of the tilted
    plane, small-tilt approximation for the spectrum argument). Geometries with the
    transmitter or the receiver behind the plane give 0.

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
    n_i = np.asarray(n_i, dtype=float)
    n_s = np.asarray(n_s, dtype=float)
    nn = np.broadcast_to(np.asarray(normal, dtype=float),
                         np.broadcast_shapes(n_i.shape, n_s.shape, np.shape(normal)))
    k = np.asarray(k, dtype=float)
    ti, ts, ph = frames.local_angles(n_i, n_s, nn)
    ci, cs = np.cos(ti), np.cos(ts)
    lit = (ci > 1e-12) & (cs > 1e-12)
    ci_c, cs_c = np.clip(ci, 0.0, 1.0), np.clip(cs, 0.0, 1.0)
    alpha = _alpha(ci_c, np.sin(ti), cs_c, np.sin(ts), np.cos(ph), np.sin(ph),
                   np.asarray(eps_r, dtype=complex))
    flat = np.allclose(nn, frames.Z_HAT)
    if not flat:
        a_i, a_s = frames.tilt_rotation(n_i, n_s, nn)
        alpha = frames.to_global(alpha, a_i, a_s)
    # Eq S7 prefactor (eq S1 as an amplitude).
    pref = np.where(lit, 4.0 * np.sqrt(np.pi) * k**2 * ci_c * cs_c, 0.0)
    b = pref[..., None, None] * alpha
    # Eq S2: Bragg vector = tangential part of q, its horizontal components.
    q = frames.scattering_vector(n_i, n_s, k)
    qt = q - np.einsum("...i,...i->...", q, nn)[..., None] * nn
    return b, qt[..., :2]


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


__all__ = ["HeightSpectrum", "spm_alpha", "spm_matrix", "spm_sigma"]
