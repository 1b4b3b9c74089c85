"""The evolving speckle of the facets (scattering/dynamics.py, eqs D2-D8)."""

import math

import numpy as np
import pytest

from seaecho.constants import C0, SURFACE_TENSION_OVER_DENSITY, G
from seaecho.geometry import frames
from seaecho.ocean.dispersion import phase_speed
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.ocean.twoscale import orbital_velocity_covariance
from seaecho.scattering.breaking import (
    dissipation_exponent,
    wind_growth_rate,
)
from seaecho.scattering.dynamics import (
    EvolvingSpeckle,
    SeaDynamics,
    bragg_frequency,
    bragg_lifetime,
    coherence_time,
    speckle_autocorrelation,
    travel_fraction,
    window_autocorrelation,
)
from seaecho.scattering.facet import FacetModel, speckled_facet_amplitudes
from seaecho.scattering.spectrum_table import BraggSpectrumTable

K = 2 * np.pi * 10e9 / C0
EPS = 55.9 - 37.0j


def _constant_table(value, k_min=1.0, k_max=20 * K):
    return BraggSpectrumTable(lambda kx, ky: np.full(np.shape(kx), float(value)), k_min,
                              k_max, n_k=16, n_psi=16)


def _dynamics(lifetime=1e3, cov=None, travel=None, breaker=(0.0, 0.0, 0.0),
              current=(0.0, 0.0)):
    life = dict.fromkeys(("specular", "bragg+", "bragg-", "breaking"), lifetime)
    return SeaDynamics(lifetimes=life,
                       velocity_covariance=np.zeros((3, 3)) if cov is None else cov,
                       breaker_velocity=np.array(breaker), travel=travel, current=current)


def _sample_acf(process, lags_s, n_starts=40, lifetime=1.0):
    """Sample E[g(t + tau) g*(t)] over facets and over start times spread evenly on one
    anchor interval (the anchor phase average of eq D5)."""
    out = np.zeros(len(lags_s), dtype=complex)
    for t0 in (np.arange(n_starts) + 0.5) / n_starts * lifetime + 3.0 * lifetime:
        g0 = process(t0)
        for j, tau in enumerate(lags_s):
            out[j] += np.mean(process(t0 + tau) * np.conj(g0))
    return out / n_starts


def test_anchor_cross_fade_has_the_stated_autocorrelation():
    # Eq D4-D5 with sigma_f = 0, f0 = 0: R_T(tau) = sin(pi x/2)/pi + (1 - x/2) cos(pi x/2),
    # x = tau / T (0 beyond 2T). 4000 facets x 40 start times: within 0.03.
    T = 0.5
    sp = EvolvingSpeckle(_dynamics(lifetime=T), seed=3, n_facets=4000)
    lags = np.array([0.0, 0.1, 0.25, 0.5, 0.75, 1.0, 1.5])
    acf = _sample_acf(lambda t: sp.process_values("specular", t, 0.0, 0.0), lags,
                      lifetime=T)
    np.testing.assert_allclose(acf.real, window_autocorrelation(lags, T), atol=0.03)
    np.testing.assert_allclose(acf.imag, 0.0, atol=0.03)
    # unit variance at every time (eqs P4-P5 unchanged): the cross-fade keeps |g|^2 = 1
    g = sp.process_values("specular", 0.37, 0.0, 0.0)
    assert np.mean(np.abs(g) ** 2) == pytest.approx(1.0, rel=0.05)
    # the closed form: 1 at 0, 0.69 at T/2, 0 at 2 T
    assert window_autocorrelation(0.0, T) == pytest.approx(1.0)
    assert window_autocorrelation(T / 2, T) == pytest.approx(
        np.sin(np.pi / 4) / np.pi + 0.75 * np.cos(np.pi / 4))
    assert window_autocorrelation(2 * T, T) == pytest.approx(0.0, abs=1e-15)


