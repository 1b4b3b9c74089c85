"""The memory estimate against the Dask workers' own limits (``--scheduler``): the client's
check (``seaecho.checks.preflight.check_run``) sees only this machine, so a cluster whose workers
cannot hold a simulation and a block of pulses per thread is refused, by name, before any
block is submitted."""

from __future__ import annotations

import pytest
from dask_helpers import tiny_scene

from seaecho import distributed
from seaecho.checks.resources import (
    SAFETY,
    check_workers_memory,
    estimate,
    format_bytes,
    worker_bytes,
)
from seaecho.config import SceneError

GB = 1e9


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_per_worker_part_of_the_estimate():
    sc = tiny_scene()
    est = estimate(sc, figures=True)
    process = est.terms["process"]
    own = sum(est.terms[k] for k in ("sea grid", "receive window", "pulses",
                                     "perturbation", "targets", "hull traces"))
    # the client's figures are not a worker's; each thread holds its own simulation
    assert worker_bytes(est, 1) == pytest.approx(SAFETY * (process + own))
    assert worker_bytes(est, 3) == pytest.approx(SAFETY * (process + 3 * own))
    assert worker_bytes(est, 3) < est.peak_bytes + 3 * SAFETY * own


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_fake_worker_info_too_small_is_refused_naming_worker_and_fields():
    sc = tiny_scene()
    need = worker_bytes(estimate(sc, figures=False), 2)
    small = {"tcp://10.0.0.1:40000": {"memory_limit": 4 * GB, "nthreads": 2},
             "tcp://10.0.0.2:40000": {"memory_limit": need / 0.8 * 0.99, "nthreads": 2}}
    with pytest.raises(SceneError) as err:
        check_workers_memory(sc, small, "s.toml")
    msg = str(err.value)
    assert msg.startswith("s.toml: the run does not fit in the Dask workers' memory")
    assert "tcp://10.0.0.2:40000 (of 2)" in msg and "10.0.0.1" not in msg
    assert f"estimated {format_bytes(need)} per worker" in msg
    assert "[sea].nx" in msg and "--block-pulses" in msg
    # just above the pause threshold, or no limit at all (0 / None): accepted
    ok = {"a": {"memory_limit": need / 0.8 * 1.01, "nthreads": 2},
          "b": {"memory_limit": 0, "nthreads": 8}, "c": {"memory_limit": None}}
    check_workers_memory(sc, ok, "s.toml")
    # more threads per worker: more simulations held
    with pytest.raises(SceneError, match="each of its 4 threads"):
        check_workers_memory(sc, {"a": {"memory_limit": need / 0.8 * 1.01, "nthreads": 4}},
                             "s.toml")


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_block_pulses_enter_the_per_worker_estimate():
    sc = tiny_scene(n_pulses=64)
    one = worker_bytes(estimate(sc, figures=False, block=1))
    big = worker_bytes(estimate(sc, figures=False, block=64))
    assert big > one  # a worker holds its block of pulses


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_a_cluster_of_tiny_workers_is_refused_before_any_task(tmp_path):
    # A real scheduler's worker information (in-process workers of 150 MB: below the
    # process alone), through seaecho.simulate(scheduler=...) as `run --scheduler` does
    import seaecho
    from distributed import Client, LocalCluster

    with (LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                       memory_limit="150MB", dashboard_address=":0",
                       scheduler_kwargs={"dashboard": False}) as lc,
          Client(lc) as client):
        out = tmp_path / "run.nc"
        with pytest.raises(SceneError, match=r"the Dask cluster: the run does not fit in "
                           r"the Dask workers' memory: worker .* has a memory limit of 143 MiB"):
            seaecho.simulate(tiny_scene(), path=out, progress=False,
                             scheduler=lc.scheduler_address)
        assert list(tmp_path.iterdir()) == []
        assert not client.who_has()  # nothing was submitted
        with pytest.raises(SceneError, match="does not fit in the Dask workers' memory"):
            distributed.DaskBlocks(client, distributed.Job.of(tiny_scene()))
