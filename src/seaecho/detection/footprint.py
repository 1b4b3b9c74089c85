"""The area of sea a range cell covers: the beam's half-power width and the pulse-limited
clutter cell, for false alarms per km^2 of range profiles.

A range profile's gate at slant range R of a monostatic radar, whose beam is theta_B
wide in azimuth (one-way half-power), covers on the sea the pulse-limited cell

.. math:: A_c = R\\,\\theta_B\\,\\Delta R\\,\\sec\\psi                              (F1)

(Skolnik 2001, section 7.1: the clutter area at low grazing, there with Delta R =
c tau / 2): the beam's arc R theta_B across, the range
extent Delta R projected on the sea along range. psi is the grazing angle at the cell:
sin psi = h / R on a flat Earth, eq (E1) of :mod:`seaecho.geometry.earth` on the 4/3 Earth
(the along-range derivative of the slant range on the sphere, dR/ds = cos psi, is the same
projection). It holds while the pulse, not the elevation beam, bounds the cell (R
theta_E / sin psi > Delta R sec psi: every low-grazing marine radar).

References
----------
Skolnik, M. I. (2001). *Introduction to Radar Systems*, 3rd ed. McGraw-Hill, section 7.1
(clutter cell area) and table 9.1 (half-power widths of line sources).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

__all__ = ["clutter_cell_area", "compressed_extent", "half_power_width", "level_extent"]


def _azimuth_cut(gain: Callable[[NDArray], NDArray]) -> Callable[[ArrayLike], NDArray]:
    """``a -> G`` of a pattern along its azimuth plane (x-y of the antenna frame) [rad]."""
    def g(a):
        a = np.asarray(a, dtype=float)
        return np.asarray(gain(np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], -1)),
                          dtype=float)
    return g


def half_power_width(gain: Callable[[NDArray], NDArray]) -> float:
    """Full width between the half-power points of a pattern in its azimuth plane [rad].

    Parameters
    ----------
    gain : callable
        ``d_local (..., 3) -> G`` in the antenna frame (x boresight, y along the width,
        z up), e.g. :meth:`seaecho.radar.antennas.Antenna.gain_local`.

    Returns
    -------
    float
        2 a_h, a_h the smallest angle off boresight in the x-y plane where G falls to half
        its boresight value (found on a grid, then by Brent's method); 2 pi for a pattern
        that never falls to half in azimuth (omnidirectional), taken symmetric.
    """
    g = _azimuth_cut(gain)
    peak = float(g(0.0))
    if not peak > 0:
        raise ValueError(f"gain at boresight = {peak}: no beam to measure")
    a = np.linspace(0.0, np.pi, 200001)
    below = np.flatnonzero(g(a) < 0.5 * peak)
    if below.size == 0:
        return 2.0 * np.pi
    i = int(below[0])
    a_h = brentq(lambda x: float(g(x)) - 0.5 * peak, a[i - 1], a[i], xtol=1e-13)
    return 2.0 * a_h


def level_extent(gain: Callable[[NDArray], NDArray], level_db: float) -> float:
    """Farthest azimuth off boresight where a pattern is still within ``level_db`` of its
    boresight value [rad].

    The angular spread of a strong echo through the beam: a scatterer whose echo exceeds
    the background by X dB still shows above it wherever the (two-way) pattern is above
    -X dB, main lobe and sidelobes alike. Pass the two-way pattern G_t G_r for a radar's
    echo (:func:`seaecho.io.detections.land_spread`).

    Parameters
    ----------
    gain : callable
        ``d_local (..., 3) -> G`` in the antenna frame (x boresight, y along the width,
        z up), evaluated along the azimuth plane (z = 0), both sides of the boresight.
    level_db : float
        X > 0 [dB]: the level below the boresight value.

    Returns
    -------
    float
        a_X = max |a| over the azimuths a in [-pi, pi] with G(a) >= 10^(-X/10) G(0) (the
        outermost crossing, found on a grid of 2^19 + 1 azimuths, then by Brent's
        method): beyond a_X the pattern stays below the level. pi where it never falls
        below (an omnidirectional pattern). For a Gaussian beam whose one-way half-power
        width is theta_3, G_t G_r = exp(-8 ln 2 a^2 / theta_3^2) gives a_X = (theta_3 / 2)
        sqrt(X / (20 log10 2)) (``tests/detection/test_land_spread.py``).
    """
    if not (np.isfinite(level_db) and level_db > 0):
        raise ValueError(f"level_db = {level_db}: the level below the boresight must be a "
                         "number > 0 dB")
    g = _azimuth_cut(gain)
    peak = float(g(0.0))
    if not peak > 0:
        raise ValueError(f"gain at boresight = {peak}: no beam to measure")
    floor = peak * 10.0 ** (-level_db / 10.0)
    a = np.linspace(-np.pi, np.pi, (1 << 19) + 1)
    above = g(a) >= floor
    if above.all():
        return float(np.pi)
    extent = 0.0
    for side in (1, -1):  # the outermost crossing on each side of the boresight
        half = a[a.size // 2:] if side > 0 else -a[:a.size // 2 + 1][::-1]
        up = above[a.size // 2:] if side > 0 else above[:a.size // 2 + 1][::-1]
        i = int(np.flatnonzero(up)[-1])
        if i == half.size - 1:
            return float(np.pi)
        x = brentq(lambda t, s=side: float(g(s * t)) - floor, half[i], half[i + 1],
                   xtol=1e-13)
        extent = max(extent, x)
    return float(extent)


def compressed_extent(pulse: ArrayLike, reference: ArrayLike, level_db: float, *,
                      oversample: int = 8, reach: int = 2048) -> float:
    r"""Farthest delay from its peak where a point echo's compressed pulse is still within
    ``level_db`` of the peak [samples].

    The echo of a point at a fractional delay x is the pulse band-limited to the sampling
    rate, sum_m s_m sinc(t - m - x) (the simulator's eq E2 of :mod:`seaecho.radar.echo`),
    and the matched filter with the reference h (the pulse times its range weighting,
    eq C1 of :mod:`seaecho.processing.range_compression`) gives at output sample k

    .. math:: y(u) = \sum_j a_j\,\mathrm{sinc}(u - j),\quad
              a_j = \sum_n h_n^*\,s_{n+j},\quad u = k - x                            (F2)

    (Whittaker-Shannon: y is band-limited and its samples at whole u are the discrete
    correlation a). Its main lobe spans c / (2 B) each side (B the bandwidth: 1 / T for
    a plain pulse of length T), and its tails decay as a power of u (as u^-3 for a
    two-sample rectangular pulse, whose a = (1, 2, 1) vanishes at the band's edge): a
    strong echo shows above the noise in the gates its tails reach.

    Parameters
    ----------
    pulse, reference : array_like
        s_n, h_n: the transmitted pulse and the matched filter's reference samples.
    level_db : float
        X > 0 [dB] below the peak of |y|^2.
    oversample : int
        Points per sample of the evaluation grid (band-limited interpolation by FFT).
    reach : int
        Samples searched beyond the correlation's own length; the extent is capped there.

    Returns
    -------
    float
        max |u - u_peak| with |y(u)|^2 >= 10^(-X/10) max |y|^2 [samples].
    """
    from scipy.fft import fft, ifft, next_fast_len

    if not (np.isfinite(level_db) and level_db > 0):
        raise ValueError(f"level_db = {level_db}: the level below the peak must be a "
                         "number > 0 dB")
    s = np.asarray(pulse, dtype=complex).ravel()
    h = np.asarray(reference, dtype=complex).ravel()
    # a_j for j = -(len(h) - 1) .. len(s) - 1: the correlation of eq F2
    a = np.correlate(s, h, mode="full")
    half = a.size + int(reach)
    n = int(next_fast_len(4 * half))
    buf = np.zeros(n, complex)
    buf[:a.size] = a
    spec = fft(buf)
    m = n * int(oversample)
    wide = np.zeros(m, complex)  # the band |f| < f_s / 2 kept, zeros outside: eq F2's sinc
    k = n // 2
    wide[:k] = spec[:k]
    wide[m - (n - k):] = spec[k:]
    if n % 2 == 0:  # the Nyquist bin split between +-f_s / 2
        wide[k] *= 0.5
        wide[m - k] = wide[k]
    y = np.abs(ifft(wide) * oversample) ** 2
    u = np.arange(m) / oversample
    u = np.where(u < n / 2, u, u - n)  # the periodic extension folded about 0
    peak = int(np.argmax(y))
    above = np.flatnonzero(y >= y[peak] * 10.0 ** (-level_db / 10.0))
    return float(min(np.max(np.abs(u[above] - u[peak])), half))


def clutter_cell_area(slant_range_m: ArrayLike, range_extent_m: ArrayLike,
                      azimuth_width_rad: ArrayLike, grazing_rad: ArrayLike) -> NDArray:
    """Pulse-limited area of sea in a range cell, eq (F1) [m^2].

    Parameters
    ----------
    slant_range_m : array_like
        R, slant range of the cell [m].
    range_extent_m : array_like
        Delta R, the cell's extent in slant range [m] (c / (2 B) for a resolution cell,
        the gate spacing for a gate).
    azimuth_width_rad : array_like
        theta_B, one-way half-power azimuth width of the beam [rad].
    grazing_rad : array_like
        psi, grazing angle at the cell [rad] (:func:`seaecho.geometry.earth.grazing_angle`).

    Returns
    -------
    ndarray
        A_c [m^2]; NaN where psi is not in [0, pi/2) (no sea at that range: nearer than
        the radar's height, or beyond the horizon).

    References
    ----------
    Skolnik (2001), section 7.1.
    """
    r, dr, th, psi = (np.asarray(v, dtype=float) for v in
                      (slant_range_m, range_extent_m, azimuth_width_rad, grazing_rad))
    ok = (psi >= 0.0) & (psi < 0.5 * np.pi)
    # Eq (F1): the beam's arc across, the range extent on the sea along range
    with np.errstate(invalid="ignore", divide="ignore"):
        area = r * th * dr / np.cos(psi)
    return np.where(ok, area, np.nan)
