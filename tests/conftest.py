"""Test-suite configuration.

Hypothesis: every run of the suite, with or without the ``CI`` environment variable,
draws the same examples (derandomised: each property's examples follow from its own
code; no example database), so the same commit always gives the same result. A random
hunt is on request: ``SEAECHO_FUZZ_RANDOM=1`` draws new examples at every run and keeps
failures in the local example database (``.hypothesis/``), ``SEAECHO_FUZZ_EXAMPLES=N``
sets the number of examples of the fuzzing properties (``tests/fuzz``), e.g.
``SEAECHO_FUZZ_RANDOM=1 SEAECHO_FUZZ_EXAMPLES=2000 pytest -m fuzz`` (``docs/checks.md``).

The on-disk cache of hull signatures (``seaecho.targets.cache``) is off for the suite
(``SEAECHO_CACHE=off``, inherited by the subprocesses and Dask workers it starts): a test
that computes a result twice must compute it twice. The cache's own tests give it a
folder of their own.
"""

import os

from hypothesis import HealthCheck, settings

os.environ["SEAECHO_CACHE"] = "off"

#: ``SEAECHO_FUZZ_RANDOM=1``: new random examples at every run (a hunt, not the suite).
RANDOM = os.environ.get("SEAECHO_FUZZ_RANDOM", "") not in ("", "0")

settings.register_profile(
    "fixed", derandomize=True, database=None, deadline=None, print_blob=False,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("random", deadline=None, print_blob=True)
settings.load_profile("random" if RANDOM else "fixed")
