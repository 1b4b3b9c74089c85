"""Scattering by breaking waves (non-Bragg, nearly polarisation-independent).

Third mechanism beside Kirchhoff/GO and Bragg (SPM, two-scale), from the semi-empirical
model of Kudryavtsev, Hauser, Caudal & Chapron (2003) ("KHCC03" below), as restated by
Kudryavtsev, Akimov, Johannessen & Chapron (2005) ("K05"). The sea is split into the
"regular" surface (Bragg + specular scattering, seaecho's own models) and the areas of
breaking zones, which cover a fraction ``q`` of the surface and scatter like very rough,
steep facets:

.. math::
    \\sigma_0 = (\\sigma_{br} + \\sigma_{sp})(1 - q) + \\sigma_{wb}\\, q
    \\qquad \\text{(KHCC03 eq 1; K05 eq 1)}                                   (BR1)

**NRCS of a breaking zone** (KHCC03 eq 60), monostatic, incidence ``theta``:

.. math::
    \\sigma_{0wb}(\\theta) = \\frac{\\sec^4\\theta}{s_{wb}^2}
    \\exp\\left(-\\frac{\\tan^2\\theta}{s_{wb}^2}\\right) + \\frac{\\varepsilon_{wb}}{s_{wb}^2}
    \\qquad s_{wb}^2 = 0.19,\\ \\varepsilon_{wb} = 0.005                      (BR2)

The first term is geometric optics (Barrick's eq K1 with unit reflectivity) on the
enhanced roughness of the breaking zone, an isotropic Gaussian of total mean square slope
``s_wb^2``; the second is the return of the breaker front (thickness-to-length ratio
``eps_wb``), which dominates at large incidence. The zones are tilted forward by
``theta_wb = 0.05`` on average (KHCC03 sec. 5; K05 eq 29), which gives an upwind/downwind
asymmetry.

**Fraction of breaking zones** (KHCC03 eq 56; K05 eq 27), from Phillips' (1985)
distribution of the length of breaking fronts ``Lambda(k, phi)`` (``Lambda k dk dphi`` is
the length of fronts per unit area of waves in ``dk dphi``):

.. math::
    q = c_q \\int_{k < k_{wb}} \\Lambda(k, \\varphi)\\, dk\\, d\\varphi,\\qquad
    \\Lambda = \\frac{1}{2k}\\left(\\frac{B}{\\alpha}\\right)^{n+1}
    = \\frac{1}{2k}\\,\\beta_\\nu^{(n+1)/n}                                     (BR3)

``c_q = 10.5``; only breakers longer than ten radar wavelengths count and not shorter
than 0.3 m, ``k_wb = min(0.1 k_r, 2 pi / 0.3)`` (KHCC03 sec. 5; K05, above eq 19). The
second form holds in the equilibrium range of the KHCC03 spectrum, where the wind input
balances the dissipation, ``B = alpha beta_nu^(1/n)`` (KHCC03 sec. 3; the spectrum itself
is :mod:`seaecho.ocean.kudryavtsev`, where these laws are defined), with the wind
growth rate (K05 eq 17; KHCC03 eqs 19-21)

.. math::
    \\beta = C_\\beta \\left(\\frac{u_*}{c}\\right)^2 \\cos\\varphi|\\cos\\varphi|,\\quad
    C_\\beta = 1.5\\frac{\\rho_a}{\\rho_w}\\left(\\frac{1}{\\kappa}\\ln\\frac{\\pi}{k z_0}
    - \\frac{c}{u_*}\\right),\\quad
    z_0 = 0.018\\frac{u_*^2}{g} + 0.1\\frac{\\nu_a}{u_*}                       (BR4)

``beta_nu = beta - 4 nu k^2 / omega`` (viscous loss), ``n = 5`` for gravity waves (a
smooth step to 1 above ``k_gamma / 4``, KHCC03 sec. 3), ``u_* = U10 sqrt(C_D)`` with
``C_D = (0.8 + 0.065 U10) 1e-3`` (Wu 1982: the drag law KHCC03 use, law ``"wu-1982"`` of
:mod:`seaecho.ocean.wind`, which also holds z0). The phase speed ``c`` and ``omega`` are
the dispersion relation's (:mod:`seaecho.ocean.dispersion`, with capillarity),
``kappa``, ``rho_a``, ``nu_a`` and the viscosity ``nu`` of sea water are those of
:mod:`seaecho.constants` (KHCC03 round kappa to 0.4; seaecho's 0.41 lowers C_beta's log
term by 2.4 %). ``q`` therefore depends only on the wind
speed and the radar wavenumber: it is the KHCC03 model's own value, not a property of
the wave spectrum used for the Bragg part.

Bistatic generalisation (ours; no published bistatic KHCC model was found)
--------------------------------------------------------------------------
BR2 is geometric optics, so it generalises exactly like eq K1: the specular facets of a
bistatic geometry have the normal ``N_sp = q / |q|`` (``q = k (n_s - n_i)``), of slopes
``Z`` relative to the mean (or facet) plane, and

.. math::
    \\sigma_{wb} = \\frac{\\pi}{(N_{sp}\\cdot N_t)^4}\\,P_{wb}(\\mathbf Z)
    + \\frac{\\varepsilon_{wb}}{s_{wb}^2},\\qquad
    P_{wb} = \\frac{1}{\\pi s_{wb}^2}\\exp\\left(-\\frac{|\\mathbf Z|^2}{s_{wb}^2}\\right),
    \\quad N_t = \\cos\\epsilon\\, N + \\sin\\epsilon\\, \\hat e_u,\\
    \\epsilon = \\theta_{wb} A_{wb}                                              (BR5)

with ``Z`` the slopes of ``N_sp`` relative to the plane of normal ``N_t``; it reduces to
BR2 at backscatter without tilt (``|Z| = tan theta``, ``N_sp . N = cos theta``). The
zones' plane ``N_t`` leans towards the wind direction ``e_u`` by ``theta_wb`` times
``A_wb``, the Lambda-weighted mean cosine of the breaking direction (KHCC03 sec. 5): at
backscatter in the wind plane BR5 is ``sigma_0wb(theta -+ epsilon)``, whose first order
is KHCC03's ``sigma_0wb (1 + M_wb theta_wb A_wb cos phi)`` (``M_wb = d ln sigma_0wb /
d theta``), and upwind looks (radar downwind of the patch) see the forward faces, as
they should. The front term ``eps_wb / s_wb^2`` is kept
isotropic (it counts wherever Tx and Rx are both above the plane); this is the part of
the generalisation that has no support in data away from backscatter.

**Polarisation.** KHCC03 treat breaking as non-polarised: ``sigma_wb`` is the same in HH
and VV and carries no cross-polarisation at backscatter (its constants absorb the
reflectivity). In FSA bases we use the specular-facet matrix of eq K2 with a unit,
polarisation-independent reflection,

.. math::
    \\mathsf T = \\mathsf A_s^T\\, \\mathrm{diag}(-1, 1)\\, \\mathsf A_i,\\qquad
    \\sigma_{wb,mn} = \\sigma_{wb} |T_{mn}|^2                                   (BR6)

(``R_h = -R_v`` is the normal-incidence limit of the Fresnel coefficients of any
medium): ``|T_hh| = |T_vv| = 1`` and ``T_hv = T_vh = 0`` at backscatter and in the plane
of incidence, and out of the plane the polarisation bases of the bisector facet rotate
power into the cross channels exactly as geometric optics does. The cross-polarised
breaking term of Kudryavtsev et al. (2019) is not included.

Time behaviour (for the per-facet use)
--------------------------------------
Breaking zones are carried by the breaking waves: their scatterers move at the phase
speed ``c(k)`` of the breakers in their direction, so the Lambda-weighted mean velocity
of the fronts, ``int c(k) cos(phi) Lambda dk dphi / int Lambda dk dphi`` along the wind
(the mean breaker velocity of Hansen et al. 2012, eq 19, after K05; read in an open
implementation of their DopRIM model; :func:`breaking_statistics`), gives the Doppler
shift of the breaking component (0.97 m/s at 10 GHz and U10 = 7.6 m/s; the mean *speed*
times the wind direction, used before, gave 1.11 m/s), and each breaker lives for
roughly one period of its wave (active breaking lasts about one wave period in the
laboratory, Rapp & Melville 1990). The speckle of
the breaking component is independent of the Bragg and specular speckle (distinct
scatterers).

``c(k)`` is the linear phase speed, i.e. the fronts' speed *relative to the water*. The
waves longer than the breakers carry them with their orbital velocity, and breaking is
modulated by them (K05), so the breakers' mean Doppler velocity is, in Hansen et al.
(2012), eq 19 plus a long-wave term, eq 5: the covariance of the modulated fraction of
breaking zones with the orbital velocity of the waves that modulate breaking,

.. math::
    |K| < k_{mod} = B_{MOD}\\, k_{wb} = k_{wb}/10                                 (BR7)

(:func:`modulating_wavenumber_limit`: ten times longer than the shortest breakers).
Per facet (``seaecho.simulation``) the zones sit on the facets of largest downward
acceleration of the resolved sea (Phillips' criterion, the threshold set by ``q``:
:func:`breaking_placement`), i.e. on the resolved crests, where the long waves have
theirs; their mean orbital velocity is eq BR8 (:func:`placement_orbital_velocity`;
0.70 m/s along the wind at U10 = 7.6 m/s on a 1 m grid, of which 0.65 from the waves
``k < k_mod``), the counterpart of K05's linear term, eq BR9
(:func:`breaking_modulation_velocity`; 0.48 m/s). The resolved waves shorter than
``k_mod`` are breakers themselves (``k < k_wb``), counted in the fronts' velocity: the
zones' Doppler leaves their orbital velocity out,

.. math::
    f_{wb} = \\mathbf q \\cdot (\\mathbf v - \\mathbf v_{|K| \\ge k_{mod}}
    + c_{br}\\,\\hat{\\mathbf u} + \\mathbf U) / 2\\pi                               (BR10)

(``v`` the facet's velocity, eq D1; ``v_|K|>=k_mod`` the band of the resolved surface's
velocity above ``k_mod`` at the facet, :func:`seaecho.sea.band_velocity`; ``U`` the
surface drift, eq C1; :meth:`seaecho.scattering.dynamics.EvolvingSpeckle.draws`), so that
they ride on the long waves only (before, on every resolved wave: +0.05 m/s on a 1 m
grid, +0.12 m/s on a 0.25 m one at U10 = 7.6 m/s).

References
----------
.. [1] Kudryavtsev, V., Hauser, D., Caudal, G. and Chapron, B. (2003). A semiempirical
   model of the normalized radar cross-section of the sea surface, 1. Background model.
   *J. Geophys. Res.* 108(C3), 8054, doi:10.1029/2001JC001003.
.. [2] Kudryavtsev, V., Akimov, D., Johannessen, J. and Chapron, B. (2005). On radar
   imaging of current features: 1. Model and comparison with observations.
   *J. Geophys. Res.* 110, C07016, doi:10.1029/2004JC002505.
.. [3] Phillips, O. M. (1985). Spectral and statistical properties of the equilibrium
   range in wind-generated gravity waves. *J. Fluid Mech.* 156, 505-531.
.. [4] Wu, J. (1982). Wind-stress coefficients over sea surface from breeze to hurricane.
   *J. Geophys. Res.* 87(C12), 9704-9706.
.. [5] Rapp, R. J. and Melville, W. K. (1990). Laboratory measurements of deep-water
   breaking waves. *Phil. Trans. R. Soc. Lond. A* 331, 735-800.
.. [6] Kudryavtsev, V., Fan, S., Zhang, B., Mouche, A. and Chapron, B. (2019). On
   quad-polarized SAR measurements of the ocean surface. *IEEE Trans. Geosci. Remote
   Sens.* 57(11), 8362-8370.
.. [7] Hansen, M. W., Kudryavtsev, V., Chapron, B., Johannessen, J. A., Collard, F.,
   Dagestad, K.-F. and Mouche, A. A. (2012). Simulation of radar backscatter and Doppler
   shifts of wave-current interaction in the presence of strong tidal current. *Remote
   Sens. Environ.* 120, 113-122.
.. [8] Johnson, N. L., Kotz, S. and Balakrishnan, N. (1994). *Continuous Univariate
   Distributions*, vol. 1, 2nd ed., Wiley, ch. 13 (the truncated normal's mean).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary, Mat2
from ..geometry import frames
from ..ocean.dispersion import phase_speed
from ..ocean.kudryavtsev import (  # noqa: F401  (KHCC03's laws, re-exported here)
    FRICTION_LAW,
    N_GRAVITY,
    dissipation_exponent,
    net_growth_rate,
    wind_growth_rate,
)

#: Mean square slope of the enhanced roughness of breaking zones s_wb^2 [-] (KHCC03).
S_WB2 = 0.19
#: Ratio of the breaker thickness to its length eps_wb [-] (KHCC03).
EPS_WB = 5.0e-3
#: Mean tilt of the breaking zones theta_wb [rad] (KHCC03).
THETA_WB = 5.0e-2
#: Constant of the fraction of breaking zones c_q [-] (KHCC03 eq 56).
C_Q = 10.5
#: Breakers shorter than 1 / B_R radar wavelengths do not scatter as zones [-] (KHCC03).
B_R = 0.1
#: Shortest breakers counted [rad/m]: wavelength 0.3 m (K05, above eq 19).
K_WB_MAX = 2.0 * np.pi / 0.3
#: The long waves that modulate breaking are at least 1 / B_MOD times longer than the
#: shortest breakers, ``k < k_mod = B_MOD k_wb`` [-] (Hansen et al. 2012 eq 5, breaking
#: term; the integration limit of the DopRIM implementation, eq BR9).
B_MOD = 0.1
#: Hydrodynamic modulation constant of the short waves m_k [-] (Hansen et al. 2012).
M_K = -4.5


# --- wind and waves (BR4) -----------------------------------------------------------
# The growth rate, the dissipation exponent and the net growth rate are those of the
# KHCC03 short-wave spectrum (seaecho.ocean.kudryavtsev), defined there once.


def breaking_front_density(k: ArrayLike, phi: ArrayLike, u10: float) -> NDArray:
    """Phillips' distribution of breaking fronts ``Lambda(k, phi)`` [m] (eq BR3).

    ``Lambda k dk dphi`` is the length of breaking fronts per unit area [1/m] of the
    waves in ``dk dphi``; in the equilibrium range of the KHCC03 spectrum
    ``Lambda = (1/2k) beta_nu^((n+1)/n)``, ``beta_nu = beta - 4 nu k^2 / omega``.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    phi : array_like
        Direction of travel relative to the wind [rad].
    u10 : float
        Wind speed at 10 m [m/s].

    References
    ----------
    .. [1] Phillips (1985); KHCC03 sec. 5 (their Lambda and eq 56); K05 eq 27.
    """
    k = np.asarray(k, dtype=float)
    beta_nu = net_growth_rate(k, phi, u10)
    n = dissipation_exponent(k)
    # Eq BR3 (equilibrium form).
    return np.maximum(beta_nu, 0.0) ** ((n + 1.0) / n) / (2.0 * k)


@dataclass(frozen=True)
class BreakingStatistics:
    """Breaking zones seen by a radar of wavenumber ``k_radar`` at wind ``u10``.

    Attributes
    ----------
    q : float
        Fraction of the surface covered by breaking zones [-] (eq BR3).
    mean_direction : float
        ``A_wb``: Lambda-weighted mean cosine of the breaking direction relative to the
        wind [-] (KHCC03 sec. 5); the zones lean towards the wind by ``theta_wb A_wb``.
    mean_phase_speed : float
        Lambda-weighted mean phase speed of the breakers [m/s]: the speed of the
        breaking scatterers (their Doppler shift).
    mean_period : float
        Lambda-weighted mean wave period ``2 pi / omega`` of the breakers [s]: the order
        of a breaker's lifetime (Rapp & Melville 1990).
    k_wb : float
        Largest wavenumber of the breakers counted [rad/m].
    mean_velocity : float
        Lambda-weighted mean velocity of the breakers along the wind [m/s]: the mean of
        ``c(k) cos(phi)`` over the breaking fronts (the mean breaker velocity of Hansen
        et al. 2012, eq 19, after K05; the crosswind mean vanishes by symmetry), the
        velocity the breaking zones drift with (their Doppler shift); below
        ``mean_phase_speed`` by the spread of the breaking directions (0.87 of it at
        10 GHz and U10 = 7.6 m/s).
    """

    q: float
    mean_direction: float
    mean_phase_speed: float
    mean_period: float
    k_wb: float
    mean_velocity: float


def breaking_wavenumber_limit(k_radar: float) -> float:
    """``k_wb = min(0.1 k_r, 2 pi / 0.3 m)`` [rad/m] (KHCC03 sec. 5; K05 above eq 19)."""
    return float(min(B_R * k_radar, K_WB_MAX))


def breaking_statistics(u10: float, k_radar: float) -> BreakingStatistics:
    """Fraction of breaking zones and breaker kinematics (eq BR3).

    Parameters
    ----------
    u10 : float
        Wind speed at 10 m [m/s], > 0.
    k_radar : float
        Radar (electromagnetic) wavenumber [rad/m], > 0.

    Returns
    -------
    BreakingStatistics

    References
    ----------
    .. [1] KHCC03 eq 56 and sec. 5; K05 eq 27.
    """
    if not (np.isfinite(u10) and u10 > 0.0):
        raise ValueError(f"u10 = {u10!r} m/s: must be a finite number > 0")
    if not (np.isfinite(k_radar) and k_radar > 0.0):
        raise ValueError(f"k_radar = {k_radar!r} rad/m: must be a finite number > 0")
    return _statistics(round(float(u10), 9), breaking_wavenumber_limit(float(k_radar)))


@lru_cache(maxsize=256)
def _statistics(u10: float, k_wb: float) -> BreakingStatistics:
    # log-spaced k from far below any spectral peak; C_beta clipping ends the integrand
    # where the waves outrun the wind.
    lk = np.linspace(np.log(1e-3), np.log(k_wb), 1201)
    k = np.exp(lk)
    x, w = np.polynomial.legendre.leggauss(64)
    phi = 0.5 * np.pi * x  # beta = 0 outside |phi| < pi/2
    wphi = 0.5 * np.pi * w
    lam = breaking_front_density(k[:, None], phi[None, :], u10)  # (nk, nphi)
    # dk = k dlnk; trapezoid in ln k.
    wk = np.gradient(lk) * k
    wk[[0, -1]] *= 0.5
    lam_k = lam * wk[:, None] * wphi[None, :]
    total = float(lam_k.sum())
    q = C_Q * total
    if total <= 0.0:
        return BreakingStatistics(0.0, 0.0, 0.0, 0.0, k_wb, 0.0)
    a_wb = float((lam_k * np.cos(phi)[None, :]).sum() / total)
    c = phase_speed(k)
    c_mean = float((lam_k.sum(axis=1) * c).sum() / total)
    # the mean velocity vector of the fronts, along the wind (Hansen et al. 2012 eq 19)
    v_mean = float(((lam_k * np.cos(phi)[None, :]).sum(axis=1) * c).sum() / total)
    period = float((lam_k.sum(axis=1) * 2.0 * np.pi / (k * c)).sum() / total)
    return BreakingStatistics(q, a_wb, c_mean, period, k_wb, v_mean)


# --- NRCS of breaking zones (BR2, BR5, BR6) --------------------------------------------

def breaking_nrcs_monostatic(theta: ArrayLike) -> NDArray:
    """NRCS of a breaking zone at backscatter, incidence ``theta`` [rad] (KHCC03 eq 60).

    Returns ``sec^4 t / s_wb^2 exp(-tan^2 t / s_wb^2) + eps_wb / s_wb^2`` [m^2/m^2]
    (eq BR2), the same for HH and VV, without the mean tilt.
    """
    t = np.asarray(theta, dtype=float)
    c = np.cos(t)
    tan2 = np.where(c > 1e-9, np.tan(t) ** 2, np.inf)
    spec = np.where(c > 1e-9, np.exp(np.minimum(-tan2 / S_WB2 - 4.0 * np.log(np.maximum(c, 1e-300)),
                                                700.0)) / S_WB2, 0.0)
    # Eq BR2.
    return spec + EPS_WB / S_WB2


def breaking_matrix(xp, n_i: Any, n_s: Any, N: Any, basis_i: tuple[Any, Any],
                    basis_s: tuple[Any, Any], cos_wind: Any, sin_wind: Any,
                    tilt: Any) -> Mat2:
    """Amplitude matrix ``W`` of breaking zones on planes of normal ``N`` (BR5-BR6).

    Over an array namespace (:mod:`seaecho.backend`): the per-facet kernel and the
    numpy :func:`breaking_amplitude` evaluate this function.

    Parameters
    ----------
    xp : array namespace
    n_i, n_s, N : vectors
        Unit incident and scattered directions and the unit normal of the plane the zones
        sit on [-].
    basis_i, basis_s : (h, v)
        Global (+z) FSA bases of ``n_i`` and ``n_s`` (eqs F1-F2).
    cos_wind, sin_wind : arrays
        Direction the wind blows towards, as a unit vector's components [-].
    tilt : float or array
        Forward tilt of the zones ``epsilon = theta_wb A_wb`` [rad].

    Returns
    -------
    Mat2
        Real-valued ``W`` [-] (``sigma_wb,mn = |W_mn|^2``), global bases, (h, v) order.

    References
    ----------
    .. [1] KHCC03 eq 60 (monostatic limit); module docstring (BR5, BR6).
    """
    d = n_s - n_i
    dn = xp.norm(d)
    ok = dn > 1e-12
    n_sp = xp.select(ok, d * (1.0 / xp.select(ok, dn, 1.0)), N)
    lit = (xp.dot(n_i, N) < -1e-12) & (xp.dot(n_s, N) > 1e-12)
    # Mean tilt: the zones' plane leans towards the wind by eps = theta_wb A_wb.
    u = xp.vec(cos_wind, sin_wind, 0.0)
    e_u = xp.normalize(u - xp.dot(u, N) * N)
    e_c = xp.cross(N, e_u)
    c_eps, s_eps = xp.cos(tilt), xp.sin(tilt)
    nt = N * c_eps + e_u * s_eps
    e_t = e_u * c_eps - N * s_eps
    cos_n = xp.dot(n_sp, nt)
    valid = cos_n > 1e-12
    cn = xp.select(valid, cos_n, 1e-12)
    z_u = -xp.dot(n_sp, e_t) / cn
    z_c = -xp.dot(n_sp, e_c) / cn
    # Eq BR5: isotropic Gaussian slopes about the tilted plane, pi / cos^4 P; plus the
    # front term.
    log_spec = -(z_u * z_u + z_c * z_c) * (1.0 / S_WB2) - math.log(S_WB2) - 4.0 * xp.log(cn)
    spec = xp.select(valid, xp.exp(xp.minimum(log_spec, xp.exp_cap)), 0.0)
    amp = xp.select(lit, xp.sqrt(spec + EPS_WB / S_WB2), 0.0)
    # Eq BR6: T = A_s^T diag(-1, 1) A_i with the bases of the bisector facet.
    h, v_i = frames.fsa_basis(xp, n_i, n_sp)
    a_i = frames.basis_change(xp, basis_i, (h, v_i))
    a_s = frames.basis_change(xp, basis_s, (h, xp.cross(h, n_s)))
    t = frames.global_matrix(Mat2.diag(-1.0, 1.0), a_i, a_s)
    return t * amp


def breaking_amplitude(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike = frames.Z_HAT,
    wind_direction: ArrayLike = 0.0,
    mean_direction: ArrayLike = 0.0,
    theta_wb: float = THETA_WB,
) -> NDArray:
    """Amplitude matrix ``W`` of breaking zones, ``sigma_wb,mn = |W_mn|^2`` (BR5-BR6).

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-], world frame.
    normal : array_like, shape (..., 3)
        Unit normal of the plane the breaking zones sit on (+z, or a facet normal) [-].
    wind_direction : array_like
        Direction the wind blows towards, CCW from +x [rad].
    mean_direction : array_like
        ``A_wb`` of :class:`BreakingStatistics` [-] (0 removes the tilt asymmetry).
    theta_wb : float
        Mean tilt of the zones [rad].

    Returns
    -------
    ndarray of complex, shape (..., 2, 2)
        ``W`` in the global (+z) FSA bases, (h, v) order [-] (real-valued phase-free
        amplitudes: the speckle phase is drawn by the caller).

    References
    ----------
    .. [1] KHCC03 eq 60 (monostatic limit); this module's docstring (BR5, BR6).
    """
    n_i = np.asarray(n_i, dtype=float)
    n_s = np.asarray(n_s, dtype=float)
    shape = np.broadcast_shapes(n_i.shape, n_s.shape, np.shape(normal))
    nn = np.broadcast_to(np.asarray(normal, dtype=float), shape)
    n_i = np.broadcast_to(n_i, shape)
    n_s = np.broadcast_to(n_s, shape)
    w = np.broadcast_to(np.asarray(wind_direction, dtype=float), shape[:-1])
    eps = theta_wb * np.broadcast_to(np.asarray(mean_direction, dtype=float), shape[:-1])
    io = Boundary(NUMPY)
    vi, vs, vn = io.vec3(n_i), io.vec3(n_s), io.vec3(nn)
    z = NUMPY.vec(0.0, 0.0, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        m = breaking_matrix(NUMPY, vi, vs, vn, frames.fsa_basis(NUMPY, vi, z),
                            frames.fsa_basis(NUMPY, vs, z), np.cos(w), np.sin(w), eps)
    out = np.empty(shape[:-1] + (2, 2), dtype=complex)
    for (r, c), e in zip(((0, 0), (0, 1), (1, 0), (1, 1)), m.flat(), strict=True):
        out[..., r, c] = np.broadcast_to(e, shape[:-1])
    return out


def breaking_sigma(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike = frames.Z_HAT,
    wind_direction: ArrayLike = 0.0,
    mean_direction: ArrayLike = 0.0,
    theta_wb: float = THETA_WB,
) -> NDArray:
    """NRCS of breaking zones ``sigma_wb,mn`` [m^2/m^2], shape (..., 4), HH, HV, VH, VV.

    Per unit area *of breaking zones*: multiply by ``q`` for the sea (eq BR1). See
    :func:`breaking_amplitude` for the parameters.
    """
    w = breaking_amplitude(n_i, n_s, normal, wind_direction, mean_direction, theta_wb)
    s = w.real**2 + w.imag**2
    return s.reshape(s.shape[:-2] + (4,))


def add_breaking(sigma_regular: ArrayLike, sigma_wb: ArrayLike, q: ArrayLike) -> NDArray:
    """Eq BR1: ``(1 - q) sigma_regular + q sigma_wb`` channel by channel [m^2/m^2].

    Parameters
    ----------
    sigma_regular : array_like, shape (..., 4)
        Bragg + specular scattering of the regular surface (any seaecho model).
    sigma_wb : array_like, shape (..., 4)
        :func:`breaking_sigma`.
    q : array_like
        Fraction of breaking zones [-], broadcast against the leading axes.
    """
    qq = np.asarray(q, dtype=float)[..., None]
    # Eq BR1.
    return (1.0 - qq) * np.asarray(sigma_regular) + qq * np.asarray(sigma_wb)


def breaking_sigma_mean_plane(
    theta_i: ArrayLike,
    phi_i: ArrayLike,
    theta_s: ArrayLike,
    phi_s: ArrayLike,
    u10: float,
    k_radar: float,
    wind_direction: float = 0.0,
) -> tuple[NDArray, float]:
    """Mean-plane ``sigma_wb,mn`` (per unit area of zones) and the fraction ``q``.

    Parameters
    ----------
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad] (:func:`frames.directions_from_angles`).
    u10 : float
        Wind speed at 10 m [m/s].
    k_radar : float
        Radar wavenumber [rad/m].
    wind_direction : float
        Direction the wind blows towards [rad].

    Returns
    -------
    sigma_wb : ndarray, shape (..., 4)
        [m^2/m^2], HH, HV, VH, VV.
    q : float
        Fraction of breaking zones [-].
    """
    stats = breaking_statistics(u10, k_radar)
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    return (breaking_sigma(n_i, n_s, frames.Z_HAT, wind_direction, stats.mean_direction),
            stats.q)


@dataclass(frozen=True)
class FacetBreaking:
    """Breaking component of N facets (the third mechanism of the per-facet model).

    Attributes
    ----------
    amplitude : ndarray of complex, shape (N, 2, 2)
        ``W`` of :func:`breaking_amplitude` (per unit area of breaking zones).
    q : ndarray, shape (N,)
        Fraction of each facet covered by breaking zones [-].
    """

    amplitude: NDArray
    q: NDArray

    def sigma(self) -> NDArray:
        """``q |W_mn|^2`` [m^2/m^2], shape (N, 4): the facet's breaking NRCS."""
        s = self.amplitude.real**2 + self.amplitude.imag**2
        return self.q[:, None] * s.reshape(-1, 4)


