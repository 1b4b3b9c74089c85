"""FacetEngine (modes, refresh interval), [[objects]] loading, hull mesh, XML scenes.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import types
from pathlib import Path

import numpy as np
import pytest

from seaecho.config import SceneError, parse_scene
from seaecho.tracing.engine import FacetEngine, reference_time
from seaecho.tracing.scene import load_object, rotation_matrix

REPO = Path(__file__).resolve().parents[2]
HULL = REPO / "scenes" / "meshes" / "motor_boat_10m.ply"
N = 48
X = (np.arange(N) - N / 2) * 1.0


class MovingSinusoidSea:
    """A sea of plain arrays: z = A sin(k (x - c t)), counting its evaluations."""

    def __init__(self, a=0.8, k=0.3, c=2.0):
        self.a, self.k, self.c = a, k, c
        self.x = self.y = X
        self.calls = []

    def state(self, t):
        self.calls.append(t)
        xx, _ = np.meshgrid(self.x, self.y)
        ph = self.k * (xx - self.c * t)
        vel = np.zeros(xx.shape + (3,))
        vel[..., 2] = -self.a * self.k * self.c * np.cos(ph)
        return types.SimpleNamespace(
            t=t, x=self.x, y=self.y, elevation=self.a * np.sin(ph),
            slope_x=self.a * self.k * np.cos(ph), slope_y=np.zeros_like(xx), velocity=vel)


TX = np.array([-400.0, 10.0, 25.0])


def test_reference_time():
    assert reference_time(0.37, 0.0) == 0.37
    assert reference_time(0.37, 0.1) == pytest.approx(0.3)
    assert reference_time(3 * 0.1, 0.1) == pytest.approx(0.3)  # rounding absorbed
    assert reference_time(0.0999999, 0.1) == 0.0


def test_raytraced_engine_matches_tracer_and_sees_shadowing():
    from seaecho.tracing.tracer import FacetTracer

    sea = MovingSinusoidSea()
    eng = FacetEngine(sea.state, lambda t: TX, mode="raytraced")
    f = eng.facets(0.5)
    assert f.mode == "raytraced" and f.time_s == 0.5 and f.visibility_time_s == 0.5
    assert 0.05 < 1 - f.lit.mean() < 0.9  # steep waves at 3.6 deg grazing: shadows
    # the engine is the tracer on the provider's surface at t and the platform at t
    st = MovingSinusoidSea().state(0.5)
    ref = FacetTracer(st.x, st.y, st.elevation).facets(st.elevation, st.velocity, TX, t=0.5)
    np.testing.assert_array_equal(f.lit, ref.lit)
    np.testing.assert_array_equal(f.visibility, ref.visibility)
    np.testing.assert_allclose(f.r_tx, ref.r_tx, rtol=1e-12)
    # An independent method: the heights depend on x only, so between nodes the mesh is
    # the linear interpolation of the node heights along x, and a straight segment to TX
    # passes below it somewhere iff it does at a node: a facet is lit when it faces TX
    # and its segment to TX is above every node it crosses within the tile. Every facet
    # must agree.
    c = f.centroid
    d = TX[None, :] - c
    s = (st.x[None, :] - c[:, :1]) / d[:, :1]  # segment parameter at each node's x
    y = c[:, 1:2] + s * d[:, 1:2]
    crossed = (s > 1e-9) & (s <= 1.0) & (y >= st.y[0]) & (y <= st.y[-1])
    below = st.elevation[0][None, :] > c[:, 2:3] + s * d[:, 2:3] + 1e-6
    facing = np.einsum("ij,ij->i", f.normal, d) > 0
    np.testing.assert_array_equal(f.lit > 0, facing & ~np.any(crossed & below, axis=1))
    # velocity: the mean of the vertices' dz/dt
    assert np.abs(f.velocity[:, 2]).max() > 0
    fa = FacetEngine(sea.state, lambda t: TX, mode="analytic", shadowing="none").facets(0.5)
    np.testing.assert_allclose(fa.r_tx, f.r_tx)
    assert fa.lit.mean() > f.lit.mean()  # facing only: no shadows


def test_refresh_interval_reuses_occlusion_deterministically():
    sea = MovingSinusoidSea()
    eng = FacetEngine(sea.state, lambda t: TX, mode="raytraced", refresh_interval_s=1.0)
    f1 = eng.facets(1.25)
    assert f1.visibility_time_s == 1.0
    f2 = eng.facets(1.75)  # same reference time: occlusion reused, geometry of t = 1.75
    assert f2.visibility_time_s == 1.0
    assert not np.allclose(f1.centroid[:, 2], f2.centroid[:, 2])
    # a fresh engine asked for t = 1.75 first gives the same facets (order-independent)
    fresh = FacetEngine(MovingSinusoidSea().state, lambda t: TX, mode="raytraced",
                        refresh_interval_s=1.0).facets(1.75)
    np.testing.assert_array_equal(fresh.lit, f2.lit)
    # at the reference time itself the result is the plain ray-traced one
    exact = FacetEngine(MovingSinusoidSea().state, lambda t: TX, mode="raytraced").facets(1.0)
    np.testing.assert_array_equal(eng.facets(1.0).lit, exact.lit)


def test_rotation_matrix_matches_sionna_convention():
    r = rotation_matrix(np.pi / 2, 0.0, 0.0)  # yaw: x -> y
    np.testing.assert_allclose(r @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    r = rotation_matrix(0.3, -0.2, 0.7)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-14)
    assert np.linalg.det(r) == pytest.approx(1.0)


def test_hull_mesh_has_the_paper_boat_dimensions():
    """Paper section V-A: length 10 m, beam 4 m, draft 1.5 m."""
    import trimesh

    from seaecho.geometry.hull import motor_boat_hull

    m = trimesh.load(HULL, force="mesh")
    lo, hi = m.bounds
    assert hi[0] - lo[0] == pytest.approx(10.0)
    assert hi[1] - lo[1] == pytest.approx(4.0)
    assert lo[2] == pytest.approx(-1.5)
    for body in m.split(only_watertight=False):
        assert body.is_watertight and body.is_winding_consistent and body.volume > 0
    v, f = motor_boat_hull()  # the bundled file is this function's output
    np.testing.assert_allclose(np.sort(v, axis=0), np.sort(np.asarray(m.vertices), axis=0),
                               atol=1e-6)


def _scene(**extra):
    data = {"sea": {"wind_speed_m_s": 6.0, "size_x_m": 64.0, "nx": 64},
            "ship": {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 10.0,
                     "heading_deg": 35.0, "position_m": [3.0, -2.0]}}
    data.update(extra)
    return parse_scene(data)


def test_follow_ship_object_is_placed_on_the_track():
    scene = _scene(objects=[{"name": "boat", "file": str(HULL), "follow_ship": True}])
    (g,) = load_object(scene.objects[0], ship=scene.ship)
    h = np.deg2rad(35.0)
    v = 10.0 * 1852 / 3600
    np.testing.assert_allclose(g.velocity, [v * np.cos(h), v * np.sin(h), 0.0])
    w0, w2 = g.world_vertices(0.0), g.world_vertices(2.0)
    np.testing.assert_allclose(w2 - w0, np.broadcast_to(2.0 * g.velocity, w0.shape))
    # bow (+x in the file) points along the heading
    bow = w0[g.vertices[:, 0] == g.vertices[:, 0].max()].mean(axis=0)
    np.testing.assert_allclose(np.arctan2(bow[1] + 2.0, bow[0] - 3.0), h, atol=1e-6)
    assert g.itu_type == "metal" and g.moving


def test_objects_config_errors_are_readable():
    with pytest.raises(SceneError, match="extensions"):
        _scene(objects=[{"name": "b", "file": "boat.dae"}])
    with pytest.raises(SceneError, match="not both"):
        _scene(objects=[{"name": "b", "file": "b.ply", "material": "metal",
                         "relative_permittivity": 3.0}])
    with pytest.raises(SceneError, match=r"\[tracing\]\.mode"):
        _scene(tracing={"mode": "magic"})
    with pytest.raises(SceneError, match=r"orientation_deg\[0\] = 400"):
        _scene(objects=[{"name": "b", "file": "b.ply", "orientation_deg": [400, 0, 0]}])
    with pytest.raises(SceneError, match="refresh_interval_s"):
        _scene(tracing={"refresh_interval_s": -1.0})
    scene = _scene(tracing={"mode": "analytic", "shadowing": "none"})
    assert scene.tracing.mode == "analytic" and scene.objects == ()


def test_missing_object_file_is_a_value_error(tmp_path):
    scene = _scene(objects=[{"name": "b", "file": "nothere.ply"}])
    with pytest.raises(ValueError, match="not found"):
        load_object(scene.objects[0], base_dir=str(tmp_path))


XML = """<scene version="2.1.0">
  <bsdf type="itu-radio-material" id="mat-concrete">
    <string name="type" value="concrete"/>
    <float name="thickness" value="0.2"/>
  </bsdf>
  <shape type="ply" id="wall">
    <string name="filename" value="wall.ply"/>
    <ref id="mat-concrete" name="bsdf"/>
  </shape>
