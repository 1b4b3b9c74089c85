"""The grid walk of the sea's shadow rays (seaecho.tracing.heightfield) against Embree.

An independent method: the same segments traced by Mitsuba / Embree against the sea's
mesh through its BVH (the path the walk replaces) give the same occlusion masks, facet
for facet, on rough random seas, with and without the periodic apron and with an object,
for steep, oblique, grazing and axis-aligned rays. Closed form: a flat sea hides nothing,
and a straight wall hides the facets whose segment passes below its top (geometric
optics).
"""

import numpy as np
import pytest

from seaecho.geometry.mesh import facet_geometry, grid_vertices
from seaecho.tracing import tracer as tracer_module
from seaecho.tracing.heightfield import WALK_MAX_CELLS, walk_cells
from seaecho.tracing.scene import ObjectGeometry, segments_blocked
from seaecho.tracing.tracer import FacetTracer

N, DX = 40, 0.5
X = (np.arange(N) - N // 2) * DX
Y = (np.arange(N - 6) - (N - 6) // 2) * 0.4  # another spacing along y
#: transmitter positions: steep, oblique, low, grazing, due north (d_x = 0), due east
POSITIONS = {"steep": (-300.0, 40.0, 300.0), "oblique": (250.0, -400.0, 120.0),
             "low": (-600.0, -150.0, 25.0), "grazing": (0.0, 900.0, 12.0),
             "north": (0.0, 500.0, 40.0), "east": (500.0, 0.0, 40.0)}


@pytest.fixture(autouse=True)
def _walk_everywhere(monkeypatch, request):
    """The walk however long (its masks do not depend on where the tracer switches)."""
    if "long_walks" not in request.node.name:
        monkeypatch.setattr(tracer_module, "WALK_MAX_CELLS", np.inf)


def _masks(z, tx, period=None, objects=()):
    """(walked, BVH) occlusion masks of every facet of ``z`` from ``tx``."""
    c, _, nrm = facet_geometry(grid_vertices(X, Y, z))
    tr = FacetTracer(X, Y, z, period_m=period, objects=objects)
    assert tr._walks(np.array(tx))
    walked = tr.occluded(c, nrm, np.array(tx))
    tr.walk = False
    return walked, tr.occluded(c, nrm, np.array(tx))


@pytest.mark.parametrize("where", list(POSITIONS))
@pytest.mark.parametrize("periodic", [False, True], ids=["tile", "apron"])
def test_walk_equals_bvh_on_a_rough_sea(gaussian_surface, where, periodic):
    # rms slope 0.35: many facets hidden at the low positions, a few at the steep one
    rng = np.random.default_rng(7)
    z = gaussian_surface(N, DX, 2.0, 0.5, rng)[: Y.size]
    period = (N * DX, Y.size * 0.4) if periodic else None
    walked, bvh = _masks(z, POSITIONS[where], period)
    assert np.array_equal(walked, bvh)
    if where in ("low", "grazing"):
        assert 0.05 < bvh.mean() < 0.99  # the test sees both cases


def test_walk_with_an_object_equals_bvh(gaussian_surface):
    # a 3 m box over the tile: its shadow comes from its own BVH, the sea's from the walk
    rng = np.random.default_rng(8)
    z = gaussian_surface(N, DX, 2.0, 0.3, rng)[: Y.size]
    v = np.array([[x, y, h] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for h in (-1.0, 3.0)])
    f = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]],
                 dtype=np.uint32)
    box = ObjectGeometry("box", v, f)
    walked, bvh = _masks(z, POSITIONS["low"], objects=[box])
    assert np.array_equal(walked, bvh)
    _, sea_only = _masks(z, POSITIONS["low"])
    assert (bvh & ~sea_only).any()  # the box hides facets the sea does not


def test_flat_sea_hides_nothing_and_a_wall_hides_what_passes_below_it():
    z = np.zeros((Y.size, N))
    walked, _ = _masks(z, POSITIONS["low"])
    assert not walked.any()
    wall_h = 1.5
    z[:, 30] = wall_h  # a straight wall along y at x = X[30]
    tx = np.array([80.0, 3.0, 20.0])
    c, _, nrm = facet_geometry(grid_vertices(X, Y, z))
    tr = FacetTracer(X, Y, z)
    hidden = tr.occluded(c, nrm, tx)
    d = tx - c
    t = (X[30] - c[:, 0]) / d[:, 0]  # where the segment crosses the wall's line
    below = (t > 0) & (c[:, 2] + t * d[:, 2] < wall_h)
    far = np.abs(c[:, 0] - X[30]) > 2 * DX  # off the wall's own slopes
    clear = np.abs(c[:, 2] + t * d[:, 2] - wall_h) > 0.05  # away from the shadow's edge
    assert below[far & clear].any() and (~below[far & clear]).any()
    assert np.array_equal(hidden[far & clear], below[far & clear])


def test_long_walks_use_the_bvh_and_the_bvh_follows_the_surface(gaussian_surface):
    rng = np.random.default_rng(9)
    z = gaussian_surface(N, DX, 2.0, 0.5, rng)[: Y.size]
    tr = FacetTracer(X, Y, np.zeros_like(z))
    low = np.array([0.0, 5000.0, 2.0])  # 0.02 deg: thousands of cells per ray
    assert walk_cells(X, Y, z.min(), z.max(), low) > WALK_MAX_CELLS
    tr.set_surface(z)
    assert not tr._walks(low)
    # the lazily rebuilt BVH is that of the new surface: the segment through a crest
    k = np.unravel_index(np.argmax(z), z.shape)
    crest = np.array([X[k[1]], Y[k[0]], 0.0])
    start = crest - np.array([3.0, 0.0, 0.0])
    assert segments_blocked([tr.sea.mi_scene], start, crest + np.array([3.0, 0.0, 0.0]),
                            variant=tr.variant)[0]
