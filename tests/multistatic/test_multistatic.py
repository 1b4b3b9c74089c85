"""Several receivers of one transmitter (``[[receivers]]``, docs/multistatic.md).

Each receiver of a multistatic run is the bistatic run of that receiver alone, bit for bit
(same seed, its receive window); a point target lands at each receiver's bistatic range
with the power of the bistatic radar equation; the dataset streams and resumes as a
bistatic run's; a scene with ``[receiver]`` keeps the bistatic layout.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seaecho.build import receiver_scene
from seaecho.config import SceneError, parse_scene
from seaecho.constants import C0
from seaecho.geometry.bistatic import bistatic_angle
from seaecho.multistatic import (
    MultistaticSimulation,
    receiver_dataset,
    simulation_of,
)
from seaecho.processing.range_compression import range_compress

ANT = {"pattern": "rectangular", "width_m": 0.18, "height_m": 0.14, "look_at_m": (0, 0, 0)}
ISO = {"pattern": "isotropic", "look_at_m": (0, 0, 0)}
RECEIVERS = [
    {"name": "near", "position_m": (-50.75, 0.0, 87.91), "antenna": ANT},
    {"name": "north", "position_m": (30.0, 40.0, 60.0), "antenna": ANT,
     "channels": ["HH", "VV"]},
    {"name": "south", "position_m": (0.0, -150.0, 4.0), "antenna": ANT},  # 1.5 deg grazing
]


def _scene(receivers=RECEIVERS, sea=True, tracing=None, n_pulses=4, targets=None,
           seed=3, tx=None, ship=False, **radar):
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6, "prf_hz": 1e3,
         "n_pulses": n_pulses, "sea_clutter": sea, "transmit_power_w": 10.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": 100e6, "duration_s": 1e-6}}
    r.update(radar)
    d = {"sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": 3.0, "size_x_m": 8.0,
                 "nx": 32},
         "run": {"seed": seed},
         # held, as sea_motion "auto" resolves with [[receivers]]: the one-receiver
         # scenes compared with them hold their sea too
         "scattering": {"sea_motion": "held"},
         "tracing": tracing or {"mode": "raytraced"},
         "radar": r,
         # 3 deg grazing at the centre: the waves hide facets from the transmitter
         "transmitter": tx or {"position_m": (-200.0, 0.0, 10.0), "antenna": ANT,
                               "motion": "linear", "velocity_m_s": (0.0, 100.0, 0.0)},
         "targets": targets if targets is not None else
         [{"position_m": (1.0, 2.0, 0.5), "rcs_m2": 3.0}]}
    if ship:  # its turbulent wake's film damps the Bragg waves of each pair's k_B
        d["ship"] = {"length_m": 4.0, "beam_m": 1.5, "draft_m": 0.5, "speed_kn": 6.0,
                     "heading_deg": 30.0, "position_m": (1.0, 0.5)}
    if isinstance(receivers, dict):
        d["receiver"] = receivers
    else:
        d["receivers"] = receivers
    return parse_scene(d)


def _alone(sc, ds, i):
    """Receiver i's bistatic scene with the window the multistatic run gave it."""
    one = receiver_scene(sc, i)
    radar = one.radar.model_copy(update={"window_start_m": float(ds.window_start_m[i]),
                                         "window_end_m": float(ds.window_end_m[i])})
    return one.model_copy(update={"radar": radar})


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
@pytest.mark.parametrize("tracing", [
    {"mode": "raytraced"},                              # the fused kernel, traced per pulse
    {"mode": "raytraced", "refresh_interval_s": 2e-3},  # occlusion held over 2 pulses
    {"mode": "analytic"},                               # the reference path
])
def test_each_receiver_is_its_bistatic_run_bit_for_bit(tracing):
    # One sea, one set of sub-facet draws, the transmitter's leg traced once: receiver
    # i's raw and compressed samples and NRCS map equal the run of receiver i alone.
    sc = _scene(tracing=tracing, ship=True)
    sim = simulation_of(sc)
    assert isinstance(sim, MultistaticSimulation)
    ds = sim.dataset(progress=False)
    assert ds.raw.dims == ("pulse", "receiver", "channel", "sample")
    assert list(ds.receiver.values) == ["near", "north", "south"]
    for i in range(3):
        one = simulation_of(_alone(sc, ds, i)).dataset(progress=False)
        mine = ds.isel(receiver=i).sel(channel=one.channel.values)
        for name in ("raw", "compressed"):
            assert np.array_equal(mine[name].values, one[name].values), (i, name)
        np.testing.assert_array_equal(mine.sigma0.values, one.sigma0.values)
        np.testing.assert_array_equal(mine.wake_mask.values, one.wake_mask.values)
        np.testing.assert_array_equal(mine.elevation.values, one.elevation.values)
        np.testing.assert_array_equal(mine.rx_position.values, one.rx_position.values)
        np.testing.assert_array_equal(ds.fast_time.values[i], one.fast_time.values)
        assert np.abs(one.raw.values).max() > 0
    # one sea; each pair's wake film damping at its own Bragg wavenumber
    masks = ds.wake_mask.values
    assert masks.max() > 0 and not np.array_equal(masks[0], masks[2])
    # receiver 'north' records HH and VV only: NaN (no data) in HV and VH, flagged
    assert not ds.recorded.sel(receiver="north", channel="HV")
    assert np.isnan(ds.raw.sel(receiver="north", channel="HV").values).all()
    assert np.isfinite(ds.raw.sel(receiver="north", channel="VV").values).all()
    # receiver_dataset gives the bistatic layout the readers take
    north = receiver_dataset(ds, "north")
    assert north.raw.dims == ("pulse", "channel", "fast_time")
    assert list(north.channel.values) == ["HH", "VV"]


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_speckle_and_sea_are_computed_once_per_block(monkeypatch):
    # The sea synthesis and the speckle draws are the first receiver's, reused by the
    # others: one Sea.state per held surface and one set of draws per block.
    import seaecho.simulation as simulation

    sc = _scene(tracing={"mode": "raytraced", "refresh_interval_s": 2e-3},
                sea_update_pulses=2)
    sim = simulation_of(sc)
    calls = {"state": [], "draws": 0}
    sea = sim.receivers[0].sea
    orig_state = sea.state
    monkeypatch.setattr(sea, "state", lambda t: calls["state"].append(t) or orig_state(t))
    orig = simulation.facet_gaussians

    def draws(*a, **k):
        calls["draws"] += 1
        return orig(*a, **k)

    monkeypatch.setattr(simulation, "facet_gaussians", draws)
    traced = []
    tracer = sim.receivers[0].engine.tracer
    orig_occ = tracer.occluded
    monkeypatch.setattr(tracer, "occluded",
                        lambda c, n, p, *a, **k: traced.append(tuple(p)) or orig_occ(c, n, p,
                                                                                *a, **k))
    sim.pulses(0, 4)
    assert sorted(set(calls["state"])) == calls["state"]  # once per held surface (2)
    assert len(calls["state"]) == 2
    m = sim.receivers[0].sea_model
    per_block = 1 + (m.tilt is not None) + (m.breaking is not None)
    assert calls["draws"] == 2 * per_block
    # per refresh (2 of them): the transmitter once, each of the 3 receivers once
    tx = {tuple(sim.radar.tx.state(t).position) for t in (0.0, 2e-3)}
    assert sum(p in tx for p in traced) == 2
    assert len(traced) == 2 * 4


