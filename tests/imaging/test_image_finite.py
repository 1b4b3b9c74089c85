"""A focused image never holds Inf, nor NaN but at its undefined pixels: what the fuzzing
suite found, and the finite-output guard on images (``seaecho.checks.guards.check_image``)."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from seaecho.checks.guards import NonFiniteEchoError, check_image, image_problems
from seaecho.cli import main

#: Shrunk from a scene of the fuzzing suite (tests/fuzz/test_fuzz_valid.py) that `check`
#: accepted: a transmitter at rest, four linear channels, [image] with its defaults. The
#: aperture does not turn, so A_eff (eq K3) and sigma0 are undefined; A_eff was written
#: as 0 instead of NaN, and the Pauli powers / A_eff as +Inf (the refined Lee filter of
#: those then overflowed too).
AT_REST = """
[sea]
wind_speed_m_s = 5.0
size_x_m = 8.0
nx = 8

[transmitter]
position_m = [280.0, 0.0, 2100.0]
[transmitter.antenna]
pattern = "isotropic"
look_at_m = [0.0, 0.0, 0.0]

[[targets]]
position_m = [0.0, 0.0, 0.0]
rcs_m2 = 1.0

[radar]
carrier_frequency_hz = 1.0e9
sampling_rate_hz = 1.0e7
prf_hz = 100.0
sea_clutter = false
channels = ["HH", "HV", "VH", "VV"]
[radar.waveform]
duration_s = 1e-07
bandwidth_hz = 1.0e7

