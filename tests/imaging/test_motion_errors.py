"""Motion errors: a Gauss-Markov perturbed track, focused with the nominal and the true
track.

The processor that knows only the nominal track backprojects with delays in error by
delta_p = (|x - t_p^true| - |x - t_p^nom|) / c per way; at the target the pulses then add
with the phase errors phi_p = 2 pi f_c (2 delta_p) (monostatic), so the focused peak is
the coherent-sum loss |sum_p exp(j phi_p)| / N of the uncompensated phase errors (Carrara,
Goodman & Majewski 1995, section 5.2; Cumming & Wong 2005, section 12.2: a random phase
error of rms sigma_phi costs exp(-sigma_phi^2) of peak power on average). The true track
restores the unperturbed impulse response.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from sar_helpers import (
    BANDWIDTH,
    INCIDENCE,
    PRF,
    SLANT_RANGE,
    SPEED,
    WAVELENGTH,
    line,
    point_scene,
    simulate,
)

from seaecho.config.image import ImageConfig
from seaecho.constants import C0
from seaecho.imaging.focus import focus_points
from seaecho.imaging.quality import irf_cut

N = 64
TARGET = np.array([0.0, 0.0, 0.0])
AZIMUTH_RES = 0.886 * WAVELENGTH * SLANT_RANGE / (2 * N * SPEED / PRF)
RANGE_RES = 0.886 * C0 / (2 * BANDWIDTH * np.sin(INCIDENCE))
# 3 cm rms path error on each axis, correlated over 0.5 s: several radians of two-way
# phase error at 3 cm wavelength, changing over the 0.128 s aperture
PERTURBATION = {"position_sigma_m": (0.03, 0.03, 0.03), "position_tau_s": 0.5,
                "step_s": 1.0e-3}


def _scene(perturbed: bool):
    tx = {"motion": "linear", "position_m": (-500.0, 0.0, 500.0),
          "velocity_m_s": (0.0, SPEED, 0.0),
          "antenna": {"pattern": "isotropic", "azimuth_deg": -90.0, "depression_deg": 45.0}}
    if perturbed:
        tx["perturbation"] = PERTURBATION
    return point_scene([{"position_m": tuple(TARGET), "rcs_m2": 1.0}], n_pulses=N,
                       transmitter=tx, seed=11)


@pytest.fixture(scope="module")
def datasets(tmp_path_factory):
    d = tmp_path_factory.mktemp("motion")
    out = {}
    for name in ("clean", "perturbed"):
        path = simulate(_scene(name == "perturbed"), d / f"{name}.nc")
        with xr.open_dataset(path, engine="h5netcdf") as ds:
            out[name] = ds.load()
    return out


def test_nominal_track_defocuses_by_the_phase_errors(datasets):
    ds = datasets["perturbed"]
    true, nom = ds["tx_position"].values, ds["tx_position_nominal"].values
    delta = np.linalg.norm(TARGET - true, axis=1) - np.linalg.norm(TARGET - nom, axis=1)
    phi = 4 * np.pi * delta / WAVELENGTH
    assert np.std(phi) > 1.0  # the perturbation matters at this wavelength
    predicted = 20 * np.log10(abs(np.mean(np.exp(1j * phi))))
    img, _ = focus_points(ds, TARGET[None, :], ImageConfig(track="nominal"))
    got = 20 * np.log10(abs(img[0, 0]))  # |s|^2 / sigma with sigma = 1 m^2
    # The defocused peak is the coherent-sum loss of the phase errors (0.3 dB: the
    # range error of a few cm also moves the range sample, 2 % of a resolution)
    assert got == pytest.approx(predicted, abs=0.3)
    assert got < -3.0
    # and the energy is spread: the azimuth response is no longer the unperturbed one
    s, pts = line(TARGET, (0, 1, 0), 15 * AZIMUTH_RES, AZIMUTH_RES / 20)
    cut, _ = focus_points(ds, pts, ImageConfig(track="nominal"))
    p = np.abs(cut[0]) ** 2
    main = np.abs(s) <= AZIMUTH_RES
    assert p[main].sum() / p.sum() < 0.6  # 0.90 of a sinc's energy is within +-1 cell


def test_true_track_recovers_the_unperturbed_response(datasets):
    ref_img, _ = focus_points(datasets["clean"], TARGET[None, :])
    img, _ = focus_points(datasets["perturbed"], TARGET[None, :], ImageConfig(track="true"))
    assert 20 * np.log10(abs(img[0, 0])) == pytest.approx(
        20 * np.log10(abs(ref_img[0, 0])), abs=0.1)
    for axis, res in (((0, 1, 0), AZIMUTH_RES), ((1, 0, 0), RANGE_RES)):
        s, pts = line(TARGET, axis, 15 * res, res / 40)
        cut, _ = focus_points(datasets["perturbed"], pts, ImageConfig(track="true"))
        m = irf_cut(cut[0], s)
        assert m.resolution == pytest.approx(res, rel=0.03)
        assert m.pslr_db == pytest.approx(-13.26, abs=0.5)
        assert abs(m.peak_position) < 0.1 * res
