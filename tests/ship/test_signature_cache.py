"""The on-disk cache of hull signatures: hits are the trace's bytes, any changed input
misses, writes are atomic under concurrent writers, a bad entry is a miss.

These are software properties (no physics): parity of a cached and a traced signature,
and the key's sensitivity to each input of ``trace_signature``.
"""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import seaecho.targets.cache as cache_mod
import seaecho.tracing.hull_echo as hull_echo
from seaecho.cli import main
from seaecho.config import load_scene
from seaecho.simulation import Simulation
from seaecho.targets import canonical
from seaecho.targets.cache import CACHE_DIR_ENV, CACHE_ENV, ArrayCache, cache_directory
from seaecho.tracing.sbr import (
    SBROptions,
    SeaPlane,
    TraceMesh,
    signature_arrays,
    signature_from_arrays,
    signature_key,
    trace_signature,
)

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
F = 10.0e9


def _args():
    v, f = canonical.rectangular_plate(0.2, 0.1)
    hull = TraceMesh.single(v + np.array([1.0, 2.0, 3.0]), f)
    x = np.linspace(-5.0, 7.0, 7)
    y = np.linspace(-4.0, 8.0, 6)
    z = 0.01 * np.arange(42.0).reshape(6, 7)
    sea = SeaPlane(level=0.0, eps_r=60.0 - 35.0j, sigma_h=0.05, patch=(x, y, z))
    occ = TraceMesh.single(v + np.array([4.0, 2.0, 3.0]), f, eps_r=3.0 - 0.1j)
    kw = {"options": SBROptions(rays_per_wavelength=2.0), "sea": sea, "occluders": [occ],
          "reference": np.array([1.0, 2.0, 3.0]), "time": 0.5,
          "velocity": np.array([1.0, 0.5, 0.0]), "variant": None}
    return [hull, np.array([-300.0, 0.0, 40.0]), np.array([-300.0, 10.0, 40.0]), F], kw


def _ulp(a, i=0):
    a = np.array(a, dtype=float, copy=True)
    a.flat[i] = np.nextafter(a.flat[i], np.inf)
    return a


def _changes():
    """(name, function (args, kw) -> (args, kw) changing one input)."""
    def arg(i, fn):
        def change(args, kw):
            args = list(args)
            args[i] = fn(args[i])
            return args, kw
        return change

    def opt(name, fn):
        def change(args, kw):
            return args, {**kw, name: fn(kw[name])}
        return change

    def mesh(field, fn):
        return lambda m: dataclasses.replace(m, **{field: fn(getattr(m, field))})

    def sea(field, fn):
        return opt("sea", lambda s: dataclasses.replace(s, **{field: fn(getattr(s, field))}))

    out = [
        ("hull vertex by one ulp", arg(0, mesh("vertices", _ulp))),
        ("hull faces reordered", arg(0, mesh("faces", lambda f: f[::-1].copy()))),
        ("hull material", arg(0, mesh("eps_r", lambda e: np.full_like(e, 4.0 + 0j)))),
        ("transmitter", arg(1, _ulp)),
        ("receiver", arg(2, lambda r: _ulp(r, 2))),
        ("frequency", arg(3, lambda f: np.nextafter(f, np.inf))),
        ("sea plane level", sea("level", lambda v: 0.01)),
        ("sea permittivity", sea("eps_r", lambda e: e + 1.0)),
        ("no sea multipath", sea("eps_r", lambda e: None)),
        ("sea roughness", sea("sigma_h", lambda v: v * 2)),
        ("roughness model", sea("roughness", lambda v: "ament")),
        ("sea patch height", sea("patch", lambda p: (p[0], p[1], _ulp(p[2], 5)))),
        ("no sea patch", sea("patch", lambda p: None)),
        ("no sea", opt("sea", lambda s: None)),
        ("occluder vertex", opt("occluders", lambda o: [dataclasses.replace(
            o[0], vertices=_ulp(o[0].vertices, 4))])),
        ("no occluder", opt("occluders", lambda o: [])),
        ("reference", opt("reference", lambda r: _ulp(r, 1))),
        ("time", opt("time", lambda t: t + 1e-9)),
        ("velocity", opt("velocity", lambda v: _ulp(v, 2))),
        ("variant", opt("variant", lambda v: "cuda_ad_mono_polarized")),
    ]
    base = SBROptions(rays_per_wavelength=2.0)
    for field, new in (("rays_per_wavelength", 2.5), ("max_bounces", 2), ("cell", 0.2),
                       ("batch", 4096), ("prune", 0.01), ("edge_refine", 2),
                       ("reciprocal", False)):
        assert getattr(base, field) != new
        out.append((f"option {field}", opt(
            "options", lambda o, f=field, n=new: dataclasses.replace(o, **{f: n}))))
    return out


