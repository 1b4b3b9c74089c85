"""The orchestrator: streamed runs, reproducibility, interrupts, and the clutter radar equation.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from seaecho.config import parse_scene
from seaecho.simulation import Simulation

ANT = {"pattern": "rectangular", "width_m": 0.18, "height_m": 0.14, "look_at_m": (0, 0, 0)}


def _scene(sea=False, seed=1, n_pulses=6, size=4.0, nx=64, **radar):
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6, "prf_hz": 1e3,
         "n_pulses": n_pulses, "sea_clutter": sea, "transmit_power_w": 10.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": 100e6, "duration_s": 1e-6}}
    r.update(radar)
    return parse_scene({
        "sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": 3.0, "size_x_m": size,
                "nx": nx},
        "run": {"seed": seed},
        "tracing": {"mode": "analytic", "shadowing": "none"},
        "radar": r,
        "transmitter": {"position_m": (-93.41, 0.0, 256.65), "antenna": ANT},
        "receiver": {"position_m": (-50.75, 0.0, 87.91), "antenna": ANT},
        "targets": [{"position_m": (1.0, 2.0, 0.5), "rcs_m2": 3.0},
                    {"position_m": (-2.0, 0.0, 0.0), "velocity_m_s": (3.0, 0, 0),
                     "s_hv": (1.0, 0.0)}],
    })


def test_targets_only_run_writes_complete_dataset(tmp_path):
    sc = _scene(thermal_noise=True)
    sim = Simulation(sc)
    out = sim.run(tmp_path / "a.nc", progress=False, chunk=4)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds["raw"].dims == ("pulse", "channel", "fast_time")
        assert ds["raw"].dtype == np.complex128 and ds["compressed"].dtype == np.complex128
        assert list(ds["channel"].values) == ["HH", "HV", "VH", "VV"]
        assert ds.sizes["pulse"] == 6
        assert ds["range"].attrs["units"] == "m"
        assert "scene_json" in ds.attrs and ds.attrs["seed"] == 1
        for v in ("tx_position", "tx_position_nominal", "rx_velocity", "target_position"):
            assert v in ds
        # the file holds what the per-pulse function computes, in any order
        np.testing.assert_array_equal(ds["raw"].values[4], Simulation(sc).pulse(4))
        np.testing.assert_allclose(ds["compressed"].values[2],
                                   sim.compress(ds["raw"].values[2]), atol=0)
    assert [p.name for p in tmp_path.iterdir()] == ["a.nc"]  # no temporary left


def test_same_seed_same_bytes_other_seed_other_noise(tmp_path):
    a = Simulation(_scene(thermal_noise=True, seed=5)).run(tmp_path / "a.nc", progress=False)
    b = Simulation(_scene(thermal_noise=True, seed=5)).run(tmp_path / "b.nc", progress=False,
                                                           chunk=1)
    c = Simulation(_scene(thermal_noise=True, seed=6)).run(tmp_path / "c.nc", progress=False)
    with (xr.open_dataset(a, engine="h5netcdf") as da, xr.open_dataset(b, engine="h5netcdf")
          as db, xr.open_dataset(c, engine="h5netcdf") as dc):
        assert da["raw"].values.tobytes() == db["raw"].values.tobytes()
        assert da["compressed"].values.tobytes() == db["compressed"].values.tobytes()
        assert da["raw"].values.tobytes() != dc["raw"].values.tobytes()


def test_interrupted_run_leaves_no_file(tmp_path, monkeypatch):
    path = tmp_path / "out.nc"
    sim = Simulation(_scene(n_pulses=40))
    calls = []

    def interrupted(p):
        calls.append(p)
        if p == 20:
            raise KeyboardInterrupt
        return np.zeros((4, sim.radar.window.n_samples), complex)

    monkeypatch.setattr(sim, "pulse", interrupted)
    with pytest.raises(KeyboardInterrupt):
        sim.run(path, progress=False, chunk=8)
    assert calls[-1] == 20
    assert list(tmp_path.iterdir()) == []  # neither the output nor a temporary
    # an existing file is left as it was
    path.write_bytes(b"old")
    with pytest.raises(KeyboardInterrupt):
        sim.run(path, progress=False, chunk=8)
    assert path.read_bytes() == b"old" and len(list(tmp_path.iterdir())) == 1


def test_memory_is_bounded_by_the_chunk(tmp_path, monkeypatch):
    # The writer holds at most `chunk` pulses: every block it compresses and writes has
    # at most `chunk` rows, whatever the number of pulses.
    sizes = []
    sim = Simulation(_scene(n_pulses=30))
    orig = sim.compress

    def spy(raw):
        sizes.append(raw.shape[0])
        return orig(raw)

    monkeypatch.setattr(sim, "compress", spy)
    sim.run(tmp_path / "m.nc", progress=False, chunk=4)
    assert max(sizes) <= 4 and sum(sizes) == 30


def test_sea_run_has_surface_sigma_maps_and_truth(tmp_path):
    sc = _scene(sea=True, n_pulses=3, sigma_map_pulse=1)
    out = Simulation(sc).run(tmp_path / "s.nc", progress=False)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds["elevation"].dims == ("y", "x") and ds.sizes["x"] == 64
        assert ds["sigma0"].dims == ("polarisation", "y_cell", "x_cell")
        assert np.all(ds["sigma0"].values >= 0) and float(ds["sigma0"].max()) > 0
        assert float(np.abs(ds["raw"]).max()) > 0
        sigma0 = ds["sigma0"].values
    # sigma0 is the NRCS per unit horizontal area: the cells' sum times dx dy is the
    # sum over the facets of sigma_mn x facet area x visibility, their mean RCS [m^2]
    sim = Simulation(sc)
    se = sim.sea_echo(1, sigma=True)
    dx = 4.0 / 64
    np.testing.assert_allclose(sigma0.sum(axis=(1, 2)) * dx * dx,
                               se.facets.area @ se.sigma_facet, rtol=1e-12)


def test_speckle_and_surface_held_within_a_block():
    # With the surface held for the block and fixed platforms, two pulses of one block are
    # identical (same surface, same speckle draw); the next block draws new speckle.
    # (Held explicitly: a sea renewed within the run evolves by default, "auto".)
    sc = _scene(sea=True, n_pulses=4, sea_update_pulses=2)
    sim = Simulation(sc.model_copy(update={"targets": (), "scattering": sc.scattering.model_copy(
        update={"sea_motion": "held"})}))
    r0, r1, r2 = sim.pulse(0), sim.pulse(1), sim.pulse(2)
    np.testing.assert_array_equal(r0, r1)
    assert not np.allclose(r0, r2)
    assert sim.surface_time(3) == sim.surface_time(2) == pytest.approx(2e-3)


def _raytraced_scene(refresh_interval_s=0.0, moving=True, n_pulses=5, **radar):
    sc = _scene(sea=True, n_pulses=n_pulses, **radar)
    upd = {"targets": (),
           "tracing": sc.tracing.model_copy(update={"mode": "raytraced",
                                                   "refresh_interval_s": refresh_interval_s})}
    if moving:  # the transmitter flies: ranges, angles and occlusion change per pulse
        upd["transmitter"] = sc.transmitter.model_copy(
            update={"motion": "linear", "velocity_m_s": (0.0, 200.0, 0.0)})
    return sc.model_copy(update=upd)


@pytest.mark.parametrize("refresh", [0.0, 2e-3])
def test_pulses_in_any_order_give_the_same_bytes(refresh):
    # docs/conventions.md: a pulse is a pure function of (scene, pulse). The per-sea-state caches
    # (facet geometry, speckle draws, occlusion of the refresh time) must not make a pulse
    # depend on which pulses were computed before it: in order, reversed, and each pulse
    # alone in a fresh Simulation must agree to the byte.
    sc = _raytraced_scene(refresh, sea_update_pulses=2)
    n = sc.radar.n_pulses
    sim = Simulation(sc)
    ordered = {p: sim.pulse(p) for p in range(n)}
    sim = Simulation(sc)
    reverse = {p: sim.pulse(p) for p in (4, 1, 3, 0, 2)}
    for p in range(n):
        alone = Simulation(sc).pulse(p)
        assert ordered[p].tobytes() == reverse[p].tobytes() == alone.tobytes(), p
    assert not np.array_equal(ordered[0], ordered[1])  # the platform moved


def test_pulses_with_the_next_sea_computed_ahead_give_the_same_bytes(monkeypatch):
    # Simulation.pulses computes the next pulse's sea state on a thread while the current
    # pulse runs (prefetch_surface): a new sea every pulse, the block's bytes are those of
    # each pulse computed alone, and every sea state but the first came from the thread
    import threading

    sc = _raytraced_scene(0.0, sea_update_pulses=1)
    sim = Simulation(sc)
    where = []
    state = sim.sea.state

    def spy(t):
        where.append(threading.current_thread() is threading.main_thread())
        return state(t)

    monkeypatch.setattr(sim.sea, "state", spy)
    raw, _ = sim.pulses(0, 4)
    for p in range(4):
        assert raw[p].tobytes() == Simulation(sc).pulse(p).tobytes(), p
    assert sorted(where) == [False, False, False, True]  # pulse 0's own, then ahead


def test_an_error_of_the_prefetched_sea_reaches_the_pulse(monkeypatch):
    sim = Simulation(_raytraced_scene(0.0, sea_update_pulses=1))
    sim.pulse(0)

    def boom(t):
        raise RuntimeError("sea failed")

    monkeypatch.setattr(sim.sea, "state", boom)
    sim.prefetch_surface(1)
    with pytest.raises(RuntimeError, match="sea failed"):
        sim.pulse(1)


def test_refresh_traces_the_held_surface():
    # With the sea held and static platforms, occlusion at the refresh time t_ref is that
    # of the pulse's own time: refreshing every 1.5 pulse periods must give the bytes of
    # tracing every pulse. (Tracing the sea of time t_ref instead of the held surface
    # would change the shadows.)
    a = _raytraced_scene(0.0, moving=False, sea_update_pulses=5)
    b = _raytraced_scene(1.5e-3, moving=False, sea_update_pulses=5)
    sa, sb = Simulation(a), Simulation(b)
    for p in (1, 4):
        assert sa.pulse(p).tobytes() == sb.pulse(p).tobytes()
        held = sb.surface_state(p).elevation
        np.testing.assert_array_equal(sb.engine.tracer._elevation, held)


def test_dataset_states_sea_update_and_refresh_interval(tmp_path):
    sc = _raytraced_scene(2e-3, n_pulses=2, sea_update_pulses=2)
    out = Simulation(sc).run(tmp_path / "r.nc", progress=False)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds.attrs["tracing_refresh_interval_s"] == 2e-3
        assert ds.attrs["tracing_mode"] == "raytraced"
        assert ds.attrs["sea_update_pulses"] == 2
        assert ds.attrs["sea_update_interval_s"] == pytest.approx(2e-3)


# ------------------------------------------------------------------ the evolving sea
def _evolving(n_pulses=6, update=3, model="blend+breaking", **radar):
    sc = _raytraced_scene(0.0, n_pulses=n_pulses, sea_update_pulses=update, **radar)
    return sc.model_copy(update={"scattering": sc.scattering.model_copy(
        update={"sea_motion": "evolving", "model": model})})


def test_evolving_sea_pulses_in_any_order_give_the_same_bytes():
    # docs/dynamics.md: the evolving speckle's anchors come from (seed, family, anchor)
    # and the phase centres from the block's surface: a pulse is still a pure function
    # of (scene, pulse), in order, reversed or alone.
    sc = _evolving()
    n = sc.radar.n_pulses
    sim = Simulation(sc)
    ordered = {p: sim.pulse(p) for p in range(n)}
    sim = Simulation(sc)
    reverse = {p: sim.pulse(p) for p in (5, 1, 4, 0, 3, 2)}
    for p in range(n):
        alone = Simulation(sc).pulse(p)
        assert ordered[p].tobytes() == reverse[p].tobytes() == alone.tobytes(), p


def test_evolving_sea_moves_within_a_block_and_held_sea_does_not():
    # Held (the paper): two pulses of a block with fixed platforms are identical.
    # Evolving: the facets move and the speckle turns, so they differ, yet stay
    # correlated over a millisecond (the coherence time is tens of ms here).
    base = _scene(sea=True, n_pulses=4, sea_update_pulses=4).model_copy(
        update={"targets": ()})
    sims = {}
    for motion in ("held", "evolving"):
        sc = base.model_copy(update={"scattering": base.scattering.model_copy(
            update={"sea_motion": motion})})
        sims[motion] = Simulation(sc)
    h0, h1 = sims["held"].pulse(0), sims["held"].pulse(1)
    np.testing.assert_array_equal(h0, h1)
    e0, e1 = sims["evolving"].pulse(0), sims["evolving"].pulse(1)
    assert not np.array_equal(e0, e1)
    rho = np.abs(np.vdot(e0, e1)) / np.sqrt(np.vdot(e0, e0).real * np.vdot(e1, e1).real)
    assert 0.5 < rho < 0.9999


def test_incremental_phase_centres_follow_the_exact_surface():
    # Between geometry updates the phase centres are carried by velocity and
    # acceleration (second order): after 5 ms they are within 10 um (measured 0.9 um;
    # 4e-4 rad of two-way phase at 10 GHz) of the particle positions of the exact
    # surface (sea_update_pulses = 1); the first order alone is off by 51 um, the held
    # positions by 2.9 mm. On still water: the default surface drift (here 0.085 m/s, 3 %
    # of U10) is an Eulerian advection the particle acceleration of the second-order term
    # does not carry; with it the error is 6.4 um (first order 57 um), still within 10 um.
    def still(sc):
        return sc.model_copy(update={"sea": sc.sea.model_copy(update={"wind_drift": "none"})})

    for drift, factor in ((False, 10.0), (True, 5.0)):
        exact = _evolving(n_pulses=6, update=1)
        inc = _evolving(n_pulses=6, update=6)
        exact, inc = (Simulation(x if drift else still(x)) for x in (exact, inc))
        p = 5
        a = exact.phase_centres(p, exact.surface_state(p))
        b = inc.phase_centres(p, inc.surface_state(p))
        err = np.abs(a - b).max()
        assert err < 1e-5
        held = inc._block_quantities(p, inc.surface_state(p), a.shape[0])
        first = held["centre"] + held["velocity"] * 5e-3
        assert np.abs(first - a).max() > factor * err


def test_dataset_says_whether_the_sea_is_frozen(tmp_path):
    out = Simulation(_evolving(n_pulses=2, update=2)).run(tmp_path / "e.nc", progress=False)
    with xr.open_dataset(out, engine="h5netcdf") as ds:
        assert ds.attrs["sea_motion"] == "evolving" and ds.attrs["sea_frozen"] == 0
        assert ds.attrs["phase_update_interval_s"] == pytest.approx(1e-3)
        assert ds.attrs["speckle_lifetime_bragg_plus_s"] > 0.0
        assert ds.attrs["scattering_model"] == "blend+breaking"
    # "auto" (the default): one surface for both pulses is held; a sea renewed at every
    # pulse evolves (held, it would give white clutter)
    for update, motion in ((2, "held"), (1, "evolving")):
        sc = _raytraced_scene(0.0, n_pulses=2, sea_update_pulses=update)
        assert sc.scattering.sea_motion == "auto"
        out = Simulation(sc).run(tmp_path / f"a{update}.nc", progress=False)
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            assert ds.attrs["sea_motion"] == motion
            assert ds.attrs["sea_frozen"] == int(motion == "held")


@pytest.mark.parametrize("mode", ["analytic", "raytraced"])
def test_scene_variant_reaches_every_kernel(mode, monkeypatch):
    # [tracing] variant selects the Dr.Jit back end of every per-pulse kernel (facet
    # frames, eqs P1-P4, the radar equation of facets and targets), not only the
    # tracer's: each kernel asks seaecho.backend.check_variant for the scene's variant
    # by name, never for "whatever runs" (None), which would leave a CUDA scene on the CPU
    from seaecho import backend

    asked = []
    check = backend.check_variant

    def spy(variant):
        asked.append(variant)
        return check(variant)

    monkeypatch.setattr(backend, "check_variant", spy)
    sc = _scene(sea=True, n_pulses=1)
    sc = sc.model_copy(update={"tracing": sc.tracing.model_copy(
        update={"mode": mode, "variant": "llvm_ad_mono_polarized"})})
    Simulation(sc).pulse(0)
    assert len(asked) >= 4 and set(asked) == {"llvm_ad_mono_polarized"}, asked


def _nan_target_echo(real, bad_pulse, bad_target):
    """target_echo with target ``bad_target``'s amplitudes NaN from ``bad_pulse`` on."""

    def echo(self, geometry, *, variant=None):
        e = real(self, geometry, variant=variant)
        if geometry.time >= self.emission_time(bad_pulse):
            e.amplitudes[:, bad_target] = np.nan
        return e

    return echo


