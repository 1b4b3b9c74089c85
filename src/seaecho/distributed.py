"""Runs and sweeps on a Dask cluster (``dask.distributed``), with the bytes of a serial run.

Every pulse is a pure function of (scene, pulse index) (:meth:`Simulation.pulse`), so the
pulses of a run can be computed anywhere in any order. The work is cut in blocks of
consecutive pulses (:func:`seaecho.io.run.block_size` of
:meth:`Simulation.block_edges`: blocks that cut the fewest held seas and occlusion
refreshes), one Dask task per block. Each worker builds a scene's
:class:`~seaecho.simulation.Simulation` once (BVH, speckle, surface caches) and keeps it
for the tasks that follow (:func:`worker_simulation`: one per scene hash and worker
thread, the last two kept).

Output
------
* netCDF: the workers return their blocks; the client writes them in pulse order
  (at most ``2 x threads`` blocks in flight), atomically: the file's bytes are those of
  ``Simulation.run``.
* Zarr (``*.zarr``): the workers write their own chunks and completion records
  (:mod:`seaecho.io.zarr_run`); the output folder must be visible to every worker (a
  shared file system). Resumable.

Sweeps
------
:func:`sweep` runs the Cartesian product of scene overrides
(:mod:`seaecho.config.overrides`), one task per case: each case is a serial run written
to its own file, or reduced
(:func:`seaecho.processing.reductions.reduce_run`) to a few numbers. A failed case is
reported with its error and does not stop the others.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import os
import threading
from collections import OrderedDict, deque
from collections.abc import Iterator
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from .multistatic import MultistaticSimulation
from .processing.reductions import reduce_run
from .simulation import Simulation

#: Simulations kept per worker thread (a sweep meets many scenes; each holds its sea).
CACHE_PER_THREAD = 2
_CACHE: OrderedDict[tuple[str, int], Simulation] = OrderedDict()
_CACHE_LOCK = threading.Lock()


@dataclass(frozen=True)
class Job:
    """A scene to simulate, as shipped to the workers.

    Attributes
    ----------
    scene : seaecho.config.Scene
    base_dir : str
        Folder of the scene file (``[[objects]]`` paths are relative to it).
    key : str
        SHA-256 of the scene's JSON and ``base_dir``: the workers' cache key.
    """

    scene: Any
    base_dir: str
    key: str

    @classmethod
    def of(cls, scene, base_dir: str | os.PathLike = ".") -> Job:
        base = str(Path(base_dir).resolve())
        h = hashlib.sha256((scene.model_dump_json() + "\0" + base).encode()).hexdigest()
        return cls(scene, base, h)


def _simulation(scene, base_dir: str | os.PathLike = "."):
    """The scene's Simulation, or its MultistaticSimulation with ``[[receivers]]``."""
    if scene.receivers:
        return MultistaticSimulation(scene, base_dir)
    return Simulation(scene, base_dir=base_dir)


def worker_simulation(job: Job) -> Simulation:
    """The simulation of ``job``'s scene on this worker thread, built on first use and
    reused by later tasks (a Simulation's caches are not shared between threads)."""
    key = (job.key, threading.get_ident())
    with _CACHE_LOCK:
        sim = _CACHE.get(key)
        if sim is not None:
            _CACHE.move_to_end(key)
            return sim
    sim = _simulation(job.scene, base_dir=job.base_dir)
    with _CACHE_LOCK:
        _CACHE[key] = sim
        mine = [k for k in _CACHE if k[1] == key[1]]
        for k in mine[:-CACHE_PER_THREAD]:
            del _CACHE[k]
    return sim


