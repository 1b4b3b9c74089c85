"""Per-facet polarimetric scattering: sigma_mn and speckled complex amplitudes.

This is the interface between the surface (ray-traced or analytic facets, tracing) and
the radar equation (radar). A facet of area ``A`` and unit normal ``N`` carries the
unresolved (sub-facet) roughness of the ocean stage: slope variances for the specular
(Kirchhoff/GO) part, the height spectrum at the local Bragg vector for the Bragg (SPM)
part. For each facet the model gives two complex 2x2 *mechanism matrices* in the global
(+z) FSA bases, (h, v) order, flattened to HH, HV, VH, VV:

.. math::
    \\mathsf K = \\sqrt{\\pi P(Z)}\\,\\frac{|\\mathbf q|^2}{q_N^2}\\,\\mathsf F, \\qquad
    \\mathsf B = 4\\sqrt\\pi k^2 \\cos\\theta_i'\\cos\\theta_s'\\,
    \\mathsf A_s^T\\boldsymbol\\alpha'\\mathsf A_i\\,\\sqrt{W(\\mathbf k'_\\perp)(1-d)}
    \\qquad \\text{(P1, P2)}

(eqs K1-K2 and S7; ``d`` the turbulent-wake damping in [0, 1], 1 = Bragg waves fully
damped), and channel weights ``w`` (eqs B1-B4 with ``beta`` between ``N`` and ``q``).
Then

.. math::
    \\sigma_{mn} = w_{mn}|K_{mn}|^2 + (1 - w_{mn})|B_{mn}|^2 \\qquad \\text{(P3)}

Speckle. The echo of a facet is the sum of many sub-facet contributions; per mechanism
they add to one complex Gaussian factor, the *same* for the four channels because the
channels of one mechanism see the same specular points (resp. the same Bragg waves).
With ``g_K, g_B`` independent circular complex Gaussians of unit variance, drawn per
facet,

.. math::
    a_{mn} = \\sqrt{A}\\left(\\sqrt{w_{mn}}\\,K_{mn}\\,g_K
           + \\sqrt{1-w_{mn}}\\,B_{mn}\\,g_B\\right) \\quad [\\mathrm m] \\qquad \\text{(P4)}

so that, per facet,

.. math::
    \\mathrm E[a_{mn}] = 0, \\qquad
    \\mathrm E[a_{mn} a_{pq}^*] = A\\left(\\sqrt{w_{mn}w_{pq}}K_{mn}K_{pq}^*
    + \\sqrt{(1-w_{mn})(1-w_{pq})}B_{mn}B_{pq}^*\\right) \\qquad \\text{(P5)}

and ``E|a_mn|^2 = sigma_mn A``: ``|a_mn|^2`` is the facet's radar cross section [m^2]
for the radar equation (``P_r = P_t G_t G_r lambda^2 |a|^2 / ((4 pi)^3 r_t^2 r_r^2)``);
in the normalisation of the paper's eq 2 (``<|S|^2> = A sigma / (4 pi)``),
``S_mn = a_mn / sqrt(4 pi)``.
Within one mechanism the channels are fully coherent (``|gamma_HHVV| = 1``, phase
``arg K_hh K_vv^*`` or ``arg B_hh B_vv^*``); the mix of mechanisms lowers the HH-VV
coherence to ``|E a_hh a_vv^*| / sqrt(E|a_hh|^2 E|a_vv|^2)`` from P5
(:func:`hhvv_coherence`). Each ``|a_mn|^2`` is exponentially distributed.

References
----------
.. [1] Paper eqs 1-3 and 7-11.
.. [2] Ulaby, F. T. and Long, D. G. (2014). *Microwave Radar and Radiometric Remote
   Sensing*, sec. 5-8 (speckle as a circular complex Gaussian field).
.. [3] Lee, J.-S. and Pottier, E. (2009). *Polarimetric Radar Imaging*, CRC, ch. 4
   (covariance matrices of distributed targets).
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import frames
from .blend import channel_weights
from .fresnel import fresnel_coefficients
from .kirchhoff import kirchhoff_log_weight
from .slopes import CoxMunkParameters
from .spectrum_table import BraggSpectrumTable
from .spm import HeightSpectrum, _alpha
from .twoscale import check_spm_validity

MODELS = ("blend", "kirchhoff", "spm")


@functools.cache
def _drjit_available() -> bool:
    """True when the Dr.Jit LLVM backend imports and runs (checked once)."""
    try:
        from ._drjit_kernel import F

        return bool(F(1.0).numpy()[0] == 1.0)
    except Exception:  # noqa: BLE001 - any failure means: use numpy
        return False


@dataclass(frozen=True)
class FacetTerms:
    """Mechanism matrices and weights of eqs P1-P3 (all shaped (N, 4), HH, HV, VH, VV).

    Attributes
    ----------
    specular : ndarray of complex
        ``K`` [-]: ``|K|^2`` is the Kirchhoff/GO sigma.
    bragg : ndarray of complex
        ``B`` [-]: ``|B|^2`` is the SPM sigma (damping included).
    weight : ndarray
        Kirchhoff weight ``w`` per channel [-].
    """

    specular: NDArray
    bragg: NDArray
    weight: NDArray

    def sigma(self) -> NDArray:
        """Eq P3: ``sigma_mn`` [m^2/m^2], shape (N, 4)."""
        k2 = self.specular.real**2 + self.specular.imag**2
        b2 = self.bragg.real**2 + self.bragg.imag**2
        return self.weight * k2 + (1.0 - self.weight) * b2

    def covariance(self) -> NDArray:
        """Eq P5 per unit area: ``E[a a^H] / A``, shape (N, 4, 4) [m^2/m^2]."""
        k = np.sqrt(self.weight) * self.specular
        b = np.sqrt(1.0 - self.weight) * self.bragg
        return k[..., :, None] * k[..., None, :].conj() + b[..., :, None] * b[..., None, :].conj()


def _get(local: Any, name: str):
    if isinstance(local, Mapping):
        return local[name]
    return getattr(local, name)


def _dot(a: NDArray, b: NDArray) -> NDArray:
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _rotate(m: NDArray, a_i: NDArray, a_s: NDArray) -> NDArray:
    """``A_s^T M A_i`` for (N, 2, 2) arrays, written out (faster than einsum)."""
    # T = M A_i
    t00 = m[:, 0, 0] * a_i[:, 0, 0] + m[:, 0, 1] * a_i[:, 1, 0]
    t01 = m[:, 0, 0] * a_i[:, 0, 1] + m[:, 0, 1] * a_i[:, 1, 1]
    t10 = m[:, 1, 0] * a_i[:, 0, 0] + m[:, 1, 1] * a_i[:, 1, 0]
    t11 = m[:, 1, 0] * a_i[:, 0, 1] + m[:, 1, 1] * a_i[:, 1, 1]
    out = np.empty(m.shape[:1] + (4,), dtype=np.result_type(m, a_i))
    out[:, 0] = a_s[:, 0, 0] * t00 + a_s[:, 1, 0] * t10
    out[:, 1] = a_s[:, 0, 0] * t01 + a_s[:, 1, 0] * t11
    out[:, 2] = a_s[:, 0, 1] * t00 + a_s[:, 1, 1] * t10
    out[:, 3] = a_s[:, 0, 1] * t01 + a_s[:, 1, 1] * t11
    return out


def _specular_matrix(n_i: NDArray, n_s: NDArray, n_sp: NDArray, eps_r: complex,
                     h_i: NDArray, v_i: NDArray, h_s: NDArray, v_s: NDArray) -> NDArray:
    """``F`` of eq K2 (N, 4), given the global bases of ``n_i`` and ``n_s``."""
    cos_iota = -_dot(n_i, n_sp)
    r_h, r_v = fresnel_coefficients(cos_iota, eps_r)
    # Bases of the specular facet: h' = N_sp x n / |N_sp x n| (same for n_i and n_s).
    hp = np.cross(n_sp, n_i)
    norm = np.sqrt(_dot(hp, hp))
    deg = norm < 1e-9
    if np.any(deg):
        hp[deg] = np.cross(n_sp[deg], frames.reference_direction(n_sp[deg]))
        norm[deg] = np.sqrt(_dot(hp[deg], hp[deg]))
    hp /= norm[:, None]
    vpi = np.cross(hp, n_i)
    vps = np.cross(hp, n_s)
    # F_mn = sum_j (m_s . e'_j,s) R_j (e'_j,i . n_i-basis), eq K2 written out.
    hi_h, hi_v = _dot(hp, h_i), _dot(hp, v_i)
    vi_h, vi_v = _dot(vpi, h_i), _dot(vpi, v_i)
    hs_h, hs_v = _dot(hp, h_s), _dot(hp, v_s)
    vs_h, vs_v = _dot(vps, h_s), _dot(vps, v_s)
    f = np.empty(n_i.shape[:1] + (4,), dtype=complex)
    f[:, 0] = hs_h * r_h * hi_h + vs_h * r_v * vi_h
    f[:, 1] = hs_h * r_h * hi_v + vs_h * r_v * vi_v
    f[:, 2] = hs_v * r_h * hi_h + vs_v * r_v * vi_h
    f[:, 3] = hs_v * r_h * hi_v + vs_v * r_v * vi_v
    return f


def facet_terms(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    wind_direction: float = 0.0,
    *,
    model: str = "blend",
    cox_munk: CoxMunkParameters | None = None,
    wake_damping: ArrayLike | None = None,
    local: Any = None,
    small_scale_height_variance: float | None = None,
    backend: str = "auto",
) -> FacetTerms:
    """Mechanism matrices ``K``, ``B`` and weights ``w`` of facets (eqs P1-P2, B1-B4).

    Parameters
    ----------
    n_i : array_like, shape (N, 3)
        Unit directions transmitter -> facet [-] (world frame).
    n_s : array_like, shape (N, 3)
        Unit directions facet -> receiver [-].
    normal : array_like, shape (N, 3)
        Unit facet normals [-].
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity ``eps' - j eps''`` [-].
    spectrum : callable or array_like
        Height spectrum of the unresolved roughness ``W(kx, ky)`` [m^4], world-frame
        wavenumbers [rad/m] (``DirectionalSpectrum.height_spectrum`` or a
        :class:`BraggSpectrumTable`), or its values at the facets' Bragg vectors
        (:func:`bragg_vectors`), shape (N,) or scalar [m^4].
    mss_upwind, mss_crosswind : float or array_like (N,)
        Unresolved (sub-facet) slope variances [-], along and across the wind.
    wind_direction : float
        Direction the wind blows towards, CCW from +x [rad].
    model : {"blend", "kirchhoff", "spm"}
        ``w`` from eqs B3-B4, or 1, or 0.
    cox_munk : CoxMunkParameters, optional
        Use the Cox-Munk Gram-Charlier slope density (its own variances) for ``K``.
    wake_damping : array_like (N,), optional
        Turbulent-wake mask in [0, 1] (1 = Bragg waves fully damped); multiplies the
        Bragg sigma by ``1 - d``.
    local : mapping or object, optional
        Precomputed ``theta_i, theta_s, phi, rot_i, rot_s`` (e.g. a
        ``seaecho.geometry.facets.Facets`` or the dict of ``facet_frames``); computed
        with :mod:`.frames` when omitted.
    small_scale_height_variance : float, optional
        Height variance of the unresolved roughness [m^2]: warns
        (``SPMValidityWarning``) when ``k h > 0.3``.
    backend : {"auto", "numpy", "drjit"}
        ``"drjit"`` runs the fused Dr.Jit LLVM kernel (needs ``spectrum`` to be a
        :class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable`; ``local`` is
        then recomputed inside the kernel); ``"auto"`` picks it when possible.

    Returns
    -------
    FacetTerms

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring.
    """
    if model not in MODELS:
        raise ValueError(f"model = {model!r}: choose from {MODELS}")
    if model != "kirchhoff":
        check_spm_validity(k, small_scale_height_variance)
    n_i = np.ascontiguousarray(n_i, dtype=float).reshape(-1, 3)
    n_s = np.ascontiguousarray(n_s, dtype=float).reshape(-1, 3)
    nn = np.ascontiguousarray(normal, dtype=float).reshape(-1, 3)
    n = n_i.shape[0]
    eps = complex(eps_r)
    if backend not in ("auto", "numpy", "drjit"):
        raise ValueError(f"backend = {backend!r}: choose from 'auto', 'numpy', 'drjit'")
    is_table = isinstance(spectrum, BraggSpectrumTable)
    if backend == "drjit" and not is_table:
        raise ValueError("backend = 'drjit' needs spectrum to be a BraggSpectrumTable")
    if backend == "drjit" or (backend == "auto" and is_table and _drjit_available()):
        from ._drjit_kernel import facet_kernel

        damp = None if wake_damping is None else np.asarray(wake_damping, float).reshape(n)
        specular, bragg, weight = facet_kernel(n_i, n_s, nn, damp, k, eps, mss_upwind,
                                               mss_crosswind, float(wind_direction),
                                               spectrum, cox_munk, model)
        return FacetTerms(specular=specular, bragg=bragg, weight=weight)

    if local is None:
        theta_i, theta_s, phi = frames.local_angles(n_i, n_s, nn)
        rot_i, rot_s = frames.tilt_rotation(n_i, n_s, nn)
    else:
        theta_i, theta_s, phi = (np.asarray(_get(local, a)).reshape(n)
                                 for a in ("theta_i", "theta_s", "phi"))
        rot_i = np.asarray(_get(local, "rot_i")).reshape(n, 2, 2)
        rot_s = np.asarray(_get(local, "rot_s")).reshape(n, 2, 2)

    d = n_s - n_i
    qn = np.sqrt(_dot(d, d))
    cos_beta = np.where(qn > 1e-12, _dot(d, nn) / np.maximum(qn, 1e-12), 0.0)

    # Weights (eqs B1-B4), beta in degrees.
    if model == "blend":
        weight = channel_weights(np.degrees(np.arccos(np.clip(cos_beta, -1.0, 1.0))))
    else:
        weight = np.full((n, 4), 1.0 if model == "kirchhoff" else 0.0)

    # Bragg part, eq P2 (S7): local SPM rotated to the global bases.
    ci, cs = np.cos(theta_i), np.cos(theta_s)
    lit = (ci > 1e-12) & (cs > 1e-12)
    if model != "kirchhoff":
        ci_c, cs_c = np.clip(ci, 0.0, 1.0), np.clip(cs, 0.0, 1.0)
        alpha = _alpha(ci_c, np.sin(theta_i), cs_c, np.sin(theta_s), np.cos(phi), np.sin(phi),
                       eps)
        q = k * d
        qt = q - (k * qn * cos_beta)[:, None] * nn
        if callable(spectrum):
            w_b = np.asarray(spectrum(qt[:, 0], qt[:, 1]), dtype=float)
        else:
            w_b = np.broadcast_to(np.asarray(spectrum, dtype=float), (n,))
        amp = 4.0 * np.sqrt(np.pi) * k * k * ci_c * cs_c * np.sqrt(np.maximum(w_b, 0.0))
        if wake_damping is not None:
            amp = amp * np.sqrt(np.clip(1.0 - np.asarray(wake_damping, dtype=float).reshape(n),
                                        0.0, 1.0))
        amp = np.where(lit, amp, 0.0)
        bragg = _rotate(alpha, rot_i, rot_s) * amp[:, None]
    else:
        bragg = np.zeros((n, 4), dtype=complex)

    # Specular part, eq P1 (K1-K2).
    if model != "spm":
        h_i, v_i = frames.polarisation_basis(n_i)
        h_s, v_s = frames.polarisation_basis(n_s)
        n_sp = np.where((qn > 1e-12)[:, None], d / np.maximum(qn, 1e-12)[:, None], nn)
        f = _specular_matrix(n_i, n_s, n_sp, eps, h_i, v_i, h_s, v_s)
        mu = np.maximum(np.asarray(mss_upwind, dtype=float), 1e-12)
        mc = np.maximum(np.asarray(mss_crosswind, dtype=float), 1e-12)
        log_w, gc = kirchhoff_log_weight(n_i, n_s, mu, mc, wind_direction, nn,
                                         cox_munk=cox_munk)
        sk = np.where(lit, np.sqrt(gc) * np.exp(0.5 * log_w), 0.0)
        specular = f * sk[:, None]
    else:
        specular = np.zeros((n, 4), dtype=complex)
    return FacetTerms(specular=specular, bragg=bragg, weight=weight)


def bragg_vectors(n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike, k: float) -> NDArray:
    """Local Bragg wave vectors of facets (eq S7): (N, 2) world (kx, ky) [rad/m].

    The horizontal components of the part of ``q = k (n_s - n_i)`` tangent to each
    facet; evaluate the height spectrum there to pass values instead of a callable.
    """
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n_s = np.asarray(n_s, dtype=float).reshape(-1, 3)
    nn = np.asarray(normal, dtype=float).reshape(-1, 3)
    q = k * (n_s - n_i)
    qt = q - _dot(q, nn)[:, None] * nn
    return qt[:, :2]


def facet_sigma(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    wind_direction: float = 0.0,
    **kwargs: Any,
) -> NDArray:
    """Per-facet scattering coefficients ``sigma_mn`` (eq P3), shape (N, 4) [m^2/m^2].

    Same parameters as :func:`facet_terms` (keywords ``model``, ``cox_munk``,
    ``wake_damping``, ``local``, ``small_scale_height_variance``). Multiply by the facet
    area for its mean radar cross section [m^2]. Channels HH, HV, VH, VV in the global
    FSA bases (m received, n transmitted).
    """
    return facet_terms(n_i, n_s, normal, k, eps_r, spectrum, mss_upwind, mss_crosswind,
                       wind_direction, **kwargs).sigma()


def speckle_draws(n: int, rng: np.random.Generator) -> tuple[NDArray, NDArray]:
    """The circular complex Gaussians ``g_K, g_B`` (unit variance) of eq P4, shape (n,) each.

    ``rng.standard_normal((n, 4))`` once, scaled by sqrt(1/2): columns Re g_K, Im g_K,
    Re g_B, Im g_B. Draw them once per sea state and pass them to
    :func:`speckle_amplitudes` (``draws=``) to reuse them while the surface is held.
    """
    g = rng.standard_normal((n, 4)) * np.sqrt(0.5)
    return g[:, 0] + 1j * g[:, 1], g[:, 2] + 1j * g[:, 3]


def speckle_amplitudes(terms: FacetTerms, area: ArrayLike,
                       rng: np.random.Generator | None = None, *,
                       draws: tuple[NDArray, NDArray] | None = None) -> NDArray:
    """Eq P4: speckled complex amplitudes ``a_mn`` [m] of facets, shape (N, 4).

    Draws two circular complex Gaussians (unit variance) per facet, ``g_K`` then
    ``g_B``, from ``rng`` (:func:`speckle_draws`: ``standard_normal((N, 4))`` once), so a
    given generator state gives the same amplitudes; or takes them from ``draws``.

    Parameters
    ----------
    terms : FacetTerms
    area : array_like (N,)
        Facet areas [m^2].
    rng : numpy.random.Generator, optional
        Source of the draws (needed when ``draws`` is not given).
    draws : (g_K, g_B), optional
        Precomputed :func:`speckle_draws` (N,) complex each; same result as drawing them
        from the generator that made them.

    Returns
    -------
    ndarray of complex, shape (N, 4)
        ``E|a_mn|^2 = sigma_mn * area`` [m^2]; covariance eq P5.
    """
    n = terms.weight.shape[0]
    if draws is None:
        if rng is None:
            raise ValueError("speckle_amplitudes needs rng or draws")
        draws = speckle_draws(n, rng)
    g_k, g_b = draws
    if g_k.shape != (n,) or g_b.shape != (n,):
        raise ValueError(f"draws of shape {g_k.shape}, {g_b.shape}: need ({n},) each")
    sa = np.sqrt(np.asarray(area, dtype=float).reshape(-1))
    # Eq P4, in place (same operations and results as the plain expression
    # sa (sqrt(w) K g_K + sqrt(1 - w) B g_B), fewer temporaries)
    w = terms.weight
    out = np.sqrt(w) * terms.specular
    out *= g_k[:, None]
    wb = 1.0 - w
    np.sqrt(wb, out=wb)
    b = wb * terms.bragg
    b *= g_b[:, None]
    out += b
    out *= sa[:, None]
    return out


def speckled_facet_amplitudes(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    area: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    wind_direction: float = 0.0,
    *,
    draws: tuple[NDArray, NDArray],
    model: str = "blend",
    cox_munk: CoxMunkParameters | None = None,
    wake_damping: ArrayLike | None = None,
    local: Any = None,
    backend: str = "auto",
) -> NDArray:
    """Eqs P1-P4 in one pass: speckled amplitudes ``a_mn`` [m] of facets, shape (N, 4).

    ``speckle_amplitudes(facet_terms(...), area, draws=draws)`` (same parameters as
    :func:`facet_terms`, ``area`` (N,) [m^2], ``draws`` from :func:`speckle_draws`), the
    Dr.Jit backend going on to eq P4 inside the scattering kernel, so that ``K``, ``B``
    and ``w`` never come back to numpy (the per-pulse path of a simulation). The two
    backends agree within rounding (tests).

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring (eqs P1-P4).
    """
    n = np.shape(n_i)[0] if np.ndim(n_i) > 1 else 1
    is_table = isinstance(spectrum, BraggSpectrumTable)
    if backend not in ("auto", "numpy", "drjit"):
        raise ValueError(f"backend = {backend!r}: choose from 'auto', 'numpy', 'drjit'")
    if backend == "drjit" and not is_table:
        raise ValueError("backend = 'drjit' needs spectrum to be a BraggSpectrumTable")
    if model not in MODELS:
        raise ValueError(f"model = {model!r}: choose from {MODELS}")
    if not (backend == "drjit" or (backend == "auto" and is_table and _drjit_available())):
        terms = facet_terms(n_i, n_s, normal, k, eps_r, spectrum, mss_upwind, mss_crosswind,
                            wind_direction, model=model, cox_munk=cox_munk,
                            wake_damping=wake_damping, local=local, backend="numpy")
        return speckle_amplitudes(terms, area, draws=draws)
    from ._drjit_kernel import facet_kernel

    g_k, g_b = draws
    if g_k.shape != (n,) or g_b.shape != (n,):
        raise ValueError(f"draws of shape {g_k.shape}, {g_b.shape}: need ({n},) each")
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n_s = np.asarray(n_s, dtype=float).reshape(-1, 3)
    nn = np.asarray(normal, dtype=float).reshape(-1, 3)
    damp = None if wake_damping is None else np.asarray(wake_damping, float).reshape(n)
    a = np.asarray(area, dtype=float).reshape(n)
    return facet_kernel(n_i, n_s, nn, damp, k, complex(eps_r), mss_upwind, mss_crosswind,
                        float(wind_direction), spectrum, cox_munk, model,
                        speckle=(g_k, g_b, a))


def facet_amplitudes(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    area: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    rng: np.random.Generator,
    wind_direction: float = 0.0,
    **kwargs: Any,
) -> NDArray:
    """Speckled complex scattering amplitudes of facets (eqs P1-P5), shape (N, 4) [m].

    Channels HH, HV, VH, VV (m received, n transmitted, global FSA bases of
    :mod:`.frames`). Calibration: ``E|a_mn|^2 = sigma_mn * area``, so ``|a_mn|^2`` is
    the facet's radar cross section [m^2] in the bistatic radar equation; the phase
    is that of the scattering amplitude (propagation phases ``exp(-j k (r_t + r_r))``
    are the radar stage's). Keywords as :func:`facet_terms`.

    Parameters
    ----------
    n_i, n_s, normal : array_like, shape (N, 3)
        Unit directions Tx -> facet, facet -> Rx and facet normals [-].
    area : array_like (N,)
        Facet areas [m^2].
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity [-].
    spectrum : callable
        Height spectrum ``W(kx, ky)`` [m^4] of the unresolved roughness.
    mss_upwind, mss_crosswind : float or array_like (N,)
        Unresolved slope variances [-].
    rng : numpy.random.Generator
        Source of the speckle draws (one per pulse / time step).
    wind_direction : float
        Direction the wind blows towards [rad].

    Returns
    -------
    ndarray of complex, shape (N, 4)
    """
    terms = facet_terms(n_i, n_s, normal, k, eps_r, spectrum, mss_upwind, mss_crosswind,
                        wind_direction, **kwargs)
    return speckle_amplitudes(terms, area, rng)


def hhvv_coherence(terms: FacetTerms) -> NDArray:
    """Complex HH-VV correlation coefficient of facets implied by eq P5 [-], shape (N,).

    ``gamma = E[a_hh a_vv^*] / sqrt(E|a_hh|^2 E|a_vv|^2)``; 0 where both vanish.
    """
    c = terms.covariance()
    den = np.sqrt(c[:, 0, 0].real * c[:, 3, 3].real)
    return np.where(den > 0, c[:, 0, 3] / np.where(den > 0, den, 1.0), 0.0)


__all__ = ["MODELS", "FacetTerms", "bragg_vectors", "facet_amplitudes", "facet_sigma",
           "facet_terms", "hhvv_coherence", "speckle_amplitudes", "speckle_draws",
           "speckled_facet_amplitudes"]
