"""Sea clutter in time: the speckle of each facet evolves (eqs D1-D8).

A facet's echo is the sum of the echoes of its sub-facet scatterers: specular points,
Bragg waves, breaking zones (:mod:`seaecho.scattering.facet`, eqs P1-P7). Eq P4 gives it
one circular Gaussian factor ``g_m`` per mechanism. On a held sea these factors are
constant (the paper's frozen map); here each is a stationary random process of time,
built so that any pulse can be computed alone from (seed, facet, time):

**Motion of the facet** (not here): the facet's phase centre follows the resolved surface
(:mod:`seaecho.simulation`): its particle position ``r + D(r, t)`` (horizontal Airy
displacement ``D``, elevation ``z``), so that the radar kernel's carrier phase gives the
Doppler ``f = q . v / (2 pi)`` of the resolved orbital motion, ``q = k (n_s - n_i)``
(D1). The sub-facet scatterers ride on it: the specular points and Bragg waves of the
unresolved waves are advected by the resolved orbital velocity (Thompson 1989; Romeiser
& Thompson 2000).

**Intrinsic Doppler** of each mechanism, relative to the facet:

* Bragg (eq D2): the two waves of the local spectrum at ``+-k_B`` (``k_B`` the local Bragg
  vector of eq S7, the part of ``q`` tangent to the facet) travel at their phase speeds:
  lines at ``+-f_B``, ``2 pi f_B = omega(|k_B|) = sqrt(g k_B + tau k_B^3)`` (the
  dispersion relation, eq 15 with surface tension; Wright 1968, Valenzuela 1978), the
  wave travelling along ``+k_B`` (towards the radar in back-scatter) giving ``+f_B``.
  Their powers are the fractions ``p+-`` of the spectrum travelling along ``+-k_B``::

      g_B(t) = sqrt(p+) g_+(t) exp(+j 2 pi f_B t) + sqrt(p-) g_-(t) exp(-j 2 pi f_B t)

  (``g_+-`` independent, each of the form D4). For a spectrum whose spreading tells the
  travel direction (Longuet-Higgins ``cos^2s(psi/2)``) ``p+ = Psi(k_B) / (Psi(k_B) +
  Psi(-k_B))``; a centro-symmetric spreading (Elfouhaily et al. 1997) does not, and the
  split is the one of the short-wave equilibrium of KHCC03, ``B ~ beta_nu^(1/n)``
  (eq BR4): waves travelling against the wind get no wind input (D3).
* Specular points: none beyond the facet's motion (a specular point's Doppler is the
  vertical velocity of the surface at it, Barrick 1968's geometric optics).
* Breaking zones: the breakers' Lambda-weighted mean velocity ``c_br`` along the wind,
  relative to the water, ``f = q . (c_br u_wind) / (2 pi)`` (Hansen et al. 2012 eq 19;
  :func:`breaking_statistics`), less the orbital velocity of the resolved waves shorter
  than the breakers' modulating waves (``breaker_short`` of :meth:`EvolvingSpeckle.draws`,
  eq BR10 of :mod:`seaecho.scattering.breaking`): the zones, placed on the resolved
  crests (the facets of largest downward acceleration), ride on the facet's velocity of
  the long waves only (eqs BR7-BR8).

**Current** (eq C1 of :mod:`seaecho.ocean.dispersion`). On a uniform surface current U
the facets stay on the fixed grid (the resolved sea is advected through them,
:mod:`seaecho.ocean.surface`) while the water and every sub-facet scatterer drift with U:
each mechanism's line moves by ``q . U / (2 pi)``. For the Bragg lines this is the
Doppler-shifted dispersion relation, ``omega_0 +- k . U`` with ``k`` the horizontal Bragg
vector ``q_h``: ``+-f_B + q . U / (2 pi)`` (Phillips 1977, section 3.6).

**Finite coherence** (eq D4). Each process is a cross-fade of independent anchors
``G_a ~ CN(0, 1)`` drawn at times ``t_a = a T`` (``T`` the scatterers' lifetime), each
rotating at its own random Doppler ``f_0 + sigma_f nu_a`` (``nu_a ~ N(0, 1)``)::

    g(t) = cos(pi u / 2) G_a exp(j 2 pi (f_0 + sigma_f nu_a)(t - t_a))
         + sin(pi u / 2) G_a+1 exp(j 2 pi (f_0 + sigma_f nu_a+1)(t - t_a+1)),
    a = floor(t / T), u = t / T - a

At any time ``g ~ CN(0, 1)`` exactly (the weights' squares sum to 1), so the single-pulse
statistics of eqs P4-P5 are those of the held sea. ``sigma_f`` is the Doppler spread of the
sub-facet scatterers advected by the orbital velocities of the unresolved waves (the
tilting band between the grid's Nyquist wavenumber and ``k/3``), ``sigma_f = sqrt(q^T C
q) / (2 pi)`` with ``C`` their velocity covariance (eq U2; Thompson 1989: the Doppler
bandwidth of a composite surface is set by the orbital velocities of the longer waves).
Averaged over the anchor phase, the autocorrelation is (D5)::

    E[g(t + tau) g*(t)] = R_T(tau) exp(-2 pi^2 sigma_f^2 tau^2) exp(j 2 pi f_0 tau),
    R_T(tau) = sin(pi x / 2) / pi + (1 - x / 2) cos(pi x / 2),  x = |tau| / T <= 2,
    0 beyond,

the anchors' cross-fade (``R_T``: 1 at 0, 0.69 at ``tau = T/2``, 0 at ``2 T``) times the
Gaussian Doppler spread. **Lifetimes** (D6-D8): Bragg waves relax to the wind's
equilibrium at the rate ``n beta_nu omega`` (linearising the KHCC03 balance ``dB/dt =
omega beta_nu B - omega B (B/alpha)^n`` about ``B = alpha beta_nu^(1/n)``), so
``T_B = 1 / (n beta_nu omega)`` at the scene's Bragg wavenumber, upwind (D6); the
specular points of the unresolved waves last about one of their periods, ``T_K = 2 pi /
<omega>`` (slope-weighted mean over the tilting band, D7); a breaker lasts about one
period of the breaking wave (Rapp & Melville 1990), ``T_W`` = the Lambda-weighted mean
period of :func:`breaking_statistics` (D8).

**Reproducible in any order.** The anchors of family ``m`` (specular, Bragg+, Bragg-,
breaking) come from ``generator(seed, "speckle-evolution", m, a)``
(``standard_normal((N, 3))``: Re G, Im G, nu per facet), so a pulse needs only the two
anchors around its time: pulses and blocks can be computed in any order or on other
machines with the same bytes. The unresolved-tilt nodes of eq P6 share the facet's Bragg
process with a fixed random phase each (``"speckle-tilt"`` stream, index 0): their
incoherent sum holds on average over facets.

References
----------
.. [1] Thompson, D. R. (1989). Calculation of microwave Doppler spectra from the ocean
   surface with a time-dependent composite model. In *Radar Scattering from Modulated
   Wind Waves*, Kluwer, 27-40.
.. [2] Romeiser, R. and Thompson, D. R. (2000). Numerical study on the along-track
   interferometric radar imaging mechanism of oceanic surface currents. *IEEE Trans.
   Geosci. Remote Sens.* 38(1), 446-458.
.. [3] Wright, J. W. (1968). A new model for sea clutter. *IEEE Trans. Antennas
   Propag.* 16(2), 217-223.
.. [4] Valenzuela, G. R. (1978). Theories for the interaction of electromagnetic and
   oceanic waves - a review. *Boundary-Layer Meteorol.* 13, 61-85.
.. [5] Kudryavtsev, V., Hauser, D., Caudal, G. and Chapron, B. (2003). A semiempirical
   model of the normalized radar cross-section of the sea surface, 1. Background model.
   *J. Geophys. Res.* 108(C3), 8054 (KHCC03).
.. [6] Rapp, R. J. and Melville, W. K. (1990). Laboratory measurements of deep-water
   breaking waves. *Phil. Trans. R. Soc. Lond. A* 331, 735-800.
.. [7] Barrick, D. E. (1968). Rough surface scattering based on the specular point
   theory. *IEEE Trans. Antennas Propag.* 16(4), 449-454.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import aligned
from ..ocean.dispersion import angular_frequency, doppler_shifted_frequency, omega_squared_deep
from ..rng import generator
from .breaking import dissipation_exponent, net_growth_rate
from .spectrum_table import BraggSpectrumTable

#: Evolving speckle families and their ids in the ``"speckle-evolution"`` stream.
FAMILIES = {"specular": 0, "bragg+": 1, "bragg-": 2, "breaking": 3}

#: Lifetimes are kept within these bounds [s] (a frozen scatterer: a very long lifetime).
LIFETIME_MIN = 1.0e-3
LIFETIME_MAX = 1.0e3


# ----------------------------------------------------------------- closed forms
def bragg_frequency(k: ArrayLike) -> NDArray:
    """Frequency of the Bragg line of wavenumber ``k`` [rad/m]: ``omega / 2 pi`` [Hz].

    Deep-water gravity-capillary waves, ``omega^2 = g k + tau k^3`` (eq D2; Valenzuela
    1978; :mod:`seaecho.ocean.dispersion`). Bragg waves are centimetric: the depth never
    matters.
    """
    return angular_frequency(k) / (2.0 * math.pi)


def window_autocorrelation(tau: ArrayLike, lifetime: float) -> NDArray:
    """``R_T(tau)`` of eq D5: autocorrelation of the anchors' cross-fade [-].

    ``sin(pi x / 2) / pi + (1 - x / 2) cos(pi x / 2)``, ``x = |tau| / T``, 0 for
    ``x > 2``; the time average over the anchor phase of
    ``sum_a w_a(t) w_a(t + tau)`` with ``w_a(t) = cos(pi (t - t_a) / (2 T))``.
    """
    x = np.abs(np.asarray(tau, dtype=float)) / float(lifetime)
    r = np.sin(0.5 * np.pi * x) / np.pi + (1.0 - 0.5 * x) * np.cos(0.5 * np.pi * x)
    return np.where(x < 2.0, r, 0.0)


def speckle_autocorrelation(tau: ArrayLike, lifetime: float, sigma_f: float = 0.0,
                            f0: float = 0.0) -> NDArray:
    """Eq D5: ``E[g(t + tau) g*(t)]`` of an evolving speckle factor [-] (complex).

    Parameters
    ----------
    tau : array_like
        Lag [s].
    lifetime : float
        Anchor interval ``T`` [s].
    sigma_f : float
        Doppler spread of the scatterers [Hz].
    f0 : float
        Doppler of the scatterers relative to the facet [Hz].
    """
    tau = np.asarray(tau, dtype=float)
    return (window_autocorrelation(tau, lifetime)
            * np.exp(-2.0 * (math.pi * sigma_f * tau) ** 2 + 2j * math.pi * f0 * tau))


def coherence_time(lifetime: float, sigma_f: float = 0.0) -> float:
    """The lag at which ``|R|`` of eq D5 falls to 1/e [s]."""
    from scipy.optimize import brentq

    def f(t):
        return float(window_autocorrelation(t, lifetime) * math.exp(
            -2.0 * (math.pi * sigma_f * t) ** 2)) - math.exp(-1.0)

    return float(brentq(f, 0.0, 2.0 * lifetime))


def bragg_lifetime(k_bragg: float, u10: float) -> float:
    """Eq D6: relaxation time of Bragg waves ``1 / (n beta_nu omega)`` [s], upwind.

    Linearising the KHCC03 balance ``dB/dt = omega beta_nu B - omega B (B / alpha)^n``
    about its equilibrium gives the relaxation rate ``n beta_nu omega`` (``beta_nu`` the
    net wind growth rate, eq BR4; ``n`` the dissipation exponent). Where the waves do not
    grow (``beta_nu <= 0``) their lifetime is :data:`LIFETIME_MAX`.

    Parameters
    ----------
    k_bragg : float
        Bragg wavenumber [rad/m].
    u10 : float
        Wind speed at 10 m [m/s].
    """
    k = float(k_bragg)
    if not (np.isfinite(k) and k > 0.0):
        return LIFETIME_MAX
    omega = float(angular_frequency(k))
    beta_nu = float(net_growth_rate(k, 0.0, u10))
    n = float(dissipation_exponent(k))
    if beta_nu <= 0.0:
        return LIFETIME_MAX
    return float(np.clip(1.0 / (n * beta_nu * omega), LIFETIME_MIN, LIFETIME_MAX))


def travel_fraction(spectrum, kx: ArrayLike, ky: ArrayLike, u10: float) -> NDArray:
    """Eq D3: fraction ``p+`` of the spectral density at ``+-K`` travelling along ``+K`` [-].

    ``Psi(K) / (Psi(K) + Psi(-K))`` when the spreading function tells the travel direction;
    for a centro-symmetric one (Elfouhaily et al. 1997) the split of the short-wave
    equilibrium of KHCC03, ``B(K) ~ max(beta_nu, 0)^(1/n)`` (eq BR4; 1/2 where neither
    direction grows).

    Parameters
    ----------
    spectrum : DirectionalSpectrum
    kx, ky : array_like
        World wavenumbers [rad/m].
    u10 : float
        Wind speed at 10 m [m/s] (for the equilibrium split).
    """
    kx = np.asarray(kx, dtype=float)
    ky = np.asarray(ky, dtype=float)
    if not _centro_symmetric(spectrum):
        a = np.asarray(spectrum(kx, ky), dtype=float)
        b = np.asarray(spectrum(-kx, -ky), dtype=float)
        tot = a + b
        return np.where(tot > 0, a / np.where(tot > 0, tot, 1.0), 0.5)
    k = np.maximum(np.hypot(kx, ky), 1e-9)
    phi = np.arctan2(ky, kx) - spectrum.wind_direction
    n = dissipation_exponent(k)
    bp = np.maximum(net_growth_rate(k, phi, u10), 0.0) ** (1.0 / n)
    bm = np.maximum(net_growth_rate(k, phi + np.pi, u10), 0.0) ** (1.0 / n)
    tot = bp + bm
    return np.where(tot > 0, bp / np.where(tot > 0, tot, 1.0), 0.5)


def _centro_symmetric(spectrum) -> bool:
    k = np.array([0.5, 5.0, 50.0, 300.0])
    for psi in (0.3, 1.0, 2.0):
        a = spectrum(k * math.cos(psi), k * math.sin(psi))
        b = spectrum(-k * math.cos(psi), -k * math.sin(psi))
        if not np.allclose(a, b, rtol=1e-9, atol=0.0):
            return False
    return True


def particle_centre(centroid: Any, displacement: Any, xp=None) -> Any:
    """Eq D1: a facet's phase centre, its surface particle's position ``r + D`` [m].

    ``centroid`` the facet's centroid ``r`` on the surface grid, ``displacement`` the
    particle's horizontal Airy displacement ``D = (D_x, D_y)`` averaged over the facet's
    vertices. numpy (``xp`` None): arrays (N, 3) and (N, 2); an array namespace (the
    fused pulse kernel, :mod:`seaecho.radar.resident`): a vector and a pair of arrays.
    """
    if xp is None or xp.is_numpy:
        out = np.array(centroid, dtype=float)
        out[:, :2] += np.asarray(displacement, dtype=float)
        return out
    dx, dy = displacement
    return xp.vec(centroid.x + dx, centroid.y + dy, centroid.z)


def extrapolate(position: Any, velocity: Any, acceleration: Any | None, dt: float,
                xp=None) -> Any:
    """Eq D1 between geometry updates: ``r + v dt + a dt^2 / 2`` [m].

    The particle positions of a surface state carried ``dt`` [s] forward by their
    velocity [m/s] and acceleration [m/s^2] (``None``: uniform motion). numpy (``xp``
    None): arrays (N, 3); an array namespace (the fused pulse kernel): its vectors, ``dt``
    entering as an opaque constant (one compiled kernel for every pulse). The same
    operations in the same order in both.
    """
    if xp is None or xp.is_numpy:
        const = float
        position, velocity = (np.asarray(a, dtype=float) for a in (position, velocity))
        if acceleration is not None:
            acceleration = np.asarray(acceleration, dtype=float)
    else:
        const = xp.const
    out = position + velocity * const(dt)
    if acceleration is not None:
        out = out + acceleration * const(0.5 * dt * dt)
    return out


# ---------------------------------------------------------------- stage model
@dataclass(frozen=True)
class SeaDynamics:
    """How the speckle of the facets evolves (eqs D2-D8); plain values, SI.

    Attributes
    ----------
    lifetimes : dict
        Anchor interval ``T`` [s] per family (:data:`FAMILIES`).
    velocity_covariance : ndarray (3, 3)
        Velocity covariance of the unresolved (tilting-band) waves [m^2/s^2] (eq U2).
    breaker_velocity : ndarray (3,)
        Velocity of the breaking scatterers relative to the facet [m/s].
    travel : BraggSpectrumTable or None
        ``p+`` of eq D3 tabulated over the Bragg roughness band (None: 1/2 everywhere).
    current : (float, float)
        Uniform surface current (U_x, U_y) [m/s] carrying the sub-facet scatterers
        (eq C1; (0, 0): still water).
    """

    lifetimes: dict
    velocity_covariance: NDArray
    breaker_velocity: NDArray
    travel: BraggSpectrumTable | None
    current: tuple[float, float] = (0.0, 0.0)

    def sigma_f(self, q: ArrayLike) -> NDArray:
        """Doppler spread ``sqrt(q^T C q) / (2 pi)`` [Hz] for scattering vectors (N, 3)."""
        q = np.asarray(q, dtype=float)
        return np.sqrt(np.einsum("...i,ij,...j->...", q, self.velocity_covariance, q)) / (
            2.0 * math.pi)


# ------------------------------------------------------------ anchors, kernel
class EvolvingSpeckle:
    """The speckle processes of N facets (eq D4), for the per-pulse scattering kernel.

    Parameters
    ----------
    dynamics : SeaDynamics
    seed : int
        The scene's seed.
    n_facets : int
    tilt_nodes : int
        Number of unresolved-tilt nodes of eq P6 (0: none).
    breaking : bool
        Whether a breaking mechanism exists.
    cache_size : int
        Anchors kept in memory (two per family are used by a pulse).
    """

    def __init__(self, dynamics: SeaDynamics, seed: int, n_facets: int, tilt_nodes: int = 0,
                 breaking: bool = False, cache_size: int = 8) -> None:
        self.dynamics = dynamics
        self.seed = int(seed)
        self.n = int(n_facets)
        self.breaking = bool(breaking)
        self.families = [f for f in FAMILIES if f != "breaking" or self.breaking]
        self._cache: OrderedDict = OrderedDict()
        self._device: dict[int, tuple[NDArray, Any]] = {}  # GPU copies (_wrap)
        self._cache_size = max(int(cache_size), 2 * len(self.families))
        self.tilt_phases: list[tuple[NDArray, NDArray]] = []
        if tilt_nodes:
            g = generator(self.seed, "speckle-tilt", 0).uniform(0.0, 2.0 * math.pi,
                                                               (tilt_nodes, self.n))
            self.tilt_phases = [(aligned(np.cos(p)), aligned(np.sin(p))) for p in g]

    def anchor(self, family: str, a: int) -> tuple[NDArray, NDArray, NDArray]:
        """``(Re G_a, Im G_a, nu_a)`` of a family's anchor ``a`` [-], (N,) each."""
        key = (family, int(a))
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        # anchors at negative times (t < 0) use the index |a| + offset: keys stay >= 0
        idx = 2 * a if a >= 0 else -2 * a - 1
        x = generator(self.seed, "speckle-evolution", FAMILIES[family], idx).standard_normal(
            (self.n, 3))
        s = math.sqrt(0.5)
        out = (aligned(x[:, 0] * s), aligned(x[:, 1] * s), aligned(x[:, 2]))
        self._cache[key] = out
        while len(self._cache) > self._cache_size:
            self._cache.popitem(last=False)
        return out

    def process_values(self, family: str, t: float, f0: ArrayLike, sigma_f: ArrayLike,
                       xp=None) -> Any:
        """Eq D4 at time ``t`` [s]: ``g(t)`` of a family for all facets (namespace array).

        ``f0`` [Hz] and ``sigma_f`` [Hz] are per facet (namespace arrays or numbers).
        """
        from ..backend import NUMPY

        xp = NUMPY if xp is None else xp
        T = float(self.dynamics.lifetimes[family])
        a0 = math.floor(t / T)
        u = t / T - a0
        total = None
        for j, w in ((0, math.cos(0.5 * math.pi * u)), (1, math.sin(0.5 * math.pi * u))):
            re, im, nu = (self._wrap(xp, b) for b in self.anchor(family, a0 + j))
            tau = xp.const(t - (a0 + j) * T)
            phase = (f0 + sigma_f * nu) * tau * (2.0 * math.pi)
            rot = xp.complex(xp.cos(phase), xp.sin(phase))
            term = xp.complex(re, im) * rot * xp.const(w)
            total = term if total is None else total + term
        return total

    def _wrap(self, xp, buf: NDArray) -> Any:
        """A cached aligned buffer as a namespace array: numpy's itself, Dr.Jit's CPU back
        end aliases it (no copy); a GPU's copy is made once and kept while the anchor is
        (not copied again at every pulse)."""
        if xp.is_numpy:
            return buf
        if xp.name == "llvm":
            return xp.Float(buf)
        hit = self._device.get(id(buf))
        if hit is not None and hit[0] is buf:
            return hit[1]
        live = {id(b) for v in self._cache.values() for b in v}
        live |= {id(b) for v in self.tilt_phases for b in v}
        self._device = {k: v for k, v in self._device.items() if k in live}
        out = xp.Float(buf)
        self._device[id(buf)] = (buf, out)
        return out

    def draws(self, t: float, breaker_short: NDArray | None = None) -> Callable:
        """The ``draws`` callable of :func:`seaecho.scattering.facet.speckled_facet_amplitudes`
        at time ``t`` [s]: evaluates eqs D2-D4 inside the facet kernel.

        ``breaker_short`` (N, 3) [m/s]: per facet, the velocity of the resolved waves
        shorter than the breakers' modulating waves, which the breaking zones' Doppler
        leaves out (eq BR10 of :mod:`seaecho.scattering.breaking`: they ride on the
        longer waves only; the shorter are breakers, counted in ``c_br``); None: none.
        """
        short = None
        if breaker_short is not None and self.breaking:  # the block's, copied once
            last = getattr(self, "_short", None)
            if last is None or last[0] is not breaker_short:
                b = np.asarray(breaker_short, dtype=float)
                last = (breaker_short,
                        tuple(aligned(np.ascontiguousarray(b[:, i])) for i in range(3)))
                self._short = last
            short = last[1]

        def make(xp, io, ctx):
            d = ctx["n_s"] - ctx["n_i"]
            q = d * ctx["k"]
            c = self.dynamics.velocity_covariance
            var = (q.x * q.x * c[0, 0] + 2.0 * q.x * q.y * c[0, 1] + q.y * q.y * c[1, 1]
                   + q.z * q.z * c[2, 2])
            sigma_f = xp.sqrt(xp.maximum(var, 0.0)) * (1.0 / (2.0 * math.pi))
            current = tuple(float(u) for u in self.dynamics.current)
            moving = current != (0.0, 0.0)
            to_hz = 1.0 / (2.0 * math.pi)
            # eq C1 with omega_0 = 0: the drift of the scatterers with the water
            f_u = doppler_shifted_frequency(0.0, q.x, q.y, current) * to_hz if moving else 0.0
            out = {"specular": self.process_values("specular", t, f_u, sigma_f, xp)}
            kx, ky = ctx["bragg_vector"]
            kb = xp.sqrt(kx * kx + ky * ky)
            w_b = xp.sqrt(omega_squared_deep(kb))  # eq D2
            table = self.dynamics.travel
            p_plus = 0.5 if table is None else xp.clip(table.lookup(xp, kx, ky), 0.0, 1.0)
            if moving:  # eq C1: omega_0 +- q_h . U, the lines of the waves along +-q_h
                f_p = doppler_shifted_frequency(w_b, q.x, q.y, current) * to_hz
                f_m = doppler_shifted_frequency(-w_b, q.x, q.y, current) * to_hz
            else:
                f_p = w_b * to_hz
                f_m = -f_p
            g_p = self.process_values("bragg+", t, f_p, sigma_f, xp)
            g_m = self.process_values("bragg-", t, f_m, sigma_f, xp)
            g_b = g_p * xp.sqrt(p_plus) + g_m * xp.sqrt(1.0 - p_plus)
            out["bragg"] = g_b
            for j, (cs, sn) in enumerate(self.tilt_phases):
                out[f"bragg{j + 1}"] = g_b * xp.complex(self._wrap(xp, cs), self._wrap(xp, sn))
            if self.breaking:
                v = self.dynamics.breaker_velocity
                f_w = (q.x * float(v[0]) + q.y * float(v[1]) + q.z * float(v[2])) * (
                    1.0 / (2.0 * math.pi))
                if moving:  # the breakers drift with the water too
                    f_w = f_w + f_u
                if short is not None:  # eq BR10: not the short waves' orbital velocity
                    sx, sy, sz = (self._wrap(xp, a) for a in short)
                    f_w = f_w - (q.x * sx + q.y * sy + q.z * sz) * (1.0 / (2.0 * math.pi))
                out["breaking"] = self.process_values("breaking", t, f_w, sigma_f, xp)
            return out

        return make


__all__ = ["FAMILIES", "LIFETIME_MAX", "LIFETIME_MIN", "EvolvingSpeckle", "SeaDynamics",
           "bragg_frequency", "bragg_lifetime", "coherence_time", "extrapolate",
           "particle_centre",
           "speckle_autocorrelation", "travel_fraction", "window_autocorrelation"]
