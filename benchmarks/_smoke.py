"""Smoke mode of the benchmarks (``--smoke``): the smallest size, one or two pulses, one
round, so that each benchmark runs in seconds to a minute and cannot rot unnoticed
(``tests/test_benchmarks.py``, in the slow set, runs every one). Its numbers mean
nothing: it checks that the benchmark still runs against the current code.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

#: Sea grid points per side in smoke mode.
GRID = 32
#: Pulses in smoke mode.
PULSES = 2
#: Launch rays per wavelength of a hull's trace in smoke mode (the schema's least).
RAYS_PER_WAVELENGTH = 1.0
#: Image pixel in smoke mode [m]: a few hundred pixels over the scenes' extents.
PIXEL_M = 8.0


def add_option(ap: argparse.ArgumentParser) -> None:
    """The ``--smoke`` option."""
    ap.add_argument("--smoke", action="store_true",
                    help="smallest size, one or two pulses, one round: does it still run? "
                    "(tests/test_benchmarks.py; the numbers mean nothing)")


def small_scene(path: Path, folder: Path | None = None, grid: int = GRID,
                pulses: int = PULSES) -> Path:
    """A copy of the scene file ``path`` on a ``grid`` x ``grid`` sea (fewer if the scene
    has fewer), with ``pulses`` pulses, a coarse ``[image]``, hulls traced with
    :data:`RAYS_PER_WAVELENGTH` and its meshes found from anywhere, written in ``folder``
    (default: a new temporary folder)."""
    from seaecho.config import load_scene
    from seaecho.config.loading import scene_to_toml_dict
    from seaecho.config.toml_writer import dumps

    path = Path(path).resolve()
    scene = load_scene(path)
    data = scene_to_toml_dict(scene)
    sea = data["sea"]
    sea["nx"] = min(sea["nx"], grid)
    if sea.get("ny") is not None:
        sea["ny"] = min(sea["ny"], grid)
    radar = data.get("radar")
    if radar is not None:
        radar["n_pulses"] = min(radar["n_pulses"], pulses)
        for key in ("sea_update_pulses", "sigma_map_pulse"):
            if radar.get(key) is not None:
                radar[key] = min(radar[key], radar["n_pulses"] - (key == "sigma_map_pulse"))
    if data.get("image") is not None:
        data["image"]["pixel_m"] = PIXEL_M
    for obj in data.get("objects") or []:
        obj["file"] = str(path.parent / obj["file"])
        if obj.get("scatterer"):  # the coarsest trace of a hull's echo
            obj["rays_per_wavelength"] = RAYS_PER_WAVELENGTH
    folder = Path(folder) if folder is not None else Path(tempfile.mkdtemp(prefix="smoke-"))
    out = folder / path.name
    out.write_text(dumps(data), encoding="utf-8")
    return out
