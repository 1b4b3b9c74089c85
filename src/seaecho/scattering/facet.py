"""Per-facet polarimetric scattering: sigma_mn and speckled complex amplitudes.

This is the interface between the surface (ray-traced or analytic facets) and the radar
equation. A facet of area ``A`` and unit normal ``N`` carries the
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

Implementation
--------------
Eqs P1-P5 are functions over an array namespace
(:mod:`seaecho.backend`): :func:`mechanisms` gives each mechanism's matrix and channel
weights, :func:`mechanism_sigma` eq P3 and :func:`speckle` eq P4. The numpy path
(``backend="numpy"``) and the fused Dr.Jit kernel (``backend="drjit"``, CPU or CUDA by
the ``variant``) run these same functions: the Dr.Jit path evaluates eqs P1-P4 in one
kernel per call. A further mechanism (e.g. breaking waves) is one more entry of
:func:`mechanisms` (its matrix and its channel weights, the weights of all mechanisms
summing to 1) and one more speckle draw: eqs P3-P5 sum over the entries.

References
----------
.. [1] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper"), eqs 1-3 and 7-11.
.. [2] Ulaby, F. T. and Long, D. G. (2014). *Microwave Radar and Radiometric Remote
   Sensing*, sec. 5-8 (speckle as a circular complex Gaussian field).
.. [3] Lee, J.-S. and Pottier, E. (2009). *Polarimetric Radar Imaging*, CRC, ch. 4
   (covariance matrices of distributed targets).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import backend as _backend
from ..backend import NUMPY, Boundary, Mat2
from ..geometry import frames
from .blend import kirchhoff_weights
from .kirchhoff import specular_direction, specular_matrix, specular_weight, wind_axes
from .slopes import CoxMunkParameters
from .spectrum_table import BraggSpectrumTable
from .spm import HeightSpectrum, azimuth_cos_sin, bragg_matrix, bragg_vector
from .twoscale import check_spm_validity

MODELS = ("blend", "kirchhoff", "spm")
BACKENDS = ("auto", "numpy", "drjit")

#: Facets behind which the transmitter or receiver lies (local cosine below) do not echo.
_BEHIND = 1e-12


def _drjit_available() -> bool:
    """True when the Dr.Jit LLVM backend imports and runs (checked once)."""
    return _backend.drjit_available()


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

    def mechanisms(self) -> dict[str, tuple[NDArray, NDArray]]:
        """The terms as :func:`mechanisms` gives them, channels on the last axis (N, 4)."""
        return {"specular": (self.specular, self.weight),
                "bragg": (self.bragg, 1.0 - self.weight)}

    def sigma(self) -> NDArray:
        """Eq P3: ``sigma_mn`` [m^2/m^2], shape (N, 4) (:func:`mechanism_sigma`)."""
        return mechanism_sigma(NUMPY, self.mechanisms())

    def covariance(self) -> NDArray:
        """Eq P5 per unit area: ``E[a a^H] / A``, shape (N, 4, 4) [m^2/m^2]."""
        k = np.sqrt(self.weight) * self.specular
        b = np.sqrt(1.0 - self.weight) * self.bragg
        return k[..., :, None] * k[..., None, :].conj() + b[..., :, None] * b[..., None, :].conj()


def _each(fn: Callable[[Any], Any], m: Any) -> Any:
    """``fn`` on every channel: on each entry of a Mat2, or on an array of channels."""
    return m.map(fn) if isinstance(m, Mat2) else fn(m)


def _get(local: Any, name: str):
    if isinstance(local, Mapping):
        return local[name]
    return getattr(local, name)


# ------------------------------------------------------------- formulas (any namespace)
def mechanisms(
    xp,
    n_i: Any,
    n_s: Any,
    N: Any,
    k: Any,
    eps_r: Any,
    spectrum: Callable[[Any, Any], Any],
    mss_upwind: Any,
    mss_crosswind: Any,
    cos_wind: Any,
    sin_wind: Any,
    *,
    model: str = "blend",
    cox_munk: CoxMunkParameters | None = None,
    damping: Any = None,
    local: tuple | None = None,
) -> dict[str, tuple[Mat2, Mat2]]:
    """Eqs P1-P2 and B1-B4: each mechanism's matrix and channel weights, per facet.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    n_i, n_s, N : vectors
        Unit directions Tx -> facet, facet -> Rx and unit facet normals [-].
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity [-].
    spectrum : callable
        ``W(kx, ky)`` [m^4] of the unresolved roughness on namespace arrays [rad/m].
    mss_upwind, mss_crosswind : arrays
        Unresolved slope variances [-].
    cos_wind, sin_wind : arrays
        Direction the wind blows towards, as a unit vector's components [-].
    model : {"blend", "kirchhoff", "spm"}
    cox_munk : CoxMunkParameters, optional
        Cox-Munk Gram-Charlier slopes for ``K``.
    damping : array, optional
        Turbulent-wake damping ``d`` in [0, 1].
    local : tuple, optional
        ``(cos_i, cos_s, cos_phi, sin_phi, A_i, A_s)`` of the facets' local frames, if
        already known (else from :mod:`seaecho.geometry.frames`).

    Returns
    -------
    dict
        ``{"specular": (K, w), "bragg": (B, 1 - w)}`` (the mechanisms of ``model``), each
        a pair of :class:`~seaecho.backend.Mat2`: the complex mechanism matrix [-] in the
        global FSA bases and its weight per channel [-].

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring (eqs P1, P2).
    """
    z = xp.vec(0.0, 0.0, 1.0)
    basis_i = frames.fsa_basis(xp, n_i, z)
    basis_s = frames.fsa_basis(xp, n_s, z)
    if local is None:
        cos_i, cos_s, x_s, y_s = frames.local_geometry(xp, n_i, n_s, N)
        cos_phi, sin_phi = azimuth_cos_sin(xp, x_s, y_s)
        a_i = frames.basis_change(xp, basis_i, frames.fsa_basis(xp, n_i, N))
        a_s = frames.basis_change(xp, basis_s, frames.fsa_basis(xp, n_s, N))
    else:
        cos_i, cos_s, cos_phi, sin_phi, a_i, a_s = local
    lit = (cos_i > _BEHIND) & (cos_s > _BEHIND)
    # Kirchhoff weight per channel, eqs B1-B4 (beta in degrees)
    if model == "blend":
        c_beta = frames.cos_beta(xp, n_i, n_s, N)
        w = kirchhoff_weights(xp, xp.acos(xp.clip(c_beta, -1.0, 1.0)) * (180.0 / math.pi))
    else:
        one = 1.0 if model == "kirchhoff" else 0.0
        w = Mat2(one, one, one, one)
    out: dict[str, tuple[Mat2, Mat2]] = {}
    if model != "spm":
        # Eq P1: K = sqrt(pi P(Z)) |q|^2 / q_N^2 F (eqs K1-K2)
        n_sp = specular_direction(xp, n_i, n_s, N)
        f = specular_matrix(xp, n_i, n_s, n_sp, eps_r, basis_i, basis_s)
        e_u, e_c = wind_axes(xp, N, cos_wind, sin_wind)
        log_w, gc = specular_weight(xp, n_sp, N, e_u, e_c, xp.maximum(mss_upwind, 1e-12),
                                    xp.maximum(mss_crosswind, 1e-12), cox_munk)
        out["specular"] = (f * xp.select(lit, xp.sqrt(gc) * xp.exp(0.5 * log_w), 0.0), w)
    if model != "kirchhoff":
        # Eq P2: B = 4 sqrt(pi) k^2 cos cos A_s^T alpha A_i sqrt(W (1 - d)) (eq S7)
        kx, ky = bragg_vector(xp, n_i, n_s, N, k)
        rough = xp.sqrt(xp.maximum(spectrum(kx, ky), 0.0))
        if damping is not None:
            rough = rough * xp.sqrt(xp.clip(1.0 - damping, 0.0, 1.0))
        b = bragg_matrix(xp, k, eps_r, cos_i, cos_s, cos_phi, sin_phi, a_i, a_s,
                         roughness=rough)
        out["bragg"] = (b, w.map(lambda x: 1.0 - x))
    return out


def mechanism_sigma(xp, mech: Mapping[str, tuple[Any, Any]]) -> Any:
    """Eq P3: ``sigma_mn = sum_j w_j,mn |M_j,mn|^2`` [m^2/m^2] (j the mechanisms).

    Each mechanism is ``(M, w)``: two :class:`~seaecho.backend.Mat2`, or two arrays with
    the channels HH, HV, VH, VV on the last axis.
    """
    total = None
    for m, w in mech.values():
        term = w * _each(xp.abs2, m)
        total = term if total is None else total + term
    return total


def speckle(xp, mech: Mapping[str, tuple[Any, Any]], draws: Mapping[str, Any],
            area: Any) -> Any:
    """Eq P4: ``a_mn = sqrt(A) sum_j sqrt(w_j,mn) M_j,mn g_j`` [m].

    ``draws[j]`` is mechanism j's circular complex Gaussian (unit variance), the same for
    the four channels; ``area`` the facet area [m^2]. Mechanisms as
    :func:`mechanism_sigma` (with channel arrays, ``draws`` and ``area`` broadcast
    against them).
    """
    total = None
    for name, (m, w) in mech.items():
        term = _each(xp.sqrt, w) * m  # a new array: scaled in place below (numpy)
        term *= draws[name]
        if total is None:
            total = term
        else:
            total += term
    total *= xp.sqrt(area)
    return total


# ----------------------------------------------------------------- the numpy boundary
def _kernel_inputs(io: Boundary, n_i, n_s, normal, k, eps_r, spectrum, mss_upwind,
                   mss_crosswind, wind_direction, wake_damping, n: int) -> dict:
    """Namespace arrays and constants of :func:`mechanisms` from numpy inputs."""
    xp = io.xp

    def per_facet(a):
        return io.array(np.broadcast_to(np.asarray(a, dtype=float), (n,))) if np.ndim(
            a) else xp.const(a)

    if isinstance(spectrum, BraggSpectrumTable):
        def lookup(kx, ky, table=spectrum):
            return table.lookup(xp, kx, ky)
    elif callable(spectrum):
        if not xp.is_numpy:
            raise ValueError("the Dr.Jit back end needs spectrum to be a BraggSpectrumTable")

        def lookup(kx, ky, fn=spectrum):
            return np.asarray(fn(kx, ky), dtype=float)
    else:
        values = per_facet(spectrum)

        def lookup(kx, ky, values=values):
            return values

    w = float(wind_direction)
    return dict(
        n_i=io.vec3(n_i), n_s=io.vec3(n_s), N=io.vec3(normal), k=xp.const(k),
        eps_r=xp.cconst(eps_r), spectrum=lookup, mss_upwind=per_facet(mss_upwind),
        mss_crosswind=per_facet(mss_crosswind), cos_wind=xp.const(math.cos(w)),
        sin_wind=xp.const(math.sin(w)),
        damping=None if wake_damping is None else io.array(
            np.asarray(wake_damping, dtype=float).reshape(n)))


def _local_frames(local: Any, n: int) -> tuple:
    """``(cos_i, cos_s, cos_phi, sin_phi, A_i, A_s)`` of precomputed facet frames."""
    theta_i, theta_s, phi = (np.asarray(_get(local, a), dtype=float).reshape(n)
                             for a in ("theta_i", "theta_s", "phi"))
    rot = [np.asarray(_get(local, a), dtype=float).reshape(n, 2, 2) for a in ("rot_i", "rot_s")]
    a_i, a_s = (Mat2(r[:, 0, 0], r[:, 0, 1], r[:, 1, 0], r[:, 1, 1]) for r in rot)
    return np.cos(theta_i), np.cos(theta_s), np.cos(phi), np.sin(phi), a_i, a_s


def _namespace(backend: str, spectrum: Any, variant: str | None):
    if backend not in BACKENDS:
        raise ValueError(f"backend = {backend!r}: choose from {', '.join(map(repr, BACKENDS))}")
    is_table = isinstance(spectrum, BraggSpectrumTable)
    if backend == "drjit" and not is_table:
        raise ValueError("backend = 'drjit' needs spectrum to be a BraggSpectrumTable")
    if backend == "numpy" or (backend == "auto" and not is_table):
        return NUMPY
    return _backend.namespace(backend, variant)


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
    variant: str | None = None,
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
        with :mod:`seaecho.geometry.frames` when omitted. The Dr.Jit back end recomputes
        them inside its kernel (cheaper than reading them).
    small_scale_height_variance : float, optional
        Height variance of the unresolved roughness [m^2]: warns
        (``SPMValidityWarning``) when ``k h > 0.3``.
    backend : {"auto", "numpy", "drjit"}
        ``"drjit"`` runs :func:`mechanisms` as one fused Dr.Jit kernel (needs
        ``spectrum`` to be a :class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable`);
        ``"auto"`` picks it when possible; ``"numpy"`` runs the same formulas on numpy.
    variant : str, optional
        Mitsuba variant choosing the Dr.Jit back end: ``"llvm_ad_mono_polarized"`` (CPU,
        default) or ``"cuda_ad_mono_polarized"`` (GPU) (:mod:`seaecho.backend`).

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
    xp = _namespace(backend, spectrum, variant)
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n = n_i.shape[0]
    io = Boundary(xp, n)
    args = _kernel_inputs(io, n_i, np.asarray(n_s, dtype=float).reshape(-1, 3),
                          np.asarray(normal, dtype=float).reshape(-1, 3), k, complex(eps_r),
                          spectrum, mss_upwind, mss_crosswind, wind_direction, wake_damping, n)
    frames_in = _local_frames(local, n) if (local is not None and xp.is_numpy) else None
    mech = mechanisms(xp, **args, model=model, cox_munk=cox_munk, local=frames_in)
    w = (mech.get("specular") or mech["bragg"])[1]
    if "specular" not in mech:
        w = w.map(lambda x: 1.0 - x)
    outs = [w] + [mech[m][0] for m in ("specular", "bragg") if m in mech]
    res = io.numpy(*outs)
    weight = res.pop(0).reshape(n, 4)
    specular = res.pop(0).reshape(n, 4) if "specular" in mech else np.zeros((n, 4), complex)
    bragg = res.pop(0).reshape(n, 4) if "bragg" in mech else np.zeros((n, 4), complex)
    return FacetTerms(specular=specular, bragg=bragg, weight=weight)


def bragg_vectors(n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike, k: float) -> NDArray:
    """Local Bragg wave vectors of facets (eq S7): (N, 2) world (kx, ky) [rad/m].

    The horizontal components of the part of ``q = k (n_s - n_i)`` tangent to each
    facet; evaluate the height spectrum there to pass values instead of a callable.
    Formula: :func:`seaecho.scattering.spm.bragg_vector`.
    """
    io = Boundary(NUMPY)
    kx, ky = bragg_vector(NUMPY, *(io.vec3(np.asarray(a, dtype=float).reshape(-1, 3))
                                   for a in (n_i, n_s, normal)), float(k))
    return np.stack([kx, ky], axis=-1)


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
    area = np.asarray(area, dtype=float).reshape(-1, 1)
    return speckle(NUMPY, terms.mechanisms(), {"specular": g_k[:, None], "bragg": g_b[:, None]},
                   area)


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
    variant: str | None = None,
) -> NDArray:
    """Eqs P1-P4 in one pass: speckled amplitudes ``a_mn`` [m] of facets, shape (N, 4).

    ``speckle_amplitudes(facet_terms(...), area, draws=draws)`` (same parameters as
    :func:`facet_terms`, ``area`` (N,) [m^2], ``draws`` from :func:`speckle_draws`):
    :func:`mechanisms` followed by :func:`speckle`, which the Dr.Jit back end evaluates
    as one kernel, so that ``K``, ``B`` and ``w`` never come back to numpy (the per-pulse
    path of a simulation). The back ends agree within rounding (tests).

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring (eqs P1-P4).
    """
    if model not in MODELS:
        raise ValueError(f"model = {model!r}: choose from {MODELS}")
    xp = _namespace(backend, spectrum, variant)
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n = n_i.shape[0]
    g_k, g_b = draws
    if np.shape(g_k) != (n,) or np.shape(g_b) != (n,):
        raise ValueError(f"draws of shape {np.shape(g_k)}, {np.shape(g_b)}: need ({n},) each")
    io = Boundary(xp, n)
    args = _kernel_inputs(io, n_i, np.asarray(n_s, dtype=float).reshape(-1, 3),
                          np.asarray(normal, dtype=float).reshape(-1, 3), k, complex(eps_r),
                          spectrum, mss_upwind, mss_crosswind, wind_direction, wake_damping, n)
    frames_in = _local_frames(local, n) if (local is not None and xp.is_numpy) else None
    mech = mechanisms(xp, **args, model=model, cox_munk=cox_munk, local=frames_in)
    g = {"specular": io.complex(g_k), "bragg": io.complex(g_b)}
    a = speckle(xp, mech, g, io.array(np.asarray(area, dtype=float).reshape(n)))
    (out,) = io.numpy(a)
    return out.reshape(n, 4)


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


__all__ = ["BACKENDS", "MODELS", "FacetTerms", "bragg_vectors", "facet_amplitudes",
           "facet_sigma", "facet_terms", "hhvv_coherence", "mechanism_sigma", "mechanisms",
           "speckle", "speckle_amplitudes", "speckle_draws", "speckled_facet_amplitudes"]
