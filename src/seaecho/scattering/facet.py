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

(eqs K1-K2 and S7; ``d <= 1`` the wake's damping, 1 = Bragg waves fully
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
The sea's scattering inputs travel as one frozen :class:`FacetModel` (wavenumber,
permittivity, roughness spectrum, unresolved slopes, wind, model, tilt nodes, breaking
tilt; ``SeaModel.facet_model`` makes a scene's), which every entry point takes whole;
:func:`kernel_sea` turns it into the namespace values :func:`mechanisms` reads
(:class:`KernelSea`), for the numpy path and for the fused kernels of ``radar.resident``
alike. Eqs P1-P5 are functions over an array namespace
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

import dataclasses
import math
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import backend as _backend
from ..backend import NUMPY, Boundary, Mat2
from ..geometry import frames
from .blend import kirchhoff_weights
from .breaking import breaking_matrix
from .kirchhoff import specular_direction, specular_matrix, specular_weight, wind_axes
from .slopes import CoxMunkParameters
from .spectrum_table import BraggSpectrumTable
from .spm import azimuth_cos_sin, bragg_matrix, bragg_vector
from .twoscale import check_spm_validity

MODELS = ("blend", "kirchhoff", "spm")
#: Working precision of eqs P1-P7 in a simulation's per-pulse Dr.Jit kernels (the fused
#: pulse of ``radar.resident`` and the reference path of ``Simulation.sea_echo``):
#: ``"single"`` (float32, the default) or ``"double"``, from the environment variable
#: ``SEAECHO_SCATTERING_PRECISION``. The geometry, the delays, the carrier phase and the
#: radar equation's magnitudes are float64 in either; the functions of this module take
#: ``precision="double"`` unless told otherwise, and numpy is float64 throughout
#: (docs/scattering.md, "Working precision").
PRECISION = os.environ.get("SEAECHO_SCATTERING_PRECISION", "single")
BACKENDS = ("auto", "numpy", "drjit")

#: Facets behind which the transmitter or receiver lies (local cosine below) do not echo.
_BEHIND = 1e-12


def _drjit_available() -> bool:
    """True when the Dr.Jit LLVM backend imports and runs (checked once)."""
    return _backend.drjit_available()


@dataclass(frozen=True)
class TiltQuadrature:
    """Nodes of the average over the unresolved tilts (eq P6), in the facet's wind frame.

    The slopes ``(Z_u, Z_c)`` of the waves between the grid's Nyquist wavenumber and the
    two-scale split tilt the Bragg-scattering plane of a facet; eq P6 averages the Bragg
    term over their Gaussian density with the five-point *unscented* rule (Julier &
    Uhlmann 2004): the centre with weight 1/3 and the four axis points
    ``(+-sqrt(3) s_u, 0)``, ``(0, +-sqrt(3) s_c)`` with weight 1/6 each, exact for the
    mean of polynomials of degree 3 and for the fourth moments ``<Z_u^4>``, ``<Z_c^4>``.
    Each weight carries the area ``sqrt(1 + Z^2)`` of a sub-facet per unit facet area
    (eq T1).

    Attributes
    ----------
    slopes : tuple of (float, float)
        ``(Z_u, Z_c)`` of the four axis nodes [-] (the centre is the facet itself).
    weights : tuple of float
        Weights of the centre then of the four axis nodes (area factor included) [-].
    """

    slopes: tuple[tuple[float, float], ...]
    weights: tuple[float, ...]

    @classmethod
    def unscented(cls, mss_upwind: float, mss_crosswind: float) -> TiltQuadrature:
        """The five-point rule for the unresolved slope variances ``s_u^2``, ``s_c^2`` [-].

        References
        ----------
        .. [1] Julier, S. J. and Uhlmann, J. K. (2004). Unscented filtering and nonlinear
           estimation. *Proc. IEEE* 92(3), 401-422 (sigma points with kappa = 3 - n).
        """
        if not (mss_upwind >= 0.0 and mss_crosswind >= 0.0):
            raise ValueError(f"mss_upwind = {mss_upwind}, mss_crosswind = {mss_crosswind}: "
                             "slope variances must be >= 0 [-]")
        zu, zc = math.sqrt(3.0 * mss_upwind), math.sqrt(3.0 * mss_crosswind)
        au, ac = math.sqrt(1.0 + zu * zu), math.sqrt(1.0 + zc * zc)
        return cls(slopes=((zu, 0.0), (-zu, 0.0), (0.0, zc), (0.0, -zc)),
                   weights=(1.0 / 3.0, au / 6.0, au / 6.0, ac / 6.0, ac / 6.0))

    @classmethod
    def gauss_hermite(cls, mss_upwind: float, mss_crosswind: float,
                      n: int = 3) -> TiltQuadrature:
        """Tensor-product Gauss-Hermite rule of ``n x n`` nodes (odd ``n``: the centre
        is a node), area factor included: the reference for :meth:`unscented`."""
        if n < 1 or n % 2 == 0:
            raise ValueError(f"n = {n}: need an odd number of nodes per axis")
        x, w = np.polynomial.hermite.hermgauss(n)
        x, w = x * math.sqrt(2.0), w / math.sqrt(math.pi)
        su, sc = math.sqrt(mss_upwind), math.sqrt(mss_crosswind)
        nodes, weights = [], []
        for i in range(n):
            for j in range(n):
                zu, zc = float(x[i] * su), float(x[j] * sc)
                c = float(w[i] * w[j]) * math.sqrt(1.0 + zu * zu + zc * zc)
                if i == j == n // 2:
                    weights.insert(0, c)
                else:
                    nodes.append((zu, zc))
                    weights.append(c)
        return cls(slopes=tuple(nodes), weights=tuple(weights))


#: Names of the mechanisms of eqs P1-P6, in the order the sums take them.
MECHANISMS = ("specular", "bragg", "bragg1", "bragg2", "bragg3", "bragg4", "breaking")


@dataclass(frozen=True)
class FacetModel:
    """The sea's scattering inputs of eqs P1-P7 (SI), one frozen object.

    The numpy path and the fused Dr.Jit kernels take it whole (:func:`kernel_sea`);
    ``SeaModel.facet_model`` makes a scene's. The per-facet quantities that change from
    block to block (the wake's damping, the breaking zones' fractions) are the entry
    points' keywords.

    Attributes
    ----------
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity ``eps' - j eps''`` [-].
    spectrum : callable, BraggSpectrumTable or array_like
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
    tilt : TiltQuadrature, optional
        Average the Bragg term over the unresolved tilts (eq P6).
    breaking_tilt : float
        Forward tilt of the breaking zones ``theta_wb A_wb`` [rad] (BR5).
    """

    k: float
    eps_r: complex
    spectrum: Any
    mss_upwind: Any = 0.0
    mss_crosswind: Any = 0.0
    wind_direction: float = 0.0
    model: str = "blend"
    cox_munk: CoxMunkParameters | None = None
    tilt: TiltQuadrature | None = None
    breaking_tilt: float = 0.0

    def __post_init__(self) -> None:
        if self.model not in MODELS:
            raise ValueError(f"model = {self.model!r}: choose from {MODELS}")

    def with_(self, **changes: Any) -> FacetModel:
        """A copy with some attributes changed (``dataclasses.replace``)."""
        return dataclasses.replace(self, **changes)


@dataclass(frozen=True)
class KernelSea:
    """A :class:`FacetModel`'s values in an array namespace: what :func:`mechanisms` reads.

    ``k``, ``eps_r``, ``mss_upwind``, ``mss_crosswind``, ``cos_wind``, ``sin_wind``
    (the wind's unit vector) and ``breaking_tilt`` are namespace constants or per-facet
    arrays, ``spectrum`` the look-up ``W(kx, ky)`` on namespace arrays [m^4]; ``model``,
    ``cox_munk`` and ``tilt`` as :class:`FacetModel`.
    """

    k: Any
    eps_r: Any
    spectrum: Callable[[Any, Any], Any]
    mss_upwind: Any
    mss_crosswind: Any
    cos_wind: Any
    sin_wind: Any
    breaking_tilt: Any = 0.0
    model: str = "blend"
    cox_munk: CoxMunkParameters | None = None
    tilt: TiltQuadrature | None = None


@dataclass(frozen=True)
class FacetTerms:
    """Mechanism matrices and weights of eqs P1-P3, P6-P7 (all shaped (N, 4), HH, HV, VH, VV).

    Attributes
    ----------
    specular : ndarray of complex
        ``K`` [-]: ``|K|^2`` is the Kirchhoff/GO sigma.
    bragg : ndarray of complex
        ``B`` [-] of the facet's own plane: ``|B|^2`` is the SPM sigma (damping included).
    weight : ndarray
        Kirchhoff weight ``w`` per channel [-].
    tilted : tuple of ndarray of complex
        ``B_n`` of the unresolved-tilt nodes n = 1..4 (eq P6), empty without them.
    tilt_weights : tuple of float
        Node weights ``c_0 .. c_4`` of eq P6 (empty: ``c_0 = 1``).
    breaking : ndarray of complex or None
        ``W`` of the breaking zones (eq P7, BR5-BR6).
    breaking_fraction : ndarray (N,) or None
        Fraction ``q`` of each facet covered by breaking zones [-].
    """

    specular: NDArray
    bragg: NDArray
    weight: NDArray
    tilted: tuple[NDArray, ...] = ()
    tilt_weights: tuple[float, ...] = ()
    breaking: NDArray | None = None
    breaking_fraction: NDArray | None = None

    def mechanisms(self) -> dict[str, tuple[NDArray, NDArray]]:
        """The terms as :func:`mechanisms` gives them, channels on the last axis (N, 4)."""
        q = None if self.breaking_fraction is None else np.asarray(
            self.breaking_fraction, dtype=float).reshape(-1, 1)
        w_k, w_b = self.weight, 1.0 - self.weight
        if q is not None:
            w_k, w_b = w_k * (1.0 - q), w_b * (1.0 - q)
        c0 = self.tilt_weights[0] if self.tilt_weights else 1.0
        out = {"specular": (self.specular, w_k),
               "bragg": (self.bragg, w_b if c0 == 1.0 else w_b * c0)}
        for j, b in enumerate(self.tilted):
            out[f"bragg{j + 1}"] = (b, w_b * self.tilt_weights[j + 1])
        if self.breaking is not None:
            out["breaking"] = (self.breaking, np.broadcast_to(
                np.zeros((1, 1)) if q is None else q, self.breaking.shape))
        return out

    def sigma(self) -> NDArray:
        """Eq P3: ``sigma_mn`` [m^2/m^2], shape (N, 4) (:func:`mechanism_sigma`)."""
        return mechanism_sigma(NUMPY, self.mechanisms())

    def covariance(self) -> NDArray:
        """Eq P5 per unit area: ``E[a a^H] / A``, shape (N, 4, 4) [m^2/m^2]."""
        out = None
        for m, w in self.mechanisms().values():
            a = np.sqrt(w) * m
            c = a[..., :, None] * a[..., None, :].conj()
            out = c if out is None else out + c
        return out


class NodeWeights(Mat2):
    """Channel weights ``c_n w_mn`` [-] of a tilt node (eq P6) with their square roots.

    ``root`` holds ``sqrt(c_n) sqrt(w_mn)``: the nodes share one square root of ``w_mn``
    per channel (:func:`speckle`'s amplitudes), four instead of twenty.
    """

    __slots__ = ("root",)

    def __init__(self, w: Mat2, root: Mat2, c: float) -> None:
        super().__init__(*(w * c).flat())
        self.root = root * math.sqrt(c)


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
    sea: KernelSea,
    *,
    damping: Any = None,
    breaking: Any = None,
    local: tuple | None = None,
    context: dict | None = None,
    monostatic: bool = False,
) -> dict[str, tuple[Mat2, Mat2]]:
    """Eqs P1-P2, P6-P7 and B1-B4: each mechanism's matrix and channel weights, per facet.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    n_i, n_s, N : vectors
        Unit directions Tx -> facet, facet -> Rx and unit facet normals [-].
    sea : KernelSea
        The sea's scattering inputs in ``xp`` (:func:`kernel_sea`): wavenumber [rad/m],
        permittivity [-], the roughness look-up ``W(kx, ky)`` [m^4], unresolved slope
        variances [-], the wind's unit vector, the model (``"blend"``, ``"kirchhoff"``,
        ``"spm"``), Cox-Munk slopes, the tilt nodes of eq P6 (entries ``"bragg1"`` ..
        ``"bragg4"`` for the axis nodes, the centre weight on ``"bragg"``) and the
        breaking zones' forward tilt [rad] (BR5).
    damping : array, optional
        Wake damping ``d <= 1`` (negative where the narrow-V wake adds Bragg waves).
    breaking : array, optional
        Fraction ``q`` of each facet covered by breaking zones [-]: an entry
        ``"breaking"`` (eq P7) and the weights of the others times ``1 - q``.
    local : tuple, optional
        ``(cos_i, cos_s, cos_phi, sin_phi, A_i, A_s)`` of the facets' local frames, if
        already known (else from :mod:`seaecho.geometry.frames`).
    context : dict, optional
        Filled with intermediate per-facet values that a caller may reuse in the same
        kernel: ``"bragg_vector"`` (kx, ky of the facet's plane) [rad/m].
    monostatic : bool
        ``n_s`` is ``-n_i`` (the same transmit and receive position): the receive side's
        FSA bases and local cosines are taken from the transmit side's
        (:func:`seaecho.geometry.frames.reversed_fsa_basis`), the numbers that computing
        them gives, to the bit, for fewer operations.

    Returns
    -------
    dict
        ``{"specular": (K, w), "bragg": (B, 1 - w), ...}`` (the mechanisms of ``model``),
        each a pair of :class:`~seaecho.backend.Mat2`: the complex mechanism matrix [-]
        in the global FSA bases and its weight per channel [-].

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring (eqs P1, P2).
    """
    k, eps_r, spectrum, model, tilt = sea.k, sea.eps_r, sea.spectrum, sea.model, sea.tilt
    cos_wind, sin_wind = sea.cos_wind, sea.sin_wind
    z = xp.vec(0.0, 0.0, 1.0)
    basis_i = frames.fsa_basis(xp, n_i, z)

    def local_frames(normal: Any) -> tuple[Any, ...]:
        """Local angles and the rotations A_i, A_s of the plane of ``normal``."""
        ci, cs, x_s, y_s = frames.local_geometry(xp, n_i, n_s, normal)
        if monostatic:  # dot(-n_i, N) is -dot(n_i, N) to the bit: one cosine, so that
            cs = ci     # the receive side's terms of eqs S3-S6 are the transmit side's
        cp, sp = azimuth_cos_sin(xp, x_s, y_s)
        a_i = frames.basis_change(xp, basis_i, frames.fsa_basis(xp, n_i, normal))
        if monostatic:
            return ci, cs, cp, sp, a_i, frames.reversed_basis_change(xp, a_i, n_i, z, normal)
        return (ci, cs, cp, sp, a_i,
                frames.basis_change(xp, basis_s, frames.fsa_basis(xp, n_s, normal)))

    basis_s = (frames.reversed_fsa_basis(xp, basis_i, n_i, z) if monostatic
               else frames.fsa_basis(xp, n_s, z))
    if local is None:
        cos_i, cos_s, cos_phi, sin_phi, a_i, a_s = local_frames(N)
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
    if context is not None:
        context["weight"] = w
    keep = None if breaking is None else 1.0 - breaking
    out: dict[str, tuple[Mat2, Mat2]] = {}
    e_u = e_c = None
    if model != "spm":
        # Eq P1: K = sqrt(pi P(Z)) |q|^2 / q_N^2 F (eqs K1-K2)
        n_sp = specular_direction(xp, n_i, n_s, N)
        f = specular_matrix(xp, n_i, n_s, n_sp, eps_r, basis_i, basis_s)
        e_u, e_c = wind_axes(xp, N, cos_wind, sin_wind)
        log_w, gc = specular_weight(xp, n_sp, N, e_u, e_c, xp.maximum(sea.mss_upwind, 1e-12),
                                    xp.maximum(sea.mss_crosswind, 1e-12), sea.cox_munk)
        out["specular"] = (f * xp.select(lit, xp.sqrt(gc) * xp.exp(0.5 * log_w), 0.0),
                           w if keep is None else w * keep)
    if model != "kirchhoff":
        # Eq P2: B = 4 sqrt(pi) k^2 cos cos A_s^T alpha A_i sqrt(W (1 - d)) (eq S7)
        damp = None if damping is None else xp.sqrt(xp.maximum(1.0 - damping, 0.0))
        kx, ky = bragg_vector(xp, n_i, n_s, N, k)
        if context is not None:
            context["bragg_vector"] = (kx, ky)
        rough = xp.sqrt(xp.maximum(spectrum(kx, ky), 0.0))
        if damp is not None:
            rough = rough * damp
        b = bragg_matrix(xp, k, eps_r, cos_i, cos_s, cos_phi, sin_phi, a_i, a_s,
                         roughness=rough)
        w_b = w.map(lambda x: 1.0 - x)
        if keep is not None:
            w_b = w_b * keep
        if tilt is None:
            out["bragg"] = (b, w_b)
        else:
            root_b = w_b.map(xp.sqrt)
            out["bragg"] = (b, NodeWeights(w_b, root_b, tilt.weights[0]))
            if e_u is None:
                e_u, e_c = wind_axes(xp, N, cos_wind, sin_wind)
            for j, (zu, zc) in enumerate(tilt.slopes):
                # Eq P6: the facet's Bragg term on the plane tilted by a node's slopes
                n_j = xp.normalize(N - e_u * xp.const(zu) - e_c * xp.const(zc))
                ci, cs, cp, sp, ai, as_ = local_frames(n_j)
                kxj, kyj = bragg_vector(xp, n_i, n_s, n_j, k)
                rj = xp.sqrt(xp.maximum(spectrum(kxj, kyj), 0.0))
                if damp is not None:
                    rj = rj * damp
                bj = bragg_matrix(xp, k, eps_r, ci, cs, cp, sp, ai, as_, roughness=rj)
                out[f"bragg{j + 1}"] = (bj, NodeWeights(w_b, root_b, tilt.weights[j + 1]))
    if breaking is not None:
        # Eq P7: breaking zones (BR5-BR6) on the facet's plane, weight q
        wb = breaking_matrix(xp, n_i, n_s, N, basis_i, basis_s, cos_wind, sin_wind,
                             sea.breaking_tilt).map(lambda e: xp.complex(e, 0.0 * e))
        out["breaking"] = (wb, Mat2(breaking, breaking, breaking, breaking))
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
        root = w.root if isinstance(w, NodeWeights) else _each(xp.sqrt, w)
        term = root * m  # a new array: scaled in place below (numpy)
        term *= draws[name]
        if total is None:
            total = term
        else:
            total += term
    total *= xp.sqrt(area)
    return total


