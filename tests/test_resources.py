"""Resource estimate (``seaecho.checks.resources``): window parity with the radar, refusal of
runs that cannot fit, and a measured peak below the estimate."""

from __future__ import annotations

import json
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from seaecho.build import build_radar
from seaecho.checks.resources import estimate, memory_limit, window_size
from seaecho.cli import main
from seaecho.config import SceneError, load_scene, parse_scene
from seaecho.constants import C0
from seaecho.radar.system import RadarSystem

ROOT = Path(__file__).resolve().parents[1]
SCENES = sorted((ROOT / "scenes").glob("*.toml"))
CAL = ROOT / "scenes" / "calibration_point_target.toml"


def _cal(**radar) -> dict:
    d = tomllib.loads(CAL.read_text())
    d["radar"].update(radar)
    return d


@pytest.mark.parametrize("path", SCENES, ids=[p.name for p in SCENES])
def test_window_size_is_the_radar_window(path):
    """Parity: the estimate's samples and NUFFT period are the radar's own, computed
    without building it (building it allocates the window). A perturbed track (the
    shipborne radar's random roll) widens the estimate by its 8-sigma bound: there the
    estimate is an upper bound, by at most that bound's samples."""
    from seaecho.build import receiver_scene
    from seaecho.checks.resources import perturbation_bound

    scene = load_scene(path)
    # [[receivers]]: each receiver's bistatic scene (the estimate's, resources.py)
    for sc in ([receiver_scene(scene, i) for i in range(len(scene.receivers))]
               if scene.receivers else [scene]):
        radar = RadarSystem(build_radar(sc))
        n_s, n_fft, n_p = window_size(sc)
        slack_m = (perturbation_bound(sc.transmitter)
                   + perturbation_bound(sc.receiver or sc.transmitter))
        if slack_m == 0.0:
            assert (n_s, n_fft, n_p) == (radar.window.n_samples, radar.n_fft,
                                         radar.waveform.n_samples)
        else:
            extra = n_s - radar.window.n_samples
            assert 0 <= extra <= np.ceil(2.0 * slack_m / C0 * sc.radar.sampling_rate_hz) + 1
            assert n_p == radar.waveform.n_samples


@pytest.mark.parametrize("radar", [
    {"window_start_m": 500.0, "window_end_m": 900.0},
    {"sea_clutter": True, "n_pulses": 3, "start_time_s": -0.5},
    {"waveform": {"kind": "pulse", "duration_s": 1e-6}, "sampling_rate_hz": 3e6},
])
def test_window_size_variants(radar):
    scene = parse_scene(_cal(**radar))
    r = RadarSystem(build_radar(scene))
    assert window_size(scene)[:2] == (r.window.n_samples, r.n_fft)


def test_perturbed_window_is_bounded_above():
    d = _cal()
    d["transmitter"]["perturbation"] = {"position_sigma_m": [3.0, 3.0, 1.0]}
    scene = parse_scene(d)
    assert window_size(scene)[0] >= RadarSystem(build_radar(scene)).window.n_samples


def test_run_refuses_what_cannot_fit_before_allocating(tmp_path, capsys):
    # bandwidth_hz = 1 Hz on the calibration scene: the automatic window grew by
    # 4 c / (2 B) = 600,000 km on each side, 8e8 samples per pulse; the run allocated
    # ~12 GiB and, with no memory limit, grew to 24 GB until the system killed it. The
    # schema now needs B T >= 1: the narrowest chirp it allows, B = 100 Hz over
    # T = 10 ms, still widens the window by 6,000 km (1.6e7 samples per pulse, 2e6 in
    # the pulse), which a 16 GB limit refuses
    d = _cal()
    d["radar"]["prf_hz"] = 50.0
    d["radar"]["waveform"].update(bandwidth_hz=100.0, duration_s=1.0e-2)
    from seaecho.config.toml_writer import dumps

    scene = tmp_path / "s.toml"
    scene.write_text(dumps(d))
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "x.nc"), "-q"] if command == "run" else []
        assert main([command, str(scene), "--max-memory-gb", "16", *extra]) == 2
        err = capsys.readouterr().err
        assert "does not fit in memory" in err and "Traceback" not in err
        for field in ("[radar.waveform].bandwidth_hz", "[radar].sampling_rate_hz",
                      "[radar].n_pulses", "window_start_m", "limit"):
            assert field in err, err
    assert sorted(tmp_path.iterdir()) == [scene]


