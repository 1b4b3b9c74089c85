"""seaecho: physics-based simulator of bistatic, polarimetric marine radar echoes.

The package is split by pipeline stage (see ``docs/design.md``): ``config`` (scene files),
``ocean`` (spectra, surfaces, sea water), ``wake`` (ship wakes), ``scattering``
(polarimetric sea scattering), ``tracing`` (Sionna RT / Mitsuba facets), ``geometry``
(analytic facets), ``radar`` (antennas, waveform, platforms, echoes), ``processing``
(range compression, focusing, detection), ``io`` (datasets and figures).
"""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("seaecho")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0+unknown"

__all__ = ["__version__"]
