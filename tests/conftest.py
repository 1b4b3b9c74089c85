"""Test-suite configuration.

Hypothesis: every run of the suite, with or without the ``CI`` environment variable,
draws the same examples (derandomised: each property's examples follow from its own
code; no example database), so the same commit always gives the same result. A random
hunt is on request: ``SEAECHO_FUZZ_RANDOM=1`` draws new examples at every run and keeps
failures in the local example database (``.hypothesis/``), ``SEAECHO_FUZZ_EXAMPLES=N``
sets the number of examples of the fuzzing properties (``tests/fuzz``), e.g.
``SEAECHO_FUZZ_RANDOM=1 SEAECHO_FUZZ_EXAMPLES=2000 pytest -m fuzz`` (``docs/checks.md``).

Derandomised examples follow from the property alone, not from the tests run before it:
Hypothesis (>= 6.131) also draws, now and then, a number or string found in the source of
the project's modules already imported (``sys.modules``), a pool that grows with every
module an earlier test imported, so that a property drew other examples alone than after
other files. Outside a random hunt that pool is empty (:func:`_no_local_constants`); a
hunt keeps it (more variety, and the blob it prints replays a failure in any order).

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


def _no_local_constants() -> None:
    """Hypothesis' pool of the local modules' constants, emptied for good (not a random
    hunt): the pool depends on which modules earlier tests imported
    (``hypothesis.internal.conjecture.providers._get_local_constants``, a private name,
    hence the loud failure if a Hypothesis release renames it;
    ``tests/fuzz/test_fuzz_order.py`` checks the draws)."""
    from hypothesis.internal.conjecture import providers

    if not hasattr(providers, "_get_local_constants"):
        import importlib.util

        if importlib.util.find_spec("hypothesis.internal.constants_ast") is None:
            return  # a Hypothesis from before the pool: nothing depends on the order
    if not callable(getattr(providers, "_get_local_constants", None)):
        raise RuntimeError("hypothesis.internal.conjecture.providers._get_local_constants "
                           "is gone: find the new way to keep the fuzz draws independent "
                           "of the order of the tests (tests/conftest.py)")
    empty = providers.Constants()
    providers._get_local_constants = lambda: empty
    providers.CONSTANTS_CACHE.cache.clear()


if not RANDOM:
    _no_local_constants()
