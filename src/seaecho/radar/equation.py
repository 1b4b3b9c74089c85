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

References
----------
.. [1] M. I. Skolnik (ed.), *Radar Handbook*, 3rd ed., McGraw-Hill, 2008, ch. 23
   (N. J. Willis, "Bistatic radar"), eq 23.1.
.. [2] N. J. Willis, *Bistatic Radar*, SciTech, 2005, eqs 3.1 and 3.23.
.. [3] J. A. Kong, *Electromagnetic Wave Theory*, EMW, 2000 (effective aperture
   A_e = G lambda^2 / 4 pi).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import C0, K_B, T0


def propagation_delay(d: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
    """Positive root tau of |D + V tau| = c tau, eq (R3) [s].

    Parameters
    ----------
    d : array_like (..., 3)
        Vector from the emitter (at emission) to the receiver's position at time 0 [m].
    v : array_like (..., 3)
        Velocity of the receiving end relative to that frame [m/s], |v| < c.
    """
    d = np.asarray(d, dtype=np.float64)
    v = np.asarray(v, dtype=np.float64)
    dv = np.einsum("...i,...i->...", d, v)
    dd = np.einsum("...i,...i->...", d, d)
    a = C0 * C0 - np.einsum("...i,...i->...", v, v)
    # Eq (R3): the root that is positive for any |v| < c
    return (dv + np.sqrt(dv * dv + a * dd)) / a


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
    p_sc = np.asarray(p_sc, dtype=np.float64)
    v_sc = np.asarray(v_sc, dtype=np.float64)
    tau_t = propagation_delay(p_sc - p_tx, v_sc)
    p_bounce = p_sc + v_sc * tau_t[..., None]
    p_rx_b = np.asarray(p_rx, dtype=np.float64) + np.asarray(v_rx, dtype=np.float64) \
        * tau_t[..., None]
    tau_r = propagation_delay(p_rx_b - p_bounce, v_rx)
    return tau_t, tau_r, p_bounce


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
    g = np.asarray(g_t, dtype=np.float64) * np.asarray(g_r, dtype=np.float64)
    # Eq (R1) without S and the phase; squared with |S|^2 = sigma it is eq (R2)
    return np.sqrt(transmit_power * g) * wavelength / (
        (4.0 * np.pi) ** 1.5 * np.asarray(r_t, dtype=np.float64)
        * np.asarray(r_r, dtype=np.float64))


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
    return np.einsum("...mp,...pq,...nq->...mn", rx_ports, s, tx_ports)


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
    "bistatic_received_power",
    "channel_matrix",
    "noise_power",
    "path_amplitude",
    "propagation_delay",
    "thermal_noise",
    "time_of_flight",
]
