"""The scanning run's CfRadial 2 product: it opens with ``xarray.open_datatree``,
xradar georeferences it, and a target's echo is at the target's azimuth (clockwise from
north, CfRadial 2.0 section 4.6) and range.

Reference: NCAR/EOL, *CfRadial Data File Format* version 2.0 (2020); xradar's data model.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaecho
from seaecho.config import SceneError, parse_scene

xradar = pytest.importorskip("xradar")


def _scene(n_pulses=400, **scan):
    s = {"mode": "rotating", "rate_rpm": 120.0, "start_deg": 0.0}
    s.update(scan)
    s = {k: v for k, v in s.items() if v is not None}
    return parse_scene({
        "name": "ppi-test",
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 720.0, "n_pulses": n_pulses, "sea_clutter": False,
                  "transmit_power_w": 25e3, "channels": ["HH", "VV"],
                  "window_start_m": 1500.0, "window_end_m": 3500.0,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (100.0, -200.0, 30.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "rectangular", "width_m": 2.4, "height_m": 0.1,
            "illumination": "taylor", "depression_deg": 0.5, "scan": s}},
        "targets": [{"name": "buoy", "position_m": (1600.0, 1100.0, 2.0), "rcs_m2": 10.0},
                    {"name": "boat", "position_m": (-1400.0, -2200.0, 3.0),
                     "rcs_m2": 100.0}]})


@pytest.fixture(scope="module")
def run():
    return seaecho.simulate(_scene(), progress=False)


def test_product_opens_and_georeferences(run, tmp_path):
    path = tmp_path / "ppi.nc"
    seaecho.ppi(run, path)
    tree = xr.open_datatree(path)
    assert tree.attrs["Conventions"] == "Cf/Radial" and tree.attrs["version"] == "2.0"
    # 400 pulses at one degree each: a revolution and 40 rays of the next
    assert list(tree["sweep_group_name"].values) == ["sweep_0", "sweep_1"]
    assert tree["sweep_1"].sizes["azimuth"] == 40
    sweep = tree["sweep_0"].to_dataset()
    assert sweep["HH_power"].dims == ("azimuth", "range")
    assert sweep.sizes["azimuth"] == 360
    assert str(sweep["sweep_mode"].values) == "azimuth_surveillance"
    # time per ray: the pulses' emission times
    t = (sweep["time"].values - np.datetime64("1970-01-01")) / np.timedelta64(1, "s")
    np.testing.assert_allclose(t, np.arange(360) / 720.0, atol=1e-9)
    # azimuth clockwise from north, one degree per pulse from 0 (body x north)
    np.testing.assert_allclose(sweep["azimuth"].values, np.arange(360.0), atol=1e-9)
    np.testing.assert_allclose(sweep["elevation"].values, -0.5, atol=1e-9)
    geo = tree.xradar.georeference()
    s = geo["sweep_0"].to_dataset()
    assert {"x", "y", "z"} <= set(s.coords)
    # x east, y north of the radar: the ray at azimuth 90 deg points east
    ray = int(np.argmin(np.abs(s["azimuth"].values - 90.0)))
    assert float(s["x"][ray, -1]) > 3000.0 and abs(float(s["y"][ray, -1])) < 1.0
    # re/im and power agree
    z = sweep["VV_re"].values.astype(float) + 1j * sweep["VV_im"].values
    np.testing.assert_allclose(10 * np.log10(np.maximum(np.abs(z) ** 2, 1e-30)),
                               sweep["VV_power"].values, atol=1e-3)


def _near(sweep, xy):
    az = np.radians(sweep["azimuth"].values)[:, None]
    r = sweep["range"].values[None, :]
    x, y = 100.0 + r * np.sin(az), -200.0 + r * np.cos(az)
    return np.hypot(x - xy[0], y - xy[1]) < 150.0


@pytest.mark.parametrize("name, xy", [("buoy", (1600.0, 1100.0)),
                                      ("boat", (-1400.0, -2200.0))])
def test_target_at_its_bearing_and_range(run, name, xy):
    sweep = seaecho.ppi(run)["sweep_0"].to_dataset()
    p = sweep["HH_power"].values
    i, j = np.unravel_index(np.argmax(np.where(_near(sweep, xy), p, -np.inf)), p.shape)
    dx, dy = xy[0] - 100.0, xy[1] + 200.0
    bearing = np.degrees(np.arctan2(dx, dy)) % 360
    assert float(sweep["azimuth"][i]) == pytest.approx(bearing, abs=1.0)  # one ray
    r = np.sqrt(dx * dx + dy * dy + 28.0**2)
    assert float(sweep["range"][j]) == pytest.approx(r, abs=7.5)  # one gate (c / 2 f_s)
    # far above the rest of its ray (the one-sample pulse's band-limited interpolation
    # leaves sinc range sidelobes that decay as 1 / delay)
    assert p[i, j] > np.median(p[i]) + 30.0


def test_sector_scan_sweeps(tmp_path):
    # sector clockwise from body x (north, bearing 0) to -60 deg counter-clockwise
    # (bearing 60), at 20 rpm = 120 deg/s: a pass every 0.5 s = 360 pulses
    scene = _scene(n_pulses=200, mode="sector", rate_rpm=20.0, start_deg=None,
                   sector_deg=(0.0, -60.0))
    ds = seaecho.simulate(scene, progress=False)
    tree = seaecho.ppi(ds)
    assert list(tree.children) == ["sweep_0"]
    az = tree["sweep_0"]["azimuth"].values
    assert az[0] == pytest.approx(0.0, abs=1e-9) and np.all(np.diff(az) > 0)
    assert az[-1] <= 60.0
    assert str(tree["sweep_0"]["sweep_mode"].values) == "sector"
    pngs = seaecho.figures(ds, tmp_path / "sector")
    assert any(p.name == "sector_ppi_sweep_0.png" for p in pngs)


def test_fixed_antenna_has_no_product():
    d = _scene(n_pulses=2).model_dump(mode="json")
    d["transmitter"]["antenna"]["scan"] = {"mode": "fixed"}
    d["transmitter"]["antenna"]["azimuth_deg"] = 30.0
    ds = seaecho.simulate(parse_scene(d), progress=False)
    assert "sweep" not in ds
    with pytest.raises(SceneError, match="does not scan"):
        seaecho.ppi(ds)


def test_receiver_that_scans_gives_the_sweeps():
    """A bistatic pair whose receiver scans (the transmitter floods): the product's
    azimuths are the receiver's boresight, clockwise from north."""
    d = _scene(n_pulses=4).model_dump(mode="json")
    tx = d["transmitter"]
    d["receiver"] = {"position_m": [300.0, -200.0, 20.0], "yaw_deg": 0.0, "antenna": dict(
        tx["antenna"])}  # body x east: the scan starts looking east
    tx["antenna"]["scan"] = {"mode": "fixed"}
    tx["antenna"]["azimuth_deg"] = 0.0
    ds = seaecho.simulate(parse_scene(d), progress=False)
    az = seaecho.ppi(ds)["sweep_0"]["azimuth"].values
    np.testing.assert_allclose(az, 90.0 + np.arange(4), atol=1e-9)
