"""An on-disk cache of computed arrays (hull signatures), keyed by a hash of their inputs.

A hull's SBR trace (:func:`seaecho.tracing.sbr.trace_signature`) takes seconds and is the
same for the same inputs, to the byte. :class:`ArrayCache` keeps such results in a user
cache folder so that a second run of a scene starts without re-tracing:

- **Key.** :func:`digest` hashes (SHA-256) every input of the computation, each array by
  its name, dtype, shape and bytes (so -0.0 and 0.0, or one ulp, are different keys), and
  :func:`code_fingerprint`: the source of every module of seaecho, the versions of
  Python, numpy, scipy, Mitsuba and Dr.Jit, and the machine's architecture and
  instruction-set flags (a folder shared by different processors keeps their entries
  apart). A change in any input or in the code misses; nothing expires with time.
- **Writes are atomic.** An entry is written to a temporary file in the cache folder and
  moved onto its name with ``os.replace`` (an atomic rename on POSIX and Windows): a
  reader sees the whole file or none, and concurrent writers of one key (workers of a
  distributed run) each replace it with the same content. The key is stored in the file
  and checked on reading; an unreadable or foreign file is a miss (and is removed).
- **Size.** After a write, the least recently used entries (by modification time, which
  a hit refreshes) are removed while the folder holds more than
  ``SEAECHO_CACHE_MAX_MB`` (default 2048 MB).
- **Failures never fail a run**: a folder that cannot be created or written makes every
  access a miss.

Where: ``SEAECHO_CACHE_DIR`` if set, else the platform's user cache folder
(``$XDG_CACHE_HOME/seaecho`` or ``~/.cache/seaecho`` on Linux, ``~/Library/Caches/seaecho``
on macOS, ``%LOCALAPPDATA%\\seaecho\\Cache`` on Windows). ``SEAECHO_CACHE=off`` (or ``0``,
``false``, ``no``) disables it; ``seaecho run --no-cache`` sets that.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import platform
import sys
import tempfile
import time
from collections.abc import Iterable, Mapping
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "CACHE_DIR_ENV",
    "CACHE_ENV",
    "CACHE_MAX_ENV",
    "ArrayCache",
    "cache_directory",
    "code_fingerprint",
    "digest",
    "tree_digest",
]

#: Environment variable that disables the cache (``off``, ``0``, ``false``, ``no``).
CACHE_ENV = "SEAECHO_CACHE"
#: Environment variable naming the cache folder (default: the user cache folder).
CACHE_DIR_ENV = "SEAECHO_CACHE_DIR"
#: Environment variable bounding the cache's size [MB] (default 2048).
CACHE_MAX_ENV = "SEAECHO_CACHE_MAX_MB"
_OFF = {"off", "0", "false", "no"}
_KEY = "__cache_key__"


def cache_directory() -> Path | None:
    """The cache folder from the environment (module docstring), or None when disabled."""
    if os.environ.get(CACHE_ENV, "").strip().lower() in _OFF:
        return None
    given = os.environ.get(CACHE_DIR_ENV, "").strip()
    if given:
        return Path(given)
    if sys.platform == "darwin":
        return Path.home() / "Library" / "Caches" / "seaecho"
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA") or str(Path.home() / "AppData" / "Local")
        return Path(base) / "seaecho" / "Cache"
    base = os.environ.get("XDG_CACHE_HOME", "").strip()
    return (Path(base) if base else Path.home() / ".cache") / "seaecho"


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """SHA-256 of seaecho's source and of the versions its numbers depend on.

    Every ``*.py`` file of the installed package (path and bytes, in sorted order), the
    versions of Python, numpy, scipy, Mitsuba and Dr.Jit, the machine architecture and
    the processor's instruction-set flags: a cached result is never used by other code,
    or on another kind of processor, than the one that computed it.
    """
    import importlib.metadata as md

    h = hashlib.sha256(tree_digest(Path(__file__).resolve().parents[1]).encode())
    versions = [sys.version, platform.machine(), _cpu_features()]
    for dist in ("numpy", "scipy", "mitsuba", "drjit"):
        try:
            versions.append(f"{dist}={md.version(dist)}")
        except md.PackageNotFoundError:
            versions.append(f"{dist}=none")
    h.update("\n".join(versions).encode())
    return h.hexdigest()


def _cpu_features() -> str:
    """The processor's instruction-set flags (Linux), else its platform name: numpy's and
    Embree's SIMD kernels are chosen by them, and their last bits may differ."""
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as f:
            for line in f:
                if line.startswith(("flags", "Features")):
                    return " ".join(sorted(line.split(":", 1)[1].split()))
    except OSError:
        pass
    return platform.processor()


def tree_digest(root: str | os.PathLike) -> str:
    """SHA-256 (hex) of the ``*.py`` files under ``root``: relative paths and bytes, in
    sorted order."""
    root = Path(root)
    h = hashlib.sha256()
    for p in sorted(root.rglob("*.py"), key=lambda q: q.relative_to(root).as_posix()):
        h.update(p.relative_to(root).as_posix().encode() + b"\0")
        h.update(p.read_bytes() + b"\0")
    return h.hexdigest()


