"""Plot extraction, association and geolocation on analytically known cases."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.detection import (
    CFAR,
    associate,
    extract_plots,
    ground_point,
    half_path,
    pd_at_pfa,
    roc,
    score_tables,
)


def test_two_blobs_centroid_extent_peak():
    power = np.ones((2, 10, 12))
    mask = np.zeros_like(power, bool)
    power[0, 2:4, 3] = [4.0, 2.0]  # blob A: two cells along axis 1
    mask[0, 2:4, 3] = True
    power[0, 7, 8:11] = [1.0, 3.0, 1.0]  # blob B, diagonal-free, along range
    mask[0, 7, 8:11] = True
    power[1, 2, 3] = 5.0  # same place, next sweep: a separate plot
    mask[1, 2, 3] = True
    noise = np.full(power.shape, 0.5)
    p = extract_plots(power, mask, noise, ndim=2)
    assert p["n_cells"].tolist() == [2, 3, 1]
    np.testing.assert_allclose(p["centroid"][0], [0, (2 * 4 + 3 * 2) / 6, 3])
    np.testing.assert_allclose(p["centroid"][1], [0, 7, 9])
    assert p["peak_index"].tolist() == [[0, 2, 3], [0, 7, 9], [1, 2, 3]]
    assert p["first"][1].tolist() == [0, 7, 8] and p["last"][1].tolist() == [0, 7, 10]
    np.testing.assert_allclose(p["snr"], [7.0, 5.0, 9.0])
    # 1-D: cells join along the last axis only
    q = extract_plots(power, mask, noise, ndim=1)
    assert q["n_cells"].tolist() == [1, 1, 3, 1]


def test_no_detection():
    p = extract_plots(np.ones((3, 4)), np.zeros((3, 4), bool), np.ones((3, 4)))
    assert p["centroid"].shape == (0, 2) and p["snr"].size == 0


def test_associate_nearest_within_gate():
    t = np.array([0.0, 1.0])
    truth = np.array([[[0.0, 0.0], [100.0, 0.0]], [[10.0, 0.0], [100.0, 10.0]]])
    det_t = np.array([0.5, 0.5, 0.5, 1.0])
    det_p = np.array([[5.0, 1.0], [100.0, 5.0], [50.0, 0.0], [100.0, 13.0]])
    obj = associate(det_t, det_p, t, truth, gate=[2.0, 4.0])
    assert obj.tolist() == [0, 1, -1, 1]


def test_ground_point_monostatic_and_bistatic_round_trip():
    tx = np.array([[0.0, 0.0, 30.0]] * 3)
    u = np.array([[1.0, 0.0], [0.0, 1.0], [np.sqrt(0.5), np.sqrt(0.5)]])
    r = np.array([100.0, 500.0, 50.0])
    p = ground_point(tx, tx, u, r)
    np.testing.assert_allclose(np.linalg.norm(p[:, :2], axis=1), np.sqrt(r**2 - 900.0))
    rx = np.array([[200.0, 100.0, 80.0]] * 3)
    tx = np.array([[-500.0, 0.0, 300.0]] * 3)
    u = np.array([[-1.0, 0.0], [0.0, -1.0], [-0.6, -0.8]])
    r = np.array([650.0, 700.0, 900.0])
    p = ground_point(tx, rx, u, r)
    np.testing.assert_allclose(half_path(p, tx, rx), r, rtol=1e-12)
    assert np.all(p[:, 2] == 0.0)
    # the calibration scene's receiver: its boresight ray meets the path's ellipse twice;
    # the 3-D boresight picks the point it looks at (the origin), the 2-D azimuth the
    # nearer one
    tx1, rx1 = np.array([[-500.0, 0.0, 300.0]]), np.array([[200.0, 100.0, 80.0]])
    r0 = half_path(np.zeros(3), tx1[0], rx1[0])
    np.testing.assert_allclose(ground_point(tx1, rx1, -rx1, [r0])[0], 0.0, atol=1e-8)
    near = ground_point(tx1, rx1, -rx1[:, :2], [r0])[0]
    assert np.hypot(*(near[:2] - rx1[0, :2])) < np.hypot(*rx1[0, :2])
    assert half_path(near, tx1[0], rx1[0]) == pytest.approx(r0, rel=1e-12)
    # inside the direct path: no point
    assert np.isnan(ground_point(tx[:1], rx[:1], u[:1], [300.0])).all()


def test_roc_at_design_threshold_matches_closed_form():
    cfar = CFAR("ca", train=8, guard=2)
    rng = np.random.default_rng(41)
    power = rng.exponential(1.0, (2000, 105))
    groups = -np.ones(power.shape, np.int64)
    cols = np.arange(10, 95, 21)
    snr = 20.0
    power[:, cols] = rng.exponential(1.0 + snr, (2000, cols.size))
    groups[:, cols] = np.arange(2000 * cols.size).reshape(2000, cols.size)
    # the background from 2000 rows of noise alone (a target raises its neighbours' noise
    # estimates): the rows with targets count only for P_D
    power = np.concatenate([power, rng.exponential(1.0, (2000, 105))])
    groups = np.concatenate([np.where(groups < 0, -2, groups), -np.ones((2000, 105), int)])
    alpha = cfar.scale(1e-3)
    curve = roc(cfar, power, groups, 2000 * cols.size, thresholds=[alpha])
    assert curve["pfa"][0] == pytest.approx(1e-3, rel=0.2)
    assert curve["pd"][0] == pytest.approx(float(cfar.pd_swerling1(alpha, snr)), abs=0.015)
    full = roc(cfar, power, groups, 2000 * cols.size)
    assert np.all(np.diff(full["pfa"]) <= 0) and np.all(np.diff(full["pd"]) <= 0)
    assert pd_at_pfa(full, 1e-3) == pytest.approx(float(cfar.pd_swerling1(alpha, snr)),
                                                  abs=0.03)


def test_score_tables_counts():
    s = score_tables(det_look=[0, 0, 1, 2], det_object=[0, -1, 0, -1], det_cells=[2, 3, 1, 1],
                     opp_look=[0, 1, 2, 0, 1, 2], opp_object=[0, 0, 0, 1, 1, 1],
                     opp_snr=[100, 100, 100, 1, 1, 1], n_looks=3, cells_tested=400,
                     area_m2=2e6)
    assert s["pd_object"] == {0: (2, 3, pytest.approx(2 / 3)), 1: (0, 3, 0.0)}
    assert s["false_alarms"] == 2
    assert s["false_alarms_per_look"] == pytest.approx(2 / 3)
    assert s["false_alarms_per_km2"] == pytest.approx(2 / 3 / 2.0)
    assert s["pfa_cell"] == pytest.approx(4 / 400)
    assert [r[2:4] for r in s["pd_snr"]] == [(0, 3), (2, 3)]
