"""End to end: a run's sea echo against the radar equation and the mean-plane point model,
with shadowing and the turbulent wake on.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

from seaecho.cli import main
from seaecho.config import parse_scene
from seaecho.simulation import Simulation

ISO = {"pattern": "isotropic", "look_at_m": (0.0, 0.0, 0.0)}
C0 = 299_792_458.0  # [m/s], exact (SI 2019)


def _db(x):
    return 10.0 * np.log10(x)


# ------------------------------------------------------------ scene NRCS vs point model
def _bragg_scene_toml(seed: int, scattering: str = "") -> str:
    """A gentle Pierson-Moskowitz sea (U19.5 = 3 m/s; an 8.8 m tile holds the 8.2 m peak
    wavelength, its 0.08 m grid keeps the Bragg roughness at k h = 0.24 < 0.3) seen
    monostatically at 40 deg incidence from 1 km (the angles vary by +-0.25 deg over the
    tile), 10 GHz, isotropic antennas."""
    th = np.radians(40.0)
    return f"""
[sea]
spectrum = "pierson-moskowitz"
spreading = "longuet-higgins"
wind_speed_m_s = 3.0
size_x_m = 8.8
nx = 110
[run]
seed = {seed}
[tracing]
mode = "analytic"
shadowing = "none"
[scattering]
{scattering}
[radar]
carrier_frequency_hz = 10.0e9
sampling_rate_hz = 200.0e6
prf_hz = 1000.0
n_pulses = 1
[radar.waveform]
kind = "lfm"
bandwidth_hz = 100.0e6
duration_s = 1.0e-6
[transmitter]
position_m = [{-1000.0 * np.sin(th)}, 0.0, {1000.0 * np.cos(th)}]
[transmitter.antenna]
pattern = "isotropic"
look_at_m = [0.0, 0.0, 0.0]
"""


def _point_model(tmp_path, scene, model):
    """``seaecho sigma --scene`` at the tile centre's monostatic 40 deg geometry [m2/m2]."""
    out = tmp_path / f"{model}.csv"
    assert main(["sigma", "--scene", str(scene), "--model", model, "--theta-i-deg", "40",
                 "--theta-s-deg", "40", "--phi-s-deg", "180", "-o", str(out),
                 "--no-figure"]) == 0
    with open(out, newline="") as fh:
        row = next(csv.DictReader(fh))
    return np.array([10 ** (float(row[f"sigma_{c}_db"]) / 10) for c in ("hh", "hv", "vh",
                                                                        "vv")])


def test_scene_nrcs_lies_between_the_mean_plane_spm_and_two_scale_models(tmp_path, capsys):
    # The run's sigma0 (NRCS per unit horizontal area of each cell, its facets summed),
    # averaged over the tile, against `seaecho sigma` for the same sea and carrier
    # (paper eqs 8-9; Valenzuela 1968 for the tilts). At 40 deg the co-pol echo is Bragg
    # scattering (Kirchhoff weight 10^-((40/18.85)^8), eq 10, is nil) on facets tilted by the
    # resolved waves: the scene value must lie between the untilted SPM and the two-scale
    # model that tilts by every wave longer than k/3 (the facets carry only the waves
    # the grid resolves, low-passed by the triangles). Measured: VV -18.60 dB within
    # [-18.87, -18.49], HH -24.52 within [-25.45, -24.13]. The tile mean varies by
    # 0.09 dB (HH) and 0.03 dB (VV) from seed to seed (23 762 facets, slopes correlated
    # over a few cells): the mean of 3 seeds is good to 0.05 dB, tolerance 0.2 dB.
    runs = []
    for seed in range(3):
        scene = tmp_path / f"s{seed}.toml"
        scene.write_text(_bragg_scene_toml(seed))
        out = tmp_path / f"s{seed}.nc"
        assert main(["run", str(scene), "-o", str(out), "-q", "--no-figures"]) == 0
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            assert ds["sigma0"].attrs["units"] == "m2 m-2"
            runs.append(ds["sigma0"].mean(dim=("y_cell", "x_cell")).values)
    runs = np.array(runs)
    assert np.all(_db(runs[:, [0, 3]]).std(axis=0) < 0.2)
    sim = _db(runs.mean(axis=0))
    spm = _db(_point_model(tmp_path, scene, "spm"))
    two_scale = _db(_point_model(tmp_path, scene, "two-scale"))
    for c in (0, 3):  # HH, VV
        assert spm[c] - 0.2 < sim[c] < two_scale[c] + 0.2, (c, spm[c], sim[c], two_scale[c])
    # tilts out of the plane of incidence depolarise: HV appears, far below co-pol
    assert -60.0 < sim[1] < sim[0] - 15.0 and sim[1] == pytest.approx(sim[2], abs=1e-6)
    capsys.readouterr()


