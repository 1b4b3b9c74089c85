"""Two-scale model: first-order SPM averaged over the large-scale slopes (bistatic).

The surface is split at a wavenumber ``k_cut``: waves longer than ``k_cut`` tilt the
local mean plane (slopes ``Z`` with an anisotropic Gaussian density of variances
``mss_upwind``, ``mss_crosswind``), waves shorter carry the Bragg roughness with the
height spectrum ``W(K) 1[|K| > k_cut]``. Each tilted plane scatters as the SPM in its
local frame, rotated to the global bases (eq S7 with eqs F3-F4); the mean-plane
coefficient is the slope average

.. math::
    \\sigma^{TS}_{mn} = \\iint \\sigma^{SPM}_{mn}(\\hat n_i, \\hat n_s; \\hat N(Z))\\,
    \\sqrt{1 + Z_x^2 + Z_y^2}\\; P(Z_x, Z_y)\\, dZ_x dZ_y \\qquad \\text{(T1)}

with ``N(Z) = (-Z_x, -Z_y, 1) / sqrt(1 + Z^2)``. The factor ``sqrt(1 + Z^2)`` is the
facet area per unit horizontal area, so that T1 is the same sum over facets (``sigma x
facet area``) that the ray-traced and analytic facet modes make. Planes facing away from
the transmitter or the receiver contribute 0 (no shadowing by other waves). As the
slopes vanish, T1 tends to the mean-plane SPM (eq S1).

The integral is a tensor-product Gauss-Hermite quadrature in the wind frame.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] Khenchaf, A. and Airiau, O. (2000). Bistatic radar moving returns from sea
   surface. *IEICE Trans. Electron.* E83-C(12), 1827-1835.
.. [2] Valenzuela, G. R. (1968). Scattering of electromagnetic waves from a tilted
   slightly rough surface. *Radio Science* 3(11), 1057-1066.
.. [3] Khenchaf, A. (2001). *Waves Random Media* 11(2), 61-89, sec. 4.
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..geometry import frames
from ..ocean.twoscale import SPM_KH_MAX
from .spm import HeightSpectrum, spm_matrix
from .validity import SPMValidityWarning


def check_spm_validity(k: float, small_scale_height_variance: float | None) -> None:
    """Warn (:class:`SPMValidityWarning`) when ``k h > 0.3``.

    Parameters
    ----------
    k : float
        Electromagnetic wavenumber [rad/m].
    small_scale_height_variance : float or None
        Height variance of the roughness the SPM describes [m^2]; None skips the check.
    """
    if small_scale_height_variance is None:
        return
    kh = k * np.sqrt(max(small_scale_height_variance, 0.0))
    if kh > SPM_KH_MAX:
        h = np.sqrt(small_scale_height_variance)
        warnings.warn(f"SPM with k h = {kh:.2f} > {SPM_KH_MAX} (rms height of the "
                      f"roughness it describes {h:.3g} m): first-order perturbation theory "
                      "is outside its domain", SPMValidityWarning, stacklevel=3)


def slope_nodes(mss_upwind: float, mss_crosswind: float, wind_direction: float,
                n: int) -> tuple[NDArray, NDArray]:
    """Gauss-Hermite nodes of the slope average: world slopes (M, 2) and weights (M,).

    The weights integrate the anisotropic Gaussian density to 1.
    """
    x, w = np.polynomial.hermite.hermgauss(n)
    zu = np.sqrt(2.0 * mss_upwind) * x
    zc = np.sqrt(2.0 * mss_crosswind) * x
    zu, zc = (a.ravel() for a in np.meshgrid(zu, zc, indexing="ij"))
    weight = np.outer(w, w).ravel() / np.pi
    c, s = np.cos(wind_direction), np.sin(wind_direction)
    slopes = np.stack([zu * c - zc * s, zu * s + zc * c], axis=-1)
    return slopes, weight


def two_scale_sigma(
    theta_i: ArrayLike,
    phi_i: ArrayLike,
    theta_s: ArrayLike,
    phi_s: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: float,
    mss_crosswind: float,
    wind_direction: float,
    k_cut: float,
    n_nodes: int = 16,
    small_scale_height_variance: float | None = None,
) -> NDArray:
    """Mean-plane bistatic two-scale scattering coefficients (eq T1).

    Parameters
    ----------
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad].
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity [-].
    spectrum : callable
        Height spectrum ``W(kx, ky)`` [m^4] (world frame); only ``|K| > k_cut`` is used.
    mss_upwind, mss_crosswind : float
        Slope variances of the large-scale waves ``K < k_cut`` [-].
    wind_direction : float
        Direction the wind blows towards [rad].
    k_cut : float
        Scale-split wavenumber [rad/m].
    n_nodes : int
        Gauss-Hermite nodes per slope axis.
    small_scale_height_variance : float, optional
        Height variance of ``K > k_cut`` [m^2], for the SPM validity warning.

    Returns
    -------
    ndarray, shape (..., 4)
        ``sigma_mn`` [m^2/m^2], HH, HV, VH, VV.

    References
    ----------
    .. [1] Khenchaf and Airiau (2000); paper section III-B(c).
    """
    check_spm_validity(k, small_scale_height_variance)
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    shape = n_i.shape[:-1]
    n_i = n_i.reshape(-1, 3)
    n_s = n_s.reshape(-1, 3)
    slopes, weight = slope_nodes(max(mss_upwind, 1e-12), max(mss_crosswind, 1e-12),
                                 wind_direction, n_nodes)
    area = np.sqrt(1.0 + np.sum(slopes**2, axis=-1))
    normals = np.concatenate([-slopes, np.ones((len(slopes), 1))], axis=-1) / area[:, None]
    out = np.empty((n_i.shape[0], 4))
    chunk = max(1, 65536 // len(weight))
    for start in range(0, n_i.shape[0], chunk):
        sl = slice(start, start + chunk)
        b, kb = spm_matrix(n_i[sl, None, :], n_s[sl, None, :], k, eps_r, normals[None])
        kmag = np.hypot(kb[..., 0], kb[..., 1])
        w = np.where(kmag > k_cut, np.asarray(spectrum(kb[..., 0], kb[..., 1])), 0.0)
        s = (b.real**2 + b.imag**2).reshape(b.shape[:-2] + (4,)) * w[..., None]
        # Eq T1: quadrature with the area factor.
        out[sl] = np.einsum("gmc,m->gc", s, weight * area)
    return out.reshape(shape + (4,))


__all__ = ["SPM_KH_MAX", "check_spm_validity", "slope_nodes", "two_scale_sigma"]
