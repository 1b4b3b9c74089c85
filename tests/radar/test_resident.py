"""The fused, device-resident sea pulse against the reference path, and its selection.

``Simulation.sea_echo`` evaluates a ray-traced sea pulse as one kernel
(``seaecho.radar.resident``) or, in its reference path, stage by stage with numpy in
between. Both call the same formulas with the same values: the parity tests ask for the
same bytes (a dropped visibility factor, a facet order changed by the compaction, a
wrong window bound or speckle draw would each change them). The GPU path cannot run
here: its plumbing (device echo, cufinufft calls on array pointers) is exercised on the
CPU back end with a stand-in for cufinufft that reads the same pointers.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import copy
import ctypes
import sys
import types
import warnings
from pathlib import Path

import numpy as np
import pytest

from seaecho import backend
from seaecho.config import load_scene
from seaecho.radar.resident import ResidentSea
from seaecho.simulation import Simulation

SIM2 = Path(__file__).resolve().parents[2] / "scenes" / "paper_sim2_sar_128m_wind55.toml"

pytestmark = pytest.mark.skipif(not backend.drjit_available(),
                                reason="Dr.Jit LLVM backend unavailable")


def _scene(nx=64, pulses=6, refresh=0.1, tracing=None, radar=None, scattering=None):
    scene = load_scene(SIM2)
    # the fused kernel computes the held sea: explicit, as "auto" would evolve a sea
    # renewed within the run (sea_update_pulses < pulses)
    # the boat's echo, the same in both paths, traced with one ray per wavelength (four
    # made its trace most of the test's time)
    boat = scene.objects[0].model_copy(update={"rays_per_wavelength": 1.0})
    return scene.model_copy(update={
        "objects": (boat, *scene.objects[1:]),
        "scattering": scene.scattering.model_copy(
            update={"sea_motion": "held", **(scattering or {})}),
        "sea": scene.sea.model_copy(update={"nx": nx}),
        "tracing": scene.tracing.model_copy(update={"refresh_interval_s": refresh,
                                                    **(tracing or {})}),
        "radar": scene.radar.model_copy(update={"n_pulses": pulses, **(radar or {})})})


def _held(scene):
    """The scene with an explicitly held sea: Simulation 1 renews its sea every pulse, so
    its default ("auto") evolves, which the fused kernel does not compute."""
    return scene.model_copy(update={"scattering": scene.scattering.model_copy(
        update={"sea_motion": "held"})})


def _pair(scene):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fused = Simulation(scene, base_dir=SIM2.parent)
        ref = Simulation(scene, base_dir=SIM2.parent)
    ref._resident = None  # the reference path: one kernel per stage, numpy between
    assert isinstance(fused._resident, ResidentSea)
    return fused, ref


@pytest.mark.parametrize("refresh", [pytest.param(0.1, marks=pytest.mark.slow), 0.0])
def test_fused_sea_pulse_equals_the_reference_path_bit_for_bit(refresh):
    # Simulation 2's geometry on a 64 x 64 sea with the boat's shadow: some facets are
    # hidden, so the kernel's compaction runs; refresh 0 re-traces every pulse.
    fused, ref = _pair(_scene(refresh=refresh))
    for p in (0, 3, 5):
        a, b = fused.sea_echo(p).echo, ref.sea_echo(p).echo
        n_facets = 2 * 63 * 63
        assert 0 < b.tau.size < n_facets  # hidden facets were left out
        np.testing.assert_array_equal(a.tau, b.tau)
        np.testing.assert_array_equal(np.stack(a.amplitudes), b.amplitudes)
        assert fused.pulse(p).tobytes() == ref.pulse(p).tobytes()


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_bistatic_fused_pulse_equals_the_reference_path():
    # Simulation 1: transmitter and receiver apart (two ranges, two occlusion masks)
    sim1 = SIM2.parent / "paper_sim1_bistatic_64m.toml"
    scene = _held(load_scene(sim1))
    scene = scene.model_copy(update={"sea": scene.sea.model_copy(update={"nx": 64})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fused, ref = (Simulation(scene, base_dir=sim1.parent) for _ in range(2))
    ref._resident = None
    assert isinstance(fused._resident, ResidentSea)
    a, b = fused.sea_echo(1).echo, ref.sea_echo(1).echo
    np.testing.assert_array_equal(a.tau, b.tau)
    np.testing.assert_array_equal(np.stack(a.amplitudes), b.amplitudes)
    assert fused.pulse(1).tobytes() == ref.pulse(1).tobytes()


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_fused_window_cut_equals_the_reference_path():
    # A receive window over part of the tile: echoes outside it are dropped in the
    # kernel (ReceiveWindow.bounds) exactly as receive() drops them.
    fused, ref = _pair(_scene(radar={"window_start_m": 4300.0, "window_end_m": 4310.0}))
    a, b = fused.sea_echo(2).echo, ref.sea_echo(2).echo
    keep = ref.radar.window.keep(b.tau, ref.radar.waveform.n_samples)
    assert 0 < keep.sum() < keep.size
    np.testing.assert_array_equal(a.tau, b.tau[keep])
    np.testing.assert_array_equal(np.stack(a.amplitudes), b.amplitudes[:, keep])
    assert fused.pulse(2).tobytes() == ref.pulse(2).tobytes()


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_new_sea_every_pulse_equals_the_reference_path():
    # A new surface per pulse: the kernel's node copies follow the surface state
    fused, ref = _pair(_scene(radar={"sea_update_pulses": 1}))
    for p in (1, 2):
        assert fused.pulse(p).tobytes() == ref.pulse(p).tobytes()


@pytest.mark.parametrize("scattering", [{"model": "blend+breaking", "unresolved_tilt": True},
                                        {"model": "blend", "unresolved_tilt": False}])
@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_fused_mechanisms_equal_the_reference_path(scattering):
    # The paper's scenes (the tests above) are "blend" with the Bragg term averaged over
    # the unresolved tilts (eq P6); with the breaking zones too (eq P7, the default
    # model) and with neither, the fused pulse is still the reference path's: a tilt
    # node or the breaking fraction dropped, or a draw given to the wrong mechanism,
    # would change the bytes
    fused, ref = _pair(_scene(scattering=scattering))
    names = set(fused._block_quantities(0, fused.surface_state(0),
                                        fused._resident.n_facets(fused.surface_state(0)))
                ["draws"])
    assert ("breaking" in names) == (scattering["model"] == "blend+breaking")
    assert ("bragg4" in names) == scattering["unresolved_tilt"]
    for p in (0, 4):
        assert fused.pulse(p).tobytes() == ref.pulse(p).tobytes()


def test_fused_path_refuses_missing_draws():
    fused, _ = _pair(_scene(scattering={"model": "blend+breaking"}))
    st = fused.surface_state(0)
    held = fused._block_quantities(0, st, fused._resident.n_facets(st))
    geo = fused.radar.geometry(0)
    _, *hidden = fused.engine.occlusion(geo.time, st)
    draws = {m: g for m, g in held["draws"].items() if m != "breaking"}
    with pytest.raises(ValueError, match="breaking"):
        fused._resident.echo(geo, st, hidden, draws, held["damping"],
                             breaking=held["breaking"])


@pytest.mark.parametrize("update, model", [
    (3, "blend+breaking"), pytest.param(1, "blend", marks=pytest.mark.slow),
    pytest.param(1, "blend+breaking", marks=pytest.mark.slow)])
def test_fused_evolving_pulse_equals_the_reference_path_bit_for_bit(update, model):
    # sea_motion = "evolving" (docs/dynamics.md): the kernel evaluates the speckle of the
    # pulse's time (eqs D2-D4, EvolvingSpeckle.draws) and carries the phase centres from
    # the surface's time (eq D1: r + D + v dt + a dt^2 / 2 from the nodes' displacement
    # and acceleration) with the reference path's functions, so the same bytes. Pulses
    # 1 and 5 are 1 and 2 ms after their surface (acceleration used) with update 3;
    # breaking zones placed on the block's downward acceleration (with update 1 its
    # vertical component alone, Simulation._kinematics).
    fused, ref = _pair(_scene(scattering={"sea_motion": "evolving", "model": model},
                              radar={"sea_update_pulses": update}))
    assert fused.evolving and ref.evolving
    for p in (1, 5):
        a, b = fused.sea_echo(p).echo, ref.sea_echo(p).echo
        np.testing.assert_array_equal(a.tau, b.tau)
        np.testing.assert_array_equal(np.stack(a.amplitudes), b.amplitudes)
    # the reference's quantities are there for a sigma pulse of the fused simulation
    assert fused.sea_echo(4, sigma=True).echo.tau.size == b.tau.size


def test_fused_path_is_chosen_for_ray_traced_scenes_only():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        analytic = Simulation(_scene(tracing={"mode": "analytic"}), base_dir=SIM2.parent)
        smith = Simulation(_scene(tracing={"subfacet_shadowing": True}), base_dir=SIM2.parent)
    # Smith's statistical visibility and the sub-facet shadowing are numpy functions of
    # the geometry stage: those scenes keep the reference path
    assert analytic._resident is None and smith._resident is None


def test_cuda_variant_without_gpu_is_a_clear_error_at_start(monkeypatch):
    # The scene asks for the GPU and there is none: the simulation refuses to start
    # (ValueError naming the variant), before any pulse is computed.
    monkeypatch.setattr(backend, "cuda_available", lambda: False)
    scene = _scene(tracing={"variant": "cuda_ad_mono_polarized"})
    with pytest.raises(ValueError, match="cuda_ad_mono_polarized.*no CUDA GPU"), \
            warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the small grid's SPM validity warning
        Simulation(scene, base_dir=SIM2.parent)


def test_variant_other_than_mitsubas_is_a_clear_error_at_start(monkeypatch):
    # Mitsuba already runs the CUDA variant in this process (pretended): an LLVM scene
    # cannot share it, and says so at construction.
    monkeypatch.setattr(backend, "cuda_available", lambda: True)
    monkeypatch.setitem(sys.modules, "mitsuba",
                        types.SimpleNamespace(variant=lambda: "cuda_ad_mono_polarized"))
    with pytest.raises(ValueError, match="Mitsuba already runs"), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        Simulation(_scene(), base_dir=SIM2.parent)


# ------------------------------------------------------------------ the GPU plumbing
def _host_view(view) -> np.ndarray:
    """The memory behind a __cuda_array_interface__ (here host memory: the LLVM back end)."""
    iface = view.__cuda_array_interface__
    dtype = np.dtype(iface["typestr"])
    n = int(np.prod(iface["shape"]))
    raw = (ctypes.c_char * (n * dtype.itemsize)).from_address(iface["data"][0])
    return np.frombuffer(raw, dtype=dtype).reshape(iface["shape"])


class _FakePlan:
    """cufinufft.Plan's interface, computed by finufft on the memory the pointers name."""

    made = 0

    def __init__(self, nufft_type, n_modes, n_trans=1, eps=1e-6, isign=None,
                 dtype="complex64", **kwargs):
        assert nufft_type == 1 and dtype == "complex128" and kwargs == {"modeord": 1}
        self.n, self.n_trans, self.eps, self.isign = n_modes[0], n_trans, eps, isign
        _FakePlan.made += 1

    def setpts(self, x):
        assert x.dtype == np.float64 and x.flags.c_contiguous
        self.x = _host_view(x).copy()

    def execute(self, data, out=None):
        import finufft

        shape = (self.n,) if self.n_trans == 1 else (self.n_trans, self.n)
        assert out is not None and out.shape == shape and data.dtype == np.complex128
        assert data.shape == ((self.x.size,) if self.n_trans == 1
                              else (self.n_trans, self.x.size))
        _host_view(out)[...] = finufft.nufft1d1(self.x, _host_view(data).copy(),
                                                n_modes=self.n, eps=self.eps,
                                                isign=self.isign, modeord=1)
        return out


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_device_echo_goes_through_cufinufft_on_array_pointers(monkeypatch):
    # The CUDA branch of the fused pulse (a DeviceEcho, accumulated by accumulate_cuda
    # through __cuda_array_interface__) run on the CPU back end: the stand-in cufinufft
    # reads the arrays at the addresses the views give. The samples must equal the
    # host path's to the NUFFT tolerance (the phasor points are folded on the device).
    from seaecho.radar import echo as echo_mod
    from seaecho.radar.system import DeviceEcho

    monkeypatch.setitem(sys.modules, "cufinufft", types.SimpleNamespace(Plan=_FakePlan))
    monkeypatch.setattr(backend, "cuda_synchronize", lambda: None)
    monkeypatch.setattr(echo_mod, "_CUDA_PLANS", {})
    monkeypatch.setattr(_FakePlan, "made", 0)  # plans made by other tests' stand-ins
    fused, ref = _pair(_scene())
    gpu_like = copy.copy(fused._resident.xp)
    gpu_like.name = "cuda"  # the same Dr.Jit arrays, the GPU's code path
    fused._resident.xp = gpu_like
    e = fused.sea_echo(3).echo
    assert isinstance(e, DeviceEcho) and len(e.amplitudes) == 4
    host = e.to_host()
    b = ref.sea_echo(3).echo
    np.testing.assert_array_equal(host.tau, b.tau)
    np.testing.assert_array_equal(host.amplitudes, b.amplitudes)
    raw, want = fused.pulse(3), ref.pulse(3)
    assert np.abs(raw - want).max() <= 1e-9 * np.abs(want).max()
    assert _FakePlan.made == 1  # one plan, reused for every channel and pulse


