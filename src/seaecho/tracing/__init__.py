"""Ray-traced facets on Sionna RT / Mitsuba: the only package that imports them.

Importing this package imports neither mitsuba nor sionna; they load (with the Mitsuba
variant chosen explicitly, :mod:`seaecho.tracing.variant`) when a scene is first built.

Entry points:

- :class:`~seaecho.tracing.engine.FacetEngine` (``FacetEngine.from_model(model, surface,
  tx, rx)``, ``engine.facets(t)``; ``seaecho.build.build_engine`` for a scene): facets of
  a sea at any time, either mode, refresh interval;
- :class:`~seaecho.tracing.tracer.FacetTracer`: ray-traced facets of plain arrays;
- :func:`seaecho.geometry.facets.analytic_facets`: the analytic mode on plain arrays.
"""

from .engine import FacetEngine, reference_time

__all__ = ["FacetEngine", "reference_time"]
