"""The checks a scene meets after its schema (``seaecho.config``) has validated it.

- :mod:`~seaecho.checks.preflight`: what ``seaecho check`` and ``seaecho run`` refuse
  before anything runs (geometry, hulls, the image, the memory);
- :mod:`~seaecho.checks.resources`: the memory and run-time estimate (sizes read from
  the modules that allocate them);
- :mod:`~seaecho.checks.guards`: the finite-output guard on pulses, run datasets and
  images (NaN or Inf stops the run, nothing is written).

docs/checks.md describes the four layers of checks in order (the schema is the first).
"""
