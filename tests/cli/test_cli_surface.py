"""The CLI: `seaecho check`, `seaecho surface`; bad input exits 2 with no traceback or file."""

import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main

ROOT = Path(__file__).resolve().parents[2]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"

SMALL = """
name = "small"
[sea]
spectrum = "elfouhaily"
spreading = "elfouhaily"
wind_speed_m_s = 6.0
size_x_m = 64.0
nx = 64
[ship]
length_m = 10.0
beam_m = 4.0
draft_m = 1.5
speed_kn = 10.0
heading_deg = 35.0
[run]
seed = 7
surface_times_s = [0.0, 0.5]
"""


@pytest.fixture
def small_scene(tmp_path):
    path = tmp_path / "small.toml"
    path.write_text(SMALL)
    return path


def test_check_valid(capsys, tmp_path):
    assert main(["check", str(SIM1)]) == 0
    out = capsys.readouterr().out
    assert "valid scene" in out and "warning" not in out
    # Sim 1 on a 0.125 m grid would leave k h_res = 0.38 > 0.3 at its 10 GHz carrier
    coarse = tmp_path / "sim1_512.toml"
    shutil.copytree(SIM1.parent / "meshes", tmp_path / "meshes")  # its [[objects]]
    text = SIM1.read_text()
    coarse.write_text(text.replace("nx = 648", "nx = 512"))
    assert main(["check", str(coarse)]) == 0
    assert "coarse against the radar wavelength" in capsys.readouterr().out


def test_surface_writes_dataset_and_figure(small_scene, tmp_path):
    out = tmp_path / "s.nc"
    assert main(["surface", str(small_scene), "-o", str(out)]) == 0
    ds = xr.open_dataset(out, engine="h5netcdf")
    assert ds["elevation"].dims == ("time", "y", "x")
    assert ds.sizes == {"time": 2, "y": 64, "x": 64}
    assert ds["x"].attrs["units"] == "m" and ds["time"].attrs["units"] == "s"
    for name in ("wake_elevation", "wake_mask", "slope_x", "slope_y", "velocity_z", "ship_x"):
        assert name in ds
    assert "small" in ds.attrs["scene_json"] and ds.attrs["seaecho_version"]
    # the wake is part of the elevation
    assert float(np.abs(ds["wake_elevation"]).max()) > 0
    assert (tmp_path / "s.png").stat().st_size > 10_000
    assert not list(tmp_path.glob(".*.part"))


def test_surface_same_seed_same_bytes(small_scene, tmp_path):
    a, b = tmp_path / "a.nc", tmp_path / "b.nc"
    main(["surface", str(small_scene), "-o", str(a), "--no-figure"])
    main(["surface", str(small_scene), "-o", str(b), "--no-figure"])
    da = xr.open_dataset(a, engine="h5netcdf")
    db = xr.open_dataset(b, engine="h5netcdf")
    for name in da.data_vars:
        assert da[name].values.tobytes() == db[name].values.tobytes(), name


@pytest.mark.parametrize(
    ("edit", "fragment"),
    [
        (("wind_speed_m_s = 6.0", 'wind_speed_m_s = "six"'), "[sea].wind_speed_m_s"),
        (("wind_speed_m_s = 6.0", "wind_speed_m_s = -6.0"), "greater than or equal to 0.3"),
        (("nx = 64", "nx = 64\ncolour = 1"), "unknown key"),
        (("speed_kn = 10.0", "speed_kn = 100.0"), "[ship].speed_kn"),
    ],
)
def test_bad_scene_exits_2_and_writes_nothing(tmp_path, capsys, edit, fragment):
    scene = tmp_path / "bad.toml"
    scene.write_text(SMALL.replace(*edit))
    out = tmp_path / "bad.nc"
    assert main(["surface", str(scene), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert fragment in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == [scene]


def test_missing_scene_file(tmp_path, capsys):
    assert main(["check", str(tmp_path / "none.toml")]) == 2
    assert "not found" in capsys.readouterr().err


def test_missing_output_directory(small_scene, tmp_path, capsys):
    assert main(["surface", str(small_scene), "-o", str(tmp_path / "no" / "x.nc")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_console_script_exit_status_and_no_traceback(tmp_path):
    scene = tmp_path / "bad.toml"
    scene.write_text(SMALL.replace("nx = 64", "nx = 63"))
    proc = subprocess.run([sys.executable, "-m", "seaecho", "check", str(scene)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert "nx = 63" in proc.stderr and "even" in proc.stderr
    assert "Traceback" not in proc.stderr
