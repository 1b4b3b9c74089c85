"""The fuzzing suite (``tests/fuzz``): every test here carries the ``fuzz`` marker.

Default budget (part of the plain ``pytest`` run): about 180 generated scenes, the same
at every run (``tests/conftest.py``: derandomised, no example database). ``pytest -m
fuzz`` runs only this suite; ``SEAECHO_FUZZ_EXAMPLES=N`` gives every property N examples
and ``SEAECHO_FUZZ_RANDOM=1`` draws new ones at every run (a hunt, ``docs/checks.md``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent


def pytest_collection_modifyitems(config, items):
    for item in items:
        if HERE in Path(str(item.fspath)).resolve().parents:
            item.add_marker(pytest.mark.fuzz)
