"""A box over a flat sea: the ray-traced shadow is the analytic shadow polygon; moving it."""

import numpy as np
import pytest
from scipy.spatial import ConvexHull, Delaunay

from seaecho.tracing.scene import ObjectGeometry
from seaecho.tracing.tracer import FacetTracer

N = 64
X = (np.arange(N) - N / 2) * 1.0


def _box(lo, hi, velocity=(0.0, 0.0, 0.0), name="box"):
    import trimesh

    m = trimesh.creation.box(bounds=[lo, hi])
    return ObjectGeometry(name, np.asarray(m.vertices, float), np.asarray(m.faces, np.uint32),
                          velocity=np.asarray(velocity, float))


def _shadow_polygon(lo, hi, source):
    """Shadow of a box on z = 0 from a point source: hull of its footprint and of the
    central projections of its top corners onto the plane (closed form)."""
    corners = np.array([[x, y] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])])
    top = np.column_stack([corners, np.full(4, hi[2])])
    s = (source[2]) / (source[2] - top[:, 2])  # ray source + s (corner - source) hits z = 0
    proj = source[None, :2] + s[:, None] * (top[:, :2] - source[None, :2])
    pts = np.vstack([corners, proj])
    return pts[ConvexHull(pts).vertices]


def _distance_to_polygon_edges(points, poly):
    d = np.full(points.shape[0], np.inf)
    for a, b in zip(poly, np.roll(poly, -1, axis=0), strict=True):
        ab = b - a
        t = np.clip(((points - a) @ ab) / (ab @ ab), 0, 1)
        d = np.minimum(d, np.linalg.norm(points - (a + t[:, None] * ab), axis=1))
    return d


@pytest.mark.parametrize("source", [np.array([-150.0, -90.0, 40.0]),
                                    np.array([120.0, 30.0, 15.0])])
def test_box_shadow_matches_shadow_polygon(source):
    lo, hi = np.array([-6.0, -4.0, -2.0]), np.array([5.0, 3.0, 4.0])
    tr = FacetTracer(X, X, objects=[_box(lo, hi)])
    f = tr.facets(np.zeros((N, N)), None, source)
    poly = _shadow_polygon(lo, hi, source)
    xy = f.centroid[:, :2]
    inside = Delaunay(poly).find_simplex(xy) >= 0
    # facets whose centroid is within 1 mm of the polygon's edges are undecided (ray
    # origins are lifted by 1 mm and Mitsuba works in float32)
    clear = _distance_to_polygon_edges(xy, poly) > 1e-3
    assert inside.sum() > 100
    np.testing.assert_array_equal(f.lit[clear] == 0, inside[clear])


def test_moving_box_shadow_moves():
    """A box moving at v: its shadow at time t is the time-0 shadow shifted by v t."""
    lo, hi = np.array([-6.0, -4.0, -2.0]), np.array([5.0, 3.0, 4.0])
    v = np.array([4.0, -2.0, 0.0])
    source = np.array([-150.0, -90.0, 40.0])
    tr = FacetTracer(X, X, objects=[_box(lo, hi, v)])
    assert tr.moving_objects is not None and tr.static_objects is None
    shadows = []
    for t in (0.0, 2.5):
        f = tr.facets(np.zeros((N, N)), None, source, t=t)
        poly = _shadow_polygon(lo + v * t, hi + v * t, source)
        xy = f.centroid[:, :2]
        clear = _distance_to_polygon_edges(xy, poly) > 1e-3
        np.testing.assert_array_equal(f.lit[clear] == 0,
                                      (Delaunay(poly).find_simplex(xy) >= 0)[clear])
        shadows.append(xy[f.lit == 0].mean(axis=0))
    # the shadow's centroid moved by about v t (one cell of discretisation)
    np.testing.assert_allclose(shadows[1] - shadows[0], v[:2] * 2.5, atol=1.0)


def test_bistatic_box_seen_and_lit_differ():
    lo, hi = np.array([-6.0, -4.0, -2.0]), np.array([5.0, 3.0, 4.0])
    tx, rx = np.array([-150.0, -90.0, 40.0]), np.array([120.0, 30.0, 15.0])
    tr = FacetTracer(X, X, objects=[_box(lo, hi)])
    f = tr.facets(np.zeros((N, N)), None, tx, rx)
    for vis, src in ((f.lit, tx), (f.seen, rx)):
        poly = _shadow_polygon(lo, hi, src)
        xy = f.centroid[:, :2]
        clear = _distance_to_polygon_edges(xy, poly) > 1e-3
        np.testing.assert_array_equal(vis[clear] == 0,
                                      (Delaunay(poly).find_simplex(xy) >= 0)[clear])
    np.testing.assert_array_equal(f.visibility, f.lit * f.seen)
    assert (f.lit != f.seen).sum() > 100
