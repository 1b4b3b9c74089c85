"""seaecho: physics-based simulator of bistatic, polarimetric marine radar echoes.

From Python (:mod:`seaecho.api`, docs/python-api.md)::

    import seaecho
    scene = seaecho.load_scene("scenes/paper_sim1_bistatic_64m.toml")
    ds = seaecho.simulate(seaecho.with_overrides(scene, {"sea.wind_speed_m_s": 8.0}))

``load_scene``, ``parse_scene``, ``with_overrides``, ``simulate``, ``surface``, ``trace``,
``compare``, ``sigma``, ``wave_spectrum``, ``permittivity``, ``image``,
``image_measures``, ``figures``, ``detect``, ``score``, ``roc``, ``stonesoup_readers``,
``save`` and ``open_dataset`` return scenes, xarray objects and files; they are imported
on first use, so ``import seaecho`` stays
fast. The package is split by pipeline stage (see ``docs/design.md``): ``config`` (scene
files), ``ocean`` (spectra, surfaces, sea water), ``wake`` (ship wakes), ``scattering``
(polarimetric sea scattering), ``tracing`` (Sionna RT / Mitsuba facets), ``geometry``
(analytic facets), ``radar`` (antennas, waveform, platforms, echoes), ``processing``
(range compression, Doppler), ``detection`` (CFAR detectors, scores), ``imaging`` (SAR
focusing), ``io`` (datasets), ``plotting`` (figures), ``checks`` (what a scene must meet
before it runs).
"""

from importlib.metadata import PackageNotFoundError, version
from typing import TYPE_CHECKING, Any

try:
    __version__ = version("seaecho")
except PackageNotFoundError:  # pragma: no cover - running from a source tree
    __version__ = "0+unknown"

__all__ = [
    "Scene",
    "__version__",
    "compare",
    "detect",
    "figures",
    "image",
    "image_measures",
    "load_scene",
    "open_dataset",
    "parse_scene",
    "permittivity",
    "roc",
    "ppi",
    "save",
    "score",
    "sigma",
    "simulate",
    "stonesoup_readers",
    "surface",
    "trace",
    "wave_spectrum",
    "with_overrides",
]
#: The Python API (:mod:`seaecho.api`), re-exported here on first use (PEP 562).
_API = frozenset(__all__) - {"__version__"}

if TYPE_CHECKING:  # pragma: no cover
    from .api import (
        Scene,
        compare,
        detect,
        figures,
        image,
        image_measures,
        load_scene,
        open_dataset,
        parse_scene,
        permittivity,
        ppi,
        roc,
        save,
        score,
        sigma,
        simulate,
        stonesoup_readers,
        surface,
        trace,
        wave_spectrum,
        with_overrides,
    )


def __getattr__(name: str) -> Any:
    if name in _API:
        from . import api

        return getattr(api, name)
    raise AttributeError(f"module 'seaecho' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API))
