"""Bad scene files through `seaecho check` and `seaecho run`: exit 2, one message naming
the field, no traceback, no file left. Each case is a defect found by trying broken
scenes (the fuzzing suite in ``tests/fuzz`` generates many more)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main

ROOT = Path(__file__).resolve().parents[2]
CAL = (ROOT / "scenes" / "calibration_point_target.toml").read_text()


def _scene(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return path


def _replace(old: str, new: str, text: str = CAL) -> str:
    assert old in text
    return text.replace(old, new, 1)


def _cli(capsys, *args) -> tuple[int, str]:
    rc = main(list(args))
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return rc, err


@pytest.mark.parametrize("command", ["check", "run"])
def test_deeply_nested_toml_value_is_a_message(tmp_path, capsys, command):
    # x = [[[[...]]]] 3000 levels deep: Python's TOML parser recurses past its limit
    text = "x = " + "[" * 3000 + "]" * 3000 + "\n" + CAL
    scene = _scene(tmp_path, text)
    out = tmp_path / "x.nc"
    extra = ["-o", str(out), "-q"] if command == "run" else []
    rc, err = _cli(capsys, command, str(scene), *extra)
    assert rc == 2 and "nested too deeply" in err
    assert sorted(tmp_path.iterdir()) == [scene]


@pytest.mark.parametrize(
    ("old", "new", "section", "allowed"),
    [
        ("nx = 64", "nx = 64\nNy = 64", "[sea].Ny", "wind_speed_m_s"),
        ("seed = 1", "Seed = 1", "[run].Seed", "surface_times_s"),
        ("position_m = [-500.0, 0.0, 300.0]", "Position_m = [-500.0, 0.0, 300.0]",
         "[transmitter].Position_m", "waypoint_times_s"),
        ('kind = "lfm"', 'KIND = "lfm"', "[radar].waveform.KIND", "up_chirp"),
    ],
)
def test_unknown_key_with_capitals_is_named_with_its_own_section(tmp_path, capsys, old, new,
                                                                 section, allowed):
    # The loc cleaner used to drop every part starting with a capital (meant for class
    # names of tagged unions): the key vanished and the top level's keys were listed
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(old, new))))
    assert rc == 2
    line = next(ln for ln in err.splitlines() if "unknown key" in ln)
    assert line.startswith(section) and allowed in line
    assert "transmitter, " not in line  # not the top level's keys


def test_long_values_are_cut_in_messages(tmp_path, capsys):
    name = "a" * 1_000_000
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(
        'name = "calibration_point_target"', f'name = "{name}"'))))
    assert rc == 2 and "at most 200 characters" in err
    assert len(err) < 1000 and "1000000 characters" in err
    targets = "".join(f"[[targets]]\nposition_m = [{i}.0, 0.0, 1.0]\nrcs_m2 = 1.0\n"
                      for i in range(10_001))
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, CAL + targets)))
    assert rc == 2 and "at most 10000 items" in err
    assert len(err) < 1000 and "10004 items" in err


def test_long_lists_in_validator_messages_are_cut(tmp_path, capsys):
    times = ", ".join(str(float(100_000 - i)) for i in range(100_000))
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(
        "seed = 1", f"seed = 1\nsurface_times_s = [{times}]"))))
    assert rc == 2 and "increasing order" in err and len(err) < 1000


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ("wind_speed_m_s = 5.0", "wind_speed_m_s = true", "[sea].wind_speed_m_s = true"),
        ("nx = 64", 'nx = "32"', '[sea].nx = "32"'),
        ("nx = 64", "nx = 64.0", "[sea].nx = 64.0"),
        ("seed = 1", "seed = 1.5", "[run].seed = 1.5"),
        ("thermal_noise = true", "thermal_noise = 1", "[radar].thermal_noise = 1"),
        ("n_pulses = 32", 'n_pulses = "32"', '[radar].n_pulses = "32"'),
    ],
)
def test_strict_types(tmp_path, capsys, old, new, field):
    # Lax validation took true as 1.0 and "32" as 32
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(old, new))))
    assert rc == 2 and field in err


def test_integer_is_accepted_for_a_float(tmp_path, capsys):
    rc, _ = _cli(capsys, "check", str(_scene(tmp_path, _replace(
        "wind_speed_m_s = 5.0", "wind_speed_m_s = 5"))))
    assert rc == 0


def _run_quietly(*args) -> int:
    """main(args) with warnings printed (as the console script does), not raised."""
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        return main(list(args))


def test_wind_below_beaufort_force_1_is_refused(tmp_path, capsys):
    # 1e-300 m/s passed the schema (> 0) and `check` died in ZeroDivisionError
    # (k_p = g Omega^2 / U10^2); the Beaufort scale calls a wind below 0.3 m/s calm
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(
        "wind_speed_m_s = 5.0", "wind_speed_m_s = 1e-300"))))
    assert rc == 2 and "[sea].wind_speed_m_s = 1e-300" in err and "0.3" in err


def test_lightest_wind_runs_with_sea_clutter(tmp_path, capsys):
    text = _replace("wind_speed_m_s = 5.0", "wind_speed_m_s = 0.3")
    text = _replace("sea_clutter = false\n", "sea_clutter = true\n", text)
    text = _replace("nx = 64", "nx = 16", text)
    scene = _scene(tmp_path, text)
    out = tmp_path / "x.nc"
    assert _run_quietly("check", str(scene)) == 0
    assert _run_quietly("run", str(scene), "-o", str(out), "-q", "--no-figures",
                        "--pulses", "1") == 0
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert np.isfinite(ds["raw"].values).all()
    assert "Traceback" not in capsys.readouterr().err


def test_carrier_whose_radar_band_the_grid_resolves(tmp_path, capsys):
    # 1.000001 MHz: the band of unresolved waves [pi/dx, 50 k] is empty; `check` died with
    # "need 0 <= k_min < k_max" while `run` (sea clutter off) exited 0
    scene = _scene(tmp_path, _replace("carrier_frequency_hz = 10.0e9",
                                      "carrier_frequency_hz = 1.000001e6"))
    rc, err = _cli(capsys, "check", str(scene))
    assert rc == 0 and "coarse against the radar wavelength" not in capsys.readouterr().out


def test_surface_of_a_grid_finer_than_every_tabulated_wave(tmp_path, capsys):
    # 1 cm tile on 1024 points: k_cut = pi / dx > 1e4 rad/m, the upper limit of the
    # unresolved band the surface file reports; an empty band has zero variance
    scene = _scene(tmp_path, "[sea]\nwind_speed_m_s = 5.0\nsize_x_m = 0.01\nnx = 1024\n")
    out = tmp_path / "s.nc"
    assert _run_quietly("surface", str(scene), "-o", str(out)) == 0
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds.attrs["unresolved_height_variance_m2"] == 0.0


@pytest.mark.parametrize(
    ("old", "new", "named"),
    [
        ('channels = ["HH", "HV", "VH", "VV"]', 'channels = ["XX"]', "'XX'"),
        ('channels = ["HH", "HV", "VH", "VV"]', 'channels = ["hh"]', "'hh'"),
        ('look_at_m = [0.0, 0.0, 0.0]\n\n[receiver]',
         'look_at_m = [0.0, 0.0, 0.0]\nbasis = "circular"\n\n[receiver]', "'HH'"),
    ],
)
def test_check_refuses_channels_that_run_refuses(tmp_path, capsys, old, new, named):
    # `check` accepted these and `run` then refused them
    scene = _scene(tmp_path, _replace(old, new))
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "x.nc"), "-q"] if command == "run" else []
        rc, err = _cli(capsys, command, str(scene), *extra)
        assert rc == 2 and "[radar].channels" in err and named in err
    assert sorted(tmp_path.iterdir()) == [scene]


def test_circular_channels_are_accepted(tmp_path, capsys):
    text = _replace('look_at_m = [0.0, 0.0, 0.0]\n\n[receiver]',
                    'look_at_m = [0.0, 0.0, 0.0]\nbasis = "circular"\n\n[receiver]')
    text = _replace('channels = ["HH", "HV", "VH", "VV"]', 'channels = ["HR", "VL"]', text)
    rc, _ = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 0


SEA_ON = _replace("sea_clutter = false\n", "sea_clutter = true\n",
                  _replace("n_pulses = 32", "n_pulses = 4"))


@pytest.mark.parametrize(
    ("text", "named"),
    [
        # a point target at the transmitter's / the receiver's position
        (_replace("position_m = [0.0, 0.0, 1.0]", "position_m = [-500.0, 0.0, 300.0]"),
         "[[targets]] 'sphere10'"),
        (_replace("position_m = [0.0, 0.0, 1.0]", "position_m = [200.0, 100.0, 80.0]"),
         "[[targets]] 'sphere10'"),
        # a target whose track passes through the transmitter at pulse 1 (t = 1 ms)
        (_replace("position_m = [-12.0, 20.0, 0.5]\nvelocity_m_s = [7.0, 3.0, 0.0]",
                  "position_m = [-501.0, 0.0, 300.0]\nvelocity_m_s = [1000.0, 0.0, 0.0]"),
         "[[targets]] 'mover'"),
        # an antenna looking at its own position
        (_replace("look_at_m = [0.0, 0.0, 0.0]\n\n[receiver]",
                  "look_at_m = [-500.0, 0.0, 300.0]\n\n[receiver]"),
         "[transmitter].antenna.look_at_m"),
        # a transmitter at the sea surface looking at itself (sea clutter on)
        (_replace("position_m = [-500.0, 0.0, 300.0]", "position_m = [0.0, 0.0, 0.0]", SEA_ON),
         "[transmitter].position_m"),
        # a receiver 5 m below the sea surface (it received sea echo)
        (_replace("position_m = [200.0, 100.0, 80.0]", "position_m = [200.0, 100.0, -5.0]",
                  SEA_ON), "[receiver].position_m"),
        # 1 MHz with sea clutter: the 1 m grid resolves every Bragg wave
        (_replace("carrier_frequency_hz = 10.0e9", "carrier_frequency_hz = 1.000001e6",
                  SEA_ON), "[sea].size_x_m / nx"),
        # nothing to receive
        (CAL[:CAL.index("[[targets]]")], "nothing to receive"),
    ],
)
def test_degenerate_geometry_is_refused_by_check_and_run(tmp_path, capsys, text, named):
    # Each of the first five ran with exit status 0 and wrote NaN/Inf into `raw`
    scene = _scene(tmp_path, text)
    out = tmp_path / "x.nc"
    assert _run_quietly("check", str(scene)) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and named in err, err
    assert _run_quietly("run", str(scene), "-o", str(out), "-q") == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and named in err, err
    assert sorted(tmp_path.iterdir()) == [scene]


@pytest.mark.parametrize(
    ("objects", "named"),
    [
        ('name = "hull"\nfile = "no_such_hull.ply"', "no_such_hull.ply"),
        ('name = "hull"\nfile = "garbage.ply"', "[[objects]] #0 (hull)"),
    ],
)
def test_object_files_the_run_cannot_load_are_refused_by_check(tmp_path, capsys, objects,
                                                                named):
    (tmp_path / "garbage.ply").write_text("not a mesh")
    scene = _scene(tmp_path, SEA_ON + "\n[[objects]]\n" + objects + "\n")
    rc, err = _cli(capsys, "check", str(scene))
    assert rc == 2 and named in err


@pytest.mark.parametrize(
    ("objects", "named"),
    [
        # found by the fuzzing suite: `check` accepted both, `run` refused them
        ('[[objects]]\nname = "hull"\nfile = "m.ply"\nfollow_ship = true\n',
         "needs a [ship]"),
        ('[[objects]]\nname = "a"\nfile = "m.ply"\n[[objects]]\nname = "a"\nfile = "n.ply"\n',
         "must be unique"),
    ],
)
def test_object_consistency_is_in_the_schema(tmp_path, capsys, objects, named):
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, CAL + "\n" + objects)))
    assert rc == 2 and "[[objects]]" in err and named in err


def test_non_finite_pulse_is_exit_2_with_no_file(tmp_path, capsys, monkeypatch):
    # The finite-output guard (seaecho.checks.guards): a NaN that no scene check foresaw stops
    # the run with a message naming the pulse and the scatterer, and leaves no file
    from seaecho.radar.system import RadarSystem

    real = RadarSystem.target_echo

    def echo(self, geometry, *, variant=None):
        e = real(self, geometry, variant=variant)
        if geometry.time >= self.emission_time(2):
            e.amplitudes[:, 2] = np.nan
        return e

    monkeypatch.setattr(RadarSystem, "target_echo", echo)
    scene = _scene(tmp_path, CAL)
    rc, err = _cli(capsys, "run", str(scene), "-o", str(tmp_path / "x.nc"), "-q",
                   "--pulses", "4")
    assert rc == 2 and "pulse 2" in err and 'point target "mover"' in err
    assert sorted(tmp_path.iterdir()) == [scene]


def test_depth_too_shallow_for_the_waves_is_refused(tmp_path, capsys):
    # Found by the fuzzing suite: depth_m = 5e-324 (> 0, allowed) made k d underflow, the
    # wave velocities NaN and the run stop on the finite-output guard
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(
        "nx = 64", "nx = 64\ndepth_m = 5e-324", SEA_ON))))
    assert rc == 2 and "[sea].depth_m = 4.94066e-324" in err and "McCowan" in err


def test_pierson_moskowitz_significant_height():
    """H_s = 0.21 U19.5^2 / g (Pierson & Moskowitz 1964; Stewart 2008, eq 16.26), which
    sets the breaking depth H_s / 0.78 (McCowan 1894) of the depth check."""
    from seaecho.build import sea_spectrum
    from seaecho.config import parse_scene
    from seaecho.constants import G
    from seaecho.ocean.limits import significant_height

    scene = parse_scene({"sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": 12.0,
                                 "size_x_m": 64.0, "nx": 16}})
    assert significant_height(sea_spectrum(scene)) == pytest.approx(0.21 * 12.0**2 / G,
                                                                     rel=0.01)


@pytest.mark.parametrize("spectrum", ["jonswap", "elfouhaily"])
def test_fetch_shorter_than_the_youngest_sea_is_refused(tmp_path, capsys, spectrum):
    # Found by the fuzzing suite: fetch_m = 5e-324 made `check` die in ZeroDivisionError
    # (JONSWAP) or give a NaN crest height (Elfouhaily)
    text = _replace("nx = 64", f'nx = 64\nspectrum = "{spectrum}"\nfetch_m = 5e-324', SEA_ON)
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and "[sea].fetch_m = 4.94066e-324" in err and "Elfouhaily" in err


def test_jonswap_fetch_beyond_full_development_is_refused(tmp_path, capsys):
    # Found by the fuzzing suite: JONSWAP's growth laws keep adding energy with fetch
    # (H_s = 37 m at 19 m/s for 22,000 km); beyond full development the sea is
    # Pierson-Moskowitz's
    text = _replace("wind_speed_m_s = 5.0", 'wind_speed_m_s = 19.0\nspectrum = "jonswap"\n'
                    "fetch_m = 22334041.0", SEA_ON)
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and "[sea].fetch_m = 2.2334e+07" in err and "fully developed" in err


def test_shortest_fetch_is_the_youngest_sea_of_the_fetch_law():
    """Elfouhaily et al. (1997): Omega_c = 0.84 tanh((X / 2.2e4)^0.4)^-0.75 spans 0.84
    (fully developed) to 5 (young); the shortest fetch accepted gives Omega_c = 5."""
    from seaecho.constants import G
    from seaecho.ocean.limits import MIN_DIMENSIONLESS_FETCH
    from seaecho.ocean.spectra import elfouhaily_parameters
    from seaecho.ocean.wind import u10_from_u19_5

    u = 8.0
    u10 = float(u10_from_u19_5(u))
    fetch = MIN_DIMENSIONLESS_FETCH * u10**2 / G
    assert elfouhaily_parameters(u, fetch).omega_c == pytest.approx(5.0, rel=1e-6)


@pytest.mark.parametrize(
    ("ship", "named"),
    [
        # found by the fuzzing suite: `run` died in ZeroDivisionError in the Wigley hull's
        # amplitude (length**2 and speed**2 underflow)
        ("length_m = 1e-252\nbeam_m = 5e-324\ndraft_m = 1.0\nspeed_m_s = 5.0",
         "[ship].length_m = 1e-252"),
        ("length_m = 10.0\nbeam_m = 4.0\ndraft_m = 1.0\nspeed_m_s = 1e-300",
         "speed_m_s = 1e-300"),
        ("length_m = 10.0\nbeam_m = 4.0\ndraft_m = 1.0\nspeed_kn = 0.1", "speed_kn = 0.1"),
        # a 5e-324 m beam made the turbulent wake's edge 0 / 0 (NaN sea facets)
        ("length_m = 1.0\nbeam_m = 5e-324\ndraft_m = 1.0\nspeed_kn = 0.0",
         "beam_m = 4.94066e-324"),
    ],
)
def test_ship_too_small_or_too_slow_for_a_wave_wake(tmp_path, capsys, ship, named):
    text = _replace("[run]", f"[ship]\n{ship}\n\n[run]", SEA_ON)
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and named in err, err


def test_slowest_water_wave():
    """Lamb (1932), art. 268: capillary-gravity waves travel at least (4 g sigma/rho)^(1/4)
    = 0.23 m/s; the minimum of our dispersion relation's phase speed is that speed."""
    from seaecho.config.ship import MIN_WAVE_SPEED_M_S
    from seaecho.ocean.dispersion import angular_frequency

    k = np.geomspace(10.0, 10_000.0, 200_001)
    c_min = float(np.min(angular_frequency(k) / k))
    assert c_min == pytest.approx(MIN_WAVE_SPEED_M_S, rel=0.01)