def test_same_inputs_same_key():
    args, kw = _args()
    again, kw2 = _args()  # new objects, same values
    assert signature_key(*args, **kw) == signature_key(*again, **kw2)
    # the default variant spelt out is the default
    from seaecho.backend import DEFAULT_VARIANT

    assert signature_key(*args, **kw) == signature_key(*args, **{**kw,
                                                                 "variant": DEFAULT_VARIANT})


@pytest.mark.parametrize("name,change", _changes(), ids=[c[0] for c in _changes()])
def test_any_changed_input_misses(name, change):
    # A stale result must never come back: every input of trace_signature is in the key
    args, kw = _args()
    new_args, new_kw = change(*_args())
    assert signature_key(*new_args, **new_kw) != signature_key(*args, **kw), name


def test_changed_code_misses(monkeypatch):
    args, kw = _args()
    key = signature_key(*args, **kw)
    monkeypatch.setattr(cache_mod, "code_fingerprint", lambda: "another version")
    assert signature_key(*args, **kw) != key


def test_code_fingerprint_follows_every_source_file(tmp_path):
    # A one-byte change in any module of the package changes the fingerprint
    src = Path(cache_mod.__file__).resolve().parents[1]
    base = cache_mod.tree_digest(src)
    assert cache_mod.tree_digest(src) == base
    copy = tmp_path / "seaecho"
    for p in src.rglob("*.py"):
        (copy / p.relative_to(src)).parent.mkdir(parents=True, exist_ok=True)
        (copy / p.relative_to(src)).write_bytes(p.read_bytes())
    assert cache_mod.tree_digest(copy) == base
    target = copy / "tracing" / "sbr.py"
    target.write_bytes(target.read_bytes() + b" ")
    assert cache_mod.tree_digest(copy) != base


def test_hit_is_the_bytes_of_the_trace(tmp_path):
    # Parity: a signature written and read back equals the trace to the byte
    v, f = canonical.dihedral(0.2, 0.15)
    sig = trace_signature(TraceMesh.single(v, f), [-400.0, 30.0, 200.0], [-400.0, 30.0, 200.0],
                          F, options=SBROptions(rays_per_wavelength=2.0))
    cache = ArrayCache(tmp_path, "sig")
    assert cache.get("ab" * 32) is None
    assert cache.put("ab" * 32, signature_arrays(sig))
    back = signature_from_arrays(cache.get("ab" * 32))
    for a, b in ((sig.centres.position, back.centres.position), (sig.centres.s, back.centres.s),
                 (sig.centres.path, back.centres.path), (sig.totals, back.totals),
                 (sig.reference, back.reference), (sig.tx, back.tx), (sig.rx, back.rx),
                 (sig.centres.velocity, back.centres.velocity)):
        assert a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()
    assert (back.centres.time, back.ray_spacing, back.n_rays, back.n_hits) == (
        sig.centres.time, sig.ray_spacing, sig.n_rays, sig.n_hits)


def _trihedral_scene():
    sc = load_scene(SCENES / "calibration_trihedral.toml")
    return sc.model_copy(update={
        "radar": sc.radar.model_copy(update={"n_pulses": 2}),
        "objects": (sc.objects[0].model_copy(update={"rays_per_wavelength": 2.0}),)})


def test_simulation_reads_its_own_traces_back(tmp_path, monkeypatch):
    # A second simulation of the scene takes the trace from the cache (the trace
    # function is not called) and its pulse is the first one's to the byte
    monkeypatch.setenv(CACHE_DIR_ENV, str(tmp_path))
    monkeypatch.delenv(CACHE_ENV)
    sc = _trihedral_scene()
    first = Simulation(sc, base_dir=SCENES)
    assert first.hulls.disk_cache.enabled
    pulse = first.pulse(0)
    assert len(list(tmp_path.glob("hull-signatures/*/*.npz"))) == 1

    def no_trace(*a, **k):
        raise AssertionError("traced again")

    monkeypatch.setattr(hull_echo, "trace_signature", no_trace)
    second = Simulation(sc, base_dir=SCENES)
    assert second.pulse(0).tobytes() == pulse.tobytes()
    # a changed input (the transmitter moved by 1 mm) is traced
    tx = sc.transmitter.model_copy(update={"position_m": (-500.0, 0.001, 300.0)})
    with pytest.raises(AssertionError, match="traced again"):
        Simulation(sc.model_copy(update={"transmitter": tx}), base_dir=SCENES).pulse(0)


def test_cache_can_be_disabled(tmp_path, monkeypatch):
    monkeypatch.setenv(CACHE_DIR_ENV, str(tmp_path))
    for off in ("off", "0", "false", "no", "OFF"):
        monkeypatch.setenv(CACHE_ENV, off)
        assert cache_directory() is None
        assert not ArrayCache(namespace="x").enabled
    monkeypatch.setenv(CACHE_ENV, "on")
    assert cache_directory() == tmp_path
    monkeypatch.delenv(CACHE_ENV)
    monkeypatch.delenv(CACHE_DIR_ENV)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    if sys.platform.startswith("linux"):
        assert cache_directory() == tmp_path / "xdg" / "seaecho"


