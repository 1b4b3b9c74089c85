"""A run's dataset as a Zarr store, written block by block, resumable.

Layout while it is written: ``OUT.zarr.part/`` holds

* ``data.zarr/``: the Zarr (format 3) store, the same variables, coordinates and
  attributes as the netCDF file of :mod:`seaecho.io.run`; ``raw`` and ``compressed``
  chunked by blocks of pulses, (block, channels, samples), so that each block of work
  writes its own chunks (from any process or machine that sees the folder);
* ``run.json``: what the run is (scene, seed, package version, shape, block size),
  written once the static variables are;
* ``blocks/NNNNNNNNN.json``: one completion record per block, written (atomically) after
  its chunks, with the SHA-256 of the block's raw and compressed bytes.

The store keeps the ``.part`` name until every block is recorded: then ``data.zarr`` is
renamed to ``OUT.zarr`` and the rest removed, so a store named ``OUT.zarr`` is always
complete and an incomplete one is never mistaken for it. An interrupted run is continued
by :func:`write_zarr_run` with ``resume=True``: it checks the records (the block's bytes
against its hashes) and computes only the blocks without one, giving the same bytes as an
uninterrupted run. A store of another scene, seed or package version, or a corrupt one, is
refused (:class:`StoreError`).

Complex variables: Zarr format 3 has ``complex128`` as a core data type (two little-endian
float64 per value, fill value ``[re, im]``), which xarray reads back as numpy complex128,
bit for bit. Fixed-width unicode has no stable Zarr 3 type: string coordinates (channel
names, ...) are stored as Zarr 3 ``string`` (variable-length UTF-8) and read back as numpy
strings with the same values.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np

from .pulses import COMPRESSED_ATTRS, RAW_ATTRS, blocks_of

#: Format tag of ``run.json``.
FORMAT = "seaecho-zarr-run/1"
DATA = "data.zarr"
MANIFEST = "run.json"
RECORDS = "blocks"


class StoreError(ValueError):
    """A Zarr run that cannot be continued: corrupt, or of another scene, seed or version."""


def is_zarr(path: str | os.PathLike) -> bool:
    """Whether ``path`` names a Zarr store (suffix ``.zarr``)."""
    return Path(path).suffix.lower() == ".zarr"


def part_path(path: str | os.PathLike) -> Path:
    """The folder of the incomplete run of ``path``: ``OUT.zarr.part``."""
    path = Path(path)
    return path.with_name(path.name + ".part")


def _write_json_atomic(path: Path, data: dict) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            json.dump(data, f, sort_keys=True)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def _digest(a: np.ndarray) -> str:
    return hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()


def _open_arrays(part: Path, mode: str = "r+"):
    import zarr

    data = part / DATA
    return (zarr.open_array(data / "raw", mode=mode, zarr_format=3),
            zarr.open_array(data / "compressed", mode=mode, zarr_format=3))


def write_block(part: str | os.PathLike, index: int, start: int, stop: int,
                raw: np.ndarray, compressed: np.ndarray) -> dict:
    """Write block ``index`` (pulses ``start`` to ``stop - 1``) into the run ``part``,
    then its completion record; return the record.

    Safe from several processes at once: a block owns its chunks and its record.
    """
    part = Path(part)
    raw_a, rc_a = _open_arrays(part)
    raw_a[start:stop] = raw
    rc_a[start:stop] = compressed
    record = {"block": int(index), "start": int(start), "stop": int(stop),
              "raw_sha256": _digest(raw), "compressed_sha256": _digest(compressed)}
    _write_json_atomic(part / RECORDS / f"{index:09d}.json", record)
    return record


def manifest(identity: dict, shape: tuple[int, int, int], block: int) -> dict:
    """What a run is: ``run.json``."""
    return {"format": FORMAT, "scene_json": identity["scene_json"],
            "seaecho_version": identity["seaecho_version"], "seed": int(identity["seed"]),
            "shape": [int(n) for n in shape], "block_pulses": int(block)}


def _flat(d, prefix=""):
    if isinstance(d, dict):
        out = {}
        for k, v in d.items():
            out.update(_flat(v, f"{prefix}{k}."))
        return out
    if isinstance(d, list) and any(isinstance(v, dict) for v in d):
        out = {}
        for i, v in enumerate(d):
            out.update(_flat(v, f"{prefix}{i}."))
        return out
    return {prefix[:-1]: d}


def check_identity(where: str, found: dict, wanted: dict) -> None:
    """Refuse a store whose version, seed or scene differ from the run's.

    Raises
    ------
    StoreError
        Naming what differs (the scene fields, by dotted name).
    """
    if found.get("seaecho_version") != wanted["seaecho_version"]:
        raise StoreError(f"{where} was written by seaecho {found.get('seaecho_version')}, "
                         f"this is seaecho {wanted['seaecho_version']}: it cannot be "
                         "continued; delete it or write to another output")
    if int(found.get("seed", -1)) != int(wanted["seed"]):
        raise StoreError(f"{where} is a run with seed {found.get('seed')}, this run has seed "
                         f"{wanted['seed']}: delete it or write to another output")
    if found.get("scene_json") != wanted["scene_json"]:
        try:
            a, b = _flat(json.loads(found["scene_json"])), _flat(json.loads(
                wanted["scene_json"]))
            diff = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
        except (KeyError, TypeError, ValueError):
            diff = []
        what = (f" (fields {', '.join(diff[:6])}{', ...' if len(diff) > 6 else ''} differ)"
                if diff else "")
        raise StoreError(f"{where} is a run of another scene{what}: delete it or write to "
                         "another output")


def _corrupt(part: Path, why: str) -> StoreError:
    return StoreError(f"{part} is not a readable seaecho run ({why}): delete it to start "
                      "over")


def _read_manifest(part: Path) -> dict:
    try:
        m = json.loads((part / MANIFEST).read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise _corrupt(part, f"no {MANIFEST}: interrupted before its first block") from None
    except (OSError, ValueError) as exc:
        raise _corrupt(part, f"{MANIFEST}: {exc}") from None
    if not isinstance(m, dict) or m.get("format") != FORMAT:
        raise _corrupt(part, f"{MANIFEST} is not a {FORMAT} manifest")
    return m


def completed_blocks(part: str | os.PathLike, blocks: list[tuple[int, int]]) -> set[int]:
    """Blocks of the run ``part`` that have a completion record whose hashes match the
    store's bytes.

    Raises
    ------
    StoreError
        A record that cannot be read, names another block, or whose hashes differ from
        the data (a corrupt store).
    """
    part = Path(part)
    try:
        raw_a, rc_a = _open_arrays(part, mode="r")
    except Exception as exc:  # zarr raises several kinds for a broken store
        raise _corrupt(part, f"{DATA}: {type(exc).__name__}: {exc}") from None
    done = set()
    for f in sorted((part / RECORDS).glob("*.json")):
        try:
            r = json.loads(f.read_text(encoding="utf-8"))
            i, a, b = int(r["block"]), int(r["start"]), int(r["stop"])
        except (OSError, ValueError, KeyError, TypeError) as exc:
            raise _corrupt(part, f"record {f.name}: {exc}") from None
        if not (0 <= i < len(blocks) and blocks[i] == (a, b)) or f.stem != f"{i:09d}":
            raise _corrupt(part, f"record {f.name} names block {i} = pulses [{a}, {b})")
        if (_digest(raw_a[a:b]) != r.get("raw_sha256")
                or _digest(rc_a[a:b]) != r.get("compressed_sha256")):
            raise _corrupt(part, f"block {i} (pulses {a} to {b - 1}) does not match its "
                           "record")
        done.add(i)
    return done


def create_store(part: Path, static, identity: dict, shape: tuple[int, ...],
                 block: int, weighting: str,
                 dims: tuple[str, ...] = ("pulse", "channel", "fast_time")) -> None:
    """Create the run ``part``: the static variables, the empty ``raw`` and
    ``compressed`` arrays (dimensions ``dims``, pulse first), then ``run.json``."""
    import zarr

    (part / RECORDS).mkdir(parents=True)
    ds = static.copy()
    for name, var in ds.variables.items():  # Zarr 3 has no stable fixed-width string
        if var.dtype.kind == "U":
            ds[name] = var.astype(object)
    ds.to_zarr(part / DATA, mode="w-", zarr_format=3, consolidated=False)
    group = zarr.open_group(part / DATA, mode="r+", zarr_format=3)
    for name, attrs in (("raw", RAW_ATTRS),
                        ("compressed", dict(COMPRESSED_ATTRS, weighting=weighting))):
        group.create_array(name, shape=shape, chunks=(block, *shape[1:]),
                           dtype=np.complex128, fill_value=0j, attributes=attrs,
                           dimension_names=tuple(dims))
    _write_json_atomic(part / MANIFEST, manifest(identity, shape, block))


def finalize(part: Path, path: Path) -> None:
    """Give the complete store its name (replacing an older ``path``) and remove the
    run's records."""
    old = None
    if path.exists():
        old = path.with_name(f".{path.name}.old.{os.getpid()}")
        os.replace(path, old)
    os.replace(part / DATA, path)
    shutil.rmtree(part)
    if old is not None:
        shutil.rmtree(old) if old.is_dir() else old.unlink()