def test_waypoints_faster_than_any_platform_are_refused(tmp_path, capsys):
    # Found by the fuzzing suite: waypoint times 0 and 2.2e-311 s made the segment's
    # velocity infinite, NaN pointing in `check` and an infinite tx_velocity written by
    # `run` with exit status 0
    text = _replace("position_m = [-500.0, 0.0, 300.0]",
                    'motion = "waypoints"\nwaypoint_times_s = [0.0, 2.225073858507e-311, 3.0]\n'
                    "waypoint_positions_m = [[-500.0, 0.0, 300.0], [-500.0, 0.0, 400.0], "
                    "[-500.0, 0.0, 300.0]]")
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and "[transmitter]: waypoints 0 and 1" in err and "+-10000" in err


@pytest.mark.parametrize(("old", "new", "named"), [
    ('name = "sphere10"', 'name = "sphere\\u000010"', "[targets][0].name"),
    ('name = "calibration_point_target"', 'name = "cal\\u0007"', "name"),
])
def test_control_characters_in_names_are_refused(tmp_path, capsys, old, new, named):
    # Found by the fuzzing suite: a target named with a NUL passed `check`, and `run`
    # died with a traceback writing it ("VLEN strings do not support embedded NULLs")
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(old, new))))
    assert rc == 2 and named in err and "control character" in err


