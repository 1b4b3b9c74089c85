"""Shared by the gallery scripts of ``examples/`` (not a figure itself; examples/README.md).

Every script takes ``--out DIR`` (default ``docs/gallery``) and a size: by default a
reduced scene that runs in a minute or two on two cores, ``--paper`` the paper's own
(minutes to an hour: docs/performance.md), ``--quick`` a tiny one of a few seconds (what
``tests/test_gallery.py`` runs, so that the scripts cannot rot). Each has
``main(argv) -> list[Path]`` returning the figures it wrote, uses the public ``seaecho``
API only, and prints each seaecho warning once, in one line, as the command line does:
the paper's scenes are outside some models' domains on purpose (e.g. the
small-perturbation method with k h > 0.3 on a 0.25 m grid), and the reduced tiles are
shorter than the longest waves; saying so is part of the result.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import warnings
from collections.abc import Callable, Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"
FIGURES = ROOT / "docs" / "gallery"

#: The SAR simulations 2 and 3 by default: a 64 m tile on the paper's 0.25 m grid with the
#: boat moved into it, the full 160-pulse aperture (the aircraft abeam at pulse 80), the
#: hull traced with one ray per wavelength, a 96 m image
SAR_DEFAULT = {"sea.size_x_m": 64.0, "sea.nx": 256, "ship.position_m": [8.0, 6.0],
               "objects.0.rays_per_wavelength": 1.0}
SAR_DEFAULT_IMAGE = {"extent_m": [-48.0, 48.0, -48.0, 48.0]}
#: ``--quick``: a 16 m tile on the same grid, 16 pulses around the middle one, 1 m pixels
SAR_QUICK = {"sea.size_x_m": 16.0, "sea.nx": 64, "ship.position_m": [2.0, 1.5],
             "radar.n_pulses": 16, "radar.start_time_s": -8.0 / 222.0,
             "radar.sea_update_pulses": 16, "radar.sigma_map_pulse": 8,
             "objects.0.rays_per_wavelength": 1.0}
SAR_QUICK_IMAGE = {"extent_m": [-12.0, 12.0, -12.0, 12.0], "pixel_m": 1.0}


def options(doc: str | None, argv: list[str] | None = None,
            more: Callable[[argparse.ArgumentParser], None] | None = None
            ) -> argparse.Namespace:
    """Parse ``--out``, ``--paper`` / ``--quick`` (into ``args.size``: ``default``,
    ``paper`` or ``quick``) and the script's own options; make the output folder; select
    matplotlib's file back end."""
    import matplotlib

    matplotlib.use("Agg")
    p = argparse.ArgumentParser(description=(doc or "").strip().splitlines()[0])
    p.add_argument("--out", type=Path, default=FIGURES,
                   help="folder of the figures (default docs/gallery)")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--paper", dest="size", action="store_const", const="paper",
                   default="default", help="the paper's scene sizes (minutes or more)")
    g.add_argument("--quick", dest="size", action="store_const", const="quick",
                   help="a tiny scene, a few seconds (what the tests run)")
    if more is not None:
        more(p)
    args = p.parse_args(argv)
    args.quick = args.size == "quick"
    args.out.mkdir(parents=True, exist_ok=True)
    return args


def sized(scene, args: argparse.Namespace, default: dict, quick: dict):
    """The scene at the size asked for: as it is (``--paper``), else with the overrides
    of the reduced (``default``) or tiny (``quick``) size."""
    import seaecho

    changes = {"paper": {}, "default": default, "quick": quick}[args.size]
    return seaecho.with_overrides(scene, changes) if changes else scene


def save(fig, out: Path, name: str, dpi: int = 110) -> Path:
    """Write ``fig`` as ``out / name``, close it, say so."""
    import matplotlib.pyplot as plt

    path = Path(out) / name
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    print(f"wrote {path}")
    return path


