"""A point target focused by backprojection against the closed forms of SAR theory.

Monostatic stripmap (``sar_helpers``), isotropic antennas, N = 64 pulses: the processed
aperture is L = N v / PRF = 12.8 m. Closed forms:

- slant-range resolution 0.886 c / (2 B) (Cumming & Wong 2005, eq 3.36 with the sinc
  of an LFM pulse of large time-bandwidth product, Cook & Bernfeld 1967, ch. 6), i.e.
  0.886 c / (2 B sin theta_i) on the ground;
- azimuth resolution 0.886 lambda R / (2 L) (Cumming & Wong 2005, eq 4.37 with the
  Doppler bandwidth 2 v L / (lambda R) of the processed aperture; Soumekh 1999,
  section 4.5), the 3 dB width of the Dirichlet kernel of N pulses;
- peak sidelobe -13.26 dB in both dimensions and ISLR of the sinc (-9.68 dB over an
  infinite span; here the same integral over the span of the cut, computed from the
  closed-form sinc);
- Hamming weighting (Harris 1978, Table 1): a 3 dB width of 1.30 bins against 0.89 for
  the rectangle (1.46 times wider) and a peak sidelobe of -42.7 dB (we ask < -41 dB:
  the LFM's finite time-bandwidth product and the 64 samples of the window);
- the calibrated peak |s|^2 is the target's RCS (eq K1-K2) and its phase that of s_mn.
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
from scipy.integrate import quad

from seaecho.config.image import ImageConfig
from seaecho.constants import C0
from seaecho.imaging.focus import focus_points
from seaecho.imaging.quality import irf_cut

N_PULSES = 64
APERTURE = N_PULSES * SPEED / PRF
RANGE_RES = 0.886 * C0 / (2 * BANDWIDTH * np.sin(INCIDENCE))  # ground range
AZIMUTH_RES = 0.886 * WAVELENGTH * SLANT_RANGE / (2 * APERTURE)
TARGET = np.array([0.0, 0.0, 0.0])
# A target with a complex, polarisation-dependent matrix: |s_hh|^2 = 4 m^2 (phase 60 deg),
# s_hv = s_vh = 1 m (-90 deg), |s_vv|^2 = 9 m^2 (phase 180 deg)
S = {"s_hh": (1.0, np.sqrt(3.0)), "s_hv": (0.0, -1.0), "s_vh": (0.0, -1.0), "s_vv": (-3.0, 0.0)}
S_COMPLEX = np.array([complex(*S[k]) for k in ("s_hh", "s_hv", "s_vh", "s_vv")])


def _islr_sinc(span_res: float) -> float:
    """ISLR [dB] of |sinc|^2 integrated over +-span (in units of 1/B), main lobe +-1."""
    def f(t):
        return np.sinc(t) ** 2

    main = quad(f, -1, 1)[0]
    side = 2 * sum(quad(f, k, k + 1)[0] for k in range(1, int(np.floor(span_res))))
    return 10 * np.log10(side / main)


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    path = tmp_path_factory.mktemp("pt") / "raw.nc"
    scene = point_scene([{"position_m": tuple(TARGET), **S}], n_pulses=N_PULSES)
    return simulate(scene, path)


@pytest.fixture(scope="module")
def raw_ds(raw):
    with xr.open_dataset(raw, engine="h5netcdf") as ds:
        yield ds.load()


@pytest.fixture(scope="module")
def long_ds(tmp_path_factory):
    """160 pulses (32 m of track), so that a pixel within 9.6 m of the target still finds
    the whole 12.8 m processed aperture of its own Doppler window."""
    path = tmp_path_factory.mktemp("pt") / "long.nc"
    scene = point_scene([{"position_m": tuple(TARGET), **S}], n_pulses=160)
    with xr.open_dataset(simulate(scene, path), engine="h5netcdf") as ds:
        yield ds.load()


def _cut(raw_ds, direction, half, step, cfg=None, channel=3):
    s, pts = line(TARGET, direction, half, step)
    img, area = focus_points(raw_ds, pts, cfg)
    return s, img[channel], area


@pytest.mark.parametrize("axis, expected", [((1, 0, 0), RANGE_RES), ((0, 1, 0), AZIMUTH_RES)])
def test_resolution_sidelobes_and_position(raw_ds, axis, expected):
    half = 20 * expected
    s, v, _ = _cut(raw_ds, axis, half, expected / 40)
    m = irf_cut(v, s)
    # 3 dB width: closed form within 2 %
    assert m.resolution == pytest.approx(expected, rel=0.02)
    # Peak sidelobe of the sinc, -13.26 dB
    assert m.pslr_db == pytest.approx(-13.26, abs=0.3)
    # ISLR of the sinc over the same span (in resolution units of 1/B: half / (w/0.886))
    assert m.islr_db == pytest.approx(_islr_sinc(half / (expected / 0.886)), abs=0.4)
    # Focused at the true position within a tenth of a resolution cell
    assert abs(m.peak_position) < 0.1 * expected


def test_peak_is_the_scattering_matrix(raw_ds):
    # Calibrated (eqs K1-K2): s(x0) = S_mn in amplitude (0.2 dB) and phase (0.05 rad)
    img, area = focus_points(raw_ds, TARGET[None, :])
    got = img[:, 0]
    np.testing.assert_allclose(20 * np.log10(np.abs(got)), 20 * np.log10(np.abs(S_COMPLEX)),
                               atol=0.2)
    np.testing.assert_allclose(np.angle(got / S_COMPLEX), 0.0, atol=0.05)
    # The resolution cell (eq K3) of an LFM pulse of large B T is the textbook one,
    # c / (2 B sin theta) x lambda R / (2 L) (Cumming & Wong 2005, eqs 4.37 and 4.39)
    cell = (RANGE_RES / 0.886) * (AZIMUTH_RES / 0.886)
    assert area[0] == pytest.approx(cell, rel=0.02)


@pytest.mark.parametrize("backend", ["drjit", "numpy"])
def test_uncalibrated_peak_is_the_coherent_sum_of_the_radar_equation(raw_ds, backend):
    # |I(x0)| = sum_p sqrt(P_r,p), P_r of the radar equation (Skolnik 2008, eq 23.1) with
    # isotropic antennas: the coherent gain of N pulses, independent of the calibration;
    # with eq B2's carrier phase of the wrong sign the pulses would not add up
    from seaecho.imaging.focus import RawData, _Processor

    raw = RawData(raw_ds)
    proc = _Processor(raw, ImageConfig(), backend)
    acc = proc.backproject(TARGET[None, :])[0][3, 0]
    tx = raw_ds["tx_position"].values
    r = np.linalg.norm(tx - TARGET, axis=1)
    p_t = raw_ds.attrs["transmit_power_w"]
    amp = np.sqrt(p_t * 9.0 * WAVELENGTH**2 / ((4 * np.pi) ** 3 * r**4))
    assert 20 * np.log10(abs(acc) / amp.sum()) == pytest.approx(0.0, abs=0.05)


def test_numpy_and_drjit_agree_on_the_image(raw_ds):
    s, pts = line(TARGET, (1, 1, 0), 5.0, 0.25)
    a, _ = focus_points(raw_ds, pts, backend="drjit")
    b, _ = focus_points(raw_ds, pts, backend="numpy")
    np.testing.assert_allclose(a, b, rtol=0, atol=2e-5 * np.abs(b).max())


@pytest.mark.parametrize("axis, expected", [((1, 0, 0), RANGE_RES), ((0, 1, 0), AZIMUTH_RES)])
def test_hamming_broadening_and_sidelobes(long_ds, axis, expected):
    # Azimuth: the processed Doppler band is that of the 12.8 m aperture, 2 v L /
    # (lambda R); each pixel's window (eq B4) slides with it over the longer track, so
    # the response keeps |FT of the window| (Cumming & Wong 2005, section 4.5). Range: the
    # raw data compressed again with the weighting
    doppler_span = 2 * SPEED * APERTURE / (WAVELENGTH * SLANT_RANGE)
    cfg = ImageConfig(azimuth_window="hamming", range_weighting="hamming",
                      doppler_bandwidth_hz=doppler_span)
    half = min(20 * expected, 8.0)
    s, v, _ = _cut(long_ds, axis, half, expected / 40, cfg)
    m = irf_cut(v, s)
    # Harris (1978), Table 1: 3 dB width 1.30 bins against 0.89 for the rectangle
    assert m.resolution / expected == pytest.approx(1.30 / 0.89, rel=0.03)
    assert m.pslr_db < -41.0
    assert abs(m.peak_position) < 0.1 * expected
    # The calibration follows the window: the peak stays the target's |s_vv|^2 = 9 m^2
    img, _ = focus_points(long_ds, TARGET[None, :], cfg)
    assert 20 * np.log10(abs(img[3, 0])) == pytest.approx(10 * np.log10(9.0), abs=0.2)
