"""``seaecho.simulate``: the same dataset as ``seaecho run`` (bytes), in memory or on disk.

The in-memory dataset goes through the pulse loop of ``seaecho.io.run`` that writes the
file (one implementation): these are parity tests between the two routes, on a scene that
exercises every random stream (surface, speckle, noise) and a point target.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaecho
from seaecho.cli import main
from seaecho.config import SceneError

#: A gentle sea (U19.5 = 3 m/s: the 8.8 m tile holds the 8.2 m peak wavelength and its
#: 0.08 m grid keeps k h = 0.24 < 0.3 at 10 GHz, so no sampling warning), ray traced,
#: bistatic, thermal noise on, the surface renewed every two pulses (so it evolves between,
#: the default "auto"), one point target.
SCENE = """
name = "api-parity"
[sea]
spectrum = "pierson-moskowitz"
spreading = "longuet-higgins"
wind_speed_m_s = 3.0
size_x_m = 8.8
nx = 110
[run]
seed = 5
[radar]
carrier_frequency_hz = 10.0e9
sampling_rate_hz = 200.0e6
prf_hz = 1000.0
n_pulses = 3
sea_update_pulses = 2
thermal_noise = true
[radar.waveform]
kind = "lfm"
bandwidth_hz = 100.0e6
duration_s = 1.0e-6
[transmitter]
position_m = [-642.8, 0.0, 766.0]
[transmitter.antenna]
pattern = "isotropic"
look_at_m = [0.0, 0.0, 0.0]
[receiver]
position_m = [300.0, 200.0, 150.0]
[receiver.antenna]
pattern = "isotropic"
look_at_m = [0.0, 0.0, 0.0]
[[targets]]
name = "buoy"
position_m = [2.0, 1.0, 0.5]
rcs_m2 = 1.0
"""


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("api") / "parity.toml"
    path.write_text(SCENE)
    return path


@pytest.fixture(scope="module")
def cli_run(scene_file):
    out = scene_file.with_name("cli.nc")
    assert main(["run", str(scene_file), "-o", str(out), "-q", "--no-figures"]) == 0
    return xr.load_dataset(out, engine="h5netcdf")


def _assert_same(a: xr.Dataset, b: xr.Dataset) -> None:
    assert set(a.variables) == set(b.variables)
    for name in a.variables:
        va, vb = a[name].values, b[name].values
        if va.dtype.kind in "OUS":  # strings: the file gives objects, memory unicode
            assert va.tolist() == vb.tolist(), name
        else:
            assert va.dtype == vb.dtype, name
            assert va.tobytes() == vb.tobytes(), name
        assert a[name].dims == b[name].dims, name
        assert a[name].attrs.keys() == b[name].attrs.keys(), name
    assert a.attrs.keys() == b.attrs.keys()
    for key, value in a.attrs.items():
        np.testing.assert_array_equal(value, b.attrs[key], err_msg=key)


def test_in_memory_run_is_the_cli_file_byte_for_byte(scene_file, cli_run):
    ds = seaecho.simulate(seaecho.load_scene(scene_file), progress=False)
    assert ds.sizes["pulse"] == 3 and ds["raw"].dtype == np.complex128
    assert np.abs(ds["raw"].values).max() > 0 and "sigma0" in ds
    _assert_same(ds, cli_run)
    # the same scene given as text (no file): the same bytes
    again = seaecho.simulate(seaecho.parse_scene(SCENE), progress=False)
    assert again["raw"].values.tobytes() == ds["raw"].values.tobytes()


def test_streamed_run_is_the_cli_file(scene_file, cli_run, tmp_path):
    path = tmp_path / "api.nc"
    with seaecho.simulate(seaecho.load_scene(scene_file), path=path, progress=False) as ds:
        assert ds["raw"].chunks is None  # opened lazily, not loaded
        _assert_same(ds.load(), cli_run)
    assert not list(tmp_path.glob(".*.part"))


def test_first_pulses_and_overrides(scene_file, cli_run):
    scene = seaecho.with_overrides(seaecho.load_scene(scene_file),
                                   {"radar.thermal_noise": False})
    ds = seaecho.simulate(scene, pulses=2, progress=False)
    assert ds.sizes["pulse"] == 2
    # without noise the echoes differ from the noisy run's, and the scene says so
    assert not np.array_equal(ds["raw"].values, cli_run["raw"].values[:2])
    assert '"thermal_noise": false' in ds.attrs["scene_json"]


def test_a_run_too_large_for_memory_is_refused_before_any_work(scene_file):
    scene = seaecho.load_scene(scene_file)
    with pytest.raises(SceneError, match=r"3 pulses x 4 channels x \d+ samples.*path="):
        seaecho.simulate(scene, max_memory_bytes=1000.0)
    with pytest.raises(SceneError, match="max_memory_bytes"):
        seaecho.simulate(scene, max_memory_bytes=-1)


@pytest.mark.parametrize(("call", "message"), [
    (lambda s: seaecho.simulate(seaecho.with_overrides(s, {"radar.n_pulses": 2}),
                                pulses=0), "pulses = 0"),
    (lambda s: seaecho.simulate("scene.toml"), "seaecho.load_scene"),
    (lambda s: seaecho.simulate(seaecho.parse_scene("[sea]\nwind_speed_m_s = 5.0\n"
                                                    "size_x_m = 64.0\nnx = 64\n")),
     "needs \\[radar\\] and \\[transmitter\\]"),
    (lambda s: seaecho.simulate(s, path="/nonexistent/dir/run.nc"), "does not exist"),
])
def test_bad_input_is_named(scene_file, call, message):
    with pytest.raises(SceneError, match=message):
        call(seaecho.load_scene(scene_file))


def test_image_of_the_dataset_is_the_image_of_the_file(tmp_path):
    # A stripmap SAR over point targets without sea (cheap): the focused image of the
    # in-memory run and of the same run read from its file are the same bytes.
    scene = seaecho.parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 32.0, "nx": 32},
        "radar": {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 180e6, "prf_hz": 500.0,
                  "n_pulses": 24, "start_time_s": -0.023, "sea_clutter": False,
                  "channels": ["HH", "VV"], "window_start_m": 667.0, "window_end_m": 747.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 150e6, "duration_s": 4e-6}},
        "transmitter": {"motion": "linear", "position_m": (-500.0, 0.0, 500.0),
                        "velocity_m_s": (0.0, 100.0, 0.0),
                        "antenna": {"pattern": "isotropic", "azimuth_deg": -90.0,
                                    "depression_deg": 45.0}},
        "targets": [{"position_m": (1.0, 0.5, 0.0), "rcs_m2": 1.0}],
    })
    ds = seaecho.simulate(scene, progress=False)
    seaecho.save(ds, tmp_path / "raw.nc")
    fields = {"pixel_m": 0.5, "extent_m": [-3.0, 5.0, -4.0, 4.0]}
    a = seaecho.image(ds, backend="numpy", **fields)
    b = seaecho.image(tmp_path / "raw.nc", backend="numpy", **fields)
    assert a["image"].values.tobytes() == b["image"].values.tobytes()
    with pytest.raises(SceneError, match=r"\[image\].pixel_m = -1"):
        seaecho.image(ds, pixel_m=-1)


def test_figures_of_a_run_and_refusals(scene_file, cli_run, tmp_path):
    # the command line's figures of the run (the same names seaecho run writes)
    paths = seaecho.figures(cli_run, tmp_path / "run")
    assert sorted(p.name for p in paths) == ["run_compressed.png", "run_elevation.png",
                                             "run_sigma.png", "run_signal.png"]
    with pytest.raises(SceneError, match="neither a run"):
        seaecho.figures(xr.Dataset(), tmp_path / "x")
    with pytest.raises(SceneError, match="does not exist"):
        seaecho.figures(cli_run, tmp_path / "nowhere" / "run")
    with pytest.raises(SceneError, match="variable = 'sigma0_filtered'"):
        seaecho.image_measures(xr.Dataset(), "sigma0_filtered")