def test_doppler_spread_and_shift_multiply_the_autocorrelation():
    # Eq D5: a Gaussian Doppler spread sigma_f multiplies R_T by exp(-2 pi^2 sigma_f^2
    # tau^2), a shift f0 turns its phase by 2 pi f0 tau. sigma_f = 3 Hz, f0 = 7 Hz.
    T = 2.0
    sp = EvolvingSpeckle(_dynamics(lifetime=T), seed=4, n_facets=6000)
    lags = np.array([0.0, 0.02, 0.05, 0.08, 0.12])
    acf = _sample_acf(lambda t: sp.process_values("bragg+", t, 7.0, 3.0), lags,
                      n_starts=30, lifetime=T)
    ref = speckle_autocorrelation(lags, T, 3.0, 7.0)
    np.testing.assert_allclose(acf, ref, atol=0.03)
    # the 1/e coherence time of the stated model: Gaussian alone, 1/(sqrt(2) pi sigma_f)
    assert coherence_time(1e6, 3.0) == pytest.approx(1 / (np.sqrt(2) * np.pi * 3.0),
                                                     rel=1e-6)
    assert coherence_time(T, 0.0) < 2 * T


def _bragg_series(p_plus, theta_deg=45.0, prf=200.0, n=256, current=(0.0, 0.0)):
    """Coherent sum over flat facets of the Bragg amplitude (VV) of eq P4 with the
    evolving draws, pulse by pulse (monostatic, no resolved motion, no spread)."""
    m = 400
    theta = np.radians(theta_deg)
    n_i, n_s = frames.directions_from_angles(np.full(m, theta), np.zeros(m),
                                             np.full(m, theta), np.full(m, np.pi))
    normal = np.tile([0.0, 0.0, 1.0], (m, 1))
    sp = EvolvingSpeckle(_dynamics(travel=_constant_table(p_plus), current=current), seed=1,
                         n_facets=m)
    table = _constant_table(1e-8)
    out = []
    for p in range(n):
        a = speckled_facet_amplitudes(n_i, n_s, normal, np.ones(m),
                                      FacetModel(K, EPS, table, 0.01, 0.01, 0.0, model="spm"),
                                      draws=sp.draws(p / prf), backend="numpy")
        out.append(a[:, 3].sum())
    return _line_frequency(out, prf)


def _line_frequency(series, prf: float) -> float:
    """Frequency [Hz] of the strongest line of a pulse series (Hann window, parabolic
    interpolation of the peak in dB)."""
    n = len(series)
    spec = np.abs(np.fft.fftshift(np.fft.fft(np.array(series) * np.hanning(n)))) ** 2
    f = np.fft.fftshift(np.fft.fftfreq(n, 1 / prf))
    i = int(np.argmax(spec))
    y0, y1, y2 = np.log(spec[i - 1: i + 2])
    return f[i] + 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2) * (f[1] - f[0])


def test_bragg_lines_at_the_dispersion_relation_with_the_right_sign():
    # A single Bragg wave train: the echo is a line at the Bragg wave's frequency
    # f_B = sqrt(g k_B (1 + (k_B / k_m)^2)) / 2 pi, k_m = sqrt(g / tau) (gravity-capillary
    # dispersion; Crombie 1955, Wright 1968, Valenzuela 1978), k_B = 2 k sin(theta) in
    # back-scatter: +f_B for a wave travelling towards the radar (approaching), -f_B for
    # one travelling away. At 10 GHz and 45 deg: 10.99 Hz. Within 0.1 Hz (bins of 0.78).
    k_b = 2 * K * np.sin(np.radians(45.0))
    k_m = np.sqrt(G / SURFACE_TENSION_OVER_DENSITY)
    f_b = np.sqrt(G * k_b * (1 + (k_b / k_m) ** 2)) / (2 * np.pi)
    assert f_b == pytest.approx(10.99, abs=0.01)
    assert float(bragg_frequency(k_b)) == pytest.approx(f_b, rel=1e-12)
    assert _bragg_series(1.0) == pytest.approx(f_b, abs=0.1)
    assert _bragg_series(0.0) == pytest.approx(-f_b, abs=0.1)


def test_travel_fraction_of_the_spreading_function_and_of_the_wind_input():
    # Longuet-Higgins cos^2s(psi/2): the fraction of the density at +-K travelling along
    # +K is cos^2s(psi/2) / (cos^2s(psi/2) + sin^2s(psi/2)), cos^2(psi/2) for s = 1.
    lh = DirectionalSpectrum(spectrum="pierson-moskowitz", spreading="longuet-higgins",
                             u19_5=8.0, s=1.0)
    psi = np.linspace(-3.0, 3.0, 13)
    p = travel_fraction(lh, 300 * np.cos(psi), 300 * np.sin(psi), 7.6)
    np.testing.assert_allclose(p, np.cos(psi / 2) ** 2, rtol=1e-9)
    # Elfouhaily's spreading is centro-symmetric: KHCC03's wind input beta ~ cos|cos|
    # (eq BR4) feeds only the waves travelling with the wind: upwind-travelling Bragg
    # waves carry everything (1), downwind 0, crosswind 1/2.
    el = DirectionalSpectrum(spectrum="elfouhaily", u19_5=8.0)
    p = travel_fraction(el, 300 * np.cos([0.0, np.pi, np.pi / 2]),
                        300 * np.sin([0.0, np.pi, np.pi / 2]), 7.6)
    np.testing.assert_allclose(p, [1.0, 0.0, 0.5], atol=1e-12)


