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


@pytest.mark.parametrize(("nx", "ny"), [(2, 100), (100, 2), (3, 70), (70, 70)])
def test_node_interpolation_of_narrow_images(nx, ny):
    # Found by the fuzzing suite: an image 2 pixels wide and 190 long (65 x 2 nodes) died
    # in scipy's spline ("my > ky failed"): the degrees were given to the wrong axes. A
    # spline of degree min(3, n - 1) per axis holds the polynomials of those degrees, so
    # its interpolant of one is the polynomial itself (C. de Boor, A Practical Guide to
    # Splines, Springer, 2001): the values between the nodes are the polynomial's
    from seaecho.imaging.focus import ImageGrid, _interpolate

    grid = ImageGrid(np.linspace(-3.0, 5.0, nx), np.linspace(-40.0, 0.0, ny))
    nodes = grid.nodes()
    dx, dy = min(3, nodes.x.size - 1), min(3, nodes.y.size - 1)

    def f(x, y):
        return (1.0 + 0.3 * x**dx + 0.2 * x) * (2.0 + 1e-4 * y**dy)

    xx, yy = np.meshgrid(nodes.x, nodes.y)
    out = _interpolate(nodes, f(xx, yy).ravel(), grid)
    gx, gy = np.meshgrid(grid.x, grid.y)
    np.testing.assert_allclose(out, f(gx, gy), rtol=1e-10)
