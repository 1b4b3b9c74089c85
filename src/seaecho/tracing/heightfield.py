"""Shadow rays against the sea's height-field mesh by a walk over its grid cells (no BVH).

The sea is a height field on a regular grid: the triangles that a segment can hit are
those of the cells that its horizontal projection crosses. :func:`heightfield_blocked`
walks those cells in order along each ray (the grid traversal of Amanatides & Woo 1987)
and tests the two triangles of each cell with the ray-triangle test of Moeller &
Trumbore (1997) in float32, written as Embree evaluates it for Mitsuba's scenes (the
same vertex order, edge vectors, geometric normal, sign handling and depth test), on the
float32 mesh that the sea's Mitsuba scene holds. A ray stops at the first hit, at the
end of its segment, where it rises above the highest node (it can hit nothing beyond),
or where it leaves a grid that is not periodic. On a periodic sea (an FFT tile) the walk
continues into the tile's periodic copies, each tested as
:meth:`seaecho.tracing.tracer.FacetTracer` tests them with Embree: the segment
translated by -T against the tile (eq A1 of that module), up to its reach (eq A2).

No acceleration structure is built: a new surface costs nothing before its rays, where
Embree rebuilds its BVH (a few hundred ms of CPU at 512 x 512). The walk's cost grows with
the number of cells a ray crosses before it clears the waves, about
``(z_max - z_min) / tan(elevation)`` over the cell size: :func:`walk_cells` estimates it,
and :class:`~seaecho.tracing.tracer.FacetTracer` walks only when it is at most
:data:`WALK_MAX_CELLS` (steep rays: airborne radars, short ranges), else it traces the
BVH. Both give the same occlusion: the masks agreed on every facet of Simulation 2's
sea at elevations from 0.5 to 45 deg, with and without the periodic apron
(``tests/tracing/test_heightfield.py``; docs/performance.md section 1).

References
----------
.. [1] J. Amanatides and A. Woo, "A fast voxel traversal algorithm for ray tracing",
   Eurographics '87, 3-10, 1987.
.. [2] T. Moeller and B. Trumbore, "Fast, minimum storage ray-triangle intersection",
   Journal of Graphics Tools 2(1), 21-28, 1997.
.. [3] I. Wald et al., "Embree: a kernel framework for efficient CPU ray tracing", ACM
   Transactions on Graphics 33(4), 143, 2014 (``triangle_intersector_moeller.h``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["WALK_MAX_CELLS", "heightfield_blocked", "walk_cells"]

#: Largest estimated walk (cells per ray, :func:`walk_cells`) for which the tracer walks
#: the grid instead of building and tracing the BVH [-].
WALK_MAX_CELLS = 128.0


def walk_cells(x: np.ndarray, y: np.ndarray, z_min: float, z_max: float,
               position: np.ndarray) -> float:
    """Estimated number of cells a shadow ray from the sea to ``position`` crosses before
    it rises above the highest wave [-]: ``(z_max - z_min) / tan(e)`` over the smaller grid
    spacing, ``e`` the lowest elevation of ``position`` seen from the tile's corners at
    ``z_min`` (inf when ``position`` is not above every corner).

    Parameters
    ----------
    x, y : (nx,), (ny,) arrays
        Node coordinates [m].
    z_min, z_max : float
        Lowest and highest node heights [m].
    position : (3,) array
        Transmitter or receiver position [m].
    """
    p = np.asarray(position, dtype=np.float64)
    cx = np.array([x[0], x[-1], x[-1], x[0]])
    cy = np.array([y[0], y[0], y[-1], y[-1]])
    rise = p[2] - z_min
    run = np.hypot(p[0] - cx, p[1] - cy).max()
    if not rise > 0.0:
        return float("inf")
    cell = min(float(x[1] - x[0]), float(y[1] - y[0]))
    return float((z_max - z_min) * run / rise / cell)


def _cross(a, b):
    # as Embree's (non-FMA) cross product: products, then differences
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _triangle_hit(dr, o, d, tfar, v0, v1, v2):
    """Whether the ray ``o + t d``, 0 < t <= tfar, hits the triangle (v0, v1, v2): the
    Moeller-Trumbore test as Embree evaluates it [2, 3] (no back-face culling, float32)."""
    e1 = (v0[0] - v1[0], v0[1] - v1[1], v0[2] - v1[2])
    e2 = (v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2])
    ng = _cross(e2, e1)
    c = (v0[0] - o[0], v0[1] - o[1], v0[2] - o[2])
    r = _cross(c, d)
    den = _dot(ng, d)
    neg = den < 0
    u = dr.select(neg, -_dot(r, e2), _dot(r, e2))
    v = dr.select(neg, -_dot(r, e1), _dot(r, e1))
    t = dr.select(neg, -_dot(ng, c), _dot(ng, c))
    absden = dr.abs(den)
    return ((den != 0) & (u >= 0) & (v >= 0) & (u + v <= absden) & (t > 0)
            & (t <= absden * tfar))


def heightfield_blocked(xp, vertices: np.ndarray, origin: Any, direction: Any, maxt: Any,
                        period_m: tuple[float, float] | None = None,
                        reach: Any = None) -> Any:
    """Whether each ray segment hits the height-field mesh (module docstring).

    Parameters
    ----------
    xp : seaecho.backend.DrJitNamespace
        The tracer's Dr.Jit namespace.
    vertices : (ny, nx, 3) float32 array
        The mesh's vertices on a regular grid (:func:`seaecho.geometry.mesh.grid_vertices`
        in float32, as the sea's Mitsuba scene holds them; a periodic sea's mesh with its
        closing row and column).
    origin, direction : namespace vectors (float64)
        Ray origins [m] and unit directions [-].
    maxt : namespace array (float64)
        Segment lengths [m].
    period_m : (float, float), optional
        The tile's periods (L_x, L_y) [m]: walk on into the periodic copies.
    reach : namespace array (float64), optional
        With ``period_m``: the segment's length tested against each copy [m] (eq A2).

    Returns
    -------
    namespace Bool
        True where the segment hits the mesh.
    """
    dr, m = xp.dr, xp.module
    f32, f64, i32 = m.Float32, m.Float64, m.Int32
    v = np.asarray(vertices)
    ny, nx = v.shape[:2]
    xs = np.ascontiguousarray(v[0, :, 0], dtype=np.float32)
    ys = np.ascontiguousarray(v[:, 0, 1], dtype=np.float32)
    zs = np.ascontiguousarray(v[..., 2], dtype=np.float32).ravel()
    xn, yn, zn = f32(xs), f32(ys), f32(zs)
    x0, y0 = float(xs[0]), float(ys[0])
    hx = float(xs[-1] - xs[0]) / (nx - 1)
    hy = float(ys[-1] - ys[0]) / (ny - 1)
    z_top = dr.opaque(f64, float(zs.max()))
    periodic = period_m is not None
    cx, cy = nx - 1, ny - 1  # cells per row and per column
    o64 = (f64(origin.x), f64(origin.y), f64(origin.z))
    d64 = (f64(direction.x), f64(direction.y), f64(direction.z))
    o32 = tuple(f32(a) for a in o64)
    d32 = tuple(f32(a) for a in d64)
    tfar = f32(maxt)
    tfar_copy = f32(reach) if periodic else tfar
    # the grid walk, in float64 on the horizontal projection (t along the unit direction)
    ox, oy, oz = o64
    dx, dy, dz = d64
    i = i32(dr.floor((ox - x0) / hx))
    j = i32(dr.floor((oy - y0) / hy))
    step_i = dr.select(dx > 0, i32(1), i32(-1))
    step_j = dr.select(dy > 0, i32(1), i32(-1))
    huge = 1e300
    edge_x = x0 + (f64(i) + dr.select(dx > 0, 1.0, 0.0)) * hx
    edge_y = y0 + (f64(j) + dr.select(dy > 0, 1.0, 0.0)) * hy
    t_x = dr.select(dx != 0, (edge_x - ox) / dx, huge)  # t at the next vertical grid line
    t_y = dr.select(dy != 0, (edge_y - oy) / dy, huge)
    dt_x = dr.select(dx != 0, hx / dr.abs(dx), huge)
    dt_y = dr.select(dy != 0, hy / dr.abs(dy), huge)
    # beyond t_end the ray is above every node (rising rays) or past its end
    t_end = dr.select(dz > 0, dr.minimum(f64(maxt), (z_top - oz) / dz), f64(maxt))
    lx, ly = (float(period_m[0]), float(period_m[1])) if periodic else (0.0, 0.0)

    def cond(i, j, t_x, t_y, hit, active):
        return active

    def body(i, j, t_x, t_y, hit, active):
        if periodic:  # copy (ci, cj) of the tile, and the cell in the tile
            ci = dr.floor(f64(i) / cx)
            cj = dr.floor(f64(j) / cy)
            il, jl = i - i32(ci) * cx, j - i32(cj) * cy
            home = (ci == 0) & (cj == 0)
            # eq A1: the segment translated by -T, rounded to float32 as Embree's
            o = (dr.select(home, o32[0], f32(ox - ci * lx)),
                 dr.select(home, o32[1], f32(oy - cj * ly)), o32[2])
            tf = dr.select(home, tfar, tfar_copy)
            inside = active
        else:
            il, jl, o, tf = i, j, o32, tfar
            inside = active & (i >= 0) & (i < cx) & (j >= 0) & (j < cy)
        k = jl * nx + il
        xa = dr.gather(f32, xn, il, inside)
        xb = dr.gather(f32, xn, il + 1, inside)
        ya = dr.gather(f32, yn, jl, inside)
        yb = dr.gather(f32, yn, jl + 1, inside)
        p00 = (xa, ya, dr.gather(f32, zn, k, inside))
        p10 = (xb, ya, dr.gather(f32, zn, k + 1, inside))
        p01 = (xa, yb, dr.gather(f32, zn, k + nx, inside))
        p11 = (xb, yb, dr.gather(f32, zn, k + nx + 1, inside))
        # the cell's triangles as grid_faces orders them: (P00, P10, P11), (P00, P11, P01)
        h = (_triangle_hit(dr, o, d32, tf, p00, p10, p11)
             | _triangle_hit(dr, o, d32, tf, p00, p11, p01))
        hit = hit | (inside & h)
        along_x = t_x < t_y
        t_in = dr.select(along_x, t_x, t_y)  # where the ray enters the next cell
        i = dr.select(along_x, i + step_i, i)
        j = dr.select(along_x, j, j + step_j)
        t_x = dr.select(along_x, t_x + dt_x, t_x)
        t_y = dr.select(along_x, t_y, t_y + dt_y)
        active = inside & ~hit & (t_in <= t_end)
        return i, j, t_x, t_y, hit, active

    n = dr.width(i)
    state = (i, j, t_x, t_y, dr.zeros(m.Bool, n), dr.full(m.Bool, True, n))
    return dr.while_loop(state=state, cond=cond, body=body)[4]
