"""How facets are seen, as plain values: :class:`TracingModel`.

:func:`seaecho.build.build_tracing` fills it from a scene's ``[tracing]`` and
``[[objects]]`` sections; :meth:`seaecho.tracing.engine.FacetEngine.from_model` takes it.
"""

from __future__ import annotations

from dataclasses import dataclass

from .scene import ObjectGeometry


@dataclass(frozen=True)
class TracingModel:
    """Facet mode, shadowing and the objects that occlude the sea.

    Attributes
    ----------
    mode : {"raytraced", "analytic"}
        Facet mode.
    shadowing : {"smith", "none"}
        Analytic mode's statistical shadowing.
    refresh_interval_s : float
        Occlusion refresh interval [s] (ray-traced mode; 0: every call).
    variant : str
        Mitsuba variant.
    objects : tuple of ObjectGeometry
        Occluders (ray-traced mode).
    frequency : float
        Radar carrier frequency [Hz].
    eps_r : complex
        Sea-water permittivity at ``frequency`` [-].
    subfacet : (float, float, float) or None
        (mss_upwind, mss_crosswind, wind_direction [rad]) of the unresolved tilting
        slopes when the visibility is to include their Smith shadowing; None otherwise.
    periodic_apron : bool
        Ray-traced mode: trace the shadow rays against the sea tile's periodic copies in
        front of it too (:class:`~seaecho.tracing.tracer.FacetTracer`).
    """

    mode: str
    shadowing: str
    refresh_interval_s: float
    variant: str
    objects: tuple[ObjectGeometry, ...]
    frequency: float
    eps_r: complex
    subfacet: tuple[float, float, float] | None = None
    periodic_apron: bool = False


__all__ = ["TracingModel"]
