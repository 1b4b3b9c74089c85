"""Figures and numbers of docs/scanning.md: fan-beam patterns, the PPI of a revolution,
a sector over the sea, and the speed of the coastal scene.

Run: ``python examples/scanning_figures.py [OUTDIR] [--quick]`` (default
``docs/figures``). Writes

- ``scanning_patterns.png``: one-way azimuth patterns of a 2 m X-band aperture
  illuminated uniformly, by a cosine and by Taylor (-30 dB, nbar 4)
  (``seaecho.radar.antennas.line_pattern``), with their half-power widths and peak
  sidelobes printed;
- ``scanning_ppi_revolution.png``: a revolution of ``scenes/coastal_vts_xband.toml``
  with the sea clutter off (targets and noise), PRF 500 Hz (1250 pulses): the PPI
  (seaecho's figure of the sweep, ``seaecho.figures``) with the targets' truth marked;
- ``scanning_ppi_sea_sector.png``: the same scene with its sea (sea state 4 on the
  256 m tile 2 km north), the antenna sweeping a sector from bearing 350 deg to 10 deg
  (56 pulses at 24 rpm, 1 kHz);

and prints, for the sector run, the seconds per pulse on this machine (wall clock, with
the load average). ``--quick``: 90 pulses of the revolution, a 64 m tile.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from _gallery import first_ppi  # noqa: E402

import seaecho  # noqa: E402
from seaecho.radar.antennas import line_pattern  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"
LAMBDA = 299792458.0 / 9.41e9


def patterns(out: Path) -> Path:
    deg = np.linspace(-8.0, 8.0, 4001)
    t = 2.0 * np.sin(np.radians(deg)) / LAMBDA
    fig, ax = plt.subplots(figsize=(6.4, 3.8), constrained_layout=True)
    for name, kw in (("uniform", {}), ("cosine", {}),
                     ("taylor", {"sidelobe_db": 30.0, "nbar": 4})):
        f = np.abs(line_pattern(t, name, **kw))
        db = 20 * np.log10(np.maximum(f, 1e-6))
        half = deg[db >= -3.0]
        tt = np.linspace(0.0, 12.0, 120001)
        ff = np.abs(line_pattern(tt, name, **kw))
        null = np.argmax(np.diff(ff) > 0)
        sll = 20 * np.log10(ff[null:].max())
        label = (f"{name}: {half.max() - half.min():.2f} deg, peak sidelobe "
                 f"{sll:.1f} dB")
        print(label)
        ax.plot(deg, db, lw=1.0, label=label)
    ax.set_ylim(-60, 2)
    ax.set_xlabel("azimuth off boresight [deg]")
    ax.set_ylabel("one-way power pattern [dB]")
    ax.set_title("2 m aperture at 9.41 GHz: illuminations along the width", fontsize=9)
    ax.legend(fontsize=8, loc="lower center")
    ax.grid(alpha=0.3)
    path = out / "scanning_patterns.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def ppi(scene, out: Path, name: str) -> tuple[Path, float, int]:
    start = time.perf_counter()
    ds = seaecho.simulate(scene, progress=False)
    wall = time.perf_counter() - start
    return first_ppi(ds, out, name), wall, ds.sizes["pulse"]


def main(argv: list[str] | None = None) -> list[Path]:
    argv = sys.argv[1:] if argv is None else argv
    quick = "--quick" in argv
    rest = [a for a in argv if a != "--quick"]
    out = Path(rest[0]) if rest else ROOT / "docs" / "figures"
    out.mkdir(parents=True, exist_ok=True)
    base = seaecho.load_scene(SCENE)
    written = [patterns(out)]
    # a revolution without the sea: targets and noise
    rev = {"radar.sea_clutter": False, "radar.prf_hz": 500.0, "radar.n_pulses": 1250}
    if quick:
        rev["radar.n_pulses"] = 90
    path, wall, n = ppi(seaecho.with_overrides(base, rev), out, "scanning_ppi_revolution")
    written.append(path)
    print(f"revolution without sea: {n} pulses in {wall:.1f} s wall")
    # a sector over the sea tile: bearing 350 -> 10 deg (counter-clockwise azimuth from
    # body x, north: 10 -> -10 deg), one pass at 24 rpm = 144 deg/s: 0.139 s, 139 pulses
    sector = {"transmitter.antenna.scan": {"mode": "sector", "rate_rpm": 24.0,
                                           "sector_deg": [10.0, -10.0]},
              "radar.n_pulses": 139, "radar.sea_update_pulses": 139}
    if quick:
        sector.update({"sea.size_x_m": 64.0, "sea.nx": 64, "radar.n_pulses": 8,
                       "radar.sea_update_pulses": 8})
    path, wall, n = ppi(seaecho.with_overrides(base, sector), out,
                        "scanning_ppi_sea_sector")
    written.append(path)
    load = os.getloadavg()[0]
    print(f"sea sector: {n} pulses in {wall:.1f} s wall = {wall / n * 1e3:.0f} ms per "
          f"pulse ({n / wall:.1f} pulses/s; a 2500-pulse revolution ~{2500 * wall / n:.0f} "
          f"s) on {os.cpu_count()} cores, load average {load:.1f}")
    for p in written:
        print(f"wrote {p}")
    return written


if __name__ == "__main__":
    main()
