"""The radar-wide sea ([sea] coverage = "radar"): patchwork, per-pulse tiles, preflight.

The layout's laws are eqs T1-T5 of seaecho.geometry.patchwork (docs/scanning.md, "The
sea over the whole coverage"); the tile selection reuses the beam's bound (eqs C1-C2).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from seaecho.config import SceneError, load_scene
from seaecho.geometry.earth import SphericalEarth, effective_radius
from seaecho.geometry.patchwork import (
    FACETS_PER_BEAM,
    Patchwork,
    band_edges,
    level_spacings,
    max_spacing,
)

SCENE = "scenes/coastal_vts_xband.toml"


def _scene(window=(150.0, 400.0), size=32.0, nx=32, **radar):
    sc = load_scene(SCENE)
    return sc.model_copy(update={
        "sea": sc.sea.model_copy(update={"coverage": "radar", "size_x_m": size, "nx": nx}),
        "radar": sc.radar.model_copy(update={"window_start_m": window[0],
                                             "window_end_m": window[1], "n_pulses": 8,
                                             **radar}),
        "targets": (),
        "tracing": sc.tracing.model_copy(update={"subfacet_shadowing": True})})


def _patchwork(r_max=3000.0, earth=None):
    # the coastal radar's beam: 2 m at 9.41 GHz, theta = lambda / W
    return Patchwork.around((0.0, -2000.0), (1.0, 1.0), (64, 64), (250.0, r_max),
                            0.0319 / 2.0, 7.5, earth)


def test_tile_is_the_default():
    sc = load_scene(SCENE)
    assert sc.sea.coverage == "tile"


def test_levels_and_bands_closed_form():
    # eq T1: spacings double up to the largest allowed; eq T3: min(lambda_p/8, dr/2)
    assert level_spacings(1.0, 7.5) == [1.0, 2.0, 4.0]
    assert level_spacings(1.0, 7.5, nodes=32) == [1.0, 2.0]  # n_J >= 16
    assert max_spacing(73.0, 15.0) == pytest.approx(7.5)
    assert max_spacing(40.0, 15.0) == pytest.approx(5.0)
    # eq T2: R_j = 8 Delta_j / theta
    e = band_edges([1.0, 2.0, 4.0], 0.01, 100.0, 10000.0)
    np.testing.assert_allclose(e, [100.0, FACETS_PER_BEAM * 2 / 0.01,
                                   FACETS_PER_BEAM * 4 / 0.01, 10000.0])
    pw = _patchwork()
    assert [lv.shape for lv in pw.levels] == [(64, 64), (32, 32), (16, 16)]
    assert all(lv.size == (64.0, 64.0) for lv in pw.levels)  # one extent at every level


@pytest.mark.parametrize("earth", [None, SphericalEarth(effective_radius())])
def test_tiles_partition_the_window(earth):
    """Every point of the annulus has exactly one owner, inside that tile's cells and in
    its level's band; nothing outside the bands is owned."""
    pw = _patchwork(earth=earth)
    rng = np.random.default_rng(0)
    r = np.sqrt(rng.uniform(0.0, 3200.0 ** 2, 20000))
    a = rng.uniform(0, 2 * np.pi, r.size)
    q = np.stack([r * np.cos(a), -2000.0 + r * np.sin(a)], axis=-1)
    own = pw.owner(q)
    inside = (r >= 250.0) & (r < 3000.0)
    assert np.all(own[inside] >= 0) and np.all(own[~inside] == -1)
    for k in np.flatnonzero(inside)[:2000]:
        x0, x1, y0, y1 = pw.span(own[k])
        assert x0 <= q[k, 0] < x1 and y0 <= q[k, 1] < y1
        lo, hi = pw.levels[pw.level[own[k]]].band
        assert lo <= r[k] < hi


def test_owned_cells_cover_the_annulus_once():
    """The cells the tiles keep (each cell's centre owned by its tile) add up to the
    annulus's area within the staircase along its circles (half a cell of each level
    along each band edge)."""
    pw = _patchwork(r_max=900.0)
    area = 0.0
    for i in range(len(pw)):
        lv = pw.levels[pw.level[i]]
        area += pw.cell_owned(i).sum() * lv.spacing[0] * lv.spacing[1]
    exact = np.pi * (900.0 ** 2 - 250.0 ** 2)
    edges = pw.edges
    stair = sum(2 * np.pi * e * lv.spacing[0] for e, lv in zip(edges[1:], pw.levels,
                                                               strict=True))
    stair += 2 * np.pi * edges[0] * pw.levels[0].spacing[0]
    assert abs(area - exact) < stair * 0.1


