"""Continuous weighting windows on [-1/2, 1/2] as cosine series (azimuth weighting).

The azimuth window of the backprojection (``imaging.backprojection`` eq B4) is evaluated
at the normalised Doppler offset xi of each pulse and pixel, not on a fixed set of
samples, so it is written as a cosine series

.. math::

    W(\\xi) = \\frac{\\sum_{m=0}^{M} c_m \\cos(2\\pi m \\xi)}{\\sum_{m=0}^{M} c_m},
    \\quad |\\xi| \\le 1/2,\\qquad W(\\xi) = 0 \\text{ otherwise}                       (W1)

normalised to W(0) = 1:

- rectangular: c = (1);
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

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["AzimuthWindow", "cosine_coefficients"]


def cosine_coefficients(kind: str, nbar: int = 5, sidelobe_db: float = 35.0
                        ) -> tuple[float, ...]:
    """Cosine-series coefficients c_m of eq (W1) for a window name.

    Parameters
    ----------
    kind : {'none', 'hamming', 'taylor'}
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
    if kind == "hamming":
        return (0.54, 0.46)
    if kind != "taylor":
        raise ValueError(f"window = {kind!r}: unknown; allowed 'none', 'hamming', 'taylor'")
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


@dataclass(frozen=True)
class AzimuthWindow:
    """The processed Doppler band and its window, eq (B4) of ``imaging.backprojection``.

    Attributes
    ----------
    bandwidth : float
        Processed Doppler bandwidth B_a [Hz].
    coefficients : tuple of float
        Cosine-series coefficients of eq (W1) (unnormalised).
    name : str
        Window name, for the dataset attributes.
    """

    bandwidth: float
    coefficients: tuple[float, ...] = (1.0,)
    name: str = "none"

    def __post_init__(self) -> None:
        if not (self.bandwidth > 0 and np.isfinite(self.bandwidth)):
            raise ValueError(f"Doppler bandwidth = {self.bandwidth} Hz: must be finite and "
                             "> 0")

    @classmethod
    def named(cls, kind: str, bandwidth: float, nbar: int = 5, sidelobe_db: float = 35.0
              ) -> AzimuthWindow:
        """Window ``kind`` ('none', 'hamming', 'taylor') over a band of B_a [Hz]."""
        return cls(float(bandwidth), cosine_coefficients(kind, nbar, sidelobe_db), kind)

    @property
    def normalised(self) -> NDArray[np.float64]:
        """c_m / sum(c): the coefficients with W(0) = 1."""
        c = np.asarray(self.coefficients, dtype=float)
        return c / c.sum()

    def __call__(self, xi: ArrayLike) -> NDArray[np.float64]:
        """W(xi) of eq (W1), zero for |xi| > 1/2 [-]."""
        xi = np.asarray(xi, dtype=float)
        inside = np.abs(xi) <= 0.5
        xi = np.where(inside, xi, 0.0)  # (an infinite offset, B_a of 5e-324 Hz, is outside)
        c = self.normalised
        w = np.full(xi.shape, c[0])
        for m in range(1, c.size):
            w += c[m] * np.cos(2.0 * np.pi * m * xi)
        return np.where(inside, w, 0.0)
