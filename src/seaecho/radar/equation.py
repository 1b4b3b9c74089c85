"""The bistatic polarimetric radar equation (paper eq 3) and the time of flight.

Each scatterer k (a point target or a sea facet) returns, on channel (m, n) = (receive
port m, transmit port n), the complex amplitude

.. math::

    a_{mn} = \\frac{\\sqrt{P_t\\,G_t(\\hat d_t)\\,G_r(\\hat d_r)}\\;\\lambda}
                  {(4\\pi)^{3/2}\\; r_t\\, r_r}\\;
             \\hat{\\mathbf r}_m^{\\,T}\\, \\mathbf S\\, \\hat{\\mathbf t}_n\\;
             e^{-j 2\\pi f_c \\tau}                                                   (R1)

in sqrt(W), where S [m] is the 2x2 scattering amplitude in the forward-scattering-
alignment bases (h, v) of n_i and n_s (|S_mn|^2 = sigma_mn [m^2]), t_n and r_m are the
transmit and receive port states projected on those bases (``seaecho.radar.antennas``),
and tau = tau_t + tau_r the time of flight. For a point scatterer of RCS sigma seen by
matched ports, |a|^2 is the bistatic radar equation

.. math::

    P_r = \\frac{P_t\\, G_t\\, G_r\\, \\lambda^2\\, \\sigma}{(4\\pi)^3\\, r_t^2\\, r_r^2} (R2)

(Skolnik 2008, eq 23.1; Willis 2005, eq 3.1). Eq (R1) is the paper's eq (3) with its
S = S_(R1) / sqrt(4 pi) (paper eq 2: <|S|^2> = A_0 sigma / (4 pi)) and its amplitude
gain matrices G = sqrt(G) lambda / sqrt(4 pi) (effective aperture A_e = G lambda^2 /
(4 pi)); the paper's 1/(2 pi r_X r_R) with those factors gives (R2).

Time of flight (paper section IV-C: "computed with respect to the objects' position and
speed at the time when the signal has been emitted"). With the transmitter at p_t at
the emission time, a scatterer moving as p_k + v_k t and the receiver as p_r + v_r t,
the outbound delay solves |p_k + v_k tau_t - p_t| = c tau_t and the return delay
|p_r + v_r (tau_t + tau_r) - p_k - v_k tau_t| = c tau_r, both quadratics
|D + V tau| = c tau with the positive root

.. math::

    \\tau = \\frac{D\\cdot V + \\sqrt{(D\\cdot V)^2 + (c^2 - |V|^2)\\,|D|^2}}{c^2 - |V|^2}
                                                                                    (R3)

so that the pulse-to-pulse phase of eq (R1) carries the Doppler frequency
f_D = -(1/lambda) d(r_t + r_r)/dt of platform and wave motion (Willis 2005, eq 3.23).
Everything here is float64: at 10 GHz, float32 k r over kilometres is off by degrees.
The formulas are written once over an array namespace (:func:`delay`, :func:`flight`,
:func:`amplitude_factor`, :func:`carrier`, :func:`polarimetric_factor`;
:mod:`seaecho.backend`): the numpy functions below and the fused Dr.Jit radar kernel
(``seaecho.radar.kernels``) call them.

References
----------
.. [1] M. I. Skolnik (ed.), *Radar Handbook*, 3rd ed., McGraw-Hill, 2008, ch. 23
   (N. J. Willis, "Bistatic radar"), eq 23.1.
.. [2] N. J. Willis, *Bistatic Radar*, SciTech, 2005, eqs 3.1 and 3.23.
.. [3] J. A. Kong, *Electromagnetic Wave Theory*, EMW, 2000 (effective aperture
   A_e = G lambda^2 / 4 pi).
.. [4] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary, Mat2
from ..constants import C0, K_B, T0


# ------------------------------------------------------------- formulas (any namespace)
def delay(xp, d: Any, v: Any) -> Any:
    """Positive root tau of ``|D + V tau| = c tau``, eq (R3) [s] (namespace vectors)."""
    dv = xp.dot(d, v)
    a = C0 * C0 - xp.dot(v, v)
    # Eq (R3): the root that is positive for any |v| < c
    return (dv + xp.sqrt(dv * dv + a * xp.dot(d, d))) / a


def flight(xp, p_tx: Any, p_sc: Any, v_sc: Any, p_rx: Any, v_rx: Any
           ) -> tuple[Any, Any, Any]:
    """Outbound and return delays [s] and the bounce point [m] of eq (R3) (namespace).

    The scatterer moves as ``p_sc + v_sc t`` and the receiver as ``p_rx + v_rx t`` from
    the emission at ``t = 0`` by the transmitter at ``p_tx``.
    """
    tau_t = delay(xp, p_sc - p_tx, v_sc)
    p_b = p_sc + v_sc * tau_t
    tau_r = delay(xp, p_rx + v_rx * tau_t - p_b, v_rx)
    return tau_t, tau_r, p_b


def amplitude_factor(xp, transmit_power: float, g_t: Any, g_r: Any, wavelength: float,
                     r_t: Any, r_r: Any) -> Any:
    """Real factor of eq (R1): ``sqrt(P_t G_t G_r) lambda / ((4 pi)^1.5 r_t r_r)``.

    [sqrt(W) / m]: times a scattering amplitude [m] gives sqrt(W); squared with
    ``|S|^2 = sigma`` it is eq (R2).
    """
    return (math.sqrt(transmit_power) * wavelength / (4.0 * math.pi) ** 1.5) * xp.sqrt(
        g_t * g_r) / (r_t * r_r)


def carrier(xp, frequency: float, tau: Any) -> Any:
    """The carrier phase factor ``exp(-j 2 pi f_c tau)`` of eq (R1) [-].

    ``f_c tau`` (about 1e5 cycles) is reduced modulo one cycle before its sine and
    cosine, which keeps the phase exact to about 1e-11 rad in float64.
    """
    cycles = frequency * tau
    phase = (-2.0 * math.pi) * (cycles - xp.floor(cycles))
    return xp.complex(xp.cos(phase), xp.sin(phase))


def polarimetric_factor(rx_ports: Mat2, s: Mat2, tx_ports: Mat2) -> Mat2:
    """``r_m^T S t_n`` of eq (R1) for all port pairs: ``R S T^T`` [m].

    ``rx_ports[m, p]``: receive port m on the FSA basis of ``n_s``; ``tx_ports[n, q]``:
    transmit port n on the basis of ``n_i``; ``s[p, q]`` (p scattered, q incident).
    """
    return rx_ports @ s @ tx_ports.T


# ---------------------------------------------------------------------- numpy API


def propagation_delay(d: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
    """Positive root tau of |D + V tau| = c tau, eq (R3) [s].

    Parameters
    ----------
    d : array_like (..., 3)
        Vector from the emitter (at emission) to the receiver's position at time 0 [m].
    v : array_like (..., 3)
        Velocity of the receiving end relative to that frame [m/s], |v| < c.
    """
    io = Boundary(NUMPY)
    return np.asarray(delay(NUMPY, io.vec3(d), io.vec3(v)))


def time_of_flight(
    p_tx: ArrayLike, p_sc: ArrayLike, v_sc: ArrayLike, p_rx: ArrayLike, v_rx: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Outbound and return delays of a pulse emitted at time 0, eq (R3).

    Parameters
    ----------
    p_tx : array_like (..., 3)
        Transmitter position at emission [m].
    p_sc, v_sc : array_like (..., 3)
        Scatterer position at emission [m] and velocity [m/s].
    p_rx, v_rx : array_like (..., 3)
        Receiver position at emission [m] and velocity [m/s].

    Returns
    -------
    tau_t, tau_r : ndarray (...)
        Transmitter-to-scatterer and scatterer-to-receiver delays [s]; the ranges are
        r_t = c tau_t and r_r = c tau_r [m].
    p_bounce : ndarray (..., 3)
        Scatterer position when the pulse reaches it [m].
    """
    io = Boundary(NUMPY)
    tau_t, tau_r, p_b = flight(NUMPY, *(io.vec3(a) for a in (p_tx, p_sc, v_sc, p_rx, v_rx)))
    tau_t, tau_r = np.broadcast_arrays(tau_t, tau_r)
    return np.array(tau_t), np.array(tau_r), np.stack(np.broadcast_arrays(*p_b), axis=-1)


