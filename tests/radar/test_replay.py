"""The scatterers' radar equation recorded once and replayed (``seaecho.radar.replay``).

Dr.Jit's CPU back end (``drjit.llvm``) records and replays like the GPU's: the replay must
give the traced kernel's bytes, for every pulse (moving platforms, a scanning antenna),
record again when the number of scatterers or the precision changes, and refuse to
freeze a platform vector as a constant. The one-transform accumulation of a GPU pulse's
point sets is checked on the CPU back end with the stand-in cufinufft of
``test_resident``.
"""

from __future__ import annotations

import copy
import sys
import types

import numpy as np
import pytest

from seaecho import backend
from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.radar.system import RadarSystem

pytestmark = pytest.mark.skipif(not backend.drjit_available(),
                                reason="Dr.Jit LLVM backend unavailable")

RECT = {"pattern": "rectangular", "width_m": 0.3, "height_m": 0.1, "look_at_m": (0, 0, 0)}


def _radar(bistatic: bool = True, scanning: bool = False) -> RadarSystem:
    tx = {"motion": "linear", "position_m": (-200, 30, 150), "velocity_m_s": (5, 60, -1),
          "roll_deg": 7.0, "antenna": RECT}
    if scanning:
        tx["antenna"] = {"pattern": "rectangular", "width_m": 1.2, "height_m": 0.1,
                         "depression_deg": 5.0,
                         "scan": {"mode": "rotating", "rate_rpm": 24.0}}
    scene = {
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.4e9, "sampling_rate_hz": 100e6, "prf_hz": 1e3,
                  "sea_clutter": False, "channels": ["HH", "HV", "VH", "VV"],
                  "window_start_m": 100.0, "window_end_m": 600.0,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 50e6, "duration_s": 1e-6}},
        "transmitter": tx}
    if bistatic:
        scene["receiver"] = {"motion": "linear", "position_m": (120, -40, 40),
                             "velocity_m_s": (-3, 2, 0), "antenna": RECT}
    return RadarSystem(build_radar(parse_scene(scene)))


def _scatterers(k: int, seed: int = 4):
    rng = np.random.default_rng(seed)
    p = np.column_stack([rng.uniform(-40, 40, k), rng.uniform(-40, 40, k),
                         rng.uniform(-2, 2, k)])
    v = rng.normal(0, 2, (k, 3))
    s = rng.normal(size=(k, 2, 2)) + 1j * rng.normal(size=(k, 2, 2))
    return p, v, s


def _bytes(e) -> bytes:
    parts = [e.tau, e.r_t, e.r_r, e.g_t, e.g_r, np.asarray(e.amplitudes)]
    parts += [a for a in (e.n_i, e.n_s) if a is not None]
    return b"".join(np.ascontiguousarray(a).tobytes() for a in parts)


@pytest.mark.parametrize("bistatic,scanning", [(True, False), (False, True)])
def test_replayed_echo_equals_the_traced_one_byte_for_byte(bistatic, scanning):
    # Pulses 0, 3, 250 of moving platforms (and a scanning antenna: its axes change from
    # pulse to pulse): the replay of the recording made at pulse 0 gives the traced
    # kernel's bytes, with one recording for the whole run.
    traced, frozen = _radar(bistatic, scanning), _radar(bistatic, scanning)
    traced.freeze, frozen.freeze = False, True
    p, v, s = _scatterers(300)
    for pulse in (0, 3, 250):
        geo = traced.geometry(pulse)
        a = traced.scatterer_echo(geo, p, v, s, directions=True)
        b = frozen.scatterer_echo(frozen.geometry(pulse), p, v, s, directions=True)
        assert _bytes(a) == _bytes(b), pulse
    assert frozen._replay["llvm"].recordings == 1
    assert frozen._replay["llvm"].error is None
    # the replay follows the pulse: pulse 250's echo is not pulse 0's
    first = frozen.scatterer_echo(frozen.geometry(0), p, v, s)
    assert not np.array_equal(first.tau, b.tau)


def test_replay_takes_any_size_and_records_again_for_another_precision():
    # Another number of scatterers (a hull's centres above the horizon, the land facets
    # in the beam) replays the same recording: Dr.Jit's frozen functions take inputs of
    # any width (one scatterer, a width-1 input like the platform vectors, records again);
    # another working precision records again; every echo has the traced kernel's bytes.
    traced, frozen = _radar(), _radar()
    traced.freeze, frozen.freeze = False, True
    runs = [(300, "double"), (17, "double"), (1, "double"), (300, "single"),
            (4000, "double")]
    for i, (k, precision) in enumerate(runs):
        p, v, s = _scatterers(k, seed=i)
        geo = traced.geometry(i)
        a = traced.scatterer_echo(geo, p, v, s, precision=precision)
        b = frozen.scatterer_echo(frozen.geometry(i), p, v, s, precision=precision)
        assert _bytes(a) == _bytes(b), (k, precision)
    assert frozen._replay["llvm"].recordings == 3


