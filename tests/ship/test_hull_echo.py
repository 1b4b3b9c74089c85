"""Hull echoes in the simulation: calibration, position, Doppler, truth, determinism."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.build import build_radar
from seaecho.cli import main
from seaecho.config import SceneError, load_scene, parse_scene
from seaecho.constants import C0
from seaecho.processing.range_compression import range_compress
from seaecho.radar.equation import bistatic_received_power
from seaecho.radar.system import RadarSystem
from seaecho.simulation import Simulation

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


def _upsampled(y, up=64):
    n = y.size
    spec = np.fft.fft(y)
    return np.fft.ifft(np.concatenate([spec[: n // 2], np.zeros(n * (up - 1)),
                                       spec[n // 2:]])) * up


def test_calibration_trihedral_is_the_radar_equation(tmp_path):
    # scenes/calibration_trihedral.toml end to end (CLI): the compressed peak of the
    # 0.5 m trihedral is P_t G^2 lambda^2 sigma / ((4 pi)^3 r^4) with sigma = 4 pi a^4 /
    # (3 lambda^2) (Knott et al. 1993, table 6.1; Skolnik 2008, eq 23.1) within 0.3 dB,
    # at the apex's range (the triple bounce's phase centre) within 0.1 m; HH = -VV in
    # the FSA bases (odd bounce), cross-polar 20 dB below. Without the figures (half the
    # run's time; the same two figures of a run are tests/cli/test_run.py's).
    out = tmp_path / "tri.nc"
    assert main(["run", str(SCENES / "calibration_trihedral.toml"), "-o", str(out),
                 "--pulses", "2", "-q", "--no-figures"]) == 0
    scene = load_scene(SCENES / "calibration_trihedral.toml")
    radar = RadarSystem(build_radar(scene))
    geo = radar.geometry(0)
    apex = np.array(scene.objects[0].position_m)
    r = np.linalg.norm(apex - geo.tx.position)
    d = (apex - geo.tx.position) / r
    g = radar.tx_antenna.gain_local(geo.tx_axes.T @ d)
    lam = radar.wavelength
    sigma = 4 * np.pi * 0.5**4 / (3 * lam**2)
    expected = bistatic_received_power(100.0, g, g, lam, sigma, r, r)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        y = {c: _upsampled(ds["compressed"].sel(channel=c).values[0])
             for c in ("HH", "HV", "VV")}
        i = int(np.argmax(np.abs(y["HH"])))
        assert 10 * np.log10(np.abs(y["HH"][i]) ** 2 / expected) == pytest.approx(0, abs=0.3)
        t = ds["fast_time"].values
        tau = t[0] + i / 64 / scene.radar.sampling_rate_hz
        assert 0.5 * C0 * tau == pytest.approx(r, abs=0.1)
        assert abs(np.angle(y["HH"][i] / y["VV"][i])) == pytest.approx(np.pi, abs=0.1)
        assert np.abs(y["HV"]).max() ** 2 < 0.01 * np.abs(y["HH"][i]) ** 2
        # the truth: apparent RCS of the hull (sigma within 0.3 dB) and the centres
        assert 10 * np.log10(ds["hull_rcs"].values[0, 0, 0] / sigma) == pytest.approx(
            0, abs=0.3)
        assert ds["hull_centre_position"].shape[1] == 3
        assert (ds["hull_trace_pulse"].values == 0).all()
        assert int(ds["hull_sea_multipath"].values[0]) == 0


def _boat_scene(n_rays=1.0, **radar):
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6, "prf_hz": 2000.0,
         "n_pulses": 16, "sea_clutter": False, "transmit_power_w": 100.0,
         "thermal_noise": False, "window_start_m": 280.0, "window_end_m": 330.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": 150e6, "duration_s": 1e-6}}
    r.update(radar)
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "ship": {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 10.0,
                 "heading_deg": 35.0, "position_m": (5.0, 3.0)},
        "radar": r,
        "transmitter": {"position_m": (-300.0, 0.0, 40.0),
                        "antenna": {"pattern": "isotropic", "look_at_m": (5.0, 3.0, 1.0)}},
        "objects": [{"name": "boat", "file": "meshes/motor_boat_10m.ply",
                     "follow_ship": True, "material": "metal", "scatterer": True,
                     "rays_per_wavelength": n_rays, "signature_cell_m": 0.25}],
    })


def test_boat_appears_at_its_position_and_doppler():
    # The boat (10 kt heading 35 deg) seen by a fixed monostatic radar: the compressed
    # echo peaks within the hull's range extent, and the phase of the peak advances by
    # 2 pi f_D / PRF per pulse with f_D = -2 u . v / lambda (Willis 2005, eq 3.23; u the
    # line of sight to the ship, v its velocity), within 5 % (the hull spans 2 deg).
    sc = _boat_scene()
    sim = Simulation(sc, base_dir=SCENES)
    radar = sim.radar
    pulses = np.stack([sim.pulse(p) for p in range(radar.n_pulses)])
    y = range_compress(pulses[:, 0], radar.waveform.samples)
    power = np.mean(np.abs(y) ** 2, axis=0)
    i = int(np.argmax(power))
    rng = 0.5 * C0 * radar.window.fast_time[i]
    hull = sim.hulls.hulls[0]
    tx = radar.tx.state(0.0).position
    v = hull.mesh(0.0).vertices
    r_hull = np.linalg.norm(v - tx, axis=1)
    assert r_hull.min() - 1.0 <= rng <= r_hull.max() + 1.0
    assert power[i] > 1e3 * np.median(power)
    speed = 10.0 * 1852.0 / 3600.0
    vel = speed * np.array([np.cos(np.deg2rad(35.0)), np.sin(np.deg2rad(35.0)), 0.0])
    centre = hull.origin(0.0)
    u = (centre - tx) / np.linalg.norm(centre - tx)
    f_d = -2.0 * (u @ vel) / radar.wavelength
    step = np.angle(np.sum(y[1:, i] * np.conj(y[:-1, i])))
    assert step * radar.prf / (2 * np.pi) == pytest.approx(f_d, rel=0.05)


def test_pulses_in_any_order_give_the_same_bytes():
    # The radar flies past the trihedral of the calibration scene (the aspect turns by
    # ~4 deg over the pulses): several traces (refresh every 1 deg); each pulse computed
    # alone in a fresh simulation, or in reverse order, equals the in-order one to the
    # byte (the schedule is a function of the tracks only).
    sc = load_scene(SCENES / "calibration_trihedral.toml")
    tx = sc.transmitter.model_copy(update={"motion": "linear",
                                           "velocity_m_s": (0.0, 200.0, 0.0)})
    sc = sc.model_copy(update={
        "transmitter": tx,
        "radar": sc.radar.model_copy(update={"n_pulses": 5, "prf_hz": 50.0}),
        "objects": (sc.objects[0].model_copy(update={"rays_per_wavelength": 2.0}),)})
    sim = Simulation(sc, base_dir=SCENES)
    assert len(sim.hulls.hulls[0].schedule) >= 2
    forward = [sim.pulse(p) for p in range(5)]
    sim2 = Simulation(sc, base_dir=SCENES)
    backward = [sim2.pulse(p) for p in reversed(range(5))][::-1]
    alone = Simulation(sc, base_dir=SCENES).pulse(3)
    for a, b in zip(forward, backward, strict=True):
        assert a.tobytes() == b.tobytes()
    assert alone.tobytes() == forward[3].tobytes()


@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_boat_over_sea_dataset(tmp_path):
    # With sea clutter: the boat's trace sees the held sea (occlusion), the hull echo adds
    # to the sea's, and the dataset holds the truth (RCS per pulse and channel, centres).
    sc = _boat_scene(sea_clutter=True, n_pulses=2, window_start_m=None, window_end_m=None)
    sc = sc.model_copy(update={"sea": sc.sea.model_copy(update={"size_x_m": 32.0,
                                                                "nx": 128})})
    sim = Simulation(sc, base_dir=SCENES)
    assert sim.hulls.surface is not None
    out = sim.run(tmp_path / "b.nc", progress=False)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds["hull_rcs"].dims == ("hull", "pulse", "polarisation")
        assert ds["hull"].values.tolist() == ["boat"]
        assert (ds["hull_rcs"].values > 0).all()
        assert ds["hull_centre_scattering"].dtype == np.complex128
        assert set(np.unique(ds["hull_centre_path"].values)) <= {0, 1, 2, 3}
        assert ds["hull_position"].shape == (1, 2, 3)
        sig = sim.hulls.signature(0, 0)
        np.testing.assert_allclose(ds["hull_rcs"].values[0, 0], sig.rcs, rtol=1e-6)
    sea_only = Simulation(sc.model_copy(update={"objects": ()}), base_dir=SCENES)
    p_boat = np.sum(np.abs(sim.pulse(0)) ** 2)
    p_sea = np.sum(np.abs(sea_only.pulse(0)) ** 2)
    assert p_boat > p_sea


def test_scatterer_options_need_scatterer():
    data = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
            "objects": [{"name": "b", "file": "meshes/motor_boat_10m.ply",
                         "rays_per_wavelength": 8.0}]}
    with pytest.raises(SceneError, match="rays_per_wavelength: only with scatterer = true"):
        parse_scene(data)
    data["objects"][0].update(scatterer=True, rays_per_wavelength=0.1)
    with pytest.raises(SceneError, match="rays_per_wavelength"):
        parse_scene(data)


def test_paper_boat_echoes():
    for name in ("paper_sim1_bistatic_64m", "paper_sim2_sar_128m_wind55",
                 "paper_sim3_sar_128m_wind0"):
        obj = load_scene(SCENES / f"{name}.toml").objects[0]
        assert obj.scatterer and obj.material == "metal" and obj.follow_ship