def facet_breaking(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    q: ArrayLike,
    wind_direction: float,
    mean_direction: float,
    theta_wb: float = THETA_WB,
) -> FacetBreaking:
    """Per-facet breaking terms: the interface the facet kernel will call.

    The breaking zones are small-scale features on the facet: their slopes (BR5) are
    taken relative to the facet normal, and the amplitude is returned in the global FSA
    bases like the Kirchhoff and Bragg matrices of the facet model. The regular
    mechanisms of the facet are then weighted by ``1 - q`` and this one by ``q`` (eq BR1),
    with its own independent circular Gaussian speckle factor.

    Parameters
    ----------
    n_i, n_s, normal : array_like, shape (N, 3)
        Unit directions and facet normals [-].
    q : array_like, shape (N,) or scalar
        Local fraction of breaking zones [-], in [0, 1]; the sea mean is
        :attr:`BreakingStatistics.q`.
    wind_direction : float
        Direction the wind blows towards [rad].
    mean_direction : float
        ``A_wb`` [-].
    theta_wb : float
        Mean tilt [rad].

    Returns
    -------
    FacetBreaking
    """
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n = n_i.shape[0]
    qq = np.broadcast_to(np.asarray(q, dtype=float), (n,)).copy()
    if np.any(~np.isfinite(qq)) or np.any(qq < 0.0) or np.any(qq > 1.0):
        raise ValueError("q: breaking fractions must lie in [0, 1]")
    w = breaking_amplitude(n_i, np.asarray(n_s, dtype=float).reshape(-1, 3),
                           np.asarray(normal, dtype=float).reshape(-1, 3), wind_direction,
                           mean_direction, theta_wb)
    return FacetBreaking(w, qq)