def test_a_geometry_that_cannot_be_bound_is_traced():
    # Platform vectors that are not float64 numpy arrays cannot be inputs of the
    # recording: the echo is traced instead (the same numbers), nothing recorded.
    from dataclasses import replace

    radar = _radar()
    radar.freeze = True
    p, v, s = _scatterers(50)
    geo = radar.geometry(2)
    odd = replace(geo, tx_axes=geo.tx_axes.astype(np.float32).astype(np.float64).tolist())
    a = radar.scatterer_echo(odd, p, v, s)
    radar.freeze = False
    b = radar.scatterer_echo(odd, p, v, s)
    assert _bytes(a) == _bytes(b)
    assert radar._replay["llvm"].recordings == 0


def test_radar_with_recordings_pickles_without_them():
    import pickle

    radar = _radar()
    radar.freeze = True
    p, v, s = _scatterers(20)
    radar.scatterer_echo(radar.geometry(0), p, v, s)
    again = pickle.loads(pickle.dumps(radar))
    assert again._replay == {} and radar._replay["llvm"].recordings == 1
    assert _bytes(again.scatterer_echo(again.geometry(1), p, v, s)) == _bytes(
        radar.scatterer_echo(radar.geometry(1), p, v, s))


@pytest.mark.parametrize("batched", [True, False])
def test_a_gpu_pulses_point_sets_take_one_transform(monkeypatch, batched):
    # The sea's DeviceEcho and a hull's centres (uploaded) of one GPU pulse go through one
    # setpts and one transform (their points concatenated on the device); the samples
    # equal the host path's to the NUFFT tolerance (stand-in cufinufft, CPU back end).
    from test_resident import _FakePlan, _host_view

    from seaecho.radar import echo as echo_mod
    from seaecho.radar.echo import DIRECT_TERMS, ReceiveWindow
    from seaecho.radar.system import DeviceEcho, ScattererEcho

    monkeypatch.setitem(sys.modules, "cufinufft", types.SimpleNamespace(Plan=_FakePlan))
    syncs = []
    monkeypatch.setattr(backend, "cuda_synchronize", lambda: syncs.append(1))
    monkeypatch.setattr(echo_mod, "_CUDA_PLANS", {})
    monkeypatch.setattr(echo_mod, "CUDA_BATCH_CHANNELS", batched)
    calls = []
    monkeypatch.setattr(_FakePlan, "setpts", lambda self, x: (
        calls.append(x.shape[0]), setattr(self, "x", _host_view(x).copy())))
    n, rng = 64, np.random.default_rng(7)
    window = ReceiveWindow(t0=1e-5, n_samples=48, sampling_rate=1e7)
    radar = types.SimpleNamespace(
        channels=("HH", "HV", "VV"), window=window,
        waveform=types.SimpleNamespace(n_samples=8),
        _spectrum=np.fft.fft(np.hanning(n)), model=types.SimpleNamespace(
            accumulation_precision="double", transmit_phase="coherent",
            thermal_noise=False))

    def echo(k):
        tau = window.t0 + rng.uniform(0.0, 40.0, k) / window.sampling_rate
        amp = rng.normal(size=(3, k)) + 1j * rng.normal(size=(3, k))
        return ScattererEcho(tau, amp, None, None, None, None, None, None)

    xp = copy.copy(backend.drjit_namespace())
    xp.name = "cuda"  # the GPU's code path on the CPU back end's arrays
    sea, wake, hull = echo(3000), echo(500), echo(DIRECT_TERMS // n + 10)
    empty = echo(0)
    devs = [DeviceEcho.upload(xp, e.tau, e.amplitudes) for e in (sea, empty, wake)]
    got = RadarSystem.receive(radar, 0, [*devs, hull])
    want = RadarSystem.receive(radar, 0, [sea, wake, hull])
    assert calls == [3000 + 500 + hull.tau.size]  # one setpts for the pulse
    assert len(syncs) == 2  # one pair of synchronisations for the pulse
    assert np.abs(got - want).max() <= 1e-9 * np.abs(want).max()


@pytest.mark.slow  # 2-4 s: two simulations with a sea, land and the crests' trace
@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_a_block_of_pulses_has_the_bytes_of_its_pulses_one_by_one():
    # Simulation.pulses finds the targets hidden by the land or the crests for the rest of
    # each sea block at once: the same samples, byte for byte, as pulse by pulse
    # (targets in front of and behind a field, one in the waves; the sea renewed every
    # two pulses, so the block of four spans three sea states).
    from seaecho.simulation import Simulation

    field = {"name": "field", "outline_m": [[-50, -500], [50, -500], [50, -450],
                                            [-50, -450]], "height_m": 30.0,
             "shore_width_m": 10.0, "resolution_m": 5.0, "terrain": "farmland"}
    targets = [{"name": "sunk", "position_m": (0.0, 0.0, -1.0), "rcs_m2": 1.0},
               {"name": "behind", "position_m": (0.0, -300.0, 2.0), "rcs_m2": 10.0},
               {"name": "front", "position_m": (300.0, -550.0, 2.0), "rcs_m2": 10.0}]
    scene = parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 16},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 5, "sea_update_pulses": 2,
                  "sea_clutter": True,
                  "transmit_power_w": 25e3, "channels": ["HH"], "thermal_noise": False,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, -600.0, 20.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "targets": targets, "land": [field]})
    block, single = Simulation(scene), Simulation(scene)
    raw, _ = block.pulses(1, 5)
    hidden = block._hidden_ahead[2]  # the last block: land, then crests
    assert hidden[0, :, 1].all() and hidden[1, :, 0].all() and not hidden[:, :, 2].any()
    want = np.stack([single.pulse(p) for p in range(1, 5)])
    assert raw.tobytes() == want.tobytes()


