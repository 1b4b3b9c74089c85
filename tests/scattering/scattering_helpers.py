"""Helpers shared by the scattering tests (imported by name: tests/ has no packages)."""

import numpy as np


def gaussian_spectrum(kx, ky, h2=1e-4, lx=0.05, ly=0.08):
    """Anisotropic Gaussian height spectrum [m^4], centro-symmetric, integral h2 [m^2].

    W(K) = h2 lx ly / (4 pi) exp(-(kx lx)^2/4 - (ky ly)^2/4) is the Fourier transform
    (1/(2 pi)^2 convention) of the correlation h2 exp(-x^2/lx^2 - y^2/ly^2), so its
    integral over the plane is h2 (checked in test_spm.py).
    """
    kx = np.asarray(kx, dtype=float)
    ky = np.asarray(ky, dtype=float)
    return h2 * lx * ly / (4 * np.pi) * np.exp(-(kx * lx) ** 2 / 4 - (ky * ly) ** 2 / 4)