def breaking_placement(downward_acceleration: ArrayLike, area: ArrayLike,
                       q: float) -> NDArray:
    """Where the breaking zones are: the fraction of each facet they cover [-], shape (N,).

    Waves break where the downward acceleration of the surface exceeds a fraction of
    gravity, ``-a_z > gamma g`` (Phillips 1958; Longuet-Higgins 1963; the threshold
    mechanism of Snyder & Kennedy 1983; Srokosz 1986): it singles out the steep,
    sharp crests of the resolved waves. The universal ``gamma`` (about 0.4-0.5) applied
    to a linear surface synthesised up to a grid's Nyquist wavenumber gives a breaking
    area that depends on the grid; here the criterion keeps its form and the threshold
    is the one that makes the broken area the fraction ``q`` of KHCC03 (eq BR3): the
    facets of largest ``-a_z`` are covered (fraction 1) until their area is ``q`` times
    the total, the last one partly.

    Parameters
    ----------
    downward_acceleration : array_like (N,)
        ``-a_z`` of the facets [m/s^2] (any monotonic breaking index works).
    area : array_like (N,)
        Facet areas [m^2].
    q : float
        Fraction of the area covered by breaking zones [-], in [0, 1].

    Returns
    -------
    ndarray (N,)
        In [0, 1]; ``sum(area * result) = q sum(area)``.

    References
    ----------
    .. [1] Phillips, O. M. (1958). The equilibrium range in the spectrum of wind-generated
       waves. *J. Fluid Mech.* 4, 426-434.
    .. [2] Snyder, R. L. and Kennedy, R. M. (1983). On the formation of whitecaps by a
       threshold mechanism. Part I: Basic formalism. *J. Phys. Oceanogr.* 13, 1482-1492.
    .. [3] Srokosz, M. A. (1986). On the probability of wave breaking in deep water.
       *J. Phys. Oceanogr.* 16, 382-385.
    """
    b = np.asarray(downward_acceleration, dtype=float).reshape(-1)
    a = np.broadcast_to(np.asarray(area, dtype=float).reshape(-1), b.shape)
    if not (np.isfinite(q) and 0.0 <= q <= 1.0):
        raise ValueError(f"q = {q!r}: the breaking fraction must lie in [0, 1]")
    out = np.zeros(b.shape)
    total = float(a.sum())
    if q == 0.0 or total <= 0.0 or b.size == 0:
        return out
    target = q * total
    # Candidates: the largest indices covering well over the target area (O(N)).
    m = min(b.size, int(np.ceil(2.0 * q * b.size)) + 16)
    cand = np.argpartition(-b, m - 1)[:m] if m < b.size else np.arange(b.size)
    order = cand[np.argsort(-b[cand], kind="stable")]
    cum = np.cumsum(a[order])
    full = int(np.searchsorted(cum, target, side="right"))
    out[order[:full]] = 1.0
    if full < order.size:
        done = cum[full - 1] if full else 0.0
        out[order[full]] = (target - done) / a[order[full]]
    elif cum[-1] < target:  # the candidates were too few (very unequal areas): widen
        return breaking_placement_sorted(b, a, q)
    return out


