"""Runs on a Dask cluster give the bytes of the serial run (netCDF file, Zarr arrays)."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from dask_helpers import tiny_scene

from seaecho import distributed
from seaecho.io.run import block_size, open_run
from seaecho.simulation import Simulation


def test_two_workers_write_the_serial_bytes(tmp_path, client, monkeypatch):
    sc = tiny_scene(n_pulses=8)
    # another block size than the cluster's: the netCDF file does not depend on it
    serial = Simulation(sc).run(tmp_path / "serial.nc", progress=False, chunk=3)
    # count the Simulations the workers build: once per worker thread, not per task
    builds = []

    class Counting(Simulation):
        def __init__(self, *a, **k):
            builds.append(1)
            super().__init__(*a, **k)

    monkeypatch.setattr(distributed, "Simulation", Counting)
    monkeypatch.setattr(distributed, "_CACHE", type(distributed._CACHE)())
    sim = Simulation(sc)  # the client's (static dataset), passed in: not counted
    nc = distributed.run(sc, tmp_path / "dask.nc", client=client, block=2, progress=False,
                         simulation=sim)
    assert nc.read_bytes() == serial.read_bytes()  # the whole file, byte for byte
    assert 1 <= len(builds) <= 2  # 4 tasks of 2 pulses, 2 worker threads
    zr = distributed.run(sc, tmp_path / "dask.zarr", client=client, block=2, progress=False,
                         simulation=sim)
    assert len(builds) <= 2  # the same scene again: the workers' cached simulations
    with open_run(serial) as a, open_run(zr) as b:
        a, b = a.load(), b.load()
        for name in ("raw", "compressed"):
            assert b[name].dtype == np.complex128
            assert a[name].values.tobytes() == b[name].values.tobytes()
            assert b[name].encoding["chunks"] == (2, 4, a.sizes["fast_time"])
        # same variables, coordinates, attributes and values as the netCDF file
        xr.testing.assert_identical(a, b)
        assert set(a.coords) == set(b.coords) and a.attrs == b.attrs
    # what the file holds is the per-pulse function (a parity check, not a tautology:
    # the run went through blocks, workers and two writers)
    np.testing.assert_array_equal(b["raw"].values[5], Simulation(sc).pulse(5))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dask.nc", "dask.zarr", "serial.nc"]


def test_evolving_sea_on_workers_writes_the_serial_bytes(tmp_path, client):
    # The evolving sea (docs/dynamics.md): phase centres carried from the block's
    # surface, speckle anchors from (seed, family, anchor index): a worker that starts at
    # pulse 2, inside a geometry update, computes the serial run's pulses
    sc = tiny_scene(n_pulses=7, sea_motion="evolving")
    serial = Simulation(sc).run(tmp_path / "serial.nc", progress=False)
    nc = distributed.run(sc, tmp_path / "dask.nc", client=client, block=2, progress=False)
    assert nc.read_bytes() == serial.read_bytes()
    with xr.open_dataset(nc, engine="h5netcdf") as ds:
        assert ds.attrs["sea_motion"] == "evolving"


def test_block_size_follows_the_held_sea():
    # sea held for 5 pulses: blocks of 15 (3 held seas, none cut) rather than 16
    edges = np.append(np.arange(0, 400, 5), 400)
    assert block_size(edges, target=16) == 15
    # held for 100 pulses: a block size whose boundaries hit the edges most often
    edges = np.append(np.arange(0, 400, 100), 400)
    assert block_size(edges, target=16) == 25  # 12 held seas cut (20 would cut 16)
    # every pulse its own sea: the target; an explicit size wins; capped at n_pulses
    assert block_size(np.arange(401), target=16) == 16
    assert block_size(np.arange(401), size=7) == 7
    assert block_size(np.array([0, 5]), target=16) == 5
    with pytest.raises(ValueError, match="block size 0"):
        block_size(np.arange(401), size=0)


def test_block_edges_of_the_simulation():
    sim = Simulation(tiny_scene(n_pulses=8))
    np.testing.assert_array_equal(sim.block_edges(), [0, 3, 6, 8])
