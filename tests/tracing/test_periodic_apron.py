"""The periodic apron of the tracer: a tile's shadow rays traced against its periodic copies.

Closed form: a straight crest of height h along x shadows a flat sea over the ground
distance h / tan(psi) behind it (geometric optics; Smith 1967's starting point, and the
"1 m crest shadows 190 m at 0.3 deg" of docs/scanning.md). An independent method: the
same tile repeated explicitly in one larger mesh (its seams closed) gives the same masks.
"""

import numpy as np
import pytest

from seaecho.geometry.mesh import facet_geometry, grid_vertices
from seaecho.tracing.tracer import FacetTracer

N, DX = 32, 1.0
X = (np.arange(N) - N // 2) * DX  # an FFT tile's nodes: period N DX
PERIOD = N * DX
CREST_ROW, CREST_M = 29, 1.0


def _crest_tile() -> np.ndarray:
    z = np.zeros((N, N))
    z[CREST_ROW, :] = CREST_M  # a straight crest along x, near the tile's far (north) edge
    return z


def _crest_hidden_closed_form(c: np.ndarray, tx: np.ndarray) -> np.ndarray:
    """Whether the straight segment from each centroid to ``tx`` passes below the crest
    line (y = y_c, z = h) of the tile or of its periodic copy to the south."""
    hidden = np.zeros(c.shape[0], dtype=bool)
    d = tx - c
    for y_crest in (X[CREST_ROW], X[CREST_ROW] - PERIOD):
        t = (y_crest - c[:, 1]) / d[:, 1]  # where the segment crosses the crest's line
        z = c[:, 2] + t * d[:, 2]
        hidden |= (t > 0) & (t < 1) & (z < CREST_M)
    return hidden


@pytest.fixture(scope="module")
def crest():
    z = _crest_tile()
    c, _, nrm = facet_geometry(grid_vertices(X, X, z))
    return z, c, nrm


@pytest.mark.parametrize("tx", [np.array([0.0, -4000.0, 200.0]),      # psi = 2.86 deg
                                np.array([1500.0, -4000.0, 180.0])],   # oblique
                         ids=["south", "oblique"])
def test_crest_shadow_length_closed_form(crest, tx):
    """With the apron a crest of 1 m shadows h / tan(psi) (about 20 m here) behind each
    copy: the facets near the tile's south edge lie in the shadow of the copy's crest."""
    z, c, nrm = crest
    flat = np.abs(c[:, 2]) < 1e-12
    flat &= np.abs(c[:, 1] - X[CREST_ROW]) > 1.5 * DX  # not on the crest's own slopes
    expected = _crest_hidden_closed_form(c, tx)
    # the shadow edge inside the tile, not at its border: both cases present
    assert 0.2 < expected[flat].mean() < 0.8
    # away from the shadow's edge (0.3 m of ground), where float32 rounding cannot decide
    d = tx - c
    y_edge = X[CREST_ROW] - PERIOD + CREST_M * np.hypot(d[:, 0], d[:, 1]) / d[:, 2] * (
        -d[:, 1] / np.hypot(d[:, 0], d[:, 1]))
    clear = flat & (np.abs(c[:, 1] - y_edge) > 0.3)
    apron = FacetTracer(X, X, z, period_m=(PERIOD, PERIOD)).occluded(c, nrm, tx)
    np.testing.assert_array_equal(apron[clear], expected[clear])
    alone = FacetTracer(X, X, z).occluded(c, nrm, tx)
    assert not alone[clear & (c[:, 1] < X[CREST_ROW])].any()  # nothing in front of them


def test_apron_equals_explicit_copies(gaussian_surface):
    """A Gaussian tile with its apron against the tile repeated in one larger mesh (seams
    closed): the same occlusion masks at 1 deg grazing (shadows of about 2.5 tiles)."""
    z = gaussian_surface(N, DX, corr_len=6.0, sigma_h=0.5, rng=np.random.default_rng(5))
    tx = np.array([700.0, -3000.0, 3080.0 * np.tan(np.radians(1.0))])
    c, _, nrm = facet_geometry(grid_vertices(X, X, z))
    tracer = FacetTracer(X, X, z, period_m=(PERIOD, PERIOD))
    copies, reach = tracer.apron_copies(c, tx)
    assert (0, -1) in copies and (0, -3) in copies and (1, -1) in copies
    assert np.all(reach <= np.linalg.norm(tx - c, axis=1))
    apron = tracer.occluded(c, nrm, tx)
    rows, cols = 6, 3  # copies j = -5..0, i = -1..1, closing node row and column
    zb = np.tile(z, (rows, cols))
    zb = np.hstack([np.vstack([zb, zb[:1]]), np.vstack([zb, zb[:1]])[:, :1]])
    xb = X[0] - PERIOD + np.arange(cols * N + 1) * DX
    yb = X[0] - (rows - 1) * PERIOD + np.arange(rows * N + 1) * DX
    explicit = FacetTracer(xb, yb, zb).occluded(c, nrm, tx)
    assert np.mean(apron != explicit) < 1e-3  # float32 ties only
    alone = FacetTracer(X, X, z).occluded(c, nrm, tx)
    assert apron.sum() > alone.sum() * 1.2  # the apron adds the missing shadows
    assert np.all(apron >= alone)  # and removes none


def test_high_grazing_needs_no_copies(gaussian_surface):
    """At 60 deg grazing the shadows (z_max / tan psi < 1 m) stay within one cell: at
    most the neighbouring copies, and the masks equal the tile's alone but at its edge."""
    z = gaussian_surface(N, DX, corr_len=6.0, sigma_h=0.3, rng=np.random.default_rng(2))
    tx = np.array([0.0, -500.0, 500.0 * np.tan(np.radians(60.0))])
    c, _, nrm = facet_geometry(grid_vertices(X, X, z))
    tracer = FacetTracer(X, X, z, period_m=(PERIOD, PERIOD))
    copies, _ = tracer.apron_copies(c, tx)
    assert set(copies) <= {(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0)}
    inner = (np.abs(c[:, 0]) < 12) & (np.abs(c[:, 1]) < 12)
    np.testing.assert_array_equal(tracer.occluded(c, nrm, tx)[inner],
                                  FacetTracer(X, X, z).occluded(c, nrm, tx)[inner])


def test_period_must_be_positive():
    with pytest.raises(ValueError, match="period_m"):
        FacetTracer(X, X, period_m=(0.0, PERIOD))


def test_mesh_closes_the_seams_with_the_periodic_continuation(gaussian_surface):
    """The periodic sea at x_0 + L_x (y_0 + L_y) is the sea at x_0 (y_0): the mesh's
    closing node column and row repeat the first ones (eq A1's periodic model), so the
    strip between the tile and its copies is the sea's own (not a flat extension)."""
    z = gaussian_surface(N, DX, corr_len=6.0, sigma_h=0.5, rng=np.random.default_rng(7))
    mesh = FacetTracer(X, X, z, period_m=(PERIOD, PERIOD))._mesh_elevation(z)
    assert mesh.shape == (N + 1, N + 1)
    np.testing.assert_array_equal(mesh[:N, :N], z)
    np.testing.assert_array_equal(mesh[N, :N], z[0])
    np.testing.assert_array_equal(mesh[:N, N], z[:, 0])
    assert mesh[N, N] == z[0, 0]
