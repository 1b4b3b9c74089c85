"""The distributed tests' two-worker cluster."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="package")
def client():
    """Two Dask workers of one thread each, in this process (processes=False: no worker
    start-up of several seconds; the tasks still run on the workers' own threads, each
    with its own cached Simulation)."""
    from seaecho.distributed import cluster

    with cluster(2, processes=False) as c:
        yield c
