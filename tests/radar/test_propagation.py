"""The two-ray propagation factor of the sea (``seaecho.radar.propagation``).

Closed forms and limits: the flat-Earth two-ray factor of a perfect reflector
F = 2 |sin(2 pi h1 h2 / (lambda R))| with its nulls and lobe peaks (Skolnik 2001,
section 8.2; Blake 1986, eq 6.11), the interference region F^4 ~ (4 pi h1 h2 / (lambda
R))^4 where the echo falls as R^-8 (Blake 1986, section 6.4), the limits F -> 1 + Gamma
and F -> 1, the specular point against the law of reflection on the sphere, Kerr's
divergence factor against a ray tube traced over the sphere (Kerr 1951, section 2.5;
Blake 1986, chapter 6), the pseudo-Brewster minimum of |Gamma_v| of sea water.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.geometry.earth import effective_radius, horizon_range
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.radar.propagation import (
    TwoRay,
    divergence_factor,
    reflection_point,
    two_ray_factor,
    two_ray_geometry,
)
from seaecho.radar.system import RadarSystem

R43 = effective_radius(4.0 / 3.0)
LAM = C0 / 9.41e9
EPS = complex(sea_water_permittivity(9.41e9, 20.0, 35.0))


def test_flat_perfect_reflector_is_skolnik_two_ray():
    # Skolnik (2001) section 8.2: Gamma = -1, flat Earth: |F| = 2 |sin(2 pi h1 h2 / (l R))|
    h1, d = 30.0, 5000.0
    h2 = np.linspace(0.0, 3.0, 301)
    psi, delta, div = two_ray_geometry(h1, h2, d)
    f = np.abs(two_ray_factor(delta, div, -1.0, LAM))
    assert np.all(div == 1.0)
    np.testing.assert_allclose(f, 2 * np.abs(np.sin(2 * np.pi * h1 * h2 / (LAM * d))),
                               atol=2e-3)
    # first null above the sea at h2 = lambda d / (2 h1), first lobe peak at half of it
    null, peak = LAM * d / (2 * h1), LAM * d / (4 * h1)
    _, dn, _ = two_ray_geometry(h1, null, d)
    _, dp, _ = two_ray_geometry(h1, peak, d)
    assert abs(two_ray_factor(dn, 1.0, -1.0, LAM)) < 1e-3
    assert abs(two_ray_factor(dp, 1.0, -1.0, LAM)) == pytest.approx(2.0, abs=1e-5)
    np.testing.assert_allclose(psi[1:], np.arctan((h1 + h2[1:]) / d), rtol=1e-12)


def test_limits_one_plus_gamma_and_one():
    two = TwoRay(LAM, EPS, sigma_h=0.0)
    # a point on the sea: both waves in phase (delta = 0): F = 1 + Gamma(psi)
    from seaecho.scattering.fresnel import fresnel_coefficients

    fh, fv = two.factors([0.0, 0.0, 20.0], [[3000.0, 0.0, 0.0]])
    rh, rv = fresnel_coefficients(np.sin(np.arctan(20.0 / 3000.0)), EPS)
    assert fh[0] == pytest.approx(1 + rh, abs=1e-12)
    assert fv[0] == pytest.approx(1 + rv, abs=1e-12)
    assert abs(fh[0]) < 0.01  # Gamma_h -> -1 at grazing: the sea's own level is dark
    # a very rough sea reflects nothing coherently: F -> 1
    rough = TwoRay(LAM, EPS, sigma_h=20.0)
    fh, fv = rough.factors([0.0, 0.0, 20.0], [[3000.0, 0.0, 5.0]])
    assert abs(fh[0] - 1) < 0.05 and abs(fv[0] - 1) < 0.05


def test_specular_point_obeys_the_law_of_reflection_on_the_sphere():
    # eq P2 (Kerr 1951, section 2.4): the two legs meet the sphere at equal grazing
    h1, h2 = np.array([30.0, 30.0, 5.0, 60.0]), np.array([10.0, 2.0, 5.0, 0.5])
    d = np.array([8e3, 15e3, 6e3, 25e3])
    d1 = reflection_point(h1, h2, d, R43)
    for a, b, dd, s in zip(h1, h2, d, d1, strict=True):
        def elev(h, s_):
            g = s_ / R43
            x = (R43 + h) * np.sin(g)
            y = h * np.cos(g) - 2 * R43 * np.sin(g / 2) ** 2
            return np.arctan2(y, x)
        assert elev(a, s) == pytest.approx(elev(b, dd - s), rel=2e-3)
    # flat-Earth limit: d1 = d h1 / (h1 + h2)
    np.testing.assert_allclose(reflection_point(h1, h2, d), d * h1 / (h1 + h2))
    np.testing.assert_allclose(reflection_point(h1, h2, d, 1e13), d * h1 / (h1 + h2),
                               rtol=1e-5)


def _ray_tube_divergence(h1, h2, d, radius):
    """D from the reflected ray tube traced over a circle (vertical plane): the tube's
    width over the width L d theta of rays from the image of a flat mirror."""
    p1 = np.array([0.0, radius + h1])
    beta = d / radius
    radial = np.array([np.sin(beta), np.cos(beta)])

    def trace(theta):
        u = np.array([np.cos(theta), -np.sin(theta)])
        b = p1 @ u
        t1 = -b - np.sqrt(b * b - (p1 @ p1 - radius**2))
        s = p1 + t1 * u
        n = s / radius
        w = u - 2 * (u @ n) * n
        # reflected ray meets the radial line through the observation point
        m = np.array([[w[0], -radial[0]], [w[1], -radial[1]]])
        t2, rr = np.linalg.solve(m, -s)
        return rr - radius, t1 + t2, w, s

    horizon = np.arccos(radius / (radius + h1))  # rays below it meet the sphere
    theta = brentq(lambda t: trace(t)[0] - h2, horizon + 1e-12, 0.5, xtol=1e-15)
    dt = 1e-7
    dh = (trace(theta + dt)[0] - trace(theta - dt)[0]) / (2 * dt)
    _, length, w, s = trace(theta)
    width = abs(dh * (radial[0] * w[1] - radial[1] * w[0]))
    grazing = np.arcsin(w @ (s / radius))  # the reflected ray leaves at psi
    return np.sqrt(length / width), radius * np.arctan2(s[0], s[1]), abs(grazing)


@pytest.mark.parametrize(("h1", "h2", "d"), [(30.0, 10.0, 10e3), (30.0, 10.0, 20e3),
                                             (30.0, 10.0, 30e3), (25.0, 2.0, 15e3)])
def test_divergence_factor_against_a_traced_ray_tube(h1, h2, d):
    # Kerr (1951) eq 2.5(9) against the ray tube over the sphere
    d_tube, d1, psi = _ray_tube_divergence(h1, h2, d, R43)
    # (measured: D agrees to 1e-5, e.g. 0.7559 at 20 km and 0.4313 at 30 km)
    assert d1 == pytest.approx(float(reflection_point(h1, h2, d, R43)), rel=1e-5)
    psi_m, _, div = two_ray_geometry(h1, h2, d, R43)
    assert float(psi_m) == pytest.approx(psi, rel=1e-3)
    assert float(div) == pytest.approx(d_tube, rel=1e-3)
    assert float(divergence_factor(d1, d - d1, psi, R43)) == pytest.approx(d_tube, rel=1e-3)
    assert float(divergence_factor(d1, d - d1, psi, np.inf)) == 1.0


def test_at_the_horizon_the_reflected_wave_vanishes():
    # the divergence factor -> 0 at tangency (eq P3 at psi -> 0): F -> 1 near the
    # horizon, where the flat Earth would give the null 1 + Gamma ~ 0
    h1, h2 = 30.0, 10.0
    d = 0.995 * float(horizon_range(h1, h2, R43))
    sphere = TwoRay(LAM, EPS, 0.0, radius=R43)
    tangent = sphere.radius  # the point at ground distance d along +x, height h2
    g = d / tangent
    p = [(tangent + h2) * np.sin(g), 0.0, h2 * np.cos(g) - 2 * tangent * np.sin(g / 2) ** 2]
    fh, _ = sphere.factors([0.0, 0.0, h1], [p])
    _, _, div = two_ray_geometry(h1, h2, d, R43)
    assert float(div) < 0.1
    assert abs(fh[0]) == pytest.approx(1.0, abs=0.1)


def test_pseudo_brewster_minimum_of_sea_water():
    # |Gamma_v| of sea water has its minimum near psi_B = arctan(1 / sqrt|eps|) (Blake
    # 1986, fig 6.3: about 5-8 deg at X band); Gamma_h stays close to -1. Points on the
    # sea (h2 = 0, delta = 0): F - 1 = Gamma(psi)
    two = TwoRay(LAM, EPS, 0.0)
    psi = np.radians(np.linspace(0.5, 30.0, 600))
    x = 100.0 / np.tan(psi)
    fh, fv = two.factors([0.0, 0.0, 100.0], np.stack([x, 0 * x, 0 * x], -1))
    gam_h, gam_v = np.abs(fh - 1.0), np.abs(fv - 1.0)
    brewster = np.degrees(np.arctan(1 / np.sqrt(abs(EPS))))
    assert 4.0 < brewster < 9.0
    assert np.degrees(psi[np.argmin(gam_v)]) == pytest.approx(brewster, rel=0.05)  # 6.90
    assert gam_v.min() < 0.5 and gam_h.min() > 0.75
    assert gam_h[0] == pytest.approx(1.0, abs=0.02) and gam_v[0] > 0.8


def _target_scene(ranges_m, h1, h2, multipath="two-ray", channels=("HH", "VV"),
                  shadowing=False):
    return {
        "sea": {"wind_speed_m_s": 3.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 1, "sea_clutter": False,
                  "transmit_power_w": 25e3, "channels": list(channels),
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, 0.0, h1), "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "propagation": {"multipath": multipath, "multipath_shadowing": shadowing},
        "targets": [{"name": f"t{i}", "position_m": (r, 0.0, h2), "rcs_m2": 1.0}
                    for i, r in enumerate(ranges_m)]}


def test_point_target_lobing_and_r8_regime():
    # Blake (1986) section 6.4: P / P_free = |F|^4 with lobes up to 16 (12 dB) and, past
    # the last lobe (R > 4 h1 h2 / lambda), |F|^4 ~ (4 pi h1 h2 / (lambda R))^4: R^-8
    h1, h2 = 10.0, 1.0
    r = np.geomspace(200.0, 20e3, 120)
    echoes = []
    for mp in ("two-ray", "none"):
        radar = RadarSystem(build_radar(parse_scene(_target_scene(r, h1, h2, mp))),
                            backend="numpy")
        echoes.append(radar.target_echo(radar.geometry(0)))
    ratio = np.abs(echoes[0].amplitudes) ** 2 / np.abs(echoes[1].amplitudes) ** 2
    assert ratio.shape == (2, r.size)
    assert 12.0 < ratio[0].max() <= 16.0  # the lobes, up to 16 x free space
    assert ratio[0][r < 2000].min() < 1e-2  # and the nulls between them
    far = r > 8e3  # x = 4 pi h1 h2 / (lambda R) < 0.5: within 5 % of the asymptote
    rr = np.hypot(r, h2 - h1)
    np.testing.assert_allclose(ratio[0][far], (4 * np.pi * h1 * h2 / (LAM * rr[far])) ** 4,
                               rtol=0.1)
    slope = np.polyfit(np.log(r[far]), np.log(ratio[0][far] / rr[far] ** 4), 1)[0]
    assert slope == pytest.approx(-8.0, abs=0.15)
    # the monostatic echo is |F|^4 of the geometry: HH with F_h, VV with F_v
    two = build_radar(parse_scene(_target_scene(r, h1, h2))).multipath
    fh, fv = two.factors([0.0, 0.0, h1], np.stack([r, 0 * r, 0 * r + h2], -1))
    np.testing.assert_allclose(ratio[0], np.abs(fh) ** 4, rtol=1e-9)
    np.testing.assert_allclose(ratio[1], np.abs(fv) ** 4, rtol=1e-9)


def test_bistatic_legs_and_cross_polar_channels():
    two = TwoRay(LAM, EPS, 0.1, radius=R43)
    p = np.array([[2000.0, 500.0, 3.0], [4000.0, -300.0, 8.0]])
    tx, rx = np.array([0.0, 0.0, 20.0]), np.array([100.0, 900.0, 40.0])
    s = np.array([[[1.0, 0.2j], [0.3, -0.5]]] * 2)
    out = two.apply(s, p, tx, rx, monostatic=False)
    ft, fr = two.factors(tx, p), two.factors(rx, p)
    for q in range(2):
        for m in range(2):
            np.testing.assert_allclose(out[:, m, q], fr[m] * s[:, m, q] * ft[q])


def test_default_none_is_todays_path():
    # no [propagation] multipath, or "none": no factor, the same bytes (the run's bytes:
    # tests/radar/test_earth_radar.py::test_flat_earth_and_fixed_antenna_are_todays_path)
    base = _target_scene([1500.0, 3000.0], 20.0, 5.0, multipath="none")
    base.pop("propagation")
    explicit = _target_scene([1500.0, 3000.0], 20.0, 5.0, multipath="none")
    echoes = []
    for scene in (base, explicit):
        model = build_radar(parse_scene(scene))
        assert model.multipath is None
        radar = RadarSystem(model, backend="numpy")
        echoes.append(radar.target_echo(radar.geometry(0)).amplitudes.tobytes())
    assert echoes[0] == echoes[1]


def test_hulls_ask_for_no_factor():
    # scatterer_echo applies the factor only when asked (targets, sea facets), never to
    # the hulls' ray-traced echo, which carries the sea's reflections itself
    radar = RadarSystem(build_radar(parse_scene(_target_scene([3000.0], 20.0, 5.0))),
                        backend="numpy")
    geo = radar.geometry(0)
    p, v = np.array([[3000.0, 0.0, 5.0]]), np.zeros((1, 3))
    s = np.eye(2, dtype=complex)[None]
    plain = radar.scatterer_echo(geo, p, v, s)
    with_f = radar.scatterer_echo(geo, p, v, s, multipath=True)
    assert not np.allclose(plain.amplitudes, with_f.amplitudes)
    free = RadarSystem(build_radar(parse_scene(_target_scene([3000.0], 20.0, 5.0, "none"))),
                       backend="numpy")
    np.testing.assert_array_equal(free.scatterer_echo(free.geometry(0), p, v, s,
                                                      multipath=True).amplitudes,
                                  plain.amplitudes)


@pytest.mark.slow  # about 5 s (two sea-tile simulations)
@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_sea_facets_carry_the_factor_of_their_own_height():
    # the sea's reference path: facet k's HH amplitude is multiplied by F_h(z_k)^2
    # (monostatic), the factor of the facet's own phase centre (eq P1)
    from seaecho.simulation import Simulation

    def sim(multipath):
        scene = _target_scene([], 25.0, 0.0, multipath, channels=("HH", "VV"))
        scene["radar"]["sea_clutter"] = True
        scene["transmitter"]["position_m"] = (0.0, -1500.0, 25.0)
        scene["sea"] = {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64}
        return Simulation(parse_scene(scene))

    with_f, free = sim("two-ray"), sim("none")
    a, b = (s.sea_echo(0, sigma=True) for s in (with_f, free))
    vis = a.facets.visibility > 0
    p = with_f.phase_centres(0, with_f.surface_state(0))[vis]
    fh, fv = with_f.radar.model.multipath.factors(with_f.radar.geometry(0).tx.position, p)
    assert np.ptp(p[:, 2]) > 0.2 and np.ptp(np.abs(fh)) > 0.1  # heights matter
    np.testing.assert_allclose(a.echo.amplitudes[0], b.echo.amplitudes[0] * fh**2,
                               rtol=1e-5, atol=1e-6 * np.abs(b.echo.amplitudes[0]).max())
    np.testing.assert_allclose(a.echo.amplitudes[1], b.echo.amplitudes[1] * fv**2,
                               rtol=1e-5, atol=1e-6 * np.abs(b.echo.amplitudes[1]).max())


def test_spherical_earth_target_and_bad_value():
    # on the 4/3 Earth the model's factor has radius k a, and a target's echo carries it
    scene = _target_scene([6000.0, 12000.0], 25.0, 3.0)
    scene["propagation"]["earth"] = "spherical"
    model = build_radar(parse_scene(scene))
    assert model.multipath.radius == pytest.approx(R43)
    radar = RadarSystem(model, backend="numpy")
    free = dict(scene, propagation={"earth": "spherical", "multipath": "none"})
    radar0 = RadarSystem(build_radar(parse_scene(free)), backend="numpy")
    a, b = (r.target_echo(r.geometry(0)) for r in (radar, radar0))
    p, _ = radar.target_positions(0.0)
    fh, fv = model.multipath.factors(radar.geometry(0).tx.position, p)
    np.testing.assert_allclose(np.abs(a.amplitudes[0] / b.amplitudes[0]) ** 2,
                               np.abs(fh) ** 4, rtol=1e-9)
    _, _, div = two_ray_geometry(25.0, 3.0, np.array([6000.0, 12000.0]), R43)
    assert np.all(div < 1.0) and div[1] < div[0]  # the sphere's divergence acts
    from seaecho.config import SceneError

    bad = _target_scene([6000.0], 25.0, 3.0, multipath="three-ray")
    with pytest.raises(SceneError, match="multipath"):
        parse_scene(bad)
