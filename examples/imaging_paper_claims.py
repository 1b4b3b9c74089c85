"""The paper's image claims (Simulations 2-4, Figs. 7-9) measured on the current code:
the table and the figures of docs/imaging.md, section 7.

    python examples/imaging_paper_claims.py [--out docs/figures] [--paper | --quick]
        [--sims 2 3 4] [--json FILE]

For each simulation it simulates ``scenes/paper_sim{2,3,4}_*.toml``, focuses it with the
scene's ``[image]`` section, measures the image (``seaecho.image_measures``: sea level,
wake contrast of means and of medians, the highest pixel outside the tile below the
highest wake pixel, wave modulation over 8 m and 16 m blocks; and the facets' own sigma0
over the same open-sea pixels, ``facets_sea_db``), and writes the figures
``imaging_sim{N}_sigma0.png`` and ``_pauli.png`` (``seaecho.figures``; Simulation 4 also
its refined-Lee filtered sigma0). Simulation 2 is focused a second time with Taylor
weighting (nbar 5, 35 dB) in range and azimuth, to measure the secondary peaks. The
numbers are printed and, with ``--json``, written to a file (``--set NAME=VALUE``
changes the scenes, e.g. to measure without the hull echo or with Michell's wake heights):
``tests/imaging/test_imaging_docs.py`` (slow set) reruns this script and compares them
with the table of docs/imaging.md.

Sizes (``_gallery.py``): by default the reduced scenes of the gallery (Simulations 2 and 3
on a 64 m tile on the paper's 0.25 m grid with the boat moved into it, the full 160-pulse
aperture, a 96 m image; a few minutes each on two cores), ``--paper`` the paper's (128 m
tiles; Simulation 4 takes about 8 minutes), ``--quick`` a 16 m tile and 16 pulses (the
gallery test).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import json
from pathlib import Path

from _gallery import (
    ROOT,
    SAR_DEFAULT,
    SAR_DEFAULT_IMAGE,
    SAR_QUICK,
    SAR_QUICK_IMAGE,
    SCENES,
    facets_sea_db,
    options,
    seaecho_warnings,
    sized,
)

SCENE_FILES = {2: "paper_sim2_sar_128m_wind55.toml", 3: "paper_sim3_sar_128m_wind0.toml",
               4: "paper_sim4_sar_500m_u10.toml"}
#: Simulation 4 reduced: a 128 m tile on its own grid (0.98 m), the same aperture
SIM4_DEFAULT = {"sea.size_x_m": 128.0, "sea.nx": 128}
SIM4_DEFAULT_IMAGE = {"extent_m": [-96.0, 96.0, -96.0, 96.0]}
SIM4_QUICK = {"sea.size_x_m": 32.0, "sea.nx": 32, "radar.n_pulses": 16}
SIM4_QUICK_IMAGE = {"extent_m": [-24.0, 24.0, -24.0, 24.0], "pixel_m": 1.0}
#: The second focusing of Simulation 2: Taylor weighting in range and azimuth.
TAYLOR = {"range_weighting": "taylor", "azimuth_window": "taylor", "taylor_nbar": 5,
          "taylor_sidelobe_db": 35.0}


def _more(p) -> None:
    p.add_argument("--sims", type=int, nargs="+", default=[2, 3, 4], choices=[2, 3, 4],
                   help="which simulations (default 2 3 4)")
    p.add_argument("--json", type=Path, help="write the measures to this JSON file")
    p.add_argument("--set", dest="overrides", action="append", default=[],
                   metavar="NAME=VALUE", help="a scene override for every simulation (as "
                   "`seaecho run --set`), e.g. objects.0.scatterer=false (no hull echo) or "
                   "ship.wake_amplitude=\"michell\"; repeatable")


def _overrides(texts: list[str]) -> dict:
    """``["a.b=1", 'c="x"']`` -> {"a.b": 1, "c": "x"} (values as TOML/JSON literals)."""
    out = {}
    for text in texts:
        name, _, value = text.partition("=")
        try:
            out[name.strip()] = json.loads(value)
        except json.JSONDecodeError:
            out[name.strip()] = value.strip()
    return out


def _measures(img) -> dict:
    import seaecho

    out = {}
    for ch, m in seaecho.image_measures(img).items():
        out[ch] = {k: round(float(v), 4) for k, v in m.items()}
    if "sigma0" in img:  # modulation over 16 m blocks as well (the table's second value)
        from seaecho.imaging.quality import paper_metrics

        for ch, m in paper_metrics(img, block_m=16.0).items():
            if "modulation" in m:
                out[ch]["modulation_16m"] = round(float(m["modulation"]), 4)
    for ch, value in facets_sea_db(img).items():  # the facets' sigma0 on the same pixels
        if ch in out:
            out[ch]["facets_sea_db"] = round(value, 4)
    return out


def run_simulation(n: int, args) -> tuple[dict, list[Path]]:
    """Simulate, focus, measure and draw Simulation ``n``: (measures, figures)."""
    import seaecho

    default, default_image, quick, quick_image = (
        (SAR_DEFAULT, SAR_DEFAULT_IMAGE, SAR_QUICK, SAR_QUICK_IMAGE) if n in (2, 3)
        else (SIM4_DEFAULT, SIM4_DEFAULT_IMAGE, SIM4_QUICK, SIM4_QUICK_IMAGE))
    scene = sized(seaecho.load_scene(SCENES / SCENE_FILES[n]), args, default, quick)
    if args.overrides:
        scene = seaecho.with_overrides(scene, _overrides(args.overrides))
    fields = dict({"paper": {}, "default": default_image, "quick": quick_image}[args.size])
    if n == 4:
        fields["speckle_filter"] = "refined-lee"
    result: dict = {}
    with seaecho_warnings():
        raw = seaecho.simulate(scene, progress=not args.quick)
        img = seaecho.image(raw, progress=not args.quick, **fields)
        result["measures"] = _measures(img)
        if n == 2:
            weighted = seaecho.image(raw, progress=not args.quick, **fields, **TAYLOR)
            result["taylor"] = _measures(weighted)
    paths = seaecho.figures(img, Path(args.out) / f"imaging_sim{n}")
    keep = [p for p in paths if p.name.endswith(("_sigma0.png", "_pauli.png",
                                                 "_sigma0_filtered.png"))]
    for p in paths:
        if p not in keep:
            p.unlink()  # the docs show these three only
    return result, keep


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv, _more)
    if args.out == ROOT / "docs" / "gallery":
        args.out = ROOT / "docs" / "figures"
        args.out.mkdir(parents=True, exist_ok=True)
    numbers: dict = {"size": args.size, "overrides": _overrides(args.overrides)}
    paths: list[Path] = []
    for n in args.sims:
        result, figs = run_simulation(n, args)
        numbers[f"sim{n}"] = result
        paths += figs
        for ch, m in result["measures"].items():
            print(f"Simulation {n} {ch}: " + ", ".join(f"{k} {v:.2f}" for k, v in m.items()))
        for ch, m in result.get("taylor", {}).items():
            print(f"Simulation {n} {ch}, Taylor: secondary_to_wake_db "
                  f"{m.get('secondary_to_wake_db', float('nan')):.2f}")
    for p in paths:
        print(f"wrote {p}")
    if args.json is not None:
        args.json.write_text(json.dumps(numbers, indent=1, sort_keys=True) + "\n")
        print(f"wrote {args.json}")
    return paths


if __name__ == "__main__":
    main()