def test_huge_aperture_is_refused_by_its_pattern_normalisation(tmp_path, capsys):
    # Found by the fuzzing suite: a 100 m aperture at 1 THz (both allowed) needs
    # 2.7e6 Gauss-Legendre nodes, an eigenvalue problem of 58 TB
    d = _cal(carrier_frequency_hz=1e12)
    d["transmitter"]["antenna"]["width_m"] = 100.0
    from seaecho.config.toml_writer import dumps

    scene = tmp_path / "s.toml"
    scene.write_text(dumps(d))
    assert main(["check", str(scene)]) == 2
    err = capsys.readouterr().err
    assert "antenna pattern" in err and "width_m" in err


def test_check_prints_the_estimate(capsys):
    assert main(["check", str(CAL)]) == 0
    out = capsys.readouterr().out
    assert "estimated peak memory" in out and "run time ~" in out


def test_memory_limit_sources(monkeypatch):
    avail, _ = memory_limit()
    monkeypatch.setenv("SEAECHO_MAX_MEMORY_GB", "0.5")
    assert memory_limit() == (0.5e9, "SEAECHO_MAX_MEMORY_GB") or avail < 0.5e9
    assert memory_limit(0.25) == (0.25e9, "--max-memory-gb") or avail < 0.25e9
    monkeypatch.setenv("SEAECHO_MAX_MEMORY_GB", "lots")
    with pytest.raises(SceneError, match="SEAECHO_MAX_MEMORY_GB"):
        memory_limit()


def test_bad_max_memory_option(capsys):
    assert main(["check", str(CAL), "--max-memory-gb", "-1"]) == 2
    assert "--max-memory-gb" in capsys.readouterr().err


#: Runs a command and prints its peak RSS [kB] (ru_maxrss of the children).
WRAPPER = ("import json, resource, subprocess, sys\n"
           "r = subprocess.run(sys.argv[1:], capture_output=True, text=True)\n"
           "print(json.dumps([r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN)"
           ".ru_maxrss, r.stdout, r.stderr]))\n")


@pytest.mark.slow  # a run in its own process, 3-4 s
def test_measured_peak_of_a_small_run_is_below_the_estimate(tmp_path):
    """The estimate is an upper bound: `seaecho run` of the calibration scene (4 pulses,
    figures drawn) in its own process peaks below what `check` announces."""
    scene = parse_scene(_cal(n_pulses=4))
    from seaecho.config.toml_writer import dumps

    path = tmp_path / "s.toml"
    path.write_text(dumps(_cal(n_pulses=4)))
    script = Path(sys.executable).with_name("seaecho")
    r = subprocess.run([sys.executable, "-c", WRAPPER, str(script), "run", str(path),
                        "-o", str(tmp_path / "o.nc"), "-q"], capture_output=True, text=True,
                       timeout=300, check=True)
    rc, peak_kb, out, err = json.loads(r.stdout)
    assert rc == 0, err
    est = estimate(scene, figures=True)
    assert "estimated peak memory" in out
    assert peak_kb * 1024 < est.peak_bytes
    assert est.peak_bytes < 2.0 * peak_kb * 1024  # and not uselessly loose


def test_perturbation_step_of_5e_324_is_refused(tmp_path, capsys):
    # Found while fuzzing: the Gauss-Markov grid of a 5e-324 s step has infinitely many
    # steps; int(ceil(inf)) raised OverflowError in the estimate itself
    from seaecho.config.toml_writer import dumps

    d = _cal()
    d["transmitter"]["perturbation"] = {"position_sigma_m": [1.0, 1.0, 1.0], "step_s": 5e-324}
    scene = tmp_path / "s.toml"
    scene.write_text(dumps(d))
    assert main(["check", str(scene)]) == 2
    err = capsys.readouterr().err
    assert "perturbation unbounded" in err and "step_s" in err and "Traceback" not in err


