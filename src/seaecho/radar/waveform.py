"""Transmitted waveforms: linear FM chirp and plain pulse, as complex baseband samples.

The transmitted envelope is the band-limited (ideal DAC) interpolation of its samples
s[n] = s(n / f_s), n = 0 .. N_p - 1, so that an echo delayed by any tau, fractional or
not, is sampled exactly by a phase ramp in the frequency domain (``seaecho.radar.echo``).

.. math::

    s_{\\mathrm{LFM}}(t) = \\exp\\!\\left(j \\pi \\frac{B}{T}\\,(t - T/2)^2\\right),\\quad
    0 \\le t < T                                                                     (W1)

    s_{\\mathrm{pulse}}(t) = 1,\\quad 0 \\le t < T                                      (W2)

(down-chirp: B -> -B). Unit amplitude: the echo's peak power is set by the radar
equation (``seaecho.radar.equation``).

References
----------
.. [1] M. A. Richards, *Fundamentals of Radar Signal Processing*, 2nd ed., McGraw-Hill,
   2014, section 4.6 (linear FM pulse, eq 4.78).
.. [2] C. E. Cook and M. Bernfeld, *Radar Signals: An Introduction to Theory and
   Application*, Academic Press, 1967, chapter 6.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray


def chirp_rate(bandwidth: float, duration: float, up: bool = True) -> float:
    """Chirp rate k = +-B / T [Hz/s] of the linear FM chirp of eq (W1) (Richards 2014,
    eq 4.78): its instantaneous frequency is k (t - T/2)."""
    return (1.0 if up else -1.0) * bandwidth / duration


def lfm_chirp(bandwidth: float, duration: float, sampling_rate: float, up: bool = True
              ) -> NDArray[np.complex128]:
    """Samples of a unit-amplitude linear FM chirp, eq (W1).

    Parameters
    ----------
    bandwidth : float
        Swept bandwidth B [Hz].
    duration : float
        Pulse length T [s].
    sampling_rate : float
        Complex sampling rate f_s [Hz], at least B.
    up : bool
        Rising (True) or falling frequency.

    Returns
    -------
    ndarray (N_p,) complex
        s(n / f_s) for n = 0 .. ceil(T f_s) - 1.

    References
    ----------
    Richards (2014), eq 4.78, centred on the pulse so the spectrum is centred on 0 Hz.
    """
    if bandwidth <= 0 or duration <= 0 or sampling_rate <= 0:
        raise ValueError(f"bandwidth = {bandwidth} Hz, duration = {duration} s, "
                         f"sampling_rate = {sampling_rate} Hz must all be > 0")
    n = max(int(np.ceil(duration * sampling_rate - 1e-9)), 1)
    t = np.arange(n) / sampling_rate
    k = chirp_rate(bandwidth, duration, up)
    # Eq (W1): quadratic phase, instantaneous frequency k (t - T/2) in [-B/2, B/2]
    return np.exp(1j * np.pi * k * (t - 0.5 * duration) ** 2)


def plain_pulse(duration: float, sampling_rate: float) -> NDArray[np.complex128]:
    """Samples of a unit-amplitude rectangular pulse of length T [s], eq (W2)."""
    if duration <= 0 or sampling_rate <= 0:
        raise ValueError(f"duration = {duration} s, sampling_rate = {sampling_rate} Hz "
                         "must be > 0")
    n = max(int(np.ceil(duration * sampling_rate - 1e-9)), 1)
    return np.ones(n, dtype=complex)


@dataclass(frozen=True)
class Waveform:
    """A sampled transmit pulse.

    Attributes
    ----------
    samples : ndarray (N_p,) complex
        s[n] [sqrt(W) per sqrt(W) transmitted: unit amplitude].
    sampling_rate : float
        f_s [Hz].
    bandwidth : float
        B [Hz] (1/T for a plain pulse).
    duration : float
        T [s].
    chirp_rate : float
        k [Hz/s] of an LFM chirp (:func:`chirp_rate`); 0 for a plain pulse.
    """

    samples: NDArray[np.complex128]
    sampling_rate: float
    bandwidth: float
    duration: float
    chirp_rate: float = 0.0

    @classmethod
    def lfm(cls, bandwidth: float, duration: float, sampling_rate: float,
            up: bool = True) -> Waveform:
        """Linear FM chirp of bandwidth B [Hz] and length T [s] at f_s [Hz], eq (W1)."""
        return cls(lfm_chirp(bandwidth, duration, sampling_rate, up), sampling_rate,
                   bandwidth, duration, chirp_rate(bandwidth, duration, up))

    @classmethod
    def pulse(cls, duration: float, sampling_rate: float) -> Waveform:
        """Plain rectangular pulse of length T [s] at f_s [Hz] (bandwidth 1/T), eq (W2)."""
        return cls(plain_pulse(duration, sampling_rate), sampling_rate, 1.0 / duration,
                   duration)

    @property
    def n_samples(self) -> int:
        """Number of samples N_p of the pulse."""
        return int(self.samples.size)

    def spectrum(self, n_fft: int) -> NDArray[np.complex128]:
        """DFT of the pulse zero-padded to ``n_fft`` (FFT order): S_l = sum s[n] e^{-j2pi ln/N}."""
        if n_fft < self.n_samples:
            raise ValueError(f"n_fft = {n_fft} is shorter than the pulse ({self.n_samples})")
        return np.fft.fft(self.samples, n_fft)


__all__ = ["Waveform", "chirp_rate", "lfm_chirp", "plain_pulse"]