</scene>
"""


def test_xml_object_occludes_the_sea(tmp_path):
    """A breakwater (a box) given as a Sionna XML scene casts a shadow on a flat sea."""
    import trimesh

    from seaecho.tracing.tracer import FacetTracer

    trimesh.creation.box(bounds=[[-3, -10, -1], [3, 10, 3]]).export(tmp_path / "wall.ply")
    (tmp_path / "breakwater.xml").write_text(XML)
    scene = _scene(objects=[{"name": "breakwater", "file": "breakwater.xml",
                             "position_m": [5.0, 0.0, 0.0]}])
    geoms = load_object(scene.objects[0], base_dir=str(tmp_path))
    assert len(geoms) == 1 and geoms[0].itu_type is None
    assert geoms[0].relative_permittivity == pytest.approx(5.24)  # ITU concrete eps'
    tr = FacetTracer(X, X, objects=geoms)
    f = tr.facets(np.zeros((N, N)), None, np.array([-200.0, 0.0, 20.0]))
    c = f.centroid
    behind = (c[:, 0] > 9.0) & (c[:, 0] < 20.0) & (np.abs(c[:, 1]) < 8.0)
    before = (c[:, 0] < 0.0) & (np.abs(c[:, 1]) < 8.0)
    assert f.lit[behind].max() == 0.0 and f.lit[before].min() == 1.0


def test_variant_is_explicit_and_cuda_needs_a_gpu():
    from seaecho.tracing.variant import DEFAULT_VARIANT, cuda_available, set_variant

    assert set_variant(None) == DEFAULT_VARIANT == "llvm_ad_mono_polarized"
    with pytest.raises(ValueError, match="allowed"):
        set_variant("scalar_rgb")
    if not cuda_available():
        with pytest.raises(ValueError, match="no CUDA GPU"):
            set_variant("cuda_ad_mono_polarized")



def test_subfacet_shadowing_from_scene_lowers_visibility():
    from seaecho.build import build_engine, build_sea, build_sea_model

    scene = _scene(tracing={"mode": "analytic", "subfacet_shadowing": True})
    tx = np.array([-600.0, 0.0, 30.0])
    sea = build_sea(scene)
    on = build_engine(scene, sea.state, frequency=10e9, tx_position=tx)
    off = build_engine(_scene(tracing={"mode": "analytic"}), sea.state, frequency=10e9,
                       tx_position=tx)
    # the engine's sub-facet slopes are the sea model's (the tilting band up to k/3)
    assert on.subfacet == build_sea_model(scene, 10e9).subfacet and off.subfacet is None
    f_on, f_off = on.facets(0.0), off.facets(0.0)
    s = f_on.extra["subfacet_shadowing"]
    assert np.all((s >= 0) & (s <= 1)) and s.mean() < 1
    np.testing.assert_allclose(f_on.visibility, f_off.visibility * s)
    np.testing.assert_array_equal(f_on.lit, f_off.lit)


def test_engine_of_a_scene_without_radar_needs_a_frequency():
    from seaecho.build import build_engine, build_sea

    scene = _scene(tracing={"mode": "analytic"})
    with pytest.raises(ValueError, match=r"no \[radar\].*frequency"):
        build_engine(scene, build_sea(scene).state, tx_position=[-600.0, 0.0, 30.0])


def test_held_surface_does_not_rebuild_the_bvh():
    from seaecho.tracing.tracer import FacetTracer

    z = MovingSinusoidSea().state(0.0).elevation
    tr = FacetTracer(X, X, z)
    assert tr.set_surface(z.copy()) is False  # same heights: no rebuild
    assert tr.set_surface(1.5 * z) is True
    # the BVH follows: same visibility as a tracer built on the new surface
    f = tr.facets(1.5 * z, None, TX)
    np.testing.assert_array_equal(f.lit, FacetTracer(X, X, 1.5 * z).facets(None, None, TX).lit)
    assert not np.array_equal(f.lit, tr.facets(z, None, TX).lit)