TRIHEDRAL = ROOT / "scenes" / "calibration_trihedral.toml"


def test_bistatic_hull_traces_count_the_reverse_launch():
    """A bistatic trace launches from T and from R (the reciprocal mean, eq X2 of
    ``seaecho.tracing.sbr``): the estimate counts two sources, the monostatic one."""
    from seaecho.checks.resources import hull_sizes

    d = tomllib.loads(TRIHEDRAL.read_text())
    mono = parse_scene(d)
    d["receiver"] = {"motion": "fixed", "position_m": [-400.0, 150.0, 250.0],
                     "antenna": dict(d["transmitter"]["antenna"])}
    bi = parse_scene(d)
    (hm,), (hb,) = hull_sizes(mono, TRIHEDRAL.parent), hull_sizes(bi, TRIHEDRAL.parent)
    assert (hm.sources, hb.sources) == (1, 2)
    assert hm.traces == hb.traces == 1  # fixed platforms, a fixed reflector
    em = estimate(mono, figures=False, base_dir=TRIHEDRAL.parent)
    eb = estimate(bi, figures=False, base_dir=TRIHEDRAL.parent)
    assert eb.hull_rays == pytest.approx(2 * em.hull_rays, rel=1e-12)
    assert em.hull_rays == pytest.approx(hm.grid, rel=1e-12)


def test_reciprocal_trace_is_two_one_way_launches():
    """What the factor 2 above stands for: the rays of a bistatic reciprocal trace are
    those of the one-way traces from T and from R (a 0.2 m PEC plate)."""
    import numpy as np

    from seaecho.tracing.sbr import SBROptions, TraceMesh, trace_signature

    v = np.array([[-0.1, -0.1, 0.0], [0.1, -0.1, 0.0], [0.1, 0.1, 0.0], [-0.1, 0.1, 0.0]])
    plate = TraceMesh.single(v, [[0, 1, 2], [0, 2, 3]])
    tx, rx = np.array([-30.0, 0.0, 40.0]), np.array([20.0, 25.0, 35.0])
    one = SBROptions(reciprocal=False, max_bounces=1)
    both = trace_signature(plate, tx, rx, 10e9, options=SBROptions(max_bounces=1))
    n_t = trace_signature(plate, tx, rx, 10e9, options=one).n_rays
    n_r = trace_signature(plate, rx, tx, 10e9, options=one).n_rays
    assert both.n_rays == n_t + n_r and n_t > 0 and n_r > 0


def test_antenna_normalisation_time_follows_its_quadrature(monkeypatch):
    """The estimate sizes the pattern normalisation by the nodes the normalisation
    uses (the Gauss-Legendre rule of order 2 n_u that
    ``seaecho.radar.antennas.aperture_radiated_power`` asks scipy for), with the band
    and margin of its docstring: n = ceil(z + 4 z^(1/3)) + 32, z_u = pi (A + B) / 2,
    z_phi = pi B (A >= B the sides in wavelengths). A monostatic radar's aperture
    counts once (the normalisation is cached)."""
    import math

    import scipy.special

    from seaecho.checks.resources import antenna_quadratures
    from seaecho.constants import C0
    from seaecho.radar import antennas

    scene = load_scene(ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml")
    assert scene.receiver is None
    ant = scene.transmitter.antenna
    lam = C0 / scene.radar.carrier_frequency_hz
    big, small = sorted((ant.width_m / lam, ant.height_m / lam), reverse=True)
    z_u, z_phi = math.pi * (big + small) / 2, math.pi * small
    expected = (math.ceil(z_u + 4 * z_u ** (1 / 3)) + 32,
                math.ceil(z_phi + 4 * z_phi ** (1 / 3)) + 32)
    assert antenna_quadratures(scene) == [expected]
    orders = []
    real = scipy.special.roots_legendre
    monkeypatch.setattr(scipy.special, "roots_legendre",
                        lambda n: orders.append(n) or real(n))
    antennas.aperture_radiated_power.__wrapped__(ant.width_m, ant.height_m, lam)
    assert orders == [2 * expected[0]]
