"""Weighting windows, once for every use: cosine series on [-1/2, 1/2], sampled or not.

Every window of seaecho is one of these: the range weighting of the matched filter
(``processing.range_compression``), the taper over the pulses of a Doppler spectrum
(``processing.doppler``), and the azimuth window of the backprojection
(``imaging.windows``, eq B4), which is evaluated at the normalised Doppler offset xi of
each pulse and pixel, not on a fixed set of samples. Each is the cosine series

.. math::

    W(\\xi) = \\frac{\\sum_{m=0}^{M} c_m \\cos(2\\pi m \\xi)}{\\sum_{m=0}^{M} c_m},
    \\quad |\\xi| \\le 1/2,\\qquad W(\\xi) = 0 \\text{ otherwise}                       (W1)

normalised to W(0) = 1:

- rectangular: c = (1);
- Hann: c = (0.5, 0.5) (Harris 1978, eq 27b and Table 1: peak sidelobe -32 dB);
- Hamming: c = (0.54, 0.46) (Harris 1978, eq 30 and Table 1: peak sidelobe -43 dB,
  3 dB width 1.30 bins against 0.89 for the rectangle);
- Taylor (nbar, sidelobe level SLL): c_0 = 1, c_m = 2 F_m for m = 1 .. nbar - 1 with

.. math::

    F_m = \\frac{(-1)^{m+1}}{2}\\,
          \\frac{\\prod_{n=1}^{\\bar n-1}\\left(1 - \\frac{m^2}{\\sigma^2 (A^2 +
          (n - 1/2)^2)}\\right)}{\\prod_{n \\ne m}\\left(1 - \\frac{m^2}{n^2}\\right)},\\quad
    A = \\frac{\\cosh^{-1} 10^{SLL/20}}{\\pi},\\quad
    \\sigma^2 = \\frac{\\bar n^2}{A^2 + (\\bar n - 1/2)^2}                               (W2)

(Taylor 1955; Carrara, Goodman & Majewski 1995, appendix D), the coefficients of
``scipy.signal.windows.taylor``, which samples the same function.

A window of N samples (:func:`sampled_window`) takes W at xi_n = (n - (N - 1)/2) / D,
n = 0 .. N - 1: D = N - 1 puts the end samples on the window's edges (Harris's
symmetric window: ``numpy.hamming``), D = N + 1 keeps them inside, where a Hann window is
not zero (an end sample of weight 0 would drop a pulse from a Doppler spectrum).

References
----------
.. [1] F. J. Harris, "On the use of windows for harmonic analysis with the discrete
   Fourier transform", Proc. IEEE 66(1), 51-83, 1978.
.. [2] T. T. Taylor, "Design of line-source antennas for narrow beamwidth and low side
   lobes", IRE Trans. Antennas Propag. 3(1), 16-28, 1955.
.. [3] W. G. Carrara, R. S. Goodman and R. M. Majewski, *Spotlight Synthetic Aperture
   Radar: Signal Processing Algorithms*, Artech House, 1995, appendix D.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY

__all__ = ["cosine_coefficients", "cosine_series", "sampled_window", "window_values"]


def cosine_coefficients(kind: str, nbar: int = 5, sidelobe_db: float = 35.0
                        ) -> tuple[float, ...]:
    """Cosine-series coefficients c_m of eq (W1) for a window name.

    Parameters
    ----------
    kind : {'none', 'hann', 'hamming', 'taylor'}
        Window.
    nbar : int
        Taylor: number of nearly constant-level sidelobes (>= 1).
    sidelobe_db : float
        Taylor: peak sidelobe level below the main lobe [dB], > 0.

    Returns
    -------
    tuple of float
        (c_0, c_1, ...) [-].
    """
    if kind == "none":
        return (1.0,)
    if kind == "hann":
        return (0.5, 0.5)
    if kind == "hamming":
        return (0.54, 0.46)
    if kind != "taylor":
        raise ValueError(f"window = {kind!r}: unknown; allowed 'none', 'hann', 'hamming', "
                         "'taylor'")
    if nbar < 1 or sidelobe_db <= 0:
        raise ValueError(f"Taylor window nbar = {nbar} (>= 1), sidelobe_db = {sidelobe_db} "
                         "(> 0)")
    # Eq (W2)
    a = np.arccosh(10.0 ** (sidelobe_db / 20.0)) / np.pi
    s2 = nbar**2 / (a * a + (nbar - 0.5) ** 2)
    m = np.arange(1, nbar, dtype=float)
    coeffs = [1.0]
    for i, mi in enumerate(m):
        num = (-1.0) ** (mi + 1) * np.prod(1.0 - mi * mi / s2 / (a * a + (m - 0.5) ** 2))
        others = np.delete(m, i)
        den = 2.0 * np.prod(1.0 - mi * mi / (others * others))
        coeffs.append(2.0 * num / den)
    return tuple(float(c) for c in coeffs)


def cosine_series(xp, xi: Any, coef: list) -> Any:
    """``sum_m c_m cos(2 pi m xi)`` of eq (W1) in namespace ``xp`` [-], for |xi| <= 1/2.

    cos(m t) by the Chebyshev recurrence (one cosine per point); the caller normalises
    ``coef`` and masks |xi| > 1/2. Written once for numpy and the Dr.Jit kernel of the
    backprojection (:mod:`seaecho.backend`).
    """
    c1 = xp.cos(xi * (2.0 * np.pi))
    w = coef[0]
    prev, cur = 1.0, c1
    for m in range(1, len(coef)):
        if m > 1:  # cos(m t) = 2 cos(t) cos((m-1) t) - cos((m-2) t)
            prev, cur = cur, 2.0 * c1 * cur - prev
        w = w + coef[m] * cur
    return w


def window_values(coefficients: tuple[float, ...], xi: ArrayLike) -> NDArray[np.float64]:
    """W(xi) of eq (W1) [-]: the cosine series normalised to W(0) = 1, 0 for |xi| > 1/2.

    Parameters
    ----------
    coefficients : tuple of float
        c_m of :func:`cosine_coefficients` (unnormalised).
    xi : array_like
        Normalised position [-].
    """
    xi = np.asarray(xi, dtype=float)
    inside = np.abs(xi) <= 0.5
    xi = np.where(inside, xi, 0.0)  # (an infinite offset, B_a of 5e-324 Hz, is outside)
    c = np.asarray(coefficients, dtype=float)
    w = cosine_series(NUMPY, xi, list(c / c.sum())) + np.zeros(xi.shape)
    return np.where(inside, w, 0.0)


def sampled_window(kind: str, n: int, nbar: int = 5, sidelobe_db: float = 35.0, *,
                   open_ends: bool = False) -> NDArray[np.float64]:
    """A window of ``n`` samples: eq (W1) at xi_n = (n - (N - 1)/2) / D [-].

    Parameters
    ----------
    kind : {'none', 'hann', 'hamming', 'taylor'}
        Window (:func:`cosine_coefficients`).
    n : int
        Number of samples N >= 1.
    nbar, sidelobe_db : int, float
        Taylor parameters.
    open_ends : bool
        False: D = N - 1, the end samples on the edges (symmetric window, Harris 1978);
        True: D = N + 1, every sample inside (no zero end sample of a Hann window).

    Returns
    -------
    ndarray (n,)
        w[n] in [0, 1], 1 at the centre [-].
    """
    coefficients = cosine_coefficients(kind, nbar, sidelobe_db)
    if n <= 1:
        return np.ones(max(n, 0))
    span = (n + 1) if open_ends else (n - 1)
    return window_values(coefficients, (np.arange(n) - 0.5 * (n - 1)) / span)
