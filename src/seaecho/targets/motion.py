"""A hull riding the waves: heave, pitch and roll from the sea under its waterplane.

The quasi-static, wave-following estimate: the hull takes the plane that fits the sea
surface over its waterplane (the rectangle L x B around its centre, along its heading)
in the least-squares sense,

.. math::

    z(\\xi, \\eta) \\approx \\zeta_0 + a\\,\\xi + b\\,\\eta, \\qquad
    \\text{heave} = \\zeta_0,\\quad \\text{pitch} = \\arctan a,\\quad
    \\text{roll} = \\arctan b                                                 (S1)

with xi forward and eta to port (pitch positive bow up, roll positive starboard side
down, as the platforms' attitudes, docs/conventions.md). On a symmetric waterplane the
fit is the waterplane average of the elevation (heave) and its first moments (pitch,
roll). This is the long-wave limit of a ship's motion response: for waves much longer
than the hull the heave and pitch transfer functions tend to 1 and to the wave slope
(Faltinsen 1990, ch. 2; Lewis 1989, PNA vol. III, ch. 8), and the
averaging over the waterplane attenuates waves comparable to the hull or shorter
(a wave of wavelength L / n along the hull averages to zero heave). Neglected: the
dynamics (added mass, damping, the resonances of heave, pitch and roll: a ship rolls
most near its natural roll period, which this estimate does not know), the surge, sway
and yaw responses and the hull's own wave making.

The dynamic response (:class:`BoxHullMotion`). Heave, pitch and roll of a box-shaped hull
(L x B x T) as three uncoupled, linear, damped oscillators driven by the waterplane
average of each wave component (eq S1 for one component, the Froude-Krylov force and
moments of a wave much longer than the draft),

.. math::

    \\ddot x + 2\\zeta\\omega_n\\dot x + \\omega_n^2 x = \\omega_n^2 f(t), \\qquad
    H(\\nu) = \\frac{1}{1 - (\\nu/\\omega_n)^2 - 2j\\zeta\\,\\nu/\\omega_n}          (S2)

for a forcing f e^{-j nu t} (the sea's convention, :mod:`seaecho.ocean.surface`), with nu
the frequency of encounter nu = omega - K . V of a wave (K, omega) met by a hull at
velocity V. A sea z = sum_K Re[(a_K e^{-j omega t} + b_K e^{+j omega t}) e^{j K.r}] gives

.. math::

    x(t) = \\sum_K \\mathrm{Re}\\big\\{W_x(\\mathbf K)\\,e^{j\\mathbf K\\cdot\\mathbf c}
        \\big[a_K H(\\omega - \\mathbf K\\cdot\\mathbf V) e^{-j\\omega t}
        + b_K H(-\\omega - \\mathbf K\\cdot\\mathbf V) e^{+j\\omega t}\\big]\\big\\}    (S3)

with the waterplane weights of eq S1 for a plane wave e^{j K.r} over the rectangle
(xi along the heading, eta to port; s(u) = sin u / u and
m(k, a) = 3 j k (sin ka - ka cos ka) / (ka)^3, the least-squares slope of e^{j k xi} on
[-a, a], -> j k for ka -> 0):

.. math::

    W_z = s(k_\\xi L/2)\\, s(k_\\eta B/2), \\quad
    W_\\theta = m(k_\\xi, L/2)\\, s(k_\\eta B/2), \\quad
    W_\\phi = s(k_\\xi L/2)\\, m(k_\\eta, B/2)                                    (S4)

heave = x_z, pitch = arctan x_theta, roll = arctan x_phi. As omega_n -> infinity (H -> 1)
this is eq S1 on the continuous waterplane; for waves much longer than the hull and
slower than the natural frequency, the heave RAO -> 1 (Faltinsen 1990, ch. 2;
Journee & Massie 2001, ch. 6); at encounter frequency omega_n the response is 1 / (2 zeta)
times the static one, 90 deg behind the forcing.

Natural frequencies of the box (Journee & Massie 2001, ch. 6, the uncoupled equations of
motion: omega_n^2 = restoring / (inertia + added inertia)):

- heave: restoring rho g L B, mass rho L B T, added mass a_33 = rho pi B^2 L / 8 (the
  high-frequency two-dimensional added mass of a floating half circle, or of a flat plate
  of width B on the free surface, Newman 1977, sec. 4.13; a rectangular section lies
  between): omega_3^2 = g / (T + pi B / 8)                                       (S5)
- pitch: restoring rho g B L^3 / 12 (the waterplane's moment; the term rho g V (KB - KG)
  neglected, small for L >> T), inertia and added inertia of the uniform box (m + a_33)
  L^2 / 12: omega_5 = omega_3
- roll: T_4 = 2 pi k_xx / sqrt(g GM) (Journee & Massie 2001, ch. 6), k_xx the radius of
  gyration in roll with its added inertia, k_xx = 0.35 B by default (within the 0.30 B to
  0.40 B of ships' roll gyradii, Journee & Massie), and GM the metacentric height.

Damping ratios: a modelling choice, stated with the defaults: heave and pitch 0.2 (ship
hulls radiate waves: their heave and pitch are strongly damped, their RAO peaks are low),
roll 0.05 (roll radiates little: a ship's roll is lightly damped and peaks sharply at its
natural period). Neglected: the coupling of heave and pitch, sway and yaw, the
diffraction force (the Froude-Krylov force alone: long waves), forward-speed changes of
the added mass and damping, the nonlinear roll damping, the ship's own waves (only the
random sea drives the motion, not the wakes).

References
----------
.. [1] O. M. Faltinsen, *Sea Loads on Ships and Offshore Structures*, Cambridge
   University Press (1990), ch. 2 (linear wave-induced motions; the long-wave limit).
.. [2] E. V. Lewis (ed.), *Principles of Naval Architecture*, 2nd rev., vol. III,
   SNAME (1989), ch. 8 (motions in waves).
.. [3] J. M. J. Journee and W. W. Massie, *Offshore Hydromechanics*, 1st ed., Delft
   University of Technology (2001), ch. 6 (rigid body dynamics: the uncoupled heave and
   roll equations, natural periods, radii of gyration).
.. [4] J. N. Newman, *Marine Hydrodynamics*, MIT Press (1977), sec. 4.13 (added mass of
   two-dimensional bodies).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..constants import G

#: Damping ratios [-] of heave, pitch and roll by default (a modelling choice, module
#: docstring).
DEFAULT_DAMPING = {"heave": 0.2, "pitch": 0.2, "roll": 0.05}
#: Roll radius of gyration over the beam, k_xx / B [-] (Journee & Massie 2001, ch. 6:
#: 0.30 to 0.40 for ships).
ROLL_GYRADIUS_OVER_BEAM = 0.35


def waterplane_motion(x: NDArray, y: NDArray, elevation: NDArray, centre, heading: float,
                      length: float, beam: float) -> tuple[float, float, float]:
    """Heave [m], pitch [rad] and roll [rad] of a hull following the sea (eq S1).

    Parameters
    ----------
    x : (nx,) array
        Grid x [m].
    y : (ny,) array
        Grid y [m].
    elevation : (ny, nx) array
        Sea surface elevation [m].
    centre : (2,) array_like
        The waterplane's centre (x, y) [m].
    heading : float
        The hull's heading, counter-clockwise from +x [rad].
    length, beam : float
        The waterplane's length and beam [m].

    Returns
    -------
    heave, pitch, roll : float
        0 where fewer than three grid nodes fall in the waterplane (a hull smaller than
        the grid spacing, or off the tile: no surface to follow).
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    c, s = np.cos(heading), np.sin(heading)
    cx, cy = float(centre[0]), float(centre[1])
    half = 0.5 * np.hypot(length, beam)
    # the grid nodes of the waterplane's bounding box, then the rectangle itself
    ix = np.flatnonzero(np.abs(x - cx) <= half)
    iy = np.flatnonzero(np.abs(y - cy) <= half)
    if ix.size == 0 or iy.size == 0:
        return 0.0, 0.0, 0.0
    dx = x[ix][None, :] - cx
    dy = y[iy][:, None] - cy
    xi = dx * c + dy * s
    eta = -dx * s + dy * c
    inside = (np.abs(xi) <= 0.5 * length) & (np.abs(eta) <= 0.5 * beam)
    if np.count_nonzero(inside) < 3:
        return 0.0, 0.0, 0.0
    z = np.asarray(elevation)[np.ix_(iy, ix)][inside]
    a = np.stack([np.ones_like(z), xi[inside], eta[inside]], axis=-1)
    # eq S1: the least-squares plane
    coef, *_ = np.linalg.lstsq(a, z, rcond=None)
    if not np.all(np.isfinite(coef)):
        return 0.0, 0.0, 0.0
    return float(coef[0]), float(np.arctan(coef[1])), float(np.arctan(coef[2]))


