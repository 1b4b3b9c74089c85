"""`seaecho image` and the [image] hook of `seaecho run`: files, reproducibility, errors."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import xarray as xr
from sar_helpers import point_scene, simulate

from seaecho.cli import main

TARGET = (2.0, -1.5, 0.0)


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    scene = point_scene([{"position_m": TARGET, "rcs_m2": 10.0}], n_pulses=48)
    return simulate(scene, tmp_path_factory.mktemp("cli") / "raw.nc")


def test_image_writes_dataset_and_figures_reproducibly(raw, tmp_path, capsys):
    out = tmp_path / "img.nc"
    args = ["image", raw, "-o", str(out), "--pixel-m", "0.25", "--extent", "-6", "8", "-8",
            "6", "-q"]
    assert main(args) == 0
    printed = capsys.readouterr().out
    assert "wrote" in printed and "pixel-pulses/s" in printed
    assert "estimated peak memory" in printed and "3136 image pixels" in printed
    for suffix in ("_rcs.png", "_pauli.png"):
        assert (tmp_path / f"img{suffix}").stat().st_size > 1000
    with xr.open_dataset(out, engine="h5netcdf") as img:
        assert img["image"].dims == ("channel", "y", "x")
        assert img.sizes["x"] == 56 and img.sizes["y"] == 56
        assert img.attrs["track"] == "nominal" and "calibration" in img.attrs
        hh = np.abs(img["image"].sel(channel="HH").values) ** 2
        iy, ix = np.unravel_index(np.argmax(hh), hh.shape)
        # the brightest pixel is the target's (pixel 0.25 m), its value its RCS (0.5 dB:
        # the pixel centre is up to 0.18 m from the peak)
        assert abs(img["x"].values[ix] - TARGET[0]) <= 0.25
        assert abs(img["y"].values[iy] - TARGET[1]) <= 0.25
        assert 10 * np.log10(hh.max()) == pytest.approx(10.0, abs=0.5)
        np.testing.assert_allclose(img["target_position"].values[0], TARGET)
    # Same input, same bytes
    out2 = tmp_path / "img2.nc"
    assert main(args[:3] + [str(out2)] + args[4:] + ["--no-figures"]) == 0
    assert out.read_bytes() == out2.read_bytes()


@pytest.mark.parametrize("extra, message", [
    (["--extent", "5", "-5", "0", "1"], "[image]: extent_m = [5.0, -5.0, 0.0, 1.0]"),
    (["--pixel-m", "1e-4"], "more than"),
    (["--pixel-m", "-1"], "[image].pixel_m = -1.0"),
    (["--filter-size", "4"], "filter_size = 4: must be odd"),
    # one pixel wide: the image measures died after the file was written (a traceback)
    (["--extent", "0", "0.5", "0", "4", "--pixel-m", "0.5"], "8 x 1 pixels; it needs at "
     "least 2 x 2"),
])
def test_image_rejects_bad_options(raw, tmp_path, capsys, extra, message):
    out = tmp_path / "bad.nc"
    assert main(["image", raw, "-o", str(out), "-q", *extra]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_image_alone_refuses_what_cannot_fit_in_memory(raw, tmp_path, capsys):
    # `seaecho image` runs the pixel-count memory estimate as `seaecho run` does: 0.002 m
    # pixels over the targets' default box are 4000 x 4000 pixels (16 million, under the
    # focusing's 4096^2), 13 GiB of maps and products: exit 2 naming the fields, no file
    out = tmp_path / "big.nc"
    args = ["image", raw, "-o", str(out), "-q", "--pixel-m", "0.002", "--extent", "-4", "4",
            "-4", "4", "--max-memory-gb", "1"]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert "the image does not fit in memory: [image].pixel_m = 0.002" in err
    assert "16000000 image pixels" in err and "--pixel-m, --extent" in err
    assert "limit 0.931 GiB, --max-memory-gb" in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []
    args[6] = "0.0019"  # 4211 x 4211: more than the focusing takes, whatever the memory
    assert main(args[:-1] + ["1000"]) == 2
    err = capsys.readouterr().err
    assert "[image].pixel_m = 0.0019" in err and "17732521 pixels, more than 16777216" in err
    assert list(tmp_path.iterdir()) == []


def test_image_estimate_counts_the_pixels_the_focusing_makes(raw):
    # Parity: the estimate's pixel count is ImageGrid.from_extent's, for a given extent and
    # for the default one (the targets' box plus 20 range resolutions, a quarter of the
    # range resolution per pixel)
    from seaecho.api import image_config
    from seaecho.checks.resources import IMAGE_PANELS, image_estimate
    from seaecho.imaging.focus import ImageGrid, RawData

    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        rd = RawData(ds)
        for fields in ({}, {"pixel_m": 0.3, "extent_m": (-5.0, 7.0, -2.0, 2.5)}):
            cfg = image_config(ds, **fields)
            pixel = cfg.pixel_m or 3e8 / (8 * rd.bandwidth)
            grid = ImageGrid.from_extent(cfg.extent_m or rd.default_extent(), pixel)
            est = image_estimate(ds, cfg, figures=True)
            assert est.pixels == grid.shape[0] * grid.shape[1]
            assert est.channels == 4 and est.n_pulses == 48
            panels = IMAGE_PANELS if cfg.figures else 0
            assert est.terms["image"] >= (120 + 160 * 4 + 60 * panels) * est.pixels


def test_image_rejects_files_that_are_not_raw_datasets(raw, tmp_path, capsys):
    assert main(["image", str(tmp_path / "none.nc"), "-q"]) == 2
    assert "does not exist" in capsys.readouterr().err
    junk = tmp_path / "junk.nc"
    junk.write_text("not netcdf")
    assert main(["image", str(junk), "-q"]) == 2
    assert "not a readable netCDF" in capsys.readouterr().err
    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        old = ds.drop_vars(["tx_antenna_axes", "tx_antenna_axes_nominal"]).load()
    old_path = tmp_path / "old.nc"
    with warnings.catch_warnings():  # h5netcdf's notice on complex variables
        warnings.simplefilter("ignore", UserWarning)
        old.to_netcdf(old_path, engine="h5netcdf", invalid_netcdf=True)
    assert main(["image", str(old_path), "-o", str(tmp_path / "o.nc"), "-q"]) == 2
    err = capsys.readouterr().err
    assert "missing tx_antenna_axes" in err and "Traceback" not in err
    assert not (tmp_path / "o.nc").exists()
    assert main(["image", raw, "-o", raw, "-q"]) == 2
    assert "overwrite" in capsys.readouterr().err


SCENE = """
[sea]
wind_speed_m_s = 5.0
size_x_m = 32.0
nx = 32

