"""Land blanking of PPI sweeps (the chart's polygons, a margin from the shore) and the
scoring of objects the truth hides: geometry against hand-computed distances, and
synthetic scanning runs with a strong land echo in exponential noise."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaecho
from seaecho.api import write_detections
from seaecho.config import SceneError
from seaecho.detection import score_tables
from seaecho.detection.landmask import land_mask
from seaecho.io.detections import run_land_outlines, run_truth

SQUARE = np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]])


def test_cells_inside_outside_and_the_margin():
    cells = np.array([[50.0, 50.0],     # inside
                      [105.0, 50.0],    # 5 m east of the east edge
                      [105.0, 105.0],   # sqrt(50) = 7.07 m from the north-east corner
                      [50.0, -20.0],    # 20 m south of the south edge
                      [np.nan, 0.0]])   # no ground point: never land
    np.testing.assert_array_equal(land_mask(cells, [SQUARE]),
                                  [True, False, False, False, False])
    np.testing.assert_array_equal(land_mask(cells, [SQUARE], 5.1),
                                  [True, True, False, False, False])
    np.testing.assert_array_equal(land_mask(cells, [SQUARE], 7.0),
                                  [True, True, False, False, False])
    np.testing.assert_array_equal(land_mask(cells, [SQUARE], 7.1),
                                  [True, True, True, False, False])
    np.testing.assert_array_equal(land_mask(cells, [SQUARE], 20.0),
                                  [True, True, True, True, False])
    # a concave outline (an L): the notch is sea; two polygons: either; none: no mask
    ell = np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 40.0], [40.0, 40.0], [40.0, 100.0],
                    [0.0, 100.0]])
    grid = np.array([[[70.0, 70.0], [20.0, 70.0]], [[70.0, 20.0], [300.0, 300.0]]])
    np.testing.assert_array_equal(land_mask(grid, [ell]), [[False, True], [True, False]])
    far = SQUARE + 250.0
    np.testing.assert_array_equal(land_mask(grid, [ell, far]), [[False, True], [True, True]])
    assert not land_mask(grid, []).any() and land_mask(grid, []).shape == (2, 2)
    # the margin along every edge, the closing one (last vertex to first) included
    ring = np.array([[50.0, -3.0], [103.0, 50.0], [50.0, 103.0], [-3.0, 50.0]])
    np.testing.assert_array_equal(land_mask(ring, [SQUARE], 3.5), [True] * 4)
    with pytest.raises(ValueError, match="margin"):
        land_mask(cells, [SQUARE], -1.0)


def scanning_run(land=True, hidden_sweep=None, seed=5):
    """Two sweeps of 180 rays x 120 gates (7.5 m) of unit exponential noise from a radar
    15 m up at the origin; a spiky land echo over its polygon (north-east, 900
    to 1200 m out, azimuth 31 to 59 deg) and a 1e4 x noise buoy due south at 1000 m."""
    rng = np.random.default_rng(seed)
    n_ray, n_r, n_sw = 180, 120, 2
    n = n_ray * n_sw
    r = 500.0 + 7.5 * np.arange(n_r)
    az = np.tile(np.arange(n_ray) * 2.0, n_sw)
    ground = np.sqrt(r ** 2 - 15.0 ** 2)
    x = ground[None] * np.sin(np.deg2rad(az))[:, None]
    y = ground[None] * np.cos(np.deg2rad(az))[:, None]
    a = np.deg2rad(np.array([31.0, 59.0]))  # between rays: no cell on an edge
    outline = np.array([[900 * np.sin(a[0]), 900 * np.cos(a[0])],
                        [1200 * np.sin(a[0]), 1200 * np.cos(a[0])],
                        [1200 * np.sin(a[1]), 1200 * np.cos(a[1])],
                        [900 * np.sin(a[1]), 900 * np.cos(a[1])]])
    on_land = land_mask(np.stack([x, y], -1), [outline])
    # the land: spiky (Weibull power of shape 0.3, mean ~ 900 x the noise), as terrain
    p = rng.exponential(1.0, (n, n_r)) + 1e2 * rng.weibull(0.3, (n, n_r)) * on_land
    buoy = np.array([0.0, -1000.0, 0.0])
    i = int(np.argmin(np.abs(ground - 1000.0)))
    p[np.abs(az - 180.0) < 1.0, i] += 1e4
    axes = np.zeros((n, 3, 3))
    axes[:, 0, 0], axes[:, 1, 0] = np.sin(np.deg2rad(az)), np.cos(np.deg2rad(az))
    radar = np.tile([0.0, 0.0, 15.0], (n, 1))
    visible = np.ones((n, 1), np.int8)
    if hidden_sweep is not None:
        visible[hidden_sweep * n_ray:(hidden_sweep + 1) * n_ray] = 0
    ds = xr.Dataset(
        {"compressed": (("pulse", "channel", "fast_time"), np.sqrt(p)[:, None, :]),
         "tx_position": (("pulse", "xyz"), radar), "rx_position": (("pulse", "xyz"), radar),
         "tx_antenna_axes": (("pulse", "xyz", "antenna_axis"), axes),
         "truth_position": (("pulse", "object", "xyz"), np.tile(buoy, (n, 1, 1))),
         "truth_visible": (("pulse", "object"), visible)},
        coords={"pulse": np.arange(n), "time": ("pulse", np.arange(n) * 2.5 / n_ray),
                "sweep": ("pulse", np.repeat(np.arange(n_sw), n_ray)), "channel": ["HH"],
                "range": ("fast_time", r), "object": ["buoy"]},
        attrs={"waveform_bandwidth_hz": 20e6})
    if land:
        ds["land_outline"] = (("land_vertex", "xy"), outline)
        ds["land_outline_land"] = (("land_vertex",), np.zeros(4, np.int16))
    return ds, int(on_land.sum())


def _detect(ds, **kw):
    # the mask and the censoring alone: these synthetic runs record no antenna, whose
    # echo's spread test_land_spread.py blanks
    kw.setdefault("land_spread_db", None)
    return seaecho.detect(ds, cfar="ca", pfa=1e-6, train=(3, 6), guard=(1, 2), **kw)


def test_ppi_land_blanked_by_default_and_on_request_off():
    ds, n_land = scanning_run()
    assert len(run_land_outlines(ds)) == 1
    det, tr = _detect(ds)
    fa = det.object_index.values < 0
    # no plot on the land; the buoy in both sweeps; the noise's own false alarms only
    assert det.attrs["land_mask"] == 1 and det.attrs["cells_blanked"] == n_land
    assert fa.sum() <= 2
    assert (det.object.values == "buoy").sum() == 2
    off, _ = _detect(ds, land_mask=False)
    assert off.attrs["land_mask"] == 0 and off.attrs["cells_blanked"] == 0
    on_land = (np.hypot(off.x_m, off.y_m) > 880) & (off.azimuth_deg > 25) & \
        (off.azimuth_deg < 65)
    assert int(on_land.sum()) >= 2  # the land's echo: plots without the mask
    # land censoring (on with the mask) leaves untested the few cells whose window keeps
    # less than half its sea cells; without it every sea cell is tested
    assert det.attrs["land_censor"] == 1 and det.attrs["cells_short"] > 0
    assert off.attrs["cells_tested"] == det.attrs["cells_tested"] + n_land + \
        det.attrs["cells_short"]
    kept, _ = _detect(ds, land_censor=False)
    assert kept.attrs["land_censor"] == 0 and kept.attrs["cells_short"] == 0
    assert off.attrs["cells_tested"] == kept.attrs["cells_tested"] + n_land
    # a margin blanks more cells; the buoy, far from the land, stays
    wide, _ = _detect(ds, land_margin_m=60.0)
    assert wide.attrs["cells_blanked"] > n_land
    assert (wide.object.values == "buoy").sum() == 2


def _boat_beside_the_land(ds, power=300.0):
    """Add a boat 25 dB over the noise on the 44 deg ray, five gates short of the land
    (gate 49; the land starts at gate 54 there), to both sweeps and to the truth."""
    r = np.asarray(ds["range"].values)
    ground = np.sqrt(r[49] ** 2 - 15.0 ** 2)
    boat = np.array([ground * np.sin(np.deg2rad(44.0)), ground * np.cos(np.deg2rad(44.0)),
                     0.0])
    ray = np.asarray(ds.tx_antenna_axes.values[:, :, 0])
    on = np.abs(np.rad2deg(np.arctan2(ray[:, 0], ray[:, 1])) - 44.0) < 0.5
    z = ds["compressed"].values.copy()
    z[on, 0, 49] = np.sqrt(power)
    pos = np.concatenate([ds.truth_position.values,
                          np.tile(boat, (ds.sizes["pulse"], 1, 1))], axis=1)
    vis = np.concatenate([ds.truth_visible.values, np.ones((ds.sizes["pulse"], 1), np.int8)],
                         axis=1)
    ds = ds.drop_vars(["truth_position", "truth_visible", "object"])
    ds["compressed"] = (("pulse", "channel", "fast_time"), z)
    ds["truth_position"] = (("pulse", "object", "xyz"), pos)
    ds["truth_visible"] = (("pulse", "object"), vis)
    return ds.assign_coords(object=["buoy", "boat"])


def test_boat_beside_the_land_found_with_land_censoring_masked_without():
    # the boat's training window (9 rays x 17 gates less the guard: N = 138) holds 36
    # land cells, ~900 x the noise on average: in the window they lift a CA-CFAR's
    # threshold far above the boat (masking); left out (the 102 sea cells averaged, alpha
    # for 102 cells) the boat is found in both sweeps
    ds = _boat_beside_the_land(scanning_run()[0])
    det, tr = _detect(ds)
    assert det.attrs["land_censor"] == 1 and det.attrs["cells_censored"] > 0
    assert (det.object.values == "boat").sum() == 2
    s = seaecho.score(det, tr)
    assert s["pd_object"][1] == (2, 2, 1.0)
    plain, tr0 = _detect(ds, land_censor=False)
    assert (plain.object.values == "boat").sum() == 0
    assert seaecho.score(plain, tr0)["pd_object"][1] == (0, 2, 0.0)
    # the censored estimate is the sea's: the false alarms stay those of the noise
    assert (det.object_index.values < 0).sum() <= 2


def test_no_land_no_mask_and_bad_options():
    ds, _ = scanning_run(land=False)
    det, _ = _detect(ds)
    assert det.attrs["land_mask"] == 0 and det.attrs["cells_blanked"] == 0
    with pytest.raises(SceneError, match="land_mask = true"):
        _detect(ds, land_mask=True)
    with pytest.raises(SceneError, match="land_margin_m"):
        _detect(scanning_run()[0], land_margin_m=-5.0)
    # land censoring needs the land mask and a sliding window; its fraction in (0, 1]
    with pytest.raises(SceneError, match="land_censor = true"):
        _detect(ds, land_censor=True)
    with pytest.raises(SceneError, match="land_censor = true"):
        _detect(scanning_run()[0], land_censor=True, land_mask=False)
    with pytest.raises(SceneError, match="land_censor = 'yes'"):
        _detect(ds, land_censor="yes")
    land = scanning_run()[0]
    for bad in (0.0, 1.5, float("nan"), True):
        with pytest.raises(SceneError, match="censor_min_fraction"):
            _detect(land, censor_min_fraction=bad)


def test_hidden_object_scored_apart_and_left_out_of_the_stonesoup_truth(tmp_path):
    # the truth hides the buoy in sweep 1 (as behind a headland): that sweep is no miss
    ds, _ = scanning_run(hidden_sweep=1)
    truth = run_truth(ds)
    assert truth.visible.shape == (360, 1) and not truth.visible[200, 0]
    ds["compressed"][180:, 0, :] = np.sqrt(np.random.default_rng(1).exponential(
        1.0, (180, 120)))  # nothing of the buoy in sweep 1
    det, tr = _detect(ds, stonesoup=tmp_path / "ss")
    np.testing.assert_array_equal(tr.visible.values, [1, 0])
    s = seaecho.score(det, tr)
    assert s["pd_object"] == {0: (1, 1, 1.0)} and s["hidden_object"] == {0: (0, 1)}
    rows = (tmp_path / "ss" / "truth.csv").read_text().splitlines()
    assert len(rows) == 2  # a header and the visible sweep
    # the CSV tables round-trip the visibility
    paths = write_detections(det, tr, tmp_path / "d.csv")
    assert seaecho.score(paths[0], paths[1])["hidden_object"] == {0: (0, 1)}


def test_score_tables_hidden_opportunities():
    s = score_tables([0, 1], [0, 0], [1, 1], [0, 1, 2, 0], [0, 0, 0, 1],
                     [10.0, 10.0, 10.0, 10.0], n_looks=3, cells_tested=100, area_m2=np.nan,
                     opp_visible=[1, 1, 0, 0])
    assert s["pd_object"] == {0: (2, 2, 1.0)} and s["pd"] == 1.0
    assert s["hidden_object"] == {0: (0, 1), 1: (0, 1)}
    everything = score_tables([0, 1], [0, 0], [1, 1], [0, 1, 2, 0], [0, 0, 0, 1],
                              [10.0] * 4, n_looks=3, cells_tested=100, area_m2=np.nan)
    assert everything["pd_object"][0] == (2, 3, pytest.approx(2 / 3))
    assert everything["hidden_object"] == {}


def test_cli_land_mask_options_and_hidden_in_the_score(tmp_path, capsys):
    from seaecho.cli import main

    ds, n_land = scanning_run(hidden_sweep=1)
    run = tmp_path / "scan.nc"
    ds.to_netcdf(run, engine="h5netcdf")
    out = tmp_path / "d.csv"
    assert main(["detect", str(run), "-o", str(out), "--train", "3", "6", "--guard", "1",
                 "2", "--no-land-spread"]) == 0
    printed = capsys.readouterr().out
    assert f"{n_land} on the land blanked" in printed and "land censored" in printed
    assert main(["score", str(out)]) == 0
    assert "buoy: hidden by the truth in 1 look(s), not scored" in capsys.readouterr().out
    assert main(["detect", str(run), "-o", str(out), "--train", "3", "6", "--guard", "1",
                 "2", "--no-land-mask"]) == 0
    assert "blanked" not in capsys.readouterr().out
    assert main(["detect", str(run), "--land-margin", "-3", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--land-margin -3" in err and "Traceback" not in err
    assert main(["detect", str(run), "-o", str(out), "--train", "3", "6", "--guard", "1",
                 "2", "--no-land-censor", "--no-land-spread"]) == 0
    assert "land censored" not in capsys.readouterr().out
    assert main(["detect", str(run), "--censor-min-fraction", "0", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--censor-min-fraction 0" in err and "Traceback" not in err
