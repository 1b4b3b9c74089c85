"""``seaecho trace`` and ``seaecho compare`` end to end on a small scene with a hull."""

import csv
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main

HULL = Path(__file__).resolve().parents[2] / "scenes" / "meshes" / "motor_boat_10m.ply"

SCENE = f"""
name = "cli-trace"
[sea]
spectrum = "pierson-moskowitz"
wind_speed_m_s = 8.0
size_x_m = 64.0
nx = 48
[ship]
length_m = 10.0
beam_m = 4.0
draft_m = 1.5
speed_kn = 10.0
heading_deg = 35.0
[[objects]]
name = "boat"
file = "{HULL}"
follow_ship = true
"""


@pytest.fixture
def scene_file(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(SCENE)
    return p


def test_trace_writes_dataset_and_maps(scene_file, tmp_path, capsys):
    out = tmp_path / "facets.nc"
    rc = main(["trace", str(scene_file), "-o", str(out), "--tx", "-200", "-150", "25",
               "--rx", "150", "-180", "15", "--time", "0.5", "--frequency-ghz", "10"])
    assert rc == 0
    assert out.exists() and out.with_suffix(".png").exists()
    with xr.open_dataset(out, engine="h5netcdf") as f:
        ds = f.load()
    assert ds.sizes == {"y_cell": 47, "x_cell": 47, "triangle": 2, "xyz": 3, "pol_to": 2,
                        "pol_from": 2}
    assert ds.attrs["facet_mode"] == "raytraced" and ds.attrs["time_s"] == 0.5
    assert ds["r_tx"].dtype == np.float64 and ds["theta_i"].attrs["units"] == "rad"
    # the hull sits at the tile centre: the facets under it are neither lit nor seen
    c = ds["centroid"].values.reshape(-1, 3)
    under = np.hypot(c[:, 0], c[:, 1]) < 1.0
    assert ds["visibility"].values.ravel()[under].max() == 0.0
    assert "lit from Tx" in capsys.readouterr().out


def test_compare_writes_table_and_figures(scene_file, tmp_path):
    out = tmp_path / "cmp"
    rc = main(["compare", str(scene_file), "-o", str(out), "--tx", "-200", "-150", "25",
               "--frequency-ghz", "10"])
    assert rc == 0
    with open(out / "compare.csv", newline="") as fh:
        rows = {r["quantity"]: r for r in csv.DictReader(fh)}
    for key in ("lit_fraction_tx", "seen_fraction_rx", "visible_fraction",
                "theta_i_difference_rms", "sigma_sum_VV_db"):
        assert key in rows
    # monostatic: seen = lit in both modes
    assert rows["lit_fraction_tx"]["raytraced"] == rows["seen_fraction_rx"]["raytraced"]
    assert 0 < float(rows["lit_fraction_tx"]["raytraced"]) < 1
    assert (out / "compare_visibility.png").exists() and (out / "compare_angles.png").exists()


def test_bad_input_exits_2(scene_file, tmp_path, capsys):
    assert main(["trace", str(scene_file), "-o", str(tmp_path / "a.nc")]) == 2
    assert "no [transmitter]" in capsys.readouterr().err
    assert main(["trace", str(scene_file), "-o", str(tmp_path / "a.nc"),
                 "--rx", "1", "2", "3"]) == 2
    assert main(["trace", str(scene_file), "-o", str(tmp_path / "nodir" / "a.nc"),
                 "--tx", "0", "0", "100"]) == 2
    assert not (tmp_path / "a.nc").exists()


def test_scene_without_radar_needs_a_frequency(scene_file, tmp_path, capsys):
    # No [radar], no --frequency-ghz: no carrier is assumed (the sea water's permittivity
    # and the two-scale split depend on it); exit 2 with a message, no file.
    capsys.readouterr()
    for cmd in (["trace", str(scene_file), "-o", str(tmp_path / "a.nc")],
                ["compare", str(scene_file), "-o", str(tmp_path / "cmp")]):
        assert main(cmd + ["--tx", "-200", "-150", "25"]) == 2
        err = capsys.readouterr().err
        assert "no [radar]" in err and "--frequency-ghz" in err and "Traceback" not in err
    assert not (tmp_path / "a.nc").exists() and not (tmp_path / "cmp").exists()
