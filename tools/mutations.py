"""Deliberate mutations of the physics: does the test suite notice?

Run ``python tools/mutations.py`` (``--full`` to run the whole suite for every mutation,
``--only NAME ...`` for some of them, ``--list`` to list them). The script copies the tree
(src, tests, scenes, docs, README.md, pyproject.toml, .ci) to a temporary folder, and for
each mutation replaces one piece of source there, runs the tests that should catch it
(then, if they all pass, the whole suite) with the copy first on ``PYTHONPATH``, and puts
the file back. A mutation is *killed* when at least one test fails. It prints one line
per mutation and the score, with the machine's load; exit status 1 if any survived.

Each mutation is a plausible mistake: a dropped factor, a changed cut-off, a swapped
channel, a sign. The first six are those an independent review found the suite blind to.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
COPY = ("src", "tests", "scenes", "docs", "README.md", "pyproject.toml", ".ci")


@dataclass(frozen=True)
class Mutation:
    """Replace ``old`` (which must occur exactly ``count`` times) by ``new`` in ``path``."""

    name: str
    path: str
    old: str
    new: str
    tests: tuple[str, ...]
    why: str
    count: int = 1


S = "src/seaecho/"
MUTATIONS = [
    # --- found by the review: the suite used to pass with each of these
    Mutation("echo-without-visibility", S + "simulation.py",
             "amp = speckled_facet_amplitudes(*args, facets.area * vis, *model,",
             "amp = speckled_facet_amplitudes(*args, facets.area, *model,",
             ("tests/test_end_to_end.py",),
             "shadowed facets still echo"),
    Mutation("echo-without-wake-damping", S + "simulation.py",
             'draws=held["draws"], wake_damping=damping,',
             'draws=held["draws"], wake_damping=None,',
             ("tests/test_end_to_end.py",),
             "the turbulent wake no longer damps the Bragg echo"),
    Mutation("no-wake-damping-anywhere", S + "simulation.py",
             "wake_damping=damping,", "wake_damping=None,",
             ("tests/test_end_to_end.py",),
             "the wake damps neither the echo nor the sigma0 map", count=2),
    Mutation("two-scale-cut-k/1.5", S + "ocean/twoscale.py",
             "TWO_SCALE_CUT_RATIO = 1.0 / 3.0", "TWO_SCALE_CUT_RATIO = 1.0 / 1.5",
             ("tests/test_build.py",), "sub-facet slopes up to k/1.5 instead of k/3"),
    Mutation("two-scale-cut-k", S + "ocean/twoscale.py",
             "TWO_SCALE_CUT_RATIO = 1.0 / 3.0", "TWO_SCALE_CUT_RATIO = 1.0",
             ("tests/test_build.py",), "sub-facet slopes up to k"),
    Mutation("bragg-table-ends-at-k", S + "ocean/twoscale.py",
             "ROUGHNESS_K_MAX_RATIO = 20.0", "ROUGHNESS_K_MAX_RATIO = 1.0",
             ("tests/test_build.py", "tests/test_end_to_end.py"),
             "no Bragg roughness above k (back-scatter beyond 30 deg goes dark)"),
    Mutation("T0-300K", S + "constants.py", "T0 = 290.0", "T0 = 300.0",
             ("tests/radar/test_system.py",), "receiver noise 0.15 dB too high"),
    # --- our own
    Mutation("radar-equation-loses-sqrt-4pi", S + "radar/kernels.py",
             "radar.wavelength / (4.0 * np.pi) ** 1.5)",
             "radar.wavelength / (4.0 * np.pi))",
             ("tests/radar/test_system.py", "tests/cli/test_run.py"),
             "the Dr.Jit radar kernel's amplitude off by sqrt(4 pi)"),
    Mutation("bragg-loses-4-sqrt-pi-drjit", S + "scattering/_drjit_kernel.py",
             "amp = (4.0 * math.sqrt(math.pi)) * kk * kk",
             "amp = kk * kk",
             ("tests/test_end_to_end.py",),
             "the facet kernel's Bragg amplitude without 4 sqrt(pi)"),
    Mutation("bragg-loses-4-sqrt-pi-numpy", S + "scattering/facet.py",
             "amp = 4.0 * np.sqrt(np.pi) * k * k * ci_c",
             "amp = np.sqrt(np.pi) * k * k * ci_c",
             ("tests/scattering/test_facet_calibration.py", "tests/test_end_to_end.py"),
             "the numpy facet model's Bragg amplitude off by 4"),
    Mutation("hv-vh-swapped", S + "radar/system.py",
             "return sorted(out, key=lambda c: (c[1], c[2]))",
             "return sorted(out, key=lambda c: (c[2], c[1]))",
             ("tests/radar/test_system.py",), "channels HV and VH exchanged"),
    Mutation("doppler-sign", S + "radar/kernels.py",
             "phase = -2.0 * np.pi * (cycles - dr.floor(cycles))",
             "phase = 2.0 * np.pi * (cycles - dr.floor(cycles))",
             ("tests/radar/test_system.py",),
             "carrier phase exp(+j 2 pi f tau): Doppler of the wrong sign"),
    Mutation("bistatic-delay-twice-outbound", S + "radar/kernels.py",
             "    tau = tau_t + tau_r\n", "    tau = 2.0 * tau_t\n",
             ("tests/radar/test_system.py",), "bistatic delay as if monostatic"),
    Mutation("pm-spectrum-without-one-half", S + "ocean/spectra.py",
             "out = 0.5 * PM_A0 * ks**-3", "out = PM_A0 * ks**-3",
             ("tests/ocean",), "the paper's eq 5 as printed (Hs too high by sqrt 2)"),
    Mutation("surface-variance-doubled", S + "ocean/surface.py",
             "np.sqrt(0.25 * self.dkx * self.dky * psi)",
             "np.sqrt(0.5 * self.dkx * self.dky * psi)",
             ("tests/ocean/test_surface.py",), "synthesis amplitudes sqrt(2) too large"),
    Mutation("waves-travel-backwards", S + "ocean/surface.py",
             "phase = np.exp(-1j * self._omega * t)",
             "phase = np.exp(1j * self._omega * t)",
             ("tests/ocean/test_surface.py",), "time evolution of eq 15 with the wrong sign"),
    Mutation("wind-profile-1.026", S + "ocean/wind.py",
             "DRAG_COEFFICIENT_10M = 1.3e-3", "DRAG_COEFFICIENT_10M = 2.4e-4",
             ("tests/ocean",), "U19.5 = 1.026 U10 again (a drag coefficient that fits it)"),
    Mutation("kelvin-dispersion-sec-not-squared", S + "wake/kelvin.py",
             "        kappa = self.k0 / np.cos(theta) ** 2\n",
             "        kappa = self.k0 / np.cos(theta)\n",
             ("tests/wake",), "Kelvin plane waves k0 sec(theta): wrong wedge, wrong crests"),
    Mutation("matched-filter-without-conjugate", S + "processing/range_compression.py",
             "* np.conj(np.fft.fft(h, n_fft))", "* np.fft.fft(h, n_fft)",
             ("tests/processing", "tests/radar/test_system.py"),
             "range compression correlates with the unconjugated pulse"),
    Mutation("noise-power-doubled", S + "radar/equation.py",
             "scale = np.sqrt(0.5 * power)", "scale = np.sqrt(power)",
             ("tests/radar/test_system.py",), "complex noise with E|n|^2 = 2 k T F B"),
    Mutation("speckle-variance-doubled", S + "scattering/facet.py",
             "g = rng.standard_normal((n, 4)) * np.sqrt(0.5)",
             "g = rng.standard_normal((n, 4))",
             ("tests/scattering/test_facet_calibration.py", "tests/test_end_to_end.py"),
             "speckle draws of variance 2: every clutter echo 3 dB too strong"),
    Mutation("subfacet-shadowing-ignored", S + "tracing/engine.py",
             "visibility=f.visibility * s,", "visibility=f.visibility,",
             ("tests/tracing/test_engine_objects.py",),
             "sub-facet shadowing computed but not applied"),
    Mutation("smith-lambda-doubled", S + "geometry/shadowing.py",
             "lam = 0.5 * np.exp(-nu * nu)", "lam = np.exp(-nu * nu)",
             ("tests/tracing/test_smith_statistics.py", "tests/geometry"),
             "Smith's Lambda twice too large (too much shadow)"),
    Mutation("permittivity-sign", S + "ocean/seawater.py",
             "- 1j * sigma / (2.0 * np.pi * EPS0 * f)",
             "+ 1j * sigma / (2.0 * np.pi * EPS0 * f)",
             ("tests/ocean/test_seawater.py",),
             "conduction loss with the exp(-j omega t) sign"),
    Mutation("aperture-gain-2pi", S + "radar/antennas.py",
             "norm = 4.0 * np.pi / aperture_radiated_power(",
             "norm = 2.0 * np.pi / aperture_radiated_power(",
             ("tests/radar/test_antennas.py",), "antenna directivity 3 dB low"),
    Mutation("blend-copol-exponent", S + "scattering/blend.py",
             "w1 = 10.0 ** (-((b / (6.0 * np.pi)) ** 8))",
             "w1 = 10.0 ** (-((b / (6.0 * np.pi)) ** 1.5))",
             ("tests/scattering/test_blend_twoscale.py",),
             "co-pol Kirchhoff weight with the cross-pol exponent"),
    Mutation("spm-validity-bound-3", S + "ocean/twoscale.py",
             "SPM_KH_MAX = 0.3", "SPM_KH_MAX = 3.0",
             ("tests/ocean/test_twoscale_sampling.py",), "no SPM validity warning ever"),
    Mutation("sigma0-per-facet-area", S + "simulation.py",
             "rcs = self.sigma_facet * f.area[:, None]", "rcs = self.sigma_facet",
             ("tests/test_simulation.py", "tests/test_end_to_end.py"),
             "the output sigma0 per facet area again, not per horizontal area"),
    Mutation("refresh-traces-the-live-sea", S + "simulation.py",
             "FacetEngine.from_model(models.tracing, self.surface_state_at,",
             "FacetEngine.from_model(models.tracing, self.sea.state,",
             ("tests/test_simulation.py",),
             "occlusion refreshed on the sea of t_ref, not the surface held then"),
    Mutation("pitch-sign", S + "radar/platforms.py",
             "r[..., 2, 0] = sp", "r[..., 2, 0] = -sp",
             ("tests/radar/test_platforms.py",), "nose-up pitch points the nose down"),
]


def _copy_tree(dest: Path) -> None:
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info", ".hypothesis", "*.pyc")
    for name in COPY:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=ignore)
        elif src.exists():
            shutil.copy2(src, dest / name)


def _pytest(tree: Path, tests: tuple[str, ...], timeout: float) -> tuple[int, str]:
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider",
           "--no-header", *tests]
    try:
        res = subprocess.run(cmd, cwd=tree, env=env, capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return -1, "timeout"
    lines = [ln for ln in res.stdout.splitlines() if ln.strip()]
    failed = [ln for ln in lines if ln.startswith(("FAILED", "ERROR"))]
    return res.returncode, (failed[0] if failed else (lines[-1] if lines else ""))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--full", action="store_true",
                    help="run the whole suite for every mutation (not only its tests)")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="run these mutations")
    ap.add_argument("--list", action="store_true", help="list the mutations and exit")
    ap.add_argument("--timeout", type=float, default=1800.0, help="per pytest run [s]")
    args = ap.parse_args()
    chosen = [m for m in MUTATIONS if not args.only or m.name in args.only]
    if args.list or not chosen:
        for m in MUTATIONS:
            print(f"{m.name:34s} {m.path}: {m.why}")
        return 0 if args.list else 2
    print(f"mutations: {len(chosen)}; load {os.getloadavg()[0]:.2f}", flush=True)
    killed = 0
    with tempfile.TemporaryDirectory(prefix="seaecho-mutations-") as tmp:
        tree = Path(tmp)
        _copy_tree(tree)
        for m in chosen:
            path = tree / m.path
            original = path.read_text(encoding="utf-8")
            n = original.count(m.old)
            if n != m.count:
                print(f"{m.name:34s} NOT APPLIED: found {n} times, expected {m.count}")
                continue
            path.write_text(original.replace(m.old, m.new), encoding="utf-8")
            t0 = time.perf_counter()
            try:
                rc, detail = _pytest(tree, () if args.full else m.tests, args.timeout)
                where = "suite" if args.full else "its tests"
                if rc == 0 and not args.full:  # its tests missed it: the whole suite?
                    rc, detail = _pytest(tree, (), args.timeout)
                    where = "suite"
            finally:
                path.write_text(original, encoding="utf-8")
            status = "killed" if rc != 0 else "SURVIVED"
            killed += rc != 0
            print(f"{m.name:34s} {status:8s} ({where}, {time.perf_counter() - t0:5.1f} s) "
                  f"{detail[:110]}", flush=True)
    print(f"score: {killed} / {len(chosen)} killed; load {os.getloadavg()[0]:.2f}")
    return 0 if killed == len(chosen) else 1


if __name__ == "__main__":
    sys.exit(main())