@pytest.mark.parametrize("tilt", [False, True])
def test_scene_nrcs_is_the_two_scale_model_of_its_own_facet_slopes(tilt):
    # Two methods that must agree: the sum over the facets (each an SPM on its tilted
    # plane, eq S7 of scattering.facet) and the Gauss-Hermite slope average of
    # scattering.twoscale (eq T1) with the facets' own sample slope variances (plus, with
    # the unresolved-tilt average of eq P6, the sub-facet slope variances). Co-pol
    # within 0.15 dB (measured within 0.05 dB over 4 seeds; the facet slopes are not
    # exactly Gaussian). Cross-pol: the facets blend it with eq 11's weight
    # w2 = 10^-((beta / 20 pi)^1.5) = 0.31 at beta = 40 deg (Kirchhoff cross-pol is 0 in
    # back-scatter), the two-scale model does not: 10 log10(1 - 0.31) = -1.62 dB.
    from seaecho.scattering.twoscale import two_scale_sigma

    opts = f'model = "blend"\nunresolved_tilt = {str(tilt).lower()}'
    scene = parse_scene(_toml_dict(_bragg_scene_toml(0, opts)))
    sim = Simulation(scene)
    truth = sim.sea_truth()
    f = sim.sea_echo(0, sigma=True).facets
    zx, zy = -f.normal[:, 0] / f.normal[:, 2], -f.normal[:, 1] / f.normal[:, 2]
    m = sim.sea_model
    sub = (m.mss_upwind, m.mss_crosswind) if tilt else (0.0, 0.0)
    th = np.radians(40.0)
    ref = two_scale_sigma(th, 0.0, th, np.pi, m.k, m.eps_r, m.bragg_spectrum,
                          zx.var() + sub[0], zy.var() + sub[1], 0.0, m.k_grid, n_nodes=24)
    got = truth["sigma0"].mean(axis=(1, 2))
    np.testing.assert_allclose(_db(got[[0, 3]]), _db(ref[[0, 3]]), atol=0.15)
    w2 = 10.0 ** (-((40.0 / (20.0 * np.pi)) ** 1.5))
    np.testing.assert_allclose(_db(got[[1, 2]] / ref[[1, 2]]), _db(1.0 - w2), atol=0.15)


def _toml_dict(text):
    import tomllib

    return tomllib.loads(text)


# ------------------------------------------------------- the wake darkens the Bragg echo
def _wake_scene(seed=0, mode="analytic", shadowing="smith", n=80, size=6.4, scattering=None,
                **radar):
    """A sea under a low-grazing bistatic radar, half of it in a turbulent wake.

    U19.5 = 5 m/s on a 0.08 m grid (k h = 0.24 for the Bragg roughness). Tx 1 km away at
    2.9 deg grazing, Rx 0.85 km away at 2.7 deg, 28 deg out of plane: Smith's shadowing
    hides a good part of the facets. The ship (10 m x 4 m, heading east, stern at
    x = 7 m) leaves a damped strip about 5 m wide along y = 2.5 m.
    """
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 1.2e9, "prf_hz": 1e3,
         "n_pulses": 1, "transmit_power_w": 10.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": 1e9, "duration_s": 0.2e-6}}
    r.update(radar)
    return parse_scene({
        "sea": {"spectrum": "pierson-moskowitz", "spreading": "longuet-higgins",
                "wind_speed_m_s": 5.0, "size_x_m": size, "nx": n},
        "ship": {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 5.0,
                 "heading_deg": 0.0, "position_m": (12.0, 2.5), "kelvin_wake": False},
        "run": {"seed": seed},
        "tracing": {"mode": mode, "shadowing": shadowing},
        "radar": r,
        "transmitter": {"position_m": (-1000.0, 0.0, 50.0), "antenna": ISO},
        "receiver": {"position_m": (-750.0, -400.0, 40.0), "antenna": ISO},
        "scattering": scattering or {},
    })


