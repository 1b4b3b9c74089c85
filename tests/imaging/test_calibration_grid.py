"""The calibration maps interpolated from their node grid against the direct evaluation,
on the paper's stripmap geometry (4 m antenna: K varies over the 28 m footprint)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from sar_helpers import simulate

from seaecho.config import load_scene
from seaecho.config.image import ImageConfig
from seaecho.imaging.focus import RawData, _Processor, focus

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "calibration_sar_point_targets.toml"


def test_interpolated_calibration_matches_the_direct_one(tmp_path):
    scene = load_scene(SCENE)
    scene = scene.model_copy(update={"radar": scene.radar.model_copy(
        update={"thermal_noise": False})})
    raw = simulate(scene, tmp_path / "raw.nc")
    # 0.5 m pixels over 128 m x 160 m: 65 nodes per axis, 2-2.5 m apart
    cfg = ImageConfig(pixel_m=0.5, extent_m=(-64.0, 64.0, -80.0, 80.0))
    img = focus(raw, cfg)
    valid = img["valid"].values.astype(bool)
    rng = np.random.default_rng(0)
    iy, ix = np.nonzero(valid)
    pick = rng.choice(iy.size, 400, replace=False)
    pts = np.stack([img["x"].values[ix[pick]], img["y"].values[iy[pick]],
                    np.zeros(400)], axis=-1)
    import xarray as xr

    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        cal, _ = _Processor(RawData(ds), cfg, "numpy").calibration(pts)
    k = img["gain"].values[iy[pick], ix[pick]]
    a = img["resolution_area"].values[iy[pick], ix[pick]]
    assert np.ptp(20 * np.log10(cal.gain)) > 3.0  # the beam's edges are in the image
    np.testing.assert_allclose(20 * np.log10(k / cal.gain), 0.0, atol=0.05)
    np.testing.assert_allclose(a / cal.area, 1.0, rtol=0.02)
    assert float(np.nanmedian(cal.area)) == pytest.approx(
        float(np.nanmedian(img["resolution_area"].values[valid])), rel=0.05)