def test_cli_no_cache_writes_nothing(tmp_path, monkeypatch):
    # seaecho run fills the cache by default and leaves it alone with --no-cache; the
    # two files hold the same raw echoes
    monkeypatch.setenv(CACHE_DIR_ENV, str(tmp_path / "cache"))
    monkeypatch.delenv(CACHE_ENV)
    scene = tmp_path / "tri.toml"
    text = (SCENES / "calibration_trihedral.toml").read_text()
    scene.write_text(text.replace('file = "meshes/', f'file = "{SCENES}/meshes/')
                     .replace("rays_per_wavelength = 4.0", "rays_per_wavelength = 2.0"))
    assert main(["run", str(scene), "-o", str(tmp_path / "a.nc"), "--pulses", "1", "-q",
                 "--no-figures", "--no-cache"]) == 0
    assert not (tmp_path / "cache").exists()
    assert os.environ.get(CACHE_ENV) is None  # restored after the run
    assert main(["run", str(scene), "-o", str(tmp_path / "b.nc"), "--pulses", "1", "-q",
                 "--no-figures"]) == 0
    assert len(list((tmp_path / "cache").glob("hull-signatures/*/*.npz"))) == 1
    with xr.open_dataset(tmp_path / "a.nc") as a, xr.open_dataset(tmp_path / "b.nc") as b:
        assert a["raw"].values.tobytes() == b["raw"].values.tobytes()


def test_bad_entries_are_misses(tmp_path):
    cache = ArrayCache(tmp_path, "x")
    key = "cd" * 32
    assert cache.put(key, {"a": np.arange(5.0)})
    p = cache.path(key)
    p.write_bytes(p.read_bytes()[:40])  # truncated
    assert cache.get(key) is None
    assert not p.exists()  # removed
    # an entry stored under another key (a file moved by hand) is not returned
    assert cache.put("ef" * 32, {"a": np.arange(5.0)})
    p.parent.mkdir(parents=True, exist_ok=True)
    os.replace(cache.path("ef" * 32), p)
    assert cache.get(key) is None
    # an unwritable folder is a miss, not an error
    ro = ArrayCache(tmp_path / "file-not-folder", "x")
    (tmp_path / "file-not-folder").write_text("")
    assert ro.put(key, {"a": np.arange(3.0)}) is False
    assert ro.get(key) is None


def test_least_recently_used_entries_are_pruned(tmp_path):
    cache = ArrayCache(tmp_path, "x", max_bytes=3.5 * 8192)
    keys = [f"{i:02d}" * 32 for i in range(6)]
    for i, k in enumerate(keys):
        assert cache.put(k, {"a": np.full(1000, float(i))})  # about 8 kB each
        os.utime(cache.path(k), (1e9 + i, 1e9 + i))
    assert cache.get(keys[-1]) is not None
    assert cache.get(keys[0]) is None and cache.get(keys[1]) is None
    total = sum(p.stat().st_size for p in tmp_path.glob("x/*/*.npz"))
    assert total <= 3.5 * 8192


_WRITER = textwrap.dedent("""
    import sys
    import numpy as np
    from seaecho.targets.cache import ArrayCache
    cache = ArrayCache(sys.argv[1], "race")
    a = np.arange(200_000, dtype=np.float64)
    for _ in range(int(sys.argv[2])):
        assert cache.put(sys.argv[3], {"a": a, "b": a[::-1].copy()})
""")


def test_concurrent_writers_never_expose_a_partial_entry(tmp_path):
    # Four processes write the same 3 MB entry again and again while this one reads:
    # every read is a miss or the whole entry (atomic rename), never a partial file
    key = "99" * 32
    procs = [subprocess.Popen([sys.executable, "-c", _WRITER, str(tmp_path), "15", key])
             for _ in range(4)]
    cache = ArrayCache(tmp_path, "race")
    expected = np.arange(200_000, dtype=np.float64)
    hits = 0
    while any(p.poll() is None for p in procs):
        got = cache.get(key)
        if got is not None:
            hits += 1
            assert got["a"].tobytes() == expected.tobytes()
            assert got["b"].tobytes() == expected[::-1].tobytes()
    assert all(p.wait() == 0 for p in procs)
    got = cache.get(key)
    assert got is not None and got["a"].tobytes() == expected.tobytes()
    assert not list(tmp_path.glob("race/*/.tmp-*"))  # no temporary file left
    assert hits >= 1


def test_another_processor_misses(monkeypatch):
    # numpy's and Embree's SIMD kernels follow the instruction set: a folder shared by
    # two kinds of processors keeps their entries apart
    args, kw = _args()
    key = signature_key(*args, **kw)
    cache_mod.code_fingerprint.cache_clear()
    monkeypatch.setattr(cache_mod, "_cpu_features", lambda: "another processor")
    try:
        assert signature_key(*args, **kw) != key
    finally:
        cache_mod.code_fingerprint.cache_clear()