@pytest.mark.parametrize("positions", [
    [(-50.0, 10.0, 30.0), (40.0, 40.0, 60.0), (5.0, -80.0, 20.0)],
])
def test_point_target_at_each_bistatic_range_with_the_bistatic_radar_equation(positions):
    # P_r = P_t G_t G_r lambda^2 sigma / ((4 pi)^3 R_t^2 R_r^2) (Willis, Bistatic Radar,
    # 2nd ed. 2005, eq 4.1; Skolnik, Radar Handbook 3rd ed. 2008, eq 23.1) with isotropic
    # antennas (G = 1), from each receiver's range-compressed peak (upsampled 64 x):
    # within 0.1 dB, at the bistatic range (R_t + R_r) / 2 within 2 % of a sample.
    target = np.array([2.0, -3.0, 1.5])
    rx = [{"name": f"r{i}", "position_m": p, "antenna": ISO} for i, p in enumerate(positions)]
    sc = _scene(receivers=rx, sea=False, n_pulses=1, targets=[
        {"position_m": tuple(target), "rcs_m2": 7.0}], transmit_power_w=50.0,
        tx={"position_m": (-93.41, 0.0, 256.65), "antenna": ISO})
    ds = simulation_of(sc).dataset(progress=False)
    lam = C0 / 1e10
    r_t = np.linalg.norm(target - np.array([-93.41, 0.0, 256.65]))
    pulse = ds.transmitted_pulse.values
    for i, p in enumerate(positions):
        r_r = np.linalg.norm(target - np.array(p))
        expected = 50.0 * lam**2 * 7.0 / ((4 * np.pi) ** 3 * r_t**2 * r_r**2)
        for ch in ("HH", "VV"):
            y = range_compress(ds.raw.isel(pulse=0, receiver=i).sel(channel=ch).values, pulse)
            n = y.size
            spec = np.fft.fft(y)
            up = 64
            yu = np.fft.ifft(np.concatenate([spec[: n // 2], np.zeros(n * (up - 1)),
                                             spec[n // 2:]])) * up
            k = int(np.argmax(np.abs(yu)))
            assert 10 * np.log10(np.abs(yu[k]) ** 2 / expected) == pytest.approx(0, abs=0.1)
            fs = 200e6
            where = k / up
            wanted = ((r_t + r_r) / C0 - float(ds.window_t0_s[i])) * fs
            assert where == pytest.approx(wanted, abs=0.02)
        beta = float(ds.bistatic_angle[i, 0])  # at the tile centre
        a, b = np.array([-93.41, 0.0, 256.65]), np.array(p)
        cos = a @ b / (np.linalg.norm(a) * np.linalg.norm(b))
        assert beta == pytest.approx(np.arccos(cos), abs=1e-12)


def test_bistatic_angle_limits():
    # beta = 0 monostatic, pi on the baseline between them (forward scatter), 90 deg for
    # orthogonal lines of sight (Willis 2005, section 3.1)
    o = np.zeros(3)
    assert bistatic_angle(np.array([1.0, 2, 3]), np.array([2.0, 4, 6]), o) == pytest.approx(0)
    assert bistatic_angle(np.array([5.0, 0, 0]), np.array([-3.0, 0, 0]), o) == pytest.approx(
        np.pi)
    assert bistatic_angle(np.array([0.0, 0, 7]), np.array([0.0, 4, 0]), o) == pytest.approx(
        np.pi / 2)


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_one_receiver_scene_keeps_the_bistatic_layout_and_bytes():
    # [receiver]: no receiver dimension, and the bytes of [[receivers]]'s receiver 0
    sc = _scene(receivers=[RECEIVERS[0]], n_pulses=2)
    ds = simulation_of(sc).dataset(progress=False)
    bi = _scene(receivers={k: v for k, v in RECEIVERS[0].items() if k != "name"},
                n_pulses=2,
                window_start_m=float(ds.window_start_m[0]),
                window_end_m=float(ds.window_end_m[0]))
    one = simulation_of(bi).dataset(progress=False)
    assert one.raw.dims == ("pulse", "channel", "fast_time")
    assert "receiver" not in one.dims and "multistatic" not in one.attrs
    # the scene JSON of a [receiver] scene is as before [[receivers]] existed (the file's
    # bytes, a Zarr run's identity)
    assert '"receivers"' not in one.attrs["scene_json"]
    assert '"receivers"' in ds.attrs["scene_json"]
    assert np.array_equal(ds.raw.isel(receiver=0).values, one.raw.values)


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_netcdf_zarr_and_resumed_zarr_have_the_same_bytes(tmp_path):
    from seaecho.io.run import open_run

    sc = _scene(n_pulses=4, sea_update_pulses=2)
    nc = simulation_of(sc).run(tmp_path / "m.nc", progress=False, chunk=2)
    sim = simulation_of(sc)
    orig = sim.pulses

    def cut(a, b):
        if a >= 2:
            raise KeyboardInterrupt
        return orig(a, b)

    sim.pulses = cut
    with pytest.raises(KeyboardInterrupt):
        sim.run(tmp_path / "m.zarr", progress=False, chunk=2)
    simulation_of(sc).run(tmp_path / "m.zarr", progress=False, resume=True)
    with open_run(nc) as a, open_run(tmp_path / "m.zarr") as b:
        assert a.raw.dims == b.raw.dims == ("pulse", "receiver", "channel", "sample")
        for name in ("raw", "compressed", "sigma0", "fast_time"):
            assert np.array_equal(a[name].values, b[name].values, equal_nan=True), name
        assert list(b.receiver.values) == ["near", "north", "south"]


def test_receivers_and_receiver_together_are_refused():
    d = _scene().model_dump()
    d["receiver"] = {k: v for k, v in RECEIVERS[0].items() if k != "name"}
    with pytest.raises(SceneError, match=r"\[\[receivers\]\].*\[receiver\]"):
        parse_scene(d)


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
@pytest.mark.parametrize("change, match", [
    (lambda r: r[1].update(name="near"), "names must be unique"),
    (lambda r: r[1].update(channels=["HH", "XV"]), r"#1 \(north\)\.channels"),
    (lambda r: r[2]["antenna"].update(basis="circular"), r"\[radar\]\.channels \(receiver #2"),
    (lambda r: r[0].pop("name"), "name"),
    (None, r"sea_motion = 'evolving' with \[\[receivers\]\]: not implemented yet"),
])
def test_bad_receivers_are_refused_naming_the_field(change, match):
    rx = [dict(r, antenna=dict(r["antenna"])) for r in RECEIVERS]
    if change is None:
        d = _scene().model_dump()
        d["scattering"]["sea_motion"] = "evolving"
        with pytest.raises(SceneError, match=match):
            parse_scene(d)
        return
    change(rx)
    with pytest.raises(SceneError, match=match):
        _scene(receivers=rx)


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_dask_run_has_the_serial_bytes(tmp_path):
    # Blocks of pulses on two Dask workers (each its own MultistaticSimulation)
    from seaecho import distributed
    from seaecho.io.run import open_run

    sc = _scene(n_pulses=4)
    serial = simulation_of(sc).run(tmp_path / "s.nc", progress=False, chunk=1)
    with distributed.cluster(2, processes=False) as client:
        dask = distributed.run(sc, tmp_path / "d.zarr", client=client, block=1,
                               progress=False)
    with open_run(serial) as a, open_run(dask) as b:
        for name in ("raw", "compressed"):
            assert np.array_equal(a[name].values, b[name].values, equal_nan=True), name


# ----------------------------------------------------------------------- command line
ROOT = Path(__file__).resolve().parents[2]
SCENE_3RX = (ROOT / "scenes" / "multistatic_ship_3rx.toml").read_text(encoding="utf-8")


def _tiny_3rx(tmp_path: Path, text: str = SCENE_3RX) -> Path:
    """The three-receiver scene at the gallery's --quick size, beside its meshes."""
    for old, new in (("size_x_m = 64.0", "size_x_m = 16.0"), ("nx = 256", "nx = 64"),
                     ("n_pulses = 128", "n_pulses = 8"),
                     ("start_time_s = -0.288288", "start_time_s = -0.018"),
                     ("sea_update_pulses = 128", "sea_update_pulses = 8"),
                     ("sigma_map_pulse = 64", "sigma_map_pulse = 4"),
                     ("position_m = [4.0, 2.8]", "position_m = [1.0, 0.7]"),
                     ("position_m = [4.0, 2.8, 1.0]", "position_m = [1.0, 0.7, 1.0]"),
                     ("pixel_m = 0.5", "pixel_m = 1.0"),
                     ("extent_m = [-32.0, 32.0, -32.0, 32.0]",
                      "extent_m = [-8.0, 8.0, -8.0, 8.0]")):
        assert old in text
        text = text.replace(old, new)
    mesh = ROOT / "scenes" / "meshes" / "motor_boat_10m.ply"
    text = text.replace('file = "meshes/motor_boat_10m.ply"', f"file = {str(mesh)!r}")
    path = tmp_path / "multistatic.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("command", ["check", "run"])
def test_cli_refuses_receiver_and_receivers_with_exit_2(tmp_path, capsys, command):
    from seaecho.cli import main

    text = SCENE_3RX.replace("[[receivers]]\nname = \"formation\"",
                             "[receiver]\nmotion = \"fixed\"\nposition_m = [0.0, -50.0, 30.0]"
                             "\n[receiver.antenna]\npattern = \"isotropic\"\n"
                             "look_at_m = [0.0, 0.0, 0.0]\n\n[[receivers]]\n"
                             "name = \"formation\"", 1)
    path = _tiny_3rx(tmp_path, text)
    out = tmp_path / "x.nc"
    rc = main([command, str(path)] + (["-o", str(out)] if command == "run" else []))
    err = capsys.readouterr().err
    assert rc == 2 and "Traceback" not in err
    assert "[[receivers]]" in err and "[receiver]" in err
    assert not out.exists()


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore::seaecho.warnings.SeaechoWarning")
def test_cli_run_and_image_of_three_receivers(tmp_path, capsys):
    # seaecho run writes the receiver dimension and every receiver's figures; seaecho
    # image focuses each pair and their incoherent combination (the mean of the
    # calibrated intensities); each receiver's image is the image of its bistatic run.
    from seaecho import api
    from seaecho.cli import main

    out = tmp_path / "m.nc"
    assert main(["run", str(_tiny_3rx(tmp_path)), "-o", str(out), "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "3 receivers x 4 channels" in text
    for name in ("formation", "south", "northeast"):
        assert (tmp_path / f"m_{name}_sigma.png").is_file()
        assert (tmp_path / f"m_image_{name}_sigma0.png").is_file()
    assert (tmp_path / "m_image_fused_sigma0.png").is_file()
    with api.open_dataset(out) as raw, api.open_dataset(tmp_path / "m_image.nc") as img:
        assert raw.raw.dims == ("pulse", "receiver", "channel", "sample")
        s0 = img.sigma0.values.astype(np.float64)
        np.testing.assert_allclose(img.fused_sigma0.values, s0.mean(axis=0), rtol=1e-6)
        one = api.image(receiver_dataset(raw.load(), "south"))
        np.testing.assert_array_equal(one.image.values, img.image.sel(receiver="south").values)


def test_images_per_receiver_and_their_incoherent_combination():
    # Each receiver's image is its bistatic run's image (same data, same grid); the
    # combination is the mean of the receivers' calibrated intensities over those that
    # record the channel (Willis and Griffiths 2007: non-coherent multistatic combination).
    from seaecho import api

    rx = [dict(r, antenna=ISO) for r in RECEIVERS]
    sc = _scene(receivers=rx, sea=False, n_pulses=8,
                tx={"position_m": (-93.41, 0.0, 256.65), "antenna": ISO,
                    "motion": "linear", "velocity_m_s": (0.0, 100.0, 0.0)},
                targets=[{"position_m": (1.0, 2.0, 0.5), "rcs_m2": 3.0},
                         {"position_m": (-3.0, -1.0, 0.0), "rcs_m2": 1.0}])
    ds = simulation_of(sc).dataset(progress=False)
    fields = {"extent_m": (-6.0, 6.0, -6.0, 6.0), "pixel_m": 1.0}
    img = api.image(ds, **fields)
    assert img.image.dims == ("receiver", "channel", "y", "x")
    rcs = np.abs(img.image.values.astype(np.complex128)) ** 2
    with np.errstate(invalid="ignore"):
        mean = np.nanmean(rcs, axis=0)
    np.testing.assert_allclose(img.fused_rcs.values, mean, rtol=1e-6)
    assert list(img.fused_receivers.values) == [3, 2, 2, 3]  # 'north': HH, VV only
    for i in range(3):
        one = simulation_of(_alone(sc, ds, i)).dataset(progress=False)
        alone = api.image(one, **fields)
        mine = img.image.isel(receiver=i).sel(channel=alone.channel.values)
        np.testing.assert_array_equal(mine.values, alone.image.values)
    assert set(api.image_measures(img)) >= {"near HH", "north VV", "south HV"}


def test_preflight_names_the_receiver_whose_geometry_is_refused():
    # seaecho check refuses what seaecho run would: each receiver's geometry, named
    from seaecho.checks.preflight import check_run

    rx = [dict(r) for r in RECEIVERS]
    rx[2]["position_m"] = (0.0, -150.0, -3.0)  # under the sea
    with pytest.raises(SceneError, match=r"\[\[receivers\]\] #2 \(south\)\.position_m"):
        check_run(_scene(receivers=rx), "s.toml")
    assert "estimated peak memory" in check_run(_scene(), "s.toml")
