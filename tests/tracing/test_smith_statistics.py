"""Ray-traced shadowing of Gaussian random surfaces vs Smith's statistical shadowing.

References: B. G. Smith, "Geometrical shadowing of a random rough surface", IEEE Trans.
Antennas Propag. AP-15(5), 668-671 (1967); C. Bourlier, G. Berginc, J. Saillard,
"Monostatic and bistatic statistical shadowing functions from a one-dimensional
stationary randomly rough surface according to the observation length: I. Single
scattering", Waves Random Media 12(2), 145-173 (2002).

Set-up: Gaussian surfaces with a Gaussian correlation (correlation length 8 m, 1 m grid,
256 x 256 nodes: the facets resolve the slopes), lit by a distant source (1e5 m: a plane
wave), at grazing angles 5, 10, 20 deg and rms slopes 0.1, 0.2. Only facets at least
(max - min height) / tan(grazing) from the tile edge on the source's side are counted, so
that the rays cross enough surface (Smith assumes an infinite surface). The rms slope
along the source's azimuth and the rms height are the sample values of the facets.

Tolerance: |mean over seeds - Smith| <= 3 standard errors of the mean over 4 seeds + 0.04.
The 0.04 is the systematic error of Smith's approximation itself, which neglects the
correlation between the heights and slopes at the point and those along the ray (Smith
1967; Bourlier et al. 2002 discuss it and compare with simulations). On these surfaces the
ray-traced lit fraction lies 0.025-0.035 *below* Smith at 0.2 rms slope (5 deg: 0.418 vs
0.443; 10 deg: 0.690 vs 0.724) and this does not change when the grid is refined (1 m ->
0.5 m: 0.4186 -> 0.4182 at 5 deg; 2 m: 0.4234), so it is Smith's error, not a mesh
artefact. The analytic mode (Smith-weighted) is compared with the ray tracer with the same
tolerance.
"""

import numpy as np
import pytest

from seaecho.geometry.facets import analytic_facets
from seaecho.geometry.shadowing import smith_bistatic, smith_monostatic
from seaecho.tracing.tracer import FacetTracer

N, DX, CORR = 256, 1.0, 8.0
X = (np.arange(N) - N / 2) * DX
SEEDS = range(4)
R_FAR = 1.0e5


@pytest.fixture(scope="module")
def tracer():
    return FacetTracer(X, X)


def _far(grazing_deg, azimuth):
    g = np.deg2rad(grazing_deg)
    return R_FAR * np.array([np.cos(g) * np.cos(azimuth), np.cos(g) * np.sin(azimuth),
                             np.sin(g)])


def _keep(c, zc, grazing_deg, azimuth):
    """Facets whose ray towards the source crosses at least the needed surface length."""
    need = (zc.max() - zc.min()) / np.tan(np.deg2rad(grazing_deg))
    e = np.array([np.cos(azimuth), np.sin(azimuth)])
    dist = np.full(c.shape[0], np.inf)
    for k in range(2):
        if e[k] > 1e-9:
            dist = np.minimum(dist, (X[-1] - c[:, k]) / e[k])
        elif e[k] < -1e-9:
            dist = np.minimum(dist, (X[0] - c[:, k]) / e[k])
    return dist > need


def _run(tracer, gaussian_surface, rms_slope, geometry):
    """geometry: list of (grazing_deg, azimuth) for Tx, and optionally Rx."""
    rows = []
    for seed in SEEDS:
        z = gaussian_surface(N, DX, CORR, rms_slope * CORR / np.sqrt(2),
                             np.random.default_rng(seed))
        tx = _far(*geometry[0])
        rx = _far(*geometry[1]) if len(geometry) > 1 else None
        f = tracer.facets(z, None, tx, rx)
        zc = f.centroid[:, 2] - f.centroid[:, 2].mean()
        keep = np.ones(f.n_facets, bool)
        for g, az in geometry:
            keep &= _keep(f.centroid, zc, g, az)
        grad = np.stack([-f.normal[:, 0] / f.normal[:, 2], -f.normal[:, 1] / f.normal[:, 2]])
        cov = np.cov(grad[:, keep])
        (g1, a1), (g2, a2) = geometry[0], geometry[-1]
        smith = smith_bistatic(np.deg2rad(90 - g1), a1, np.deg2rad(90 - g2), a2, cov)
        # the analytic mode, Smith-weighted, on the same surface: normals from spectral
        # (analytic) slopes, facing x F(zeta)^Lambda with the surface's own statistics
        k = 2 * np.pi * np.fft.fftfreq(N, DX)
        zf = np.fft.fft2(z)
        sx = np.real(np.fft.ifft2(1j * k[None, :] * zf))
        sy = np.real(np.fft.ifft2(1j * k[:, None] * zf))
        fa = analytic_facets(X, X, z, sx, sy, None, tx, rx, shadowing="smith")
        rows.append((f.visibility[keep].mean(), smith, fa.visibility[keep].mean()))
    rows = np.array(rows)
    return rows.mean(axis=0), rows[:, 0].std(ddof=1) / np.sqrt(len(rows))


@pytest.mark.parametrize("rms_slope", [0.1, 0.2])
@pytest.mark.parametrize("grazing_deg", [5.0, 10.0, 20.0])
def test_monostatic_shadowed_fraction_vs_smith(tracer, gaussian_surface, rms_slope,
                                               grazing_deg):
    (traced, smith, analytic), sem = _run(tracer, gaussian_surface, rms_slope,
                                          [(grazing_deg, -np.pi / 2)])
    tol = 3 * sem + 0.04
    assert traced == pytest.approx(smith, abs=tol)
    # Smith's closed form (eq T4) equals the bistatic routine in the monostatic limit
    # (the sample rms slope of 4 finite surfaces differs from the nominal one by ~2 %)
    assert smith == pytest.approx(
        smith_monostatic(np.deg2rad(90 - grazing_deg), rms_slope), abs=0.02)
    # the analytic mode with Smith weights agrees with the ray-traced mode
    assert analytic == pytest.approx(traced, abs=tol)


@pytest.mark.parametrize("rms_slope", [0.1, 0.2])
@pytest.mark.parametrize("geometry", [
    [(10.0, -np.pi / 2), (10.0, np.pi / 2)],       # forward: opposite azimuths
    pytest.param([(5.0, -np.pi / 2), (15.0, np.pi / 2)], marks=pytest.mark.slow),
    pytest.param([(10.0, -np.pi / 2), (10.0, 0.0)],  # out of plane, 90 deg apart
                 marks=pytest.mark.slow),
], ids=["fwd-10-10", "fwd-5-15", "oop-10-10"])
def test_bistatic_visible_fraction_vs_smith(tracer, gaussian_surface, rms_slope, geometry):
    (traced, smith, analytic), sem = _run(tracer, gaussian_surface, rms_slope, geometry)
    tol = 3 * sem + 0.04
    assert traced == pytest.approx(smith, abs=tol)
    assert analytic == pytest.approx(traced, abs=tol)