def _expected_clutter_energy(sim, pulse):
    """The clutter radar equation, written out: sum over facets of
    P_t G_t G_r lambda^2 sigma_mn A v / ((4 pi)^3 r_t^2 r_r^2), times the pulse energy
    (Skolnik 2008, eq 23.9 for bistatic clutter), with G = 1 (isotropic antennas), A the
    facet area, v its visibility (lit and seen: Smith's shadowing or ray traced) and
    sigma_mn the facet model with the turbulent wake's Bragg damping read from the sea
    state's mask, the unresolved-tilt average and the breaking zones where the simulation
    placed them. The speckled echo must have this mean (Ulaby & Long 2014, sec. 5-8)."""
    from seaecho.geometry.mesh import to_facets
    from seaecho.scattering.facet import facet_sigma

    geo = sim.radar.geometry(pulse)
    st = sim.surface_state(pulse)
    f = sim.engine.facets(geo.time, state=st)
    sig = facet_sigma(f.n_i, f.n_s, f.normal, sim.sea_model.facet_model,
                      wake_damping=to_facets(st.wake_mask).reshape(-1), backend="numpy",
                      breaking_fraction=sim.breaking_fraction(st))
    r_t = np.linalg.norm(f.centroid - geo.tx.position, axis=-1)
    r_r = np.linalg.norm(f.centroid - geo.rx.position, axis=-1)
    lam = C0 / 1e10
    p_r = (10.0 * lam**2 * sig * (f.area * f.visibility)[:, None]
           / ((4.0 * np.pi) ** 3 * (r_t**2 * r_r**2)[:, None]))
    pulse_energy = np.sum(np.abs(sim.radar.waveform.samples) ** 2)
    return p_r.sum(axis=0) * pulse_energy, f


@pytest.mark.parametrize("mode,seeds,tol", [("analytic", 16, 0.25), ("raytraced", 10, 0.35)])
def test_clutter_echo_is_the_radar_equation_with_shadowing_and_wake(mode, seeds, tol):
    # The mean received energy of the speckled sea echo (independent surfaces and
    # speckle per seed) equals the clutter radar equation with the visibility and the
    # wake damping in it. With a 1 GHz chirp the 6.4 m tile spans about 40 range cells
    # at this grazing angle: one seed's measured / expected ratio spreads by 0.2-0.27 per
    # channel (measured), so 16 seeds give a standard error of 0.05-0.07 (tolerance 0.25)
    # and 10 ray-traced seeds 0.04-0.09 (tolerance 0.35). Dropping the visibility from the
    # echo raises it by 1.5-1.7 here, dropping the wake damping by 2.1-2.5.
    ratios, shadow, damped = [], [], []
    for seed in range(seeds):
        sim = Simulation(_wake_scene(seed, mode=mode))
        raw = sim.pulse(0)
        expected, f = _expected_clutter_energy(sim, 0)
        ratios.append(np.sum(np.abs(raw) ** 2, axis=-1) / expected)
        shadow.append(1.0 - np.average(f.visibility, weights=f.area))
        damped.append(sim.surface_state(0).wake_mask.mean())
    assert np.mean(shadow) > 0.4  # the visibility matters: (measured) 59-65 % hidden
    assert 0.3 < np.mean(damped) < 0.8  # the wake covers a good part of the tile
    np.testing.assert_allclose(np.mean(ratios, axis=0), 1.0, atol=tol)  # HH, HV, VH, VV


def test_turbulent_wake_scales_the_bragg_echo_by_its_damping(tmp_path):
    # Behind a ship the short (Bragg) waves are damped (Milgram, Peltzer & Griffin 1993):
    # the wake's damping d in [0, 1] multiplies the height spectrum at the Bragg
    # wavenumber by 1 - d (eq P2), and SPM's sigma is proportional to that spectrum
    # (Valenzuela 1978). At this low-grazing, far-from-specular geometry the Kirchhoff
    # weight is negligible (10^-((beta/18.85)^8), eq 10, beta ~ 90 deg), so every cell's
    # NRCS is that of the same surface without the wake times 1 - d (d averaged over the
    # cell's corners: 1.5 % at most, measured, from facet vs cell averaging). The
    # reference run drops the ship: the same seed gives the same surface bits.
    from seaecho.config.loading import scene_to_toml_dict

    scene = _wake_scene(0, shadowing="none", scattering={"model": "blend"})
    bare = scene_to_toml_dict(scene)
    bare.pop("ship")
    sigma = []
    for name, sc in (("wake", scene), ("bare", parse_scene(bare))):
        out = Simulation(sc).run(tmp_path / f"{name}.nc", progress=False)
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            sigma.append(ds["sigma0"].values)
            if name == "wake":
                m = ds["wake_mask"].values
    d = 0.25 * (m[:-1, :-1] + m[1:, :-1] + m[:-1, 1:] + m[1:, 1:])
    seen = sigma[1][3] > 0
    damped = seen & (d > 0.05)
    assert damped.sum() > 1000 and 0.3 < d[damped].mean() < 0.9
    for c in range(4):  # HH, HV, VH, VV
        ratio = sigma[0][c][damped] / sigma[1][c][damped]
        np.testing.assert_allclose(ratio, 1.0 - d[damped], atol=0.02)
        np.testing.assert_array_equal(sigma[0][c][seen & (d == 0)],
                                      sigma[1][c][seen & (d == 0)])
