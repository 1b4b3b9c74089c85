"""The land's echo spread blanked with the land (docs/detection.md, "Land blanking"):
the extent of the two-way beam and of the compressed pulse at a level against closed
forms, the dilation of the mask on the polar grid, and a boat beyond the spread."""

from __future__ import annotations

import numpy as np
import pytest
from test_landmask import scanning_run

import seaecho
from seaecho.api import LAND_SPREAD_DB
from seaecho.config import SceneError
from seaecho.constants import C0
from seaecho.detection.footprint import compressed_extent, half_power_width, level_extent
from seaecho.detection.landmask import spread, spread_bins
from seaecho.io.detections import land_spread
from seaecho.io.product import antenna_variables
from seaecho.radar.antennas import Antenna

LOG2_DB = 20.0 * np.log10(2.0)  # 6.02 dB


def _gaussian(theta3_rad):
    # one-way Gaussian beam of half-power width theta3: G = exp(-4 ln 2 a^2 / theta3^2)
    # (a Gaussian main lobe, the usual approximation of a pencil beam; Skolnik 2001, ch. 9)
    return lambda d: np.exp(-4.0 * np.log(2.0) * np.arctan2(d[..., 1], d[..., 0]) ** 2
                            / theta3_rad ** 2)


def test_gaussian_two_way_level_extent_closed_form():
    # two-way G^2 = exp(-8 ln 2 a^2 / theta3^2) is -X dB at a = (theta3 / 2) sqrt(X / 6.02)
    th = np.deg2rad(1.0)
    g = _gaussian(th)
    for x_db in (3.0, 6.02, 20.0, 40.0):
        got = level_extent(lambda d: g(d) ** 2, x_db)
        assert got == pytest.approx(0.5 * th * np.sqrt(x_db / LOG2_DB), rel=1e-9)
    # X = 6.02 dB two-way is the one-way half-power point
    assert 2 * level_extent(lambda d: g(d) ** 2, LOG2_DB) == pytest.approx(
        half_power_width(g), rel=1e-9)
    assert level_extent(lambda d: np.ones(d.shape[:-1]), 40.0) == np.pi  # never below
    with pytest.raises(ValueError, match="level_db"):
        level_extent(g, 0.0)


def test_uniform_aperture_extent_reaches_past_the_first_null():
    # the project's rectangular aperture (eq A1, uniform: sinc(a u / lambda) with the
    # obliquity factor): its first two-way sidelobe is -26.5 dB (2 x 13.26 dB), so at
    # 20 dB the extent stays inside the first null sin a = lambda / a; at 30 dB it lies
    # in the first sidelobe, between the first and second nulls (lambda / a, 2 lambda / a)
    lam, width = 0.032, 2.0
    ant = Antenna("rectangular", lam, width, 0.12)
    two_way = lambda d: ant.gain_local(d) ** 2  # noqa: E731
    null1, null2 = np.arcsin(lam / width), np.arcsin(2 * lam / width)
    e20 = level_extent(two_way, 20.0)
    assert half_power_width(ant.gain_local) / 2 < e20 < null1
    e30 = level_extent(two_way, 30.0)
    assert null1 < e30 < null2


def test_compressed_pulse_extent():
    # a single-sample pulse: y(u) = sinc(u), |y|^2 = -X dB first crossing of the main
    # lobe; beyond, the sidelobes 1/(pi u)^2 in power: the outermost u with
    # sinc^2 >= 10^(-X/10) lies within half a sample of 10^(X/20) / pi
    one = np.ones(1)
    for x_db in (30.0, 40.0):
        u = compressed_extent(one, one, x_db, oversample=16)
        assert abs(u - 10 ** (x_db / 20) / np.pi) <= 1.0  # within a lobe of it
    # a two-sample rectangle: a = (1, 2, 1), y(u) = sinc(u + 1) + 2 sinc(u) + sinc(u - 1)
    # = -2 sin(pi u) / (pi u (u^2 - 1)), peak 2: its tails' envelope 1 / (pi |u|^3)
    # crosses 10^(-X/20) near u = (10^(X/20) / pi)^(1/3)
    two = np.ones(2)
    for x_db in (50.0, 60.0):
        u = compressed_extent(two, two, x_db, oversample=16)
        assert abs(u - (10 ** (x_db / 20) / np.pi) ** (1 / 3)) <= 1.0
    # the main lobe alone at a small level: c / (2 B) is one sample for this pulse
    assert compressed_extent(two, two, 3.0) < 1.0


