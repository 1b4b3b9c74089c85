"""Echoes of hulls and other deterministic scatterers: the plain-numpy parts.

The ray tracing itself (shooting and bouncing rays on Mitsuba) lives in
:mod:`seaecho.tracing.sbr`, the only place that imports mitsuba; this package holds what
does not need it:

- :mod:`.po`: physical-optics ray-tube kernels (reflection of a ray's field on a facet,
  equivalent currents, radiated field, ray-tube shape function);
- :mod:`.multipath`: the sea's specular reflection (Fresnel times a rough-surface
  reduction factor) for the image method;
- :mod:`.centres`: scattering centres (delay-equivalent positions, clustering, coherent
  totals, refresh schedule);
- :mod:`.canonical`: canonical meshes (plate, dihedral, trihedral, sphere) for
  validation and calibration;
- :mod:`.swerling`: fluctuating point targets (Swerling cases 0 to 4);
- :mod:`.motion`: a hull's heave, pitch and roll following the sea under its waterplane.

The theory pages are ``docs/ship.md`` and ``docs/targets.md``.
"""
