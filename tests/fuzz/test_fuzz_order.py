"""The fuzzing suite's examples follow from each property alone, not from the tests run
before it in the same process.

Hypothesis now and then draws a constant found in the source of the local modules already
imported; every module an earlier test imports used to add to that pool, so that a
property drew other scenes alone than after, e.g., ``tests/radar/test_scan.py``.
``tests/conftest.py`` empties the pool outside a random hunt. Here the same property runs
twice, before and after a new module full of constants is imported (what an earlier test
file does), and must draw the same scenes. ``tools/fuzz_draws.py`` compares the examples
of the whole fuzzing suite run alone and after other test files.
"""

from __future__ import annotations

import importlib
import os
import sys

import pytest
from fuzz_schema import section
from hypothesis import HealthCheck, given, settings

from seaecho.config.radar import RadarConfig

#: A module an earlier test might import: numbers in the ranges of many scene fields.
PROBE = """
FLOATS = ({floats})
INTEGERS = ({ints})
NAMES = ("probe-a", "probe-b", "HH", "VV", "lfm", "pulse")
"""

#: A random hunt (``tests/conftest.py``) keeps the pool.
RANDOM = os.environ.get("SEAECHO_FUZZ_RANDOM", "") not in ("", "0")


def _draws() -> list[str]:
    drawn: list[str] = []

    @settings(max_examples=6, derandomize=True, database=None, deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(data=section(RadarConfig))
    def record(data):
        drawn.append(repr(data))

    record()
    return drawn


@pytest.mark.skipif(RANDOM, reason="a random hunt draws new examples at every run")
def test_draws_do_not_depend_on_the_modules_imported_before(tmp_path, monkeypatch):
    from hypothesis.internal.conjecture import providers

    before = _draws()
    floats = ", ".join(repr(x * 10.0**e) for e in range(-6, 7) for x in (1.25, 3.5, 7.75))
    ints = ", ".join(str(i) for i in (*range(2, 40), 64, 100, 1000, 4096))
    (tmp_path / "seaecho_order_probe.py").write_text(PROBE.format(floats=floats, ints=ints))
    monkeypatch.syspath_prepend(str(tmp_path))
    try:
        importlib.import_module("seaecho_order_probe")
        assert len(providers._get_local_constants()) == 0
        after = _draws()
    finally:
        sys.modules.pop("seaecho_order_probe", None)
    assert after == before
    assert len(set(before)) > 1
