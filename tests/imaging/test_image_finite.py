"""A focused image never holds Inf, nor NaN but at its undefined pixels: what the fuzzing
suite found."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

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
    for name, v in img.data_vars.items():
        assert not np.isinf(v.values).any(), name
    for name in ("resolution_area", "sigma0", "pauli"):  # undefined: NaN, not 0 or Inf
        assert np.isnan(img[name].values).all(), name
    assert np.isfinite(img["pauli_filtered"].values).all()
    # the calibrated image is still defined: the target's RCS at its peak (eq K2)
    hh = np.abs(img["image"].sel(channel="HH").values) ** 2
    assert np.isfinite(hh).all() and 10 * np.log10(hh.max()) == pytest.approx(0.0, abs=1.0)

