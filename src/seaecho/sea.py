"""The sea of a scene: a random wind sea plus the ship's wake, at any time.

This joins the ocean stage (:mod:`seaecho.ocean`) and the wake stage
(:mod:`seaecho.wake`); :func:`seaecho.build.build_sea` makes the sea of a scene. Later
stages (tracing, radar) take its :class:`SurfaceState` arrays.
"""

from __future__ import annotations

import threading
import weakref
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .ocean.spectra import DirectionalSpectrum
from .ocean.surface import SeaSurface, _kinematics_scratch


class LazySlopes:
    """The slopes (dz/dx, dz/dy) of a sea state, synthesised when first asked for
    (:meth:`seaecho.ocean.surface.SeaSurface.slopes`, the bytes of the batched
    synthesis) plus the Kelvin wakes' (``wake``: their summed fields, or None); once,
    from any thread. A ray-traced pulse never asks (its facets come from the heights)."""

    def __init__(self, surface: SeaSurface, t: float, wake=None) -> None:
        self._args = (surface, float(t), wake)
        self._value: tuple[NDArray, NDArray] | None = None
        self._lock = threading.Lock()

    @property
    def value(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(dz/dx, dz/dy), sea + wake [-]."""
        with self._lock:
            if self._value is None:
                surface, t, wake = self._args
                sx, sy = surface.slopes(t)
                if wake is not None:
                    sx, sy = sx + wake.slope_x, sy + wake.slope_y
                self._value = (sx, sy)
                self._args = None
            return self._value

    def __reduce__(self):  # pickled as its arrays
        return (tuple, (self.value,))


@dataclass(frozen=True)
class SurfaceState:
    """Sea + wake on the grid at one time. Arrays shaped (ny, nx) unless stated.

    The slopes come as ``slopes``: the pair (dz/dx, dz/dy), or a :class:`LazySlopes`
    that synthesises them when :attr:`slope_x` or :attr:`slope_y` is first read.
    """

    t: float  #: time [s]
    x: NDArray[np.float64]  #: x coordinates (nx,) [m]
    y: NDArray[np.float64]  #: y coordinates (ny,) [m]
    elevation: NDArray[np.float64]  #: z, sea + wake [m]
    slopes: tuple | LazySlopes  #: (dz/dx, dz/dy), sea + wake [-], or their LazySlopes
    velocity: NDArray[np.float64]  #: surface velocity (u, v, w), (ny, nx, 3) [m/s]
    wake_elevation: NDArray[np.float64]  #: the Kelvin wake's own height [m]
    #: Bragg spectrum change of the wake: the sea's Bragg spectrum is multiplied by
    #: 1 - wake_mask; 0 (none) .. 1 (short waves damped by the turbulent wake), negative
    #: where the narrow-V wake adds Bragg waves (:mod:`seaecho.wake.narrow_v`) [-]
    wake_mask: NDArray[np.float64]

    @property
    def slope_x(self) -> NDArray[np.float64]:
        """dz/dx, sea + wake [-]."""
        s = self.slopes
        return (s.value if isinstance(s, LazySlopes) else s)[0]

    @property
    def slope_y(self) -> NDArray[np.float64]:
        """dz/dy, sea + wake [-]."""
        s = self.slopes
        return (s.value if isinstance(s, LazySlopes) else s)[1]


@dataclass(frozen=True)
class SurfaceKinematics:
    """Displacement and acceleration of the wind sea's surface particles at one time.

    Linear (Airy) kinematics of the synthesised waves: for a wave of wavenumber K the
    particle at rest position ``r`` moves horizontally by ``D = j (K / |K|) coth(K d) z``
    (in the phasor notation of :mod:`seaecho.ocean.surface`; its time derivative is the
    horizontal orbital velocity there) and vertically by the elevation ``z``; the
    acceleration is ``-omega^2`` times the displacement (Lamb 1932, art. 228-229). Arrays
    shaped (ny, nx, ...). The Kelvin wake is not included (its heights are a steady
    pattern moving with the ship).

    Attributes
    ----------
    t : float
        Time [s].
    displacement : ndarray (ny, nx, 2)
        Horizontal particle displacement (D_x, D_y) [m].
    acceleration : ndarray (ny, nx, 3) or None
        Particle acceleration (a_x, a_y, a_z) [m/s^2] (None when not asked for).
    acceleration_z : ndarray (ny, nx) or None
        The vertical acceleration a_z [m/s^2]: ``acceleration[..., 2]`` where that is
        given, alone with ``acceleration="vertical"``, else None.
    """

    t: float
    displacement: NDArray[np.float64]
    acceleration: NDArray[np.float64] | None
    acceleration_z: NDArray[np.float64] | None = None


def surface_kinematics(surface: SeaSurface, t: float, acceleration: bool | str = True
                       ) -> SurfaceKinematics:
    """:class:`SurfaceKinematics` of a :class:`~seaecho.ocean.surface.SeaSurface` at ``t``.

    Uses the realisation's travelling-wave amplitudes (``plus`` along +K, ``minus`` along
    -K) and its dispersion relation: the inverse real FFTs of ``j (K / K) coth(K d) z``
    (two) and of ``-omega^2`` times those and ``z`` (three more with ``acceleration``;
    ``"vertical"``: the one of ``z``, for ``acceleration_z`` alone; False: none, the
    acceleration attributes None), batched in one transform whose spectra are written
    into pooled scratch arrays (``ocean.surface._kinematics_scratch``); only the fields
    returned are new arrays, views of one (k, ny, nx) array with the component axis moved
    last. Every field has the bytes of its own inverse FFT whatever else is asked for.
    """
    vertical = isinstance(acceleration, str)
    if vertical and acceleration != "vertical":
        raise ValueError(f"acceleration = {acceleration!r}: allowed True, False, 'vertical'")
    jx, jy = _displacement_factors(surface)
    full = not vertical and bool(acceleration)
    n = 5 if full else 3 if vertical else 2
    with _kinematics_scratch(surface._a.shape) as w:
        plus, minus = surface._travelling_into(t, w)
        z_hat = np.add(plus, minus, out=w["z_hat"])
        spectra = w["spectra"][:n]
        np.multiply(jx, z_hat, out=spectra[0])  # j (K_x / K) coth(K d) z
        np.multiply(jy, z_hat, out=spectra[1])
        if n > 2:  # -omega^2 ([D_x, D_y,] z)
            w2 = _minus_omega_squared(surface)
            if full:
                np.multiply(w2, spectra[0], out=spectra[2])
                np.multiply(w2, spectra[1], out=spectra[3])
            np.multiply(w2, z_hat, out=spectra[n - 1])
        fields = surface._irfft_scratch(spectra)  # one batched transform
    disp = np.moveaxis(fields[:2], 0, -1)
    acc = np.moveaxis(fields[2:], 0, -1) if full else None
    return SurfaceKinematics(t=float(t), displacement=disp, acceleration=acc,
                             acceleration_z=fields[n - 1] if n > 2 else None)


_FACTORS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _displacement_factors(surface: SeaSurface) -> tuple[NDArray, NDArray]:
    """``j K_x coth(K d) / K`` and ``j K_y coth(K d) / K`` of a surface's wavenumbers [-]
    (0 at K = 0): the time-independent factors of the horizontal displacement, made once
    per surface."""
    out = _FACTORS.get(surface)
    if out is None:
        k = np.hypot(surface._kx, surface._ky)
        with np.errstate(divide="ignore", invalid="ignore"):
            coth = 1.0 if surface.depth is None else 1.0 / np.tanh(k * surface.depth)
            gain = np.where(k > 0, coth / np.where(k > 0, k, 1.0), 0.0)
        out = (1j * surface._kx * gain, 1j * surface._ky * gain)
        _FACTORS[surface] = out
    return out


def _minus_omega_squared(surface: SeaSurface) -> NDArray[np.float64]:
    """``-omega^2`` of a surface's half plane [rad^2/s^2], made once per surface."""
    out = _W2.get(surface)
    if out is None:
        out = -surface._omega ** 2
        _W2[surface] = out
    return out


