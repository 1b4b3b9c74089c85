"""The raw product contract (docs/products.md): imaging reads the product, never the scene.

A raw file whose stored scene this seaecho cannot parse (a key it does not know) still
focuses, to the same values as before the edit; a product of another ``product_version``
is refused in one line (exit 2, no file); the antennas the processor rebuilds from the
product's ``tx_antenna_*`` / ``rx_antenna_*`` variables have the gains of the scene's
antennas (the builder's), bit for bit.
"""

from __future__ import annotations

import json
import shutil

import h5py
import numpy as np
import pytest
import xarray as xr
from sar_helpers import ALTITUDE, GROUND_RANGE, SPEED, point_scene, simulate

from seaecho.build import build_antennas
from seaecho.cli import main
from seaecho.io.product import PRODUCT_VERSION, read_antenna

TARGET = (1.0, 0.5, 0.0)
#: A real aperture (Taylor illumination along its width) for the transmitter and a
#: half-wave dipole for the receiver: the calibration's two-way gain uses both.
TX_ANTENNA = {"pattern": "rectangular", "width_m": 0.6, "height_m": 0.1,
              "illumination": "taylor", "taylor_sidelobe_db": 25.0, "taylor_nbar": 3,
              "azimuth_deg": -90.0, "depression_deg": 45.0}
RX = {"motion": "linear", "position_m": (-GROUND_RANGE, 20.0, ALTITUDE),
      "velocity_m_s": (0.0, SPEED, 0.0),
      "antenna": {"pattern": "hw_dipole", "azimuth_deg": -90.0,
                  "depression_deg": 45.0}}
ARGS = ["--pixel-m", "0.25", "--extent", "-3", "5", "-3", "4", "-q", "--no-figures"]


def _scene():
    tx = {"motion": "linear", "position_m": (-GROUND_RANGE, 0.0, ALTITUDE),
          "velocity_m_s": (0.0, SPEED, 0.0), "antenna": TX_ANTENNA}
    return point_scene([{"position_m": TARGET, "rcs_m2": 10.0}], n_pulses=32,
                       transmitter=tx, receiver=RX, channels=["HH", "VV"])


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    return simulate(_scene(), tmp_path_factory.mktemp("product") / "raw.nc")


def _edited(raw, tmp_path, name, **attrs):
    """A copy of the raw file with attributes replaced in place (h5py: the rest of the
    file, pulses included, untouched)."""
    path = tmp_path / name
    shutil.copyfile(raw, path)
    with h5py.File(path, "r+") as f:
        for key, value in attrs.items():
            if value is None:
                del f.attrs[key]
            else:
                f.attrs[key] = value
    return str(path)