def _cuda_replays(path: str) -> None:
    """Echoes of the scatterers at three pulses on ``drjit.cuda``, traced and replayed,
    and the number of recordings (in its own process: one Mitsuba variant each)."""
    out = []
    radars = [_radar(), _radar()]
    radars[0].freeze, radars[1].freeze = False, True
    for radar in radars:
        for pulse, k in ((0, 300), (3, 2000), (250, 300)):
            p, v, s = _scatterers(k, seed=pulse)
            e = radar.scatterer_echo(radar.geometry(pulse), p, v, s, directions=True,
                                     variant="cuda_ad_mono_polarized")
            out.append(np.frombuffer(_bytes(e), dtype=np.float64))
    out.append(np.array([radars[1]._replay["cuda"].recordings], dtype=np.float64))
    np.save(path, np.concatenate(out))


@pytest.mark.gpu
@pytest.mark.skipif(not backend.cuda_available(), reason="needs a CUDA GPU")
def test_cuda_replayed_echo_equals_the_traced_one(tmp_path):
    # The radar equation replayed on drjit.cuda: the traced kernel's bytes, one recording
    import subprocess
    from pathlib import Path

    path = tmp_path / "replay.npy"
    res = subprocess.run([sys.executable, "-c", "import test_replay; "
                          f"test_replay._cuda_replays({str(path)!r})"],
                         cwd=str(Path(__file__).parent), capture_output=True, text=True)
    assert res.returncode == 0, res.stderr[-3000:]
    a = np.load(path)
    traced, frozen = a[:-1][: (a.size - 1) // 2], a[:-1][(a.size - 1) // 2:]
    assert traced.tobytes() == frozen.tobytes() and a[-1] == 1.0


def test_a_pulse_geometry_is_computed_once():
    # RadarSystem.geometry keeps the last pulses' geometries: the same object for the same
    # pulse (a pulse asks for it two to three times), the bytes of a fresh computation,
    # and a bounded number kept.
    from seaecho.radar.system import GEOMETRIES_KEPT

    radar, fresh = _radar(scanning=True), _radar(scanning=True)
    g = radar.geometry(7)
    assert radar.geometry(7) is g and radar.geometry(8) is not g
    for pulse in range(3 * GEOMETRIES_KEPT):
        radar.geometry(pulse)
    assert len(radar._geometries) <= GEOMETRIES_KEPT
    again, want = radar.geometry(7), fresh.geometry(7)
    for a, b in ((again.tx_axes, want.tx_axes), (again.rx.position, want.rx.position),
                 (again.tx.rotation, want.tx.rotation), (g.tx_axes, want.tx_axes)):
        assert a.tobytes() == b.tobytes()
    assert again.time == want.time


def test_read_only_amplitudes_are_uploaded_once(monkeypatch):
    # A hull's scattering amplitudes, held (read-only) between two traces, are converted
    # to Dr.Jit once while they live: the next pulses convert only the positions and
    # velocities, and every echo keeps the traced kernel's bytes.
    import gc

    from seaecho.radar import replay

    converted = []
    convert = backend._convert
    monkeypatch.setattr(backend, "_convert", lambda xp, a, kind, keep: (
        converted.append(kind), convert(xp, a, kind, keep))[1])
    traced, frozen = _radar(), _radar()
    traced.freeze, frozen.freeze = False, True
    p, v, s = _scatterers(200)
    s.flags.writeable = False
    for pulse in (0, 5, 9):
        converted.clear()
        a = traced.scatterer_echo(traced.geometry(pulse), p + pulse, v, s)
        converted.clear()
        b = frozen.scatterer_echo(frozen.geometry(pulse), p + pulse, v, s)
        assert _bytes(a) == _bytes(b), pulse
        # positions, velocities, the packed platform vectors (+ the four components once)
        assert converted.count("complex") == (4 if pulse == 0 else 0), converted
    assert ("llvm", id(s)) in replay._AMPLITUDES
    key = ("llvm", id(s))
    del s
    gc.collect()
    assert key not in replay._AMPLITUDES


def test_a_hull_echo_kept_on_the_device_sums_to_the_host_one(monkeypatch):
    # RadarSystem.scatterer_echo(on_device=True) of a set large enough for the NUFFT
    # returns the replay's arrays as a DeviceEcho (the GPU's branch, on the CPU back end
    # with the stand-in cufinufft): the same delays, byte for byte, the same amplitudes
    # inside the receive window and zero outside it (scatterers 3 km away), and the
    # pulse's samples equal the host echo's to the NUFFT tolerance (eps 1e-9).
    from test_resident import _FakePlan

    from seaecho.radar import echo as echo_mod
    from seaecho.radar.echo import DIRECT_TERMS
    from seaecho.radar.system import DeviceEcho, ScattererEcho

    monkeypatch.setitem(sys.modules, "cufinufft", types.SimpleNamespace(Plan=_FakePlan))
    monkeypatch.setattr(backend, "cuda_synchronize", lambda: None)
    monkeypatch.setattr(echo_mod, "_CUDA_PLANS", {})
    device, host = _radar(), _radar()
    device.freeze, host.freeze = True, True
    device.device_echoes = True
    k = DIRECT_TERMS // device._spectrum.size + 60
    p, v, s = _scatterers(k)
    p[:40, 0] += 3000.0  # beyond the window's end
    geo = device.geometry(3)
    e = device.scatterer_echo(geo, p, v, s, on_device=True)
    h = host.scatterer_echo(host.geometry(3), p, v, s, on_device=True)  # host: default
    assert isinstance(e, DeviceEcho) and isinstance(h, ScattererEcho)
    back = e.to_host()
    keep = device.window.keep(h.tau, device.waveform.n_samples)
    assert keep.sum() == k - 40
    assert back.tau.tobytes() == h.tau.tobytes()
    assert back.amplitudes[:, keep].tobytes() == h.amplitudes[:, keep].tobytes()
    assert not back.amplitudes[:, ~keep].any()
    got = device.receive(3, [e], noise=False)
    want = host.receive(3, [h], noise=False)
    assert np.abs(got - want).max() <= 1e-9 * np.abs(want).max()
    # a set small enough for the direct sum, or asked with its directions, stays on the host
    assert isinstance(device.scatterer_echo(geo, p[:5], v[:5], s[:5], on_device=True),
                      ScattererEcho)
    assert isinstance(device.scatterer_echo(geo, p, v, s, directions=True, on_device=True),
                      ScattererEcho)


@pytest.mark.slow  # ~5 s: two simulations with a sea, land and a target
@pytest.mark.filterwarnings("ignore::seaecho.scattering.validity.SPMValidityWarning")
def test_a_pulse_with_its_land_on_the_device_equals_the_host_one(monkeypatch):
    # The GPU's branch of a whole pulse on the CPU back end (stand-in cufinufft): the
    # land's echo kept on the device (RadarSystem.device_echoes, every set sent to the
    # NUFFT: DIRECT_TERMS 0) and summed in one transform with the sea's and the target's,
    # against the host pulse, to the NUFFT tolerance (eps 1e-9).
    from test_resident import _FakePlan

    from seaecho.radar import echo as echo_mod
    from seaecho.radar import system as system_mod
    from seaecho.radar.system import DeviceEcho
    from seaecho.simulation import Simulation

    monkeypatch.setitem(sys.modules, "cufinufft", types.SimpleNamespace(Plan=_FakePlan))
    monkeypatch.setattr(backend, "cuda_synchronize", lambda: None)
    monkeypatch.setattr(echo_mod, "_CUDA_PLANS", {})
    monkeypatch.setattr(system_mod, "DIRECT_TERMS", 0)
    field = {"name": "field", "outline_m": [[-50, -500], [50, -500], [50, -450],
                                            [-50, -450]], "height_m": 30.0,
             "shore_width_m": 10.0, "resolution_m": 5.0, "terrain": "farmland"}
    scene = parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 16},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 3, "sea_clutter": True,
                  "transmit_power_w": 25e3, "channels": ["HH"], "thermal_noise": False,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, -600.0, 20.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "targets": [{"name": "front", "position_m": (300.0, -550.0, 2.0),
                     "rcs_m2": 10.0}],
        "land": [field]})
    device, host = Simulation(scene), Simulation(scene)
    device.radar.device_echoes = True
    geo = device.radar.geometry(1)
    assert isinstance(device.land.echo(geo, variant=device.variant), DeviceEcho)
    got, want = device.pulse(1), host.pulse(1)
    assert np.abs(got - want).max() <= 1e-9 * np.abs(want).max()