def test_line_breaks_are_allowed_in_the_description(tmp_path, capsys):
    text = _replace('description = "', 'description = "two\\nlines, a\\ttab; ')
    assert _cli(capsys, "check", str(_scene(tmp_path, text)))[0] == 0


@pytest.mark.parametrize("size", ["5e-324", "1e-300", "0.009"])
@pytest.mark.parametrize("command", ["check", "surface"])
def test_tile_below_a_centimetre_is_refused(tmp_path, capsys, size, command):
    # Found by the fuzzing suite: size_x_m = 5e-324 crashed check (infinite wavenumber)
    # and surface (ZeroDivisionError); 1e-300 wrote a NaN surface
    scene = _scene(tmp_path, f"[sea]\nwind_speed_m_s = 5.0\nsize_x_m = {size}\nnx = 4\n")
    extra = ["-o", str(tmp_path / "s.nc")] if command == "surface" else []
    rc, err = _cli(capsys, command, str(scene), *extra)
    assert rc == 2 and "[sea].size_x_m" in err
    assert sorted(tmp_path.iterdir()) == [scene]


def test_refresh_interval_shorter_than_any_pulse_interval_is_refused(tmp_path, capsys):
    # Found by the fuzzing suite: refresh_interval_s = 5e-324 (>= 0, allowed) made
    # floor(t / interval) overflow ("cannot convert float infinity to integer") in `run`
    text = _replace("[transmitter]", "[tracing]\nrefresh_interval_s = 5e-324\n\n[transmitter]",
                    SEA_ON)
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and "refresh_interval_s = 4.94066e-324" in err and "1e-07" in err


@pytest.mark.parametrize(("old", "new", "named"), [
    # an lfm pulse of 5e-324 s: B / T overflowed and the transmitted pulse was NaN
    ("duration_s = 2.0e-6", "duration_s = 5e-324", "bandwidth_hz x duration_s"),
    # a PRF of 5e-324 Hz: the second pulse at t = inf; check died on a NaN
    ("prf_hz = 1000.0", "prf_hz = 5e-324", "the run would last"),
])
def test_waveform_and_pulse_train_extremes(tmp_path, capsys, old, new, named):
    rc, err = _cli(capsys, "check", str(_scene(tmp_path, _replace(old, new))))
    assert rc == 2 and named in err, err


def test_lfm_time_bandwidth_product_of_one_is_accepted(tmp_path, capsys):
    text = _replace("duration_s = 2.0e-6", "duration_s = 1.0e-8")  # B T = 1
    assert _cli(capsys, "check", str(_scene(tmp_path, text)))[0] == 0
