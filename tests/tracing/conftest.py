"""Shared helpers of the tracing tests: synthetic surfaces made with numpy FFT filtering."""

import numpy as np
import pytest


def _gaussian_surface(n: int, dx: float, corr_len: float, sigma_h: float,
                      rng: np.random.Generator) -> np.ndarray:
    """Gaussian random surface with Gaussian correlation exp(-r^2 / corr_len^2).

    White noise filtered by the square root of the Gaussian spectrum
    exp(-k^2 corr_len^2 / 4), i.e. an amplitude filter exp(-k^2 corr_len^2 / 8); then
    scaled to the sample rms height sigma_h. Its rms slope along any direction is
    sqrt(2) sigma_h / corr_len.
    """
    k = 2 * np.pi * np.fft.fftfreq(n, dx)
    kx, ky = np.meshgrid(k, k)
    w = rng.standard_normal((n, n))
    z = np.real(np.fft.ifft2(np.fft.fft2(w) * np.exp(-(kx**2 + ky**2) * corr_len**2 / 8)))
    return z * sigma_h / z.std()


@pytest.fixture
def gaussian_surface():
    return _gaussian_surface
