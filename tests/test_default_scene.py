"""README's main command on the default scene runs clean: no warning on a first run.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seaecho.build import build_sea_model
from seaecho.cli import main
from seaecho.config import load_scene

ROOT = Path(__file__).resolve().parents[1]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"


def test_default_scene_is_inside_the_models_validity_domain():
    # The grid keeps the unresolved (Bragg) roughness within the small-perturbation bound
    # k h <= 0.3 (Thorsos & Jackson 1989) at the 10 GHz carrier, while the scene stays
    # the paper's Simulation 1 (64 m tile, U19.5 = 4.53 m/s, 10 m boat at 10 kn).
    scene = load_scene(SIM1)
    assert scene.sea.size_m == (64.0, 64.0) and scene.sea.wind_speed_m_s == 4.53
    assert scene.radar.carrier_frequency_hz == 10e9
    m = build_sea_model(scene)
    assert m.k * np.sqrt(m.roughness_height_variance) <= 0.3


def test_check_prints_no_warning(capsys):
    assert main(["check", str(SIM1)]) == 0
    out = capsys.readouterr()
    assert "warning" not in out.out.lower() and out.err == ""


def _run_one_pulse(scene, out, capsys):
    # README's command with one pulse; any warning is an error in this suite.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert main(["run", str(scene), "-o", str(out), "--pulses", "1", "-q",
                     "--no-figures"]) == 0
    assert capsys.readouterr().err == ""
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds.sizes["pulse"] == 1 and float(np.abs(ds["raw"]).max()) > 0


def test_one_pulse_run_raises_no_warning(tmp_path, capsys):
    # The default scene as it is, except that the boat's echo is traced with one ray per
    # wavelength instead of four (16 times fewer rays: the trace was most of the run's
    # 25 s). The shooting-and-bouncing-ray trace warns of nothing itself, and its density
    # changes no other stage (sea, wake, shadows, receive window); the scene exactly as
    # README runs it is test_readme_command_one_pulse_raises_no_warning (slow).
    text = SIM1.read_text()
    for old, new in (('file = "meshes/', f'file = "{SIM1.parent}/meshes/'),
                     ("scatterer = true\n", "scatterer = true\nrays_per_wavelength = 1.0\n")):
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    scene = tmp_path / SIM1.name
    scene.write_text(text)
    _run_one_pulse(scene, tmp_path / "sim1.nc", capsys)


@pytest.mark.slow  # ~25 s, most of it the boat's trace at four rays per wavelength
def test_readme_command_one_pulse_raises_no_warning(tmp_path, capsys):
    _run_one_pulse(SIM1, tmp_path / "sim1.nc", capsys)