# ----------------------------------------------------------------- the numpy boundary
def kernel_sea(io: Boundary, sea: FacetModel, xs=None) -> KernelSea:
    """A :class:`FacetModel` as the values of :func:`mechanisms` in ``xs`` [SI].

    Made in ``io.xp`` (float64) and cast to ``xs``, the namespace of the scattering
    formulas (``io.xp`` by default; its float32 twin in single precision), where the
    spectrum is looked up: the reference path and the fused pulse kernel
    (``radar.resident``) both call this function, so both start from the same values.

    Parameters
    ----------
    io : Boundary
        The kernel's boundary (namespace and facet count, for per-facet slopes).
    sea : FacetModel
    xs : array namespace, optional
    """
    xp = io.xp
    xs = xp if xs is None else xs
    n = io.n

    def per_facet(a):
        return io.array(np.broadcast_to(np.asarray(a, dtype=float), (n,))) if np.ndim(
            a) else xp.const(a)

    spectrum = sea.spectrum
    if isinstance(spectrum, BraggSpectrumTable):
        def lookup(kx, ky, table=spectrum):
            return table.lookup(xs, kx, ky)
    elif callable(spectrum):
        if not xp.is_numpy:
            raise ValueError("the Dr.Jit back end needs spectrum to be a BraggSpectrumTable")

        def lookup(kx, ky, fn=spectrum):
            return np.asarray(fn(kx, ky), dtype=float)
    else:
        values = xs.cast(per_facet(spectrum))

        def lookup(kx, ky, values=values):
            return values

    w = float(sea.wind_direction)
    return KernelSea(
        k=xs.cast(xp.const(sea.k)), eps_r=xs.cast(xp.cconst(complex(sea.eps_r))),
        spectrum=lookup, mss_upwind=xs.cast(per_facet(sea.mss_upwind)),
        mss_crosswind=xs.cast(per_facet(sea.mss_crosswind)),
        cos_wind=xs.cast(xp.const(math.cos(w))), sin_wind=xs.cast(xp.const(math.sin(w))),
        breaking_tilt=xs.cast(xp.const(float(sea.breaking_tilt))), model=sea.model,
        cox_munk=sea.cox_munk, tilt=sea.tilt)