def test_bragg_lifetime_is_the_relaxation_time_of_the_khcc03_balance():
    # Integrate dB/dt = omega beta_nu B - omega B (B / alpha)^n (KHCC03's short-wave
    # balance, equilibrium B = alpha beta_nu^(1/n)) from B = 1.2 B_eq: the excess decays
    # as exp(-t / T) with T of eq D6 (within 2 %; alpha drops out).
    k, u10 = 300.0, 8.0
    omega = k * float(phase_speed(k))
    beta_nu = float(wind_growth_rate(k, 0.0, u10)) - 4 * 1.05e-6 * k**2 / omega
    n = float(dissipation_exponent(k))
    b_eq = beta_nu ** (1 / n)
    T = bragg_lifetime(k, u10)
    b, dt = 1.01 * b_eq, T / 2000
    for _ in range(2000):
        b += dt * (omega * beta_nu * b - omega * b * b**n)
    assert (b - b_eq) / (0.01 * b_eq) == pytest.approx(np.exp(-1.0), rel=0.02)
    assert 0.05 < T < 5.0
    assert bragg_lifetime(300.0, 1.0) > bragg_lifetime(300.0, 8.0)  # weaker wind: slower


def test_orbital_velocity_covariance_of_the_band_is_that_of_the_surface():
    # Eq U2 against the particle velocities of synthesised surfaces (Lamb 1932, art.
    # 228): in deep water the horizontal speed variance equals the vertical one; the
    # vertical variance of 8 realisations of a 16 m tile (band from the cell edge of its
    # lowest modes, pi / L, to the grid's Nyquist wavenumber) within 10 % (measured 5 %);
    # more along the wind than across it; horizontal and vertical velocities uncorrelated.
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=8.0)
    c = orbital_velocity_covariance(spec, np.pi / 16.0, np.pi / 0.125)
    samples = []
    for seed in range(8):
        surf = SeaSurface(spec, (16.0, 16.0), (128, 128), np.random.default_rng(seed))
        samples.append(np.cov(surf.fields(0.0).velocity.reshape(-1, 3).T))
    sample = np.mean(samples, axis=0)
    assert c[0, 0] + c[1, 1] == pytest.approx(c[2, 2], rel=1e-9)
    assert sample[2, 2] == pytest.approx(c[2, 2], rel=0.1)
    assert c[0, 0] > 1.5 * c[1, 1] and sample[0, 0] > 1.5 * sample[1, 1]
    assert abs(sample[0, 2]) < 0.05 * sample[2, 2]


def test_anchors_do_not_depend_on_the_order_of_requests():
    sp1 = EvolvingSpeckle(_dynamics(lifetime=0.1), seed=9, n_facets=50, cache_size=2)
    sp2 = EvolvingSpeckle(_dynamics(lifetime=0.1), seed=9, n_facets=50)
    ts = [0.95, 0.02, -0.3, 0.41, 0.02]
    a = [sp1.process_values("bragg-", t, 2.0, 1.5) for t in ts]
    b = [sp2.process_values("bragg-", t, 2.0, 1.5) for t in reversed(ts)][::-1]
    for x, y in zip(a, b, strict=True):
        assert x.tobytes() == y.tobytes()
    assert math.isfinite(float(np.abs(a[2]).sum()))


