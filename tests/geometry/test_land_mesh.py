"""The land's mesh: shore polygon and height profile (eq G1 of seaecho.geometry.land)."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.geometry.land import distance_to_outline, inside_polygon, land_mesh


def test_polygon_inclusion_and_distance():
    square = [[0, 0], [10, 0], [10, 10], [0, 10]]
    pts = np.array([[5, 5], [11, 5], [0.5, 9], [-1, -1]])
    assert inside_polygon(pts, square).tolist() == [True, False, True, False]
    assert distance_to_outline(pts, square) == pytest.approx([5, 1, 0.5, np.sqrt(2)])


def test_even_odd_rule_on_a_concave_outline():
    # a U (a bay 40 m wide and 60 m deep cut into a 100 m square from the north): a
    # horizontal ray from a point left of the outline, or in the bay, crosses it an even
    # number of times (Franklin's crossing test): outside; on the land, an odd number
    u = [[0, 0], [100, 0], [100, 100], [70, 100], [70, 40], [30, 40], [30, 100], [0, 100]]
    pts = np.array([[-5, 50], [-5, 20], [50, 70], [50, 20], [15, 70], [85, 70], [110, 70]])
    assert inside_polygon(pts, u).tolist() == [False, False, False, True, True, True, False]
    assert inside_polygon(pts, u[::-1]).tolist() == inside_polygon(pts, u).tolist()
    # the mesh covers the U's area, 100^2 - 40 x 60 m^2 (its edges on the 10 m grid)
    v, f, _ = land_mesh(u, 5.0, 0.0, 10.0)
    tri = v[f]
    area = 0.5 * np.abs(np.cross(tri[:, 1, :2] - tri[:, 0, :2], tri[:, 2, :2] - tri[:, 0, :2]))
    assert area.sum() == pytest.approx(100**2 - 40 * 60)


def test_mesh_follows_the_profile_and_faces_up():
    outline = [[0, 0], [400, 0], [400, 300], [0, 300]]
    v, f, cells = land_mesh(outline, 30.0, 50.0, 10.0)
    d = np.minimum.reduce([v[:, 0], 400 - v[:, 0], v[:, 1], 300 - v[:, 1]])
    # eq G1: z = H min(d / W, 1), 0 on the shore
    assert v[:, 2] == pytest.approx(30.0 * np.minimum(np.maximum(d, 0) / 50.0, 1.0))
    tri = v[f]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    assert (n[:, 2] > 0).all()
    # the grid cells inside: the polygon's area (it is on the grid here)
    assert 0.5 * np.abs(n[:, 2]).sum() == pytest.approx(400 * 300)
    assert cells.shape == (f.shape[0], 2)


def test_a_coarse_grid_with_no_cell_inside_is_refused():
    with pytest.raises(ValueError, match="no grid cell inside"):
        land_mesh([[0, 0], [1, 0], [0, 1]], 5.0, 0.0, 10.0)