def facet_arrays(io: Boundary, xs, wake_damping: Any = None,
                 breaking_fraction: Any = None) -> tuple[Any, Any]:
    """The per-facet ``damping`` and ``breaking`` of :func:`mechanisms` in ``xs`` [-].

    Numpy arrays (or numbers) go through ``io`` (float64) and are cast, as
    :func:`kernel_sea` does; device arrays of ``io.xp`` are cast; None stays None.
    """
    n = io.n

    def one(a, check=None):
        if a is None:
            return None
        if isinstance(a, np.ndarray | float | int):
            a = np.asarray(a if check is None else check(a), dtype=float)
            a = io.array(np.broadcast_to(a, (n,))) if a.ndim else io.xp.const(float(a))
        return xs.cast(a)

    return one(wake_damping), one(breaking_fraction, _fraction)


def _fraction(q) -> Any:
    """Breaking fractions checked to lie in [0, 1]."""
    q = np.asarray(q, dtype=float)
    if not (np.all(np.isfinite(q)) and np.all((q >= 0.0) & (q <= 1.0))):
        raise ValueError("breaking_fraction: fractions must lie in [0, 1]")
    return q if q.ndim else float(q)


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


@dataclass(frozen=True)
class _Evaluation:
    """The kernel set-up shared by the per-facet entry points: the namespace ``xs`` of the
    scattering formulas, the boundary ``io`` of the back end, the facet count, the
    float64 directions (``io.xp`` vectors) and the mechanisms' (lazy) matrices with the
    context :func:`mechanisms` filled."""

    xs: Any
    io: Boundary
    n: int
    directions: tuple[Any, Any, Any]
    mech: dict
    context: dict


