"""The calibration maps interpolated from their node grid against the direct evaluation,
on the paper's stripmap geometry (4 m antenna: K varies over the 28 m footprint).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seaecho.config import load_scene
from seaecho.config.image import ImageConfig
from seaecho.imaging.focus import RawData, _Processor, focus
from seaecho.simulation import Simulation

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "calibration_sar_point_targets.toml"


def test_interpolated_calibration_matches_the_direct_one():
    # The calibration needs the tracks and antennas only: the static part of the raw
    # dataset with silent pulses (no simulation of the echoes)
    sim = Simulation(load_scene(SCENE))
    raw = sim.static_dataset()
    shape = (raw.sizes["pulse"], raw.sizes["channel"], raw.sizes["fast_time"])
    raw["compressed"] = (("pulse", "channel", "fast_time"), np.zeros(shape, complex))
    # 0.5 m pixels over 128 m x 160 m: 65 nodes per axis, 2-2.5 m apart
    cfg = ImageConfig(pixel_m=0.5, extent_m=(-64.0, 64.0, -80.0, 80.0))
    img = focus(raw, cfg)
    valid = img["valid"].values.astype(bool)
    rng = np.random.default_rng(0)
    iy, ix = np.nonzero(valid)
    pick = rng.choice(iy.size, 400, replace=False)
    pts = np.stack([img["x"].values[ix[pick]], img["y"].values[iy[pick]],
                    np.zeros(400)], axis=-1)
    cal, _ = _Processor(RawData(raw), cfg, "numpy").calibration(pts)
    k = img["gain"].values[iy[pick], ix[pick]]
    a = img["resolution_area"].values[iy[pick], ix[pick]]
    assert np.ptp(20 * np.log10(cal.gain)) > 3.0  # the beam's edges are in the image
    np.testing.assert_allclose(20 * np.log10(k / cal.gain), 0.0, atol=0.05)
    np.testing.assert_allclose(a / cal.area, 1.0, rtol=0.02)
    assert float(np.nanmedian(cal.area)) == pytest.approx(
        float(np.nanmedian(img["resolution_area"].values[valid])), rel=0.05)
