"""Turbulent wake strip behind the hull, where short (Bragg) waves are damped.

Behind a ship the propeller and hull boundary layer leave a turbulent, bubble- and
surfactant-laden strip in which short gravity-capillary waves are suppressed; it is the
dark centreline of SAR images of ship wakes (Reed & Milgram 2002; Milgram, Peltzer &
Griffin 1993). Far behind a self-propelled ship the wake carries no net momentum, and the
self-similar momentumless wake grows as the one-fifth power of the distance (Tennekes &
Lumley 1972, section 4.3; the x^(1/5) growth of ship wakes is reported in the review of
Reed & Milgram 2002, section 5). The strip is modelled by its full width

.. math::

    w(\\xi) = w_0 \\left(1 + \\frac{\\xi}{w_0}\\right)^{1/5}                  (W13)

with xi the distance behind the stern along the track and w_0 the width at the stern
(default: the beam B; the virtual origin one stern width behind the stern keeps w finite
and smooth there), over a length L_t (default 20 ship lengths, a modelling choice). The mask is 1 in
the core of the strip (fully damped) and falls smoothly to 0 across its edges and at its
two ends:

.. math::

    M(\\xi, \\eta) = S\\!\\left(\\frac{\\xi}{w_0}\\right)
        S\\!\\left(\\frac{L_t - \\xi}{0.2 L_t}\\right)
        S\\!\\left(\\frac{w(\\xi)/2 + \\delta/2 - |\\eta|}{\\delta}\\right),
    \\quad \\delta = 0.25\\, w(\\xi),\\quad
    S(s) = \\sin^2\\!\\left(\\tfrac{\\pi}{2}\\,\\mathrm{clip}(s, 0, 1)\\right)   (W14)

with eta the transverse distance from the track. The exponent is the published part;
the prefactor (w_0 = B) and the edge shape are modelling choices, exposed as parameters.

**Damping** (:func:`turbulent_wake_mask`). Inside the strip the Bragg spectrum is reduced
by the fraction

.. math::

    d(\\xi, \\eta) = M(\\xi, \\eta)\\left[1 - (1 - d_t(\\xi))(1 - d_f)\\right],\\quad
    d_t = \\left(1 + \\frac{\\xi}{w_0}\\right)^{-3/5},\\quad
    d_f = 1 - 10^{C_f/10}                                                    (W15)

*Turbulence* suppresses the short waves completely at the stern (Milgram, Peltzer &
Griffin 1993) and its effect decays with the wake's eddy viscosity: in the self-similar
momentumless wake the turbulent velocity falls as xi^(-4/5) and the width grows as
xi^(1/5) (Tennekes & Lumley 1972, 4.3), so ``nu_t ~ u' w ~ xi^(-3/5)``; in the short-wave
balance of Kudryavtsev et al. (2003, 2005) the relative reduction of capillary-gravity
Bragg waves (their exponent n = 1) equals the added damping rate over the wind growth
rate, hence ``d_t ~ nu_t``. The wake's age ``xi / V`` enters through ``xi``.

*Surfactant films* swept up by the wake's bubbles and vortices (Kaiser et al. 1988;
Peltzer et al. 1992) persist over the strip. Their contrast ``C_f`` [dB] is the Marangoni
damping of the Bragg waves by a purely elastic film (eqs W16, W17 of
:mod:`seaecho.wake.film`: Lucassen-Reynders & Lucassen 1969; Alpers & Huehnerfuss 1989),
evaluated at the radar's Bragg wavenumber (``Ship.bragg_wavenumber``) for the film's
dilational modulus (``Ship.turbulent_wake_film_elasticity``, default 0.010 N/m, Alpers &
Huehnerfuss 1988): about -3.5 to -3.8 dB at X band between 20 and 45 deg incidence,
-0.7 dB at L band. ``Ship.turbulent_wake_film_contrast_db`` overrides it. No measured
contrast of a ship wake against the surrounding sea with its wind, band and age could be
found to check the sum against (docs/wake.md lists what was searched); the film's decay
with the wake's age and the dependence on the wind speed are not modelled.

References
----------
.. [1] A. M. Reed and J. H. Milgram, "Ship wakes and their radar images", Annu. Rev.
   Fluid Mech. 34, 469-502 (2002).
.. [2] J. H. Milgram, R. D. Peltzer and O. M. Griffin, "Suppression of short sea waves
   in ship wakes: measurements and observations", J. Geophys. Res. 98(C4), 7103-7114
   (1993).
.. [3] H. Tennekes and J. L. Lumley, *A First Course in Turbulence*, MIT Press (1972),
   section 4.3.
.. [4] J. A. C. Kaiser, W. D. Garrett, S. E. Ramberg, R. D. Peltzer and D. M. Andrews,
   "WAKEX 86: a ship wake/films exploratory experiment", NRL report (1988).
.. [5] R. D. Peltzer, W. D. Garrett and P. M. Smith, "Hydrodynamics of ship wake
   surfactant films", Proc. 18th Symp. Naval Hydrodynamics, 533-550 (1991, publ. 1992).
.. [6] V. Kudryavtsev, D. Hauser, G. Caudal and B. Chapron, J. Geophys. Res. 108(C3), 8054
   (2003); V. Kudryavtsev, D. Akimov, J. Johannessen and B. Chapron, J. Geophys. Res.
   110, C07016 (2005).
.. [7] J. D. Lyden, R. R. Hammond, D. R. Lyzenga and R. A. Shuchman, "Synthetic aperture
   radar imaging of surface ship wakes", J. Geophys. Res. 93(C10), 12293-12303 (1988).
.. [8] A. Soloviev, M. Gilman, K. Young, S. Brusch and S. Lehner, "Sonar measurements in
   ship wakes simultaneous with TerraSAR-X overpasses", IEEE Trans. Geosci. Remote Sens.
   48(2), 841-851 (2010).
.. [9] E. H. Lucassen-Reynders and J. Lucassen, "Properties of capillary waves", Adv.
   Colloid Interface Sci. 2, 347-395 (1969); W. Alpers and H. Huehnerfuss, J. Geophys.
   Res. 93(C4), 3642-3648 (1988) and 94(C5), 6251-6265 (1989).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .film import film_contrast_db as _film_contrast_db
from .ship import Ship


def _smooth_step(s: NDArray[np.float64]) -> NDArray[np.float64]:
    """S(s) = sin^2(pi/2 clip(s, 0, 1)) [-] of eq W14: 0 below 0, 1 above 1, C1."""
    return np.sin(0.5 * np.pi * np.clip(s, 0.0, 1.0)) ** 2


def turbulent_wake_width(xi: ArrayLike, width_at_stern: float) -> NDArray[np.float64]:
    """Full width of the turbulent wake strip w(xi) [m] (eq W13).

    Parameters
    ----------
    xi : array_like
        Distance behind the stern along the track, >= 0 [m] (negative values are
        treated as 0).
    width_at_stern : float
        w_0 > 0 [m].

    Returns
    -------
    ndarray
        w [m]; grows as xi^(1/5) for xi >> w_0.

    References
    ----------
    Tennekes & Lumley (1972) section 4.3; Reed & Milgram (2002).
    """
    xi = np.maximum(np.asarray(xi, dtype=np.float64), 0.0)
    # Eq W13
    return width_at_stern * (1.0 + xi / width_at_stern) ** 0.2


def turbulent_damping_profile(
    xi: ArrayLike, width_at_stern: float, film_contrast_db: float
) -> NDArray[np.float64]:
    """Bragg damping fraction along the wake core, ``1 - (1 - d_t)(1 - d_f)`` (eq W15) [-].

    Parameters
    ----------
    xi : array_like
        Distance behind the stern [m] (negative values are treated as 0).
    width_at_stern : float
        w_0 > 0 [m].
    film_contrast_db : float
        Persistent film contrast C_f <= 0 [dB].

    References
    ----------
    Milgram, Peltzer & Griffin (1993); Tennekes & Lumley (1972) 4.3; Kudryavtsev et al.
    (2003, 2005).
    """
    if not (np.isfinite(film_contrast_db) and film_contrast_db <= 0.0):
        raise ValueError(f"film_contrast_db = {film_contrast_db!r} dB: must be <= 0")
    xi = np.maximum(np.asarray(xi, dtype=np.float64), 0.0)
    # Eq W15: turbulent part decays with the eddy viscosity of the momentumless wake.
    d_t = (1.0 + xi / width_at_stern) ** -0.6
    d_f = 1.0 - 10.0 ** (film_contrast_db / 10.0)
    return 1.0 - (1.0 - d_t) * (1.0 - d_f)


def turbulent_wake_film_contrast_db(ship: Ship) -> float:
    """The film contrast C_f of eq W15 for a ship [dB].

    ``ship.turbulent_wake_film_contrast_db`` if set; else the Marangoni contrast of the
    film (eq W17) at ``ship.bragg_wavenumber`` for ``ship.turbulent_wake_film_elasticity``;
    0 dB (no film term) when the ship has no Bragg wavenumber (a scene without a radar).

    References
    ----------
    Alpers & Huehnerfuss (1989); :mod:`seaecho.wake.film`.
    """
    if ship.turbulent_wake_film_contrast_db is not None:
        return float(ship.turbulent_wake_film_contrast_db)
    if ship.bragg_wavenumber is None:
        return 0.0
    return _film_contrast_db(ship.bragg_wavenumber, ship.turbulent_wake_film_elasticity)


def turbulent_wake_mask(
    ship: Ship,
    x: ArrayLike,
    y: ArrayLike,
    t: float = 0.0,
    length: float | None = None,
    width_at_stern: float | None = None,
    film_contrast_db: float | None = None,
) -> NDArray[np.float64]:
    """Bragg damping of the turbulent wake on the grid (x, y) at time t (eqs W13-W15).

    The strip of :func:`turbulent_wake_strip` times the damping profile of
    :func:`turbulent_damping_profile`.

    Parameters
    ----------
    ship, x, y, t, length, width_at_stern
        As :func:`turbulent_wake_strip`.
    film_contrast_db : float or None
        C_f [dB]; None takes :func:`turbulent_wake_film_contrast_db` of the ship (its
        override, else the Marangoni film contrast at its Bragg wavenumber).

    Returns
    -------
    ndarray, shape (ny, nx)
        Fraction of the Bragg spectrum removed, in [0, 1).
    """
    w0 = ship.beam if width_at_stern is None else float(width_at_stern)
    c_f = turbulent_wake_film_contrast_db(ship) if film_contrast_db is None else film_contrast_db
    strip, xs, core = _strip(ship, x, y, t, length, width_at_stern)
    if not np.any(strip):
        return strip
    # zero outside the strip's core (strip 0 there): the profile where it can be non-zero
    mask = np.zeros(strip.shape)
    mask[core] = strip[core] * turbulent_damping_profile(xs[core] - 0.5 * ship.length,
                                                         w0, c_f)
    return mask


def turbulent_wake_strip(
    ship: Ship,
    x: ArrayLike,
    y: ArrayLike,
    t: float = 0.0,
    length: float | None = None,
    width_at_stern: float | None = None,
) -> NDArray[np.float64]:
    """Extent of the turbulent wake strip on the grid (x, y) at time t (eqs W13, W14).

    Parameters
    ----------
    ship : Ship
        The ship (position at time t from eq W1).
    x : array_like, shape (nx,)
        x coordinates (east) [m].
    y : array_like, shape (ny,)
        y coordinates (north) [m].
    t : float
        Time [s].
    length : float or None
        Length of the strip behind the stern L_t [m]; None takes
        ``ship.turbulent_wake_length`` or, if that is None, 20 ship lengths.
    width_at_stern : float or None
        w_0 [m]; None takes the beam.

    Returns
    -------
    ndarray, shape (ny, nx)
        Strip mask M in [0, 1]: 1 in the core, 0 outside.

    References
    ----------
    Reed & Milgram (2002); Milgram, Peltzer & Griffin (1993); Tennekes & Lumley (1972).
    """
    return _strip(ship, x, y, t, length, width_at_stern)[0]


def _strip(ship: Ship, x: ArrayLike, y: ArrayLike, t: float, length: float | None,
           width_at_stern: float | None
           ) -> tuple[NDArray[np.float64], NDArray[np.float64] | None, NDArray | None]:
    """:func:`turbulent_wake_strip`, the ship-frame x' of the grid [m] and the core: the
    grid points where the strip can be non-zero (``0 < xi < L_t`` and
    ``|y'| < 0.7 w(L_t)``, a superset of eq W14's support, ``|y'| < 5 w / 8``), on which
    alone the formulas are evaluated (the strip is exactly 0 elsewhere, as S(s <= 0)).
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    if x.ndim != 1 or y.ndim != 1:
        raise ValueError("x and y must be 1-D coordinate arrays [m]")
    lt = ship.wake_length if length is None else float(length)
    if not np.isfinite(lt) or lt < 0.0:
        raise ValueError(f"length = {length!r} m: must be >= 0")
    w0 = ship.beam if width_at_stern is None else float(width_at_stern)
    if not np.isfinite(w0) or w0 <= 0.0:
        raise ValueError(f"width_at_stern = {width_at_stern!r} m: must be > 0")
    if 0.2 * lt == 0.0:  # no strip (a subnormal length underflows the fade-out: 0/0)
        return np.zeros((y.size, x.size)), None, None
    xs, ys = ship.to_ship_frame(x[None, :], y[:, None], t)
    xi = xs - 0.5 * ship.length  # distance behind the stern
    eta = np.abs(ys)
    core = (xi > 0.0) & (xi < lt) & (eta < 0.7 * float(turbulent_wake_width(lt, w0)))
    xi, eta = xi[core], eta[core]
    w = turbulent_wake_width(xi, w0)
    delta = 0.25 * w
    # Eq W14: onset behind the stern, fade-out at the end, smooth lateral edges. A strip
    # of a few 1e-308 m has a subnormal fade-out length: the ratio overflows to +-inf,
    # which the clip of S takes to 0 or 1 (found by the fuzzing suite)
    with np.errstate(over="ignore"):
        along = _smooth_step(xi / w0) * _smooth_step((lt - xi) / (0.2 * lt))
    across = _smooth_step((0.5 * w + 0.5 * delta - eta) / delta)
    strip = np.zeros(core.shape)
    strip[core] = along * across
    return strip, xs, core


__all__ = ["turbulent_damping_profile", "turbulent_wake_film_contrast_db",
           "turbulent_wake_mask", "turbulent_wake_strip", "turbulent_wake_width"]
