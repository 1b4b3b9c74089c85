"""Sea multipath of a hull echo: image method, Fresnel and rough-sea factors.

References: Blake, L. V. (1986), *Radar Range-Performance Analysis*, Artech House, ch. 6
(pattern-propagation factor F = |1 + rho Gamma exp(-jk Delta)| over a flat sea, power
F^4 for a monostatic point target); Ament (1953) and Miller, Brown and Vegh (1984)
(specular reduction factors); Abramowitz and Stegun (1964), eq 9.7.1 (I0(x) e^-x ->
1 / sqrt(2 pi x)).
"""

from __future__ import annotations

import numpy as np
import pytest
from ship_helpers import F, K, db

from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.scattering.fresnel import fresnel_coefficients
from seaecho.targets import canonical
from seaecho.targets.centres import PATH_NAMES
from seaecho.targets.multipath import mirror, plane_crossing, sea_reflection, specular_reduction
from seaecho.tracing.sbr import SBROptions, SeaPlane, TraceMesh, trace_signature

EPS_SEA = complex(sea_water_permittivity(F, 20.0, 35.0))


def test_specular_reduction_limits():
    # Ament: exp(-2 g^2) with g = k sigma sin psi; small g: 1 - 2 g^2. Miller-Brown-Vegh:
    # exp(-2 g^2) I0(2 g^2), equal to Ament to O(g^4) and -> 1 / (2 g sqrt(pi)) for large
    # g (A&S 9.7.1); both 1 at grazing incidence and for a smooth sea.
    k, sigma = 2 * np.pi / 0.03, 0.1
    psi = np.arcsin(0.01 / (k * sigma))  # g = 0.01
    ament = specular_reduction(psi, sigma, k, "ament")
    assert ament == pytest.approx(1 - 2e-4, rel=1e-7)
    assert specular_reduction(psi, sigma, k) == pytest.approx(ament, rel=2e-8)
    psi = np.arcsin(10.0 / (k * sigma))  # g = 10
    assert specular_reduction(psi, sigma, k) == pytest.approx(1 / (20 * np.sqrt(np.pi)),
                                                              rel=0.01)
    assert specular_reduction(psi, sigma, k, "ament") < 1e-80
    assert specular_reduction(0.0, sigma, k) == 1.0
    assert specular_reduction(0.3, 0.0, k) == 1.0
    assert specular_reduction(0.3, sigma, k, "none") == 1.0
    with pytest.raises(ValueError, match="model"):
        specular_reduction(0.3, sigma, k, "kirchhoff")
    with pytest.raises(ValueError, match="sigma_h"):
        specular_reduction(0.3, -1.0, k)


def test_image_geometry():
    p = np.array([[1.0, 2.0, 3.0]])
    assert mirror(p, 0.5)[0].tolist() == [1.0, 2.0, -2.0]
    x, t = plane_crossing(p, np.array([[0.0, 0.6, -0.8]]), 0.0)
    assert x[0] == pytest.approx([1.0, 4.25, 0.0]) and t[0] == pytest.approx(3.75)
    gh, gv = sea_reflection(np.deg2rad(2.0), EPS_SEA, 0.0, K)
    rh, rv = fresnel_coefficients(np.sin(np.deg2rad(2.0)), EPS_SEA)
    assert gh == pytest.approx(rh) and gv == pytest.approx(rv)


def _sphere_at(h, tx, sea, cell=0.1):
    # 5120 facets of ~16 mm: sagitta 0.13 mm << lambda / 8
    v, f = canonical.sphere(0.25, 4)
    return trace_signature(TraceMesh.single(v + [0, 0, h], f), tx, tx, F,
                           options=SBROptions(rays_per_wavelength=3, cell=cell), sea=sea,
                           reference=[0, 0, h])


def _four_path(h, tx, gamma_fn):
    """Blake's four-path factor of a monostatic point target at (0, 0, h): the direct
    amplitude times (1 + (r_d / r_i) Gamma e^{-jk Delta})^2 (flat sea, divergence 1)."""
    p = np.array([0.0, 0.0, h])
    r_d = np.linalg.norm(p - tx)
    r_i = np.linalg.norm(p - mirror(tx))
    psi = np.arcsin((tx[2] + h) / r_i)
    g = gamma_fn(psi)
    return [(1 + (r_d / r_i) * gi * np.exp(-1j * K * (r_i - r_d))) ** 2 for gi in g]


