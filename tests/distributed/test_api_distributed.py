"""``seaecho.simulate`` on a Dask cluster: the serial run's values, in memory and in a
Zarr store (parity tests of the Python API's route through ``seaecho.distributed``)."""

from __future__ import annotations

import pytest
import xarray as xr
from dask_helpers import tiny_scene

import seaecho
from seaecho.config import SceneError


# the tiny test tile (4 m) is shorter than the peak wavelength on purpose: cheap pulses
@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_simulate_on_a_cluster_is_the_serial_run(tmp_path, client):
    sc = tiny_scene(n_pulses=6)
    serial = seaecho.simulate(sc, progress=False)
    # the package's in-process cluster, reached by its address as an external one would be
    on_cluster = seaecho.simulate(sc, progress=False, scheduler=client.scheduler.address,
                                  block_pulses=2)
    xr.testing.assert_identical(serial, on_cluster)
    for name in ("raw", "compressed"):
        assert serial[name].values.tobytes() == on_cluster[name].values.tobytes()
    with seaecho.simulate(sc, path=tmp_path / "run.zarr", progress=False,
                          scheduler=client.scheduler.address, block_pulses=4) as z:
        assert z["raw"].chunks is not None  # opened lazily from the store
        assert z["raw"].values.tobytes() == serial["raw"].values.tobytes()
    # complete: resuming the same run leaves it as it is
    with seaecho.simulate(sc, path=tmp_path / "run.zarr", progress=False, resume=True,
                          block_pulses=4) as z:
        assert z["compressed"].values.tobytes() == serial["compressed"].values.tobytes()


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"workers": 0}, "workers = 0: must be an integer >= 1"),
    ({"block_pulses": 1.5}, "block_pulses = 1.5"),
    ({"workers": 2, "scheduler": "tcp://localhost:8786"}, "give one of them"),
    ({"resume": True}, "needs a Zarr path"),
    ({"resume": True, "path": "run.nc"}, "run.nc is not a Zarr store"),
])
def test_bad_cluster_options_are_named_before_any_work(kwargs, message):
    with pytest.raises(SceneError, match=message):
        seaecho.simulate(tiny_scene(n_pulses=2), progress=False, **kwargs)