[radar]
carrier_frequency_hz = 1.0e10
sampling_rate_hz = 180.0e6
prf_hz = 500.0
n_pulses = 16
start_time_s = -0.015
sea_clutter = false
window_start_m = 670.0
window_end_m = 750.0
[radar.waveform]
kind = "lfm"
bandwidth_hz = 150.0e6
duration_s = 4.0e-6

[transmitter]
motion = "linear"
position_m = [-500.0, 0.0, 500.0]
velocity_m_s = [0.0, 100.0, 0.0]
[transmitter.antenna]
pattern = "isotropic"
azimuth_deg = -90.0
depression_deg = 45.0

[[targets]]
position_m = [2.0, -1.5, 0.0]
rcs_m2 = 10.0

[image]
pixel_m = 0.5
extent_m = [-4.0, 4.0, -4.0, 4.0]
azimuth_window = "hamming"
figures = false
"""


def test_run_focuses_when_the_scene_has_an_image_section(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(SCENE)
    out = tmp_path / "r.nc"
    assert main(["run", str(path), "-o", str(out), "-q", "--no-figures"]) == 0
    assert "r_image.nc" in capsys.readouterr().out
    with xr.open_dataset(tmp_path / "r_image.nc", engine="h5netcdf") as img:
        assert img.attrs["azimuth_window"] == "hamming" and img.sizes["x"] == 16


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
@pytest.mark.parametrize("backend", ["drjit", "numpy"])
def test_a_processed_doppler_band_of_5e_324_hz_is_clean(raw, tmp_path, backend):
    # Found by the fuzzing suite: 1 / B_a overflows to inf, and the Doppler offsets of
    # eq (B4) with it (RuntimeWarnings from the window and the numpy kernel); the offsets
    # are then outside the band: here no pulse is weighted, K = 0 and the image is NaN,
    # undefined, at every pixel
    from seaecho.checks.guards import image_problems

    out = tmp_path / "img.nc"
    assert main(["image", raw, "-o", str(out), "-q", "--no-figures", "--backend", backend,
                 "--pixel-m", "0.5", "--doppler-bandwidth-hz", "5e-324"]) == 0
    with xr.open_dataset(out, engine="h5netcdf") as img:
        assert image_problems(img.load()) == []
