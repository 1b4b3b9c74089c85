"""The land of ``[[land]]``: it hides the sea and the targets behind it and echoes with
the constant-gamma model through the radar equation.

References: Barton, Proc. IEEE 73(2) (1985) (sigma0 = gamma sin psi); the radar equation
eq R2 of seaecho.radar.equation (Skolnik 2008, eq 23.1); Billingsley (2002), chapter 2
(unit-mean Weibull powers).
"""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest
from scipy import stats

from seaecho.build import build_engine, build_sea
from seaecho.checks.preflight import check_run
from seaecho.config import SceneError, parse_scene
from seaecho.constants import C0
from seaecho.io.truth_tracks import truth_rows
from seaecho.radar.equation import bistatic_received_power
from seaecho.simulation import Simulation

HEADLAND = {"name": "headland", "outline_m": [[-100, -1300], [100, -1300], [100, -1100],
                                              [-100, -1100]],
            "height_m": 40.0, "shore_width_m": 20.0, "resolution_m": 5.0,
            "terrain": "farmland"}


def _scene(land, targets=(), sea_clutter=False, tx=(0.0, -2000.0, 25.0), **radar):
    return {
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 2, "sea_clutter": sea_clutter,
                  "transmit_power_w": 25e3, "channels": ["HH"], "thermal_noise": False,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}, **radar},
        "transmitter": {"position_m": tx, "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "targets": list(targets), "land": list(land)}


def test_target_behind_the_headland_is_silent_and_in_front_heard():
    targets = [{"name": "behind", "position_m": (0.0, 0.0, 2.0), "rcs_m2": 10.0},
               {"name": "front", "position_m": (300.0, -1500.0, 2.0), "rcs_m2": 10.0}]
    # a field 5 m high behind the headland: its facets face the radar but are hidden
    field = dict(HEADLAND, name="field", outline_m=[[-50, -900], [50, -900], [50, -700],
                                                    [-50, -700]], height_m=5.0)
    sim = Simulation(parse_scene(_scene([dict(HEADLAND, echo=False), field], targets)))
    geo = sim.radar.geometry(0)
    assert sim.land.n_facets > 1000 and not sim.land.rcs(geo.tx.position,
                                                         geo.tx.position).any()
    alone = Simulation(parse_scene(_scene([field], targets))).land
    # without the headland it is seen (but for its far shore, which faces away)
    assert (alone.rcs(geo.tx.position, geo.tx.position) > 0).mean() > 0.8
    hidden = sim.targets_hidden([0, 1])
    assert hidden[0].tolist() == [[True, False], [True, False]]  # behind the land
    assert not hidden[1].any()  # no wave crest in between
    echo = sim.radar.target_echo(sim.radar.geometry(0), hidden=hidden[0, 0])
    assert echo.r_t == pytest.approx([math.dist((300, -1500, 2), (0, -2000, 25))])
    assert np.array_equal(sim.pulse(0), sim.radar.receive(0, [echo]))  # the front one
    ds = sim.static_dataset()
    assert ds["truth_hidden_reason"].values.tolist() == [[3, 0], [3, 0]]  # behind_land
    assert ds["truth_visible"].values.tolist() == [[0, 1], [0, 1]]
    assert [r[-1] for r in truth_rows(ds)] == ["behind_land", "visible"] * 2  # the CSV
    # the 40 m plateau is not seen from 25 m: its facets are silent (eq L5's V_f)
    lan = Simulation(parse_scene(_scene([HEADLAND], targets))).land
    tx = sim.radar.geometry(0).tx.position
    top = np.isclose(lan.centroid[:, 2], 40.0)
    sigma = lan.rcs(tx, tx)
    assert top.sum() > 100 and not sigma[top].any() and sigma[~top].any()
    # without the land both are heard
    free = Simulation(parse_scene(_scene([], targets)))
    assert free.radar.target_echo(free.radar.geometry(0)).tau.size == 2


def test_flat_land_patch_echo_is_the_radar_equation_of_gamma_sin_psi():
    # a plateau 1 m high, 3 km of flat land seen from 60 m: each facet's echo power is
    # eq R2 with sigma_f = gamma sin(psi_f) A_f w_f (constant gamma, Barton 1985)
    land = dict(HEADLAND, outline_m=[[-400, -1000], [400, -1000], [400, 1000], [-400, 1000]],
                height_m=1.0, shore_width_m=0.0, resolution_m=10.0, terrain="flatland",
                weibull_shape=1.5)
    sim = Simulation(parse_scene(_scene([land], tx=(0.0, -2000.0, 60.0))))
    geo = sim.radar.geometry(0)
    lan = sim.land
    tx = geo.tx.position
    gamma = 10 ** (-20 / 10)  # flatland at 10 GHz
    sigma = lan.rcs(tx, tx)
    top = np.isclose(lan.centroid[:, 2], 1.0) & (sigma > 0)
    r = np.linalg.norm(lan.centroid - tx, axis=-1)
    sin_psi = (tx[2] - lan.centroid[:, 2]) / r  # a horizontal facet, flat Earth
    assert top.sum() > 10_000
    np.testing.assert_allclose(sigma[top], (gamma * sin_psi * lan.area * lan.power)[top],
                               rtol=1e-12)
    echo = lan.echo(geo)
    seen = sigma > 0
    p = np.abs(echo.amplitudes[0]) ** 2
    expect = bistatic_received_power(25e3, echo.g_t, echo.g_r, C0 / 10e9,
                                     sigma[seen], echo.r_t, echo.r_r)
    np.testing.assert_allclose(p, expect, rtol=1e-9)
    # the land's mean power: eq R2 with <sigma_f> = gamma sin(psi) A_f (E[w] = 1); the
    # draw's mean is within 4 standard errors (Var w = Gamma(4) / Gamma(2.5)^2 - 1)
    mean = bistatic_received_power(25e3, echo.g_t, echo.g_r, C0 / 10e9,
                                   (sigma / lan.power)[seen], echo.r_t, echo.r_r)
    var = math.gamma(4.0) / math.gamma(2.5) ** 2 - 1.0
    n_eff = mean.sum() ** 2 / (mean ** 2).sum()
    assert p.sum() / mean.sum() == pytest.approx(1.0, abs=4 * math.sqrt(var / n_eff))
    # the facets' powers follow Billingsley's Weibull law of the scene's a_w = 1.5, eq L4:
    # P(w > x) = exp(-(x / b)^(1 / a_w)), b = 1 / Gamma(1 + a_w); not the exponential
    b = 1.0 / math.gamma(2.5)
    assert stats.kstest(lan.power, lambda x: 1.0 - np.exp(-(np.maximum(x, 0) / b)
                                                          ** (1 / 1.5))).pvalue > 1e-3
    assert stats.kstest(lan.power, "expon").pvalue < 1e-6
    # and that echo is the pulse's: no sea, no target, no noise
    raw = sim.pulse(0)
    assert np.array_equal(raw, sim.radar.receive(0, [echo]))


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_the_headland_hides_the_sea_behind_it():
    # a cliff 30 m high whose shore is 2 m left of the radar's line to the tile's centre:
    # the lines of sight from the facets left of x = -20 m pass over it lower than 12 m
    land = dict(HEADLAND, outline_m=[[-200, -400], [-2, -400], [-2, -300], [-200, -300]],
                height_m=30.0, shore_width_m=0.0)
    scene = parse_scene(_scene([land], sea_clutter=True, tx=(0.0, -600.0, 20.0)))
    surface = build_sea(scene).state
    f1 = build_engine(scene, surface).facets(0.0)  # the land among the occluders
    f0 = build_engine(scene.model_copy(update={"land": ()}), surface).facets(0.0)
    x = f1.centroid[:, 0]
    assert f0.visibility[x < -20].mean() > 0.3  # seen without the land
    assert not f1.visibility[x < -20].any()  # behind the headland: none seen
    right = x > 5
    assert np.array_equal(f1.visibility[right], f0.visibility[right])


def test_land_keys_are_checked():
    base = _scene([HEADLAND])
    for change, match in [
        ({"gamma_db": -10.0}, "either terrain or gamma_db"),
        ({"terrain": None}, "either terrain or gamma_db"),
        ({"outline_m": [[0, 0], [1, 1], [2, 2]]}, "no area"),
        ({"weibull_shape": 0.5}, "weibull_shape"),
    ]:
        bad = copy.deepcopy(base)
        bad["land"][0].update(change)
        if bad["land"][0].get("terrain", "") is None:
            bad["land"][0].pop("terrain")
        with pytest.raises(SceneError, match=match):
            parse_scene(bad)
    twice = copy.deepcopy(base)
    twice["land"].append(dict(HEADLAND))
    with pytest.raises(SceneError, match="names must be unique"):
        parse_scene(twice)
    analytic = copy.deepcopy(base)
    analytic["tracing"] = {"mode": "analytic"}
    with pytest.raises(SceneError, match="mode = 'raytraced'"):
        parse_scene(analytic)


def test_check_refuses_an_antenna_under_the_ground_and_a_huge_grid():
    under = _scene([dict(HEADLAND, outline_m=[[-100, -2100], [100, -2100], [100, -1900],
                                              [-100, -1900]])])
    with pytest.raises(SceneError, match=r"\[transmitter\].position_m: .* below the ground"):
        check_run(parse_scene(under), "scene.toml", figures=False)
    huge = _scene([dict(HEADLAND, resolution_m=0.5, outline_m=[[0, 0], [5000, 0],
                                                                [5000, 5000]])])
    with pytest.raises(SceneError, match="grid cells; at most"):
        check_run(parse_scene(huge), "scene.toml", figures=False)
    check_run(parse_scene(_scene([HEADLAND])), "scene.toml", figures=False)


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_a_target_in_the_waves_is_hidden_by_the_crests_and_its_truth_says_so():
    # on the tile, a target 1 m below the mean sea is under the surface for the radar's
    # line of sight (hidden by the waves); one 20 m up is seen; one off the tile's
    # ground track is not traced against the waves
    targets = [{"name": "sunk", "position_m": (0.0, 0.0, -1.0), "rcs_m2": 1.0},
               {"name": "high", "position_m": (5.0, 0.0, 20.0), "rcs_m2": 1.0},
               {"name": "off", "position_m": (500.0, -1500.0, 1.0), "rcs_m2": 1.0}]
    sim = Simulation(parse_scene(_scene([], targets, sea_clutter=True,
                                        tx=(0.0, -600.0, 20.0))))
    hidden = sim.targets_hidden([0, 1])
    assert not hidden[0].any()  # no land
    assert hidden[1].tolist() == [[True, False, False]] * 2
    truth = sim.truth_hidden()
    assert truth[1].tolist() == [[True, False, False]] * 2


@pytest.mark.slow
def test_land_patches_outside_the_beam_are_skipped_within_the_stated_bound():
    # a rotating 2 m Taylor (-30 dB) fan beam over a field 1 km north: the patches a
    # pulse skips return, computed anyway, at most the floor g_f times their power at
    # both beams' peaks (eq C3 of docs/scanning.md, applied to each patch)
    field = dict(HEADLAND, name="field", outline_m=[[-300, -1100], [300, -1100],
                                                    [300, -900], [-300, -900]],
                 height_m=2.0, resolution_m=10.0)
    scene = _scene([field], tx=(0.0, -2000.0, 35.0), n_pulses=2500)
    scene["transmitter"]["antenna"] = {
        "pattern": "rectangular", "width_m": 2.0, "height_m": 0.12,
        "illumination": "taylor", "taylor_sidelobe_db": 30.0, "taylor_nbar": 4,
        "depression_deg": 0.5, "scan": {"mode": "rotating", "rate_rpm": 24.0}}
    sim = Simulation(parse_scene(scene))
    floor = 1e-6  # the default -60 dB
    g_peak = sim.radar.tx_antenna.peak_gain ** 2
    assert sim.land_patches(0).any()  # the beam on the field
    checked = 0
    # the beam leaving the field (0.144 deg per pulse) on either side, and far from it
    for p in [*range(20, 200, 12), *range(2300, 2490, 12), 625, 1250, 1875]:
        keep = sim.land_patches(p)
        if keep.all():
            continue
        e = sim.land.echo(sim.radar.geometry(p), ~keep)  # the skipped patches, computed
        got = np.sum(np.abs(e.amplitudes[0]) ** 2)
        at_peak = np.sum(np.abs(e.amplitudes[0]) ** 2 * g_peak / (e.g_t * e.g_r))
        assert got <= floor * at_peak
        checked += got > 1e-3 * floor * at_peak  # within 30 dB of the bound
    assert checked > 10


def test_land_gamma_at_the_carrier_or_as_given():
    # gamma of the terrain at the carrier, eq L3: farmland -15 dB at 10 GHz (Nathanson,
    # Reilly & Cohen 1999, as restated by MATLAB's surfacegamma) + 5 log10(f / 10 GHz)
    # (Barton 1985's f^(1/2)): -17.61 dB at 3 GHz; a scene's gamma_db replaces the table
    from seaecho.build import build_land

    def gamma_db(land, f_hz):
        scene = parse_scene(_scene([land], carrier_frequency_hz=f_hz))
        return 10.0 * math.log10(build_land(scene).pieces[0].gamma)

    assert gamma_db(HEADLAND, 3e9) == pytest.approx(-15.0 - 2.6144, abs=1e-4)
    assert gamma_db(HEADLAND, 10e9) == pytest.approx(-15.0, abs=1e-12)
    given = {k: v for k, v in HEADLAND.items() if k != "terrain"}
    assert gamma_db({**given, "gamma_db": -7.0}, 3e9) == pytest.approx(-7.0, abs=1e-12)


def test_bistatic_land_echo_is_gamma_times_the_geometric_mean_and_shadowed_for_both():
    # transmitter south, receiver east: a facet's RCS is eq L5 with eq L2's geometric
    # mean gamma sqrt(sin psi_i sin psi_s) A_f w_f (the bistatic constant-gamma law,
    # Willis 2005, section 9.2), not the transmitter's gamma sin psi_i; a wall (not
    # echoing) between the receiver and part of the field hides that part from the
    # receiver only, and the land echoes on HH and VV alike, nothing cross-polarised
    field = dict(HEADLAND, name="field", outline_m=[[-400, -1000], [400, -1000], [400, 0],
                                                    [-400, 0]],
                 height_m=1.0, shore_width_m=0.0, resolution_m=20.0, terrain="flatland")
    wall = dict(HEADLAND, name="wall", outline_m=[[700, -560], [760, -560], [760, -440],
                                                  [700, -440]], echo=False)
    scene = _scene([field, wall], tx=(0.0, -2000.0, 60.0),
                   channels=["HH", "HV", "VH", "VV"])
    scene["receiver"] = {"position_m": (2000.0, -500.0, 30.0),
                         "antenna": {"pattern": "isotropic", "look_at_m": (0, -500, 0)}}
    sim = Simulation(parse_scene(scene))
    geo = sim.radar.geometry(0)
    lan = sim.land
    tx, rx = geo.tx.position, geo.rx.position
    c = lan.centroid
    sigma = lan.rcs(tx, rx)
    top = np.isclose(c[:, 2], 1.0)  # horizontal facets: sin psi = height / range
    sin_i = (tx[2] - c[:, 2]) / np.linalg.norm(c - tx, axis=-1)
    sin_s = (rx[2] - c[:, 2]) / np.linalg.norm(c - rx, axis=-1)
    gamma = 10 ** (-20 / 10)  # flatland at 10 GHz
    # the receiver's shadow of the 40 m wall from 30 m: the field behind it, the wall's
    # edges seen from the receiver (y = -500 +- 60 m at x = 700..760) fanned out to x = 400
    bearing = (c[:, 1] - rx[1]) / (rx[0] - c[:, 0])
    behind = top & (np.abs(bearing) < 60.0 / 1300.0 - 0.01)
    clear = top & (np.abs(bearing) > 60.0 / 1240.0 + 0.01)
    assert behind.sum() > 300 and clear.sum() > 2500
    assert not sigma[behind].any()
    assert (sigma[clear] > 0).all()
    np.testing.assert_allclose(sigma[clear], (gamma * np.sqrt(sin_i * sin_s) * lan.area
                                              * lan.power)[clear], rtol=1e-12)
    # the transmitter's gamma sin psi_i alone would be sqrt(sin psi_i / sin psi_s) times
    # eq L2: 1.3 to 2.1 times here
    assert np.abs(np.sqrt(sin_i / sin_s)[clear] - 1).min() > 0.25
    a = np.asarray(lan.echo(geo).amplitudes)  # (HH, HV, VH, VV) per lit facet
    np.testing.assert_allclose(a[3], a[0], rtol=1e-12)
    assert np.abs(a[1:3]).max() < 1e-12 * np.abs(a[0]).min()
    # the facets' phases are uniform over [0, 2 pi) (module docstring): Kolmogorov-Smirnov
    assert stats.kstest(lan.phase, stats.uniform(0.0, 2.0 * np.pi).cdf).pvalue > 1e-3


def test_land_below_the_radio_horizon_is_silent():
    # a slope rising 30 m over 200 m, facing a 25 m antenna 30 km away on the 4/3 Earth:
    # a facet at height h is above the horizon when its distance is below
    # sqrt(2 k a) (sqrt(25 m) + sqrt(h)) (the 4/3-Earth radar horizon, Skolnik 2001, ch. 8;
    # the "radio horizon range" of Federal Standard 1037C: 2.23 NM (sqrt(h_t) + sqrt(h_r)),
    # heights in m, i.e. 4.12 km), i.e. h > 5 m at 30 km. On a
    # flat Earth the whole slope is lit.
    from seaecho.build import build_land
    from seaecho.geometry.earth import effective_radius, horizon_range
    from seaecho.geometry.land import land_mesh
    from seaecho.tracing.land import LandEchoes

    hill = dict(HEADLAND, name="hill", outline_m=[[-1000, 30000], [1000, 30000],
                                                  [1000, 30600], [-1000, 30600]],
                height_m=30.0, shore_width_m=200.0, resolution_m=20.0)
    scene = _scene([hill], tx=(0.0, 0.0, 25.0))
    v, f, _ = land_mesh(hill["outline_m"], 30.0, 200.0, 20.0)
    mid = v[f].mean(axis=1)  # the facets in the scene's (Earth-following) coordinates
    # the seaward slope, away from the sides (there the nearest shore is the side's)
    slope = (mid[:, 1] < 30190.0) & (np.abs(mid[:, 0]) < 700.0)
    d = np.hypot(mid[:, 0], mid[:, 1])
    assert d[slope].min() > 30000.0
    d_h = horizon_range(25.0, mid[:, 2], effective_radius(4.0 / 3.0))
    assert float(horizon_range(25.0, 5.0, effective_radius(4.0 / 3.0))) == pytest.approx(
        4.12e3 * (5.0 + math.sqrt(5.0)), rel=2e-3)
    below, above = slope & (d > 1.05 * d_h), slope & (d < 0.95 * d_h)
    assert below.sum() >= 20 and above.sum() >= 20
    for earth in ("spherical", "flat"):
        s = parse_scene({**scene, "propagation": {"earth": earth}})
        model = build_land(s)
        lan = LandEchoes(model, None, 0)
        tx = np.array([0.0, 0.0, 25.0])
        if model.earth is not None:
            tx = model.earth.position(tx)
        sigma = lan.rcs(tx, tx)
        assert (sigma[above] > 0).all()
        if earth == "spherical":
            assert not sigma[below].any()
        else:
            assert (sigma[below] > 0).all()  # the Earth hides them, not the land