def compute_block(job: Job, start: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
    """Task: raw and compressed samples of pulses ``start`` to ``stop - 1``."""
    return worker_simulation(job).pulses(start, stop)


def store_block(job: Job, part: str, index: int, start: int, stop: int) -> dict:
    """Task: compute block ``index`` and write it into the Zarr run ``part``."""
    from .io.zarr_run import write_block

    return write_block(part, index, start, stop, *compute_block(job, start, stop))


class DaskBlocks:
    """The Dask runner of :func:`seaecho.io.run.write_run`.

    Parameters
    ----------
    client : distributed.Client
    job : Job
    window : int, optional
        Blocks in flight for the ordered (netCDF) writer; default twice the cluster's
        threads.
    block : int, optional
        Pulses per block (``--block-pulses``), for the workers' memory check
        (:func:`check_workers`).
    """

    def __init__(self, client, job: Job, window: int | None = None,
                 block: int | None = None):
        check_workers(client, job, block)
        self.client = client
        self.job = job
        self.window = window or max(2, 2 * sum(client.nthreads().values()))

    def ordered(self, blocks: list[tuple[int, int]]) -> Iterator[tuple[np.ndarray,
                                                                      np.ndarray]]:
        """The blocks' (raw, compressed) in block order, at most ``window`` in flight."""
        pending: deque = deque()
        todo = iter(blocks)
        try:
            for a, b in itertools.islice(todo, self.window):
                pending.append(self._submit(compute_block, a, b))
            while pending:
                result = pending.popleft().result()
                nxt = next(todo, None)
                if nxt is not None:
                    pending.append(self._submit(compute_block, *nxt))
                yield result
        finally:
            for f in pending:
                f.cancel()

    def stored(self, part: Path, todo: list[int], blocks: list[tuple[int, int]]
               ) -> Iterator[dict]:
        """Blocks computed and written by the workers; their records as they complete."""
        from distributed import as_completed

        futures = [self._submit(store_block, str(part), i, *blocks[i]) for i in todo]
        try:
            for f in as_completed(futures):
                yield f.result()
        finally:
            for f in futures:
                f.cancel()

    def _submit(self, fn, *args):
        # pure=False: every block is its own task (no deduplication by argument hash)
        return self.client.submit(partial(fn, self.job), *args, pure=False)


def check_workers(client, job: Job, block: int | None = None) -> None:
    """Refuse (:class:`~seaecho.config.SceneError`) a run whose per-worker memory
    (``seaecho.checks.resources.worker_bytes``: per thread a simulation and a block of pulses)
    exceeds a worker's memory limit, from the scheduler's worker information; the
    client's own memory is checked by ``seaecho.checks.preflight.check_run``."""
    from .checks.resources import check_workers_memory

    try:
        info = client.scheduler_info(n_workers=-1)
    except TypeError:  # older distributed: every worker without the argument
        info = client.scheduler_info()
    check_workers_memory(job.scene, dict(info.get("workers", {})), "the Dask cluster",
                         block=block, base_dir=job.base_dir)


@contextlib.contextmanager
def cluster(workers: int | None = None, scheduler: str | None = None,
            processes: bool = True, threads_per_worker: int = 1) -> Iterator:
    """A ``distributed.Client``: of ``scheduler`` (an address, e.g.
    ``tcp://host:8786``), else of a LocalCluster of ``workers`` workers, closed at exit."""
    import dask

    from distributed import Client, LocalCluster

    if scheduler is not None:
        with Client(scheduler) as client:
            yield client
        return
    if workers is None or workers < 1:
        raise ValueError(f"workers = {workers}: must be >= 1")
    with (dask.config.set({"distributed.nanny.pre-spawn-environ": worker_environment()}),
          # no dashboard; the scheduler's HTTP server on a free port (its default 8787
          # may be taken by another cluster on the machine: a warning, then a failure)
          LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker,
                       processes=processes, dashboard_address=":0",
                       scheduler_kwargs={"dashboard": False}) as lc,
          Client(lc) as client):
        yield client


def worker_environment() -> dict:
    """Dask's environment for new worker processes, less ``MALLOC_TRIM_THRESHOLD_``.

    Setting it at all turns off glibc's dynamic mmap threshold: every large array of a
    pulse is then mapped and unmapped anew, with a page fault per page (measured: 1.9
    million faults and +70 % CPU time per 100 pulses of the Simulation 2 benchmark).
    """
    import dask

    env = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    env.pop("MALLOC_TRIM_THRESHOLD_", None)
    return env


def run(scene, path: str | os.PathLike, *, client, base_dir: str | os.PathLike = ".",
        block: int | None = None, resume: bool = False, progress: bool = True,
        simulation: Simulation | None = None) -> Path:
    """Simulate ``scene`` on a Dask cluster and write its dataset to ``path``.

    Same output, bit for bit, as ``Simulation(scene, base_dir).run(path, chunk=block)``
    whatever the cluster.

    Parameters
    ----------
    scene : seaecho.config.Scene
    path : path
        netCDF file, or Zarr store (``*.zarr``, resumable).
    client : distributed.Client
        :func:`cluster`.
    base_dir : path
        Folder of the scene file.
    block : int, optional
        Pulses per block (default :func:`seaecho.io.run.block_size`).
    resume : bool
        Zarr: continue an interrupted run.
    progress : bool
        tqdm progress bar over the pulses.
    simulation : Simulation, optional
        The scene's simulation if already built here (its static dataset is written by
        this process).
    """
    sim = _simulation(scene, base_dir=base_dir) if simulation is None else simulation
    return sim.run(path, progress=progress, chunk=block, resume=resume,
                   runner=DaskBlocks(client, Job.of(scene, base_dir), block=block))


# ----------------------------------------------------------------------------- sweeps
@dataclass(frozen=True)
class Case:
    """One case of a sweep: its index, its overrides and its validated scene."""

    index: int
    overrides: dict
    scene: Any


def sweep_cases(scene, grid: dict[str, list], source: str = "sweep") -> list[Case]:
    """The Cartesian product of ``grid`` (dotted name -> values; the last name varies
    fastest), each case validated like a scene file before any work starts.

    Raises
    ------
    seaecho.config.SceneError
        The first bad case: the message names the field, the value and what is allowed.
    """
    from .config import SceneError
    from .config.overrides import with_overrides

    names = list(grid)
    cases = []
    for i, values in enumerate(itertools.product(*(grid[n] for n in names))):
        ov = dict(zip(names, values, strict=True))
        sc = with_overrides(scene, ov, source=source)
        if sc.radar is None or sc.transmitter is None:
            raise SceneError(f"{source}: a run needs [radar] and [transmitter] sections")
        cases.append(Case(i, ov, sc))
    return cases


