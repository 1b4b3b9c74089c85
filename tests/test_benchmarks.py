"""Every benchmark runs: ``python benchmarks/X.py --smoke`` (smallest size, one or two
pulses, one round; ``benchmarks/_smoke.py``) exits 0 against the current code, so a
benchmark cannot rot unnoticed (``bench_oceansar --seaecho-run`` once failed with
``KeyError: 'pulse'`` after the run's writer changed). Slow set: a few seconds to a
minute each."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"
FILES = sorted(p.name for p in BENCHMARKS.glob("*.py") if not p.name.startswith("_"))


def test_every_benchmark_has_a_smoke_mode():
    for name in FILES:
        assert "add_option(" in (BENCHMARKS / name).read_text(), name


@pytest.mark.slow
@pytest.mark.parametrize("name", FILES)
def test_benchmark_smoke_mode_runs(name, tmp_path):
    env = {**os.environ, "SEAECHO_CACHE_DIR": str(tmp_path / "cache")}
    r = subprocess.run([sys.executable, str(BENCHMARKS / name), "--smoke"], cwd=tmp_path,
                       capture_output=True, text=True, timeout=900, env=env)
    assert r.returncode == 0, f"{name} --smoke failed:\n{r.stdout[-2000:]}\n{r.stderr[-4000:]}"
