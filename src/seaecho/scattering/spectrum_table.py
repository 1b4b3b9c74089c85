"""Tabulated height spectrum for fast per-facet Bragg lookups.

Evaluating a full sea spectrum (e.g. Elfouhaily et al. 1997) at 262,144 facet Bragg
vectors costs more than the rest of the scattering model. :class:`BraggSpectrumTable`
tabulates ``log W(K, psi)`` once per sea state on a logarithmic wavenumber grid and a
periodic azimuth grid and interpolates bilinearly (in ``log K``, ``psi``, ``log W``):

.. math::
    \\log W(K,\\psi) \\approx \\text{bilinear}\\big(\\log W(K_i, \\psi_j)\\big),
    \\quad K_i = k_{min} (k_{max}/k_{min})^{i/(n_K - 1)},
    \\quad \\psi_j = -\\pi + 2\\pi j / n_\\psi \\qquad \\text{(T2)}

and 0 outside ``[k_min, k_max]`` (so ``k_min`` is also the two-scale split: the table is
the spectrum of the *unresolved* roughness). With the defaults (1024 x 360) the relative
error on a smooth spectrum is below 1e-3 (``tests/scattering/test_drjit_kernel.py``).
The same function (:meth:`BraggSpectrumTable.lookup`) is evaluated by numpy
(``__call__``) and inside the Dr.Jit facet kernel.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY

#: log W stored for W = 0 (exp gives exactly 0 in float64).
_LOG_ZERO = -745.0


class BraggSpectrumTable:
    """Tabulated height spectrum ``W(kx, ky)`` [m^4] on ``k_min <= K <= k_max``.

    Parameters
    ----------
    spectrum : callable
        ``W(kx, ky)`` [m^4], world-frame wavenumbers [rad/m] (e.g.
        ``DirectionalSpectrum.height_spectrum``).
    k_min, k_max : float
        Wavenumber range [rad/m]; ``W = 0`` outside.
    n_k, n_psi : int
        Table size in ``log K`` and azimuth.
    """

    def __init__(self, spectrum: Callable[[NDArray, NDArray], NDArray], k_min: float,
                 k_max: float, n_k: int = 1024, n_psi: int = 360) -> None:
        if not 0.0 < k_min < k_max or not np.isfinite(k_max):
            raise ValueError(f"k_min = {k_min}, k_max = {k_max} rad/m: need 0 < k_min < k_max")
        if n_k < 2 or n_psi < 4:
            raise ValueError(f"n_k = {n_k}, n_psi = {n_psi}: need n_k >= 2, n_psi >= 4")
        self.k_min = float(k_min)
        self.k_max = float(k_max)
        self.n_k = int(n_k)
        self.n_psi = int(n_psi)
        self.log_k0 = float(np.log(k_min))
        self.dlog_k = float(np.log(k_max / k_min) / (n_k - 1))
        k = np.exp(self.log_k0 + self.dlog_k * np.arange(n_k))
        psi = -np.pi + 2.0 * np.pi * np.arange(n_psi) / n_psi
        kk, pp = np.meshgrid(k, psi, indexing="ij")
        w = np.asarray(spectrum(kk * np.cos(pp), kk * np.sin(pp)), dtype=float)
        with np.errstate(divide="ignore"):
            self.values = np.maximum(np.log(np.maximum(w, 0.0)), _LOG_ZERO).ravel()
        self._device_values: dict[str, Any] = {}

    def __call__(self, kx: ArrayLike, ky: ArrayLike) -> NDArray:
        """Interpolated ``W`` (eq T2) [m^4] at numpy wavenumbers [rad/m]."""
        kx = np.asarray(kx, dtype=float)
        ky = np.asarray(ky, dtype=float)
        with np.errstate(divide="ignore"):
            return np.asarray(self.lookup(NUMPY, kx, ky))

    def lookup(self, xp, kx: Any, ky: Any) -> Any:
        """Eq T2 over an array namespace (:mod:`seaecho.backend`): ``W(kx, ky)`` [m^4].

        Bilinear in ``(log K, psi)`` of ``log W``, periodic in ``psi``; 0 outside
        ``[k_min, k_max]``. The numpy path (:meth:`__call__`) and the facet kernels both
        evaluate this function.
        """
        kmag = xp.sqrt(kx * kx + ky * ky)
        u = (xp.log(xp.maximum(kmag, xp.tiny)) - self.log_k0) * (1.0 / self.dlog_k)
        inside = (u >= 0.0) & (u <= self.n_k - 1)
        u = xp.clip(u, 0.0, self.n_k - 1.000001)
        i0 = xp.floor(u)
        fu = u - i0
        v = (xp.atan2(ky, kx) + math.pi) * (self.n_psi / (2.0 * math.pi))
        j0 = xp.floor(v)
        fv = v - j0
        b0 = xp.index(i0) * self.n_psi
        b1 = b0 + self.n_psi
        # periodic in psi: psi = +pi (v = n_psi) is node 0, as psi = -pi
        j0 = xp.index(xp.select(j0 >= self.n_psi, j0 - self.n_psi, xp.maximum(j0, 0.0)))
        j1 = j0 + 1
        j1 = xp.select(j1 >= self.n_psi, j1 - self.n_psi, j1)
        t = self._values(xp)
        lw = ((1.0 - fu) * ((1.0 - fv) * xp.gather(t, b0 + j0) + fv * xp.gather(t, b0 + j1))
              + fu * ((1.0 - fv) * xp.gather(t, b1 + j0) + fv * xp.gather(t, b1 + j1)))
        return xp.select(inside, xp.exp(lw), 0.0)

    def _values(self, xp) -> Any:
        """The table in ``xp``'s memory (copied to a Dr.Jit device once per namespace)."""
        if xp.is_numpy:
            return self.values
        key = (xp.name, xp.precision)
        if key not in self._device_values:
            self._device_values[key] = xp.table(self.values)
        return self._device_values[key]

    def lookup_drjit(self, kx, ky):
        """Eq T2 on Dr.Jit LLVM arrays (former entry point; see :meth:`lookup`)."""
        from ..backend import drjit_namespace

        return self.lookup(drjit_namespace(), kx, ky)


__all__ = ["BraggSpectrumTable"]
