"""Radiometric calibration of backprojected images: RCS and sigma0 per pixel.

A static scatterer of scattering amplitude S_mn [m] at x contributes to pulse p the
compressed echo a_p chi(t - tau_p(x)) with (``docs/radar.md`` eq R1, matched ports)

.. math::

    a_p = A_p(x)\\, S_{mn}\\, e^{-j 2\\pi f_c \\tau_p(x)},\\qquad
    A_p(x) = \\frac{\\sqrt{P_t\\, G_t\\, G_r}\\;\\lambda}{(4\\pi)^{3/2}\\, r_t\\, r_r}    (K1)

[sqrt(W)/m], G_t and G_r the antenna power gains towards x at pulse p and chi the
compressed pulse normalised to chi(0) = 1 (range compression eq C1, any weighting). The
backprojection (eq B2) of that scatterer at its own position is therefore
I(x) = K(x) S_mn with

.. math::

    K(x) = \\sum_p w_p(x)\\, A_p(x)                                                  (K2)

and the calibrated image s(x) = I(x) / K(x) [m] has |s|^2 = sigma_mn [m^2] at the peak of
a point target (its RCS), whatever the geometry, the antennas, the ranges, the number of
pulses, the window or the pulse compression gain: all of them are in K.

A distributed target of backscattering coefficient sigma0 (scatterers of independent
phases, E sum |S|^2 = sigma0 dA) gives E|s(x)|^2 = sigma0 A_eff(x), A_eff the integral of
the squared normalised impulse response over the image plane. Linearising tau_p about x
(g_p = grad tau_p, horizontal part [s/m]) the response to a scatterer at x - u is
sum_p w_p A_p chi(g_p . u) exp(j 2 pi f_c g_p . u) / K; its 2-D spectrum occupies the
wavenumbers kappa = (f_c + f) g_p (f the baseband frequency, p the pulse) and Parseval's
theorem, with the pulses dense enough to treat p as continuous (no azimuth ambiguity
inside the band), gives

.. math::

    A_{\\mathrm{eff}}(x) = \\frac{E_\\chi}{K(x)^2}\\sum_p
        \\frac{w_p^2 A_p^2}{f_c\\, |g_p \\times \\dot g_p|},\\qquad
    E_\\chi = \\int |\\chi(t)|^2 dt                                                   (K3)

with g_p-dot = dg/dp the change of the delay gradient from one pulse to the next (central
difference) and the cross product's z component. For a monostatic broadside stripmap with
uniform weights this is the textbook resolution cell: E_chi = 1/B for an ideal sinc
pulse, |g| = 2 sin(theta_i)/c and f_c |g-dot| = 2 v / (lambda R PRF) give
A_eff = (c / (2 B sin theta_i)) (lambda R / (2 L)), L the processed aperture (Cumming &
Wong 2005, eqs 4.37 and 4.39 with the integral of sinc^2 equal to 1; Ulaby & Long 2014,
section 13-4, for sigma0 = mean intensity over the cell area). In the bistatic case
|g x g-dot| is the area of the parallelogram of the range and Doppler gradients, i.e.
the bistatic resolution cell of Cardillo (1990) and Moccia & Renga (2011), who write it
as delta_r delta_a / sin(beta) with beta the angle between the two gradients.

The calibrated sigma0 image is |s(x)|^2 / A_eff(x) [m^2/m^2]. E_chi is computed from the
transmitted pulse and the range weighting (sum of |chi[m]|^2 / f_s, exact for a pulse
band-limited to f_s). K and A_eff vary on the scale of the antenna footprints; they are
evaluated on a coarse grid of nodes and interpolated (cubic) to the pixels.

References
----------
.. [1] I. G. Cumming and F. H. Wong, *Digital Processing of Synthetic Aperture Radar
   Data*, Artech House, 2005, sections 4.3-4.5.
.. [2] F. T. Ulaby and D. G. Long, *Microwave Radar and Radiometric Remote Sensing*,
   University of Michigan Press, 2014, ch. 13.
.. [3] G. P. Cardillo, "On the use of the gradient to determine bistatic SAR resolution",
   Antennas and Propagation Society International Symposium, 1990, 1032-1035.
.. [4] A. Moccia and A. Renga, "Spatial resolution of bistatic synthetic aperture radar:
   impact of acquisition geometry on imaging performance", IEEE Trans. Geosci. Remote
   Sens. 49(10), 3487-3503, 2011.
.. [5] M. I. Skolnik (ed.), *Radar Handbook*, 3rd ed., McGraw-Hill, 2008, eq 23.1
   (bistatic radar equation, eq K1 squared).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import C0
from ..radar.equation import path_amplitude
from .backprojection import delays, doppler
from .windows import AzimuthWindow

__all__ = [
    "CalibrationMaps",
    "Track",
    "amplitude_factor",
    "calibration_at",
    "compressed_pulse_energy",
    "delay_gradient",
]


@dataclass(frozen=True)
class Track:
    """Platform states used by the processor, one row per pulse.

    Attributes
    ----------
    tx, rx : ndarray (N, 3)
        Positions at emission [m].
    tx_velocity, rx_velocity : ndarray (N, 3)
        Velocities [m/s].
    tx_axes, rx_axes : ndarray (N, 3, 3)
        Antenna axes in the world (columns boresight, width, height) [-].
    """

    tx: NDArray[np.float64]
    rx: NDArray[np.float64]
    tx_velocity: NDArray[np.float64]
    rx_velocity: NDArray[np.float64]
    tx_axes: NDArray[np.float64]
    rx_axes: NDArray[np.float64]

    def __getitem__(self, index) -> Track:
        return Track(*(a[index] for a in (self.tx, self.rx, self.tx_velocity,
                                          self.rx_velocity, self.tx_axes, self.rx_axes)))

    @property
    def n_pulses(self) -> int:
        return int(self.tx.shape[0])

    def doppler_centroid(self, wavelength: float) -> NDArray[np.float64]:
        """f_c,p of eq (B4): Doppler of the point on both boresights [Hz], shape (N,)."""
        return (np.einsum("ni,ni->n", self.tx_velocity, self.tx_axes[:, :, 0])
                + np.einsum("ni,ni->n", self.rx_velocity, self.rx_axes[:, :, 0])) / wavelength


def amplitude_factor(points: ArrayLike, track: Track, tx_antenna, rx_antenna,
                     transmit_power: float, wavelength: float) -> NDArray[np.float64]:
    """A_p(x) of eq (K1) for every point and pulse [sqrt(W)/m].

    Parameters
    ----------
    points : array_like (P, 3)
        Positions [m].
    track : Track
        Platform positions and antenna axes (N pulses).
    tx_antenna, rx_antenna : seaecho.radar.antennas.Antenna
        Patterns (``gain_local``).
    transmit_power : float
        P_t [W].
    wavelength : float
        lambda [m].

    Returns
    -------
    ndarray (P, N)
    """
    x = np.asarray(points, dtype=np.float64)[:, None, :]
    gains, ranges = [], []
    for pos, axes, ant in ((track.tx, track.tx_axes, tx_antenna),
                           (track.rx, track.rx_axes, rx_antenna)):
        if gains and ant == tx_antenna and np.array_equal(pos, track.tx) \
                and np.array_equal(axes, track.tx_axes):  # monostatic: the same factors
            gains.append(gains[0])
            ranges.append(ranges[0])
            continue
        d = x - pos[None]
        r = np.linalg.norm(d, axis=-1)
        d_local = np.einsum("nji,pnj->pni", axes, d / r[..., None])
        gains.append(ant.gain_local(d_local))
        ranges.append(r)
    # Eq (K1), the amplitude of the bistatic radar equation per unit S (radar eq R1)
    return path_amplitude(transmit_power, gains[0], gains[1], wavelength, ranges[0],
                          ranges[1])


def delay_gradient(points: ArrayLike, track: Track) -> NDArray[np.float64]:
    """Horizontal gradient g_p(x) of the delay (r_t + r_r)/c [s/m], shape (P, N, 2)."""
    x = np.asarray(points, dtype=np.float64)[:, None, :]
    g = np.zeros(x.shape[:1] + (track.n_pulses, 3))
    for pos in (track.tx, track.rx):
        d = x - pos[None]
        g += d / np.linalg.norm(d, axis=-1, keepdims=True)
    return g[..., :2] / C0


def compressed_pulse_energy(pulse: ArrayLike, sampling_rate: float, weighting: str = "none",
                            nbar: int = 5, sidelobe_db: float = 35.0) -> float:
    """E_chi of eq (K3): the energy of the compressed pulse normalised to chi(0) = 1 [s].

    The pulse's own echo is compressed with ``processing.range_compression`` (eq C1,
    whose normalisation puts chi(0) = 1) and sum |chi[m]|^2 / f_s is returned (Parseval on
    the samples of a signal band-limited to f_s). An ideal sinc pulse of bandwidth B
    gives 1/B.
    """
    from ..processing.range_compression import range_compress

    s = np.asarray(pulse, dtype=np.complex128)
    n = s.size
    r = np.concatenate([np.zeros(n), s, np.zeros(2 * n)])
    chi = range_compress(r, s, weighting, nbar=nbar, sidelobe_db=sidelobe_db)
    return float(np.sum(np.abs(chi) ** 2) / sampling_rate)


@dataclass(frozen=True)
class CalibrationMaps:
    """K(x) and A_eff(x) of eqs (K2)-(K3) at a set of points.

    Attributes
    ----------
    gain : ndarray (P,)
        K(x) [sqrt(W)/m].
    area : ndarray (P,)
        A_eff(x) [m^2] (NaN where no pulse is weighted or the aperture does not turn).
    """

    gain: NDArray[np.float64]
    area: NDArray[np.float64]


def calibration_at(points: ArrayLike, track: Track, tx_antenna, rx_antenna,
                   transmit_power: float, carrier: float, window: AzimuthWindow,
                   pulse_energy: float, weight: ArrayLike | None = None,
                   delay_window: tuple[float, float] | None = None,
                   max_elements: int = 2_000_000) -> CalibrationMaps:
    """Eqs (K2)-(K3) at points, with the weights w_p(x) of eq (B4).

    Parameters
    ----------
    points : array_like (P, 3)
        Positions on the image surface [m].
    track : Track
        The processor's track (N pulses).
    tx_antenna, rx_antenna : Antenna
        Patterns.
    transmit_power, carrier : float
        P_t [W], f_c [Hz].
    window : AzimuthWindow
        Processed Doppler band and window.
    pulse_energy : float
        E_chi [s] (:func:`compressed_pulse_energy`).
    weight : array_like (N,), optional
        Extra per-pulse weights (default 1).
    delay_window : (float, float), optional
        Delays [s] the receive window covers; pulses whose echo of x falls outside do not
        count (they add nothing to the image either).
    max_elements : int
        Points x pulses per vectorised tile.

    Returns
    -------
    CalibrationMaps
    """
    x = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    lam = C0 / carrier
    n = track.n_pulses
    wp = np.ones(n) if weight is None else np.asarray(weight, dtype=float)
    fdc = track.doppler_centroid(lam)
    gain = np.zeros(x.shape[0])
    area = np.full(x.shape[0], np.nan)
    step = max(1, max_elements // max(n, 1))
    for s in range(0, x.shape[0], step):  # tiles of points, each vectorised
        xs = x[s:s + step]
        a = amplitude_factor(xs, track, tx_antenna, rx_antenna, transmit_power, lam)
        f = doppler(xs, track.tx, track.rx, track.tx_velocity, track.rx_velocity, lam)
        with np.errstate(over="ignore"):  # outside any band: W(+-inf) = 0
            w = window((f - fdc[None, :]) / window.bandwidth) * wp[None, :]
        if delay_window is not None:
            tau = delays(xs, track.tx, track.rx, track.rx_velocity)
            w = w * ((tau >= delay_window[0]) & (tau <= delay_window[1]))
        k = np.sum(w * a, axis=1)  # eq (K2)
        gain[s:s + step] = k
        if n < 2:
            continue
        g = delay_gradient(xs, track)
        g_dot = np.gradient(g, axis=1)
        jac = carrier * np.abs(g[..., 0] * g_dot[..., 1] - g[..., 1] * g_dot[..., 0])
        # Eq (K3) is the same for A_p over any constant: over 2^e near each point's
        # largest, its squares neither underflow (a 5e-324 W transmitter's A_p^2 is
        # 1e-340) nor overflow; a power of two keeps the bytes of ordinary values
        with np.errstate(divide="ignore"):
            e = np.frexp(np.max(np.abs(w * a), axis=1, initial=0.0))[1]
        wa = w * a * np.ldexp(1.0, -e)[:, None]
        kn = np.sum(wa, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            # pulses of zero weight do not count even where jac = 0
            terms = np.where(w > 0, wa**2 / jac, 0.0)
            area[s:s + step] = pulse_energy * np.sum(terms, axis=1) / (kn * kn)
    area[~np.isfinite(area) | (area <= 0)] = np.nan
    return CalibrationMaps(gain, area)
