"""Test-suite configuration.

Hypothesis: under CI (the ``CI`` environment variable set, as ``.ci/run`` is run) the
examples are derandomised, so a CI run is reproducible; developers' runs keep exploring
new examples (and keep failures in the local example database).

The on-disk cache of hull signatures (``seaecho.targets.cache``) is off for the suite
(``SEAECHO_CACHE=off``, inherited by the subprocesses and Dask workers it starts): a test
that computes a result twice must compute it twice. The cache's own tests give it a
folder of their own.
"""

import os

from hypothesis import HealthCheck, settings

os.environ["SEAECHO_CACHE"] = "off"

settings.register_profile(
    "ci", derandomize=True, database=None, deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