def test_tile_nodes_do_not_grow_with_the_window():
    """The largest tile (the memory of one tile's facets) and the levels near the radar
    are the same for windows of 3, 6 and 12 km (closed form: (n_0 / 2^j)^2 nodes)."""
    pws = [_patchwork(r_max=r) for r in (3000.0, 6000.0, 12000.0)]
    shapes = {tuple(lv.shape for lv in pw.levels) for pw in pws}
    assert shapes == {((64, 64), (32, 32), (16, 16))}
    # the tiles of a band below 3 km are the same tiles (and seeds) in each
    for pw in pws[1:]:
        a = pws[0]
        near = a.level < 2
        keys = set(zip(a.level[near], a.ix[near], a.iy[near], strict=True))
        keys_b = {k for k in zip(pw.level, pw.ix, pw.iy, strict=True) if k[0] < 2}
        assert keys == keys_b
        assert a.seed(0, 3) == pw.seed(0, 3)


def test_tile_frame_grazing_on_the_earth():
    """Eq T5: seen from its tile's frame, the radar's depression at the tile centre is
    the grazing angle of eq E1 (the law of cosines on the 4/3 Earth)."""
    from seaecho.geometry.earth import grazing_angle

    earth = SphericalEarth(effective_radius())
    pw = _patchwork(r_max=12000.0, earth=earth)
    radar = earth.position(np.array([0.0, -2000.0, 35.0]))
    i = int(np.argmax(np.hypot(*(np.array([pw.tile_centre(k) for k in range(len(pw))])
                                 - [0.0, -2000.0]).T)))
    f = pw.frame(i)
    p = f.to_tile(radar) - f.centre
    r = np.linalg.norm(p)
    psi = np.arcsin(p[2] / r)
    assert psi == pytest.approx(float(grazing_angle(35.0, r, earth.radius)), rel=1e-6)


@pytest.mark.slow  # ~60 s each: a tracer per tile, a few dozen tiles
@pytest.mark.parametrize("update", [250, 2])  # held, evolving (renewed within the run)
def test_a_pulse_does_not_depend_on_the_tiles_computed_before(update):
    """Pulse 5 computed first, or after pulses 0-4 (other tiles held), or holding no
    tile, or with every facet of the tiles through the facet model: the same bytes."""
    from seaecho.build import sea_motion
    from seaecho.simulation import Simulation

    sc = _scene(sea_update_pulses=update)
    assert sea_motion(sc) == ("held" if update == 250 else "evolving")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = Simulation(sc)
        assert a.coverage.cached == (update == 250)  # eqs U1-U3 for the held sea
        first = a.pulse(5)
        b = Simulation(sc)
        for p in range(5):
            b.pulse(p)
        after = b.pulse(5)
        c = Simulation(sc)
        c.coverage.cache_nodes = c.coverage.cache_bytes = 0
        one = c.pulse(5)
        # the tile pipeline of every pulse: every facet through the facet model or only
        # the weighted ones (held sea: the same)
        ref, d = Simulation(sc), Simulation(sc)
        ref.coverage.cached = d.coverage.cached = False
        make = d.coverage._factory

        def whole(models, weight):
            sim = make(models, weight)
            sim.cull = False
            return sim

        d.coverage._factory = whole
        culled, uncut = ref.pulse(5), d.pulse(5)
    assert len(a.coverage.selected(5)) >= 2
    np.testing.assert_array_equal(first, after)
    np.testing.assert_array_equal(first, one)
    np.testing.assert_array_equal(culled, uncut)
    if update != 250:
        np.testing.assert_array_equal(first, culled)
    assert np.abs(first).max() > 0


