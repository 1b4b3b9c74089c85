"""Radar sections of the scene files: validation errors and the paper scenes' geometry.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seaecho.build import build_radar
from seaecho.config import SceneError, load_scene, parse_scene
from seaecho.constants import C0
from seaecho.radar.system import RadarSystem

SCENES = Path(__file__).resolve().parents[2] / "scenes"


def test_sim1_angles_at_tile_centre():
    # Paper section V-A: theta_i = 20 deg and theta_s = 30 deg at the centre, 18 x 14 cm
    # apertures aimed at it, 10 GHz
    sc = load_scene(SCENES / "paper_sim1_bistatic_64m.toml")
    radar = RadarSystem(build_radar(sc))
    geo = radar.geometry(0)
    for pos, angle in ((geo.tx.position, 20.0), (geo.rx.position, 30.0)):
        d = -pos / np.linalg.norm(pos)
        assert np.degrees(np.arccos(-d[2])) == pytest.approx(angle, abs=0.01)
    np.testing.assert_allclose(geo.tx_axes[:, 0], -geo.tx.position / np.linalg.norm(
        geo.tx.position), atol=1e-12)
    assert sc.transmitter.antenna.width_m == 0.18 and sc.receiver.antenna.height_m == 0.14
    assert radar.carrier == 10e9


@pytest.mark.parametrize("name", ["paper_sim2_sar_128m_wind55", "paper_sim3_sar_128m_wind0",
                                  "paper_sim4_sar_500m_u10"])
def test_sar_scenes(name):
    # Paper section V-B: 3000 m altitude, 3000 m ground range, 222 m/s, PRF 222 Hz (one
    # pulse per metre), 10 GHz, 75 MHz chirp of 333 ns (c / 2B = 2 m), monostatic; the
    # beam passes over the tile centre at t = 0 (broadside, 45 deg down)
    sc = load_scene(SCENES / f"{name}.toml")
    radar = RadarSystem(build_radar(sc))
    assert radar.monostatic and radar.carrier == 10e9
    assert np.linalg.norm(sc.transmitter.velocity_m_s) / radar.prf == pytest.approx(1.0)
    assert C0 / (2 * radar.waveform.bandwidth) == pytest.approx(2.0, rel=0.01)
    assert radar.waveform.duration == pytest.approx(333e-9, rel=1e-9, abs=0)
    state = radar.tx.state(0.0)
    assert state.position[2] == 3000.0 and np.hypot(*state.position[:2]) == 3000.0
    axes = radar.tx_pointing.axes(state)
    hit = state.position - axes[:, 0] * state.position[2] / axes[2, 0]
    assert np.hypot(hit[0], hit[1]) < 1e-6  # boresight meets the sea at the centre
    # azimuth resolution L / 2 ~ 2 m (stripmap)
    assert sc.transmitter.antenna.width_m / 2 == pytest.approx(2.0)
    # the pulses cover the tile plus one azimuth footprint
    footprint = 0.886 * radar.wavelength * 3000 * np.sqrt(2) / sc.transmitter.antenna.width_m
    assert radar.n_pulses >= sc.sea.size_m[1] + footprint


@pytest.mark.parametrize("change,message", [
    ({"channels": ["HX"]}, "channel"),
    ({"waveform": {"kind": "lfm", "duration_s": 1e-6}}, "bandwidth_hz"),
    ({"sampling_rate_hz": 1e6}, "exceeds sampling_rate_hz"),
    ({"prf_hz": 2e6}, "pulse repetition interval"),
    ({"window_start_m": 100.0}, "window_end_m"),
])
def test_bad_radar_sections(change, message):
    radar = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 1e8, "prf_hz": 1e3,
             "waveform": {"kind": "lfm", "bandwidth_hz": 5e7, "duration_s": 1e-6}}
    radar.update(change)
    data = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64}, "radar": radar,
            "transmitter": {"position_m": (0, 0, 100),
                            "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}}}
    with pytest.raises((SceneError, ValueError), match=message):
        RadarSystem(build_radar(parse_scene(data)))


def test_antenna_errors_name_the_field():
    data = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
            "transmitter": {"position_m": (0, 0, 100),
                            "antenna": {"pattern": "rectangular", "look_at_m": (0, 0, 0)}}}
    with pytest.raises(SceneError, match=r"\[transmitter\]\.antenna.*width_m and height_m"):
        parse_scene(data)
    data["transmitter"]["antenna"] = {"pattern": "isotropic"}
    with pytest.raises(SceneError, match="exactly one"):
        parse_scene(data)


@pytest.mark.parametrize("name", ["coastal_vts_xband", "shipborne_navigation_xband"])
def test_scanning_scenes(name):
    # docs/scanning.md: X band, 24 rpm (2.5 s, 2500 pulses at 1 kHz: one revolution),
    # 4/3 Earth, the sea tile above the horizon; `seaecho check` accepts them
    from seaecho.checks.preflight import check_run
    from seaecho.geometry.earth import effective_radius, grazing_angle

    sc = load_scene(SCENES / f"{name}.toml")
    model = build_radar(sc)
    assert model.scan_period == pytest.approx(2.5)
    assert model.n_pulses / model.prf == pytest.approx(model.scan_period)
    assert model.earth.radius == pytest.approx(effective_radius(4.0 / 3.0))
    assert model.carrier == 9.41e9
    check_run(sc, name, base_dir=SCENES)
    if name == "coastal_vts_xband":
        assert model.transmit_phase == "random"
        # grazing angle at the tile's centre, 2 km from a 35 m antenna: 1.0 deg
        radar = RadarSystem(model, backend="numpy")
        p = radar.tx.state(0.0).position
        r = float(np.linalg.norm(p))
        assert np.degrees(grazing_angle(35.0, r, model.earth.radius)) == pytest.approx(
            1.0, abs=0.01)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["coastal_vts_xband", "shipborne_navigation_xband"])
def test_scanning_scenes_run(name, tmp_path):
    # `seaecho run SCENE -o OUT.nc` on a few pulses: the run, its CfRadial product and PPI
    import warnings

    import xarray as xr

    from seaecho.cli import main
    from seaecho.scattering.validity import SPMValidityWarning
    from seaecho.warnings import SamplingWarning

    out = tmp_path / "out.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SamplingWarning)
        warnings.simplefilter("ignore", SPMValidityWarning)
        assert main(["run", str(SCENES / f"{name}.toml"), "-o", str(out), "--pulses", "6",
                     "-q"]) == 0
    tree = xr.open_datatree(tmp_path / "out_ppi.nc")
    assert tree["sweep_0"].sizes["azimuth"] == 6
    assert (tmp_path / "out_ppi_sweep_0.png").exists()
