"""SBR + PO against the closed-form RCS of canonical shapes (optical region).

References: Knott, Shaeffer and Tuley (1993), *Radar Cross Section*, 2nd ed., table 6.1
(plate 4 pi A^2 / lambda^2, sphere pi a^2, dihedral 8 pi a^2 b^2 / lambda^2, triangular
trihedral 4 pi a^4 / (3 lambda^2)) and ch. 5 (physical optics of a flat plate: the sinc
pattern); Balanis (2012), *Advanced Engineering Electromagnetics*, 2nd ed., sec. 11.3
(bistatic PO of a rectangular plate); Born and Wolf (1999), sec. 1.5 (Fresnel at normal
incidence). The polarimetric checks use the FSA bases of the project (a single bounce
gives S_hh = -S_vv, a double S_hh = S_vv); the backscatter alignment of RCS texts is
S_BSA = diag(-1, 1) S_FSA (Lee and Pottier 2009, sec. 3.1), where the textbook statements
(dihedral: HH and VV in opposition; trihedral: in phase) hold.
"""

from __future__ import annotations

import numpy as np
import pytest
from ship_helpers import LAM, db, direction, trace

from seaecho.geometry.frames import polarisation_basis
from seaecho.targets import canonical
from seaecho.tracing.scene import rotation_matrix

BSA = np.diag([-1.0, 1.0])


def test_plate_at_normal_incidence_is_4_pi_a2_over_lambda2():
    # A plate tiled exactly by the ray tubes (sides multiples of lambda / 4): the PO
    # integral is exact, 4 pi A^2 / lambda^2 within 0.02 dB; any other size within the
    # edge coverage of one tube per side (0.3 dB here). Dropping the factor 2 of
    # J = 2 n x H, or the tube area, fails by 6 dB or more.
    delta = LAM / 4
    for a, b, tol in ((40 * delta, 24 * delta, 0.02), (0.3, 0.2, 0.3)):
        sig = trace(canonical.rectangular_plate(a, b), [0, 0, 1.0], n=4)
        expected = 4 * np.pi * (a * b) ** 2 / LAM**2
        assert db(sig.rcs[[0, 3]] / expected) == pytest.approx([0, 0], abs=tol)
        assert sig.rcs[1] < 1e-12 * expected and sig.rcs[2] < 1e-12 * expected
        # FSA: a single bounce at normal incidence gives S_hh = -S_vv
        assert sig.s[0, 0] / sig.s[1, 1] == pytest.approx(-1.0, abs=1e-6)


@pytest.mark.parametrize("x", [0.0, 1.39, 4.49, 7.73])  # peak, -3 dB, two sidelobe peaks
def test_plate_pattern_is_the_po_sinc(x):
    # Plate a x b rotated about its b side by theta: sigma = 4 pi (ab/lambda)^2 cos^2
    # theta sinc^2(k a sin theta) (Knott et al. 1993, ch. 5). Points chosen where the
    # pattern is not steep (at a null any edge error is unbounded in dB): within 0.5 dB
    # at 8 rays per wavelength, with the side a = 0.3 m not a multiple of the tube.
    a, b = 0.3, 0.2
    theta = np.arcsin(x / (2 * np.pi / LAM * a))
    sig = trace(canonical.rectangular_plate(a, b), [np.sin(theta), 0, np.cos(theta)], n=8)
    expected = 4 * np.pi * (a * b / LAM) ** 2 * np.cos(theta) ** 2 * np.sinc(x / np.pi) ** 2
    assert db(sig.rcs[0] / expected) == pytest.approx(0.0, abs=0.5)
    assert db(sig.rcs[3] / expected) == pytest.approx(0.0, abs=0.5)


def test_plate_pattern_nulls():
    # The first two nulls k a sin theta = pi, 2 pi are at least 20 dB below the peak
    a, b = 0.3, 0.2
    peak = 4 * np.pi * (a * b / LAM) ** 2
    for x in (np.pi, 2 * np.pi):
        theta = np.arcsin(x / (2 * np.pi / LAM * a))
        sig = trace(canonical.rectangular_plate(a, b), [np.sin(theta), 0, np.cos(theta)], n=8)
        assert sig.rcs[0] < peak / 100


