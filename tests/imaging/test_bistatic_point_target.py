"""A bistatic point target: a fixed transmitter, a receiver flying past.

Closed form (gradient method: Cardillo 1990; Walterscheid et al. 2006, eqs 3-6; Moccia &
Renga 2011, section II): with g = grad_ground (r_t + r_r) / c the delay gradient and
f_D = -(1/lambda) d(r_t + r_r)/dt the bistatic Doppler, the image spectrum of a point
target fills the parallelogram spanned by a = B g and b = T grad_ground f_D (T the
aperture time), so the impulse response is sinc(a . u) sinc(b . u): its 3 dB width is
0.886 / (|a| sin beta) along the iso-Doppler line (u perpendicular to b) and
0.886 / (|b| sin beta) along the iso-range line (u perpendicular to a), beta the angle
between the two gradients (the bistatic resolution cell delta_r delta_a / sin beta).
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from sar_helpers import BANDWIDTH, WAVELENGTH, line, point_scene, simulate

from seaecho.constants import C0
from seaecho.imaging.focus import focus_points
from seaecho.imaging.quality import irf_cut

N = 64
TX = np.array([-600.0, -400.0, 500.0])
RX0 = np.array([-500.0, 0.0, 500.0])  # at the middle of the aperture
VR = np.array([0.0, 100.0, 0.0])
TARGET = np.array([3.0, -2.0, 0.0])
SMALL = {"pattern": "rectangular", "width_m": 0.05, "height_m": 0.05}  # 15 dBi, wide beam


@pytest.fixture(scope="module")
def bistatic(tmp_path_factory):
    mid = 0.5 * (np.linalg.norm(TARGET - TX) + np.linalg.norm(TARGET - RX0))
    scene = point_scene(
        [{"position_m": tuple(TARGET), "rcs_m2": 4.0}], n_pulses=N,
        transmitter={"position_m": tuple(TX),
                     "antenna": {**SMALL, "look_at_m": (0.0, 0.0, 0.0)}},
        receiver={"motion": "linear", "position_m": tuple(RX0), "velocity_m_s": tuple(VR),
                  "antenna": {**SMALL, "look_at_m": (0.0, 0.0, 0.0),
                              "track_look_at": True}},
        window_start_m=mid - 40.0, window_end_m=mid + 40.0)
    path = simulate(scene, tmp_path_factory.mktemp("bi") / "raw.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        yield ds.load()


def _gradients(ds):
    """a = B g and b = T grad f_D at the target from the platform positions [1/m]."""
    rx = ds["rx_position"].values

    def g(r):  # horizontal gradient of (r_t + r_r) / c at the target
        u = (TARGET - TX) / np.linalg.norm(TARGET - TX) + (TARGET - r) / np.linalg.norm(
            TARGET - r)
        return u[:2] / C0

    a = BANDWIDTH * g(rx[N // 2])
    # f_c (g_last - g_first) over N - 1 pulse steps, times N steps (Dirichlet kernel)
    b = (C0 / WAVELENGTH) * (g(rx[-1]) - g(rx[0])) * N / (N - 1)
    return a, b


def test_bistatic_focus_position_and_resolution(bistatic):
    a, b = _gradients(bistatic)
    sin_beta = abs(a[0] * b[1] - a[1] * b[0]) / (np.linalg.norm(a) * np.linalg.norm(b))
    assert 0.5 < sin_beta < 0.99  # a genuinely skewed bistatic cell
    for along, other in ((b, a), (a, b)):
        # the cut follows the line on which `along` . u = 0 (the other sinc alone)
        d = np.array([-along[1], along[0], 0.0])
        expected = 0.886 / (np.linalg.norm(other) * sin_beta)
        s, pts = line(TARGET, d, 12 * expected, expected / 40)
        img, _ = focus_points(bistatic, pts)
        m = irf_cut(img[0], s)
        assert m.resolution == pytest.approx(expected, rel=0.03)
        # Focused at the true position within a tenth of the resolution
        assert abs(m.peak_position) < 0.1 * expected
        assert m.pslr_db == pytest.approx(-13.26, abs=0.5)


def test_bistatic_calibration_is_the_rcs(bistatic):
    # Eq K2 with the two antennas' gains and r_t != r_r: |s|^2 = 4 m^2 within 0.2 dB on
    # the co-polar channels, nothing on the cross-polar ones (the ports are H/V of each
    # antenna's own basis, equal to the FSA bases of a level platform)
    img, area = focus_points(bistatic, TARGET[None, :])
    db = 20 * np.log10(np.abs(img[:, 0]))
    assert db[0] == pytest.approx(10 * np.log10(4.0), abs=0.2)
    assert db[3] == pytest.approx(10 * np.log10(4.0), abs=0.2)
    assert max(db[1], db[2]) < db[0] - 40
    # and the resolution cell of eq K3 is the parallelogram's area 1 / |a x b|, with the
    # energy E_chi = 1/B of the compressed pulse and the Dirichlet kernel's 1/N per pulse
    a, b = _gradients(bistatic)
    assert area[0] == pytest.approx(1.0 / abs(a[0] * b[1] - a[1] * b[0]), rel=0.03)



def test_fixed_bistatic_radar_is_calibrated_but_has_no_sigma0(tmp_path):
    # The repository's calibration scene: transmitter and receiver at rest, 10 m^2 sphere
    # at (0, 0, 1), noise 50 dB below. Without motion there is no azimuth compression,
    # yet eq K2 still gives |s|^2 = RCS (2 pulses summed coherently); eq K3 has no
    # aperture rotation to work with, which the processor says with a warning.
    from pathlib import Path

    from seaecho.config import load_scene
    from seaecho.config.image import ImageConfig
    from seaecho.imaging.focus import focus
    from seaecho.warnings import SamplingWarning

    scene = load_scene(Path(__file__).resolve().parents[2] / "scenes"
                       / "calibration_point_target.toml")
    scene = scene.model_copy(update={"radar": scene.radar.model_copy(
        update={"n_pulses": 2})})
    path = simulate(scene, tmp_path / "fixed.nc")
    img, area = focus_points(path, np.array([[0.0, 0.0, 1.0]]))
    assert 20 * np.log10(abs(img[0, 0])) == pytest.approx(10.0, abs=0.2)
    assert np.isnan(area[0])
    with pytest.warns(SamplingWarning, match="aperture does not turn"):
        focus(path, ImageConfig(pixel_m=1.0, extent_m=(-4.0, 4.0, -4.0, 4.0)))