def test_the_product_carries_its_version_and_antennas(raw):
    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        assert ds.attrs["product_version"] == PRODUCT_VERSION
        assert ds["tx_antenna_pattern"].attrs["flag_meanings"].split()[
            int(ds["tx_antenna_pattern"])] == "rectangular"
        assert float(ds["tx_antenna_width_m"]) == 0.6
        assert float(ds["rx_antenna_width_m"]) == 0.0  # a dipole is not an aperture
        # the waveform: LFM of B = 150 MHz over T = 4 us, k = B / T (Richards 2014, eq
        # 4.78), the slope of the stored pulse's instantaneous frequency
        k = ds.attrs["waveform_chirp_rate_hz_s"]
        assert k == pytest.approx(150e6 / 4e-6, rel=1e-12)
        fs = float(ds.attrs["sampling_rate_hz"])
        phase = np.unwrap(np.angle(ds["transmitted_pulse"].values))
        f_inst = np.diff(phase) * fs / (2.0 * np.pi)
        slope = np.polyfit(np.arange(f_inst.size) / fs, f_inst, 1)[0]
        assert slope == pytest.approx(k, rel=1e-6)
        # the processor's antennas are the builder's: the same gains, bit for bit
        scene_tx, scene_rx = build_antennas(_scene())
        wavelength = 299792458.0 / float(ds.attrs["carrier_frequency_hz"])
        tx, rx = read_antenna(ds, "tx", wavelength), read_antenna(ds, "rx", wavelength)
    d = np.random.default_rng(0).normal(size=(500, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    d[0] = (1.0, 0.0, 0.0)
    for ours, theirs in ((tx, scene_tx), (rx, scene_rx)):
        assert (ours.pattern, ours.width, ours.height, ours.illumination, ours.basis,
                ours.taylor_sidelobe_db, ours.taylor_nbar, ours.wavelength) == (
            theirs.pattern, theirs.width, theirs.height, theirs.illumination,
            theirs.basis, theirs.taylor_sidelobe_db, theirs.taylor_nbar, theirs.wavelength)
        np.testing.assert_array_equal(ours.gain_local(d), theirs.gain_local(d))
    # a rectangular aperture's peak is its directivity 4 pi A / lambda^2 times the Taylor
    # taper efficiency (< 1; Balanis 2016, eq 12-39 for the uniform aperture's 4 pi A /
    # lambda^2)
    uniform = 4.0 * np.pi * 0.6 * 0.1 / wavelength**2
    assert 0.8 * uniform < tx.peak_gain < uniform


def test_unknown_scene_keys_do_not_stop_imaging(raw, tmp_path, capsys):
    # the stored scene gets a section and a [radar] key this version does not know: the
    # scene no longer parses, the product is unchanged, the image is the same
    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        scene = json.loads(ds.attrs["scene_json"])
    scene["future_section"] = {"anything": 1}
    scene["radar"]["a_key_from_a_newer_seaecho"] = 2.5
    edited = _edited(raw, tmp_path, "edited.nc", scene_json=json.dumps(scene))
    before, after = tmp_path / "before.nc", tmp_path / "after.nc"
    assert main(["image", raw, "-o", str(before), *ARGS]) == 0
    assert main(["image", edited, "-o", str(after), *ARGS]) == 0
    with xr.open_dataset(before, engine="h5netcdf") as a, \
            xr.open_dataset(after, engine="h5netcdf") as b:
        assert set(a.variables) == set(b.variables)
        for name in a.variables:
            assert a[name].values.tobytes() == b[name].values.tobytes(), name
        other = {k for k in a.attrs if k not in ("scene_json", "source")}
        assert {k: str(a.attrs[k]) for k in other} == {k: str(b.attrs[k]) for k in other}
        assert "future_section" in b.attrs["scene_json"]  # kept as a record
        # the target's RCS from the two-way gain of the rectangular aperture and the
        # dipole (the calibration's antennas are the product's): 10 m^2 within 0.5 dB
        hh = np.abs(a["image"].sel(channel="HH").values) ** 2
        assert 10 * np.log10(hh.max()) == pytest.approx(10.0, abs=0.5)


@pytest.mark.parametrize("version, message", [
    (PRODUCT_VERSION + 1, f"product_version = {PRODUCT_VERSION + 1}: this seaecho reads "
     f"raw products of version {PRODUCT_VERSION} only"),
    (0, f"product_version = 0: this seaecho reads raw products of version "
     f"{PRODUCT_VERSION} only"),
    (None, "has no product_version attribute: written before the raw product contract"),
])
def test_other_product_versions_are_refused(raw, tmp_path, capsys, version, message):
    edited = _edited(raw, tmp_path, "other.nc", product_version=version)
    out = tmp_path / "img.nc"
    assert main(["image", edited, "-o", str(out), *ARGS]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
    assert not out.exists()


def test_a_bad_antenna_variable_is_named(raw, tmp_path, capsys):
    path = tmp_path / "bad_antenna.nc"
    shutil.copyfile(raw, path)
    with h5py.File(path, "r+") as f:
        f["tx_antenna_pattern"][()] = 9
    out = tmp_path / "img.nc"
    assert main(["image", str(path), "-o", str(out), *ARGS]) == 2
    err = capsys.readouterr().err
    assert "tx_antenna_pattern = 9: allowed 0 .. 4" in err and "Traceback" not in err
    assert not out.exists()


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SeaechoWarning")
def test_multistatic_product_has_each_receivers_antenna_and_ignores_the_scene(tmp_path):
    # [[receivers]]: the rx_antenna_* variables gain the receiver axis (one pattern per
    # receiver); each receiver's product is focused without parsing the stored scene, so
    # an unknown key leaves the images bit for bit
    from seaecho.config import parse_scene
    from seaecho.config.image import ImageConfig
    from seaecho.multistatic import MultistaticSimulation, image_multistatic

    aperture = {"pattern": "rectangular", "width_m": 0.3, "height_m": 0.2,
                "look_at_m": (0.0, 0.0, 0.0)}
    scene = parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 32.0, "nx": 32},
        "run": {"seed": 1},
        "radar": {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6, "prf_hz": 500.0,
                  "n_pulses": 8, "sea_clutter": False, "thermal_noise": False,
                  "transmit_power_w": 10.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 100e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": (-200.0, 0.0, 100.0), "antenna": aperture,
                        "motion": "linear", "velocity_m_s": (0.0, 100.0, 0.0)},
        "receivers": [
            {"name": "a", "position_m": (-150.0, 50.0, 80.0), "antenna": aperture},
            {"name": "b", "position_m": (0.0, -200.0, 60.0),
             "antenna": {"pattern": "hw_dipole", "look_at_m": (0.0, 0.0, 0.0)}}],
        "targets": [{"position_m": (1.0, 2.0, 0.0), "rcs_m2": 3.0}]})
    ds = MultistaticSimulation(scene).dataset(progress=False)
    assert ds["rx_antenna_pattern"].dims == ("receiver",)
    assert [int(v) for v in ds["rx_antenna_pattern"].values] == [0, 3]
    np.testing.assert_array_equal(ds["rx_antenna_width_m"].values, [0.3, 0.0])
    assert ds["tx_antenna_pattern"].dims == () and ds.attrs["product_version"] == 1
    cfg = ImageConfig(pixel_m=0.5, extent_m=[-4.0, 6.0, -3.0, 7.0])
    before = image_multistatic(ds, cfg, backend="numpy")
    assert (before["fused_receivers"].values == 2).all()  # both pairs focused
    stored = json.loads(ds.attrs["scene_json"])
    stored["receivers"][1]["a_key_from_a_newer_seaecho"] = True
    ds.attrs["scene_json"] = json.dumps(stored)
    after = image_multistatic(ds, cfg, backend="numpy")
    for name in before.data_vars:
        assert before[name].values.tobytes() == after[name].values.tobytes(), name
    # the raw file's figures (one set per receiver) read the product, not the scene
    from seaecho.api import figures

    pngs = figures(ds, tmp_path / "m")
    assert sorted(p.name for p in pngs) == ["m_a_compressed.png", "m_a_signal.png",
                                            "m_b_compressed.png", "m_b_signal.png"]


def test_the_product_codes_cover_the_scene_schema():
    # every pattern, basis and illumination a scene may name has a code in the product
    # (a new one without a code would make `seaecho run` fail at the writer)
    import typing

    from seaecho.config.radar import AntennaConfig
    from seaecho.io.product import BASES, PATTERNS
    from seaecho.radar.antennas import ILLUMINATIONS

    fields = AntennaConfig.model_fields
    for name, codes in (("pattern", PATTERNS), ("basis", BASES),
                        ("illumination", ILLUMINATIONS)):
        assert set(typing.get_args(fields[name].annotation)) == set(codes), name