def run_case(case: Case, base_dir: str, out_dir: str | None, reduce: bool,
             block: int | None = None) -> dict:
    """Task: one case of a sweep, serially on the worker; never raises (a failed case
    is a row with its error)."""
    row: dict[str, Any] = {"case": case.index, "status": "ok", "error": "", "output": ""}
    try:
        sim = _simulation(case.scene, base_dir=base_dir)
        if reduce:
            from .io.pulses import blocks_of
            from .io.run import block_size

            blocks = blocks_of(sim.radar.n_pulses, block_size(sim.block_edges(), block))
            comp = np.concatenate([sim.pulses(a, b)[1] for a, b in blocks])
            ds = sim.static_dataset()
            ds["compressed"] = (("pulse", "channel", "fast_time"), comp)
            row.update(reduce_run(ds))
        else:
            out = Path(out_dir) / f"case_{case.index:05d}.nc"
            sim.run(out, progress=False, chunk=block)
            row["output"] = out.name
    except Exception as exc:  # a failed case is reported, the sweep goes on
        row.update(status="failed", error=f"{type(exc).__name__}: {exc}")
    return row


def sweep(cases: list[Case], out_dir: str | os.PathLike, *, base_dir: str | os.PathLike = ".",
          reduce: bool = False, client=None, block: int | None = None,
          progress: bool = True, refused: dict[int, str] | None = None) -> list[dict]:
    """Run every case (one task each on ``client``, else here one after the other);
    return the rows of the summary in case order (:func:`write_summary`). The cases in
    ``refused`` (index -> message, e.g. from ``seaecho.checks.preflight.check_run``) are not
    run: their rows are failed with that message."""
    from tqdm import tqdm

    base = str(Path(base_dir).resolve())
    out = str(out_dir)
    rows: dict[int, dict] = {i: {"case": i, "status": "failed", "error": msg, "output": ""}
                             for i, msg in (refused or {}).items()}
    cases_run = [c for c in cases if c.index not in rows]
    with tqdm(total=len(cases_run), unit="case", disable=not progress,
              desc="seaecho sweep") as bar:
        if client is None:
            for c in cases_run:
                rows[c.index] = run_case(c, base, out, reduce, block)
                bar.update(1)
        else:
            from distributed import as_completed

            futures = {client.submit(run_case, c, base, out, reduce, block, pure=False):
                       c.index for c in cases_run}
            try:
                for f in as_completed(futures):
                    try:
                        rows[futures[f]] = f.result()
                    except Exception as exc:  # the worker died, the task was lost...
                        rows[futures[f]] = {"case": futures[f], "status": "failed",
                                            "error": f"{type(exc).__name__}: {exc}",
                                            "output": ""}
                    bar.update(1)
            finally:
                for f in futures:
                    f.cancel()
    table = []
    for c in cases:
        row = {"case": c.index, **{k: _cell(v) for k, v in c.overrides.items()}}
        row.update({k: v for k, v in rows[c.index].items() if k != "case"})
        table.append(row)
    return table


def _cell(v):
    return v if isinstance(v, bool | int | float | str) else str(v)


def write_summary(rows: list[dict], out_dir: str | os.PathLike) -> tuple[Path, Path]:
    """The sweep's table as ``summary.csv`` and ``summary.nc`` (dimension ``case``),
    each written atomically."""
    import csv

    import xarray as xr

    from .io.dataset import atomic_path, write_dataset_atomic

    out_dir = Path(out_dir)
    columns: list[str] = []
    for r in rows:
        columns += [k for k in r if k not in columns]
    csv_path = out_dir / "summary.csv"
    with atomic_path(csv_path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in columns})
    data = {}
    for k in columns:
        vals = [r.get(k) for r in rows]
        if all(isinstance(v, bool) for v in vals):
            arr = np.array(vals, dtype=np.int8)
        elif all(isinstance(v, int | float) and not isinstance(v, bool) for v in vals):
            arr = np.array(vals)
        elif all(isinstance(v, int | float) or v is None for v in vals):
            arr = np.array([np.nan if v is None else v for v in vals], dtype=float)
        else:
            arr = np.array(["" if v is None else str(v) for v in vals], dtype=object)
        data[k] = ("case", arr)
    ds = xr.Dataset({k: v for k, v in data.items() if k != "case"},
                    coords={"case": data["case"][1]})
    nc_path = write_dataset_atomic(ds, out_dir / "summary.nc")
    return csv_path, nc_path


__all__ = ["Case", "DaskBlocks", "Job", "check_workers", "cluster",
           "compute_block", "run", "run_case", "store_block", "sweep",
           "sweep_cases", "worker_environment", "worker_simulation", "write_summary"]