def _evaluate_mechanisms(n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike, sea: FacetModel,
                         *, wake_damping: Any = None, breaking_fraction: Any = None,
                         local: Any = None, backend: str = "auto",
                         variant: str | None = None, precision: str = "double") -> _Evaluation:
    """:func:`mechanisms` of facets on the chosen back end (in ``precision``)."""
    xp = _namespace(backend, sea.spectrum, variant)
    xs = xp.with_precision(precision)
    n_i = np.asarray(n_i, dtype=float).reshape(-1, 3)
    n = n_i.shape[0]
    io = Boundary(xp, n)
    directions = (io.vec3(n_i), io.vec3(np.asarray(n_s, dtype=float).reshape(-1, 3)),
                  io.vec3(np.asarray(normal, dtype=float).reshape(-1, 3)))
    damping, breaking = facet_arrays(io, xs, wake_damping, breaking_fraction)
    frames_in = _local_frames(local, n) if (local is not None and xp.is_numpy) else None
    ctx: dict = {}
    mech = mechanisms(xs, *(xs.cast(v) for v in directions), kernel_sea(io, sea, xs),
                      damping=damping, breaking=breaking, local=frames_in, context=ctx)
    return _Evaluation(xs, io, n, directions, mech, ctx)


def facet_terms(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    sea: FacetModel,
    *,
    wake_damping: ArrayLike | None = None,
    breaking_fraction: ArrayLike | None = None,
    local: Any = None,
    small_scale_height_variance: float | None = None,
    backend: str = "auto",
    variant: str | None = None,
    precision: str = "double",
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
    sea : FacetModel
        The sea's scattering inputs (wavenumber, permittivity, roughness spectrum,
        unresolved slopes, wind, model, tilt nodes, breaking tilt).
    wake_damping : array_like (N,), optional
        Wake mask ``d <= 1`` (1 = Bragg waves fully damped, negative where the narrow-V
        wake adds Bragg waves); multiplies the Bragg sigma by ``1 - d``.
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
    breaking_fraction : array_like (N,) or float, optional
        Fraction ``q`` of each facet covered by breaking zones, in [0, 1] (eq P7).
    precision : {"double", "single"}
        Working precision of the formulas on the Dr.Jit back end (float64 or float32;
        the inputs are cast to it, the results returned as float64 / complex128); numpy
        is float64 whatever is asked. A simulation's kernels take :data:`PRECISION`.

    Returns
    -------
    FacetTerms

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring.
    """
    if sea.model != "kirchhoff":
        check_spm_validity(sea.k, small_scale_height_variance)
    ev = _evaluate_mechanisms(n_i, n_s, normal, sea, wake_damping=wake_damping,
                              breaking_fraction=breaking_fraction, local=local,
                              backend=backend, variant=variant, precision=precision)
    io, n, mech, tilt = ev.io, ev.n, ev.mech, sea.tilt
    names = list(mech)
    res = io.numpy(ev.context["weight"], *[mech[m][0] for m in names])
    weight = res.pop(0).reshape(n, 4)
    mats = {m: r.reshape(n, 4) for m, r in zip(names, res, strict=True)}
    zero = np.zeros((n, 4), complex)
    return FacetTerms(
        specular=mats.get("specular", zero), bragg=mats.get("bragg", zero), weight=weight,
        tilted=tuple(mats[f"bragg{j}"] for j in range(1, len(mats) + 1) if f"bragg{j}" in mats),
        tilt_weights=() if tilt is None or sea.model == "kirchhoff" else tuple(tilt.weights),
        breaking=mats.get("breaking"),
        breaking_fraction=None if breaking_fraction is None else np.broadcast_to(
            _fraction(breaking_fraction), (n,)).copy())


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


def facet_sigma(n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike, sea: FacetModel,
                **kwargs: Any) -> NDArray:
    """Per-facet scattering coefficients ``sigma_mn`` (eq P3), shape (N, 4) [m^2/m^2].

    Same parameters as :func:`facet_terms` (keywords ``wake_damping``,
    ``breaking_fraction``, ``local``, ``small_scale_height_variance``, ``backend``...).
    Multiply by the facet area for its mean radar cross section [m^2]. Channels HH, HV,
    VH, VV in the global FSA bases (m received, n transmitted).
    """
    return facet_terms(n_i, n_s, normal, sea, **kwargs).sigma()


def speckle_draws(n: int, rng: np.random.Generator) -> tuple[NDArray, NDArray]:
    """The circular complex Gaussians ``g_K, g_B`` (unit variance) of eq P4, shape (n,) each.

    ``rng.standard_normal((n, 4))`` once, scaled by sqrt(1/2): columns Re g_K, Im g_K,
    Re g_B, Im g_B. Draw them once per sea state and pass them to
    :func:`speckle_amplitudes` (``draws=``) to reuse them while the surface is held.
    """
    g = rng.standard_normal((n, 4)) * np.sqrt(0.5)
    return g[:, 0] + 1j * g[:, 1], g[:, 2] + 1j * g[:, 3]


def circular_gaussians(n: int, count: int, rng: np.random.Generator) -> list[NDArray]:
    """``count`` independent circular complex Gaussians of unit variance, shape (n,) each.

    ``rng.standard_normal((n, 2 count))`` once, scaled by sqrt(1/2) (the draws of the
    further mechanisms of eqs P6-P7: tilt nodes, breaking zones).
    """
    g = rng.standard_normal((n, 2 * count)) * np.sqrt(0.5)
    return [g[:, 2 * j] + 1j * g[:, 2 * j + 1] for j in range(count)]


def _draw_map(draws: Any, names: list[str], n: int) -> dict[str, Any]:
    """Draws as ``{mechanism: (n,) complex}``: a dict, or ``(g_K, g_B)``."""
    if isinstance(draws, Mapping):
        d = dict(draws)
    else:
        g_k, g_b = draws
        d = {"specular": g_k, "bragg": g_b}
    missing = [m for m in names if m not in d]
    if missing:
        raise ValueError(f"draws: none given for the mechanisms {missing} (pass a dict "
                         f"with one (N,) complex draw per mechanism of {names})")
    for m in names:
        if np.shape(d[m]) != (n,):
            raise ValueError(f"draws of shape {np.shape(d[m])} for {m!r}: need ({n},)")
    return d


def speckle_amplitudes(terms: FacetTerms, area: ArrayLike,
                       rng: np.random.Generator | None = None, *,
                       draws: Any = None) -> NDArray:
    """Eq P4: speckled complex amplitudes ``a_mn`` [m] of facets, shape (N, 4).

    Draws two circular complex Gaussians (unit variance) per facet, ``g_K`` then
    ``g_B``, from ``rng`` (:func:`speckle_draws`: ``standard_normal((N, 4))`` once), so a
    given generator state gives the same amplitudes, then those of the further
    mechanisms (:func:`circular_gaussians`, in the order of :data:`MECHANISMS`); or
    takes them from ``draws``.

    Parameters
    ----------
    terms : FacetTerms
    area : array_like (N,)
        Facet areas [m^2].
    rng : numpy.random.Generator, optional
        Source of the draws (needed when ``draws`` is not given).
    draws : (g_K, g_B) or dict, optional
        Precomputed draws, (N,) complex each: :func:`speckle_draws`, or a dict with one
        per mechanism (:data:`MECHANISMS`); same result as drawing them from the
        generator that made them.

    Returns
    -------
    ndarray of complex, shape (N, 4)
        ``E|a_mn|^2 = sigma_mn * area`` [m^2]; covariance eq P5.
    """
    n = terms.weight.shape[0]
    mech = terms.mechanisms()
    names = list(mech)
    if draws is None:
        if rng is None:
            raise ValueError("speckle_amplitudes needs rng or draws")
        g_k, g_b = speckle_draws(n, rng)
        draws = {"specular": g_k, "bragg": g_b}
        extra = [m for m in names if m not in draws]
        draws.update(zip(extra, circular_gaussians(n, len(extra), rng), strict=True))
    d = _draw_map(draws, names, n)
    area = np.asarray(area, dtype=float).reshape(-1, 1)
    return speckle(NUMPY, mech, {m: np.asarray(d[m])[:, None] for m in names}, area)


def draw_context(xp, n_i: Any, n_s: Any, normal: Any, k: float) -> dict[str, Any]:
    """What a ``draws(xp, io, context)`` callable reads (the evolving speckle of
    :mod:`seaecho.scattering.dynamics`), in ``xp`` (float64): the directions ``n_i``,
    ``n_s`` [-], the wavenumber ``k`` [rad/m] and the facet's Bragg vector (eq S7,
    :func:`seaecho.scattering.spm.bragg_vector`) [rad/m] of the facets with unit normals
    ``normal``. The reference path (:func:`speckled_facet_amplitudes`) and the fused pulse
    (:func:`seaecho.radar.kernels.sea_echo_terms`) both build it here.
    """
    kc = xp.const(float(k))
    return dict(n_i=n_i, n_s=n_s, k=kc, bragg_vector=bragg_vector(xp, n_i, n_s, normal, kc))


def speckled_facet_amplitudes(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    area: ArrayLike,
    sea: FacetModel,
    *,
    draws: Any,
    wake_damping: ArrayLike | None = None,
    breaking_fraction: ArrayLike | None = None,
    local: Any = None,
    backend: str = "auto",
    variant: str | None = None,
    precision: str = "double",
) -> NDArray:
    """Eqs P1-P7 in one pass: speckled amplitudes ``a_mn`` [m] of facets, shape (N, 4).

    ``speckle_amplitudes(facet_terms(...), area, draws=draws)`` (same parameters as
    :func:`facet_terms`, ``area`` (N,) [m^2]): :func:`mechanisms` followed by
    :func:`speckle`, which the Dr.Jit back end evaluates as one kernel, so that the
    mechanism matrices never come back to numpy (the per-pulse path of a simulation).
    The back ends agree within rounding (tests); ``precision`` as :func:`facet_terms`
    (``"single"``: within 1e-5 of the float64 amplitudes, tests).

    ``draws`` is ``(g_K, g_B)`` (:func:`speckle_draws`), a dict of (N,) complex draws,
    one per mechanism (:data:`MECHANISMS`), or a callable ``draws(xp, io, context)``
    returning such a dict of namespace arrays, evaluated inside the kernel (``context``
    as filled by :func:`mechanisms`, plus ``"n_i"``, ``"n_s"``): the evolving speckle of
    :mod:`seaecho.scattering.dynamics`.

    References
    ----------
    .. [1] Paper eqs 7-11; module docstring (eqs P1-P7).
    """
    ev = _evaluate_mechanisms(n_i, n_s, normal, sea, wake_damping=wake_damping,
                              breaking_fraction=breaking_fraction, local=local,
                              backend=backend, variant=variant, precision=precision)
    xp, io, n, mech, ctx = ev.xs, ev.io, ev.n, ev.mech, ev.context
    names = list(mech)
    if callable(draws):
        # the evolving speckle's phases in float64 (io.xp), from float64 directions
        ctx.update(draw_context(io.xp, *ev.directions, sea.k))
        g = draws(io.xp, io, ctx)
    else:
        d = _draw_map(draws, names, n)
        g = {m: io.complex(d[m]) for m in names}
    a = speckle(xp, mech, {m: xp.cast(v) for m, v in g.items()},
                xp.cast(io.array(np.asarray(area, dtype=float).reshape(n))))
    (out,) = io.numpy(a)
    return out.reshape(n, 4)


def facet_amplitudes(
    n_i: ArrayLike,
    n_s: ArrayLike,
    normal: ArrayLike,
    area: ArrayLike,
    sea: FacetModel,
    rng: np.random.Generator,
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
    sea : FacetModel
        The sea's scattering inputs.
    rng : numpy.random.Generator
        Source of the speckle draws (one per pulse / time step).

    Returns
    -------
    ndarray of complex, shape (N, 4)
    """
    return speckle_amplitudes(facet_terms(n_i, n_s, normal, sea, **kwargs), area, rng)


def hhvv_coherence(terms: FacetTerms) -> NDArray:
    """Complex HH-VV correlation coefficient of facets implied by eq P5 [-], shape (N,).

    ``gamma = E[a_hh a_vv^*] / sqrt(E|a_hh|^2 E|a_vv|^2)``; 0 where both vanish.
    """
    c = terms.covariance()
    den = np.sqrt(c[:, 0, 0].real * c[:, 3, 3].real)
    return np.where(den > 0, c[:, 0, 3] / np.where(den > 0, den, 1.0), 0.0)


__all__ = ["BACKENDS", "MECHANISMS", "MODELS", "FacetModel", "FacetTerms", "KernelSea",
           "TiltQuadrature", "bragg_vectors", "circular_gaussians", "draw_context",
           "facet_amplitudes",
           "facet_arrays", "facet_sigma", "facet_terms", "hhvv_coherence", "kernel_sea",
           "mechanism_sigma", "mechanisms", "speckle", "speckle_amplitudes", "speckle_draws",
           "speckled_facet_amplitudes"]
