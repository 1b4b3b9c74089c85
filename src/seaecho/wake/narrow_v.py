"""Narrow-V wake: the Bragg-scale divergent waves of the Kelvin pattern (eqs N1-N7).

SAR images of ships, at L band above all, show two bright arms of a few degrees
half-angle about the track, inside the 19.5 deg Kelvin wedge (SEASAT, Munk,
Scully-Power & Zachariasen 1987; Lyden et al. 1988; Shemdin 1990; review: Reed & Milgram
2002). They are Bragg scattering from the short divergent waves the hull makes: the
Kelvin wave whose wavenumber equals the radar's Bragg wavenumber ``k_B`` lies on one ray
of the pattern only, and that ray is the arm (Milgram 1988; Shemdin 1990: "the half
angles associated with narrow-V wakes are consistent with first-order Bragg surface wave
theory ... The decay rate along the bright arms ... is consistent with the combined
viscous and radiation decay of short surface waves with first-order Bragg wavelengths").

**Ray of a wavenumber** (N1-N3). A wave steady in the ship frame (speed V) travelling at
angle theta to the track has phase speed ``c(k) = V cos theta``; ``c`` is the deep-water
capillary-gravity phase speed of eq 15' (:mod:`seaecho.ocean.dispersion`, which also
holds n and the inverse k(c)). Its energy
moves in the ship frame with the group velocity ``c_g = n c`` along the wave plus the
stream V along the track, so its ray makes the angle alpha with the track,

.. math::

    \\cos\\theta = c(k)/V, \\qquad
    n(k) = \\frac{c_g}{c} = \\frac{g + 3\\tau k^2}{2(g + \\tau k^2)}          (N1)

    \\tan\\alpha = \\frac{n \\tan\\theta}{1 - n + \\tan^2\\theta}              (N2)

(Lighthill 1978, section 3.10; with n = 1/2, eq N2 is Kelvin's tan alpha = tan theta /
(1 + 2 tan^2 theta) of eq 16). For the short waves of the arms, tan theta >> 1, and

.. math::

    \\alpha \\approx c_g(k_B) / V                                             (N3)

the narrow-V half-angle: the Bragg waves' group speed over the ship's speed. No wave of
wavenumber k is steady if ``V <= c(k)``: no narrow-V (a ship at rest, or one slower than
the Bragg waves, has none).

**Amplitude** (N4, N5). The local amplitude of the wave theta at distance R along its
ray is the stationary-phase value of eq W4 with the Michell amplitude A(theta) of the
ship's Wigley hull (eq W8), capped so that the wave is not steeper than breaking (eq E2)
where it leaves the near field, ``R_0 = (L/2 + lambda_0/2) / cos alpha`` (as eq W12b):

.. math::

    a(R) = |A(\\theta)| \\sqrt{\\frac{2\\pi}{R |\\phi''(\\theta)|}}\\,
        \\min\\!\\left(1, \\frac{0.444 / k}{|A|\\sqrt{2\\pi / (R_0 |\\phi''|)}}\\right)
        e^{-2\\nu k^2 R / |\\mathbf u_e|}\\, W(x')                            (N4)

with ``phi(theta) = k(theta) cos(theta + alpha)`` the phase per metre along the ray
(``k(theta)`` from N1), ``|u_e| = V sqrt((1 - n cos^2 theta)^2 + (n cos theta
sin theta)^2)`` the speed of the energy in the ship frame (so R / |u_e| is the wave's
age), ``2 nu k^2`` Lamb's (1932, art. 348) viscous amplitude decay rate and W the
near-field window of eq W11. Hence the energy along an arm

.. math::

    a^2 \\propto R^{-1} \\exp(-4\\nu k^2 R / |\\mathbf u_e|)                   (N5)

the radiation (geometric spreading) and viscous decay of Shemdin (1990). Michell's
amplitude is that of gravity waves (eq W8); at the Bragg scale of X band surface tension
also enters the wave generation, which is not modelled (the cap (E2) bounds the result).

**Two scales** (N6, N7). The arms' waves (2 cm at X band, 30 cm at L band) are far
shorter than the facets: they belong to the sub-facet roughness that the Bragg term of
the scattering model reads (docs/scattering.md), not to the resolved heights (the Kelvin
wake's synthesis is band-limited at the grid). The facet sees the local plane wave
``a cos(k_w . r)`` through its own periodogram: over a facet of sides dx, dy (a cell of
the grid) the wave's height spectrum at the radar's Bragg vector K_B is

.. math::

    W_V(\\mathbf K_B) = \\frac{a^2}{4} \\frac{dx\\,dy}{4\\pi^2} \\sum_\\pm
        \\mathrm{sinc}^2\\frac{(K_{Bx} \\mp k_{wx}) dx}{2}\\,
        \\mathrm{sinc}^2\\frac{(K_{By} \\mp k_{wy}) dy}{2}                     (N6)

(sinc x = sin x / x; the small-perturbation cross section of a deterministic facet is
``16 pi k^4 |alpha|^2`` times this, Rice 1951; Valenzuela 1978), and the wind sea's Bragg
spectrum W(K_B) is raised by the factor

.. math::

    1 + g, \\qquad g = W_V(\\mathbf K_B) / W(\\mathbf K_B)                    (N7)

The arm is bright only where the local wave vector matches K_B to within the facet's
resolution 2 pi / dx in direction as well as in modulus: the narrow-V waves run almost
across the track, so the arms light up when the radar looks across the track (the ship
sails along the SAR's azimuth), as observed ("especially when the ship is traveling in a
direction close to the SAR track", Tunaley; Shemdin 1990 imaged "azimuthally travelling
ships").

References
----------
.. [1] W. H. Munk, P. Scully-Power and F. Zachariasen, "The Bakerian lecture, 1986: Ships
   from space", Proc. R. Soc. Lond. A 412, 231-254 (1987).
.. [2] A. M. Reed and J. H. Milgram, "Ship wakes and their radar images", Annu. Rev.
   Fluid Mech. 34, 469-502 (2002).
.. [3] O. H. Shemdin, "Synthetic aperture radar imaging of ship wakes in the Gulf of
   Alaska", J. Geophys. Res. 95(C9), 16319-16338 (1990), doi:10.1029/90JC00486.
.. [4] J. D. Lyden, R. R. Hammond, D. R. Lyzenga and R. A. Shuchman, "Synthetic aperture
   radar imaging of surface ship wakes", J. Geophys. Res. 93(C10), 12293-12303 (1988).
.. [5] J. H. Milgram, "Theory of radar backscatter from short waves generated by ships,
   with application to radar (SAR) imagery", J. Ship Res. 32(1), 54-69 (1988).
.. [6] G. Zilman, A. Zapolski and M. Marom, "The speed and beam of a ship from its wake's
   SAR images", IEEE Trans. Geosci. Remote Sens. 42(10), 2335-2343 (2004).
.. [10] G. Zilman and T. Miloh, "Radar backscatter of a V-like ship wake from a sea
   surface covered by surfactants", Proc. 21st Symp. Naval Hydrodynamics, 235-248 (1997):
   "a bright V with a narrow half angle of 2-3 deg ... explained as a result of the Bragg
   scattering from ship-generated divergent waves (Milgram 1988)".
.. [7] M. J. Lighthill, *Waves in Fluids*, Cambridge University Press (1978), section 3.10.
.. [8] H. Lamb, *Hydrodynamics*, 6th ed., Cambridge University Press (1932), art. 348.
.. [9] J. K. E. Tunaley, "The narrow-V wake" (abstract): narrow-V wakes are seen
   "especially when the ship is traveling in a direction close to the SAR track and when
   the wind is light".
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import NU_SEA_WATER
from ..ocean.dispersion import (
    CAPILLARY_WAVENUMBER,
    group_to_phase_ratio,
    phase_speed,
    wavenumber_of_phase_speed,
)
from .empirical import BREAKING_SLOPE
from .michell import transverse_wavelength, wigley_amplitude
from .ship import Ship

#: Half-width of the band of wavenumbers tabulated about k_B, in facet resolutions
#: 2 pi / dx (eq N6's sinc^2 is below 1 % beyond it) [-].
_BAND_RESOLUTIONS = 6.0
#: Rays tabulated per band [-].
_TABLE_SIZE = 2048
#: Points per cell side averaged by eq N6 [-].
_SUBSAMPLES = 8


def steady_wave_angle(speed: float, k: ArrayLike) -> NDArray[np.float64]:
    """Angle theta of the steady wave of wavenumber k to the track, cos theta = c(k) / V
    (eq N1) [rad]; NaN where ``V <= c(k)`` (no steady wave).

    Parameters
    ----------
    speed : float
        Ship speed V >= 0 [m/s].
    k : array_like
        Wavenumber [rad/m], > 0.
    """
    c = phase_speed(k)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(speed > c, c / speed, np.nan)
    return np.arccos(ratio)  # Eq N1


def ray_angle(theta: ArrayLike, n: ArrayLike) -> NDArray[np.float64]:
    """Ray angle alpha of the steady wave theta (eq N2) [rad].

    Parameters
    ----------
    theta : array_like
        Wave angle to the track, [0, pi/2) [rad].
    n : array_like
        c_g / c of the wave [-] (:func:`group_to_phase_ratio`).

    References
    ----------
    Lighthill (1978) section 3.10; n = 1/2 gives Kelvin's ray (eq 16).
    """
    t = np.tan(np.asarray(theta, dtype=np.float64))
    n = np.asarray(n, dtype=np.float64)
    return np.arctan2(n * t, 1.0 - n + t * t)  # Eq N2


def narrow_v_half_angle(speed: float, bragg_wavenumber: ArrayLike) -> NDArray[np.float64]:
    """Half-angle of the narrow-V wake's arms (eqs N1, N2) [rad]; NaN where the ship is not
    faster than the Bragg waves (``V <= c(k_B)``: no narrow-V).

    Parameters
    ----------
    speed : float
        Ship speed V >= 0 [m/s].
    bragg_wavenumber : array_like
        The radar's Bragg wavenumber k_B [rad/m], > 0.

    Returns
    -------
    ndarray
        alpha [rad]; about ``c_g(k_B) / V`` (eq N3).

    References
    ----------
    Milgram (1988); Shemdin (1990); Reed & Milgram (2002). Zilman, Zapolski & Marom (2004)
    infer a ship's speed from this angle; their text was not available here, so their
    closed form is not compared.
    """
    k = np.asarray(bragg_wavenumber, dtype=np.float64)
    return ray_angle(steady_wave_angle(speed, k), group_to_phase_ratio(k))


def _rays(ship: Ship, k_lo: float, k_hi: float, capillary: bool):
    """Steady waves of wavenumber in [k_lo, k_hi] (one branch of eq 15'), split where
    alpha(k) turns (the group speed's minimum near 0.39 k_m is an inner caustic of the
    pattern: two waves share each ray beyond it). Yields, per monotonic piece, arrays
    sorted by alpha: alpha, theta, k, the amplitude per sqrt(m) |A| sqrt(2 pi / |phi''|)
    [m^1.5] and the energy speed |u_e| [m/s]."""
    k = np.geomspace(k_lo, k_hi, _TABLE_SIZE)
    theta = steady_wave_angle(ship.speed, k)
    ok = np.isfinite(theta) & (theta > 0.0)
    k, theta = k[ok], theta[ok]
    if k.size < 2:
        return []
    n = group_to_phase_ratio(k)
    alpha = ray_angle(theta, n)
    v = ship.speed

    def phase(th):
        # phi(theta) = k(theta) cos(theta + alpha): phase per metre along the ray alpha
        return wavenumber_of_phase_speed(v * np.cos(th), capillary) * np.cos(th + alpha)

    h = 1e-4 * (0.5 * np.pi - theta)
    phi2 = (phase(theta + h) - 2.0 * phase(theta) + phase(theta - h)) / (h * h)
    amp = np.abs(wigley_amplitude(theta, ship.length, ship.beam, ship.draft, v))
    per_root_m = amp * np.sqrt(2.0 * np.pi / np.maximum(np.abs(phi2), 1e-300))  # Eq N4
    cos_t = np.cos(theta)
    u_e = v * np.hypot(1.0 - n * cos_t**2, n * cos_t * np.sin(theta))
    rising = np.diff(alpha) > 0.0
    cuts = np.flatnonzero(rising[1:] != rising[:-1]) + 1
    pieces = []
    for lo, hi in zip(np.r_[0, cuts], np.r_[cuts + 1, alpha.size], strict=True):
        if hi - lo < 2:
            continue
        order = np.argsort(alpha[lo:hi]) + lo
        pieces.append(tuple(a[order] for a in (alpha, theta, k, per_root_m, u_e)))
    return pieces


def narrow_v_amplitude(ship: Ship, k: ArrayLike, distance: ArrayLike) -> NDArray[np.float64]:
    """Amplitude a of the ship's steady wave of wavenumber k at ``distance`` R from
    midship along its ray (eq N4 without the near-field window) [m].

    Parameters
    ----------
    ship : Ship
        The ship (hull and speed).
    k : array_like
        Wavenumber [rad/m] (gravity branch below k_m, capillary above).
    distance : array_like
        R > 0 [m], broadcast with k.

    Returns
    -------
    ndarray
        a [m]; 0 where ``V <= c(k)``.

    References
    ----------
    Stationary phase of eq W4 (Newman 1977, 6.17) with Michell's A (eq W8); breaking
    limit E2 (Williams 1981); viscous decay 2 nu k^2 (Lamb 1932, art. 348).
    """
    k = np.asarray(k, dtype=np.float64)
    r = np.asarray(distance, dtype=np.float64)
    k, r = np.broadcast_arrays(k, r)
    out = np.zeros(k.shape)
    theta = steady_wave_angle(ship.speed, k)
    ok = np.isfinite(theta) & (theta > 0.0)
    if not np.any(ok):
        return out
    k_ok, th, r_ok = k[ok], theta[ok], r[ok]
    n = group_to_phase_ratio(k_ok)
    alpha = ray_angle(th, n)
    v = ship.speed
    capillary = k_ok > CAPILLARY_WAVENUMBER

    def phase(t):
        kk = np.where(capillary, wavenumber_of_phase_speed(v * np.cos(t), True),
                      wavenumber_of_phase_speed(v * np.cos(t), False))
        return kk * np.cos(t + alpha)

    h = 1e-4 * (0.5 * np.pi - th)
    phi2 = (phase(th + h) - 2.0 * phase(th) + phase(th - h)) / (h * h)
    amp = np.abs(wigley_amplitude(th, ship.length, ship.beam, ship.draft, v))
    per_root_m = amp * np.sqrt(2.0 * np.pi / np.maximum(np.abs(phi2), 1e-300))
    cos_t = np.cos(th)
    u_e = v * np.hypot(1.0 - n * cos_t**2, n * cos_t * np.sin(th))
    out[ok] = _amplitude(ship, k_ok, alpha, per_root_m, u_e, r_ok)
    return out


def _amplitude(ship: Ship, k, alpha, per_root_m, u_e, r) -> NDArray[np.float64]:
    """Eq N4 (without W): stationary phase, breaking cap where the wave leaves the near
    field (E2, as eq W12b), viscous decay over the wave's age R / |u_e| [m]."""
    r0 = (0.5 * ship.length + 0.5 * transverse_wavelength(ship.speed)) / np.cos(alpha)
    cap = np.minimum(1.0, BREAKING_SLOPE / np.maximum(k * per_root_m / np.sqrt(r0), 1e-300))
    with np.errstate(divide="ignore"):
        return (per_root_m / np.sqrt(r) * cap
                * np.exp(-2.0 * NU_SEA_WATER * k * k * r / u_e))  # Eq N4


def narrow_v_bragg_gain(
    ship: Ship,
    x: ArrayLike,
    y: ArrayLike,
    t: float,
    bragg_vector: tuple[float, float],
    sea_bragg_spectrum: float,
) -> NDArray[np.float64]:
    """Relative rise g of the Bragg spectrum in the narrow-V arms (eqs N4-N7) [-].

    Parameters
    ----------
    ship : Ship
        One ship (track, speed, hull).
    x : array_like, shape (nx,)
        Grid x (east), evenly spaced: the facets' side dx [m].
    y : array_like, shape (ny,)
        Grid y (north), evenly spaced [m].
    t : float
        Time [s].
    bragg_vector : (float, float)
        The radar's Bragg vector K_B at the scene, horizontal [rad/m].
    sea_bragg_spectrum : float
        The wind sea's height spectrum W(K_B) [m^4], > 0.

    Returns
    -------
    ndarray, shape (ny, nx)
        g >= 0: the Bragg spectrum there is (1 + g) W(K_B) (eq N7). Zeros for a ship
        slower than the Bragg waves.
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    if x.ndim != 1 or y.ndim != 1 or x.size < 2 or y.size < 2:
        raise ValueError("x and y must be 1-D coordinate arrays of at least 2 points [m]")
    kbx, kby = (float(v) for v in bragg_vector)
    k_b = float(np.hypot(kbx, kby))
    if not (np.isfinite(k_b) and k_b > 0.0):
        raise ValueError(f"bragg_vector = {bragg_vector!r} rad/m: must be finite, non-zero")
    if not (np.isfinite(sea_bragg_spectrum) and sea_bragg_spectrum > 0.0):
        raise ValueError(f"sea_bragg_spectrum = {sea_bragg_spectrum!r} m^4: must be > 0")
    gain = np.zeros((y.size, x.size))
    if ship.speed == 0.0 or not np.isfinite(narrow_v_half_angle(ship.speed, k_b)):
        return gain  # Eq N1: no steady wave of the Bragg wavenumber
    dx, dy = abs(float(x[1] - x[0])), abs(float(y[1] - y[0]))
    capillary = k_b > CAPILLARY_WAVENUMBER
    band = _BAND_RESOLUTIONS * 2.0 * np.pi / min(dx, dy)
    k_lo, k_hi = max(k_b - band, 1e-3 * k_b), k_b + band
    k_lo, k_hi = ((max(k_lo, CAPILLARY_WAVENUMBER), k_hi) if capillary
                  else (k_lo, min(k_hi, CAPILLARY_WAVENUMBER)))
    pieces = _rays(ship, k_lo, k_hi, capillary)
    if not pieces:
        return gain
    lo = min(p[0][0] for p in pieces)
    hi = max(p[0][-1] for p in pieces)
    xs, ys = ship.to_ship_frame(x[None, :], y[:, None], t)
    r = np.hypot(xs, ys)
    alpha = np.arctan2(np.abs(ys), xs)
    with np.errstate(divide="ignore"):
        span = 0.5 * np.hypot(dx, dy) / r  # the cell's angular half-width seen from midship
    near = (alpha + span >= lo) & (alpha - span <= hi)
    if not np.any(near):
        return gain
    # Each cell is averaged over _SUBSAMPLES^2 points: an arm is narrower than a cell
    # (eq N6's k-resolution 2 pi / dx maps to a fraction of a degree of alpha)
    m = _SUBSAMPLES
    off = (np.arange(m) + 0.5) / m - 0.5
    iy, ix = np.nonzero(near)
    px = (x[ix][:, None, None] + dx * off[None, None, :]).reshape(ix.size, -1)
    py = (y[iy][:, None, None] + dy * off[None, :, None]).reshape(iy.size, -1)
    px, py = np.broadcast_arrays(px, py)
    xs_p, ys_p = ship.to_ship_frame(px, py, t)
    w_v = _periodogram(ship, pieces, xs_p, ys_p, (kbx, kby), dx, dy).mean(axis=1)
    gain[near] = w_v / sea_bragg_spectrum  # Eq N7
    return gain


def _periodogram(ship: Ship, pieces, xs, ys, bragg_vector, dx: float, dy: float
                 ) -> NDArray[np.float64]:
    """Eq N6 at ship-frame points (xs, ys) [m^4]: the height spectrum at K_B that a
    facet of sides dx, dy sees of the local plane waves (one per piece of the ray table
    whose alpha range holds the point), summed."""
    kbx, kby = bragg_vector
    r = np.hypot(xs, ys)
    alpha = np.arctan2(np.abs(ys), xs)
    w_v = np.zeros(xs.shape)
    if xs.size == 0:
        return w_v
    from .kelvin import KelvinWake

    window = KelvinWake(ship).near_field_window(xs)[0]  # eq W11
    c, s = np.cos(ship.heading), np.sin(ship.heading)
    for alpha_t, theta_t, k_t, amp_t, ue_t in pieces:  # one wave per piece on each ray
        on = (alpha >= alpha_t[0]) & (alpha <= alpha_t[-1]) & (r > 0.0) & (window > 0.0)
        ap = alpha[on]
        theta, k, amp, u_e = (np.interp(ap, alpha_t, tab)
                              for tab in (theta_t, k_t, amp_t, ue_t))
        a = _amplitude(ship, k, ap, amp, u_e, r[on]) * window[on]  # Eq N4
        # local wave vector: ship frame k (cos theta, -sign(y') sin theta); x' = -h, y' = -n
        kx_s, ky_s = k * np.cos(theta), -np.sign(ys[on]) * k * np.sin(theta)
        kwx = -(kx_s * c - ky_s * s)
        kwy = -(kx_s * s + ky_s * c)
        w_v[on] += plane_wave_periodogram(a, kwx, kwy, (kbx, kby), dx, dy)
    return w_v


def plane_wave_periodogram(amplitude: ArrayLike, kwx: ArrayLike, kwy: ArrayLike,
                           bragg_vector: tuple[float, float], dx: float, dy: float
                           ) -> NDArray[np.float64]:
    """Height spectrum at K_B that a facet of sides dx, dy sees of the plane wave
    ``a cos(k_w . r + phase)`` (eq N6) [m^4].

    ``|int_facet z exp(-i K_B . r) dr|^2 / (4 pi^2 dx dy)``: the spectral density whose
    first-order (small-perturbation) cross section is the facet's (Rice 1951); the cross
    term between +k_w and -k_w, which depends on the phase and is small once
    ``|k_w| dx >> 2 pi``, is left out.

    Parameters
    ----------
    amplitude : array_like
        a [m].
    kwx, kwy : array_like
        Wave vector k_w [rad/m].
    bragg_vector : (float, float)
        K_B [rad/m].
    dx, dy : float
        Facet sides [m].
    """
    kbx, kby = bragg_vector
    a = np.asarray(amplitude, dtype=np.float64)
    kwx = np.asarray(kwx, dtype=np.float64)
    kwy = np.asarray(kwy, dtype=np.float64)
    resp = (np.sinc((kbx - kwx) * dx / (2.0 * np.pi)) ** 2
            * np.sinc((kby - kwy) * dy / (2.0 * np.pi)) ** 2
            + np.sinc((kbx + kwx) * dx / (2.0 * np.pi)) ** 2
            * np.sinc((kby + kwy) * dy / (2.0 * np.pi)) ** 2)
    return 0.25 * a * a * dx * dy / (4.0 * np.pi**2) * resp  # Eq N6


__all__ = ["narrow_v_amplitude", "narrow_v_bragg_gain", "plane_wave_periodogram",
           "narrow_v_half_angle",
           "ray_angle", "steady_wave_angle"]