_W2: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def vertical_acceleration(surface: SeaSurface, t: float, k_max: float | None = None
                          ) -> NDArray[np.float64]:
    """The particles' vertical acceleration a_z = -omega^2 z of the wind sea at ``t``
    [m/s^2], shape (ny, nx): ``surface_kinematics(surface, t).acceleration[..., 2]``, bit
    for bit, by one inverse FFT instead of five (Lamb 1932, art. 228-229).

    ``k_max`` [rad/m]: that of the waves ``|K| < k_max`` only (the long waves that
    modulate breaking, eq BR7 of :mod:`seaecho.scattering.breaking`); None, or a
    ``k_max`` above every wavenumber of the grid, gives the whole sea's, bit for bit.
    """
    plus, minus = surface._travelling(t)
    spec = -surface._omega ** 2 * (plus + minus)
    if k_max is not None:
        k2 = surface._kx ** 2 + surface._ky ** 2
        if float(np.max(k2)) >= k_max * k_max:
            spec = np.where(k2 < k_max * k_max, spec, 0.0)
    return surface._irfft_scratch(spec)


def band_velocity(surface: SeaSurface, t: float, k_min: float) -> NDArray[np.float64]:
    """The wind sea's surface velocity (u, v, w) at ``t`` of the waves ``|K| >= k_min``
    [m/s], shape (ny, nx, 3): :meth:`SeaSurface.fields`' velocity (orbital, less the
    current's advection on a current, eq C1) band-limited on the grid's own wavenumbers,
    synthesised from the travelling waves' spectra with the same factors
    (:meth:`SeaSurface.band_velocity`: three inverse transforms in one call, no forward
    one).

    The breaking zones ride on the waves longer than the breakers; the resolved waves
    shorter than ``k_mod`` (eq BR7 of :mod:`seaecho.scattering.breaking`) are breakers
    themselves, whose speed the fronts' velocity already counts: this is the part of the
    facets' velocity that the breaking zones' Doppler leaves out (eq BR10).
    """
    return surface.band_velocity(t, k_min)


