"""Writing datasets atomically.

Every file seaecho writes goes to a temporary file in the destination's directory first
and is renamed over the destination (``os.replace``, atomic on POSIX) only once it is
complete; an exception or an interrupt removes the temporary file, so a crash never leaves
a corrupt or partial output file.
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import xarray as xr

from .. import __version__


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; on success rename it to ``path``.

    On any exception (including KeyboardInterrupt) the temporary file is removed and
    ``path`` is left as it was.
    """
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise FileNotFoundError(f"output directory {directory} does not exist")
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=f".{path.name}.", suffix=".part")
    os.close(fd)
    tmp_path = Path(tmp)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp_path, 0o666 & ~umask)  # mkstemp makes 0600; give the usual permissions
    try:
        yield tmp_path
        os.replace(tmp_path, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()
        raise


def scene_attrs(scene) -> dict[str, Any]:
    """Dataset attributes that say how a file was made: the full scene and the version."""
    return {
        "scene_json": json.dumps(scene.model_dump(mode="json"), sort_keys=True),
        "seaecho_version": __version__,
        "seed": int(scene.run.seed),
        "Conventions": "CF-1.8",
    }


def write_dataset_atomic(ds: xr.Dataset, path: str | os.PathLike,
                         guard: Callable[[xr.Dataset], None] | None = None) -> Path:
    """Write ``ds`` to netCDF-4 (h5netcdf) at ``path`` atomically.

    Complex variables are stored as HDF5 compound types (``invalid_netcdf=True``), which
    ``xarray.open_dataset(path, engine="h5netcdf")`` reads back as complex. ``guard``, if
    given, is called on ``ds`` inside the atomic write, before the file is renamed into
    place (e.g. ``seaecho.checks.guards.check_image``): if it raises, nothing is left at
    ``path``.
    """
    path = Path(path)
    with atomic_path(path) as tmp:
        if guard is not None:
            guard(ds)
        ds.to_netcdf(tmp, engine="h5netcdf", invalid_netcdf=True)
    return path


def atomic_savefig(fig, path: str | os.PathLike, **kwargs: Any) -> Path:
    """Save a matplotlib figure atomically (PNG unless the suffix says otherwise)."""
    path = Path(path)
    fmt = kwargs.pop("format", path.suffix.lstrip(".") or "png")
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=fmt, **kwargs)
    return path


__all__ = ["atomic_path", "atomic_savefig", "scene_attrs", "write_dataset_atomic"]