[image]
speckle_filter = "refined-lee"
figures = false
"""


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_image_of_a_platform_at_rest_has_undefined_not_infinite_products(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(AT_REST)
    assert main(["run", str(scene), "-o", str(tmp_path / "r.nc"), "-q", "--no-figures"]) == 0
    assert "wrote" in capsys.readouterr().out
    with xr.open_dataset(tmp_path / "r_image.nc", engine="h5netcdf") as img:
        img = img.load()
    assert image_problems(img) == []
    for name in ("resolution_area", "sigma0", "pauli"):  # undefined: NaN, not 0 or Inf
        assert np.isnan(img[name].values).all(), name
    assert np.isfinite(img["pauli_filtered"].values).all()
    # the calibrated image is still defined: the target's RCS at its peak (eq K2)
    hh = np.abs(img["image"].sel(channel="HH").values) ** 2
    assert np.isfinite(hh).all() and 10 * np.log10(hh.max()) == pytest.approx(0.0, abs=1.0)


def _image(**over) -> xr.Dataset:
    """A 2 x 3 image dataset with the variables the guard reads."""
    gain = np.array([[1.0, 1.0, 0.0], [1.0, 1.0, 1.0]])
    area = np.array([[2.0, 2.0, np.nan], [2.0, np.nan, 2.0]])
    s = np.ones((2, 2, 3), dtype=complex)
    s[:, 0, 2] = np.nan  # K = 0
    sigma0 = np.abs(s) ** 2 / area
    truth = np.ones((2, 2, 3))
    truth[:, :, 0] = np.nan  # outside the tile
    truth[1] = np.nan  # a circular channel: not in the raw's (linear) sigma map
    data = {"image": s, "sigma0": sigma0, "gain": gain, "resolution_area": area,
            "pauli": np.stack([sigma0[0]] * 3), "sigma0_truth": truth,
            "tile": np.array([[0, 1, 1], [0, 1, 1]], dtype=np.uint8),
            "valid": np.array([[1, 0, 0], [1, 1, 1]], dtype=np.uint8)}
    data.update(over)
    dims = {2: ("y", "x"), 3: ("channel", "y", "x")}
    ds = xr.Dataset({k: (dims[np.ndim(v)] if k != "pauli" else ("component", "y", "x"), v)
                     for k, v in data.items()},
                    coords={"channel": ["HH", "RR"],
                            "polarisation": ["HH", "HV", "VH", "VV"]})
    return ds


def test_guard_accepts_nan_only_at_undefined_pixels():
    check_image(_image())  # every NaN above marks an undefined pixel
    bad = _image()
    bad["sigma0"].values[0, 1, 1] = np.inf
    bad["gain"].values[1, 0] = np.nan
    sigma0 = bad["sigma0"].values.copy()
    sigma0[0, 0, 0] = np.nan  # A_eff is defined there
    bad["sigma0"].values[:] = sigma0
    bad["sigma0_truth"].values[0, 0, 1] = np.nan  # inside the tile, a linear channel
    found = image_problems(bad)
    assert found == ["sigma0 (1 Inf and 1 NaN of 12 values at defined pixels)",
                     "gain (1 NaN of 6 values)",
                     "sigma0_truth (1 NaN of 12 values at defined pixels)"]
    with pytest.raises(NonFiniteEchoError, match=r"image of raw\.nc: non-finite values in "
                       r"sigma0 \(1 Inf"):
        check_image(bad, "raw.nc")
    # a calibrated product past float64 is NaN at a pixel without data (valid = 0), and
    # only there
    filtered = np.ones((2, 2, 3))
    filtered[:, 0, 1] = np.nan  # valid = 0
    check_image(_image(sigma0_filtered=filtered))
    filtered[0, 1, 1] = np.nan  # valid = 1
    assert image_problems(_image(sigma0_filtered=filtered)) == [
        "sigma0_filtered (1 NaN of 12 values at defined pixels)"]


def test_an_image_with_inf_stops_the_run_and_leaves_no_file(tmp_path, capsys, monkeypatch):
    # The last line of defence: whatever overflows to Inf in a focusing is not written,
    # exit 2, and the run's raw file (and figures) go with it: no partial output
    from test_cli_image import SCENE  # a moving platform, one target, [image]

    import seaecho.api

    focus = seaecho.api.image

    def overflowing(*a, **k):
        img = focus(*a, **k)
        img["sigma0"].values[0, 0, 0] = np.inf
        return img

    monkeypatch.setattr(seaecho.api, "image", overflowing)
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE.replace("figures = false", "figures = true"))
    rc = main(["run", str(scene), "-o", str(tmp_path / "r.nc"), "-q"])
    err = capsys.readouterr().err
    assert rc == 2 and "Traceback" not in err
    assert "image of " in err and "r.nc: non-finite values in sigma0 (1 Inf of" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
    raw = tmp_path / "raw.nc"  # `seaecho image` alone: the same refusal, no image file
    monkeypatch.setattr(seaecho.api, "image", focus)
    assert main(["run", str(scene), "-o", str(raw), "-q", "--no-figures"]) == 0
    (tmp_path / "raw_image.nc").unlink()
    monkeypatch.setattr(seaecho.api, "image", overflowing)
    assert main(["image", str(raw), "-o", str(tmp_path / "img.nc"), "-q"]) == 2
    assert "non-finite values in sigma0" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["raw.nc", "s.toml"]


@pytest.mark.parametrize("power_w", [5e-324, pytest.param(1e-200, marks=pytest.mark.slow)])
def test_image_does_not_depend_on_the_transmit_power(tmp_path, power_w):
    # s = I / K (eqs B2, K2): I and K are both proportional to sqrt(P_t), so the
    # calibrated image of a point target is its scattering amplitude whatever P_t. Found
    # by the fuzzing suite: at 5e-324 W the echoes (1e-170 sqrt(W)) flushed to zero in
    # the backprojection's float32 samples and the image of a target was 0
    from sar_helpers import point_scene, simulate

    from seaecho.api import image

    target = [{"position_m": (2.0, -1.5, 0.0), "rcs_m2": 10.0}]
    grid = {"pixel_m": 0.5, "extent_m": (-2.0, 6.0, -6.0, 3.0)}
    ref = image(simulate(point_scene(target, n_pulses=16), tmp_path / "ref.nc"), **grid)
    weak = image(simulate(point_scene(target, n_pulses=16, transmit_power_w=power_w),
                          tmp_path / "weak.nc"), **grid)
    s0, s1 = ref["image"].values, weak["image"].values
    assert 10 * np.log10(np.abs(s0).max() ** 2) == pytest.approx(10.0, abs=1.0)
    np.testing.assert_allclose(s1, s0, rtol=0, atol=1e-5 * np.abs(s0).max())
    # so are A_eff and sigma0 (eq K3: K^2 of 1e-340 underflowed, sigma0 was undefined)
    for name in ("resolution_area", "sigma0"):
        a0, a1 = ref[name].values, weak[name].values
        assert np.isfinite(a0).all()
        np.testing.assert_allclose(a1, a0, rtol=1e-4, atol=1e-5 * np.abs(a0).max())
    assert image_problems(weak) == []


def test_noise_equivalent_rcs_bound_against_the_image_noise(tmp_path):
    # image_noise_rcs is k T0 F B_n / N_s / (N_p A^2) (Skolnik 2008, eq 1.8, and eq K1)
    # with the gains at their bound 10 and the ranges at the platform's height: on the
    # broadside stripmap of isotropic antennas (G = 1) at 500 m height and 707 m slant
    # range, the image's measured noise |s|^2 is that bound times 10^2 (gains) times
    # (707 / 500)^4 = 4 (ranges): 400, to the noise's sampling error
    from sar_helpers import point_scene, simulate

    from seaecho.api import image
    from seaecho.checks.preflight import image_noise_rcs

    grid = {"pixel_m": 0.5, "extent_m": (-4.0, 4.0, -4.0, 4.0)}
    scene = point_scene([{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 1e-12}], n_pulses=16,
                        thermal_noise=True, transmit_power_w=1e-3, image=grid)
    img = image(simulate(scene, tmp_path / "noise.nc"))
    measured = float(np.mean(np.abs(img["image"].values) ** 2))
    assert measured / image_noise_rcs(scene) == pytest.approx(400.0, rel=0.2)


def test_an_image_of_noise_beyond_float32_is_refused_by_check(tmp_path, capsys):
    # Found by the fuzzing suite: a 5e-324 W transmitter with thermal noise; the image's
    # noise calibrates to 1e300+ m^2 (s = I / K, K of sqrt(5e-324 W)), which no image can
    # hold: check and run refuse it by name, before anything is written
    from test_cli_image import SCENE

    scene = tmp_path / "s.toml"
    scene.write_text(SCENE.replace("prf_hz = 500.0", "prf_hz = 500.0\nthermal_noise = "
                                   "true\ntransmit_power_w = 5e-324"))
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "r.nc"), "-q"] if command == "run" else []
        assert main([command, str(scene), *extra]) == 2
        err = capsys.readouterr().err
        assert "[radar].transmit_power_w = 5e-324" in err and "noise-equivalent" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
    scene.write_text(SCENE.replace("prf_hz = 500.0", "prf_hz = 500.0\nthermal_noise = "
                                   "true\ntransmit_power_w = 1e-20"))
    assert main(["check", str(scene)]) == 0  # 1e-20 W: noise of 1e19 m^2 at least, held
    # a noise bandwidth of 5e-324 Hz: k T0 B_n underflows, its logarithm does not (a
    # divide-by-zero in log10, found by the fuzzing suite's mutations)
    scene.write_text(SCENE.replace("prf_hz = 500.0", "prf_hz = 500.0\nthermal_noise = "
                                   "true\nnoise_bandwidth_hz = 5e-324"))
    assert main(["check", str(scene)]) == 0


#: A scene `check` accepts whose image's noise calibrates beyond float32: a 5e-43 W
#: transmitter (its noise-equivalent RCS bound, 9e29 m^2, is under the preflight's 1e30)
#: at 100 m height and 1.5 km range, its 3 m aperture pointed 1.5 deg off the image
#: (the bound takes the aperture's peak gain and the height for the range). sigma0 of its
#: noise reaches ~9e39: float32 image files held Inf there (the guard then refused the
#: image of a scene check had accepted); the products are float64 now.
BEYOND_FLOAT32 = """
[sea]
wind_speed_m_s = 5.0
size_x_m = 32.0
nx = 32