def breaking_placement_sorted(b: NDArray, a: NDArray, q: float) -> NDArray:
    """:func:`breaking_placement` by a full sort (the general case)."""
    out = np.zeros(b.shape)
    order = np.argsort(-b, kind="stable")
    cum = np.cumsum(a[order])
    target = q * float(a.sum())
    full = int(np.searchsorted(cum, target, side="right"))
    out[order[:full]] = 1.0
    if full < order.size:
        out[order[full]] = (target - (cum[full - 1] if full else 0.0)) / a[order[full]]
    return out


def modulating_wavenumber_limit(k_wb: float) -> float:
    """``k_mod = B_MOD k_wb`` [rad/m]: the long waves that modulate breaking (eq BR7).

    Hansen et al. (2012) eq 5 integrates the breakers' modulation over the waves at least
    ten times longer than the shortest breakers (the DopRIM implementation's limit
    ``k < k_wb / 10``); shorter resolved waves are breakers themselves (``k < k_wb``,
    eq BR3), whose speed the fronts' velocity already counts.
    """
    return float(B_MOD * k_wb)


def _polar_band(spectrum, k_max: float, n_k: int = 1500, n_psi: int = 360):
    """Log-spaced K up to ``k_max`` from 1/50 of the spectral peak and travel directions
    psi relative to the wind [rad], with ``S_1d D`` [m^3/rad] (``Psi d^2K = S_1d D dK
    dpsi``) and the quadrature weights of ``dK dpsi``."""
    k = np.geomspace(spectrum.peak_wavenumber() / 50.0, k_max, n_k)
    psi = np.linspace(-np.pi, np.pi, n_psi, endpoint=False)
    dens = spectrum.omni(k)[:, None] * spectrum.spread(k[:, None], psi[None, :])
    wk = np.gradient(k)
    return k, psi, dens, wk[:, None] * (2.0 * np.pi / n_psi)


