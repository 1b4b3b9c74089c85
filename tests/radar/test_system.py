"""The radar chain on point targets: calibration, delay, Doppler, polarisation, noise."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.processing.range_compression import range_compress
from seaecho.radar.equation import bistatic_received_power, propagation_delay, time_of_flight
from seaecho.radar.system import RadarSystem

RECT_T = {"pattern": "rectangular", "width_m": 0.18, "height_m": 0.14, "look_at_m": (0, 0, 0)}
RECT_R = {"pattern": "rectangular", "width_m": 0.30, "height_m": 0.20, "look_at_m": (0, 0, 0)}


def _scene(targets, tx=None, rx=None, **radar):
    r = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6, "prf_hz": 1e3,
         "n_pulses": 4, "sea_clutter": False, "transmit_power_w": 100.0,
         "waveform": {"kind": "lfm", "bandwidth_hz": 100e6, "duration_s": 2e-6}}
    r.update(radar)
    d = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64}, "radar": r,
         "transmitter": tx or {"position_m": (-500, 0, 300), "antenna": RECT_T},
         "targets": targets}
    if rx is not False:
        d["receiver"] = rx or {"position_m": (200, 100, 80), "antenna": RECT_R}
    return parse_scene(d)


def _upsampled_peak(y, up=64):
    """Peak |y|^2 and its position [samples] by zero-padding the spectrum."""
    n = y.size
    spec = np.fft.fft(y)
    pad = np.concatenate([spec[: n // 2], np.zeros(n * (up - 1)), spec[n // 2:]])
    yu = np.fft.ifft(pad) * up
    i = int(np.argmax(np.abs(yu)))
    return np.abs(yu[i]) ** 2, i / up, yu[i]


@pytest.mark.parametrize("position", [(3.0, -2.0, 1.0), (-20.0, 15.0, 0.0), (0.3, 0.1, 2.0)])
def test_point_target_power_is_bistatic_radar_equation(position):
    # P_r = P_t G_t G_r lambda^2 sigma / ((4 pi)^3 r_t^2 r_r^2) (Skolnik, Radar Handbook
    # 3rd ed. 2008, eq 23.1; Willis, Bistatic Radar 2005, eq 3.1) within 0.1 dB, from the
    # range-compressed peak (upsampled 64x so the fractional delay does not bias it).
    sc = _scene([{"position_m": position, "rcs_m2": 10.0}])
    radar = RadarSystem(build_radar(sc))
    geo = radar.geometry(0)
    echo = radar.target_echo(geo)
    raw = radar.receive(0, [echo])
    # gains and ranges from first principles, independently of the chain
    p_t, p_r = geo.tx.position, geo.rx.position
    r_t = np.linalg.norm(np.array(position) - p_t)
    r_r = np.linalg.norm(np.array(position) - p_r)
    d_t = (np.array(position) - p_t) / r_t
    d_r = (np.array(position) - p_r) / r_r
    g_t = radar.tx_antenna.gain_local(geo.tx_axes.T @ d_t)
    g_r = radar.rx_antenna.gain_local(geo.rx_axes.T @ d_r)
    expected = bistatic_received_power(100.0, g_t, g_r, C0 / 1e10, 10.0, r_t, r_r)
    for ch in (0, 3):  # HH, VV
        y = range_compress(raw[ch], radar.waveform.samples)
        peak, _, _ = _upsampled_peak(y)
        assert 10 * np.log10(peak / expected) == pytest.approx(0.0, abs=0.1)
    # and the received energy is P_r times the pulse energy (Parseval), within 0.01 dB
    energy = np.sum(np.abs(raw[0]) ** 2) / np.sum(np.abs(radar.waveform.samples) ** 2)
    assert 10 * np.log10(energy / expected) == pytest.approx(0.0, abs=0.01)


def test_delay_lands_at_fractional_fast_time_position():
    # The compressed peak sits at (tau - t0) f_s with tau = (r_t + r_r) / c, to 1 % of a
    # sample: the fractional delay is kept exactly (no rounding to a sample).
    for dx in (0.0, 0.2, 0.37, 0.61):
        sc = _scene([{"position_m": (dx, 0.0, 0.0), "rcs_m2": 1.0}],
                    window_start_m=380.0, window_end_m=440.0)
        radar = RadarSystem(build_radar(sc))
        geo = radar.geometry(0)
        raw = radar.receive(0, [radar.target_echo(geo)])
        tau = (np.linalg.norm(np.array([dx, 0, 0]) - geo.tx.position)
               + np.linalg.norm(np.array([dx, 0, 0]) - geo.rx.position)) / C0
        _, pos, _ = _upsampled_peak(range_compress(raw[0], radar.waveform.samples))
        assert pos == pytest.approx((tau - radar.window.t0) * radar.window.sampling_rate,
                                    abs=0.01)


@pytest.mark.parametrize("case", ["moving_target", "moving_transmitter", "moving_receiver"])
def test_pulse_to_pulse_phase_follows_doppler(case):
    # f_D = -(1/lambda) d(r_t + r_r)/dt (Willis 2005, eq 3.23): the phase of the
    # compressed peak advances by 2 pi f_D / PRF from pulse to pulse. d(r_t + r_r)/dt is
    # the projection of the velocities on the unit vectors, computed here directly.
    v = np.array([7.0, -4.0, 0.5])
    tx = {"position_m": (-500, 0, 300), "antenna": RECT_T}
    rx = {"position_m": (200, 100, 80), "antenna": RECT_R}
    target = {"position_m": (3.0, -2.0, 1.0), "rcs_m2": 10.0}
    if case == "moving_target":
        target["velocity_m_s"] = tuple(v)
    elif case == "moving_transmitter":
        tx.update(motion="linear", velocity_m_s=tuple(3 * v))
    else:
        rx.update(motion="linear", velocity_m_s=tuple(3 * v))
    radar = RadarSystem(build_radar(_scene([target], tx=tx, rx=rx, prf_hz=4000.0)))
    compressed = [range_compress(radar.receive(p, [radar.target_echo(radar.geometry(p))])[0],
                                 radar.waveform.samples) for p in range(3)]
    i0 = int(np.argmax(np.abs(compressed[0])))  # same range cell on every pulse
    peaks = [y[i0] for y in compressed]
    t = radar.emission_time(1)
    geo = radar.geometry(1)
    pos = np.array(target["position_m"]) + t * np.array(target.get("velocity_m_s", (0, 0, 0)))
    u_t = (pos - geo.tx.position) / np.linalg.norm(pos - geo.tx.position)
    u_r = (pos - geo.rx.position) / np.linalg.norm(pos - geo.rx.position)
    v_tgt = np.array(target.get("velocity_m_s", (0, 0, 0)))
    rate = np.dot(v_tgt - geo.tx.velocity, u_t) + np.dot(v_tgt - geo.rx.velocity, u_r)
    f_d = -rate / radar.wavelength
    measured = np.angle(peaks[2] / peaks[1])
    expected = np.angle(np.exp(2j * np.pi * f_d / radar.prf))
    assert abs(f_d / radar.prf) < 0.5  # unambiguous
    assert measured == pytest.approx(expected, abs=2e-3)


def test_h_only_radar_sees_no_v_only_scatterer():
    # Ideal H ports on level platforms project to exactly zero on a scatterer with only
    # s_vv (forward scattering alignment, docs/conventions.md); VV sees it.
    sc = _scene([{"position_m": (3.0, -2.0, 1.0), "s_vv": (2.0, 1.0)}],
                channels=["HH", "VV"])
    radar = RadarSystem(build_radar(sc))
    raw = radar.receive(0, [radar.target_echo(radar.geometry(0))])
    assert radar.channel_names == ["HH", "VV"]
    assert np.abs(raw[0]).max() == 0.0
    assert np.abs(raw[1]).max() > 1e-9


def test_channels_quad_pol_map_scattering_matrix():
    # Each channel mn carries s_mn (m received, n transmitted), ordered HH, HV, VH, VV
    s = {"s_hh": (1.0, 0.0), "s_hv": (0.0, 0.5), "s_vh": (0.25, 0.0), "s_vv": (0.0, -2.0)}
    sc = _scene([{"position_m": (0.0, 0.0, 0.0), **s}])
    radar = RadarSystem(build_radar(sc))
    echo = radar.target_echo(radar.geometry(0))
    a = echo.amplitudes[:, 0]
    ratio = a / a[0]
    np.testing.assert_allclose(ratio, [1.0, 0.5j, 0.25, -2.0j], atol=1e-12)


def test_monostatic_uses_transmitter_for_reception():
    sc = _scene([{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 1.0}], rx=False)
    radar = RadarSystem(build_radar(sc))
    assert radar.monostatic and radar.rx is radar.tx
    echo = radar.target_echo(radar.geometry(0))
    assert echo.r_t[0] == pytest.approx(echo.r_r[0], rel=1e-9)
    assert echo.g_t[0] == pytest.approx(echo.g_r[0], rel=1e-12)


def test_thermal_noise_power_is_ktbf():
    # E|n|^2 = k T0 F B (Skolnik 2008, eq 1.8) with the constants written out here, not
    # taken from the package: k = 1.380649e-23 J/K (exact, SI 2019) and the standard
    # reference temperature T0 = 290 K (IEEE Std 145 / Skolnik 2008, sec. 1.4); F = 3 dB,
    # B = 200 MHz. 4 x 431 samples x 100 pulses: the relative standard error of the mean
    # power is 1/sqrt(172400) = 0.24 %; tolerance 1.2 % (5 standard errors), while
    # T0 = 300 K or a noise figure off by 0.15 dB would be 3.4 % off. (Compared as a
    # ratio: pytest.approx on the pW values would add its default 1e-12 absolute
    # tolerance, about 60 % here.)
    sc = _scene([], thermal_noise=True, noise_figure_db=3.0, window_start_m=500.0,
                window_end_m=800.0, n_pulses=100)
    radar = RadarSystem(build_radar(sc))
    powers = [np.mean(np.abs(radar.receive(p, [])) ** 2) for p in range(100)]
    expected = 1.380649e-23 * 290.0 * 10 ** (3.0 / 10.0) * 200e6
    assert np.mean(powers) / expected == pytest.approx(1.0, abs=0.012)
    # same pulse, same draw; another pulse, another draw
    np.testing.assert_array_equal(radar.receive(3, []), radar.receive(3, []))
    assert not np.array_equal(radar.receive(3, []), radar.receive(4, []))


def test_time_of_flight_closed_form():
    # Static case: tau = |d| / c; receding scatterer at speed v along the line of sight:
    # c tau = |d| + v tau, i.e. tau = |d| / (c - v) (exact, eq R3)
    d = np.array([300.0, 400.0, 0.0])
    assert propagation_delay(d, np.zeros(3)) == pytest.approx(500.0 / C0, rel=1e-15, abs=0)
    u = d / 500.0
    assert propagation_delay(d, 1000.0 * u) == pytest.approx(500.0 / (C0 - 1000.0),
                                                            rel=1e-13, abs=0)
    tau_t, tau_r, _ = time_of_flight(np.zeros(3), d, np.zeros(3), 2 * d, np.zeros(3))
    assert tau_t == pytest.approx(tau_r, rel=1e-15, abs=0)  # delays [s]: no abs tol


def test_bad_channel_names_rejected():
    with pytest.raises(ValueError, match="channel"):
        RadarSystem(build_radar(_scene([{"position_m": (0, 0, 0), "rcs_m2": 1.0}],
                                        channels=["HR"])))


def test_circular_ports_on_a_monostatic_sphere():
    # A sphere in backscatter is s_hh = -s_vv in the FSA bases (h_s = -h_i, v_s = v_i)
    # and reverses the handedness of a circular wave: same-sense channels (RR, LL) see
    # nothing, opposite-sense ones (RL, LR) the whole RCS (Ulaby & Elachi, Radar
    # Polarimetry for Geoscience Applications, 1990, ch. 1).
    ant = {**RECT_T, "basis": "circular"}
    sc = _scene([{"position_m": (0.0, 0.0, 0.0), "s_hh": (1.0, 0.0), "s_vv": (-1.0, 0.0)}],
                tx={"position_m": (-500, 0, 300), "antenna": ant}, rx=False,
                channels=["RR", "RL", "LR", "LL"])
    radar = RadarSystem(build_radar(sc))
    a = np.abs(radar.target_echo(radar.geometry(0)).amplitudes[:, 0])
    assert a[0] < 1e-12 * a[1] and a[3] < 1e-12 * a[1]
    assert a[1] == pytest.approx(a[2], rel=1e-12, abs=0)  # amplitudes ~1e-9


def test_cross_polar_isolation_two_way():
    # Ports with isolation X dB: an H-only radar sees a V-only scatterer through the
    # leakage of both antennas, x^2 in amplitude, i.e. -2X dB in power (to first order)
    x_db = 30.0
    ant_t = {**RECT_T, "cross_polar_isolation_db": x_db}
    ant_r = {**RECT_R, "cross_polar_isolation_db": x_db}
    sc = _scene([{"position_m": (0.0, 0.0, 0.0), "s_vv": (1.0, 0.0)}],
                tx={"position_m": (-500, 0, 300), "antenna": ant_t},
                rx={"position_m": (200, 100, 80), "antenna": ant_r}, channels=["HH", "VV"])
    radar = RadarSystem(build_radar(sc))
    a = np.abs(radar.target_echo(radar.geometry(0)).amplitudes[:, 0])
    x2 = 10 ** (-x_db / 10)
    assert 20 * np.log10(a[0] / a[1]) == pytest.approx(20 * np.log10(x2), abs=0.01)


def test_true_track_drives_the_echo():
    # With a Gauss-Markov perturbation the echo's range is that of the true (perturbed)
    # transmitter, not of the nominal one
    tx = {"position_m": (-500, 0, 300), "antenna": RECT_T,
          "perturbation": {"position_sigma_m": (2.0, 2.0, 2.0), "position_tau_s": 1.0,
                           "attitude_sigma_deg": (0.5, 0.5, 0.5)}}
    sc = _scene([{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 1.0}], tx=tx)
    radar = RadarSystem(build_radar(sc))
    geo = radar.geometry(2)
    echo = radar.target_echo(geo)
    true = radar.tx.state(geo.time).position
    nominal = radar.tx.nominal_state(geo.time).position
    assert np.linalg.norm(true - nominal) > 0.01
    assert echo.r_t[0] == pytest.approx(np.linalg.norm(true), rel=1e-12)
    # the attitude error moves the (platform-fixed) beam: the gain is not the nominal one
    axes_nominal = radar.tx_pointing.axes(radar.tx.nominal_state(geo.time))
    assert not np.allclose(geo.tx_axes, axes_nominal)
