"""The facet model's mean sigma0 does not depend on the grid spacing (two scales done right).

One realisation of an Elfouhaily sea (U19.5 = 7 m/s, 32 m tile) is synthesised on a
0.1 m grid and band-limited to coarser grids (0.2, 0.5, 1 and 2 m) by truncating its
Fourier series, so that every grid carries the *same* resolved waves and only the split
between facets and sub-facet statistics changes. Monostatic 10 GHz back-scatter at
20 deg grazing, looking upwind; sigma0 = sum over facets of area x sigma_mn (facing
test) over the mesh's horizontal area.

Without the unresolved-tilt average (the paper's facet model: the Bragg term of the
facet's own plane) the tilt-induced cross-polarisation and the HH of the slopes between
the grid's Nyquist wavenumber and the two-scale split k/3 are lost: HV drops by several
dB from 0.1 m to 2 m (the drift measured with ``seaecho compare``: -44.2 -> -48.6 dB
from 0.125 to 2 m). With the sub-facet slopes that the facets miss (eq U1) and the Bragg
term averaged over them (eq P6), co-pol stays within 0.5 dB and cross-pol within 1 dB;
and the mean-plane limit (the facet sum equals the two-scale model, eq T1, of the total
slope variance: Khenchaf & Airiau 2000) is tested in tests/test_end_to_end.py.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest

from seaecho.build import build_sea_model, sea_spectrum
from seaecho.config import parse_scene
from seaecho.geometry.mesh import facet_geometry, grid_vertices
from seaecho.ocean.surface import SeaSurface
from seaecho.scattering.facet import facet_sigma

L = 32.0
FINE = 320
GRIDS = (320, 160, 64, 32, 16)  # 0.1, 0.2, 0.5, 1, 2 m
GRAZING = np.radians(20.0)


def _scene(n, tilt):
    return parse_scene({
        "sea": {"spectrum": "elfouhaily", "spreading": "elfouhaily", "wind_speed_m_s": 7.0,
                "size_x_m": L, "nx": n},
        "scattering": {"model": "blend", "unresolved_tilt": tilt},
        "tracing": {"mode": "raytraced"},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 2e8, "prf_hz": 1e3,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 1e8, "duration_s": 1e-6}},
    })


def _band_limited(z_fine, n):
    """The fine grid's Fourier series truncated to an n x n grid (same node positions
    x = (i - n/2) L / n; the Nyquist row and column left empty, as the synthesis does)."""
    zh = np.fft.fft2(z_fine, norm="forward")
    idx = np.r_[0:n // 2, FINE - n // 2:FINE]
    zc = zh[np.ix_(idx, idx)].copy()
    zc[n // 2, :] = 0.0
    zc[:, n // 2] = 0.0
    return np.fft.ifft2(zc, norm="forward").real


@pytest.fixture(scope="module")
def elevation():
    spec = sea_spectrum(_scene(FINE, True))
    return SeaSurface(spec, (L, L), (FINE, FINE), np.random.default_rng(2)).elevation(0.0)


def _sigma0(z_fine, n, tilt):
    sc = _scene(n, tilt)
    m = build_sea_model(sc)
    x = (np.arange(n) - n // 2) * (L / n)
    _, area, normal = facet_geometry(grid_vertices(x, x, _band_limited(z_fine, n)))
    # wind towards +x; the radar east of the tile looks west (upwind)
    n_i = np.array([-np.cos(GRAZING), 0.0, -np.sin(GRAZING)])
    vis = (normal @ n_i < 0) & (normal @ -n_i > 0)
    ni = np.broadcast_to(n_i, normal.shape)
    sea = m.facet_model if tilt else m.facet_model.with_(tilt=None)
    sig = facet_sigma(ni, -ni, normal, sea)
    # per unit horizontal area of the mesh, which covers (n - 1)^2 cells of the tile
    return 10 * np.log10((area * vis) @ sig / ((n - 1) * L / n) ** 2)


def test_sigma0_is_grid_independent_from_0_1_to_2_m(elevation):
    new = np.array([_sigma0(elevation, n, True) for n in GRIDS])
    old = np.array([_sigma0(elevation, n, False) for n in (GRIDS[0], GRIDS[-1])])
    # The paper's facet model drifts (the failure this fixes stays visible): HV and HH
    # fall with the grid spacing (the finest and the coarsest grid compared).
    assert old[0, 1] - old[-1, 1] > 3.0
    assert old[0, 0] - old[-1, 0] > 1.0
    # Two scales done right: the 0.1 m grid within 0.25 dB (co-pol), 0.5 dB (cross-pol).
    # (measured: 0.05 dB in every channel; the requirement is 0.5 and 1 dB)
    for c, tol in ((0, 0.25), (3, 0.25), (1, 0.5), (2, 0.5)):
        assert np.abs(new[:, c] - new[0, c]).max() < tol, (c, new[:, c])