@pytest.mark.parametrize("h", [0.5, 0.75, 1.25, 2.0])
def test_sphere_over_flat_sea_is_four_path_interference(h):
    # A sphere (a point-like target: same echo for the four paths at small bistatic
    # angles) at height h over a smooth sea, radar 1 km away at 10 m: the RCS with
    # multipath over the free-space RCS is the power factor |F|^4 of Blake (1986), per
    # channel with the Fresnel coefficient of sea water at the specular grazing angle
    # (about 0.6 deg; lobes 1.5 m apart in h). Within 0.2 dB where F^4 is no more than
    # 10 dB below its peak of 12 dB (deep nulls depend on the last 1 % of the sums).
    tx = np.array([-1000.0, 0.0, 10.0])
    sea = SeaPlane(eps_r=EPS_SEA, sigma_h=0.0)
    with_sea = _sphere_at(h, tx, sea)
    free = _sphere_at(h, tx, None)
    factor = _four_path(h, tx, lambda psi: fresnel_coefficients(np.sin(psi), EPS_SEA))
    for ch, f4 in ((0, factor[0]), (3, factor[1])):
        expected = abs(f4) ** 2
        got = with_sea.rcs[ch] / free.rcs[ch]
        if db(expected) > 2.0:
            assert db(got / expected) == pytest.approx(0.0, abs=0.2)
        else:
            assert db(got) < 2.0
    # each sea leg scales the direct path by |Gamma_h| (HH): sea-hull and hull-sea by
    # |Gamma|, sea-hull-sea by |Gamma|^2 (3 %; the bistatic echo of the sphere differs
    # slightly from its monostatic one)
    psi = np.arcsin((tx[2] + h) / np.linalg.norm([1000.0, 0.0, tx[2] + h]))
    g = abs(fresnel_coefficients(np.sin(psi), EPS_SEA)[0])
    amp = np.abs(with_sea.totals.sum(axis=1)[:, 0, 0])
    assert amp[1:] / amp[0] == pytest.approx([g, g, g * g], rel=0.03)


def test_rough_sea_scales_each_sea_leg_by_rho():
    # A rough sea (sigma_h = 15 cm: g = k sigma sin psi ~ 0.35) multiplies each sea-reflected
    # leg by rho_s (Miller-Brown-Vegh): the single-bounce paths by rho, the double by
    # rho^2, relative to the smooth sea (1 %).
    tx = np.array([-1000.0, 0.0, 10.0])
    h = 1.0
    smooth = _sphere_at(h, tx, SeaPlane(eps_r=EPS_SEA, sigma_h=0.0))
    rough = _sphere_at(h, tx, SeaPlane(eps_r=EPS_SEA, sigma_h=0.15))
    psi = np.arcsin((tx[2] + h) / np.linalg.norm([1000.0, 0.0, 10.0 + h]))
    rho = specular_reduction(psi, 0.15, K)
    assert 0.5 < rho < 0.95
    a_s = smooth.totals.sum(axis=1)[:, 0, 0]
    a_r = rough.totals.sum(axis=1)[:, 0, 0]
    ratio = np.abs(a_r / a_s)
    assert ratio == pytest.approx([1.0, rho, rho, rho**2], rel=0.01)