def placement_orbital_velocity(spectrum, q: float, k_index: float, direction: float,
                               depth: float | None = None,
                               k_velocity: float | None = None) -> float:
    r"""Mean orbital velocity along ``direction`` of the surface the breaking zones cover
    [m/s], for the placement of :func:`breaking_placement` on the index of eq BR7.

    The index ``X = -a_z`` of the waves ``K < k_index`` (the grid's resolved sea for the
    simulation's placement, ``pi / dx``) and the horizontal particle velocity ``u_e``
    along the unit vector of azimuth ``direction`` of the waves ``K < k_velocity`` are
    jointly Gaussian on a linear sea; covering the fraction ``q`` of largest ``X``
    (``X > x_q sigma_X``, ``x_q = sqrt(2) erfcinv(2 q)``) selects, on average (the
    conditional mean of a bivariate normal beyond a threshold, the inverse Mills ratio;
    Johnson, Kotz & Balakrishnan 1994, ch. 13),

    .. math::
        \langle u_e \rangle_q = \frac{\mathrm{cov}(u_e, X)}{\sigma_X}
        \frac{\varphi(x_q)}{q},\quad
        \mathrm{cov}(u_e, X) = \int_{K<k_v} \omega^3 \coth(Kd) \cos(\psi -
        \psi_e)\, \Psi\, d^2K,\quad
        \sigma_X^2 = \int_{K<k_{index}} \omega^4\, \Psi\, d^2K            (BR8)

    (linear waves: ``-a_z = omega^2 z`` and ``u = omega coth(Kd) z`` along the travel
    direction, in phase; Lamb 1932, art. 228; ``k_v = min(k_velocity, k_index)``: the
    waves outside the index are independent of it and average out over the zones).
    ``k_velocity = k_mod`` (eq BR7) gives the part of the long waves that modulate
    breaking, the counterpart of eq BR9; the rest, the resolved waves shorter than
    ``k_mod``, are breakers themselves (``k < k_wb``), whose speed the fronts' velocity
    already counts.

    Parameters
    ----------
    spectrum : DirectionalSpectrum
        The sea's spectrum (its ``wind_direction`` places ``psi``).
    q : float
        Fraction of the area covered [-], in (0, 1).
    k_index : float
        Upper wavenumber of the index [rad/m].
    direction : float
        Azimuth of the velocity component [rad], CCW from +x.
    depth : float or None
        Water depth [m] (None: deep water).
    k_velocity : float or None
        Upper wavenumber of the velocity [rad/m] (None: ``k_index``).
    """
    from scipy.special import erfcinv

    from ..ocean.dispersion import angular_frequency, horizontal_to_vertical_ratio

    if not (0.0 < q < 1.0):
        raise ValueError(f"q = {q!r}: must lie in (0, 1)")
    k, psi, dens, w = _polar_band(spectrum, k_index)
    om = angular_frequency(k, depth)[:, None]
    coth = horizontal_to_vertical_ratio(k, depth)
    coth = np.broadcast_to(np.asarray(coth, dtype=float), k.shape)[:, None]
    cos_e = np.cos(psi + spectrum.wind_direction - direction)[None, :]
    in_v = (k < (k_index if k_velocity is None else k_velocity))[:, None]
    # Eq BR8.
    cov = float(np.sum(np.where(in_v, om ** 3 * coth * cos_e * dens * w, 0.0)))
    sigma = math.sqrt(float(np.sum(om ** 4 * dens * w)))
    x_q = math.sqrt(2.0) * float(erfcinv(2.0 * q))
    return cov / sigma * math.exp(-0.5 * x_q * x_q) / math.sqrt(2.0 * math.pi) / q