def test_a_kept_geometry_follows_a_platform_assigned_later():
    # The kept geometries are keyed on the ids of the platforms and pointings: an entry
    # holds those objects (a platform assigned later cannot take a freed one's id and be
    # served its geometry), and a platform assigned in place of another gives its own.
    import weakref

    from seaecho.radar.platforms import Platform

    radar = _radar()
    first = radar.geometry(0)
    old = weakref.ref(radar.tx)
    for shift in (10.0, 20.0, 30.0):  # each new platform replaces (and frees) the last
        radar.tx = Platform(np.array([0.0]), np.array([[shift, 0.0, 100.0]]))
        radar.model = None  # (the model's reference too: freed when replaced)
        geo = radar.geometry(0)
        assert geo.tx.position.tolist() == [shift, 0.0, 100.0]
        assert radar.geometry(0) is geo
    assert first.tx.position.tolist() != [10.0, 0.0, 100.0]
    assert old() is not None  # held by its kept entry while it is kept


def test_each_pulse_of_a_block_reads_its_own_hidden_targets(monkeypatch):
    # Simulation.pulses computes the targets hidden for the rest of a sea block at once;
    # each pulse must read its own column (a target that goes behind the land or a crest
    # within the block). targets_hidden is replaced by a pattern that changes every
    # pulse, and the flags each pulse hands to target_echo are recorded.
    from seaecho.simulation import Simulation

    targets = [{"name": f"t{i}", "position_m": (20.0 * i, 0.0, 2.0), "rcs_m2": 1.0}
               for i in range(3)]
    scene = parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 16.0, "nx": 16},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 6, "sea_update_pulses": 4,
                  "sea_clutter": False, "channels": ["HH"], "thermal_noise": False,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, -600.0, 20.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "targets": targets})
    sim = Simulation(scene)

    def pattern(pulses):  # (2, P, T): target p % 3 behind the land at pulse p
        p = np.atleast_1d(np.asarray(pulses))
        out = np.zeros((2, p.size, 3), dtype=bool)
        out[0, np.arange(p.size), p % 3] = True
        return out

    seen = {}
    echo = sim.radar.target_echo

    def recorded(geo, **kw):
        seen[round(geo.time * 1000.0)] = kw["hidden"].tolist()
        return echo(geo, **kw)

    monkeypatch.setattr(sim, "targets_hidden", pattern)
    monkeypatch.setattr(sim.radar, "target_echo", recorded)
    sim.pulses(1, 6)
    assert seen == {p: [i == p % 3 for i in range(3)] for p in range(1, 6)}


def test_no_garbage_collection_while_recording_or_replaying(monkeypatch):
    # A collection inside a recording freed other Dr.Jit arrays there and aborted the
    # process (a radar-wide sea's tiles): the recording and every replay run with the
    # cyclic collector held off, and it is back on afterwards.
    import gc

    from seaecho.radar import replay

    seen = []
    terms = replay.echo_terms

    def spy(*args, **kwargs):
        seen.append(gc.isenabled())
        return terms(*args, **kwargs)

    monkeypatch.setattr(replay, "echo_terms", spy)
    radar = _radar()
    radar.freeze = True
    for i in range(2):
        p, v, s = _scatterers(50, seed=i)
        radar.scatterer_echo(radar.geometry(i), p, v, s)
    assert seen and not any(seen)  # the body ran (recorded) with the collector off
    assert gc.isenabled()
    gc.disable()
    with replay.no_garbage_collection():
        pass
    assert not gc.isenabled()  # a collector that was off stays off
    gc.enable()
