"""A scanning radar's plots for Stone Soup: the PPI's azimuth (clockwise from north) against
Stone Soup's bearing (counter-clockwise from east, atan2(y, x) of
``CartesianToBearingRange``), the bearing-range model centred on the radar round-tripping
known targets, and one plot per sweep per target in the export of a synthetic scanning
run (unit complex Gaussian noise, two moving targets)."""

from __future__ import annotations

from datetime import datetime

import numpy as np
import pytest
import xarray as xr

import seaecho
from seaecho.config import SceneError
from seaecho.io.detections import bearing_from_azimuth

RADAR = np.array([100.0, -200.0, 15.0])
SCAN_S = 2.5
N_AZ, N_R, N_SWEEPS = 180, 160, 4
GATE_M = 7.5
TARGETS = {"north-east": ([RADAR[0] + 1500 * np.sin(np.deg2rad(30.0)),
                           RADAR[1] + 1500 * np.cos(np.deg2rad(30.0)), 0.0], [4.0, 0.0, 0.0]),
           "south-west": ([RADAR[0] - 900.0, RADAR[1] - 700.0, 0.0], [0.0, 6.0, 0.0])}


def _wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


def test_bearing_is_ninety_degrees_minus_azimuth():
    az = np.array([0.0, 30.0, 90.0, 180.0, 270.0, 359.0])
    want = np.deg2rad([90.0, 60.0, 0.0, -90.0, -180.0, 91.0])
    np.testing.assert_allclose(bearing_from_azimuth(az), want, atol=1e-12)