def test_spread_bins_and_the_dilation():
    assert spread_bins(1.155, 0.288) == 4 and spread_bins(20.6, 7.5) == 3
    assert spread_bins(3.0, 7.5) == 0 and spread_bins(3.75, 7.5) == 1
    m = np.zeros((12, 10), bool)
    m[0, 4] = True  # land on the first ray
    out = spread(m, 2, 1, circular=True)
    rows, cols = np.nonzero(out)
    assert set(rows) == {10, 11, 0, 1, 2} and set(cols) == {3, 4, 5}  # wraps in azimuth
    assert out.sum() == 15
    flat = spread(m, 2, 1, circular=False)
    assert set(np.nonzero(flat)[0]) == {0, 1, 2} and flat.sum() == 9  # stops at ray 0
    assert spread(m, 6, 0, circular=True)[:, 4].all()  # the whole ring
    np.testing.assert_array_equal(spread(m, 0, 0), m)


def _with_antenna(ds, width_m=0.6, weighting_samples=2):
    """The synthetic scanning run with a uniform 0.6 m aperture at 10 GHz (one-way
    half-power width 0.886 lambda / L = 2.5 deg) and a plain pulse of 2 samples."""
    ant = Antenna("rectangular", 0.03, width_m, 0.12)
    ds = ds.assign(antenna_variables("tx", ant))
    ds["transmitted_pulse"] = (("pulse_sample",), np.ones(weighting_samples, complex))
    ds.attrs.update(wavelength_m=0.03, sampling_rate_hz=20e6)
    return ds


def test_run_spread_from_its_antenna_and_pulse():
    ds = _with_antenna(scanning_run()[0])
    az, rg = land_spread(ds, 20.0)
    ant = Antenna("rectangular", 0.03, 0.6, 0.12)
    assert az == pytest.approx(level_extent(lambda d: ant.gain_local(d) ** 2, 20.0))
    gate = C0 / (2 * 20e6)
    assert rg == pytest.approx(gate * compressed_extent(np.ones(2), np.ones(2), 20.0))
    assert gate <= rg < 2 * gate  # past the main lobe's c / (2 B), one gate
    det, _ = seaecho.detect(ds, cfar="ca", pfa=1e-6, train=(3, 6), guard=(1, 2),
                            land_spread_db=20.0)
    a = det.attrs
    assert a["land_spread_db"] == 20.0
    assert a["land_spread_rays"] == spread_bins(np.rad2deg(az), 2.0)
    assert a["land_spread_gates"] == spread_bins(rg, 7.5)
    none, _ = seaecho.detect(ds, cfar="ca", pfa=1e-6, train=(3, 6), guard=(1, 2),
                             land_spread_db=None)
    assert none.attrs["land_spread_db"] == 0.0 and none.attrs["land_spread_rays"] == 0
    # the spread adds the dilated cells: each sweep's mask grown by rays x gates
    from seaecho.api import _detection_frames, _land_blanking

    frames, kind, _ = _detection_frames(ds, None, None, None, None)
    _land_blanking(ds, kind, frames, None, 0.0, None)
    grown = sum(int(spread(np.broadcast_to(f.blanked, f.power.shape),
                           a["land_spread_rays"], a["land_spread_gates"], True).sum())
                for f in frames)
    assert a["cells_blanked"] == grown > none.attrs["cells_blanked"]


