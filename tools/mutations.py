"""Deliberate mutations of the physics: does the test suite notice?

Run ``python tools/mutations.py`` (``--full`` to run the whole suite for every mutation,
``--only NAME ...`` for some of them, ``--list`` to list them). The script copies the
working tree (the files git lists) to a temporary folder, and for each mutation replaces
one piece of source there, runs the tests that should catch it (then, if they all pass,
the whole suite) with the copy first on ``PYTHONPATH``, and puts the file back. A
mutation is *killed* when at least one test fails. It prints one line per mutation and
the score, with the machine's load; exit status 1 if any survived, 2 (before running
anything) if a mutation's text no longer occurs in the source as often as it expects, or
one of its test paths is gone: the list must follow the code.

Each mutation is a plausible mistake: a dropped factor, a changed cut-off, a swapped
channel, a sign. The first seven are mistakes the suite was once blind to. A formula
written once for numpy and Dr.Jit (:mod:`seaecho.backend`) is mutated once: the mistake
then reaches both back ends.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
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
COPY = ("src", "tests", "scenes", "docs", "benchmarks", "examples", "tools", "README.md",
        "pyproject.toml", "setup.sh", ".ci")


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
    # --- the suite used to pass with each of these
    Mutation("echo-without-visibility", S + "simulation.py",
             "amp = speckled_facet_amplitudes(*args, facets.area * vis, self.sea_model",
             "amp = speckled_facet_amplitudes(*args, facets.area, self.sea_model",
             ("tests/test_end_to_end.py",),
             "shadowed facets still echo"),
    Mutation("echo-without-wake-damping", S + "simulation.py",
             "draws=draws, wake_damping=damping,",
             "draws=draws, wake_damping=None,",
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
    Mutation("radar-equation-loses-sqrt-4pi", S + "radar/equation.py",
             "wavelength / (4.0 * math.pi) ** 1.5)",
             "wavelength / (4.0 * math.pi))",
             ("tests/radar/test_system.py", "tests/imaging/test_calibration.py"),
             "eq R1's amplitude off by sqrt(4 pi) (one formula: numpy, Dr.Jit kernel and the "
             "image calibration)"),
    Mutation("bragg-loses-4-sqrt-pi-drjit", S + "scattering/spm.py",
             "(4.0 * math.sqrt(math.pi)) * k * k * ci * cs * roughness",
             "k * k * ci * cs * roughness",
             ("tests/scattering/test_spm.py", "tests/scattering/test_facet_calibration.py"),
             "eq S7's Bragg amplitude without 4 sqrt(pi) (one formula for both back ends)"),
    Mutation("bragg-loses-4-sqrt-pi-numpy", S + "scattering/spm.py",
             "(4.0 * math.sqrt(math.pi)) * k * k * ci * cs * roughness",
             "math.sqrt(math.pi) * k * k * ci * cs * roughness",
             ("tests/scattering/test_spm.py", "tests/scattering/test_facet_calibration.py"),
             "eq S7's Bragg amplitude off by 4 (one formula for both back ends)"),
    Mutation("hv-vh-swapped", S + "radar/system.py",
             "return sorted(out, key=lambda c: (c[1], c[2]))",
             "return sorted(out, key=lambda c: (c[2], c[1]))",
             ("tests/radar/test_system.py",), "channels HV and VH exchanged"),
    Mutation("doppler-sign", S + "radar/equation.py",
             "phase = (-2.0 * math.pi) * (cycles - xp.floor(cycles))",
             "phase = (2.0 * math.pi) * (cycles - xp.floor(cycles))",
             ("tests/radar/test_system.py",),
             "carrier phase exp(+j 2 pi f tau): Doppler of the wrong sign (both back ends)"),
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
             ("tests/wake",), "Kelvin plane waves k0 sec(theta): wrong wedge, wrong crests "
             "(the synthesis and the height measurement)", count=2),
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
             "w1 = xp.exp(-_LN10 * (b * (1.0 / (6.0 * math.pi))) ** 8)",
             "w1 = xp.exp(-_LN10 * (b * (1.0 / (6.0 * math.pi))) ** 1.5)",
             ("tests/scattering/test_blend_twoscale.py",),
             "co-pol Kirchhoff weight with the cross-pol exponent (both back ends)"),
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
    # --- tried by hand on the formulas written once for numpy and Dr.Jit
    Mutation("fresnel-rv-without-eps", S + "scattering/fresnel.py",
             "(eps_r * c - root) / xp.select(zv, 1.0, den_v)",
             "(c - root) / xp.select(zv, 1.0, den_v)",
             ("tests/scattering/test_fresnel.py",),
             "eq R2's numerator without eps_r (TM reflection wrong, both back ends)"),
    Mutation("blend-6pi-to-7pi", S + "scattering/blend.py",
             "(b * (1.0 / (6.0 * math.pi))) ** 8", "(b * (1.0 / (7.0 * math.pi))) ** 8",
             ("tests/scattering/test_blend_twoscale.py",),
             "eq B3's co-pol Kirchhoff domain 22 deg instead of 18.85 deg"),
    Mutation("spm-s6-sign", S + "scattering/spm.py",
             "em1 * (eps_r * sin_i * sin_s - r_i * r_s * cos_phi)",
             "em1 * (eps_r * sin_i * sin_s + r_i * r_s * cos_phi)",
             ("tests/scattering/test_spm.py",),
             "eq S6 (alpha_vv) with the bistatic term's sign flipped"),
    Mutation("gram-charlier-c22-doubled", S + "scattering/slopes.py",
             "    c22: float = 0.12\n", "    c22: float = 0.24\n",
             ("tests/scattering/test_kirchhoff.py",),
             "Cox-Munk peakedness coefficient c22 twice its measured value"),
    Mutation("go-exponent-q2", S + "scattering/kirchhoff.py",
             "math.log(math.pi) - 4.0 * xp.log(cn) + log_p",
             "math.log(math.pi) - 2.0 * xp.log(cn) + log_p",
             ("tests/scattering/test_kirchhoff.py",),
             "eq K1 with |q|^2 / q_N^2 instead of |q|^4 / q_N^4 (both back ends)"),
    # --- code that is new since the script was written
    Mutation("breaking-fraction-doubled", S + "scattering/breaking.py",
             "    q = C_Q * total\n", "    q = 2.0 * C_Q * total\n",
             ("tests/scattering/test_breaking.py", "tests/scattering/test_validation_gmf.py"),
             "KHCC03's fraction of breaking zones q twice too large"),
    Mutation("bragg-lines-swapped", S + "scattering/dynamics.py",
             'g_p = self.process_values("bragg+", t, f_b, sigma_f, xp)\n'
             '            g_m = self.process_values("bragg-", t, -f_b, sigma_f, xp)',
             'g_p = self.process_values("bragg+", t, -f_b, sigma_f, xp)\n'
             '            g_m = self.process_values("bragg-", t, f_b, sigma_f, xp)',
             ("tests/scattering/test_dynamics.py",),
             "evolving speckle: approaching Bragg waves at -f_B, receding at +f_B"),
    Mutation("dispersion-gravity-only", S + "ocean/dispersion.py",
             "    return k * (g + surface_tension * k * k)  # Eq. 15' restoring forces",
             "    return k * g  # Eq. 15' restoring forces",
             ("tests/scattering/test_dynamics.py", "tests/ocean/test_spectra.py"),
             "the dispersion relation without its capillary term: the Bragg lines of the "
             "evolving speckle (11.0 Hz -> 8.6 Hz at X band, 45 deg), the Elfouhaily "
             "phase speed, KHCC03's growth rates (one formula, numpy and Dr.Jit)"),
    Mutation("bragg-line-gravity-only", S + "scattering/dynamics.py",
             "f_b = xp.sqrt(omega_squared_deep(kb))",
             "f_b = xp.sqrt(kb * 9.80665)",
             ("tests/scattering/test_dynamics.py",),
             "the Bragg lines of the evolving speckle without the capillary term of the "
             "dispersion relation (11.0 Hz -> 8.6 Hz at X band, 45 deg)"),
    Mutation("fused-evolving-centre-without-displacement", S + "scattering/dynamics.py",
             "return xp.vec(centroid.x + dx, centroid.y + dy, centroid.z)",
             "return xp.vec(centroid.x, centroid.y + dy, centroid.z)",
             ("tests/radar/test_resident.py",),
             "eq D1 in the fused kernel: the phase centre without the particle's x "
             "displacement"),
    Mutation("fused-evolving-echo-at-centroids", S + "radar/kernels.py",
             'facets.get("position", facets["centroid"])', 'facets["centroid"]',
             ("tests/radar/test_resident.py",),
             "the fused evolving pulse echoes from the centroids, not the carried particle "
             "positions (eq D1)"),
    Mutation("extrapolate-full-acceleration", S + "scattering/dynamics.py",
             "acceleration * const(0.5 * dt * dt)", "acceleration * const(dt * dt)",
             ("tests/test_simulation.py", "tests/radar/test_resident.py"),
             "eq D1: a dt^2 instead of a dt^2 / 2 (both paths)"),
    Mutation("auto-motion-held-when-renewed", S + "build.py",
             "r.sea_update_pulses >= r.n_pulses", "r.sea_update_pulses > 1",
             ("tests/test_build.py",),
             "sea_motion = 'auto' holds a sea renewed every few pulses (block-white clutter)"),
    Mutation("auto-motion-evolves-the-aperture", S + "build.py",
             "r.sea_update_pulses >= r.n_pulses", "r.sea_update_pulses > r.n_pulses",
             ("tests/test_build.py",),
             "sea_motion = 'auto' evolves a sea held for the whole run (the paper's SAR "
             "scenes would change)"),
    Mutation("breaking-without-1-q", S + "scattering/facet.py",
             "keep = None if breaking is None else 1.0 - breaking",
             "keep = None",
             ("tests/scattering/test_breaking_facets.py",),
             "eq P7: the blend's mechanisms keep their weight on the breaking zones' area"),
    Mutation("tilt-centre-weight-one", S + "scattering/facet.py",
             'out["bragg"] = (b, w_b * tilt.weights[0])',
             'out["bragg"] = (b, w_b)',
             ("tests/scattering/test_breaking_facets.py",),
             "eq P6: the centre node of the unresolved-tilt average with weight 1"),
    Mutation("breaking-swb2", S + "scattering/breaking.py",
             "S_WB2 = 0.19", "S_WB2 = 0.1",
             ("tests/scattering/test_breaking.py",),
             "KHCC03's mean square slope of breaking zones 0.1 instead of 0.19"),
    Mutation("kelvin-height-as-amplitude", S + "wake/kelvin.py",
             "h = max(h, float(z.max() - z.min()))",
             "h = max(h, 0.5 * float(z.max() - z.min()))",
             ("tests/wake/test_wake_heights.py",),
             "Michell's amplitude taken for the crest-to-trough height: empirical wake "
             "heights doubled"),
    Mutation("kriebel-seelig-decay-sqrt", S + "wake/empirical.py",
             "(y / length) ** (-1.0 / 3.0)", "(y / length) ** (-0.5)",
             ("tests/wake/test_wake_heights.py",),
             "wake heights decay as y^(-1/2) (transverse waves) not y^(-1/3) (cusp)"),
    Mutation("turbulent-damping-decay", S + "wake/turbulent.py",
             "d_t = (1.0 + xi / width_at_stern) ** -0.6",
             "d_t = (1.0 + xi / width_at_stern) ** -0.2",
             ("tests/wake/test_turbulent_damping.py",),
             "the wake's Bragg damping decays as its width grows, not as its eddy viscosity"),
    Mutation("calibration-mean-not-sum", S + "imaging/calibration.py",
             "k = np.sum(w * a, axis=1)  # eq (K2)",
             "k = np.mean(w * a, axis=1)  # eq (K2)",
             ("tests/imaging/test_bistatic_point_target.py",),
             "eq K2 without the number of pulses: image RCS N^2 too large"),
    Mutation("calibration-monostatic-range", S + "imaging/calibration.py",
             "wavelength, ranges[0],\n                          ranges[1])",
             "wavelength, ranges[0],\n                          ranges[0])",
             ("tests/imaging/test_calibration.py",),
             "eq K1 with r_t^2 for r_t r_r (the bistatic range factor lost)"),
    Mutation("backprojection-phase-sign", S + "imaging/backprojection.py",
             "cos=xp.cos(phase) * w, sin=xp.sin(phase) * w)",
             "cos=xp.cos(phase) * w, sin=-xp.sin(phase) * w)",
             ("tests/imaging/test_monostatic_point_target.py",),
             "eq B2's carrier phase exp(-j 2 pi f_c tau) (numpy and Dr.Jit, one formula): "
             "the pulses do not add up"),
    # --- the speed work: faster evaluations that must keep their numbers
    Mutation("mirrored-channel-sign", S + "radar/echo.py",
             "total[c] = sign * total[src]", "total[c] = total[src]",
             ("tests/radar/test_echo.py",),
             "the monostatic VH sum taken as +HV (FSA reciprocity gives VH = -HV)"),
    Mutation("nufft-chunk-dropped", S + "radar/echo.py",
             "for p, d in parts[1:]:", "for p, d in parts[1:-1]:",
             ("tests/radar/test_echo.py",), "the last chunk of points left out of eq E2"),
    Mutation("ocean-slope-x-with-ky", S + "ocean/surface.py",
             "np.multiply(jkx, z_c, out=spectra[0])", "np.multiply(jky, z_c, out=spectra[0])",
             ("tests/ocean/test_surface.py",), "the x slope's batched spectrum multiplied by j Ky"),
    Mutation("kelvin-line-shift-sign", S + "wake/kelvin.py",
             "side * y * ky + (n // 2) * p))", "side * y * ky - (n // 2) * p))",
             ("tests/wake/test_wake_speed_parity.py",),
             "the line height's NUFFT with its mode shift the wrong way"),
    Mutation("raw97-short-wave-rise-lost", S + "ocean/romeiser.py",
             "np.sqrt(1.0 + (k / k6) ** 7.2)", "np.sqrt(1.0 + (k / k6) ** 2.2)",
             ("tests/ocean/test_romeiser.py", "tests/scattering/test_validation_gmf.py"),
             "RAW97's eq 42 with a slower rise above 280 rad/m: X-band Bragg waves too low"),
    Mutation("raw97-wind-exponent-centre", S + "ocean/romeiser.py",
             "np.exp(-(((k - k4) / k5) ** 2)))", "np.exp(-(((k + k4) / k5) ** 2)))",
             ("tests/ocean/test_romeiser.py", "tests/scattering/test_validation_gmf.py"),
             "RAW97's wind exponent (eq 41) centred at -140 rad/m: short waves hardly grow "
             "with the wind"),
    Mutation("raw97-spreading-over-real-line", S + "ocean/romeiser.py",
             "norm = np.sqrt(np.pi / a) * erf(np.pi * np.sqrt(a))", "norm = np.sqrt(np.pi / a)",
             ("tests/ocean/test_romeiser.py",),
             "RAW97's spreading normalised over the real line, not (-pi, pi]"),
    # --- detection (docs/detection.md)
    Mutation("ca-cfar-law-exponent", S + "detection/theory.py",
             "return (1.0 + np.asarray(alpha, dtype=float) / n) ** (-float(n))",
             "return (1.0 + np.asarray(alpha, dtype=float) / n) ** (-float(n - 1))",
             ("tests/detection/test_cfar.py",), "CA-CFAR's P_FA law with N - 1 (eq D1)"),
    Mutation("so-cfar-law-one-plus", S + "detection/theory.py",
             "(n_half + j) * np.log(2.0 + t)", "(n_half + j) * np.log(1.0 + t)",
             ("tests/detection/test_cfar.py",), "SO's law with (1 + T) for (2 + T) (eq D3)"),
    Mutation("swerling1-without-one", S + "detection/theory.py",
             "/ (1.0 + np.asarray(snr, dtype=float))", "/ np.asarray(snr, dtype=float)",
             ("tests/detection/test_cfar.py",), "Swerling 1 P_D with alpha / S, not / (1 + S)"),
    Mutation("ca-cfar-k-window-power", S + "detection/theory.py",
             "n * np.log(np.maximum(phi, 1e-300))",
             "(n - 1) * np.log(np.maximum(phi, 1e-300))",
             ("tests/detection/test_cfar_k.py",),
             "CA-CFAR in independent K clutter with N - 1 training cells in eq D8"),
    Mutation("ca-cfar-k-texture-mean", S + "detection/theory.py",
             "    x0 = y / nu  # texture of the CUT", "    x0 = y  # texture of the CUT",
             ("tests/detection/test_cfar_k.py",),
             "the CUT's gamma texture of mean nu, not 1 (eq D8)"),
    Mutation("k-laplace-tricomi-b", S + "detection/theory.py",
             "special.hyperu(nu, nu, zs)", "special.hyperu(nu, nu + 1.0, zs)",
             ("tests/detection/test_cfar_k.py",),
             "eq D7 with U(nu, nu + 1, z), not U(nu, nu, z)"),
    Mutation("os-cfar-rank-off-by-one", S + "detection/cfar.py",
             "ndimage.rank_filter(x, self.rank - 1,", "ndimage.rank_filter(x, self.rank,",
             ("tests/detection/test_cfar.py",), "OS-CFAR takes the (k+1)-th cell (eq D4)"),
    Mutation("go-so-swapped", S + "detection/cfar.py",
             "(np.maximum if self.kind == \"go\" else np.minimum)",
             "(np.minimum if self.kind == \"go\" else np.maximum)",
             ("tests/detection/test_cfar.py",), "greatest-of and smallest-of swapped"),
    Mutation("clutter-map-includes-the-scan", S + "detection/clutter_map.py",
             "            if n >= self.warmup:\n                out[n] = q\n"
             "            q = (1.0 - w) * q + w * power[n]\n",
             "            q = (1.0 - w) * q + w * power[n]\n"
             "            if n >= self.warmup:\n                out[n] = q\n",
             ("tests/detection/test_clutter_map.py",),
             "the clutter map updated with the scan it tests (Nitzberg's q_{n-1})"),
    Mutation("m-of-n-strict", S + "detection/clutter_map.py",
             "c[n:] - c[:-n] >= m", "c[n:] - c[:-n] > m",
             ("tests/detection/test_clutter_map.py",), "M-of-N needing more than M (eq D6)"),
    Mutation("clutter-cell-without-sec-psi", S + "detection/footprint.py",
             "area = r * th * dr / np.cos(psi)", "area = r * th * dr",
             ("tests/detection/test_footprint.py",),
             "the range cell not projected on the sea (eq F1 without sec psi)"),
    Mutation("bearing-is-the-azimuth", S + "io/detections.py",
             "phi = 0.5 * np.pi - np.deg2rad(", "phi = np.deg2rad(",
             ("tests/detection/test_tracking_export.py",),
             "Stone Soup's bearing taken as the PPI's azimuth (clockwise from north)"),
    # --- one source per law: each law and constant once, each mistake caught once
    Mutation("dispersion-finite-depth-ignored", S + "ocean/dispersion.py",
             "omega2 = omega2 * np.tanh(k * depth)", "omega2 = omega2 * 1.0",
             ("tests/ocean",), "eq 15 without tanh(K d): shallow water as deep"),
    Mutation("sea-water-viscosity-x10", S + "constants.py",
             "NU_SEA_WATER = 1.05e-6", "NU_SEA_WATER = 1.05e-5",
             ("tests/wake/test_turbulent_damping.py", "tests/scattering/test_breaking.py",
              "tests/scattering/test_dynamics.py"),
             "kinematic viscosity of sea water ten times Sharqawy et al.'s (film damping, "
             "KHCC03's viscous loss)"),
    Mutation("von-karman-0.35", S + "constants.py",
             "VON_KARMAN = 0.41", "VON_KARMAN = 0.35",
             ("tests/ocean/test_wind.py",), "von Karman constant outside Smith's 0.41 +- 0.025"),
    Mutation("wu-drag-slope", S + "ocean/wind.py",
             "u * np.sqrt((0.8 + 0.065 * u) * 1e-3)", "u * np.sqrt((0.8 + 0.65 * u) * 1e-3)",
             ("tests/ocean/test_wind.py",), "Wu's (1982) drag coefficient slope ten times"),
    Mutation("donelan-roughness", S + "ocean/wind.py",
             "z0 = 3.7e-5 * u**2 / G * inverse_wave_age**0.9",
             "z0 = 3.7e-5 * u**2 / G * inverse_wave_age**1.9",
             ("tests/ocean/test_wind.py",), "Donelan's roughness with Omega_c^1.9"),
    Mutation("breaking-friction-law", S + "scattering/breaking.py",
             'FRICTION_LAW = "wu-1982"', 'FRICTION_LAW = "constant-drag"',
             ("tests/ocean/test_wind.py", "tests/scattering/test_breaking.py"),
             "KHCC03's wind growth rate with another drag law than theirs (Wu 1982)"),
    Mutation("elfouhaily-short-wave-half", S + "ocean/spectra.py",
             "b_h = 0.5 * p.alpha_m * (C_M / c) * f_m", "b_h = p.alpha_m * (C_M / c) * f_m",
             ("tests/ocean/test_spectra.py",),
             "Elfouhaily's short-wave curvature without its 1/2 (Bragg roughness x2)"),
    Mutation("elfouhaily-short-wave-width", S + "ocean/spectra.py",
             "np.exp(-0.25 * (ks / K_M - 1.0) ** 2)", "np.exp(-0.025 * (ks / K_M - 1.0) ** 2)",
             ("tests/ocean/test_spectra.py",),
             "Elfouhaily's short-wave side effect F_m ten times wider"),
    Mutation("hamming-as-hann", S + "processing/windows.py",
             "        return (0.54, 0.46)", "        return (0.5, 0.5)",
             ("tests/processing", "tests/imaging/test_windows_and_quality.py"),
             "Hamming's coefficients (0.54, 0.46) taken as Hann's (every window of seaecho)"),
    Mutation("kelvin-wavelength-half", S + "wake/michell.py",
             "return 2.0 * math.pi / kelvin_wavenumber(speed, g)",
             "return math.pi / kelvin_wavenumber(speed, g)",
             ("tests/wake",), "the transverse Kelvin wavelength pi V^2 / g"),
    Mutation("marangoni-y-factor", S + "wake/film.py",
             "big_y = elasticity * k / (4.0 * rho * nu * omega)",
             "big_y = elasticity * k / (2.0 * rho * nu * omega)",
             ("tests/wake/test_turbulent_damping.py",),
             "eq W16's Y = E k / (4 rho nu omega) with 2 for 4 (Lucassen-Reynders & Lucassen)"),
    Mutation("sbr-one-bounce-less", S + "tracing/sbr.py",
             "        for bounce in range(self.opt.max_bounces):",
             "        for bounce in range(self.opt.max_bounces - 1):",
             ("tests/ship/test_sbr_canonical.py",),
             "shooting and bouncing rays stop one bounce early (no dihedral, no flat plate "
             "at max_bounces = 1)"),
    Mutation("backprojection-delay-monostatic", S + "imaging/backprojection.py",
             "    return tau_t + tau_r\n", "    return 2.0 * tau_t\n",
             ("tests/imaging/test_bistatic_point_target.py",),
             "eq B1's bistatic delay taken as twice the outbound one"),
    Mutation("po-magnetic-current-sign", S + "targets/po.py",
             "m = -alpha * ((1.0 + rh) * e2a) - beta * (e2b + rv * e2c)",
             "m = alpha * ((1.0 + rh) * e2a) - beta * (e2b + rv * e2c)",
             ("tests/ship/test_po_kernels.py",),
             "eq O4's equivalent magnetic current M with its TE term's sign flipped"),
    Mutation("chirp-direction", S + "radar/waveform.py",
             "return (1.0 if up else -1.0) * bandwidth / duration",
             "return (-1.0 if up else 1.0) * bandwidth / duration",
             ("tests/processing", "tests/radar"),
             "an up-chirp sweeping down (eq W1's sign)"),
    Mutation("pauli-order", S + "imaging/speckle.py",
             "np.abs(hh - vv) ** 2, np.abs(hv + vh) ** 2,\n                           "
             "np.abs(hh + vv) ** 2]",
             "np.abs(hh + vv) ** 2, np.abs(hv + vh) ** 2,\n                           "
             "np.abs(hh - vv) ** 2]",
             ("tests/imaging/test_speckle.py",),
             "Pauli RGB as (|HH+VV|, |HV+VH|, |HH-VV|): odd and even bounces swapped"),
    # --- scanning radar, 4/3 Earth, CfRadial product
    Mutation("scan-counter-clockwise", S + "radar/pointing.py",
             "a = self.start - self.turned(t)", "a = self.start + self.turned(t)",
             ("tests/radar/test_scan.py", "tests/io/test_cfradial.py"),
             "the antenna turns counter-clockwise"),
    Mutation("cosine-taper-width", S + "radar/antennas.py",
             "d = 1.0 - 4.0 * t * t", "d = 1.0 - 2.0 * t * t",
             ("tests/radar/test_scan.py",), "the cosine aperture's pattern denominator"),
    Mutation("taylor-sigma", S + "radar/antennas.py",
             "sigma = nbar / np.sqrt(a * a + (nbar - 0.5) ** 2)",
             "sigma = nbar / np.sqrt(a * a + nbar ** 2)",
             ("tests/radar/test_scan.py",), "Taylor's dilation factor without the 1/2"),
    Mutation("grazing-refraction-sign", S + "geometry/earth.py",
             "s = h / r + (h * h - r * r) / (2.0 * radius * r)",
             "s = h / r + (h * h + r * r) / (2.0 * radius * r)",
             ("tests/geometry/test_earth.py",), "the Earth's bulge raises the grazing angle"),
    Mutation("horizon-without-2", S + "geometry/earth.py",
             "return np.sqrt(2.0 * radius) * (np.sqrt(h1) + np.sqrt(h2))",
             "return np.sqrt(radius) * (np.sqrt(h1) + np.sqrt(h2))",
             ("tests/geometry/test_earth.py",), "the horizon sqrt(k a h) instead of 2 k a h"),
    Mutation("earth-map-without-drop", S + "geometry/earth.py",
             "- 2.0 * self.radius * np.sin(0.5 * beta) ** 2], axis=-1)",
             "], axis=-1)",
             ("tests/geometry/test_earth.py", "tests/radar/test_earth_radar.py"),
             "points mapped onto the sphere without the drop below the tangent plane"),
    Mutation("targets-never-occluded", S + "radar/system.py",
             "        if not seen.any():\n            return None\n",
             "        seen = np.ones_like(seen)\n",
             ("tests/radar/test_earth_radar.py",), "targets beyond the horizon still echo"),
    Mutation("cfradial-azimuth-ccw", S + "io/cfradial.py",
             "np.arctan2(b[..., 0], b[..., 1])", "np.arctan2(b[..., 1], b[..., 0])",
             ("tests/io/test_cfradial.py", "tests/radar/test_scan.py"),
             "the product's azimuth counter-clockwise from east, not clockwise from north"),
    Mutation("scan-ignores-attitude", S + "radar/pointing.py",
             "return state.rotation @ self.scan.axes_body(t)",
             "return self.scan.axes_body(t) + 0.0 * state.rotation",
             ("tests/radar/test_scan.py",), "the pedestal does not roll with the ship"),
    # --- fluctuating targets (Swerling 1954)
    Mutation("swerling-chi4-unscaled", S + "targets/swerling.py",
             "np.where(m == 1, l1, 0.5 * (l1 + l2))", "np.where(m == 1, l1, l1 + l2)",
             ("tests/targets/test_swerling.py",),
             "the chi-square-4 RCS not scaled to unit mean (mean RCS doubled)"),
    Mutation("swerling-dwell-pulse-swapped", S + "targets/swerling.py",
             "by_pulse = np.isin(cases, (2, 4))", "by_pulse = np.isin(cases, (1, 3))",
             ("tests/targets/test_swerling.py",),
             "scan-to-scan and pulse-to-pulse cases exchanged"),
    Mutation("swerling-amplitude-not-sqrt", S + "radar/model.py",
             "self.scattering * np.sqrt(self.rcs_factor(int(pulse)))",
             "self.scattering * self.rcs_factor(int(pulse))",
             ("tests/targets/test_swerling.py",),
             "the power factor applied to the amplitude (RCS F^2 instead of F)"),
    # --- ships on waypoints, several ships, ground truth
    Mutation("route-corner-cut-half-angle", S + "wake/ship.py",
             "cut = np.concatenate([[0.0], r * np.tan(0.5 * np.abs(turn)), [0.0]])",
             "cut = np.concatenate([[0.0], r * np.tan(np.abs(turn)), [0.0]])",
             ("tests/wake/test_ship_route.py",),
             "the corner cut R tan(Delta) instead of R tan(Delta / 2): turns off the legs"),
    Mutation("route-arc-sign", S + "wake/ship.py",
             "kappa.append(np.sign(turn[i]) / r)", "kappa.append(-np.sign(turn[i]) / r)",
             ("tests/wake/test_ship_route.py",), "turns the wrong way"),
    Mutation("wake-masks-added", S + "sea.py",
             "keep = 1.0 - m if keep is None else keep * (1.0 - m)",
             "keep = 1.0 - m if keep is None else keep - m",
             ("tests/wake/test_ship_route.py",),
             "turbulent damping of several ships added instead of combined"),
    Mutation("truth-range-cell-two-way", S + "radar/truth.py",
             "cell = np.rint((2.0 * rng / C0 - w.t0) * w.sampling_rate)",
             "cell = np.rint((rng / C0 - w.t0) * w.sampling_rate)",
             ("tests/radar/test_truth.py",), "the range cell from a one-way delay"),
    Mutation("horizon-true-earth", S + "geometry/earth.py",
             "STANDARD_REFRACTION_K = 4.0 / 3.0", "STANDARD_REFRACTION_K = 1.0",
             ("tests/radar/test_truth.py", "tests/geometry"),
             "the radio horizon without refraction"),
    Mutation("hull-roll-sign", S + "targets/motion.py",
             "return float(coef[0]), float(np.arctan(coef[1])), float(np.arctan(coef[2]))",
             "return float(coef[0]), float(np.arctan(coef[1])), float(-np.arctan(coef[2]))",
             ("tests/targets/test_motion.py",), "the hull rolls against the sea's slope"),
    Mutation("hull-response-leads", S + "targets/motion.py",
             "return 1.0 / (1.0 - r * r - 2j * zeta * r)",
             "return 1.0 / (1.0 - r * r + 2j * zeta * r)",
             ("tests/targets/test_motion.py",),
             "the damped hull moves ahead of the waves that drive it"),
    Mutation("hull-heave-no-added-mass", S + "targets/motion.py",
             "G / (self.draft + np.pi * self.beam / 8.0)", "G / self.draft",
             ("tests/targets/test_motion.py",), "heave natural period without added mass"),
    Mutation("hull-encounter-frequency-sign", S + "targets/motion.py",
             "oscillator_response(waves.omega - kv, wn, zeta)",
             "oscillator_response(waves.omega + kv, wn, zeta)",
             ("tests/targets/test_motion.py",),
             "the frequency of encounter of a moving hull with the wrong Doppler sign"),
    Mutation("hull-slope-weight-real", S + "targets/motion.py",
             "return 3j * np.asarray(k, dtype=np.float64) * f",
             "return 3.0 * np.asarray(k, dtype=np.float64) * f",
             ("tests/targets/test_motion.py",),
             "pitch and roll in phase with the elevation instead of the slope"),
    Mutation("wave-components-origin", S + "ocean/surface.py",
             "shift = np.exp(-1j * (kx * self.x[0] + ky * self.y[0]))",
             "shift = np.ones(kx.shape)",
             ("tests/targets/test_motion.py",),
             "the wave components referred to the grid's corner instead of the origin"),
    Mutation("hull-route-no-turn", S + "tracing/hull_echo.py",
             "dh = float(self.heading(t) - self.heading(0.0))", "dh = 0.0",
             ("tests/ship/test_hull_route.py",),
             "the hull on waypoints does not turn with its route"),
    Mutation("hull-route-yaw-rate-sign", S + "tracing/hull_echo.py",
             "w * np.stack([-d[:, 1], d[:, 0], np.zeros(len(d))], -1)",
             "w * np.stack([d[:, 1], -d[:, 0], np.zeros(len(d))], -1)",
             ("tests/ship/test_hull_route.py",),
             "a turning hull's points swing the wrong way (Doppler)"),
    Mutation("hull-skip-inverted", S + "simulation.py",
             "return lambda corners: two_way_bound(self.radar, pulse, corners) >= floor",
             "return lambda corners: two_way_bound(self.radar, pulse, corners) < floor",
             ("tests/ship/test_hull_sharing.py",),
             "hulls in the beam skipped, hulls outside it computed"),
    Mutation("hull-shared-trace-turned-back", S + "tracing/hull_echo.py",
             "dh = float(hi.heading(ti) - hj.heading(tj))",
             "dh = float(hj.heading(tj) - hi.heading(ti))",
             ("tests/ship/test_hull_sharing.py",),
             "an identical hull's trace turned the wrong way onto the other hull"),
    # --- several receivers (docs/multistatic.md)
    Mutation("multistatic-tx-occlusion-of-lead-receiver", S + "tracing/engine.py",
             "occ_tx = self._lead.occlusion(t, st)[1]",
             "occ_tx = self._lead.occlusion(t, st)[2]",
             ("tests/multistatic/test_multistatic.py",),
             "a receiver takes the first receiver's shadowing as the transmitter's"),
    Mutation("multistatic-bistatic-angle-supplement", S + "geometry/bistatic.py",
             "return np.arctan2(cross, np.sum(a * b, axis=-1))",
             "return np.arctan2(cross, -np.sum(a * b, axis=-1))",
             ("tests/multistatic/test_multistatic.py",),
             "bistatic angle measured from the forward-scatter direction"),
    Mutation("multistatic-fused-sum", S + "multistatic.py",
             'rcs.mean("receiver", skipna=True)', 'rcs.sum("receiver", skipna=True)',
             ("tests/multistatic/test_multistatic.py",),
             "the incoherent combination adds the receivers' intensities"),
    Mutation("multistatic-speckle-per-receiver", S + "simulation.py",
             "g_k, g_b = facet_gaussians(n_facets, 2, seed, \"speckle\", block, xp=xp)",
             "g_k, g_b = facet_gaussians(n_facets, 2, seed + len(self.radar.channels) "
             "+ int(abs(1e3 * self.radar.rx.state(0.0).position[0])), \"speckle\", block, xp=xp)",
             ("tests/multistatic/test_multistatic.py",),
             "each receiver draws its own sub-facet speckle"),

    # --- the narrow-V wake (eqs N1-N7)
    Mutation("narrow-v-kelvin-ray-without-n", S + "wake/narrow_v.py",
             "return np.arctan2(n * t, 1.0 - n + t * t)  # Eq N2",
             "return np.arctan2(n * t, 1.0 + t * t)  # Eq N2",
             ("tests/wake/test_narrow_v.py",),
             "the ray of a steady wave without the group speed's share in its denominator"),
    Mutation("narrow-v-viscous-decay-halved", S + "wake/narrow_v.py",
             "np.exp(-2.0 * NU_SEA_WATER * k * k * r / u_e))  # Eq N4",
             "np.exp(-NU_SEA_WATER * k * k * r / u_e))  # Eq N4",
             ("tests/wake/test_narrow_v.py",),
             "the arms' Bragg waves decay at half Lamb's viscous rate"),
    Mutation("narrow-v-gain-clipped-in-facet-model", S + "scattering/facet.py",
             "xp.sqrt(xp.maximum(1.0 - damping, 0.0))",
             "xp.sqrt(xp.clip(1.0 - damping, 0.0, 1.0))",
             ("tests/wake/test_narrow_v.py",),
             "the facet model drops the narrow-V's added Bragg waves (wake mask < 0)"),
    Mutation("narrow-v-periodogram-one-sided", S + "wake/narrow_v.py",
             "return 0.25 * a * a * dx * dy / (4.0 * np.pi**2) * resp  # Eq N6",
             "return 0.5 * a * a * dx * dy / (4.0 * np.pi**2) * resp  # Eq N6",
             ("tests/wake/test_narrow_v.py",),
             "the plane wave's variance a^2/2 put whole at +k_w and again at -k_w"),
    Mutation("beam-bound-largest-u", S + "radar/coverage.py",
             "antenna.width * np.abs(u).min(axis=-1) / antenna.wavelength",
             "antenna.width * np.abs(u).max(axis=-1) / antenna.wavelength",
             ("tests/radar/test_coverage.py",),
             "the beam's bound at the tile's farthest corner, not its nearest (eq C1)"),
    Mutation("beam-bound-no-envelope", S + "radar/coverage.py",
             "env = np.maximum.accumulate(f[::-1])[::-1]", "env = f",
             ("tests/radar/test_coverage.py",),
             "the pattern itself in place of its envelope (eq C1: not a bound)"),
    Mutation("beam-bound-one-way", S + "radar/coverage.py",
             "    return g * one_way_bounds(radar.rx_antenna,",
             "    return one_way_bounds(radar.rx_antenna,",
             ("tests/radar/test_coverage.py",), "the two-way bound without the transmitter"),
    Mutation("copol-np-sign", S + "scattering/copol.py",
             "regular_vv = (vv - hh) / (1.0 - p)", "regular_vv = (vv - hh) / (1.0 + p)",
             ("tests/scattering/test_copol.py", "tests/scattering/test_validation_gmf.py"),
             "eq CP3: the polarisation difference over (1 + p) instead of (1 - p)"),
    Mutation("copol-np-hh", S + "scattering/copol.py",
             "return vv - regular_vv, regular_vv", "return hh - regular_vv, regular_vv",
             ("tests/scattering/test_copol.py", "tests/scattering/test_validation_gmf.py"),
             "eq CP3: NP taken from HH minus the regular VV"),
    Mutation("ground-resolution-monostatic-factor", S + "radar/resolution.py",
             "    return C0 / (bandwidth * gh), grad / gh",
             "    return C0 / (2 * bandwidth * gh), grad / gh",
             ("tests/radar/test_resolution.py",),
             "the bistatic ground cell with the monostatic factor 2 again (eq R2)"),
    Mutation("azimuth-resolution-full-aperture", S + "radar/resolution.py",
             "    return wavelength * slant_range / (2 * aperture)",
             "    return wavelength * slant_range / aperture",
             ("tests/radar/test_resolution.py",),
             "lambda R / L: the two-way phase of a synthetic aperture forgotten (eq R3)"),
    # --- the sea's two-ray propagation factor (radar/propagation.py)
    Mutation("two-ray-no-divergence", S + "radar/propagation.py",
             "two_ray_factor(delta, div, ", "two_ray_factor(delta, 1.0, ",
             ("tests/radar/test_propagation.py",),
             "eq P1 without the spherical Earth's divergence factor D", count=2),
    Mutation("two-ray-no-roughness", S + "radar/propagation.py",
             " * rho, self.wavelength)", ", self.wavelength)",
             ("tests/radar/test_propagation.py",),
             "eq P1 with the smooth sea's reflection: no rough-sea specular factor", count=2),
    Mutation("two-ray-reflection-sign", S + "radar/propagation.py",
             "return 1.0 + np.asarray(gamma) * np.asarray(divergence)",
             "return 1.0 - np.asarray(gamma) * np.asarray(divergence)",
             ("tests/radar/test_propagation.py",),
             "eq P1 with the sign of the reflection coefficient flipped"),
    Mutation("two-ray-specular-point-swapped", S + "radar/propagation.py",
             "flat = np.where(hs > 0, d * h1 / hs, 0.5 * d)",
             "flat = np.where(hs > 0, d * h2 / hs, 0.5 * d)",
             ("tests/radar/test_propagation.py",),
             "eq P2's flat limit measured from the wrong end"),
    Mutation("two-ray-not-applied", S + "radar/system.py",
             "if not multipath or two_ray is None or len(s) == 0:",
             "if True:",
             ("tests/radar/test_propagation.py",),
             "[propagation] multipath = 'two-ray' ignored by the radar equation"),
    # --- land, lines of sight, the truth's frame (docs/land.md)
    Mutation("land-sigma0-sin-squared", S + "scattering/land.py",
             "return gamma * si  # Eq (L1)", "return gamma * si * si  # Eq (L1)",
             ("tests/scattering/test_land_clutter.py", "tests/tracing/test_land.py"),
             "sigma0 = gamma sin^2(psi) instead of constant gamma (eq L1)"),
    Mutation("land-weibull-not-unit-mean", S + "scattering/land.py",
             "return rng.standard_exponential(n) ** shape / math.gamma(1.0 + shape)",
             "return rng.standard_exponential(n) ** shape",
             ("tests/scattering/test_land_clutter.py", "tests/tracing/test_land.py"),
             "the Weibull power without b = 1 / Gamma(1 + a_w): mean != 1 (eq L4)"),
    Mutation("land-gamma-10-log-f", S + "scattering/land.py",
             "+ 5.0 * math.log10(frequency_hz / GAMMA_REFERENCE_HZ)",
             "+ 10.0 * math.log10(frequency_hz / GAMMA_REFERENCE_HZ)",
             ("tests/scattering/test_land_clutter.py",), "gamma ~ f instead of f^(1/2)"),
    Mutation("land-echo-without-visibility", S + "tracing/land.py",
             "* self.power[sel] * self.visibility(tx, rx)[sel]", "* self.power[sel]",
             ("tests/tracing/test_land.py",),
             "land facets behind a crest or facing away still echo (eq L5's V_f)"),
    Mutation("land-does-not-occlude-the-sea", S + "build.py",
             "            objects += [p.geometry() for p in land.pieces]",
             "            objects += []",
             ("tests/tracing/test_land.py",), "the sea behind a headland is still lit"),
    Mutation("targets-hidden-ignored-in-the-pulse", S + "simulation.py",
             'else {"hidden": hidden.any(axis=0)[0]}',
             "else {}",
             ("tests/tracing/test_land.py",),
             "a target behind the land still echoes in the pulse"),
    Mutation("wave-crests-hide-nothing", S + "simulation.py",
             "                out[1][sel] |= hit", "                out[1][sel] |= False",
             ("tests/tracing/test_land.py",), "a target under a wave crest is seen"),
    Mutation("hull-not-hidden-by-the-earth", S + "tracing/hull_echo.py",
             "    return on, earth.visible(tx, test) & earth.visible(rx, test)",
             "    return on, np.ones(len(p), dtype=bool)",
             ("tests/tracing/test_line_of_sight.py",),
             "a hull's part below the horizon still echoes"),
    Mutation("hull-bounce-centre-tested-below-the-sea", S + "tracing/hull_echo.py",
             "np.abs(p[:, 2:])", "p[:, 2:]",
             ("tests/tracing/test_line_of_sight.py",),
             "a sea-bounce centre's image depth makes it always hidden"),
    Mutation("land-patches-skipped-above-the-floor", S + "simulation.py",
             "                                  boxes) >= floor",
             "                                  boxes) >= 1e5 * floor",
             ("tests/tracing/test_land.py",),
             "land patches skipped with a two-way gain bound up to 1e5 times the floor"),
    Mutation("truth-range-in-the-scene-frame", S + "radar/truth.py",
             "cart = pos if earth is None else earth.position(pos)", "cart = pos",
             ("tests/radar/test_truth_frame.py",),
             "the truth's range from Earth-following coordinates (frames mixed)"),
    Mutation("patchwork-band-of-finer-level", S + "geometry/patchwork.py",
             "inner = [FACETS_PER_BEAM * d / beam_rad for d in spacings[1:]]",
             "inner = [FACETS_PER_BEAM * d / beam_rad for d in spacings[:-1]]",
             ("tests/test_coverage_sea.py",),
             "level j starts where level j - 1's facets reach theta g / 8 (eq T2)"),
    Mutation("patchwork-pitch-n-cells", S + "geometry/patchwork.py",
             "return (self.shape[1] - 1) * self.spacing[0], (self.shape[0] - 1) * self.spacing[1]",
             "return self.shape[1] * self.spacing[0], self.shape[0] * self.spacing[1]",
             ("tests/test_coverage_sea.py",),
             "tiles placed an FFT period apart: a strip of one cell between them (eq T4)"),
    Mutation("tile-frame-not-tilted", S + "geometry/patchwork.py",
             "return TileFrame(self.earth.tilt(o), self.earth.position(o), o)",
             "return TileFrame(np.eye(3), self.earth.position(o), o)",
             ("tests/test_coverage_sea.py",),
             "a tile dropped on the Earth but not turned to its local vertical (eq T5)"),
    Mutation("tile-frame-not-dropped", S + "geometry/patchwork.py",
             "return TileFrame(self.earth.tilt(o), self.earth.position(o), o)",
             "return TileFrame(self.earth.tilt(o), o.copy(), o)",
             ("tests/test_coverage_sea.py",),
             "a tile turned to its local vertical but left on the tangent plane (eq T5)"),
    Mutation("unit-echo-gain-not-square-rooted", S + "coverage.py",
             "(out[idx],) = io.numpy(xp.sqrt(g_t * g_r))",
             "(out[idx],) = io.numpy(g_t * g_r)",
             ("tests/test_coverage_sea.py",),
             "the unit-gain echo scaled by the two-way power gain, not its root (eq U2)"),
    Mutation("unit-echo-sector-one-side", S + "coverage.py",
             "for centre in (phi_y + 0.5 * np.pi, phi_y - 0.5 * np.pi):",
             "for centre in (phi_y + 0.5 * np.pi,):",
             ("tests/test_coverage_sea.py",),
             "a tile's facets taken on one side of the antenna only (eq U3)"),
    Mutation("tile-prefilter-no-elevation", S + "coverage.py",
             "q = (u_max + s_max * abs(float(y[2]))) / (c_min * rho) + 1e-9",
             "q = u_max / rho",
             ("tests/test_coverage_sea.py",),
             "the tiles' azimuth prefilter without their elevation (eq U3): near tiles lost"),
]


def _copy_tree(dest: Path) -> None:
    """Copy the working tree: the files git tracks or would track (README, setup.sh,
    benchmarks... which tests read too), else the folders of ``COPY``."""
    try:
        listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                                 "--exclude-standard"], cwd=ROOT, capture_output=True,
                                check=True).stdout.decode().split("\0")
    except (OSError, subprocess.CalledProcessError):
        listed = []
    if listed:
        for name in filter(None, listed):
            src = ROOT / name
            if src.is_file():
                (dest / name).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(src, dest / name)
        return
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info", ".hypothesis", "*.pyc")
    for name in COPY:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=ignore)
        elif src.exists():
            shutil.copy2(src, dest / name)


def _stale(mutations: list[Mutation]) -> list[str]:
    """One line per mutation whose ``old`` text or tests are not where it expects them."""
    out = []
    for m in mutations:
        path = ROOT / m.path
        n = path.read_text(encoding="utf-8").count(m.old) if path.is_file() else None
        if n is None:
            out.append(f"{m.name}: {m.path} does not exist")
        elif n != m.count:
            out.append(f"{m.name}: its text occurs {n} times in {m.path}, expected {m.count}")
        out += [f"{m.name}: test path {t} does not exist" for t in m.tests
                if not (ROOT / t).exists()]
    return out


def _pytest(tree: Path, tests: tuple[str, ...], timeout: float) -> tuple[int, str]:
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    # slow tests included (-m overrides the default 'not slow'): a parity guard moved to
    # the slow set still kills its mutations
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider",
           "--no-header", "-m", "not gpu", *tests]
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
    unknown = sorted(set(args.only or ()) - {m.name for m in MUTATIONS})
    if unknown:
        print(f"unknown mutation(s): {', '.join(unknown)} (see --list)", file=sys.stderr)
        return 2
    if args.list or not chosen:
        for m in MUTATIONS:
            print(f"{m.name:34s} {m.path}: {m.why}")
        return 0 if args.list else 2
    stale = _stale(chosen)
    if stale:  # a mutation that no longer applies tests nothing: refuse to run
        print("tools/mutations.py is out of date with the source:", file=sys.stderr)
        for line in stale:
            print(f"  {line}", file=sys.stderr)
        return 2
    print(f"mutations: {len(chosen)}; load {os.getloadavg()[0]:.2f}", flush=True)
    killed = 0
    with tempfile.TemporaryDirectory(prefix="seaecho-mutations-") as tmp:
        tree = Path(tmp)
        _copy_tree(tree)
        for m in chosen:
            path = tree / m.path
            original = path.read_text(encoding="utf-8")
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