def hull_rotation(heading: float, pitch: float, roll: float) -> NDArray[np.float64]:
    """The world rotation (3, 3) that pitches and rolls a hull about its own axes:
    Rz(h) Ry(-pitch) Rx(roll) Rz(-h) (pitch bow up, roll starboard down; the platforms'
    convention, docs/conventions.md)."""
    ch, sh = np.cos(heading), np.sin(heading)
    cp, sp = np.cos(-pitch), np.sin(-pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    rz = np.array([[ch, -sh, 0.0], [sh, ch, 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return rz @ ry @ rx @ rz.T


def oscillator_response(nu: NDArray, omega_n: float, zeta: float) -> NDArray[np.complex128]:
    """Response H(nu) of a damped oscillator to a forcing e^{-j nu t} [-] (eq S2).

    Parameters
    ----------
    nu : array
        Signed forcing frequency [rad/s] (the sea's e^{-j omega t} convention).
    omega_n : float
        Natural angular frequency [rad/s], > 0.
    zeta : float
        Damping ratio [-], > 0.
    """
    r = np.asarray(nu, dtype=np.float64) / omega_n
    return 1.0 / (1.0 - r * r - 2j * zeta * r)  # Eq. S2


def _sinc(u: NDArray) -> NDArray[np.float64]:
    """sin u / u [-]."""
    return np.sinc(u / np.pi)


def _slope_weight(k: NDArray, a: float) -> NDArray[np.complex128]:
    """m(k, a) = 3 j k (sin ka - ka cos ka) / (ka)^3 [rad/m]: the least-squares slope of
    e^{j k xi} over xi in [-a, a] (eq S4)."""
    x = np.asarray(k, dtype=np.float64) * a
    small = np.abs(x) < 1e-3
    xs = np.where(small, 1.0, x)
    # (sin x - x cos x) / x^3, its series 1/3 - x^2/30 near 0
    f = np.where(small, 1.0 / 3.0 - x * x / 30.0, (np.sin(xs) - xs * np.cos(xs)) / xs**3)
    return 3j * np.asarray(k, dtype=np.float64) * f


@dataclass(frozen=True)
class WaveComponents:
    """The sea as travelling wave components (:mod:`seaecho.ocean.surface`, eq 12'):
    z(r, t) = sum w Re[(a e^{-j omega t} + b e^{+j omega t}) e^{j K.r}].

    Attributes
    ----------
    kx, ky : (N,) arrays
        Wavenumbers [rad/m].
    omega : (N,) array
        Angular frequencies [rad/s].
    a, b : (N,) complex arrays
        Amplitudes of the waves travelling along +K and -K [m].
    weight : (N,) array
        1 or 2 (the half plane of a real FFT) [-].
    """

    kx: NDArray[np.float64]
    ky: NDArray[np.float64]
    omega: NDArray[np.float64]
    a: NDArray[np.complex128]
    b: NDArray[np.complex128]
    weight: NDArray[np.float64]

    def elevation(self, x: float, y: float, t: float) -> float:
        """z at one point (x, y) [m] at time t [s] [m]."""
        e = np.exp(1j * (self.kx * x + self.ky * y))
        ph = np.exp(-1j * self.omega * t)
        return float(np.sum(self.weight * np.real(e * (self.a * ph + self.b * np.conj(ph)))))


@dataclass(frozen=True)
class BoxHullMotion:
    """Heave, pitch and roll of a box hull in waves (eqs S2 to S5).

    Parameters
    ----------
    length, beam, draft : float
        L, B, T [m].
    metacentric_height : float
        GM [m] (> 0).
    damping : (float, float, float)
        Damping ratios of heave, pitch and roll [-].
    roll_gyradius : float or None
        k_xx [m]; None: 0.35 B.
    """

    length: float
    beam: float
    draft: float
    metacentric_height: float
    damping: tuple = (DEFAULT_DAMPING["heave"], DEFAULT_DAMPING["pitch"],
                      DEFAULT_DAMPING["roll"])
    roll_gyradius: float | None = None

    def __post_init__(self) -> None:
        for name in ("length", "beam", "draft", "metacentric_height"):
            v = getattr(self, name)
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"BoxHullMotion.{name} = {v!r} m: must be > 0")
        if len(self.damping) != 3 or not all(np.isfinite(z) and z > 0 for z in self.damping):
            raise ValueError(f"damping = {self.damping!r}: three ratios > 0 [-]")

    @property
    def heave_frequency(self) -> float:
        """omega_3 = sqrt(g / (T + pi B / 8)) [rad/s] (eq S5)."""
        return float(np.sqrt(G / (self.draft + np.pi * self.beam / 8.0)))

    @property
    def pitch_frequency(self) -> float:
        """omega_5 = omega_3 for the uniform box [rad/s] (module docstring)."""
        return self.heave_frequency

    @property
    def roll_frequency(self) -> float:
        """omega_4 = sqrt(g GM) / k_xx [rad/s] (T_4 = 2 pi k_xx / sqrt(g GM))."""
        k = (ROLL_GYRADIUS_OVER_BEAM * self.beam if self.roll_gyradius is None
             else self.roll_gyradius)
        return float(np.sqrt(G * self.metacentric_height) / k)

    def attitude(self, waves: WaveComponents, centre, heading: float, velocity,
                 t: float) -> tuple[float, float, float]:
        """(heave [m], pitch [rad], roll [rad]) at time t [s] (eq S3).

        Parameters
        ----------
        waves : WaveComponents
            The sea.
        centre : (2,) array_like
            The waterplane's centre (x, y) at t [m].
        heading : float
            The hull's heading at t, counter-clockwise from +x [rad].
        velocity : (2,) array_like
            The hull's velocity over the ground at t [m/s] (the encounter frequency).
        t : float
            Time [s].
        """
        ga, gb = self._gains(waves, float(heading), float(velocity[0]), float(velocity[1]))
        ph = np.exp(-1j * waves.omega * t)
        e = np.exp(1j * (waves.kx * float(centre[0]) + waves.ky * float(centre[1])))
        # Eq. S3 (the time-independent factors in ga, gb)
        x = np.real((ga * ph + gb * np.conj(ph)) @ e)
        return float(x[0]), float(np.arctan(x[1])), float(np.arctan(x[2]))

    def _gains(self, waves: WaveComponents, heading: float, vx: float, vy: float
               ) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """(3, N) factors w W_x a H(omega - K.V) and w W_x b H(-omega - K.V) of eq S3 for
        heave, pitch slope, roll slope; the last heading and velocity's are kept (a
        straight course reuses them at every pulse)."""
        key = (id(waves), heading, vx, vy)
        memo = self.__dict__.get("_memo")
        if memo is not None and memo[0] == key:
            return memo[1]
        c, s = np.cos(heading), np.sin(heading)
        kxi = waves.kx * c + waves.ky * s
        keta = -waves.kx * s + waves.ky * c
        half_l, half_b = 0.5 * self.length, 0.5 * self.beam
        # Eq. S4: the waterplane weights
        sl, sb = _sinc(kxi * half_l), _sinc(keta * half_b)
        weights = (sl * sb, _slope_weight(kxi, half_l) * sb, sl * _slope_weight(keta, half_b))
        kv = waves.kx * vx + waves.ky * vy
        ga, gb = [], []
        for w, wn, zeta in zip(weights, (self.heave_frequency, self.pitch_frequency,
                                          self.roll_frequency), self.damping, strict=True):
            # each travelling component through the oscillator at its encounter frequency
            ga.append(waves.weight * w * waves.a
                      * oscillator_response(waves.omega - kv, wn, zeta))
            gb.append(waves.weight * w * waves.b
                      * oscillator_response(-waves.omega - kv, wn, zeta))
        out = (np.array(ga), np.array(gb))
        object.__setattr__(self, "_memo", (key, out))
        return out


__all__ = ["DEFAULT_DAMPING", "ROLL_GYRADIUS_OVER_BEAM", "BoxHullMotion", "WaveComponents",
           "hull_rotation", "oscillator_response", "waterplane_motion"]
