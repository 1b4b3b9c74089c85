"""Driving the CLI in-process for the fuzzing suite: write a scene, run a command,
collect exit status, stdout, stderr and what was left in the folder."""

from __future__ import annotations

import contextlib
import io
import os
import tempfile
import warnings
from dataclasses import dataclass
from pathlib import Path
from unittest import mock

import numpy as np

from seaecho.cli import main
from seaecho.config.toml_writer import dumps

#: Examples per property: small by default (CI), more with SEAECHO_FUZZ_EXAMPLES=2000.
EXAMPLES = int(os.environ.get("SEAECHO_FUZZ_EXAMPLES", "0")) or None
#: Memory limit given to every fuzzed command [GB]: large scenes are refused quickly.
MAX_MEMORY_GB = "2"
#: The machine's available memory as the fuzzed commands see it [bytes]: fixed above
#: MAX_MEMORY_GB, so that the limit is MAX_MEMORY_GB whatever else runs on the machine
#: (a limit that followed MemAvailable made a scene's verdict depend on the load).
FIXED_AVAILABLE_BYTES = 64e9


def examples(default: int) -> int:
    """The number of examples of a property: ``default`` unless the environment asks."""
    return EXAMPLES or default


@dataclass
class Outcome:
    rc: int
    out: str
    err: str
    files: list[str]  #: what the command left in its folder besides the scene
    finite: bool | None  #: every float/complex variable of the output finite (if written),
    #: and its image's (``[image]``) but at the undefined pixels (``seaecho.checks.guards``)


def scene_text(data: dict) -> str:
    return dumps(data)


def run_cli(command: str, text: str, *extra: str) -> Outcome:
    """``seaecho COMMAND scene.toml ...`` in-process in a fresh folder."""
    with tempfile.TemporaryDirectory(prefix="seaecho-fuzz-") as tmp:
        folder = Path(tmp)
        scene = folder / "scene.toml"
        scene.write_text(text, encoding="utf-8")
        args = [command, str(scene), "--max-memory-gb", MAX_MEMORY_GB, "--no-figures"]
        out_nc = folder / "out.nc"
        if command == "run":  # check estimates the same run: without figures
            # a scene's own [run] output is kept (check checks it), in the folder
            args += ([] if _has_output(text) else ["-o", str(out_nc)]) + ["-q"]
        args += list(extra)
        o, e = io.StringIO(), io.StringIO()
        fixed = (FIXED_AVAILABLE_BYTES, "available memory (fixed by the fuzzing suite)")
        with (contextlib.redirect_stdout(o), contextlib.redirect_stderr(e),
              warnings.catch_warnings(), contextlib.chdir(folder),
              mock.patch("seaecho.checks.resources.available_memory", lambda: fixed)):
            warnings.simplefilter("always")  # printed as the console script does
            rc = main(args)
        finite = None
        own = _output(text) if command == "run" else None
        if own is not None and (folder / own).exists() and own.endswith(".zarr"):
            from seaecho.api import open_dataset  # a Zarr run: the same finite check

            with open_dataset(folder / own) as ds:
                finite = all(bool(np.isfinite(v.values).all())
                             for v in ds.data_vars.values() if v.dtype.kind in "fc")
        if own is not None and not own.endswith(".zarr"):
            out_nc = folder / own
        if out_nc.exists() and out_nc.is_file():
            import xarray as xr

            with xr.open_dataset(out_nc, engine="h5netcdf") as ds:
                finite = all(bool(np.isfinite(v.values).all()) for v in ds.data_vars.values()
                             if v.dtype.kind in "fc")
        img_nc = folder / "out_image.nc"
        if img_nc.exists():  # [image]: no Inf, NaN only at its undefined pixels
            import xarray as xr

            from seaecho.checks.guards import image_problems

            with xr.open_dataset(img_nc, engine="h5netcdf") as ds:
                finite = bool(finite) and not image_problems(ds.load())
        files = sorted(p.name for p in folder.iterdir() if p.name != "scene.toml")
        return Outcome(rc, o.getvalue(), e.getvalue(), files, finite)


def _output(text: str) -> str | None:
    """The scene's ``[run] output`` (then `run` writes there, relative to its folder)."""
    import tomllib

    try:
        run = tomllib.loads(text).get("run")
    except (tomllib.TOMLDecodeError, RecursionError):
        return None
    out = run.get("output") if isinstance(run, dict) else None
    return out if isinstance(out, str) else None


def _has_output(text: str) -> bool:
    return _output(text) is not None


def assert_clean(outcome: Outcome, what: str = "") -> None:
    """Exit 0 or 2; 2 comes with one 'seaecho: error:' message, never a traceback, and
    leaves no file behind."""
    context = f"{what}\nstatus {outcome.rc}\nstderr:\n{outcome.err[-3000:]}"
    assert outcome.rc in (0, 2), context
    assert "Traceback" not in outcome.err, context
    if outcome.rc == 2:
        assert "seaecho: error:" in outcome.err, context
        assert outcome.files == [], context
    if outcome.finite is not None:
        assert outcome.finite, "non-finite values written\n" + context
