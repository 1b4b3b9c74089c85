"""Radiometry of a distributed target: the calibrated image of a sea tile has, on
average, the sigma0 of the facets it came from.

For independent scatterers of total sigma0 dA per area, E|s(x)|^2 = sigma0 A_eff (eq K3 of
``imaging.calibration``; Ulaby & Long 2014, section 13-4: a SAR pixel's mean intensity
is sigma0 times the resolution cell's area), so the mean of the sigma0 image over a region
estimates the mean of the facets' sigma0 there. Its statistical tolerance: single-look
intensity is exponential (relative variance 1) times the facets' own variation (the
texture T, relative variance CV_T^2), so a mean over N_ind = area / A_eff independent
cells has relative standard deviation sqrt((1 + 2 CV_T^2) / N_ind) (product model;
Oliver & Quegan 2004, section 11.3); we allow three of them.
"""

from __future__ import annotations

import numpy as np
import pytest
from sar_helpers import point_scene, radar_section

from seaecho.config import parse_scene
from seaecho.config.image import ImageConfig
from seaecho.imaging.focus import focus
from seaecho.simulation import Simulation

N = 64
# The facets' sigma0 is whatever the scattering stage gives on this coarse grid (its SPM
# is outside its k h domain here, and warns); the test only compares image and facets.
pytestmark = pytest.mark.filterwarnings(
    "ignore::seaecho.scattering.validity.SPMValidityWarning")


def _sea_scene():
    base = point_scene([{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 0.0}], n_pulses=N)
    data = base.model_dump(mode="json")
    data.pop("targets")
    data["image"] = None
    data["sea"] = {"spectrum": "pierson-moskowitz", "wind_speed_m_s": 4.0,
                   "wind_direction_deg": 0.0, "size_x_m": 32.0, "nx": 64}
    data["tracing"] = {"mode": "analytic", "shadowing": "none"}
    data["radar"] = radar_section(N, sea_clutter=True, sea_update_pulses=N,
                                  sigma_map_pulse=N // 2, window_start_m=None,
                                  window_end_m=None)
    data["transmitter"]["antenna"] = {"pattern": "rectangular", "width_m": 0.05,
                                      "height_m": 0.05, "azimuth_deg": -90.0,
                                      "depression_deg": 45.0}
    return parse_scene(data)


@pytest.fixture(scope="module")
def image(tmp_path_factory):
    path = tmp_path_factory.mktemp("sea") / "raw.nc"
    Simulation(_sea_scene()).run(path, progress=False)
    img = focus(path, ImageConfig(pixel_m=0.25, extent_m=(-16.0, 16.0, -16.0, 16.0)))
    return img


def test_mean_sigma0_of_the_image_is_that_of_the_facets(image):
    # A region 4 m inside the tile: the facets near the edge spill out of it and in
    inner = (np.abs(image["x"]) < 12.0) & (np.abs(image["y"]) < 12.0)
    region = inner.values & image["valid"].values.astype(bool)
    a_eff = float(np.nanmean(image["resolution_area"].values[region]))
    n_ind = region.sum() * 0.25**2 / a_eff
    assert n_ind > 150
    for k, ch in enumerate(image["channel"].values):
        truth = image["sigma0_truth"].values[k][region]
        got = image["sigma0"].values[k][region]
        cv2 = np.var(truth) / np.mean(truth) ** 2
        tol = 3.0 * np.sqrt((1.0 + 2.0 * cv2) / n_ind)
        ratio = got.mean() / truth.mean()
        assert abs(ratio - 1.0) < tol, (str(ch), ratio, tol)