@pytest.mark.parametrize("update, field", [
    ({"radar": {"window_start_m": None, "window_end_m": None}}, "window_start_m"),
    ({"radar": {"sea_gain_floor_db": "off"}}, "sea_gain_floor_db"),
    ({"transmitter": {"motion": "linear", "velocity_m_s": (1.0, 0.0, 0.0)}}, "motion"),
    ({"tracing": {"subfacet_shadowing": False}}, "subfacet_shadowing"),
])
def test_check_refuses_what_the_radar_wide_sea_cannot_run(update, field):
    from seaecho.checks.preflight import check_run

    sc = _scene()
    for sec, vals in update.items():
        sc = sc.model_copy(update={sec: getattr(sc, sec).model_copy(update=vals)})
    with pytest.raises(SceneError) as exc:
        check_run(sc, "x.toml")
    assert "[sea].coverage = 'radar'" in str(exc.value) and field in str(exc.value)


@pytest.mark.slow  # ~25 s: 18 ray-traced tiles
def test_sigma0_of_the_levels_is_grid_independent_at_low_grazing():
    """The levels of the patchwork are tiles of one extent at spacings 1, 2 and 4 m
    (eq T1). Their NRCS at the coastal radar's 1.0 deg grazing (a 128 m tile 2 km from
    the 35 m antenna, HH, sea state 4, ray traced with the sub-facet shadowing), mean of
    the tile's cells over 6 realisations each, agrees with the 1 m tile's within 0.7 dB
    (3 standard deviations of the difference of two such means, 0.2 dB each): the facet
    model is grid independent (docs/scattering.md, "Unresolved tilts and grid
    independence", 0.05 dB from 0.1 to 2 m at 20 deg). Measured: -39.05, -39.49, -39.07
    dB; without the sub-facet shadowing the 4 m tiles were 0.6 dB above the 1 m ones."""
    from seaecho.simulation import Simulation

    sc = load_scene(SCENE)
    means = []
    for n in (128, 64, 32):
        vals = []
        for seed in range(6):
            s = sc.model_copy(update={
                "sea": sc.sea.model_copy(update={"size_x_m": 128.0, "nx": n}),
                "radar": sc.radar.model_copy(update={"n_pulses": 1, "sea_update_pulses": 1}),
                "run": sc.run.model_copy(update={"seed": seed}), "targets": (),
                "tracing": sc.tracing.model_copy(update={"subfacet_shadowing": True})})
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                vals.append(Simulation(s).sea_truth()["sigma0"][0].mean())
        means.append(10 * np.log10(np.mean(vals)))
    assert means[0] == pytest.approx(-39.05, abs=0.05)  # the measurement above
    assert abs(means[1] - means[0]) < 0.7 and abs(means[2] - means[0]) < 0.7


def test_shared_cell_spectrum_and_centre_keep_the_surface():
    """A tile's surface with its level's shared cell spectrum and its centre is the
    surface of the same seed at the origin, moved: the same heights bit for bit."""
    from seaecho.build import sea_spectrum
    from seaecho.ocean.surface import SeaSurface, cell_averaged_spectrum
    from seaecho.rng import generator

    sp = sea_spectrum(load_scene(SCENE))
    a = SeaSurface(sp, (64.0, 64.0), (32, 32), generator(1, "surface"))
    k = 2 * np.pi * np.fft.fftfreq(32, 2.0)
    psi = cell_averaged_spectrum(sp, k[None, :], k[:, None], 2 * np.pi / 64, 2 * np.pi / 64)
    b = SeaSurface(sp, (64.0, 64.0), (32, 32), generator(1, "surface"), centre=(5.0, 6.0),
                   cell_spectrum=psi)
    np.testing.assert_array_equal(a.fields(0.3).elevation, b.fields(0.3).elevation)
    np.testing.assert_array_equal(b.x, a.x + 5.0)
    np.testing.assert_array_equal(b.y, a.y + 6.0)


