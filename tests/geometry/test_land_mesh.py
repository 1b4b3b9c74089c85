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