def scanning_run(seed=4):
    """A run-like dataset of a radar turning clockwise from north (2 deg rays, one turn
    per 2.5 s) with two targets moving at 4 and 6 m/s, 40 dB over the noise in the rays
    within 2 deg of their azimuth and their range gate."""
    rng = np.random.default_rng(seed)
    n = N_AZ * N_SWEEPS
    t = np.arange(n) * SCAN_S / N_AZ
    az = np.deg2rad((np.arange(n) % N_AZ) * 360.0 / N_AZ)
    r = 1000.0 + GATE_M * np.arange(N_R)
    z = (rng.standard_normal((n, 1, N_R)) + 1j * rng.standard_normal((n, 1, N_R))) / np.sqrt(2)
    p0 = np.array([v[0] for v in TARGETS.values()])
    v = np.array([v[1] for v in TARGETS.values()])
    for k in range(p0.shape[0]):
        where = p0[k] + t[:, None] * v[k] - RADAR
        az_t = np.arctan2(where[:, 0], where[:, 1])
        off = np.abs((az - az_t + np.pi) % (2 * np.pi) - np.pi)
        gate = np.rint((np.hypot(np.hypot(where[:, 0], where[:, 1]), RADAR[2]) - r[0])
                       / GATE_M).astype(int)
        rays = np.flatnonzero(off <= np.deg2rad(2.0) + 1e-9)
        z[rays, 0, gate[rays]] += 100.0
    axes = np.zeros((n, 3, 3))
    axes[:, 0, 0], axes[:, 1, 0] = np.sin(az), np.cos(az)
    pos = np.tile(RADAR, (n, 1))
    return xr.Dataset(
        {"compressed": (("pulse", "channel", "fast_time"), z),
         "sweep": (("pulse",), np.arange(n) // N_AZ),
         "tx_position": (("pulse", "xyz"), pos), "rx_position": (("pulse", "xyz"), pos),
         "tx_antenna_axes": (("pulse", "xyz", "antenna_axis"), axes),
         "rx_antenna_axes": (("pulse", "xyz", "antenna_axis"), axes),
         "target_position": (("target", "xyz"), p0),
         "target_velocity": (("target", "xyz"), v)},
        coords={"pulse": np.arange(n), "time": ("pulse", t), "channel": ["HH"],
                "range": ("fast_time", r), "target": list(TARGETS)},
        attrs={"waveform_bandwidth_hz": 20e6})


@pytest.fixture(scope="module")
def export(tmp_path_factory):
    d = tmp_path_factory.mktemp("ss")
    det, truth = seaecho.detect(scanning_run(), cfar="ca", pfa=1e-6, train=(3, 5),
                                guard=(2, 2), stonesoup=d)
    return det, truth, d


def test_scanning_export_has_one_plot_per_sweep_per_target(export):
    det, truth, d = export
    assert det.attrs["kind"] == "ppi" and det.attrs["n_looks"] == N_SWEEPS
    for name in TARGETS:
        on = det.where(det.object == name, drop=True)
        assert sorted(on.sweep.values.tolist()) == list(range(N_SWEEPS)), name
        tr = truth.where(truth.object == name, drop=True)
        assert sorted(tr.look.values.tolist()) == list(range(N_SWEEPS)), name
    rows, _ = seaecho.io.detections.read_table(d / "detections.csv")
    assert {"bearing_rad", "ground_range_m", "radar_x_m", "radar_y_m"} <= set(rows)
    assert np.all(np.diff(rows["time"]) >= 0)
    np.testing.assert_allclose(rows["radar_x_m"], RADAR[0])
    np.testing.assert_allclose(rows["radar_y_m"], RADAR[1])
    # the model's noise: a resolution cell's spread, c / (2 B) / sqrt(12) in range and the
    # azimuth gate (three 2 deg rays: no antenna in this dataset) / sqrt(12) in bearing
    s = seaecho.io.detections.json.loads((d / "stonesoup.json").read_text())
    assert s["measurement"] == "bearing-range"
    np.testing.assert_allclose(s["bearing_range_noise"],
                               [np.deg2rad(6.0) / np.sqrt(12), GATE_M / np.sqrt(12)])


def test_bearing_range_model_round_trips_the_targets(export):
    pytest.importorskip("stonesoup")
    from stonesoup.models.measurement.nonlinear import CartesianToBearingRange
    from stonesoup.types.state import State

    det, _, d = export
    reader, truths = seaecho.stonesoup_readers(d)
    got = [x for _, ds in reader for x in ds]
    assert len(got) == det.sizes["detection"]
    n_on = 0
    for x in got:
        m = x.measurement_model
        assert isinstance(m, CartesianToBearingRange) and m.ndim_state == 4
        np.testing.assert_allclose(np.ravel(m.translation_offset), RADAR[:2])
        # the plot back to x, y: the detection table's position
        back = m.inverse_function(x)
        assert float(back[0, 0]) == pytest.approx(float(x.metadata["x"]), abs=1e-6)
        assert float(back[2, 0]) == pytest.approx(float(x.metadata["y"]), abs=1e-6)
        name = x.metadata["object"]
        if name not in TARGETS:
            continue
        n_on += 1
        # a target's true state at the plot's time through the model: its bearing and
        # ground range within half a ray (1 deg) and half a gate of the plot
        p0, v = (np.array(a) for a in TARGETS[name])
        ts = (x.timestamp - datetime(1970, 1, 1)).total_seconds()
        where = p0 + ts * v
        h = m.function(State(np.array([[where[0]], [v[0]], [where[1]], [v[1]]])))
        az = np.arctan2(where[0] - RADAR[0], where[1] - RADAR[1])  # clockwise from north
        assert _wrap(float(h[0, 0]) - (np.pi / 2 - az)) == pytest.approx(0.0, abs=1e-12)
        assert _wrap(float(x.state_vector[0, 0]) - float(h[0, 0])) == pytest.approx(
            0.0, abs=np.deg2rad(1.0))
        assert float(x.state_vector[1, 0]) == pytest.approx(float(h[1, 0]), abs=GATE_M)
    assert n_on == 2 * N_SWEEPS
    paths = set()
    for _, ps in truths:
        paths |= ps
    assert {p.id for p in paths} == set(TARGETS)
    assert all(len(p) == N_SWEEPS for p in paths)


def test_cartesian_model_on_request_and_bearing_range_refused_for_profiles(export, tmp_path):
    pytest.importorskip("stonesoup")
    from stonesoup.models.measurement.linear import LinearGaussian

    _, _, d = export
    reader, _ = seaecho.stonesoup_readers(d, measurement="cartesian")
    assert all(isinstance(x.measurement_model, LinearGaussian) for _, ds in reader for x in ds)
    with pytest.raises(SceneError, match="measurement = 'polar'"):
        seaecho.stonesoup_readers(d, measurement="polar")
    ds = scanning_run().drop_vars("sweep")  # range profiles
    seaecho.detect(ds.isel(pulse=slice(0, 40)), pfa=1e-3, train=8, guard=2,
                   stonesoup=tmp_path / "p")
    with pytest.raises(SceneError, match="PPI sweeps only"):
        seaecho.stonesoup_readers(tmp_path / "p", measurement="bearing-range")
