"""`seaecho doppler`: range-Doppler product of a run; bad input exits 2 with no file."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main
from seaecho.config import parse_scene
from seaecho.simulation import Simulation
from seaecho.warnings import ValidityWarning

ISO = {"pattern": "isotropic", "look_at_m": (0.0, 0.0, 0.0)}


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    # A moving point target in a tiny evolving sea: its Doppler line must come out at
    # f_D = 2 v_r / lambda (monostatic, approaching: v_r > 0).
    sc = parse_scene({
        "sea": {"wind_speed_m_s": 4.0, "size_x_m": 8.0, "nx": 16},
        "scattering": {"sea_motion": "evolving"},
        "tracing": {"mode": "analytic"},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 60e6, "prf_hz": 1000.0,
                  "n_pulses": 16, "sea_update_pulses": 8, "channels": ["HH", "VV"],
                  "waveform": {"kind": "lfm", "bandwidth_hz": 50e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": (300.0, 0.0, 300.0), "antenna": ISO},
        "targets": [{"position_m": (0.0, 0.0, 1.0), "velocity_m_s": (3.0, 0.0, 0.0),
                     "rcs_m2": 10.0}],
    })
    path = tmp_path_factory.mktemp("dop") / "run.nc"
    with warnings.catch_warnings():  # a coarse grid for speed: k h > 0.3 here
        warnings.simplefilter("ignore", ValidityWarning)
        Simulation(sc).run(path, progress=False)
    return path


def test_doppler_product_and_figure(raw, tmp_path, capsys):
    out = tmp_path / "d.nc"
    assert main(["doppler", str(raw), "-o", str(out), "--cpi", "8"]) == 0
    assert "centroid" in capsys.readouterr().out
    assert out.with_suffix(".png").stat().st_size > 1000
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds.sizes["doppler"] == 8 and list(ds["channel"].values) == ["HH", "VV"]
        assert ds["range_doppler"].dims == ("channel", "doppler", "range")
        assert ds.attrs["sea_motion"] == "evolving"
        # the target dominates its range cell: its line at 2 v_r / lambda
        # (v_r = 3 m/s x sin 45 deg towards the radar: 141.5 Hz), within one bin
        rd = ds["range_doppler"].values[0]
        cell = np.argmax(rd.sum(axis=0))
        f = ds["doppler"].values[np.argmax(rd[:, cell])]
        assert f == pytest.approx(2 * 3.0 * np.sqrt(0.5) / (299792458.0 / 10e9), abs=125.0)


def test_bad_input_exits_2_without_output(tmp_path, capsys):
    out = tmp_path / "d.nc"
    assert main(["doppler", str(tmp_path / "missing.nc"), "-o", str(out)]) == 2
    xr.Dataset({"a": ("x", np.arange(3.0))}).to_netcdf(tmp_path / "other.nc",
                                                       engine="h5netcdf")
    assert main(["doppler", str(tmp_path / "other.nc"), "-o", str(out)]) == 2
    assert "missing compressed" in capsys.readouterr().err
    assert not out.exists()
