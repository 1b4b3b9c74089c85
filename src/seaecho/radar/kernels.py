"""The per-scatterer radar equation, written once, run by numpy or as one Dr.Jit kernel.

:func:`echo_terms` is eqs (R1) and (R3) for a set of scatterers over an array namespace
(:mod:`seaecho.backend`): time of flight (eq R3, :func:`seaecho.radar.equation.flight`),
directions, antenna gains (eq A1 and the built-in patterns of
:mod:`seaecho.radar.antennas`), port states on the FSA bases (eq A2 against eq F1, both
:func:`seaecho.geometry.frames.fsa_basis`, rotated by eq F3), the polarimetric factor
and the amplitude with the carrier phase (eq R1). :func:`scatterer_echo` evaluates it
with numpy (``RadarSystem.scatterer_echo_numpy``) or as one fused Dr.Jit kernel on the
CPU (``drjit.llvm``) or a CUDA GPU (``drjit.cuda``), about 20x faster than numpy on 2
cores at half a million facets (``benchmarks/bench_radar.py``). The delays, directions,
carrier phase and amplitude magnitude are float64: ranges keep sub-micrometre precision
and the carrier phase 2 pi f_c tau is reduced modulo one cycle before its sine and
cosine. The antenna gains, port states and polarimetric factor are evaluated in the
namespace ``scattering`` when one is given (the sea's float32 kernels), else in
float64. Per-pulse values (platform positions, velocities, antenna axes) enter as opaque
constants: one compiled kernel per run.

:func:`sea_echo_terms` chains the sea's per-pulse stages for a set of facets: facing test
and ray-traced visibility (eq G1 and the local angles of :mod:`seaecho.geometry.frames`),
the speckled facet amplitudes (eqs P1-P4, :func:`seaecho.scattering.facet.mechanisms`
and :func:`~seaecho.scattering.facet.speckle`) and :func:`echo_terms`. These are the same
functions, called with the same values, as the reference path of
``Simulation.sea_echo`` (a Dr.Jit kernel per stage, numpy in between; both in the
working precision ``seaecho.scattering.facet.PRECISION``, float32 by default, where eqs
P1-P4 and the gains and ports are concerned), so Dr.Jit records them as one kernel whose
numbers are those of the reference to the last bit (tests);
:class:`seaecho.radar.resident.ResidentSea` runs it on device-resident facets.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..backend import Boundary, Mat2, Rows
from ..constants import C0
from ..geometry.bistatic import ranges
from ..geometry.frames import basis_change, bistatic_angles, fsa_basis
from ..scattering.facet import draw_context, speckle
from .antennas import port_coefficients
from .equation import amplitude_factor, carrier, flight, polarimetric_factor

__all__ = ["antenna_gain", "echo_terms", "facet_visibility", "port_matrix", "scatterer_echo",
           "scatterer_echo_drjit", "sea_echo_terms"]


def antenna_gain(xp, antenna, d: Any, axes: Any, xs: Any = None) -> Any:
    """Power gain [-] of ``antenna`` towards unit world directions ``d`` (eq A1 et al.).

    ``axes`` (3, 3): the antenna axes in the world (columns boresight, width, height);
    the direction in the antenna frame is ``axes^T d``. ``xs``: the namespace the gain is
    evaluated in (``d`` one of its values; ``xp`` by default), the axes entering as
    ``xp``'s constants cast to it.
    """
    xs = xp if xs is None else xs
    a = np.asarray(axes, dtype=np.float64)
    d_local = xs.vec(*(xs.dot(d, xs.cast(xp.vconst(a[:, j]))) for j in range(3)))
    return antenna.gain_local(d_local, xp=xs)


def _coefficient(xp, c: complex) -> Any:
    """A port coefficient: structural 0, a real literal or a complex one."""
    c = complex(c)
    if c == 0:
        return 0
    if c.imag == 0:
        return c.real
    return xp.complex(c.real, c.imag)


def port_matrix(xp, coefficients: NDArray, n: Any, up: Any) -> Mat2:
    """Port states of an antenna on the world FSA basis of direction ``n``: ``C A`` [-].

    ``coefficients[port, (h_a, v_a)]`` on the antenna's own basis (eq A2: the FSA basis
    of ``n`` about the platform's vertical ``up``, :func:`fsa_basis`), ``A`` the rotation
    (eq F3) from the world basis (eq F1, about +z) to the antenna's basis; row ``p`` of
    the result is port p's components on (h, v) of ``n``.
    """
    world = fsa_basis(xp, n, xp.vec(0.0, 0.0, 1.0))
    own = fsa_basis(xp, n, up)
    c = Mat2(*(_coefficient(xp, x) for x in np.asarray(coefficients).ravel()))
    return c @ basis_change(xp, world, own)


def echo_terms(xp, radar, geometry, p: Any, v: Any, s: Mat2, *,
               scattering: Any = None) -> dict[str, Any]:
    """Eqs (R1), (R3), (A1), (A2) for scatterers, over an array namespace.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    radar : seaecho.radar.system.RadarSystem
        Antennas, channels, carrier and power.
    geometry : seaecho.radar.system.PulseGeometry
        Platform states and antenna axes at the emission.
    p, v : vectors
        Scatterer positions at the emission [m] and velocities [m/s].
    s : Mat2 of complex
        Scattering amplitudes [m] on the world FSA bases, (h, v) order.
    scattering : array namespace, optional
        Where the antenna gains, the port states and the polarimetric factor are
        evaluated (the sea's float32 namespace, ``xp.with_precision("single")``): the
        directions are cast to it, the gains and the factor cast back. The delays, the
        directions, the carrier phase and the radar equation's magnitude stay in ``xp``.
        Default ``xp``.

    Returns
    -------
    dict
        ``tau, r_t, r_r, g_t, g_r`` [s, m, m, -, -], ``n_i, n_s`` (vectors [-]) and
        ``amplitudes``: one complex array per channel of ``radar.channels`` [sqrt(W)].
    """
    xs = xp if scattering is None else scattering
    tx, rx = geometry.tx, geometry.rx
    p_tx = xp.vconst(tx.position)
    p_rx = xp.vconst(rx.position)
    v_rx = xp.vconst(rx.velocity)
    # Eq (R3): outbound delay, bounce point, return delay to the moving receiver
    tau_t, tau_r, p_b = flight(xp, p_tx, p, v, p_rx, v_rx)
    tau = tau_t + tau_r
    r_t, r_r = C0 * tau_t, C0 * tau_r
    n_i = (p_b - p_tx) * (1.0 / r_t)
    n_s = (p_rx + v_rx * tau - p_b) * (1.0 / r_r)
    d_i, d_s = xs.cast(n_i), xs.cast(n_s)
    g_t = xp.cast(antenna_gain(xp, radar.tx_antenna, d_i, geometry.tx_axes, xs))
    g_r = xp.cast(antenna_gain(xp, radar.rx_antenna, -d_s, geometry.rx_axes, xs))
    # Port states on the world FSA bases (receive: the conjugate states, eq A2)
    t_ports = port_matrix(xs, port_coefficients(radar.tx_antenna.basis,
                                                radar.tx_antenna.cross_polar_isolation_db),
                          d_i, xs.cast(xp.vconst(tx.rotation[:, 2])))
    r_ports = port_matrix(xs, np.conj(port_coefficients(
        radar.rx_antenna.basis, radar.rx_antenna.cross_polar_isolation_db)),
        d_s, xs.cast(xp.vconst(rx.rotation[:, 2])))
    m = polarimetric_factor(r_ports, xs.cast(s), t_ports)
    # Eq (R1): real amplitude and carrier phase exp(-j 2 pi f_c tau)
    a = carrier(xp, radar.carrier, tau) * amplitude_factor(
        xp, radar.transmit_power, g_t, g_r, radar.wavelength, r_t, r_r)
    return dict(tau=tau, r_t=r_t, r_r=r_r, g_t=g_t, g_r=g_r, n_i=n_i, n_s=n_s,
                amplitudes=[m[i, j] * a for _, i, j in radar.channels])


def scatterer_echo(xp, radar, geometry, p: NDArray, v: NDArray, s: NDArray,
                   directions: bool = True, scattering: Any = None) -> dict[str, NDArray]:
    """:func:`echo_terms` of numpy scatterers, evaluated in namespace ``xp``.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
        numpy, or Dr.Jit (one fused kernel, CPU or GPU).
    radar, geometry
        As :func:`echo_terms`.
    p, v : ndarray (K, 3)
        Scatterer positions at the emission [m] and velocities [m/s] (float64).
    s : ndarray (K, 2, 2) complex
        Scattering amplitudes [m] on the world FSA bases, (h, v) order.
    directions : bool
        Also return the unit directions n_i, n_s.
    scattering : array namespace, optional
        As :func:`echo_terms` (the sea's reference path: the fused kernel's float32).

    Returns
    -------
    dict of numpy arrays
        ``tau, r_t, r_r, g_t, g_r`` (K,), ``amplitudes`` (C, K) complex [sqrt(W)], and
        ``n_i, n_s`` (K, 3) when asked for.

    Notes
    -----
    Inputs enter as contiguous columns aliased by Dr.Jit: reading them with
    ``dr.gather`` from the interleaved numpy buffers instead was 3x slower (LLVM, 2 cores).
    """
    k = p.shape[0]
    io = Boundary(xp, k)
    sm = Mat2(*(io.complex(s[:, a, b]) for a in range(2) for b in range(2)))
    t = echo_terms(xp, radar, geometry, io.vec3(p), io.vec3(v), sm, scattering=scattering)
    names = ["tau", "r_t", "r_r", "g_t", "g_r"] + (["n_i", "n_s"] if directions else [])
    res = io.numpy(*(t[n] for n in names), Rows(t["amplitudes"]))
    out = dict(zip(names, res[:-1], strict=True))
    out["amplitudes"] = res[-1].astype(np.complex128, copy=False)
    return out


def scatterer_echo_drjit(radar, geometry, p: NDArray, v: NDArray, s: NDArray,
                         directions: bool = False, *, variant: str | None = None) -> dict:
    """:func:`scatterer_echo` as one Dr.Jit kernel (former entry point).

    ``variant``: Mitsuba variant selecting ``drjit.llvm`` (default) or ``drjit.cuda``.
    """
    from ..backend import drjit_namespace

    return scatterer_echo(drjit_namespace(variant), radar, geometry, p, v, s, directions)


def facet_visibility(xp, geometry, facets: dict[str, Any]) -> tuple[Any, Any, Any]:
    """Facing test and ray-traced visibility of facets, as the facet engine has them.

    Returns ``(visible, n_i, n_s)``: Bool (lit from the transmitter and seen from the
    receiver: facing, eq G1 and the local angles, and not occluded, ``facets["hidden_tx"]``,
    ``facets["hidden_rx"]``) and the unit directions of eq G1 at the emission positions.
    """
    tx = np.asarray(geometry.tx.position, dtype=np.float64)
    rx = np.asarray(geometry.rx.position, dtype=np.float64)
    c, nrm = facets["centroid"], facets["normal"]
    _, _, n_i, n_s = ranges(xp, c, xp.vconst(tx), xp.vconst(rx),
                            bool(np.array_equal(tx, rx)))
    theta_i, theta_s, _ = bistatic_angles(xp, n_i, n_s, nrm)
    visible = ((theta_i < math.pi / 2) & ~facets["hidden_tx"]
               & (theta_s < math.pi / 2) & ~facets["hidden_rx"])
    return visible, n_i, n_s


def sea_echo_terms(xp, radar, geometry, facets: dict[str, Any], mechanisms_of: Any,
                   draws: Any, lo: float, hi: float, *, scattering: Any = None,
                   wavenumber: float | None = None) -> dict[str, Any]:
    """One pulse of sea facets over a namespace: visibility, eqs P1-P4, eqs R1 and R3.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    radar : seaecho.radar.system.RadarSystem
    geometry : seaecho.radar.system.PulseGeometry
        Platform states of the pulse; the facing test and the scattering use the
        positions at the emission (``geometry.tx.position``, ``geometry.rx.position``), as
        the facet engine does.
    facets : dict
        Namespace values: ``centroid``, ``normal``, ``velocity`` (vectors) [m, -, m/s],
        ``area`` [m^2], ``hidden_tx``, ``hidden_rx`` (Bool: segment to the transmitter /
        receiver blocked, ``FacetEngine.occlusion``); optionally ``position`` (vector
        [m]): the phase centres whose echo eqs R1 and R3 compute (the evolving sea's
        particle positions at the pulse's time, eq D1 of
        :mod:`seaecho.scattering.dynamics`), the centroids otherwise. The facing test and
        the scattering use the centroids, as the facet engine does.
    mechanisms_of : callable
        ``(n_i, n_s, N, monostatic=...) -> mechanisms``
        (:func:`seaecho.scattering.facet.mechanisms` with the sea's values bound): the
        facets' mechanism matrices and weights.
    draws : dict or callable
        Speckle draws per mechanism (complex namespace values, eq P4), or a callable
        ``draws(xp, io, context)`` returning them (the evolving speckle, eqs D2-D4 of
        :mod:`seaecho.scattering.dynamics`), evaluated in ``xp`` (float64) with the
        context of :func:`seaecho.scattering.facet.draw_context`, as the reference path
        (:func:`~seaecho.scattering.facet.speckled_facet_amplitudes`) does.
    lo, hi : float
        Delays [s] outside which an echo cannot reach the receive window
        (``ReceiveWindow.keep``).
    scattering : array namespace, optional
        The namespace of eqs P1-P4 (``mechanisms_of`` and the speckle; ``xp`` in float32,
        ``xp.with_precision("single")``): the directions, normals, areas and draws are
        cast to it, and the amplitudes it gives enter eqs R1 and R3, which stay in
        ``xp``. Default ``xp``.
    wavenumber : float, optional
        The radar's wavenumber ``k`` [rad/m] of the sea's scattering model (the
        ``FacetModel``'s), for callable ``draws``.

    Returns
    -------
    dict
        ``tau`` [s], ``amplitudes`` (one complex value per channel) [sqrt(W)] and ``keep``
        (Bool: visible and inside the window), for every facet.
    """
    xs = xp if scattering is None else scattering
    visible, n_i, n_s = facet_visibility(xp, geometry, facets)
    # Eqs P1-P4 with the facet's area times its visibility (0 or 1)
    area = facets["area"] * xp.select(visible, xp.const(1.0), xp.const(0.0))
    monostatic = bool(np.array_equal(geometry.tx.position, geometry.rx.position))
    mech = mechanisms_of(xs.cast(n_i), xs.cast(n_s), xs.cast(facets["normal"]),
                         monostatic=monostatic)  # n_s = -n_i there (eq G1)
    if callable(draws):  # the evolving speckle of the pulse's time, in float64
        if wavenumber is None:
            raise ValueError("sea_echo_terms: evolving draws need the wavenumber")
        draws = draws(xp, Boundary(xp), draw_context(xp, n_i, n_s, facets["normal"],
                                                      wavenumber))
    s = speckle(xs, mech, {m: xs.cast(g) for m, g in draws.items()}, xs.cast(area))
    # Eqs R1, R3
    t = echo_terms(xp, radar, geometry, facets.get("position", facets["centroid"]),
                   facets["velocity"], s, scattering=scattering)
    keep = visible & (t["tau"] > lo) & (t["tau"] < hi)
    return dict(tau=t["tau"], amplitudes=t["amplitudes"], keep=keep)