def _feed(h, name: str, value: Any) -> None:
    """Hash one named input: arrays by dtype, shape and bytes; scalars through numpy;
    strings and None by a tagged text; sequences element by element."""
    h.update(name.encode() + b"\0")
    if value is None:
        h.update(b"none\0")
    elif isinstance(value, str):
        h.update(b"str\0" + value.encode() + b"\0")
    elif isinstance(value, (tuple, list)) and not all(
            isinstance(v, (int, float, complex, bool, np.number)) for v in value):
        h.update(f"seq{len(value)}\0".encode())
        for i, v in enumerate(value):
            _feed(h, f"{name}[{i}]", v)
    else:
        a = np.ascontiguousarray(value)
        if a.dtype == object:
            raise TypeError(f"{name}: cannot hash an object array")
        h.update(f"{a.dtype.str}{a.shape}\0".encode())
        h.update(a.tobytes())


def digest(items: Iterable[tuple[str, Any]]) -> str:
    """SHA-256 (hex) of named inputs and of :func:`code_fingerprint`.

    Parameters
    ----------
    items : iterable of (str, value)
        The inputs, in a fixed order: arrays, numbers, strings, None, or sequences of
        those.
    """
    h = hashlib.sha256()
    _feed(h, "code", code_fingerprint())
    for name, value in items:
        _feed(h, name, value)
    return h.hexdigest()


class ArrayCache:
    """A folder of ``.npz`` entries, each a dict of arrays under a hex key.

    Parameters
    ----------
    directory : path or None
        The cache root (None: :func:`cache_directory`; a disabled cache gives a cache
        whose every access misses).
    namespace : str
        Sub-folder of the entries (one kind of result).
    max_bytes : float, optional
        Size bound of the namespace [bytes] (default ``SEAECHO_CACHE_MAX_MB``, else
        2048 MB).
    """

    def __init__(self, directory: str | os.PathLike | None = None, namespace: str = "arrays",
                 max_bytes: float | None = None) -> None:
        root = cache_directory() if directory is None else Path(directory)
        self.directory = None if root is None else root / namespace
        if max_bytes is None:
            try:
                max_bytes = float(os.environ.get(CACHE_MAX_ENV, 2048)) * 2.0**20
            except ValueError:
                max_bytes = 2048 * 2.0**20
        self.max_bytes = max_bytes

    @classmethod
    def disabled(cls) -> ArrayCache:
        """A cache that never hits and never writes."""
        out = cls.__new__(cls)
        out.directory, out.max_bytes = None, 0.0
        return out

    @property
    def enabled(self) -> bool:
        """Whether entries are read and written."""
        return self.directory is not None

    def path(self, key: str) -> Path:
        """The file of an entry."""
        if self.directory is None:
            raise ValueError("the cache is disabled")
        return self.directory / key[:2] / f"{key}.npz"

    def get(self, key: str) -> dict[str, NDArray] | None:
        """The arrays stored under ``key``, or None (a miss, a disabled cache, or an
        unreadable entry, which is then removed)."""
        if self.directory is None:
            return None
        p = self.path(key)
        try:
            with open(p, "rb") as f, np.load(f, allow_pickle=False) as z:
                out = {k: z[k] for k in z.files}
        except FileNotFoundError:
            return None
        except Exception:  # noqa: BLE001 - truncated, corrupt or foreign file: a miss
            with contextlib.suppress(OSError):
                p.unlink()
            return None
        if str(out.pop(_KEY, "")) != key:
            return None
        with contextlib.suppress(OSError):
            os.utime(p)  # least recently used first out
        return out

    def put(self, key: str, arrays: Mapping[str, Any]) -> bool:
        """Store ``arrays`` under ``key`` atomically; False when it could not be written."""
        if self.directory is None:
            return False
        if _KEY in arrays:
            raise ValueError(f"{_KEY!r} is reserved")
        p = self.path(key)
        tmp = None
        try:
            p.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=p.parent, prefix=".tmp-", suffix=".npz")
            with os.fdopen(fd, "wb") as f:
                np.savez(f, **{_KEY: np.array(key)}, **arrays)
                f.flush()
                os.fsync(f.fileno())
            os.replace(tmp, p)
            tmp = None
        except OSError:
            return False
        finally:
            if tmp is not None:
                with contextlib.suppress(OSError):
                    os.unlink(tmp)
        self.prune()
        return True

    def prune(self) -> None:
        """Remove the least recently used entries while the namespace is over its size
        bound (to 80 % of it)."""
        if self.directory is None:
            return
        entries = []
        now = time.time()
        try:
            for p in self.directory.glob("*/*.npz"):
                with contextlib.suppress(OSError):
                    st = p.stat()
                    if not p.name.startswith("."):
                        entries.append((st.st_mtime, st.st_size, p))
                    elif now - st.st_mtime > 3600.0:  # left by a writer that died
                        p.unlink()
        except OSError:
            return
        total = sum(e[1] for e in entries)
        if total <= self.max_bytes:
            return
        for _, size, p in sorted(entries, key=lambda e: (e[0], str(e[2]))):
            if total <= 0.8 * self.max_bytes:
                break
            with contextlib.suppress(OSError):
                p.unlink()
                total -= size
