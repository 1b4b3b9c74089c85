"""Beyond the paper: the PPI of each bundled scanning radar, one revolution each.

    python examples/scanning_ppi.py [--out docs/gallery] [--paper | --quick]

Runs the scanning scenes of ``scenes/`` with ``seaecho.simulate`` and writes the PPI of
their first sweep (``seaecho.figures``: polar, dB, x east / y north, the truth's ships
and targets marked; docs/scanning.md):

- ``ppi_coastal_vts_xband.png``: ``coastal_vts_xband.toml``, a VTS radar 30 m up on a
  headland, 24 rpm, 6 km, sea state 4 on its 256 m tile, the coastline, boats and
  Swerling targets;
- ``ppi_shipborne_navigation_xband.png``: ``shipborne_navigation_xband.toml``, a
  navigation radar on a ship at 12 kn that rolls, pitches and yaws, the sea on a 256 m
  tile ahead;
- ``ppi_sband_longrange.png``: ``sband_longrange.toml``, an S-band magnetron radar with
  a 12 km window and the sea everywhere the window reaches (``[sea] coverage =
  "radar"``): that sea costs about half a second of CPU per pulse even held
  (docs/scanning.md), so this one is a 20 deg sector of its revolution centred on the
  tanker, the sea held over the sector (the tiles computed once at unit gains; the
  magnetron's random phase per pulse leaves no coherent processing that would see the
  held sea's missing Doppler; the scene itself evolves its sea).

By default the coastal and shipborne revolutions at half their PRF (1250 pulses each,
one revolution) and the S-band sector (167 pulses); ``--paper``: the scenes as they
are (2500-pulse revolutions; the S-band scene's 3000-pulse revolution with its evolving
sea takes hours);
``--quick``: a few pulses each on small tiles. The times per scene are printed.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

from _gallery import SCENES, first_ppi, options, seaecho_warnings

import seaecho

#: One revolution at half the scenes' PRF (24 rpm: 2.5 s, 1250 pulses at 500 Hz)
HALF_PRF = {"radar.prf_hz": 500.0, "radar.n_pulses": 1250, "radar.sea_update_pulses": 125}
#: A few pulses on a small tile: what the test runs
QUICK = {"radar.n_pulses": 6, "radar.sea_update_pulses": 6, "sea.size_x_m": 64.0,
         "sea.nx": 64}
#: The S-band scene's sector (20 rpm = 120 deg/s at 1 kHz: 0.12 deg per pulse): 20 deg
#: centred on the first ship's bearing, the sea held over the sector
SBAND_SECTOR = {"radar.n_pulses": 167, "radar.sea_update_pulses": 167,
                "scattering.sea_motion": "held"}
SBAND_QUICK = {"radar.n_pulses": 2, "radar.sea_update_pulses": 2,
               "scattering.sea_motion": "held",
               "radar.window_end_m": 2000.0, "sea.size_x_m": 64.0, "sea.nx": 32}

SCENE_SIZES = {
    "coastal_vts_xband": ({}, HALF_PRF, QUICK),
    "shipborne_navigation_xband": ({}, HALF_PRF, QUICK),
    "sband_longrange": ({}, SBAND_SECTOR, SBAND_QUICK),
}


def _sector(scene, pulses: int) -> dict:
    """A sector scan of ``pulses`` pulses centred on the first target's bearing (the
    scene's rate and PRF): the S-band scene's sea costs too much for a revolution."""
    import numpy as np

    scan = scene.transmitter.antenna.scan
    step_deg = 360.0 * scan.rate_rpm / 60.0 / scene.radar.prf_hz
    half = 0.5 * pulses * step_deg
    xy = np.asarray(scene.targets[0].position_m[:2]) - np.asarray(
        scene.transmitter.position_m[:2])
    # CCW from the radar's body x (the scene's yaw turns body x from east)
    centre = float(np.degrees(np.arctan2(xy[1], xy[0]))) - (scene.transmitter.yaw_deg or 0.0)
    return {"transmitter.antenna.scan": {"mode": "sector", "rate_rpm": scan.rate_rpm,
                                         "sector_deg": [centre + half, centre - half]}}


def ppi(name: str, size: str, out: Path) -> Path:
    """Simulate one scene at ``size`` and keep the PPI of its first sweep."""
    scene = seaecho.load_scene(SCENES / f"{name}.toml")
    paper, default, quick = SCENE_SIZES[name]
    changes = dict({"paper": paper, "default": default, "quick": quick}[size])
    if name == "sband_longrange" and size != "paper":
        changes.update(_sector(scene, changes["radar.n_pulses"]))
    scene = seaecho.with_overrides(scene, changes) if changes else scene
    start, cpu = time.perf_counter(), time.process_time()
    with seaecho_warnings():
        ds = seaecho.simulate(scene, progress=size != "quick")
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    n = ds.sizes["pulse"]
    print(f"{name}: {n} pulses in {wall:.1f} s wall / {cpu:.1f} s CPU "
          f"({wall / n * 1e3:.1f} ms per pulse), load {os.getloadavg()[0]:.1f}")
    target = first_ppi(ds, out, f"ppi_{name}")
    print(f"wrote {target}")
    return target


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    return [ppi(name, args.size, Path(args.out)) for name in SCENE_SIZES]


if __name__ == "__main__":
    main()
