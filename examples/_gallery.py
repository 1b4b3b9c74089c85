"""Shared by the gallery scripts of ``examples/`` (not a figure itself).

Every script takes ``--out DIR`` (default ``docs/figures``) and ``--quick`` (a reduced
mode: small grid, few pulses, a few seconds; ``tests/examples`` runs every script so), has
``main(argv) -> list[Path]`` returning the figures it wrote, and prints each seaecho
warning once, in one line, as the command line does: the paper's scenes are outside some
models' domains on purpose (e.g. the small-perturbation method with k h > 0.3 on a
0.25 m grid), and saying so is part of the result.

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
FIGURES = ROOT / "docs" / "figures"

#: Reduced mode of the paper's SAR simulations 2 and 3: a 32 m tile on the same 0.25 m
#: grid with the boat moved into it, 64 pulses (the aircraft abeam at the middle one),
#: the hull traced with one ray per wavelength, a 48 m image
QUICK_SAR = {"sea.size_x_m": 32.0, "sea.nx": 128, "ship.position_m": [4.0, 3.0],
             "radar.n_pulses": 64, "radar.start_time_s": -32.0 / 222.0,
             "radar.sea_update_pulses": 64, "radar.sigma_map_pulse": 32,
             "objects.0.rays_per_wavelength": 1.0}
QUICK_SAR_IMAGE = {"extent_m": [-24.0, 24.0, -24.0, 24.0]}


def options(doc: str | None, argv: list[str] | None = None,
            more: Callable[[argparse.ArgumentParser], None] | None = None
            ) -> argparse.Namespace:
    """Parse ``--out`` and ``--quick`` (and the script's own options), make the output
    folder, select matplotlib's file back end."""
    import matplotlib

    matplotlib.use("Agg")
    p = argparse.ArgumentParser(description=(doc or "").strip().splitlines()[0])
    p.add_argument("--out", type=Path, default=FIGURES,
                   help="folder of the figures (default docs/figures)")
    p.add_argument("--quick", action="store_true",
                   help="reduced mode: small grid, few pulses (seconds; what the tests run)")
    if more is not None:
        more(p)
    args = p.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    return args


def save(fig, out: Path, name: str, dpi: int = 110) -> Path:
    """Write ``fig`` as ``out / name`` atomically, close it, say so."""
    import matplotlib.pyplot as plt

    from seaecho.io.dataset import atomic_savefig

    path = atomic_savefig(fig, Path(out) / name, dpi=dpi)
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


def db(x, floor: float = 1e-30):
    """10 log10(x) with a floor [dB]."""
    import numpy as np

    return 10.0 * np.log10(np.maximum(x, floor))


def sar_figures(scene_file: str, stem: str, args: argparse.Namespace,
                quick: dict, quick_image: dict, filtered: bool = False) -> list[Path]:
    """Simulate a SAR scene of the paper (Figs. 7-9), focus it with its ``[image]``
    section and write the sigma0 and Pauli figures as ``<stem>_*.png``; print the paper's
    image measures (``seaecho.imaging.quality.paper_metrics``). ``quick``: scene
    overrides and ``quick_image``: ``[image]`` fields of the reduced mode; ``filtered``:
    also the refined-Lee filtered sigma0."""
    import seaecho
    from seaecho.imaging.figures import image_figures
    from seaecho.imaging.quality import paper_metrics

    scene = seaecho.load_scene(SCENES / scene_file)
    fields: dict = {"speckle_filter": "refined-lee"} if filtered else {}
    if args.quick:
        scene = seaecho.with_overrides(scene, quick)
        fields.update(quick_image)
    with seaecho_warnings():
        raw = seaecho.simulate(scene, progress=not args.quick)
        img = seaecho.image(raw, progress=not args.quick, **fields)
    for ch, m in paper_metrics(img).items():
        if m:
            print(f"  {ch}: " + ", ".join(f"{k} {v:.2f}" for k, v in m.items()))
    cfg = seaecho.api.image_config(raw, **fields)
    paths = image_figures(img, Path(args.out) / stem, cfg.dynamic_range_db)
    for p in paths:
        print(f"wrote {p}")
    return paths
