"""Registries of the wave-spectrum models, by name (a scene's ``[sea] spectrum`` and
``spreading``): the contract of an omnidirectional spectrum and of a spreading function,
and the decorators that register them. The models live in :mod:`seaecho.ocean.spectra`
and in modules of their own (:mod:`seaecho.ocean.romeiser`), which register themselves.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import numpy as np
from numpy.typing import NDArray


class OmniSpectrum(Protocol):
    """Contract of an omnidirectional spectrum: S_1d(k) [m^3] for k [rad/m]."""

    def __call__(
        self, k: NDArray[np.float64], u19_5: float, fetch: float | None
    ) -> NDArray[np.float64]: ...


class Spreading(Protocol):
    """Contract of a spreading function: D(k, psi) [1/rad], unit integral over psi."""

    def __call__(
        self,
        k: NDArray[np.float64],
        psi: NDArray[np.float64],
        u19_5: float,
        fetch: float | None,
        s: float,
    ) -> NDArray[np.float64]: ...


#: Registry of omnidirectional spectra, by name.
OMNI_SPECTRA: dict[str, OmniSpectrum] = {}
#: Registry of spreading functions, by name.
SPREADINGS: dict[str, Spreading] = {}


def register_spectrum(name: str) -> Callable[[OmniSpectrum], OmniSpectrum]:
    """Decorator: register an omnidirectional spectrum under ``name``."""

    def wrap(func: OmniSpectrum) -> OmniSpectrum:
        OMNI_SPECTRA[name] = func
        return func

    return wrap


def register_spreading(name: str) -> Callable[[Spreading], Spreading]:
    """Decorator: register a spreading function under ``name``."""

    def wrap(func: Spreading) -> Spreading:
        SPREADINGS[name] = func
        return func

    return wrap


#: Below this wavenumber [rad/m] (wavelength 6,000 km) every spectrum here is 0 in double
#: precision (exp(-b0 g^2 / (K^2 U^4)) underflows); treating it as 0 avoids 0 x inf.
K_FLOOR = 1e-6


__all__ = ["K_FLOOR", "OMNI_SPECTRA", "SPREADINGS", "OmniSpectrum", "Spreading",
           "register_spectrum", "register_spreading"]
