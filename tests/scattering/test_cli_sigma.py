"""``seaecho sigma`` and ``seaecho permittivity`` command lines."""

import numpy as np
import pytest

from seaecho.cli import main
from seaecho.ocean.seawater import meissner_wentz
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.scattering.spm import spm_sigma

COLUMNS = ("theta_i_deg,theta_s_deg,phi_i_deg,phi_s_deg,"
           "sigma_hh_db,sigma_hv_db,sigma_vh_db,sigma_vv_db")


def test_sigma_csv_columns_rows_and_png(tmp_path, capsys):
    out = tmp_path / "fig3.csv"
    rc = main(["sigma", "--model", "spm", "--theta-i-deg", "20", "--theta-s-deg", "30",
               "--phi-s-deg", "0:180:30", "-o", str(out)])
    assert rc == 0
    lines = out.read_text().splitlines()
    assert lines[0] == COLUMNS
    rows = np.loadtxt(out, delimiter=",", skiprows=1)
    assert rows.shape == (7, 8)
    np.testing.assert_allclose(rows[:, 3], np.arange(0, 181, 30))
    assert (tmp_path / "fig3.png").stat().st_size > 1000
    # The CSV holds the library's numbers (6 significant digits).
    spec = DirectionalSpectrum(u19_5=4.53)
    eps = meissner_wentz(10e9, 20.0, 35.0)
    k = 2 * np.pi * 10e9 / 299_792_458.0
    ref = spm_sigma(np.radians(20), 0.0, np.radians(30), np.radians(rows[:, 3]), k, eps,
                    spec.height_spectrum)
    db = np.maximum(10 * np.log10(np.maximum(ref, 1e-300)), -300)
    np.testing.assert_allclose(rows[:, 4:], db, atol=1e-3)
    # SPM over the whole sea is outside its domain: a one-line warning on stderr.
    assert "k h =" in capsys.readouterr().err


def test_sigma_monostatic_has_no_cross_pol(tmp_path):
    out = tmp_path / "mono.csv"
    assert main(["sigma", "--model", "two-scale", "--theta-i-deg", "40", "--theta-s-deg",
                 "40", "--phi-s-deg", "180", "--no-figure", "-o", str(out)]) == 0
    row = np.loadtxt(out, delimiter=",", skiprows=1)
    # Reciprocity at backscatter: HV = VH.
    np.testing.assert_allclose(row[5], row[6], atol=1e-3)
    assert not (tmp_path / "mono.png").exists()


def test_sigma_two_angles_map(tmp_path):
    out = tmp_path / "map.csv"
    assert main(["sigma", "--theta-i-deg", "39", "--theta-s-deg", "0:60:30", "--phi-s-deg",
                 "0:180:90", "-o", str(out)]) == 0
    rows = np.loadtxt(out, delimiter=",", skiprows=1)
    assert rows.shape == (9, 8) and np.all(np.isfinite(rows))
    assert (tmp_path / "map.png").exists()


@pytest.mark.parametrize("argv", [
    ["--theta-i-deg", "abc"],
    ["--theta-i-deg", "10:0:5"],
    ["--theta-s-deg", "95"],
    ["--frequency-ghz", "0"],
    ["--spectrum", "jonswap"],
    ["-o", "/nonexistent/dir/x.csv"],
    ["-o", "x.txt"],
    ["--cut-ratio", "0"],
])
def test_sigma_bad_input_exits_2_without_file(argv, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["sigma", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("seaecho: error:") and len(err.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_permittivity_prints_model_value(capsys):
    assert main(["permittivity", "--frequency-ghz", "10", "--temperature-c", "20",
                 "--salinity-psu", "35", "--model", "meissner-wentz"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "model,frequency_ghz,temperature_c,salinity_psu,eps_real,eps_imag"
    name, f, t, s, re, im = out[1].split(",")
    eps = meissner_wentz(10e9, 20.0, 35.0)
    assert name == "meissner-wentz" and float(f) == 10
    np.testing.assert_allclose([float(re), float(im)], [eps.real, eps.imag], atol=1e-4)


def test_permittivity_bad_input(capsys):
    assert main(["permittivity", "--salinity-psu", "90"]) == 2
    assert "salinity" in capsys.readouterr().err