def test_device_copies_of_the_anchors_are_made_once():
    # On a GPU, a numpy anchor becomes a device array by a copy: it is made once per
    # anchor and kept while the anchor is used (not at every pulse). Emulated on the CPU
    # back end with the namespace named as a GPU's; values as the aliased arrays'.
    import copy

    from seaecho import backend

    if not backend.drjit_available():
        pytest.skip("Dr.Jit LLVM backend unavailable")
    llvm = backend.drjit_namespace()
    gpu = copy.copy(llvm)
    gpu.name = "cuda"
    sp = EvolvingSpeckle(_dynamics(lifetime=1.0), seed=5, n_facets=64)
    g = sp.process_values("specular", 0.10, 3.0, 0.5, gpu)  # anchors 0 and 1
    copies = {k: v[1] for k, v in sp._device.items()}
    assert len(copies) == 6
    for t in (0.15, 0.20):  # the same anchors: no new copy
        g = sp.process_values("specular", t, 3.0, 0.5, gpu)
    assert len(sp._device) == 6
    assert all(sp._device[k][1] is v for k, v in copies.items())
    ref = sp.process_values("specular", 0.20, 3.0, 0.5, llvm)
    np.testing.assert_array_equal(g.real.numpy(), ref.real.numpy())
    np.testing.assert_array_equal(g.imag.numpy(), ref.imag.numpy())
    sp.process_values("specular", 1.5, 3.0, 0.5, gpu)  # anchors 1 and 2: three more
    assert len(sp._device) == 9
    assert all(sp._device[k][1] is v for k, v in copies.items())


def test_bragg_lines_on_a_current_are_doppler_shifted():
    # On a uniform current U the Bragg waves turn at omega_0 +- k_B . U (Phillips 1977,
    # section 3.6; eq C1): both lines move by q . U / 2 pi = 2 U . r_hat / lambda. The
    # radar lies towards -x of the facets (azimuth pi of the scattered direction): a
    # current of 0.5 m/s along -x approaches it, +2 * 0.5 * sin(45 deg) / lambda =
    # +23.58 Hz at 10 GHz. Within 0.1 Hz, as the still-water lines.
    shift = 2 * 0.5 * np.sin(np.radians(45.0)) * K / (2 * np.pi)
    assert shift == pytest.approx(23.58, abs=0.01)
    k_b = 2 * K * np.sin(np.radians(45.0))
    f_b = float(bragg_frequency(k_b))
    assert _bragg_series(1.0, current=(-0.5, 0.0)) == pytest.approx(f_b + shift, abs=0.1)
    assert _bragg_series(0.0, current=(-0.5, 0.0)) == pytest.approx(-f_b + shift, abs=0.1)


def _breaking_series(breaker, short=None, prf=200.0, n=128):
    """Coherent sum over flat facets wholly covered by breaking zones (eq P7, q_f = 1) of
    the VV amplitude with the evolving draws (monostatic, 45 deg, radar towards -x)."""
    m = 100
    theta = np.radians(45.0)
    n_i, n_s = frames.directions_from_angles(np.full(m, theta), np.zeros(m),
                                             np.full(m, theta), np.full(m, np.pi))
    normal = np.tile([0.0, 0.0, 1.0], (m, 1))
    sp = EvolvingSpeckle(_dynamics(breaker=breaker), seed=2, n_facets=m, breaking=True)
    model = FacetModel(K, EPS, _constant_table(1e-8), 0.01, 0.01, 0.0, model="spm",
                       breaking_tilt=0.0)
    short = None if short is None else np.tile(short, (m, 1))
    out = []
    for p in range(n):
        a = speckled_facet_amplitudes(n_i, n_s, normal, np.ones(m), model,
                                      draws=sp.draws(p / prf, short), backend="numpy",
                                      breaking_fraction=np.ones(m))
        out.append(a[:, 3].sum())
    return _line_frequency(out, prf)


def test_breakers_ride_on_the_long_waves_only():
    # Eq BR10: the breaking zones' line is q . (c_br - v_short) / 2 pi, the fronts'
    # velocity on the facet's motion less the orbital velocity of the resolved waves
    # shorter than the modulating ones (breakers themselves, counted in c_br). Fronts at
    # 1 m/s towards the radar: 2 (1.0) sin(45 deg) / lambda = 47.2 Hz; with 0.3 m/s of
    # short-wave velocity towards it taken out, 33.0 Hz. Within 0.1 Hz.
    per_m_s = 2 * np.sin(np.radians(45.0)) * K / (2 * np.pi)
    assert _breaking_series((-1.0, 0.0, 0.0)) == pytest.approx(per_m_s, abs=0.1)
    assert _breaking_series((-1.0, 0.0, 0.0), (-0.3, 0.0, 0.0)) == pytest.approx(
        0.7 * per_m_s, abs=0.1)
