"""scenes/coastal_traffic_xband.toml end to end (slow): the run writes the truth of every
ship and target, the PPI product and figure; the identical launches share one trace; the
turning fishing boat is where its route puts it (docs/targets.md)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "coastal_traffic_xband.toml"


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore")
def test_traffic_scene_runs_end_to_end(tmp_path, monkeypatch):
    monkeypatch.setenv("SEAECHO_CACHE", "off")
    out = tmp_path / "t.nc"
    assert main(["run", str(SCENE), "-o", str(out), "--pulses", "30", "-q"]) == 0
    assert (tmp_path / "t_ppi.nc").is_file()
    assert (tmp_path / "t_ppi_sweep_0.png").is_file()
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        names = list(ds["object"].values.astype(str))
        assert names == ["coaster", "pilot-1", "pilot-2", "fishing", "buoy-1", "buoy-2",
                         "dinghy", "yacht", "debris"]
        assert list(ds["object_kind"].values.astype(str)) == ["ship"] * 4 + ["target"] * 5
        # pilot-2 takes pilot-1's trace (the same hull at the same aspect)
        assert (ds["hull_trace_hull"].values[2] == 1).all()
        assert (ds["hull_trace_hull"].values[[0, 1, 3]] == np.array([[0], [1], [3]])).all()
        # the fishing boat: 8 kn east from (60, -100), turning 90 deg to port at 2 deg/s
        # (radius r = V / omega) round the corner at (178, -100): the turn starts r
        # before the corner (the tangent distance r tan 45 deg), d = 118 - r after t = 0
        t = ds["time"].values
        v, omega = 8 * 1852 / 3600, np.radians(2.0)
        r = v / omega
        d = 118.0 - r
        s = v * t
        u = np.maximum(s - d, 0.0) / r  # the angle turned
        expected = np.stack([60.0 + np.minimum(s, d) + r * np.sin(u),
                             -100.0 + r * (1 - np.cos(u))], -1)
        np.testing.assert_allclose(ds["truth_position"].values[:, 3, :2], expected,
                                   atol=1e-6)
        assert np.isfinite(ds["compressed"].values).all()