def path_amplitude(transmit_power: float, g_t: ArrayLike, g_r: ArrayLike,
                   wavelength: float, r_t: ArrayLike, r_r: ArrayLike) -> NDArray[np.float64]:
    """Real amplitude factor of eq (R1): sqrt(P_t G_t G_r) lambda / ((4 pi)^1.5 r_t r_r).

    Parameters
    ----------
    transmit_power : float
        P_t [W].
    g_t, g_r : array_like
        Transmit and receive power gains towards the scatterer [-].
    wavelength : float
        lambda [m].
    r_t, r_r : array_like
        Ranges transmitter-scatterer and scatterer-receiver [m].

    Returns
    -------
    ndarray
        [sqrt(W) / m]: times a scattering amplitude [m] gives sqrt(W).
    """
    # Eq (R1) without S and the phase; squared with |S|^2 = sigma it is eq (R2)
    return np.asarray(amplitude_factor(NUMPY, transmit_power, *(
        np.asarray(a, dtype=np.float64) for a in (g_t, g_r)), wavelength, *(
        np.asarray(a, dtype=np.float64) for a in (r_t, r_r))))


def bistatic_received_power(transmit_power: float, g_t: ArrayLike, g_r: ArrayLike,
                            wavelength: float, sigma: ArrayLike, r_t: ArrayLike,
                            r_r: ArrayLike) -> NDArray[np.float64]:
    """The bistatic radar equation, eq (R2) [W].

    References
    ----------
    Skolnik (2008), eq 23.1; Willis (2005), eq 3.1.
    """
    return (transmit_power * np.asarray(g_t) * np.asarray(g_r) * wavelength**2
            * np.asarray(sigma) / ((4.0 * np.pi) ** 3 * np.asarray(r_t) ** 2
                                   * np.asarray(r_r) ** 2))