@pytest.mark.parametrize("batched", [True, False])
def test_host_scatterers_of_a_gpu_pulse_take_cufinufft(monkeypatch, batched):
    # A pulse whose sea is a DeviceEcho accumulates there, through cufinufft on the same
    # plan, a host scatterer set too large for the direct sum (a hull's centres); one
    # small enough for the direct sum stays on the host. The samples are the host
    # path's to the NUFFT tolerance (stand-in cufinufft on the CPU back end), with the
    # channels in one cufinufft call (n_trans = C) or one call each.
    from seaecho.radar import echo as echo_mod
    from seaecho.radar.echo import DIRECT_TERMS, ReceiveWindow
    from seaecho.radar.system import DeviceEcho, RadarSystem, ScattererEcho

    monkeypatch.setitem(sys.modules, "cufinufft", types.SimpleNamespace(Plan=_FakePlan))
    monkeypatch.setattr(backend, "cuda_synchronize", lambda: None)
    monkeypatch.setattr(echo_mod, "_CUDA_PLANS", {})
    monkeypatch.setattr(echo_mod, "CUDA_BATCH_CHANNELS", batched)  # one call or C calls
    calls = []
    monkeypatch.setattr(_FakePlan, "setpts", lambda self, x: (
        calls.append(x.shape[0]), setattr(self, "x", _host_view(x).copy())))
    n, rng = 64, np.random.default_rng(5)
    window = ReceiveWindow(t0=1e-5, n_samples=48, sampling_rate=1e7)
    radar = types.SimpleNamespace(
        channels=("HH", "VV"), window=window, waveform=types.SimpleNamespace(n_samples=8),
        _spectrum=np.fft.fft(np.hanning(n)), model=types.SimpleNamespace(
            accumulation_precision="double", transmit_phase="coherent",
            thermal_noise=False))

    def echo(k):
        tau = window.t0 + rng.uniform(0.0, 40.0, k) / window.sampling_rate
        amp = rng.normal(size=(2, k)) + 1j * rng.normal(size=(2, k))
        return ScattererEcho(tau, amp, None, None, None, None, None, None)

    xp = copy.copy(backend.drjit_namespace())
    xp.name = "cuda"  # the GPU's code path on the CPU back end's arrays
    sea, hull, buoy = echo(3000), echo(DIRECT_TERMS // n + 10), echo(3)
    dev = DeviceEcho.upload(xp, sea.tau, sea.amplitudes)
    got = RadarSystem.receive(radar, 0, [dev, hull, buoy])
    want = RadarSystem.receive(radar, 0, [sea, hull, buoy])
    # one transform for the sea and the hull; the buoy's three scatterers: the direct sum
    assert calls == [3000 + hull.tau.size]
    assert np.abs(got - want).max() <= 1e-9 * np.abs(want).max()


def _cuda_pulse(variant: str, path: str) -> None:
    """One fused sea pulse of the small Simulation 2 on ``variant`` (in its own process).

    The boat casts its shadow but returns no echo here: its hull signature comes from
    shooting and bouncing rays, whose float32 intersections on OptiX's and Embree's
    BVHs differ in the last bits, which moves the signature by about 1e-3 of the pulse's
    peak (measured on an H100: the whole pulse 2e-3, the sea alone 4e-10, identical
    occlusion masks). The sea's kernels are compared here.
    """
    scene = _scene(tracing={"variant": variant})
    scene = scene.model_copy(update={"objects": tuple(
        o.model_copy(update={"scatterer": False}) for o in scene.objects)})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(scene, base_dir=SIM2.parent)
    np.save(path, sim.pulse(3))


@pytest.mark.gpu
@pytest.mark.skipif(not backend.cuda_available(), reason="needs a CUDA GPU")
def test_cuda_fused_pulse_equals_the_cpu_one(tmp_path):
    # On a GPU machine: the whole pulse on drjit.cuda + cufinufft against the LLVM one
    # (each in a process of its own: one Mitsuba variant per process). cufinufft sums
    # with atomics, so the comparison is at the NUFFT tolerance, not bit for bit, with
    # the scattering formulas in float64. In float32 (the default) the two back ends
    # round differently (their float32 sin/cos/sqrt and fused multiply-adds): measured on
    # an H100, 3.9e-6 of the peak, inside the 2e-6 of each kernel from the float64 one
    # (docs/scattering.md, "Working precision") taken twice.
    import os
    import subprocess

    for precision, bound in (("double", 1e-8), ("single", 1e-5)):
        out = {}
        env = dict(os.environ, SEAECHO_SCATTERING_PRECISION=precision)
        for v in ("llvm_ad_mono_polarized", "cuda_ad_mono_polarized"):
            out[v] = tmp_path / f"{v}_{precision}.npy"
            res = subprocess.run([sys.executable, "-c", "import test_resident; "
                                  f"test_resident._cuda_pulse({v!r}, {str(out[v])!r})"],
                                 cwd=str(Path(__file__).parent), capture_output=True,
                                 text=True, env=env)
            assert res.returncode == 0, res.stderr[-3000:]
        a, b = (np.load(p) for p in out.values())
        assert np.abs(a - b).max() <= bound * np.abs(a).max(), precision


def _cuda_frozen_pulses(path: str) -> None:
    """Three sea echoes of the small Simulation 2 on the CUDA variant, traced and frozen
    (in its own process: one Mitsuba variant per process)."""
    scene = _scene(tracing={"variant": "cuda_ad_mono_polarized"})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sims = [Simulation(scene, base_dir=SIM2.parent) for _ in range(2)]
    sims[0]._resident.freeze, sims[1]._resident.freeze = False, True
    out = []
    for sim in sims:
        for p in (0, 2, 5):
            e = sim.sea_echo(p).echo.to_host()
            out += [e.tau, np.stack(e.amplitudes).view(np.float64).ravel()]
    out.append(np.array([sims[1]._resident._frozen.n_recordings], dtype=np.float64))
    np.save(path, np.concatenate(out))


@pytest.mark.gpu
@pytest.mark.skipif(not backend.cuda_available(), reason="needs a CUDA GPU")
def test_cuda_frozen_pulse_equals_the_traced_one(tmp_path):
    # The frozen kernel replayed on drjit.cuda: the traced kernel's bytes, one recording
    import subprocess

    path = tmp_path / "frozen.npy"
    res = subprocess.run([sys.executable, "-c", "import test_resident; "
                          f"test_resident._cuda_frozen_pulses({str(path)!r})"],
                         cwd=str(Path(__file__).parent), capture_output=True, text=True)
    assert res.returncode == 0, res.stderr[-3000:]
    a = np.load(path)
    traced, frozen = a[:-1][: (a.size - 1) // 2], a[:-1][(a.size - 1) // 2:]
    assert traced.tobytes() == frozen.tobytes() and a[-1] == 1.0


def test_sigma_map_in_one_kernel_equals_the_reference():
    # The dataset's NRCS map (Simulation.sea_truth) from the fused kernel: the same
    # per-cell sigma0 and visibility as the reference path's SeaEcho.sigma0_cells. Both
    # start from the same float32 mechanism matrices (facet.PRECISION); the kernel sums
    # eq P3 in float32, numpy in float64 (a few float32 ulps: 2e-7 measured), in float64
    # kernels to an ulp (Dr.Jit fuses the multiply-adds of |M|^2; numpy does not).
    p = 2
    fused, ref = _pair(_scene(radar={"sigma_map_pulse": p}))
    se = ref.sea_echo(p, sigma=True)
    dx = float(ref.sea.x[1] - ref.sea.x[0])
    want = se.sigma0_cells(dx * dx)
    st = fused.surface_state(p)
    geo = fused.radar.geometry(p)
    held = fused._block_quantities(p, st, fused._resident.n_facets(st))
    _, *hidden = fused.engine.occlusion(geo.time, st)
    sigma0, vis = fused._resident.sigma_cells(geo, st, hidden, held["damping"],
                                              breaking=held["breaking"])
    single = fused._resident.xs.precision == "single"
    np.testing.assert_allclose(sigma0, want, rtol=1e-6 if single else 1e-15, atol=0)
    np.testing.assert_array_equal(vis, se.facets.cell_mean("visibility"))
    assert vis.dtype == np.float64
    # sea_truth takes the kernel's map where the pulses use the kernel, else the reference
    assert fused.sea_truth()["sigma0"].tobytes() == sigma0.tobytes()
    truth = ref.sea_truth()
    assert truth["sigma0"].tobytes() == want.tobytes()
    np.testing.assert_array_equal(truth["visibility"], vis)
    assert np.any(vis == 0) and np.any(vis == 0.5)  # the boat's shadow, its edge


# ------------------------------------------------------------------ frozen kernel
def _frozen_pair(scene, base_dir=SIM2.parent):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plain, frozen = (Simulation(scene, base_dir=base_dir) for _ in range(2))
    plain._resident.freeze, frozen._resident.freeze = False, True
    return plain, frozen


def _same_echo(a, b):
    return (a.tau.tobytes() == b.tau.tobytes()
            and all(x.tobytes() == y.tobytes()
                    for x, y in zip(a.amplitudes, b.amplitudes, strict=True)))


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
@pytest.mark.parametrize(("refresh", "update"), [(0.0, 160), (0.1, 1)])
def test_frozen_pulse_kernel_equals_the_traced_one(refresh, update):
    # drjit.freeze replays the kernel recorded at the first pulse: the platform moves
    # (positions bound as inputs), the occlusion is re-traced at every pulse (refresh 0)
    # or the sea is new at every pulse (update 1); every pulse must be the traced
    # kernel's to the byte, with one recording (a platform vector frozen as a constant
    # would repeat the first pulse's ranges and phases)
    plain, frozen = _frozen_pair(_scene(refresh=refresh, radar={"sea_update_pulses": update}))
    for p in (0, 1, 4, 2):
        assert _same_echo(plain.sea_echo(p).echo, frozen.sea_echo(p).echo), p
    res = frozen._resident
    assert res.freeze and res.freeze_error is None and res._frozen.n_recordings == 1
    assert frozen.pulse(5).tobytes() == plain.pulse(5).tobytes()


def test_frozen_bistatic_pulse_equals_the_traced_one():
    # Simulation 1: transmitter and receiver apart (both positions, the receiver's
    # velocity and both antennas' axes bound)
    sim1 = SIM2.parent / "paper_sim1_bistatic_64m.toml"
    scene = _held(load_scene(sim1))
    scene = scene.model_copy(update={"sea": scene.sea.model_copy(update={"nx": 48})})
    plain, frozen = _frozen_pair(scene, sim1.parent)
    for p in (0, 3):
        assert _same_echo(plain.sea_echo(p).echo, frozen.sea_echo(p).echo), p
    assert frozen._resident._frozen.n_recordings == 1


def test_frozen_kernel_records_again_for_another_grid():
    # The facet count is part of the recorded kernel: a surface of another size makes a
    # second recording (not a replay at the old size), and the first size replays again.
    # One ResidentSea (the 64 x 64 sea's constants) on both surfaces, traced and frozen.
    small, big = (_frozen_pair(_scene(nx=n))[1] for n in (48, 64))
    res = big._resident

    def echo(sim, freeze):
        res.freeze = freeze
        st = sim.surface_state(1)
        held = sim._block_quantities(1, st, res.n_facets(st))
        geo = sim.radar.geometry(1)
        _, *hidden = sim.engine.occlusion(geo.time, st)
        return res.echo(geo, st, hidden, held["draws"], held["damping"])

    ref_big, ref_small = echo(big, False), echo(small, False)
    assert ref_big.tau.size != ref_small.tau.size
    assert _same_echo(echo(big, True), ref_big)
    assert res._frozen.n_recordings == 1
    assert _same_echo(echo(small, True), ref_small)
    assert res._frozen.n_recordings == 2
    assert _same_echo(echo(big, True), ref_big)
    assert res._frozen.n_recordings == 2


def test_a_platform_view_that_is_not_bound_is_refused():
    from seaecho.radar.resident import _BoundGeometry, _view_key

    xp = backend.namespace("drjit")
    rot = np.eye(3)
    bound = _BoundGeometry(xp, {_view_key(rot[:, 2]): "bound"}, (rot,))
    assert bound.vconst(np.asarray(rot)[:, 2]) == "bound"  # another view, same entries
    with pytest.raises(RuntimeError, match="frozen as a constant"):
        bound.vconst(rot[0])
    bound.vconst(np.array([0.0, 0.0, 1.0]))  # a vector of its own: a constant


@pytest.mark.slow  # a parity guard of ~10-20 s (the default set keeps the bit-for-bit pulse)
def test_float32_scattering_against_the_float64_kernel():
    # The fused kernel evaluates eqs P1-P7, the antenna gains and port states in float32
    # (ResidentSea.precision, default facet.PRECISION) and the geometry, delays, carrier
    # phase and the radar equation's magnitude in float64: against the same kernel in
    # float64, the delays are the same bytes, every amplitude is within 1e-5 of its
    # channel's largest (1.8e-6 measured at 128^2), each channel's power within 1e-4 dB
    # (6.5e-6 dB measured) and the pulse within 1e-5 of its peak. A float32 delay or
    # carrier phase (errors of 1e-7 of 4000 m at 3 cm wavelength: radians), or a
    # monostatic specular facet whose degenerate basis became a random one in float32,
    # would fail.
    scene = _scene(scattering={"model": "blend+breaking", "unresolved_tilt": True})
    single, double = _pair(scene)
    r = single._resident
    for sim, precision in ((single, "single"), (double, "double")):
        sim._resident = ResidentSea(r.radar, r.facet_model, precision=precision)
        assert sim._resident.xs.precision == precision
    for p in (0, 4):
        a, b = single.sea_echo(p).echo, double.sea_echo(p).echo
        assert a.tau.tobytes() == b.tau.tobytes()
        x, y = np.stack(a.amplitudes), np.stack(b.amplitudes)
        assert np.all(np.abs(x - y) <= 1e-5 * np.abs(y).max(axis=1, keepdims=True))
        power = [np.sum(np.abs(z) ** 2, axis=1) for z in (x, y)]
        assert np.all(np.abs(10 * np.log10(power[0] / power[1])) < 1e-4)
        s, d = single.pulse(p), double.pulse(p)
        assert np.abs(s - d).max() < 1e-5 * np.abs(d).max()