@pytest.mark.parametrize("theta_s_deg", [30.0, 33.0, 26.0, 40.0])
def test_bistatic_plate_is_po_closed_form(theta_s_deg):
    # PEC plate in z = 0, transmitter at theta_i = 30 deg on the -x side, receiver in the
    # plane of incidence at theta_s on the +x side (specular at 30 deg). PO with
    # J = 2 n x H_i (Balanis 2012, sec. 11.3): sigma_hh = 4 pi (A/lambda)^2 cos^2 theta_i
    # sinc^2 X, sigma_vv = 4 pi (A/lambda)^2 cos^2 theta_s sinc^2 X, X = (k a / 2)
    # (sin theta_s - sin theta_i). The ratio VV/HH, independent of the tube coverage,
    # within 0.01 dB; the levels within 0.3 dB (plate tiled by the tubes). One-way SBR
    # (PO is not reciprocal; the reciprocal mean is test_sbr_reciprocity's).
    a = b = 32 * LAM / 8
    ti, ts = np.deg2rad(30.0), np.deg2rad(theta_s_deg)
    tx = [-np.sin(ti), 0, np.cos(ti)]
    rx = [np.sin(ts), 0, np.cos(ts)]
    sig = trace(canonical.rectangular_plate(a, b), tx, rx, n=8, reciprocal=False)
    x = 0.5 * (2 * np.pi / LAM) * a * (np.sin(ts) - np.sin(ti))
    base = 4 * np.pi * (a * b / LAM) ** 2 * np.sinc(x / np.pi) ** 2
    assert db(sig.rcs[0] / (base * np.cos(ti) ** 2)) == pytest.approx(0.0, abs=0.3)
    assert db(sig.rcs[3] / (base * np.cos(ts) ** 2)) == pytest.approx(0.0, abs=0.3)
    assert db(sig.rcs[3] / sig.rcs[0]) == pytest.approx(db(np.cos(ts) ** 2 / np.cos(ti) ** 2),
                                                        abs=0.01)


def test_sphere_optical_limit_is_pi_a2():
    # Sphere of radius 0.25 m (ka = 52) facetted finely enough (sagitta << lambda / 8):
    # pi a^2 within 0.3 dB (PO's own ripple at this ka is ~0.1 dB), co-polar only,
    # HH = -VV in the FSA bases, at an arbitrary direction.
    a = 0.25
    sig = trace(canonical.sphere(a, 5), direction(37.0, 21.0), n=4)
    assert db(sig.rcs[[0, 3]] / (np.pi * a**2)) == pytest.approx([0, 0], abs=0.3)
    assert sig.rcs[1] < 1e-3 * np.pi * a**2
    assert sig.s[0, 0] / sig.s[1, 1] == pytest.approx(-1.0, abs=0.05)


def test_dihedral_peak_and_even_bounce_polarimetry():
    # 8 pi a^2 b^2 / lambda^2 at the bisector within 0.2 dB; double bounce: S_hh = S_vv in
    # FSA (zero phase), i.e. HH and VV in opposition in BSA (the textbook dihedral).
    a, b = 0.3, 0.4
    sig = trace(canonical.dihedral(a, b), direction(45.0), n=4)
    expected = 8 * np.pi * a**2 * b**2 / LAM**2
    assert db(sig.rcs[[0, 3]] / expected) == pytest.approx([0, 0], abs=0.2)
    assert abs(np.angle(sig.s[0, 0] / sig.s[1, 1])) < 0.05
    s_bsa = BSA @ sig.s
    assert abs(abs(np.angle(s_bsa[0, 0] / s_bsa[1, 1])) - np.pi) < 0.05
    # the double bounce carries it (bounce order 2 of the direct path)
    order = np.abs(sig.totals[0, :, 0, 0]) ** 2
    assert order[1] > 100 * order[0]


def test_dihedral_rolled_45_deg_is_cross_polar():
    # Rolled by 45 deg about the line of sight, the dihedral turns H into V: co-polar
    # channels vanish, |S_hv|^2 = |S_vh|^2 = 8 pi a^2 b^2 / lambda^2 (Knott et al. 1993;
    # the calibration scene's "dihedral45").
    a, b = 0.3, 0.4
    v, f = canonical.dihedral(a, b)
    u = direction(45.0)
    # rotate the mesh by 45 deg about u (Rodrigues)
    c, s = np.cos(np.pi / 4), np.sin(np.pi / 4)
    ux = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    r = c * np.eye(3) + s * ux + (1 - c) * np.outer(u, u)
    sig = trace((v @ r.T, f), u, n=4)
    expected = 8 * np.pi * a**2 * b**2 / LAM**2
    assert db(sig.rcs[[1, 2]] / expected) == pytest.approx([0, 0], abs=0.3)
    assert sig.rcs[0] < 1e-3 * expected and sig.rcs[3] < 1e-3 * expected


def test_trihedral_peak_and_odd_bounce_polarimetry():
    # Triangular trihedral on its axis: 4 pi a^4 / (3 lambda^2) within 0.5 dB; HH and VV
    # equal in magnitude (0.1 dB), in opposition in FSA, in phase in BSA (odd bounce),
    # cross-polar 25 dB below; the triple bounce carries it.
    a = 0.3
    sig = trace(canonical.trihedral(a), np.ones(3) / np.sqrt(3), n=4)
    expected = 4 * np.pi * a**4 / (3 * LAM**2)
    assert db(sig.rcs[[0, 3]] / expected) == pytest.approx([0, 0], abs=0.5)
    assert db(sig.rcs[0] / sig.rcs[3]) == pytest.approx(0.0, abs=0.1)
    assert abs(abs(np.angle(sig.s[0, 0] / sig.s[1, 1])) - np.pi) < 0.05
    s_bsa = BSA @ sig.s
    assert abs(np.angle(s_bsa[0, 0] / s_bsa[1, 1])) < 0.05
    assert max(sig.rcs[1], sig.rcs[2]) < sig.rcs[0] / 300
    order = np.abs(sig.totals[0, :, 0, 0]) ** 2
    assert order[2] > 30 * max(order[0], order[1])