def breaking_modulation_velocity(spectrum, u10: float, k_radar: float,
                                 direction: float) -> float:
    r"""Long-wave part of the breakers' Doppler velocity at grazing incidence [m/s]:
    the breaking term of Hansen et al. (2012) eq 5 with K05's modulation transfer function.

    The breaking zones' fraction is modulated by the long waves, ``q (1 + M_h k zeta)``,
    and the zones ride on their orbital velocity: their mean velocity along the unit
    vector of azimuth ``direction`` gains

    .. math::
        c_{wb} = -\int_{K<k_{mod}} \mathrm{Re}\,M_h \cos(\psi - \psi_e)\, c\, K^2
        \Psi\, d^2K,\quad
        M_h = \frac{m_k}{4}(n + 1)(1 + 2\cos^2(\psi - \psi_e))
        \frac{1 - i\tau}{1 + \tau^2},\quad
        \tau = \frac{n \beta_{wb} \omega_{wb}}{\omega}                      (BR9)

    (``m_k = -9/2``, ``n = 5``, ``beta_wb`` the wind growth rate of eq BR4 at ``k_wb``
    along the wind, ``k_mod`` of eq BR7) to add to the fronts' mean velocity
    (:attr:`BreakingStatistics.mean_velocity`, Hansen et al. eq 19). The tilt term and the
    imaginary (relaxation) term of eq 5 carry ``1 / tan(theta)`` and are left out: at
    grazing incidence the front term of eq BR2 does not depend on the incidence (the tilt
    MTF vanishes) and ``tau / tan(theta)`` is below 1 % at 3 deg grazing. Eq 5 and the
    constants were read in the open DopRIM implementation (stereoid project), which
    names them after the article; the article itself was not available.

    Parameters
    ----------
    spectrum : DirectionalSpectrum
    u10 : float
        Wind speed at 10 m [m/s].
    k_radar : float
        Radar wavenumber [rad/m].
    direction : float
        Azimuth of the velocity component (e.g. towards the radar) [rad].

    References
    ----------
    .. [1] Hansen et al. (2012), eqs 5 and 19; K05 (the MTF of the breaking zones).
    """
    from ..ocean.dispersion import angular_frequency

    k_wb = breaking_wavenumber_limit(k_radar)
    k, psi, dens, w = _polar_band(spectrum, modulating_wavenumber_limit(k_wb))
    beta_wb = float(wind_growth_rate(k_wb, 0.0, u10))
    om = angular_frequency(k)[:, None]
    tau = N_GRAVITY * beta_wb * float(angular_frequency(k_wb)) / om
    cos_e = np.cos(psi + spectrum.wind_direction - direction)[None, :]
    # Eq BR9 (real part of M_h).
    re_m = M_K / 4.0 * (N_GRAVITY + 1.0) * (1.0 + 2.0 * cos_e ** 2) / (1.0 + tau ** 2)
    return float(np.sum(-re_m * cos_e * (om / k[:, None]) * k[:, None] ** 2 * dens * w))


__all__ = [
    "B_MOD", "M_K", "breaking_modulation_velocity", "modulating_wavenumber_limit",
    "placement_orbital_velocity",
    "B_R", "C_Q", "EPS_WB", "FRICTION_LAW", "K_WB_MAX", "N_GRAVITY", "S_WB2", "THETA_WB",
    "BreakingStatistics", "FacetBreaking", "add_breaking", "breaking_amplitude",
    "breaking_placement",
    "breaking_front_density", "breaking_matrix", "breaking_nrcs_monostatic", "breaking_sigma",
    "breaking_sigma_mean_plane", "breaking_statistics", "breaking_wavenumber_limit",
    "dissipation_exponent", "facet_breaking", "net_growth_rate", "wind_growth_rate",
]