def _boat(ds, gate=45, power=300.0):
    """A boat 25 dB over the noise on the 44 deg ray at ``gate``, in both sweeps and the
    truth: the land (its outline's chord at 900 cos 14 deg = 873 m ground) starts at gate
    50 on that ray, so gate 45 is five gates short of it."""
    r = np.asarray(ds["range"].values)
    ground = np.sqrt(r[gate] ** 2 - 15.0 ** 2)
    boat = np.array([ground * np.sin(np.deg2rad(44.0)), ground * np.cos(np.deg2rad(44.0)),
                     0.0])
    ray = np.asarray(ds.tx_antenna_axes.values[:, :, 0])
    on = np.abs(np.rad2deg(np.arctan2(ray[:, 0], ray[:, 1])) - 44.0) < 0.5
    z = ds["compressed"].values.copy()
    z[on, 0, gate] = np.sqrt(power)
    pos = np.concatenate([ds.truth_position.values,
                          np.tile(boat, (ds.sizes["pulse"], 1, 1))], axis=1)
    vis = np.ones(pos.shape[:2], np.int8)
    ds = ds.drop_vars(["truth_position", "truth_visible", "object"])
    ds["compressed"] = (("pulse", "channel", "fast_time"), z)
    ds["truth_position"] = (("pulse", "object", "xyz"), pos)
    ds["truth_visible"] = (("pulse", "object"), vis)
    return ds.assign_coords(object=["buoy", "boat"])


def test_boat_beyond_the_spread_still_detected():
    # the boat five gates short of the land on the 44 deg ray; the spread at 20 dB is
    # spread_bins(rg, 7.5) = 2 gates: the boat's cell is tested and found in both sweeps
    ds = _with_antenna(_boat(scanning_run()[0]))
    first = np.flatnonzero(np.asarray(ds["compressed"].values[22, 0, 46:]) ** 2 > 50)[0]
    assert 46 + first >= 50  # nothing strong between the boat and the land
    det, tr = seaecho.detect(ds, cfar="ca", pfa=1e-6, train=(3, 6), guard=(1, 2),
                             land_spread_db=20.0)
    assert det.attrs["land_spread_gates"] < 5
    assert (det.object.values == "boat").sum() == 2
    # a spread that reaches it (a long pulse: 12 samples, main lobe 12 gates) blanks it
    long = _with_antenna(_boat(scanning_run()[0]), weighting_samples=12)
    det2, tr2 = seaecho.detect(long, cfar="ca", pfa=1e-6, train=(3, 6), guard=(1, 2),
                               land_spread_db=20.0)
    assert det2.attrs["land_spread_gates"] >= 5
    assert (det2.object.values == "boat").sum() == 0


def test_bad_land_spread_values(tmp_path, capsys):
    ds = _with_antenna(scanning_run()[0])
    for bad in (0.0, float("nan"), True, "beam"):
        with pytest.raises(SceneError, match="land_spread_db"):
            seaecho.detect(ds, train=(3, 6), guard=(1, 2), land_spread_db=bad)
    # no antenna in the dataset: the default refuses and names the way out
    with pytest.raises(SceneError, match=f"land_spread_db = {LAND_SPREAD_DB:g}.*no-land-spread"):
        seaecho.detect(scanning_run()[0], train=(3, 6), guard=(1, 2))
    from seaecho.cli import main

    run = tmp_path / "scan.nc"
    ds.to_netcdf(run, engine="h5netcdf")
    out = tmp_path / "d.csv"
    assert main(["detect", str(run), "-o", str(out), "--land-spread-db", "0"]) == 2
    err = capsys.readouterr().err
    assert "--land-spread-db 0" in err and "Traceback" not in err
    assert main(["detect", str(run), "-o", str(out), "--train", "3", "6", "--guard", "1",
                 "2", "--land-spread-db", "20"]) == 0
    assert "its echo's spread at -20 dB" in capsys.readouterr().out
    # (--no-land-spread: test_landmask.py's command lines)