#: Grids with at least this many nodes compute the ship's wake on a second thread [-].
THREAD_MIN_NODES = 128 * 128


class ThreadJob:
    """``fn(*args)`` on a thread of its own; :meth:`result` joins it and returns its value
    or raises its exception (a plain thread per call: nothing to shut down, fork-safe)."""

    def __init__(self, fn, *args) -> None:
        self._out: list = []
        self._thread = threading.Thread(target=self._run, args=(fn, args), daemon=True)
        self._thread.start()

    def _run(self, fn, args) -> None:
        try:
            self._out.append((True, fn(*args)))
        except BaseException as exc:  # re-raised by result() in the caller's thread
            self._out.append((False, exc))

    def result(self):
        self._thread.join()
        ok, value = self._out[0]
        if not ok:
            raise value
        return value


class Sea:
    """The sea of a scene: surface realisation (seeded) and optional ship wakes.

    Several ships: their Kelvin wakes add (linear waves superpose: elevations, slopes
    and vertical velocities sum) and their turbulent wakes damp the Bragg waves in turn,
    the combined damping fraction being ``1 - prod(1 - m_i)`` of the ships' masks m_i
    (each removes its fraction of what the others left, as eq W15 combines the turbulent
    and film parts; docs/wake.md).

    Parameters
    ----------
    surface : SeaSurface
        The wind sea.
    ship : seaecho.wake.Ship, sequence of them, or None
        The ship(s) whose wakes are added.
    kelvin_wake : bool or sequence of bool
        Add the Kelvin wake heights (else only the turbulent-wake mask), for all ships or
        one flag per ship.
    turbulent_wake_length : float or None
        Length of the turbulent wake [m] (None: each ship's own, else the wake stage's
        default).
    narrow_v : bool or sequence of bool
        Add each ship's narrow-V wake (:mod:`seaecho.wake.narrow_v`), for all ships or one
        flag per ship; it needs ``narrow_v_bragg_vector``.
    narrow_v_bragg_vector : (float, float) or None
        The radar's Bragg vector K_B [rad/m] at which the narrow-V wakes' Bragg waves
        raise the sea's Bragg spectrum (:func:`seaecho.wake.narrow_v_bragg_gain`); None:
        no narrow-V wake.
    """

    def __init__(self, surface: SeaSurface, ship=None, kelvin_wake=True,
                 turbulent_wake_length: float | None = None, narrow_v=False,
                 narrow_v_bragg_vector: tuple[float, float] | None = None) -> None:
        self.surface = surface
        if ship is None:
            ships: tuple = ()
        elif isinstance(ship, (list, tuple)):
            ships = tuple(ship)
        else:
            ships = (ship,)
        #: every ship whose wake is added
        self.ships = ships
        #: the first ship (None without ships)
        self.ship = ships[0] if ships else None
        self.turbulent_wake_length = turbulent_wake_length
        flags = (kelvin_wake if isinstance(kelvin_wake, (list, tuple))
                 else [kelvin_wake] * len(ships))
        if len(flags) != len(ships):
            raise ValueError(f"kelvin_wake: {len(flags)} flags for {len(ships)} ships")
        narrow = (list(narrow_v) if isinstance(narrow_v, (list, tuple))
                  else [narrow_v] * len(ships))
        if len(narrow) != len(ships):
            raise ValueError(f"narrow_v: {len(narrow)} flags for {len(ships)} ships")
        self.narrow_v_bragg_vector = narrow_v_bragg_vector
        #: the ships whose narrow-V wake is added (none without a Bragg vector)
        self.narrow_v_ships = (() if narrow_v_bragg_vector is None else
                               tuple(s for s, n in zip(ships, narrow, strict=True) if n))
        from .wake import KelvinWake

        self._wakes = [KelvinWake(s) for s, k in zip(ships, flags, strict=True) if k]
        #: :meth:`state` synthesises the slopes only when they are read (a ray-traced
        #: simulation sets it: its facets come from the heights)
        self.lazy_slopes = False

    @property
    def spectrum(self) -> DirectionalSpectrum:
        return self.surface.spectrum

    @property
    def x(self) -> NDArray[np.float64]:
        return self.surface.x

    @property
    def y(self) -> NDArray[np.float64]:
        return self.surface.y

    def kinematics(self, t: float = 0.0, acceleration: bool | str = True
                   ) -> SurfaceKinematics:
        """Particle displacement and acceleration of the wind sea at ``t`` [s]
        (:func:`surface_kinematics`; the displacement alone without ``acceleration``, and
        the vertical acceleration only with ``"vertical"``).
        From then on the surface keeps its last time's travelling waves for the sea state
        of that time (``SeaSurface.share_travelling``)."""
        self.surface.share_travelling = True
        return surface_kinematics(self.surface, t, acceleration)

    def band_velocity(self, t: float, k_min: float) -> NDArray[np.float64]:
        """The wind sea's surface velocity of the waves ``|K| >= k_min`` [rad/m] at ``t``
        [s] [m/s], (ny, nx, 3) (:func:`band_velocity`)."""
        return band_velocity(self.surface, t, k_min)

    def vertical_acceleration(self, t: float = 0.0, k_max: float | None = None
                              ) -> NDArray[np.float64]:
        """Vertical particle acceleration of the wind sea at ``t`` [m/s^2], of the waves
        ``|K| < k_max`` [rad/m] if given (:func:`vertical_acceleration`)."""
        return vertical_acceleration(self.surface, t, k_max)

    def _ship_fields(self, t: float):
        """The Kelvin wakes' summed fields (or None) and the combined turbulent-wake mask
        (or None)."""
        w = None
        for wake in self._wakes:  # a few ships, each one vectorised over the grid
            f = wake.fields(self.x, self.y, t)
            w = f if w is None else type(f)(*(getattr(w, n) + getattr(f, n) for n in
                                               ("elevation", "slope_x", "slope_y", "dzdt")))
        mask = None
        if self.ships:
            from .wake import turbulent_wake_mask

            keep = None
            for ship in self.ships:
                m = turbulent_wake_mask(ship, self.x, self.y, t,
                                        length=self.turbulent_wake_length)
                keep = 1.0 - m if keep is None else keep * (1.0 - m)
            mask = 1.0 - keep if len(self.ships) > 1 else m
            if self.narrow_v_ships:
                from .wake import narrow_v_bragg_gain

                k_b = self.narrow_v_bragg_vector
                s_b = float(self.spectrum.height_spectrum(*k_b))
                # the ships' Bragg-wave energies add (linear waves)
                gain = sum(narrow_v_bragg_gain(s, self.x, self.y, t, k_b, s_b)
                           for s in self.narrow_v_ships)
                # Eq N7: the narrow-V's Bragg waves raise what the turbulent wakes leave
                mask = 1.0 - (1.0 - mask) * (1.0 + gain)
        return w, mask

    def state(self, t: float = 0.0, lazy_slopes: bool | None = None) -> SurfaceState:
        """Sea + wake at time ``t`` [s].

        On grids of at least :data:`THREAD_MIN_NODES` nodes the ship's wake is computed
        on a thread of its own while the wind sea is synthesised (finufft and numpy
        release the GIL): the same numbers, in less wall time on two cores. With
        ``lazy_slopes`` (None: :attr:`lazy_slopes`) the slopes are synthesised only if
        read (:class:`LazySlopes`, the same bytes): a ray-traced pulse does not read them.
        """
        if lazy_slopes is None:
            lazy_slopes = self.lazy_slopes
        threaded = bool(self.ships) and self.x.size * self.y.size >= THREAD_MIN_NODES
        job = ThreadJob(self._ship_fields, t) if threaded else None
        f = self.surface.fields(t, slopes=not lazy_slopes)
        w, mask = job.result() if threaded else self._ship_fields(t)
        shape = f.elevation.shape
        wake_z = np.zeros(shape)
        elevation, velocity = f.elevation, f.velocity
        slopes = LazySlopes(self.surface, t, w) if lazy_slopes else (f.slope_x, f.slope_y)
        if w is not None:
            wake_z = w.elevation
            elevation = elevation + w.elevation
            if not lazy_slopes:
                slopes = (f.slope_x + w.slope_x, f.slope_y + w.slope_y)
            velocity = velocity.copy()
            velocity[..., 2] += w.dzdt
        if mask is None:
            mask = np.zeros(shape)
        return SurfaceState(
            t=float(t), x=self.x, y=self.y, elevation=elevation, slopes=slopes,
            velocity=velocity, wake_elevation=wake_z,
            wake_mask=np.asarray(mask, dtype=np.float64),
        )


__all__ = ["THREAD_MIN_NODES", "LazySlopes", "Sea", "SurfaceKinematics", "SurfaceState",
           "band_velocity", "surface_kinematics", "vertical_acceleration"]