def test_sea_paths_have_their_own_delays():
    # The centres of each path kind lie at that path's bistatic range: direct 2 (r_d - a),
    # sea-hull and hull-sea r_d + r_i - 2 a, sea-hull-sea 2 (r_i - a) (the sphere's
    # specular point, a = radius), within the cell size (2 cm).
    tx = np.array([-300.0, 0.0, 20.0])
    h, a, cell = 1.5, 0.25, 0.02
    sig = _sphere_at(h, tx, SeaPlane(eps_r=EPS_SEA), cell=cell)
    p = np.array([0.0, 0.0, h])
    r_d = np.linalg.norm(p - tx)
    r_i = np.linalg.norm(p - mirror(tx))
    expected = [2 * (r_d - a), r_d + r_i - 2 * a, r_d + r_i - 2 * a, 2 * (r_i - a)]
    c = sig.centres
    rng = 2 * np.linalg.norm(c.position - tx, axis=1)
    for kind, name in enumerate(PATH_NAMES):
        sel = c.path == kind
        assert sel.any(), name
        # the strongest centre of each kind (the specular point)
        i = np.argmax(np.where(sel, np.abs(c.s[:, 0, 0]), -1))
        assert rng[i] == pytest.approx(expected[kind], abs=2 * cell)
    # filed along the line of sight, r_i - r_d beyond the direct echo (nearest point of
    # the longer path's iso-range surface to the hit)
    u = -tx / np.linalg.norm(tx)
    i0, i3 = (np.argmax(np.where(c.path == kind, np.abs(c.s[:, 0, 0]), -1)) for kind in (0, 3))
    assert (c.position[i3] - c.position[i0]) @ u == pytest.approx(r_i - r_d, abs=2 * cell)


def test_multipath_needs_platforms_above_the_sea():
    v, f = canonical.sphere(0.25, 2)
    with pytest.raises(ValueError, match="above the mean sea level"):
        trace_signature(TraceMesh.single(v + [0, 0, 2], f), [-100, 0, -5.0], [-100, 0, 5.0],
                        F, sea=SeaPlane(eps_r=EPS_SEA))


def test_signature_bytes_do_not_depend_on_the_threads(monkeypatch):
    # Parity: the batches of rays run on worker threads and are added in batch order,
    # so one thread and four give the same bytes (small batches: many of them, direct and
    # sea-first launches, edge cells); a thread pool that summed in completion order, or
    # a batch dropped, would fail.
    import seaecho.tracing.sbr as sbr

    v, f = canonical.sphere(0.25, 3)
    tx = np.array([-20.0, 5.0, 12.0])
    sea = SeaPlane(eps_r=EPS_SEA, sigma_h=0.05)
    out = []
    for threads in (1, 4):
        monkeypatch.setattr(sbr, "THREADS", threads)
        out.append(trace_signature(TraceMesh.single(v + [0, 0, 1.0], f), tx, tx, F,
                                   options=SBROptions(rays_per_wavelength=2, batch=2048),
                                   sea=sea))
    a, b = out
    assert a.n_rays == b.n_rays and a.n_hits == b.n_hits > 4 * 2048
    assert a.totals.tobytes() == b.totals.tobytes()
    assert a.centres.position.tobytes() == b.centres.position.tobytes()
    assert a.centres.s.tobytes() == b.centres.s.tobytes()


def test_an_empty_batch_on_a_worker_thread_is_no_hits(monkeypatch):
    # The abort once seen with SBR threads on: a batch with no ray left after the first
    # bounce asked Mitsuba to intersect empty arrays, and Dr.Jit aborted the process
    # ("jit_var(r0): unknown variable!") on whichever thread traced it (reproduced on a
    # worker thread with the guard of sbr._intersect removed). This bistatic trace of a
    # sphere over the sea (small batches) holds one such batch: on 4 threads it is no
    # hits, and the signature has the bytes of one thread.
    import seaecho.tracing.sbr as sbr

    empty = []
    intersect = sbr._intersect

    def counted(mi, scene, o, d):
        empty.append(o.shape[0] == 0)
        return intersect(mi, scene, o, d)

    monkeypatch.setattr(sbr, "_intersect", counted)
    v, f = canonical.sphere(0.25, 2)
    tx, rx = [21.944, 39.971, 14.558], [87.669, -5.565, 28.572]
    out = []
    for threads in (4, 1):
        monkeypatch.setattr(sbr, "THREADS", threads)
        out.append(trace_signature(TraceMesh.single(v + [0, 0, 1.5], f), tx, rx, F,
                                   options=SBROptions(rays_per_wavelength=4, batch=2048),
                                   sea=SeaPlane(eps_r=complex(50, -30), sigma_h=0.02)))
    assert sum(empty) == 2  # one empty batch in each trace
    assert out[0].totals.tobytes() == out[1].totals.tobytes()
    assert out[0].centres.s.tobytes() == out[1].centres.s.tobytes()