def test_dielectric_plate_is_fresnel_times_pec():
    # A dielectric half-space plate at normal incidence: sigma = |R(0)|^2 4 pi A^2 /
    # lambda^2 with R(0) = (1 - sqrt eps) / (1 + sqrt eps) (Born and Wolf 1999, sec. 1.5):
    # the PO currents of the total field (J and M) with the facet's Fresnel coefficients.
    delta = LAM / 4
    a, b = 40 * delta, 24 * delta
    eps = 4.0 - 0.4j
    sig = trace(canonical.rectangular_plate(a, b), [0, 0, 1.0], n=4, eps_r=eps)
    r0 = (1 - np.sqrt(eps)) / (1 + np.sqrt(eps))
    expected = abs(r0) ** 2 * 4 * np.pi * (a * b) ** 2 / LAM**2
    assert db(sig.rcs[[0, 3]] / expected) == pytest.approx([0, 0], abs=0.02)


@pytest.mark.parametrize("shape", ["trihedral", "dihedral", "sphere"])
def test_rcs_converges_as_the_ray_density_doubles(shape):
    # Doubling the rays per lambda^2 (n -> n sqrt 2) changes the RCS by < 0.5 dB (both
    # co-polar channels), at an aspect off the peak for the corners (partial illumination
    # and partial triple bounces, where coverage errors show most).
    mesh, u = {"trihedral": (canonical.trihedral(0.3), direction(45.0, 30.0)),
               "dihedral": (canonical.dihedral(0.3, 0.4), direction(35.0, 10.0)),
               "sphere": (canonical.sphere(0.2, 5), direction(20.0, 70.0))}[shape]
    r = [trace(mesh, u, n=n).rcs for n in (4.0, 4.0 * np.sqrt(2))]
    assert db(r[1][[0, 3]] / r[0][[0, 3]]) == pytest.approx([0, 0], abs=0.5)


def test_rotated_mesh_gives_the_same_rcs():
    # Invariance: the trihedral turned onto another direction (object orientation
    # through Sionna's yaw/pitch/roll) and seen along it has the same RCS (0.3 dB).
    a = 0.3
    v, f = canonical.trihedral(a)
    r = rotation_matrix(np.deg2rad(140.0), np.deg2rad(20.0), np.deg2rad(45.0))
    u = r @ (np.ones(3) / np.sqrt(3))
    sig = trace((v @ r.T, f), u, n=4)
    expected = 4 * np.pi * a**4 / (3 * LAM**2)
    assert db(sig.rcs[[0, 3]] / expected) == pytest.approx([0, 0], abs=0.5)
    # polarisation bases are those of the line of sight (FSA, normal +z)
    h, v_ = polarisation_basis(-u)
    assert abs(h[2]) < 1e-12


@pytest.mark.slow
def test_ship_rcs_converges_as_the_ray_density_doubles():
    # The 80 m ship of scenes/ship_low_grazing_80m.toml (its geometry: 2 km, 25 m high
    # radar, heading 60 deg, sea multipath): the apparent RCS (HH, VV) moves by < 0.5 dB
    # from 1.41 to 2 rays per wavelength (measured: 0.4 dB; 2 -> 2.83: 0.03 dB), the
    # density the scene uses. Corners and flashes dominate a ship at this aspect.
    from pathlib import Path

    import trimesh

    from seaecho.ocean.seawater import sea_water_permittivity
    from seaecho.tracing.sbr import SBROptions, SeaPlane, TraceMesh, trace_signature

    m = trimesh.load(Path(__file__).resolve().parents[2] / "scenes" / "meshes"
                     / "vessel_80m.ply", process=False)
    v = m.vertices @ rotation_matrix(np.deg2rad(60.0), 0.0, 0.0).T
    tx = np.array([-2000.0, 0.0, 25.0])
    sea = SeaPlane(eps_r=complex(sea_water_permittivity(9.41e9, 15.0, 35.0)), sigma_h=0.0977)
    r = [trace_signature(TraceMesh.single(v, m.faces), tx, tx, 9.41e9, sea=sea,
                         options=SBROptions(rays_per_wavelength=n, cell=0.25)).rcs
         for n in (np.sqrt(2), 2.0)]
    assert db(r[1][[0, 3]] / r[0][[0, 3]]) == pytest.approx([0, 0], abs=0.5)
