"""The azimuth window of the backprojection (``imaging.backprojection`` eq B4).

It is a window of :mod:`seaecho.processing.windows` (eq W1 there: a cosine series on
[-1/2, 1/2], normalised to W(0) = 1), evaluated at the normalised Doppler offset xi of
each pulse and pixel, not on a fixed set of samples.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..processing.windows import cosine_coefficients, window_values

__all__ = ["AzimuthWindow", "cosine_coefficients"]


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
        return window_values(self.coefficients, xi)