def test_non_finite_pulse_stops_the_run_and_names_the_target(tmp_path, monkeypatch):
    from seaecho.checks.guards import NonFiniteEchoError
    from seaecho.radar.system import RadarSystem

    monkeypatch.setattr(RadarSystem, "target_echo",
                        _nan_target_echo(RadarSystem.target_echo, 3, 1))
    path = tmp_path / "out.nc"
    with pytest.raises(NonFiniteEchoError, match=r"pulse 3 .*point target \"target1\""):
        Simulation(_scene(n_pulses=6)).run(path, progress=False, chunk=2)
    assert list(tmp_path.iterdir()) == []


def test_non_finite_sea_facets_are_named(monkeypatch):
    from seaecho.checks.guards import NonFiniteEchoError

    sim = Simulation(_scene(sea=True, n_pulses=2))
    real = sim.sea_echo

    def sea_echo(pulse, geometry=None, sigma=False):
        se = real(pulse, geometry, sigma)
        se.echo.tau[5] = np.inf
        return se

    monkeypatch.setattr(sim, "sea_echo", sea_echo)
    with pytest.raises(NonFiniteEchoError, match=r"pulse 1 .*1 sea facets \(first index 5\)"):
        sim.pulse(1)


def test_non_finite_static_variable_stops_the_run(tmp_path, monkeypatch):
    from seaecho.checks.guards import NonFiniteEchoError
    from seaecho.io import run as io_run

    sim = Simulation(_scene(n_pulses=3))
    real = io_run.run_dataset

    def run_dataset(*args, **kwargs):
        ds = real(*args, **kwargs)
        ds["tx_velocity"].values[1, 0] = np.inf
        return ds

    monkeypatch.setattr(io_run, "run_dataset", run_dataset)
    with pytest.raises(NonFiniteEchoError, match="tx_velocity"):
        sim.run(tmp_path / "out.nc", progress=False)
    assert list(tmp_path.iterdir()) == []