def channel_matrix(s: ArrayLike, rx_ports: ArrayLike, tx_ports: ArrayLike
                   ) -> NDArray[np.complex128]:
    """Polarimetric factor r_m^T S t_n of eq (R1) for all port pairs.

    Parameters
    ----------
    s : array_like (..., 2, 2) complex
        Scattering amplitude [m] in (h, v) order, S[..., p, q]: p scattered, q incident.
    rx_ports : array_like (..., 2, 2) complex
        Receive port states on (h_s, v_s): [..., m, p] (``project_ports`` of the
        receive antenna's conjugated states).
    tx_ports : array_like (..., 2, 2) complex
        Transmit port states on (h_i, v_i): [..., n, q].

    Returns
    -------
    ndarray (..., 2, 2) complex
        [..., m, n] [m]: receive port m, transmit port n.
    """
    def mat(a):
        a = np.asarray(a)
        return Mat2(a[..., 0, 0], a[..., 0, 1], a[..., 1, 0], a[..., 1, 1])

    m = polarimetric_factor(mat(rx_ports), mat(s), mat(tx_ports))
    e = np.broadcast_arrays(*m.flat())
    return np.stack(e, axis=-1).reshape(e[0].shape + (2, 2))


def noise_power(noise_figure_db: float, bandwidth: float) -> float:
    """Thermal noise power k T0 F B [W] (Skolnik 2008, eq 1.8).

    Parameters
    ----------
    noise_figure_db : float
        Receiver noise figure F [dB].
    bandwidth : float
        Noise bandwidth B [Hz].
    """
    return K_B * T0 * 10.0 ** (noise_figure_db / 10.0) * bandwidth


def thermal_noise(shape: tuple[int, ...], power: float, rng: np.random.Generator
                  ) -> NDArray[np.complex128]:
    """Circular complex white Gaussian noise with E|n|^2 = power [W] per sample."""
    scale = np.sqrt(0.5 * power)
    return scale * (rng.standard_normal(shape) + 1j * rng.standard_normal(shape))


__all__ = [
    "amplitude_factor",
    "bistatic_received_power",
    "carrier",
    "channel_matrix",
    "delay",
    "flight",
    "noise_power",
    "path_amplitude",
    "polarimetric_factor",
    "propagation_delay",
    "thermal_noise",
    "time_of_flight",
]