def write_zarr_run(path: str | os.PathLike, static: Callable[[], object], *,
                   identity: dict, shape: tuple[int, ...], block: int, runner,
                   weighting: str = "none", progress: bool = True,
                   resume: bool = False,
                   dims: tuple[str, ...] = ("pulse", "channel", "fast_time")) -> Path:
    """Write (or continue) a run's Zarr store (module docstring).

    Parameters as :func:`seaecho.io.run.write_run`. With ``resume``, an incomplete run
    of ``path`` (``OUT.zarr.part``) of the same scene, seed and version is continued
    (its block size is kept); a complete ``path`` of the same run is left as it is.

    Raises
    ------
    StoreError
        An incomplete run exists and ``resume`` is not set; or the store to continue is
        corrupt or of another run.
    """
    from tqdm import tqdm

    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise FileNotFoundError(f"output directory {directory} does not exist")
    part = part_path(path)
    if part.exists() and not resume:
        raise StoreError(f"{part} holds an interrupted run of {path.name}: continue it with "
                         "--resume (resume=True), or delete it to start over")
    if resume and not part.exists() and path.exists():
        import xarray as xr

        try:
            with xr.open_zarr(path, consolidated=False) as ds:
                attrs = dict(ds.attrs)
        except Exception as exc:  # zarr raises several kinds for a broken store
            raise StoreError(f"{path} is not a readable seaecho run ({type(exc).__name__}: "
                             f"{exc})") from None
        check_identity(str(path), attrs, identity)
        return path
    if resume and part.exists():
        m = _read_manifest(part)
        check_identity(str(part), m, identity)
        if tuple(m.get("shape", ())) != tuple(shape):
            raise _corrupt(part, f"shape {m.get('shape')} != {list(shape)}")
        block = int(m["block_pulses"])
        blocks = blocks_of(shape[0], block)
        done = completed_blocks(part, blocks)
    else:
        blocks = blocks_of(shape[0], block)
        try:
            create_store(part, static(), identity, shape, block, weighting, dims)
        except BaseException:
            shutil.rmtree(part, ignore_errors=True)  # nothing worth resuming yet
            raise
        done = set()
    todo = [i for i in range(len(blocks)) if i not in done]
    with tqdm(total=shape[0], initial=sum(b - a for i, (a, b) in enumerate(blocks)
                                          if i in done),
              unit="pulse", disable=not progress, desc="seaecho run") as bar:
        for record in runner.stored(part, todo, blocks):
            bar.update(record["stop"] - record["start"])
    missing = set(range(len(blocks))) - {int(f.stem) for f in (part / RECORDS).glob("*.json")}
    if missing:
        raise StoreError(f"{part}: blocks {sorted(missing)[:8]} have no completion record")
    finalize(part, path)
    return path


__all__ = ["StoreError", "check_identity", "completed_blocks", "create_store", "finalize",
           "is_zarr", "manifest", "part_path", "write_block", "write_zarr_run"]