def test_single_precision_accumulation_matches_double():
    """Parity: ``[radar] accumulation_precision = "single"`` (finufft in float32) gives
    the sea's pulse of the float64 NUFFT within 1e-4 of its peak (the float32 transform's
    ~1e-5 per channel, docs/performance.md); a target-only echo (the exact direct sum)
    is unaffected; a bad value names the field."""
    pulses = {p: Simulation(_scene(sea=True, accumulation_precision=p)).pulse(2)
              for p in ("double", "single")}
    d, s = pulses["double"], pulses["single"]
    err = np.abs(s - d).max() / np.abs(d).max()
    assert 0 < err < 1e-4
    t = {p: Simulation(_scene(accumulation_precision=p)).pulse(1) for p in ("double", "single")}
    np.testing.assert_array_equal(t["double"], t["single"])
    with pytest.raises(ValueError, match="accumulation_precision"):
        _scene(accumulation_precision="half")


def test_default_sea_renewed_every_pulse_gives_coherent_clutter():
    # A scene that says nothing of the sea's motion and renews the sea every pulse
    # (sea_update_pulses = 1): held, each pulse has new speckle and the clutter is white
    # (lag-one correlation ~ 0); the default ("auto" -> evolving) keeps the pulses
    # coherent over the PRI (1 ms here, for a coherence time of tens of ms at X band:
    # docs/dynamics.md), so its Doppler spectrum is that of the moving sea.
    base = _scene(sea=True, n_pulses=12).model_copy(update={"targets": ()})
    assert base.scattering.sea_motion == "auto" and base.radar.sea_update_pulses == 1
    rho = {}
    for motion in ("auto", "held"):
        sc = base.model_copy(update={"scattering": base.scattering.model_copy(
            update={"sea_motion": motion})})
        sim = Simulation(sc)
        x = np.array([sim.pulse(p) for p in range(sc.radar.n_pulses)])
        rho[motion] = (np.abs(np.sum(x[1:] * np.conj(x[:-1])))
                       / np.sum(np.abs(x[:-1]) ** 2))
        assert sim.evolving == (motion == "auto")
    assert rho["held"] < 0.3
    assert rho["auto"] > 0.8


@pytest.mark.parametrize("name", ["paper_sim2_sar_128m_wind55", "paper_sim4_sar_500m_u10"])
def test_sar_scenes_hold_their_sea_by_default_to_the_byte(name):
    # The paper's SAR scenes hold one sea for the whole aperture (sea_update_pulses =
    # n_pulses): the default "auto" must give the bytes of an explicitly held sea (their
    # pulses before the default changed). A coarse grid and no hull keep it cheap.
    import warnings
    from pathlib import Path

    from seaecho.config import load_scene

    path = Path(__file__).resolve().parents[1] / "scenes" / f"{name}.toml"
    sc = load_scene(path)
    sc = sc.model_copy(update={"objects": (), "sea": sc.sea.model_copy(update={"nx": 48})})
    held = sc.model_copy(update={"scattering": sc.scattering.model_copy(
        update={"sea_motion": "held"})})
    assert sc.scattering.sea_motion == "auto"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the coarse grid's sampling warnings
        a, b = Simulation(sc, base_dir=path.parent), Simulation(held, base_dir=path.parent)
        assert not a.evolving
        for p in (0, 7):
            assert a.pulse(p).tobytes() == b.pulse(p).tobytes()