@pytest.mark.slow  # ~7 s: two simulations (JIT, tracer)
def test_tile_coverage_is_todays_path():
    """coverage = 'tile' (the default, or given) is the single tile as before the key:
    no patchwork, the same bytes (the 4 pulses of the coastal scene on a 64 m tile of
    32 x 32 had the sha256 ccd16907... before and after the radar-wide sea landed:
    docs/scanning.md)."""
    from seaecho.simulation import Simulation

    sc = load_scene(SCENE)
    sc = sc.model_copy(update={"sea": sc.sea.model_copy(update={"size_x_m": 64.0,
                                                                "nx": 16}),
                               "radar": sc.radar.model_copy(update={"n_pulses": 2})})
    given = sc.model_copy(update={"sea": sc.sea.model_copy(update={"coverage": "tile"})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a, b = Simulation(sc), Simulation(given)
        assert a.coverage is None and a.sea is not None
        np.testing.assert_array_equal(a.pulse(1), b.pulse(1))


def test_tiles_of_a_pulse_are_those_the_beams_bound_keeps():
    """The tiles' bounds at once (two_way_bounds) are the single box's bound (eqs C1-C2)
    of each; the beam at bearing 43 deg keeps the tile under its boresight 2 km out and
    not the one opposite."""
    from seaecho.build import build_radar, coverage_layout, sea_spectrum
    from seaecho.coverage import TILE_MARGIN_M
    from seaecho.radar.coverage import two_way_bound, two_way_bounds
    from seaecho.radar.system import RadarSystem

    sc = _scene(window=(300.0, 2500.0), size=128.0, nx=128, n_pulses=400)
    model = build_radar(sc)
    pw = coverage_layout(sc, model, sea_spectrum(sc))
    radar = RadarSystem(model)
    boxes = pw.boxes(TILE_MARGIN_M)
    b = two_way_bounds(radar, 300, boxes)
    some = np.linspace(0, len(pw) - 1, 40).astype(int)
    np.testing.assert_array_equal(b[some], [two_way_bound(radar, 300, boxes[i])
                                            for i in some])
    bearing = np.radians(300 * 360.0 / 2500)  # 24 rpm at 1 kHz, clockwise from north
    ahead = pw.owner(np.array([[2000 * np.sin(bearing), -2000 + 2000 * np.cos(bearing)]]))
    behind = pw.owner(np.array([[-2000 * np.sin(bearing), -2000 - 2000 * np.cos(bearing)]]))
    assert b[ahead[0]] >= model.sea_gain_floor > b[behind[0]]


# ------------------------------------------------ the held sea's unit-gain echoes (U1-U3)
def _radar(n_pulses=400):
    from seaecho.build import build_radar
    from seaecho.radar.system import RadarSystem

    sc = _scene(window=(300.0, 3000.0), n_pulses=n_pulses)
    return RadarSystem(build_radar(sc.model_copy(update={"land": ()})), backend="numpy")


def test_unit_gain_echo_times_the_gains_is_the_echo():
    """Eq R1 is linear in sqrt(G_t G_r): the echo of scatterers with the scene's antennas
    equals their echo with isotropic unit-gain antennas of the same ports (eq U1) times
    beam_gains (eq U2, in float64), to rounding; incidence_directions are the radar
    equation's n_i (eq R3) and the facets below the floor get 0."""
    import dataclasses

    from seaecho.coverage import beam_gains, incidence_directions, unit_gain_antenna
    from seaecho.radar.system import RadarSystem

    radar = _radar()
    unit = RadarSystem(dataclasses.replace(
        radar.model, tx_antenna=unit_gain_antenna(radar.tx_antenna),
        rx_antenna=unit_gain_antenna(radar.rx_antenna)), backend="numpy")
    geo = radar.geometry(300)  # beam at bearing 43 deg
    rng = np.random.default_rng(1)
    r = rng.uniform(400.0, 2500.0, 64)
    az = np.radians(43.0) + rng.uniform(-0.1, 0.1, r.size)  # bearing, clockwise from N
    p = np.stack([r * np.sin(az), -2000.0 + r * np.cos(az), rng.normal(0, 1, r.size)], -1)
    v = rng.normal(0.0, 1.0, p.shape)
    s = rng.normal(size=(r.size, 2, 2)) + 1j * rng.normal(size=(r.size, 2, 2))
    full = radar.scatterer_echo(geo, p, v, s)
    one = unit.scatterer_echo(geo, p, v, s)
    n = incidence_directions(geo, p, v)
    np.testing.assert_allclose(n, full.n_i, rtol=0, atol=1e-15)
    w = beam_gains(radar, geo, n, 0.0, precision="double")
    np.testing.assert_allclose(w, np.sqrt(full.g_t * full.g_r), rtol=1e-12)
    np.testing.assert_allclose(one.amplitudes * w, full.amplitudes, rtol=1e-12)
    np.testing.assert_array_equal(one.tau, full.tau)
    floor = 1e-4  # -40 dB: the sidelobes' facets are cut
    cut = beam_gains(radar, geo, n, floor, precision="double")
    assert 0 < np.count_nonzero(cut) < r.size
    assert np.all((cut == 0) | (cut == w))


def test_sector_holds_every_facet_the_bound_keeps():
    """Eq U3: the azimuth slices of a tile's sorted facets hold every facet with
    |n . y| < u_max (and few others), across the -pi/pi cut too."""
    from seaecho.coverage import UnitEcho

    rng = np.random.default_rng(2)
    phi = rng.uniform(-np.pi, np.pi, 20000)
    el = rng.uniform(-0.1, 0.0, phi.size)
    n = np.stack([np.cos(el) * np.cos(phi), np.cos(el) * np.sin(phi), np.sin(el)], -1)
    u = UnitEcho.sorted(0, np.arange(phi.size, dtype=float), np.ones((1, phi.size)), n)
    for bearing in (0.3, np.pi / 2, 3.1):  # boresight azimuth; the width axis is across
        dep = np.radians(0.5)
        y = np.array([-np.sin(bearing), np.cos(bearing), 0.0])
        x = np.array([np.cos(bearing) * np.cos(dep), np.sin(bearing) * np.cos(dep),
                      -np.sin(dep)])
        y = np.cross(np.cross(x, y), x)  # kept orthogonal to the tilted boresight
        idx = u.sector(y, 0.05)
        want = np.flatnonzero(np.abs(u.direction @ y) < 0.05)
        assert set(want) <= set(idx)
        assert idx.size < 1.2 * want.size + 50
    # a rolled antenna (a ship's roll of 8 deg): the width axis leaves the horizontal,
    # y_z = sin 8 deg, and the facets' n_z widen the arcs by s |y_z| / (c rho_y) (eq U3's
    # elevation term; without it facets the bound keeps fall outside the arcs)
    el = rng.uniform(-0.3, 0.0, phi.size)
    n = np.stack([np.cos(el) * np.cos(phi), np.cos(el) * np.sin(phi), np.sin(el)], -1)
    u = UnitEcho.sorted(0, np.arange(phi.size, dtype=float), np.ones((1, phi.size)), n)
    roll = np.radians(8.0)
    for bearing in (0.3, 2.0):
        y = np.array([-np.sin(bearing) * np.cos(roll), np.cos(bearing) * np.cos(roll),
                      np.sin(roll)])
        idx = u.sector(y, 0.05)
        want = np.flatnonzero(np.abs(u.direction @ y) < 0.05)
        assert want.size > 100 and set(want) <= set(idx)


@pytest.mark.slow  # ~25 s: the tiles of one pulse, twice in each precision
@pytest.mark.parametrize("precision, tol", [("double", 1e-8), ("single", 1e-4)])
def test_cached_pulse_is_the_tile_pipeline(monkeypatch, precision, tol):
    """A held sea's pulse from the tiles' unit-gain echoes times its gains (eqs U1-U3)
    against the tile pipeline of every pulse (the evolving sea's path): in float64
    working precision they differ by the accumulation's NUFFT tolerance (1e-9 per
    channel; measured 3.4e-10 of the largest sample), in the default float32 by the
    rounding of the gains' direction cosines, taken in the radar's frame instead of each
    tile's (measured 8e-6; the gains themselves are float32 in either path). The next
    pulse of the block uses the held unit echoes."""
    import seaecho.scattering.facet as facet
    from seaecho.simulation import Simulation

    monkeypatch.setattr(facet, "PRECISION", precision)
    sc = _scene(sea_update_pulses=250)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref, cached = Simulation(sc), Simulation(sc)
        ref.coverage.cached = False
        for p in (5, 6):
            a, b = ref.coverage.raw(p), cached.coverage.raw(p)
            assert np.abs(b - a).max() <= tol * np.abs(a).max()
    assert cached.coverage.tiles_made == len(cached.coverage.selected(5))
    assert cached.coverage.facets_echoed > 1000


@pytest.mark.slow  # ~3 s: the coverage's models (a sea model per level)
def test_selected_tiles_are_those_of_the_bound_over_every_tile():
    """The tiles' azimuth prefilter (eq U3 with each box's azimuths and elevation bound)
    keeps every tile whose bound reaches the floor: the same tiles as eq C2 over all of
    them, through a revolution and at the back lobe's tiles near the radar."""
    from seaecho.build import build_simulation
    from seaecho.coverage import CoverageSea
    from seaecho.radar.system import RadarSystem

    sc = _scene(window=(300.0, 2500.0), size=128.0, nx=128, n_pulses=2500)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        models = build_simulation(sc.model_copy(update={"land": ()}))
    cov = CoverageSea(models, RadarSystem(models.radar), factory=None)
    for p in range(0, 2500, 97):
        want = np.flatnonzero(cov.gain_bounds(p) >= cov.floor)
        np.testing.assert_array_equal(cov.selected(p), want)
    assert len(cov._candidates(300)) < 0.2 * len(cov)


def test_static_occluder_hides_the_facets_behind_it_in_the_simulation_frame():
    """Eq T6: a tile's facets (tile frame) carried into the simulation frame (eq T5,
    q -> T (q - O) + P) and traced against a static occluder placed there: a facet is
    dropped exactly where its segment to the antenna crosses the box (the slab test,
    closed form), whatever the tile's rotation and offset."""
    from types import SimpleNamespace

    import trimesh

    from seaecho.coverage import CoverageSea
    from seaecho.geometry.patchwork import TileFrame
    from seaecho.tracing.scene import ObjectGeometry
    from seaecho.tracing.variant import set_variant

    a = np.radians(35.0)  # the tile turned 35 deg about z and tilted 2 deg about x
    rz = np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0, 0, 1]])
    b = np.radians(2.0)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, np.cos(b), -np.sin(b)], [0.0, np.sin(b), np.cos(b)]])
    frame = TileFrame(rz @ rx, np.array([1500.0, -800.0, -0.2]), np.array([40.0, 60.0, 0.0]))
    rng = np.random.default_rng(4)
    n_cells = 300
    c = np.column_stack([rng.uniform(0.0, 80.0, 2 * n_cells), rng.uniform(20.0, 100.0,
                                                                          2 * n_cells),
                         rng.uniform(-0.5, 0.5, 2 * n_cells)])  # tile frame [m]
    normal = np.tile([0.0, 0.0, 1.0], (c.shape[0], 1))
    tx_tile = np.array([40.0, -400.0, 30.0])  # the antenna, in the tile's frame [m]
    cw, tw = frame.to_world(c), frame.to_world(tx_tile)
    # a box in the simulation frame, across the segments of about half the facets
    mid = frame.to_world(np.array([40.0, 0.0, 0.0]))
    lo, hi = mid + np.array([-25.0, -25.0, -5.0]), mid + np.array([25.0, 25.0, 3.0])
    m = trimesh.creation.box(bounds=[lo, hi])
    box = ObjectGeometry("box", np.asarray(m.vertices, float), np.asarray(m.faces, np.uint32))
    d = tw - cw  # slab test of each segment cw + t d, 0 < t < 1, against [lo, hi]
    with np.errstate(divide="ignore"):
        t1, t2 = (lo - cw) / d, (hi - cw) / d
    t_in = np.minimum(t1, t2).max(axis=1)
    t_out = np.maximum(t1, t2).min(axis=1)
    expected = (t_in < t_out) & (t_out > 0.0) & (t_in < 1.0)
    margin = np.minimum(np.abs(t_out - t_in), np.abs(t_in)) * np.linalg.norm(d, axis=1)
    clear = margin > 0.05  # segments not grazing an edge (float32 rounding) [m]
    assert 0.2 < expected.mean() < 0.8
    cs = object.__new__(CoverageSea)
    level = SimpleNamespace(spacing=(1.0, 1.0))
    cs.patchwork = SimpleNamespace(frame=lambda i: frame, level=[0], levels=[level],
                                   cell_owned=lambda i: np.ones(n_cells, dtype=bool))
    cs._beyond, cs._static, cs._occluders = [False], (box,), None
    cs.floor, cs.radar = 0.0, None  # not read without the beam (beam=False)
    sim = SimpleNamespace(engine=SimpleNamespace(
        geometry=lambda state: (c, None, normal, None),
        tracer=SimpleNamespace(variant=set_variant(None))))
    ant = SimpleNamespace(position=tx_tile)
    w = cs._weight(0, beam=False)(sim, None, SimpleNamespace(tx=ant, rx=ant))
    np.testing.assert_array_equal(w[clear] == 0.0, expected[clear])
