"""Visibility in the hull trace: the sea hides the submerged hull, objects block rays."""

from __future__ import annotations

import numpy as np
import pytest
from ship_helpers import FAR, LAM, db, direction

from seaecho.targets import canonical
from seaecho.tracing.sbr import SBROptions, SeaPlane, TraceMesh, trace_signature

DELTA = LAM / 4


def _vertical_plate(a, b, z0):
    """Plate a (along y) x b (along z) in the plane x = 0, bottom at z0, facing -x."""
    v, f = canonical.rectangular_plate(b, a)  # x: b, y: a in z = 0
    v = v[:, [2, 1, 0]]  # -> x = 0, z along the old x
    v[:, 2] += z0 + b / 2
    return v, f


def _sig(mesh, u, **kw):
    tx = FAR * np.asarray(u)
    return trace_signature(TraceMesh.single(*mesh), tx, tx, 10e9,
                           options=SBROptions(rays_per_wavelength=4), **kw)


def test_submerged_half_of_a_plate_is_hidden():
    # A vertical plate half under the mean sea (z from -b/2 to b/2), seen at normal
    # incidence along the horizon: only the upper half echoes, 4 pi (A/2)^2 / lambda^2
    # (-6.02 dB from the whole plate) within 0.1 dB; the sea without multipath only hides.
    a, b = 40 * DELTA, 40 * DELTA
    u = direction(0.0, 180.0)
    whole = _sig(_vertical_plate(a, b, 2.0), u)
    half = _sig(_vertical_plate(a, b, -b / 2), u, sea=SeaPlane())
    assert db(half.rcs[0] / whole.rcs[0]) == pytest.approx(-6.02, abs=0.1)
    # a traced flat sea patch at z = 0 hides it the same way
    x = np.linspace(-1.0, 1.0, 5)
    patch = (x, x, np.zeros((5, 5)))
    half_patch = _sig(_vertical_plate(a, b, -b / 2), direction(5.0, 180.0),
                      sea=SeaPlane(patch=patch))
    half_plane = _sig(_vertical_plate(a, b, -b / 2), direction(5.0, 180.0), sea=SeaPlane())
    assert db(half_patch.rcs[0] / half_plane.rcs[0]) == pytest.approx(0.0, abs=0.1)


def test_a_wave_crest_hides_the_hull():
    # A sea patch with a 1 m crest between the radar (low grazing) and a plate 0.5 m high
    # blocks it entirely; without the crest the plate echoes.
    a, b = 20 * DELTA, 20 * DELTA
    plate = _vertical_plate(a, b, 0.05)
    u = direction(2.0, 180.0)
    x = np.linspace(-3.0, 1.0, 41)
    y = np.linspace(-1.0, 1.0, 21)
    z = np.zeros((y.size, x.size))
    z[:, (x > -2.0) & (x < -1.0)] = 1.0
    blocked = _sig(plate, u, sea=SeaPlane(patch=(x, y, z)))
    clear = _sig(plate, u, sea=SeaPlane(patch=(x, y, np.zeros_like(z))))
    assert clear.rcs[0] > 1.0
    assert blocked.rcs[0] < 1e-6 * clear.rcs[0]


def test_an_object_in_front_blocks_the_plate():
    # A box between the radar and the plate (another [[objects]] entry) blocks it; a box
    # beside the line of sight does not.
    a, b = 20 * DELTA, 20 * DELTA
    plate = _vertical_plate(a, b, 1.0)
    u = direction(0.0, 180.0)
    box_v = np.array([[x, y, z] for x in (-2.0, -1.5) for y in (-1.0, 1.0)
                      for z in (0.0, 3.0)])
    import trimesh

    hull = trimesh.convex.convex_hull(box_v)
    box = TraceMesh.single(hull.vertices, hull.faces)
    free = _sig(plate, u)
    blocked = _sig(plate, u, occluders=[box])
    beside = _sig(plate, u, occluders=[TraceMesh.single(hull.vertices + [0, 5.0, 0],
                                                        hull.faces)])
    assert blocked.rcs[0] < 1e-9 * free.rcs[0]
    assert db(beside.rcs[0] / free.rcs[0]) == pytest.approx(0.0, abs=1e-6)


def test_transmitter_inside_the_hull_is_refused():
    v, f = canonical.sphere(1.0, 2)
    with pytest.raises(ValueError, match="bounding sphere"):
        trace_signature(TraceMesh.single(v, f), [0.5, 0, 0], [100.0, 0, 0], 10e9)


def test_a_batch_of_no_rays_is_no_hits():
    # Found by the fuzzing suite: when no ray of a batch hit at the first bounce, the
    # second bounce asked Mitsuba to intersect empty arrays, and Dr.Jit aborted the whole
    # process ("jit_var(r0): unknown variable!"), on the main thread as on a worker
    from seaecho.tracing.sbr import _intersect, _mi_scene
    from seaecho.tracing.variant import mitsuba_modules

    _, mi, _ = mitsuba_modules()  # the process's variant, as the tracer takes it
    keep: list = []
    scene = _mi_scene(mi, np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]),
                      np.array([[0, 1, 2]]), keep)
    t, prim = _intersect(mi, scene, np.zeros((0, 3)), np.zeros((0, 3)))
    assert t.shape == (0,) and prim.shape == (0,) and prim.dtype == np.int64
    t, prim = _intersect(mi, scene, np.array([[0.2, 0.2, 1.0]]), np.array([[0, 0, -1.0]]))
    assert t[0] == pytest.approx(1.0) and prim[0] == 0