[radar]
carrier_frequency_hz = 1.0e10
sampling_rate_hz = 180.0e6
prf_hz = 500.0
thermal_noise = true
transmit_power_w = 4.827944717311516e-43
n_pulses = 16
start_time_s = -0.015
sea_clutter = false
window_start_m = 1470.0
window_end_m = 1540.0
[radar.waveform]
kind = "lfm"
bandwidth_hz = 150.0e6
duration_s = 4.0e-6

[transmitter]
motion = "linear"
position_m = [-1500.0, 0.0, 100.0]
velocity_m_s = [0.0, 100.0, 0.0]
[transmitter.antenna]
pattern = "rectangular"
width_m = 3.0
height_m = 3.0
azimuth_deg = -88.5
depression_deg = 3.81

[[targets]]
position_m = [2.0, -1.5, 0.0]
rcs_m2 = 10.0

[image]
pixel_m = 0.5
extent_m = [-4.0, 4.0, -4.0, 4.0]
azimuth_window = "hamming"
figures = false
speckle_filter = "boxcar"
looks = [2, 2]
"""


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SamplingWarning")
def test_image_beyond_float32_is_written_finite(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(BEYOND_FLOAT32)
    assert main(["check", str(scene)]) == 0
    assert main(["run", str(scene), "-o", str(tmp_path / "r.nc"), "-q", "--no-figures"]) == 0
    with xr.open_dataset(tmp_path / "r_image.nc", engine="h5netcdf") as img:
        img = img.load()
    assert image_problems(img) == []
    f32 = float(np.finfo(np.float32).max)
    valid = img["valid"].values.astype(bool)
    for name in ("sigma0", "pauli", "sigma0_filtered", "pauli_filtered",
                 "sigma0_multilook"):
        a = img[name].values
        assert a.dtype == np.float64, name
        assert np.isfinite(a).all(), name  # no pixel without data here: finite everywhere
    assert valid.all()
    assert np.nanmax(img["sigma0"].values) > f32  # what float32 held as Inf
    assert img["image"].dtype == np.complex128


def test_calibrated_products_are_nan_only_where_there_is_no_data():
    # _calibrated: a value past float64 becomes NaN at a pixel without data, and stays
    # (for the guard to report) at a pixel with data
    from seaecho.imaging.focus import _calibrated

    a = np.array([[np.inf, 5.0, np.nan], [np.inf, 2.0, 3.0]], dtype=np.float32)
    nodata = np.array([[True, True, True], [False, False, False]])
    out = _calibrated(a, nodata)
    assert out.dtype == np.float64
    assert np.isnan(out[0, [0, 2]]).all() and out[0, 1] == 5.0  # finite values stay
    assert np.isinf(out[1, 0]) and out[1, 1] == 2.0
