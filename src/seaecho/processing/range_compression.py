"""Range compression: the matched filter, with optional amplitude weighting.

The compressed signal is the cross-correlation of the received samples with the
(weighted) transmitted pulse,

.. math::

    y[m] = \\frac{\\sum_n r[m + n]\\; w[n]\\, s^*[n]}{\\sum_n w[n]\\, |s[n]|^2}     (C1)

computed by FFT (zero padded, no wrap-around inside the window). Sample m of y is the
echo of delay t_0 + m / f_s: a point echo of amplitude a and integer-sample delay
gives y = a at its delay, so |y|^2 at the peak is the received power of the radar
equation whatever the weighting (the weighting's loss in signal-to-noise ratio is the
processing's, not the echo's).

For a linear FM pulse of bandwidth B and large time-bandwidth product, the unweighted
output is close to sinc(B t) (Cook & Bernfeld 1967, ch. 6; Richards 2014, section 4.6):
a 3 dB width of 0.886 / B in delay, i.e. 0.886 c / (2 B) in range, and a peak sidelobe
of -13.26 dB. Weighting w (Hamming, Taylor) trades a wider main lobe for lower
sidelobes (Harris 1978, Table 1: Hamming -42.7 dB with a 3 dB width of 1.30 bins
against 0.89 for the rectangle; Taylor at its design sidelobe level).

References
----------
.. [1] C. E. Cook and M. Bernfeld, *Radar Signals: An Introduction to Theory and
   Application*, Academic Press, 1967, chapter 6.
.. [2] M. A. Richards, *Fundamentals of Radar Signal Processing*, 2nd ed., McGraw-Hill,
   2014, sections 4.2 (matched filter), 4.6 (LFM), 5.1 (weighting).
.. [3] F. J. Harris, "On the use of windows for harmonic analysis with the discrete
   Fourier transform", Proc. IEEE 66(1), 51-83, 1978, Table 1.
.. [4] T. T. Taylor, "Design of line-source antennas for narrow beamwidth and low side
   lobes", IRE Trans. Antennas Propag. 3(1), 16-28, 1955.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.fft import next_fast_len

from .windows import sampled_window


def weighting_window(kind: str, n: int, nbar: int = 5, sidelobe_db: float = 35.0
                     ) -> NDArray[np.float64]:
    """Amplitude weighting of the matched filter.

    Parameters
    ----------
    kind : {'none', 'hamming', 'taylor'}
    n : int
        Number of pulse samples.
    nbar : int
        Taylor: number of nearly constant-level sidelobes.
    sidelobe_db : float
        Taylor: peak sidelobe level below the main lobe [dB], > 0.

    Returns
    -------
    ndarray (n,)
        w[n] >= 0 [-]: the symmetric window of :func:`seaecho.processing.windows.
        sampled_window` (end samples on the window's edges; its scale cancels in eq C1).
    """
    if kind not in ("none", "hamming", "taylor"):
        raise ValueError(f"weighting = {kind!r}: unknown; allowed: 'none', 'hamming', "
                         "'taylor'")
    return sampled_window(kind, n, nbar, sidelobe_db)


def range_compress(raw: ArrayLike, pulse: ArrayLike, weighting: str = "none", *,
                   nbar: int = 5, sidelobe_db: float = 35.0) -> NDArray[np.complex128]:
    """Matched-filter the fast-time axis (last axis) of raw samples, eq (C1).

    Parameters
    ----------
    raw : array_like (..., n_samples) complex
        Received samples [sqrt(W)].
    pulse : array_like (N_p,) complex
        Transmitted pulse samples s[n] (``Waveform.samples``).
    weighting : {'none', 'hamming', 'taylor'}
        Amplitude weighting of the reference.
    nbar, sidelobe_db : int, float
        Taylor parameters.

    Returns
    -------
    ndarray (..., n_samples) complex
        y[m] [sqrt(W)], aligned with the raw fast-time axis (sample m = delay of an echo
        whose pulse starts at sample m).
    """
    r = np.asarray(raw)
    s = np.asarray(pulse, dtype=np.complex128)
    w = weighting_window(weighting, s.size, nbar, sidelobe_db)
    h = w * s
    n = r.shape[-1]
    n_fft = int(next_fast_len(n + s.size))
    # Eq (C1): correlation by FFT, normalised by the weighted pulse energy
    spec = np.fft.fft(r, n_fft, axis=-1) * np.conj(np.fft.fft(h, n_fft))
    y = np.fft.ifft(spec, axis=-1)[..., :n]
    return y / np.sum(w * np.abs(s) ** 2)


__all__ = ["range_compress", "weighting_window"]
