"""``seaecho.detect`` / ``seaecho.score`` / the Stone Soup export on datasets: synthetic
runs, images and PPI sweeps with known targets in exponential noise (their P_D and P_FA
against the closed forms of Richards 2014, ch. 7, with exact binomial bounds), and the
calibration scene's run."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from scipy import stats

import seaecho
from seaecho.config import SceneError
from seaecho.constants import C0
from seaecho.detection import CFAR, ObjectTruth
from seaecho.io.detections import sweep_frames

ROOT = Path(__file__).resolve().parents[2]
H_M = 20.0


def synthetic_run(n_pulses=3000, n_range=240, snr_db=(3.0, 10.0, 17.0), seed=3):
    """A monostatic run-like dataset: unit complex Gaussian noise in every cell and
    Swerling 1 targets (complex Gaussian of variance S) in one range cell each, at rest on
    the sea along the boresight (+x)."""
    rng = np.random.default_rng(seed)
    fs = 100e6
    r = 500.0 + np.arange(n_range) * C0 / (2 * fs)
    z = (rng.standard_normal((n_pulses, 1, n_range))
         + 1j * rng.standard_normal((n_pulses, 1, n_range))) / np.sqrt(2)
    cells = 40 + 60 * np.arange(len(snr_db))
    for c, s in zip(cells, snr_db, strict=True):
        amp = np.sqrt(10 ** (s / 10) / 2)
        z[:, 0, c] += amp * (rng.standard_normal(n_pulses) + 1j * rng.standard_normal(n_pulses))
    t = np.arange(n_pulses) * 1e-3
    pos = np.stack([np.sqrt(r[cells] ** 2 - H_M**2), np.zeros(cells.size),
                    np.zeros(cells.size)], -1)
    radar = np.tile([0.0, 0.0, H_M], (n_pulses, 1))
    axes = np.zeros((n_pulses, 3, 3))
    axes[:, :, 0] = [1.0, 0.0, -0.04]
    ds = xr.Dataset(
        {"compressed": (("pulse", "channel", "fast_time"), z),
         "tx_position": (("pulse", "xyz"), radar), "rx_position": (("pulse", "xyz"), radar),
         "rx_antenna_axes": (("pulse", "xyz", "antenna_axis"), axes),
         "tx_antenna_axes": (("pulse", "xyz", "antenna_axis"), axes),
         "target_position": (("target", "xyz"), pos),
         "target_velocity": (("target", "xyz"), np.zeros_like(pos))},
        coords={"pulse": np.arange(n_pulses), "time": ("pulse", t), "channel": ["HH"],
                "range": ("fast_time", r), "target": [f"t{s:g}dB" for s in snr_db]},
        attrs={"waveform_bandwidth_hz": fs})
    return ds, 10 ** (np.asarray(snr_db) / 10)


def _binom_ok(k, n, p, level=1e-6):
    lo, hi = stats.binom.interval(1 - level, n, p)
    return lo <= k <= hi


def test_pd_per_object_and_pfa_per_cell_match_closed_forms(tmp_path):
    ds, snr = synthetic_run()
    pfa = 1e-4
    det, truth = seaecho.detect(ds, cfar="ca", pfa=pfa, train=8, guard=2)
    s = seaecho.score(det, truth)
    cfar = CFAR("ca", 8, 2)
    alpha = cfar.scale(pfa)
    assert det.attrs["alpha"] == pytest.approx(alpha)
    for o, (hit, n, _) in s["pd_object"].items():
        # the gate holds three cells: P_D of the target's cell, plus false alarms of two
        pd = float(cfar.pd_swerling1(alpha, snr[o]))
        p_any = 1 - (1 - pd) * (1 - pfa) ** 2
        assert n == 3000
        assert _binom_ok(hit, n, p_any), (o, hit, n * p_any)
    # the false alarms: one cell each (an isolated crossing) in noise at this P_FA
    fa_cells = round(s["pfa_cell"] * det.attrs["cells_tested"])
    assert _binom_ok(fa_cells, det.attrs["cells_tested"], pfa, level=1e-9)
    assert s["false_alarms_per_look"] == pytest.approx(s["false_alarms"] / 3000)
    # plots on the target: at its range, on the sea along the boresight
    on = det.where(det.object_index == 2, drop=True)
    r_true = float(ds.range[160])
    assert np.all(np.abs(on.range_m - r_true) <= 1.5)
    np.testing.assert_allclose(on.x_m, np.sqrt(on.range_m**2 - H_M**2), rtol=1e-9)
    # the CSV tables give the same scores
    seaecho.api.write_detections(det, truth, tmp_path / "d.csv")
    again = seaecho.score(tmp_path / "d.csv")
    assert again["pd_object"] == s["pd_object"]
    assert again["false_alarms"] == s["false_alarms"]


def test_m_of_n_and_clutter_map_on_profiles():
    ds, snr = synthetic_run(n_pulses=600)
    det, truth = seaecho.detect(ds, cfar="ca", pfa=1e-2, train=8, guard=2, m_of_n=(3, 4))
    s = seaecho.score(det, truth)
    cfar = CFAR("ca", 8, 2)
    p1 = float(cfar.pd_swerling1(cfar.scale(1e-2), snr[2]))
    # a Swerling 2 target (independent pulses) crosses in >= 3 of 4 with the binomial tail
    # (Richards 2014, ch. 6), the two neighbouring cells' false alarms adding little
    from seaecho.detection import theory
    q = float(theory.pfa_m_of_n(p1, 3, 4))
    hit, n, _ = s["pd_object"][2]
    assert n == 597 and abs(hit / n - q) < 0.06
    assert det.attrs["pfa_integrated"] == pytest.approx(
        sum(stats.binom.pmf(j, 4, 1e-2) for j in (3, 4)), rel=1e-9)
    # The clutter map learns each cell's own level: a target that stays in its cell is
    # part of the map, its ratio exponential of mean 1 as noise (Nitzberg 1986), so it is
    # detected at the false-alarm rate; the map's P_FA per cell is the design's
    det, truth = seaecho.detect(ds, cfar="map", pfa=1e-3, map_weight=0.25)
    assert det.attrs["n_looks"] == 600 - 20
    s = seaecho.score(det, truth)
    cm = seaecho.detection.ClutterMap(0.25)
    assert s["pd_object"][2][0] <= 5
    fa_cells = round(s["pfa_cell"] * det.attrs["cells_tested"])
    assert 0.5e-3 < fa_cells / det.attrs["cells_tested"] < 2e-3
    assert float(cm.pfa(det.attrs["alpha"])) == pytest.approx(1e-3, rel=1e-9)


def test_stonesoup_export_reads_back(tmp_path):
    pytest.importorskip("stonesoup")
    ds, _ = synthetic_run(n_pulses=200)
    det, truth = seaecho.detect(ds, pfa=1e-3, train=8, guard=2, stonesoup=tmp_path / "ss")
    dr, tr = seaecho.stonesoup_readers(tmp_path / "ss")
    got = [(t, d) for t, ds_ in dr for d in ds_]
    assert len(got) == det.sizes["detection"]
    times = [t for t, _ in got]
    assert times == sorted(times)
    want = sorted(zip(det.time.values.round(9), det.x_m.values, det.y_m.values,
                      strict=True))
    have = sorted(((t - times[0]).total_seconds() + float(det.time.min()),
                   float(d.state_vector[0, 0]), float(d.state_vector[1, 0]))
                  for t, d in got)
    np.testing.assert_allclose(np.array(have), np.array(want), atol=2e-6)
    assert all(d.measurement_model is not None and d.measurement_model.ndim_state == 4
               for _, d in got)
    paths = set()
    n_states = 0
    for _, ps in tr:
        paths |= ps
    n_states = sum(len(p) for p in paths)
    assert {p.id for p in paths} == set(truth.object.values)
    assert n_states == truth.sizes["opportunity"]


def test_image_2d_detection():
    rng = np.random.default_rng(9)
    ny, nx = 120, 140
    img = (rng.standard_normal((1, ny, nx)) + 1j * rng.standard_normal((1, ny, nx))) / 10
    img[0, 60, 70] = 3.0  # a 9 m^2 point target on 0.01 m^2 of noise
    x = -70.0 + np.arange(nx) * 0.5
    y = -30.0 + np.arange(ny) * 0.5
    ds = xr.Dataset({"image": (("channel", "y", "x"), img),
                     "valid": (("y", "x"), np.ones((ny, nx), np.uint8)),
                     "target_position": (("target", "xyz"), [[x[70], y[60], 0.0]]),
                     "target_velocity": (("target", "xyz"), [[0.0, 0.0, 0.0]])},
                    coords={"channel": ["VV"], "x": x, "y": y, "target": ["buoy"]},
                    attrs={"pixel_m": 0.5, "n_pulses": 10, "prf_hz": 100.0})
    det, truth = seaecho.detect(ds, cfar="os", pfa=1e-5, train=4, guard=2)
    s = seaecho.score(det, truth)
    assert s["pd_object"] == {0: (1, 1, 1.0)}
    on = det.where(det.object_index == 0, drop=True)
    assert float(on.x_m[0]) == pytest.approx(x[70], abs=0.25)
    assert float(on.y_m[0]) == pytest.approx(y[60], abs=0.25)
    assert det.attrs["area_m2"] == pytest.approx(det.attrs["cells_tested"] * 0.25)


def test_ppi_sweeps_target_position_and_wrap():
    rng = np.random.default_rng(10)
    n_az, n_r = 360, 200
    rng_m = 1000.0 + 7.5 * np.arange(n_r)
    az = np.arange(n_az) * 1.0
    target = np.array([1500.0 * np.sin(np.deg2rad(1.0)), 1500.0 * np.cos(np.deg2rad(1.0)),
                       0.0])  # at azimuth 1 degree: its window wraps past north
    r_t = np.hypot(np.hypot(*target[:2]), 15.0)
    power, times = [], []
    for k in range(3):
        p = rng.exponential(1.0, (n_az, n_r))
        i = int(np.argmin(np.abs(rng_m - r_t)))
        p[0:3, i] = 1e4
        power.append(p)
        times.append(k * 2.5 + az / 360 * 2.5)
    truth = ObjectTruth(np.array([0.0, 10.0]), np.stack([target[None]] * 2), ("ship",),
                        np.array([0.0]))
    frames = sweep_frames(power, [az] * 3, times, rng_m, [np.array([0.0, 0.0, 15.0])] * 3,
                          truth=truth)
    assert all(f.extra["circular"] for f in frames)
    from seaecho.detection import detect_frames
    cfar = CFAR("ca", (3, 5), (1, 2), circular=True)
    dets, opps, totals = detect_frames(frames, cfar.noise, cfar.scale(1e-6))
    on = dets["object"] == 0
    assert on.sum() == 3 and opps["look"].size == 3
    np.testing.assert_allclose(dets["azimuth_deg"][on], 1.0, atol=1e-9)
    np.testing.assert_allclose(dets["x_m"][on], target[0], atol=8.0)
    np.testing.assert_allclose(dets["y_m"][on], target[1], atol=8.0)
    assert totals["n_looks"] == 3 and totals["cells_tested"] == 3 * n_az * (n_r - 14)


@pytest.fixture(scope="module")
def calibration_run(tmp_path_factory):
    scene = seaecho.load_scene(ROOT / "scenes" / "calibration_point_target.toml")
    path = tmp_path_factory.mktemp("cal") / "cal.nc"
    seaecho.simulate(scene, path=path, pulses=8)
    return path


def test_calibration_run_sphere_detected_no_false_alarm(calibration_run):
    det, truth = seaecho.detect(calibration_run, pfa=1e-6, train=12, guard=3, channel="VV")
    s = seaecho.score(det, truth)
    names = s["objects"]
    sphere = next(o for o, n in names.items() if n == "sphere10")
    assert s["pd_object"][sphere][:2] == (8, 8)
    assert s["false_alarms"] == 0
    on = det.where(det.object == "sphere10", drop=True)
    # the sphere is at (0, 0, 1): its plot on the sea along the receiver's boresight
    assert np.all(np.hypot(on.x_m, on.y_m) < 6.0)


def test_cli_detect_score_and_bad_input(calibration_run, tmp_path, capsys):
    from seaecho.cli import main

    out = tmp_path / "d.csv"
    assert main(["detect", str(calibration_run), "-o", str(out), "--cfar", "go",
                 "--pfa", "1e-6", "--train", "12", "--guard", "3", "--channel", "HH",
                 "--stonesoup", str(tmp_path / "ss")]) == 0
    assert out.is_file() and (tmp_path / "d_truth.csv").is_file()
    assert (tmp_path / "ss" / "detections.csv").is_file()
    assert main(["score", str(out), "-o", str(tmp_path / "s.json")]) == 0
    assert "sphere10: P_D 1.000 (8/8)" in capsys.readouterr().out
    bad = [
        (["detect", str(tmp_path / "nope.nc")], "does not exist"),
        (["detect", str(calibration_run), "--pfa", "0"], "--pfa"),
        (["detect", str(calibration_run), "--channel", "XY", "-o", str(tmp_path / "e.csv")],
         "channel = 'XY'"),
        (["detect", str(calibration_run), "--train", "0"], "--train"),
        (["detect", str(calibration_run), "-o", str(tmp_path / "no" / "d.csv")],
         "does not exist"),
        (["detect", str(calibration_run), "--cfar", "os", "--rank", "99",
          "-o", str(tmp_path / "e.csv")], "rank = 99"),
        (["detect", str(calibration_run), "--m-of-n", "5", "3",
          "-o", str(tmp_path / "e.csv")], "M = 5"),
        (["score", str(tmp_path / "s.json")], "does not exist"),
        (["score", str(calibration_run), "--truth", str(out)], "not a CSV table"),
        (["score", str(tmp_path / "d_truth.csv"), "--truth", str(tmp_path / "d_truth.csv")],
         "missing column(s) n_cells"),
    ]
    for argv, msg in bad:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert msg in err and "Traceback" not in err, (argv, err)
    assert not (tmp_path / "e.csv").exists()


def test_cfradial2_file_sweeps(tmp_path):
    # The CfRadial 2 layout (xradar's DataTree, sweep_N groups, azimuth x range, azimuth
    # clockwise from north, per-ray time, {channel}_re/_im samples); a radar 15 m up at
    # the scene's origin and a target at azimuth 90 deg (east), 1500 m
    rng = np.random.default_rng(11)
    n_az, n_r = 180, 160
    rng_m = 1000.0 + 7.5 * np.arange(n_r)
    r_t = np.hypot(1500.0, 15.0)
    i = int(np.argmin(np.abs(rng_m - r_t)))
    groups = {}
    for k in range(2):
        re = rng.standard_normal((n_az, n_r)) / np.sqrt(2)
        im = rng.standard_normal((n_az, n_r)) / np.sqrt(2)
        re[44:47, i] = 100.0  # azimuths 88, 90, 92 deg
        az = np.arange(n_az) * 2.0
        groups[f"/sweep_{k}"] = xr.Dataset(
            {"HH_re": (("azimuth", "range"), re.astype(np.float32)),
             "HH_im": (("azimuth", "range"), im.astype(np.float32))},
            coords={"azimuth": ("azimuth", az), "range": ("range", rng_m),
                    "time": ("azimuth", k * 3.0 + az / 360.0 * 3.0)})
    root = xr.Dataset(coords={"altitude": ((), 15.0)})
    tree = xr.DataTree.from_dict({"/": root, **groups})
    path = tmp_path / "ppi.nc"
    tree.to_netcdf(path, engine="h5netcdf")
    truth = ObjectTruth(np.array([0.0]), np.array([[[1500.0, 0.0, 0.0]]]), ("buoy",),
                        np.array([0.0]))
    det, tr = seaecho.detect(path, cfar="ca", pfa=1e-6, train=(3, 5), guard=(1, 2),
                             truth=truth)
    assert det.attrs["kind"] == "ppi" and det.attrs["channel"] == "HH"
    on = det.where(det.object == "buoy", drop=True)
    assert on.sizes["detection"] == 2 and set(on.sweep.values) == {0, 1}
    np.testing.assert_allclose(on.azimuth_deg, 90.0, atol=1e-3)  # float32 samples
    np.testing.assert_allclose(on.x_m, 1500.0, atol=8.0)
    np.testing.assert_allclose(on.y_m, 0.0, atol=0.05)
    assert seaecho.score(det, tr)["pd_object"] == {0: (2, 2, 1.0)}


def test_per_pulse_truth_of_several_objects_is_used():
    # A run with per-pulse truth (truth_position (pulse, object, xyz), an object
    # coordinate and a length per object) in place of its point targets: the objects are
    # those of the truth, gated by half their length plus the range resolution
    ds, _ = synthetic_run(n_pulses=50)
    pos = np.repeat(ds.target_position.values[None], 50, axis=0)
    ds = ds.drop_vars(["target_position", "target_velocity", "target"])
    ds["truth_position"] = (("pulse", "object", "xyz"), pos)
    ds["object_length_m"] = (("object",), np.array([0.0, 0.0, 20.0]))
    ds = ds.assign_coords(object=["a", "b", "ship"])
    truth = seaecho.io.detections.run_truth(ds)
    assert truth.names == ("a", "b", "ship")
    np.testing.assert_array_equal(truth.extent_m, [0.0, 0.0, 20.0])
    det, tr = seaecho.detect(ds, pfa=1e-4, train=8, guard=2)
    assert set(tr.object.values) == {"a", "b", "ship"}
    gate = float(seaecho.io.detections.profile_frames(ds)[0].gate_m[2])
    assert gate == pytest.approx(10.0 + C0 / (2 * 100e6))


def _with_antenna(ds, width_m=1.0, scene_json=None):
    """The synthetic run with a rectangular receive antenna in the product (and a scene's
    propagation, when given)."""
    from seaecho.io.product import antenna_variables
    from seaecho.radar.antennas import Antenna

    lam = 0.03
    ds = ds.assign({k: xr.Variable(*v[:2], v[2] if len(v) > 2 else None) for k, v in
                    antenna_variables("rx", Antenna("rectangular", lam, width_m, 0.2)).items()})
    ds.attrs.update(wavelength_m=lam)
    if scene_json is not None:
        ds.attrs["scene_json"] = scene_json
    return ds, lam


@pytest.mark.parametrize(("earth", "y_m"), [("flat", 0.0), ("spherical", 0.0),
                                            ("spherical", -2000.0)])
def test_profile_false_alarms_per_km2_from_the_pulse_limited_cell(earth, y_m):
    # Each tested gate covers R theta_B dR sec psi (Skolnik 2001, section 7.1), theta_B =
    # 0.8859 lambda / L for a uniform aperture (Balanis 2016, 12.5), sin psi = h / R
    # (flat) or h / R + h^2 / (2 k a R) - R / (2 k a) (4/3 Earth, eq E1), h the
    # height above the sphere (2 km from the tangent point: 0.235 m above the frame's z)
    ds, _ = synthetic_run(n_pulses=60)
    js = '{"propagation": {"earth": "spherical", "earth_radius_factor": 1.3333333333333333}}'
    ds, lam = _with_antenna(ds, 1.0, js if earth == "spherical" else None)
    for v in ("tx_position", "rx_position"):
        ds[v] = ds[v] + np.array([0.0, y_m, 0.0])
    det, truth = seaecho.detect(ds, pfa=1e-2, train=8, guard=2)
    r = ds.range.values
    ka = 4.0 / 3.0 * 6371.0088e3 if earth == "spherical" else np.inf
    h = H_M if y_m == 0.0 else np.hypot(y_m, H_M + ka) - ka
    assert h == pytest.approx(H_M + (0.235 if y_m else 0.0), abs=1e-3)
    # the beam width measured on the pattern (tests/detection/test_footprint.py checks it
    # against 0.8859 lambda / L), so that the height's 1e-5 on sec psi is seen
    from seaecho.detection import half_power_width
    from seaecho.radar.antennas import Antenna

    theta = half_power_width(Antenna("rectangular", lam, 1.0, 0.2).gain_local)
    assert theta == pytest.approx(0.8859 * lam, rel=2e-4)

    def area(rr, dr):
        s = h / rr + (h**2 - rr**2) / (2 * ka * rr)
        return rr * theta * dr / np.sqrt(1.0 - s * s)

    tested = r[10:-10]  # train 8 + guard 2 each side
    want = area(tested, r[1] - r[0]).sum()
    assert det.attrs["area_m2"] == pytest.approx(want, rel=1e-9)
    s = seaecho.score(det, truth)
    n_fa = int((det.object_index.values < 0).sum())
    assert n_fa > 0
    assert s["false_alarms_per_km2"] == pytest.approx(n_fa / 60 / (want * 1e-6), rel=1e-9)
    np.testing.assert_allclose(det.cell_area_m2.values, area(det.range_m.values, C0 / 2e8),
                               rtol=1e-9)
    assert det.attrs["beamwidth_deg"] == pytest.approx(np.rad2deg(theta), rel=1e-12)


def test_profile_area_unknown_without_antenna_or_bistatic():
    ds, _ = synthetic_run(n_pulses=20)
    det, _ = seaecho.detect(ds, pfa=1e-2, train=8, guard=2)
    assert np.isnan(det.attrs["area_m2"])
    ds, _ = _with_antenna(ds)
    ds["rx_position"] = ds.rx_position + np.array([50.0, 0.0, 0.0])
    det, _ = seaecho.detect(ds, pfa=1e-2, train=8, guard=2)
    assert np.isnan(det.attrs["area_m2"])


def _image(power_rng, ny=60, nx=80, x0=-20.0, target=None):
    z = (power_rng.standard_normal((1, ny, nx)) + 1j * power_rng.standard_normal((1, ny, nx))
         ) / np.sqrt(2)
    x = x0 + np.arange(nx) * 0.5
    y = -15.0 + np.arange(ny) * 0.5
    data = {"image": (("channel", "y", "x"), z),
            "valid": (("y", "x"), np.ones((ny, nx), np.uint8))}
    coords = {"channel": ["VV"], "x": x, "y": y}
    if target is not None:
        j, i = target
        z[0, j, i] = 30.0  # 29.5 dB over the unit noise
        data["target_position"] = (("target", "xyz"), [[x[i], y[j], 0.0]])
        data["target_velocity"] = (("target", "xyz"), [[0.0, 0.0, 0.0]])
        coords["target"] = ["buoy"]
    return xr.Dataset(data, coords=coords, attrs={"pixel_m": 0.5, "n_pulses": 10,
                                                  "prf_hz": 100.0})


def test_clutter_map_on_a_stack_of_images_matches_nitzberg():
    # 21 images of one grid, map weight 1/4 (warm-up 20): the last image is tested
    # against the map of the 20 before it; exponential pixels, P_FA of Nitzberg (1986)
    # within exact binomial bounds (one test per pixel: independent trials)
    from seaecho.detection import theory

    rng = np.random.default_rng(21)
    stack = [_image(rng) for _ in range(20)] + [_image(rng, target=(30, 40))]
    pfa = 1e-2
    det, truth = seaecho.detect(stack, cfar="map", pfa=pfa, map_weight=0.25)
    a = det.attrs
    assert a["n_looks"] == 1 and a["cells_tested"] == 60 * 80
    assert float(theory.pfa_clutter_map(a["alpha"], 0.25)) == pytest.approx(pfa, rel=1e-9)
    s = seaecho.score(det, truth)
    assert s["pd_object"] == {0: (1, 1, 1.0)}
    fa_cells = int(det.n_cells.values[det.object_index.values < 0].sum())
    assert _binom_ok(fa_cells, 60 * 80 - 9, pfa), fa_cells
    assert set(det.look.values) == {20}


def test_clutter_map_refuses_one_image_and_mixed_grids():
    rng = np.random.default_rng(22)
    with pytest.raises(SceneError, match="single SAR image has no past"):
        seaecho.detect(_image(rng), cfar="map")
    with pytest.raises(SceneError, match="same cells in every image"):
        seaecho.detect([_image(rng), _image(rng, x0=0.0)], cfar="map")
    with pytest.raises(SceneError, match="more than 40 images"):
        seaecho.detect([_image(rng), _image(rng)], cfar="map")


def test_cli_detect_on_a_stack_of_images(tmp_path, capsys):
    from seaecho.cli import main

    rng = np.random.default_rng(23)
    paths = []
    for k in range(6):  # weight 1: warm-up 5, the sixth image tested
        paths.append(str(tmp_path / f"img{k}.nc"))
        seaecho.save(_image(rng, ny=30, nx=40), paths[-1])
    out = tmp_path / "d.csv"
    assert main(["detect", *paths, "--cfar", "map", "--map-weight", "1", "--pfa", "0.01",
                 "-o", str(out)]) == 0
    rows, header = seaecho.io.detections.read_table(out)
    assert header["n_looks"] == "1" and header["cells_tested"] == str(30 * 40)
    assert main(["detect", *paths[:2], "--cfar", "map", "-o", str(tmp_path / "e.csv")]) == 2
    err = capsys.readouterr().err
    assert "more than 40 images" in err and "Traceback" not in err
    assert not (tmp_path / "e.csv").exists()


def test_hidden_objects_scored_apart_on_range_profiles_and_in_the_roc():
    # the truth hides the 17 dB target in the second half of the pulses (as behind a
    # crest): those looks are no misses of P_D, nor of the ROC; the same rule as sweeps
    ds, _ = synthetic_run(n_pulses=400)
    pos = np.asarray(ds.target_position.values)
    ds["truth_position"] = (("pulse", "object", "xyz"), np.tile(pos, (400, 1, 1)))
    visible = np.ones((400, 3), np.int8)
    visible[200:, 2] = 0
    ds["truth_visible"] = (("pulse", "object"), visible)
    ds = ds.assign_coords(object=list(ds.target.values))
    det, tr = seaecho.detect(ds, cfar="ca", pfa=1e-4, train=8, guard=2)
    hidden = tr.visible.values == 0
    assert hidden.sum() == 200 and (tr.object_index.values[hidden] == 2).all()
    s = seaecho.score(det, tr)
    assert s["pd_object"][2][1] == 200 and s["hidden_object"][2][1] == 200
    assert s["pd_object"][0][1] == 400
    # the ROC: the hidden looks are left out of P_D (its peaks still listed)
    curve = seaecho.roc(ds, CFAR("ca", 8, 2))
    assert curve["n_opportunities"] == 1000 and curve["n_hidden"] == 200
    assert curve["opportunity_visible"].sum() == 1000
    peaks = curve["opportunity_peak"][curve["opportunity_visible"]]
    t = curve["threshold"][len(curve["threshold"]) // 2]
    k = int(np.searchsorted(curve["threshold"], t))
    assert curve["pd"][k] == pytest.approx((peaks > curve["threshold"][k]).mean())


def test_hidden_object_of_a_given_truth_on_an_image():
    img = _image(np.random.default_rng(7), target=(30, 40))
    own, t_mid = seaecho.io.detections.image_truth(img)
    hidden = ObjectTruth(own.time_s, own.position_m, own.names, own.extent_m,
                         visible=np.zeros((1, 1), bool))
    det, tr = seaecho.detect(img, cfar="ca", pfa=1e-4, train=6, guard=2, truth=hidden)
    assert tr.visible.values.tolist() == [0]
    s = seaecho.score(det, tr)
    assert s["pd_object"] == {} and s["hidden_object"] == {0: (1, 1)}
    assert seaecho.roc(img, CFAR("ca", (6, 6), (2, 2)), truth=hidden)["n_hidden"] == 1