@contextlib.contextmanager
def seaecho_warnings() -> Iterator[None]:
    """Show each seaecho warning once, in one line; other warnings as Python shows them
    (and as the caller's filters say: errors under the test suite)."""
    from seaecho.warnings import SeaechoWarning

    seen: set[str] = set()

    def show(message, category, filename, lineno, file=None, line=None):
        text = f"{category.__name__}: {message}"
        if text not in seen:
            seen.add(text)
            print(f"warning: {text}", file=sys.stderr)

    with warnings.catch_warnings():
        warnings.filterwarnings("always", category=SeaechoWarning)
        previous, warnings.showwarning = warnings.showwarning, show
        try:
            yield
        finally:
            warnings.showwarning = previous


def facets_sea_db(img) -> dict[str, float]:
    """The facets' own sigma0 [dB] per channel (``sigma0_truth``) averaged over the image's
    valid open-sea pixels, the truth beside the image's sea level (docs/imaging.md,
    section 3); empty when the image has no ground truth or no open-sea mask."""
    import numpy as np

    if "sigma0_truth" not in img or "open_sea" not in img:
        return {}
    sea = img["valid"].values.astype(bool) & img["open_sea"].values.astype(bool)
    out = {}
    for c, ch in enumerate(str(v) for v in img["channel"].values):
        truth = img["sigma0_truth"].values[c][sea]
        if truth.size:
            out[ch] = float(10 * np.log10(truth.mean()))
    return out


def first_ppi(ds, out: Path, name: str) -> Path:
    """Write the PPI of a scanning run's first sweep as ``out / (name + '.png')``: the
    figures of ``seaecho.figures`` are drawn beside it under ``_<name>`` and all but that
    PPI removed (the scripts of docs/scanning.md, docs/land.md and the gallery's)."""
    import shutil

    import seaecho

    pngs = [p for p in seaecho.figures(ds, Path(out) / f"_{name}") if "_ppi_sweep_" in p.name]
    target = Path(out) / f"{name}.png"
    shutil.move(pngs[0], target)
    for p in Path(out).glob(f"_{name}*.png"):
        p.unlink()
    return target


def db(x, floor: float = 1e-30):
    """10 log10(x) with a floor [dB]."""
    import numpy as np

    return 10.0 * np.log10(np.maximum(x, floor))


def sar_figures(scene_file: str, stem: str, args: argparse.Namespace, *,
                default: dict, default_image: dict, quick: dict, quick_image: dict,
                filtered: bool = False) -> list[Path]:
    """Simulate a SAR scene (the paper's Figs. 7-9), focus it with its ``[image]`` section
    and write its sigma0 and Pauli figures as ``<stem>_*.png`` (``seaecho.figures``);
    print the paper's image measures (``seaecho.image_measures``, and the facets' own
    sigma0 over the same open-sea pixels, ``facets_sea_db``). ``default`` /
    ``quick``: scene overrides of the reduced / tiny size, ``*_image``: their ``[image]``
    fields; ``filtered``: also the refined-Lee filtered sigma0."""
    import seaecho

    scene = sized(seaecho.load_scene(SCENES / scene_file), args, default, quick)
    fields: dict = {"speckle_filter": "refined-lee"} if filtered else {}
    fields.update({"paper": {}, "default": default_image, "quick": quick_image}[args.size])
    with seaecho_warnings():
        raw = seaecho.simulate(scene, progress=not args.quick)
        img = seaecho.image(raw, progress=not args.quick, **fields)
    facets = facets_sea_db(img)
    for ch, m in seaecho.image_measures(img).items():
        if ch in facets:
            m = {**m, "facets_sea_db": facets[ch]}
        if m:
            print(f"  {ch}: " + ", ".join(f"{k} {v:.2f}" for k, v in m.items()))
    paths = seaecho.figures(img, Path(args.out) / stem)
    for p in paths:
        print(f"wrote {p}")
    return paths
