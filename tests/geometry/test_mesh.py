"""Grid mesh facets: counts, orientation, areas, interpolation, smooth-surface normals."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from seaecho.geometry.mesh import (
    facet_count,
    facet_geometry,
    grid_faces,
    grid_vertices,
    to_facets,
)


def _grid(nx=9, ny=7, dx=1.5, dy=0.75):
    return (np.arange(nx) - nx / 2) * dx, (np.arange(ny) - ny / 2) * dy


def test_count_and_faces_match_vertices():
    x, y = _grid()
    faces = grid_faces(x.size, y.size)
    assert faces.shape == (facet_count(x.size, y.size), 3) == (2 * 8 * 6, 3)
    assert faces.max() == x.size * y.size - 1
    # 512 x 512 nodes give 522k triangles (2 x 511 x 511)
    assert facet_count(512, 512) == 522_242


def test_flat_sea_normals_up_and_areas_sum_to_tile():
    x, y = _grid()
    c, area, n = facet_geometry(grid_vertices(x, y, np.zeros((y.size, x.size))))
    np.testing.assert_allclose(n, np.tile([0.0, 0.0, 1.0], (n.shape[0], 1)), atol=0)
    np.testing.assert_allclose(area.sum(), (x[-1] - x[0]) * (y[-1] - y[0]), rtol=1e-12)
    # centroid of triangle 0 of cell (0, 0) at (x0 + 2dx/3, y0 + dy/3)
    np.testing.assert_allclose(c[0], [x[0] + 1.0, y[0] + 0.25, 0.0])


def test_faces_agree_with_facet_geometry():
    """The Mitsuba face list and the slicing used for float64 geometry give the same triangles."""
    x, y = _grid()
    rng = np.random.default_rng(1)
    v = grid_vertices(x, y, rng.normal(size=(y.size, x.size)))
    tri = v.reshape(-1, 3)[grid_faces(x.size, y.size).astype(int)]
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    c, area, n = facet_geometry(v)
    np.testing.assert_allclose(tri.mean(axis=1), c, atol=1e-12)
    np.testing.assert_allclose(0.5 * np.linalg.norm(cross, axis=1), area, rtol=1e-12)
    np.testing.assert_allclose(cross / np.linalg.norm(cross, axis=1)[:, None], n, atol=1e-12)


def test_linear_field_interpolates_exactly_at_centroids():
    x, y = _grid()
    xx, yy = np.meshgrid(x, y)
    f = 2.0 + 0.3 * xx - 1.1 * yy
    c, _, _ = facet_geometry(grid_vertices(x, y, np.zeros_like(xx)))
    np.testing.assert_allclose(to_facets(f), 2.0 + 0.3 * c[:, 0] - 1.1 * c[:, 1], atol=1e-12)


def test_plane_normal_is_exact():
    """A tilted plane z = a x + b y has the normal (-a, -b, 1)/norm on every facet."""
    x, y = _grid()
    xx, yy = np.meshgrid(x, y)
    _, _, n = facet_geometry(grid_vertices(x, y, 0.2 * xx - 0.4 * yy))
    expected = np.array([-0.2, 0.4, 1.0]) / np.sqrt(1.2)
    np.testing.assert_allclose(n, np.broadcast_to(expected, n.shape), atol=1e-14)


def test_sinusoid_normals_match_analytic_within_taylor_bound():
    """Facet normals of z = A sin(kx x + ky y) vs the analytic normal at the centroid.

    The facet slope is a finite difference over one cell: its error against the exact
    slope at the centroid is bounded by |z''| h = A k^2 h (Taylor remainder, h the larger
    cell side), and the angle between the normals by the slope error.
    """
    a, kx, ky = 0.4, 0.21, -0.13
    x, y = _grid(64, 48, 0.5, 0.7)
    xx, yy = np.meshgrid(x, y)
    c, _, n = facet_geometry(grid_vertices(x, y, a * np.sin(kx * xx + ky * yy)))
    g = a * np.cos(kx * c[:, 0] + ky * c[:, 1])
    exact = np.stack([-g * kx, -g * ky, np.ones_like(g)], axis=-1)
    exact /= np.linalg.norm(exact, axis=1)[:, None]
    angle = np.arccos(np.clip(np.einsum("ij,ij->i", n, exact), -1, 1))
    bound = a * (kx**2 + ky**2) * 0.7
    assert angle.max() < bound
    assert angle.max() > 0.05 * bound  # the bound is not vacuous


@settings(max_examples=25, deadline=None)
@given(arrays(np.float64, (6, 5), elements=st.floats(-3, 3)))
def test_normals_unit_up_and_area_at_least_projected(z):
    x, y = _grid(5, 6)
    _, area, n = facet_geometry(grid_vertices(x, y, z))
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, rtol=1e-12)
    assert np.all(n[:, 2] > 0)
    # projected area of each triangle is half a cell; the slanted one is at least that
    assert np.all(area * n[:, 2] == pytest.approx(0.5 * 1.5 * 0.75, rel=1e-9))


def test_bad_grid_rejected():
    x, y = _grid()
    with pytest.raises(ValueError, match="does not match"):
        grid_vertices(x, y, np.zeros((x.size, y.size)))
    with pytest.raises(ValueError, match="increasing"):
        grid_vertices(x[::-1], y, np.zeros((y.size, x.size)))


def test_facet_geometry_in_a_kernel_equals_numpy_bit_for_bit():
    # The fused sea kernel computes each facet from its gathered vertices: the same
    # formulas (mesh.triangle, mesh.vertex_mean) as the numpy slices, the same numbers.
    from seaecho import backend
    from seaecho.backend import Boundary
    from seaecho.geometry.mesh import facet_geometry_in

    if not backend.drjit_available():
        pytest.skip("Dr.Jit LLVM backend unavailable")
    xp = backend.drjit_namespace()
    rng = np.random.default_rng(1)
    x, y = np.arange(30) * 0.25, 3.0 + np.arange(24) * 0.3
    z, v = rng.normal(0, 0.3, (24, 30)), rng.normal(size=(24, 30, 3))
    want = (*facet_geometry(grid_vertices(x, y, z)), to_facets(v))
    io = Boundary(xp)
    g = facet_geometry_in(xp, io.array(x), io.array(y), io.array(z.ravel()),
                          io.vec3(v.reshape(-1, 3)), 30, 24)
    got = Boundary(xp, want[1].size).numpy(g["centroid"], g["area"], g["normal"],
                                             g["velocity"])
    for a, b in zip(got, want, strict=True):
        assert a.tobytes() == b.tobytes()
