"""Random sea surface synthesis and time evolution (paper eqs 12 and 15).

A realisation is drawn once, in the Fourier domain, and evolved to any time t exactly:

.. math::

    \\hat z(\\mathbf K, t) = h_0(\\mathbf K) e^{-j\\omega t}
        + h_0^*(-\\mathbf K) e^{+j\\omega t},\\qquad
    h_0(\\mathbf K) = \\xi(\\mathbf K)\\sqrt{\\tfrac12 \\bar\\Psi(\\mathbf K)\\,\\delta K_x
        \\delta K_y}                                                               (12')

    z(\\mathbf r, t) = \\sum_{\\mathbf K} \\hat z(\\mathbf K, t) e^{j \\mathbf K\\cdot\\mathbf r}

with xi zero-mean circular complex Gaussian of unit variance (the paper's uniform [0, 1]
draws of eq 12 have a non-zero mean and the wrong distribution, see docs/ocean.md),
omega(K) from the dispersion relation (eq 15) and
:math:`\\bar\\Psi` the spectrum averaged over each grid cell. The first term is the wave
that travels along +K, the second the one along -K; the sum is Hermitian
(:math:`\\hat z(-K) = \\hat z^*(K)`) so z is real, and
:math:`E\\,z^2 = \\sum_K \\bar\\Psi\\,\\delta K^2`, the integral of the spectrum over the
resolved band (every grid cell but the zero-wavenumber one and the Nyquist row/column).

Slopes are spectral derivatives (j K_x, j K_y); the vertical surface velocity is
dz/dt; the horizontal orbital velocity at the surface follows linear wave theory,
u = (K / K) omega coth(K d) z for a wave travelling along K (Lamb 1932, art. 228).

The tessellated FFT approach is that of Tessendorf (2001) and Mastin et al. (1987).

A uniform surface current U (``current``) carries every wave: the wave along +K turns at
omega_0(K) + K.U and the one along -K at omega_0(K) - K.U
(:func:`~seaecho.ocean.dispersion.doppler_shifted_frequency`, eq C1), so that
z(r, t) = z_0(r - U t, t), the still-water sea advected by U. The fields are Eulerian
(on the fixed grid): the velocity returned is then the rate of change of the surface
point above each node, the orbital velocity less the advection of the orbital pattern,
``-U . grad`` of the displacement and of the elevation; the particles' own drift U is
carried by the sub-facet scatterers (:mod:`seaecho.scattering.dynamics`).

Precision. The elevation, which sets the echoes' phases (a two-way path of 2 z cos(theta)
is 4 pi z / lambda of carrier phase), is synthesised in float64. The slopes and the
velocities are synthesised by default in float32 (``precision="single"``) and returned as
float64: an FFT of 2^18 points rounds at about 1e-7 of the field's rms, i.e. 1e-8 in
slope and 1e-8 m/s in velocity for a sea of 0.1 rms slope and 0.1 m/s rms velocity, far
below anything a facet's scattering or Doppler resolves, at a quarter of the float64
transform's cost on this CPU (``docs/performance.md``). ``precision="double"`` synthesises
every field in float64 (the parity reference of the tests).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] G. A. Mastin, P. A. Watterberg and J. F. Mareda, "Fourier synthesis of ocean
   scenes", IEEE Computer Graphics and Applications 7(3), 16-23, 1987.
.. [2] J. Tessendorf, "Simulating ocean water", SIGGRAPH course notes, 2001.
.. [3] H. Lamb, *Hydrodynamics*, 6th ed., 1932, art. 228.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np
import scipy.fft
from numpy.typing import NDArray

from ..constants import SURFACE_TENSION_OVER_DENSITY
from .dispersion import angular_frequency, doppler_shifted_frequency, horizontal_to_vertical_ratio
from .spectra import K_FLOOR, DirectionalSpectrum

#: Grid cells whose centre lies within this many peak wavenumbers are integrated on a
#: sub-grid when a cell is coarser than _REFINE_COARSE peak wavenumbers; elsewhere the
#: spectrum is smooth on the scale of a cell (midpoint error ~ (dk / k_p)^2 < 0.3 %).
_REFINE_PEAKS = 4.0
_REFINE_COARSE = 0.05
_REFINE_SUB = 6
#: Allowed ``SeaSurface(precision=...)``.
PRECISIONS = ("single", "double")


def grid_coordinates(size: float, n: int) -> NDArray[np.float64]:
    """Cell coordinates of a periodic grid centred on 0: (arange(n) - n/2) * size / n [m]."""
    return (np.arange(n) - n // 2) * (size / n)


def cell_averaged_spectrum(
    spectrum: DirectionalSpectrum,
    kx: NDArray[np.float64],
    ky: NDArray[np.float64],
    dkx: float,
    dky: float,
) -> NDArray[np.float64]:
    """Psi averaged over the grid cells centred on (kx, ky) of size dkx x dky [m^4].

    Near the spectral peak (within a few peak wavenumbers) the spectrum varies on the
    scale of a cell of a small tile, so those cells are integrated with a 6 x 6 midpoint
    rule; elsewhere the midpoint value is used. kx, ky broadcast against each other.
    """
    kx, ky = np.broadcast_arrays(np.asarray(kx, float), np.asarray(ky, float))
    k = np.hypot(kx, ky)
    psi = _psi_on_fft_grid(spectrum, kx, ky, k)
    k_peak = spectrum.peak_wavenumber()
    refine = np.broadcast_to(k < _REFINE_PEAKS * k_peak + 2 * np.hypot(dkx, dky), psi.shape)
    if max(dkx, dky) > _REFINE_COARSE * k_peak and np.any(refine):
        kxb, kyb = np.broadcast_arrays(kx, ky)
        cx = kxb[refine][:, None]
        cy = kyb[refine][:, None]
        offsets = (np.arange(_REFINE_SUB) + 0.5) / _REFINE_SUB - 0.5
        ox, oy = np.meshgrid(offsets * dkx, offsets * dky, indexing="xy")
        sub = spectrum(cx + ox.ravel()[None, :], cy + oy.ravel()[None, :])
        psi = psi.copy()
        psi[refine] = sub.mean(axis=1)
    return psi


def _psi_on_fft_grid(
    spectrum: DirectionalSpectrum,
    kx: NDArray[np.float64],
    ky: NDArray[np.float64],
    k: NDArray[np.float64],
) -> NDArray[np.float64]:
    """Psi on a grid, evaluating the (costly) omnidirectional spectrum once per |K|.

    On an FFT grid |K| takes each value at up to four points (+-kx, +-ky); the
    omnidirectional part is evaluated on the unique (|kx|, |ky|) pairs and gathered, which
    gives the same numbers as ``spectrum(kx, ky)`` at a quarter of the cost.
    """
    ukx, ix = np.unique(np.abs(kx[0, :]), return_inverse=True)
    uky, iy = np.unique(np.abs(ky[:, 0]), return_inverse=True)
    if ukx.size * uky.size * 2 > k.size or not (
        np.all(kx == kx[:1, :]) and np.all(ky == ky[:, :1])
    ):
        return spectrum(kx, ky)
    kq = np.hypot(ukx[None, :], uky[:, None])
    omni = spectrum.omni(kq)[iy[:, None], ix[None, :]]
    psi_dir = np.arctan2(ky, kx) - spectrum.wind_direction
    pos = k > K_FLOOR
    ks = np.where(pos, k, 1.0)
    return np.where(pos, omni * spectrum.spread(ks, psi_dir) / ks, 0.0)  # Eq. 4


#: Scratch arrays of :meth:`SeaSurface.fields`, by (half-plane shape, complex type): a
#: few sets per grid shape, shared by the surfaces of that shape (two threads may
#: synthesise at once: the next pulse's sea computed ahead) [-].
_SCRATCH: dict[tuple, list[dict]] = {}
_SCRATCH_LOCK = threading.Lock()
_SCRATCH_KEEP = 2


class _scratch:
    """A set of scratch arrays for :meth:`SeaSurface.fields` on a half plane of
    ``shape`` (``with _scratch(shape, complex_type) as w``): taken from the pool, or
    made, and given back after use."""

    def __init__(self, shape: tuple[int, int], c: type) -> None:
        self.key = (tuple(shape), np.dtype(c).str)
        self.shape, self.c = tuple(shape), c

    def __enter__(self) -> dict:
        with _SCRATCH_LOCK:
            free = _SCRATCH.get(self.key)
            if free:
                self.w = free.pop()
                return self.w
        self.w = self._make()
        return self.w

    def _make(self) -> dict:
        e = np.empty
        return dict(phase=e(self.shape, np.complex128), plus=e(self.shape, np.complex128),
                    z_hat=e(self.shape, np.complex128), z_c=e(self.shape, self.c),
                    diff=e(self.shape, self.c), spectra=e((5, *self.shape), self.c))

    def __exit__(self, *exc) -> None:
        with _SCRATCH_LOCK:
            free = _SCRATCH.setdefault(self.key, [])
            if len(free) < _SCRATCH_KEEP:
                free.append(self.w)


class _kinematics_scratch(_scratch):
    """Scratch arrays of the particles' kinematics (:func:`seaecho.sea.
    surface_kinematics`) on a half plane of ``shape``: the travelling waves' (for
    :meth:`SeaSurface._travelling_into`), ``z_hat`` and a stack of five float64 spectra
    (``with _kinematics_scratch(shape) as w``), pooled as :class:`_scratch`'s."""

    def __init__(self, shape: tuple[int, int]) -> None:
        super().__init__(shape, np.complex128)
        self.key = (*self.key, "kinematics")

    def _make(self) -> dict:
        e = np.empty
        return dict(phase=e(self.shape, np.complex128), plus=e(self.shape, np.complex128),
                    z_hat=e(self.shape, np.complex128),
                    spectra=e((5, *self.shape), np.complex128))


@dataclass(frozen=True)
class SurfaceFields:
    """The sea surface on the grid at one time; arrays shaped (ny, nx)."""

    t: float  #: time [s]
    elevation: NDArray[np.float64]  #: z [m]
    slope_x: NDArray[np.float64] | None  #: dz/dx [-] (None: ``fields(slopes=False)``)
    slope_y: NDArray[np.float64] | None  #: dz/dy [-] (None: ``fields(slopes=False)``)
    velocity: NDArray[np.float64]  #: surface particle velocity (u, v, w), shape (ny, nx, 3) [m/s]


class SeaSurface:
    """One random realisation of a sea surface on a periodic grid, at any time.

    Parameters
    ----------
    spectrum : DirectionalSpectrum
        The directional wave spectrum.
    size : (float, float)
        Tile extents (Lx, Ly) [m].
    shape : (int, int)
        Grid nodes (ny, nx) in array order (as every gridded field), each even.
    rng : numpy.random.Generator
        Source of the random amplitudes (see :mod:`seaecho.rng`).
    depth : float or None
        Water depth [m] for the dispersion relation (eq 15); None for deep water.
    surface_tension : float
        Kinematic surface tension [m^3/s^2] in the dispersion relation; 0 for eq 15 as
        printed.
    precision : {"single", "double"}
        Floating-point type in which the slopes and velocities are synthesised (the
        elevation is always float64; see the module docstring).
    centre : (float, float)
        Coordinates (x, y) of the grid's node (nx/2, ny/2) [m] (default the origin).
    cell_spectrum : ndarray (ny, nx), optional
        :func:`cell_averaged_spectrum` of this spectrum on this grid in FFT order [m^4],
        if already computed (the tiles of a radar-wide sea share their level's).
    current : (float, float)
        Uniform surface current (U_x, U_y) [m/s] in the scene frame (module docstring);
        (0, 0): still water, the same numbers as without it.

    Notes
    -----
    Arrays are shaped (ny, nx): axis 0 is y (north), axis 1 is x (east). Coordinates are
    ``x = centre_x + (arange(nx) - nx/2) dx``; the tile is periodic.
    """

    def __init__(
        self,
        spectrum: DirectionalSpectrum,
        size: tuple[float, float],
        shape: tuple[int, int],
        rng: np.random.Generator,
        depth: float | None = None,
        surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
        precision: str = "single",
        centre: tuple[float, float] = (0.0, 0.0),
        cell_spectrum: NDArray[np.float64] | None = None,
        current: tuple[float, float] = (0.0, 0.0),
    ) -> None:
        if precision not in PRECISIONS:
            raise ValueError(f"precision = {precision!r}: allowed {PRECISIONS}")
        lx, ly = (float(v) for v in size)
        ny, nx = (int(v) for v in shape)
        if nx < 4 or ny < 4 or nx % 2 or ny % 2:
            raise ValueError(f"shape = {shape}: grid sizes must be even and >= 4")
        if not (lx > 0 and ly > 0):
            raise ValueError(f"size = {size} m: tile extents must be > 0")
        self.spectrum = spectrum
        self.size = (lx, ly)
        #: grid nodes (ny, nx), the shape of every field
        self.shape = (ny, nx)
        self.depth = depth
        self.dx, self.dy = lx / nx, ly / ny
        #: the grid's centre node (index n / 2) [m]: a tile of a radar-wide sea lies
        #: away from the origin (seaecho.geometry.patchwork); only the coordinates move
        self.centre = (float(centre[0]), float(centre[1]))
        self.x = self.centre[0] + grid_coordinates(lx, nx)
        self.y = self.centre[1] + grid_coordinates(ly, ny)
        self.dkx, self.dky = 2 * np.pi / lx, 2 * np.pi / ly

        # full-plane wavenumber grid in FFT order, (ny, nx)
        kx = 2 * np.pi * np.fft.fftfreq(nx, self.dx)
        ky = 2 * np.pi * np.fft.fftfreq(ny, self.dy)
        kxg, kyg = kx[None, :], ky[:, None]
        psi = (cell_averaged_spectrum(spectrum, kxg, kyg, self.dkx, self.dky)
               if cell_spectrum is None else np.array(cell_spectrum, dtype=np.float64))
        if psi.shape != (ny, nx):
            raise ValueError(f"cell_spectrum: shape {psi.shape}, the grid's is {(ny, nx)}")
        psi[0, 0] = 0.0  # zero mean
        psi[ny // 2, :] = 0.0  # Nyquist row and column: no travelling direction
        psi[:, nx // 2] = 0.0
        #: expected variance of z: the integral of Psi over the resolved band [m^2]
        self.resolved_variance = float(psi.sum() * self.dkx * self.dky)

        # a + j b with a, b ~ N(0, 1) drawn as pairs: variance 2, i.e. sqrt(2) times the
        # unit circular Gaussian xi of eq 12'; hence sqrt(Psi dK^2 / 4) for the
        # sqrt(Psi dK^2 / 2) of eq 12' (E |h0|^2 = Psi dK^2 / 2 either way)
        xi2 = rng.standard_normal((ny, nx, 2)).view(np.complex128)[..., 0]
        h0 = xi2 * np.sqrt(0.25 * self.dkx * self.dky * psi)  # Eq. 12'

        # keep the half plane kx >= 0 for real inverse FFTs (axis 1 = x is the rfft axis)
        half = nx // 2 + 1
        neg_y = (-np.arange(ny)) % ny
        neg_x = (-np.arange(half)) % nx
        self._a = np.ascontiguousarray(h0[:, :half])
        self._b = np.conj(h0[neg_y][:, neg_x])  # h0*(-K) on the half plane
        self._kx = kx[:half][None, :].copy()
        self._kx[0, -1] = np.pi / self.dx  # Nyquist column (zero amplitude anyway)
        self._ky = ky[:, None].copy()
        k = np.hypot(self._kx, self._ky)
        self._omega = angular_frequency(k, depth, surface_tension)
        with np.errstate(divide="ignore", invalid="ignore"):
            coth = horizontal_to_vertical_ratio(k, depth)
            speed = np.where(k > 0, self._omega * coth / k, 0.0)
        self._ux = self._kx * speed
        self._uy = self._ky * speed
        #: uniform surface current (U_x, U_y) [m/s]
        self.current = (float(current[0]), float(current[1]))
        if not all(np.isfinite(self.current)):
            raise ValueError(f"current = {current} m/s: must be finite")
        #: (omega(+K), omega(-K)) of eq C1 on the half plane [rad/s]; None in still water
        self._omega_current = None
        if self.current != (0.0, 0.0):
            kxb, kyb = np.broadcast_arrays(self._kx, self._ky)
            self._omega_current = (
                doppler_shifted_frequency(self._omega, kxb, kyb, self.current),  # along +K
                -doppler_shifted_frequency(-self._omega, kxb, kyb, self.current))  # -K
        #: complex type of the slopes' and velocities' spectra
        self.precision = precision
        c = np.complex64 if precision == "single" else np.complex128
        r = np.float32 if precision == "single" else np.float64
        # multipliers of z_hat (slopes) and of plus - minus (velocities), in that order
        self._derivatives = (
            (1j * self._kx).astype(c), (1j * self._ky).astype(c),
            (-1j * self._omega).astype(c), self._ux.astype(r), self._uy.astype(r))
        #: keep the last time's travelling waves for the next caller of that time (set
        #: by ``seaecho.sea.Sea.kinematics``; off, a surface keeps nothing per time)
        self.share_travelling = False
        self._travelling_lock = threading.Lock()
        self._travelling_last: tuple[float, tuple[NDArray, NDArray]] | None = None

    def __getstate__(self) -> dict:
        state = dict(self.__dict__)
        state["_travelling_lock"] = None  # a lock does not pickle
        state["_travelling_last"] = None
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._travelling_lock = threading.Lock()

    def _irfft(self, spec: NDArray[np.complexfloating]) -> NDArray[np.floating]:
        """Inverse real FFT over the last two axes (a stack of spectra in one call), in
        the precision of ``spec``."""
        ny, nx = self.shape
        return scipy.fft.irfft2(spec, s=(ny, nx), axes=(-2, -1), norm="forward", workers=-1)

    def _irfft_scratch(self, spec: NDArray[np.complexfloating]) -> NDArray[np.floating]:
        """:meth:`_irfft` of ``spec``, the same bytes, with ``spec`` (a scratch array)
        overwritten by the inverse complex FFT along y: pocketfft's ``irfft2`` does that
        transform first (with the unit factor of ``norm="forward"``) into a temporary
        array of the spectra's size, whose pages the kernel would fault in and zero at
        every call; here only the output is new."""
        ny, nx = self.shape
        spec = scipy.fft.ifft(spec, axis=-2, norm="forward", overwrite_x=True, workers=-1)
        return scipy.fft.irfft(spec, n=nx, axis=-1, norm="forward", workers=-1)

    def _travelling(self, t: float) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """The two travelling waves' spectra at ``t`` [s] (eq 12'): ``a e^{-j omega t}``
        and ``b e^{+j omega t}``, read-only. With :attr:`share_travelling` the last
        time's are kept (the sea state and the particles' kinematics of one time share
        them, from whichever thread asks first)."""
        if not self.share_travelling:
            return self._travelling_at(t)
        with self._travelling_lock:
            last = self._travelling_last
            if last is not None and last[0] == t:
                return last[1]
            out = self._travelling_at(t)
            self._travelling_last = (t, out)
            return out

    def _minus_j_omega(self) -> NDArray[np.complex128]:
        """``-1j * omega`` on the half plane [rad/s] (made once)."""
        out = self.__dict__.get("_mjw")
        if out is None:
            out = -1j * self._omega
            self._mjw = out
        return out

    def _travelling_at(self, t: float) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        if self._omega_current is None:
            phase = self._minus_j_omega() * t
            np.exp(phase, out=phase)  # Eq. 15 evolution, exp(-j omega t)
            out = (self._a * phase, self._b * np.conj(phase))
        else:  # eq C1: each wave at its Doppler-shifted frequency
            w_plus, w_minus = self._omega_current
            out = (self._a * np.exp(-1j * w_plus * t), self._b * np.exp(1j * w_minus * t))
        for a in out:
            a.flags.writeable = False
        return out

    def components(self, slope_fraction: float = 1e-3, height_fraction: float = 1e-4,
                   limit: int = 20000) -> tuple[NDArray, ...]:
        """The realisation as travelling waves, the strongest first:
        z(r, t) = sum w Re[(a e^{-j omega t} + b e^{+j omega t}) e^{j K.r}] (eq 12').

        Keeps the fewest components that carry all but ``height_fraction`` of the
        height variance and all but ``slope_fraction`` of the slope variance, at most
        ``limit`` of them.

        Returns
        -------
        kx, ky, omega, a, b, weight : (N,) arrays
            [rad/m], [rad/m], [rad/s], [m], [m], [-] (weight 2 on the half plane's
            columns kx > 0, 1 on kx = 0, as the inverse real FFT counts them).
        """
        if self._omega_current is not None:
            raise NotImplementedError("not implemented yet: the travelling-wave components "
                                      "of a sea on a current (one frequency per component)")
        ny, nx = self.shape
        w = np.full(self._a.shape, 2.0)
        w[:, 0] = 1.0
        w[:, -1] = 1.0 if nx % 2 == 0 else 2.0
        kx = np.broadcast_to(self._kx, w.shape)
        ky = np.broadcast_to(self._ky, w.shape)
        e = (w * (np.abs(self._a) ** 2 + np.abs(self._b) ** 2)).ravel()
        keep = np.zeros(e.size, dtype=bool)
        for energy, frac in ((e, height_fraction), (e * (kx * kx + ky * ky).ravel(),
                                                    slope_fraction)):
            order = np.argsort(-energy, kind="stable")
            cum = np.cumsum(energy[order])
            if cum[-1] <= 0.0:
                continue
            n = int(np.searchsorted(cum, (1.0 - frac) * cum[-1])) + 1
            keep[order[:n]] = True
        idx = np.flatnonzero(keep)
        idx = idx[np.argsort(-e[idx], kind="stable")][:limit]
        kx, ky = kx.ravel()[idx].copy(), ky.ravel()[idx].copy()
        # the grid's first node (x[0], y[0]) is the transform's origin
        shift = np.exp(-1j * (kx * self.x[0] + ky * self.y[0]))
        return (kx, ky, np.broadcast_to(self._omega, w.shape).ravel()[idx].copy(),
                self._a.ravel()[idx] * shift, self._b.ravel()[idx] * shift, w.ravel()[idx])

    def elevation(self, t: float = 0.0) -> NDArray[np.float64]:
        """z(x, y, t) [m], shape (ny, nx)."""
        plus, minus = self._travelling(t)
        return self._irfft_scratch(plus + minus)

    def fields(self, t: float = 0.0, slopes: bool = True) -> SurfaceFields:
        """Elevation, slopes and surface velocity at time t [s].

        The five derived fields go through one batched inverse FFT in the type of
        ``precision`` (module docstring); every array returned is float64. The spectra
        in between are written into scratch arrays kept between calls
        (:func:`_scratch`: no fresh pages to fault in at every time), with the same
        operations, hence the same numbers, as fresh arrays, and the transforms work in
        them (:meth:`_irfft_scratch`). ``slopes=False`` leaves the
        slopes out (None; three transforms instead of five): :meth:`slopes` gives the
        same arrays later.
        """
        jkx, jky, jw, ux, uy = self._derivatives
        c = jkx.dtype
        with _scratch(self._a.shape, c) as w:
            return self._fields(t, w, slopes)

    def slopes(self, t: float = 0.0) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The slopes (dz/dx, dz/dy) [-] of :meth:`fields` at time ``t`` [s], the same
        bytes, by two transforms."""
        jkx, jky, jw, ux, uy = self._derivatives
        with _scratch(self._a.shape, jkx.dtype) as w:
            plus, minus = self._travelling_into(t, w)
            z_c = self._spectrum_z(plus, minus, w)
            spectra = w["spectra"][:2]
            np.multiply(jkx, z_c, out=spectra[0])  # dz/dx
            np.multiply(jky, z_c, out=spectra[1])  # dz/dy
            derived = self._irfft_scratch(spectra)
        return derived[0].astype(np.float64), derived[1].astype(np.float64)

    def band_velocity(self, t: float, k_min: float) -> NDArray[np.float64]:
        """The surface velocity (u, v, w) of :meth:`fields` at ``t`` [s] of the waves
        ``|K| >= k_min`` [rad/m] alone [m/s], shape (ny, nx, 3): its spectra
        (:meth:`_velocity_spectra`, the same factors) with the waves ``|K| < k_min``
        zeroed, in one batched inverse transform (:meth:`_irfft_scratch`), in the type
        of ``precision``. ``k_min = 0`` gives :meth:`fields`' velocity, bit for bit."""
        jkx = self._derivatives[0]
        with _scratch(self._a.shape, jkx.dtype) as w:
            plus, minus = self._travelling_into(t, w)
            z_c = self._spectrum_z(plus, minus, w)
            spectra = self._velocity_spectra(plus, minus, z_c, w)
            # the band |K| < k_min: rows |K_y| < k_min, columns K_x < k_min (corners)
            rows = np.flatnonzero(np.abs(self._ky[:, 0]) < k_min)
            cols = int(np.count_nonzero(self._kx[0] < k_min))
            if rows.size and cols:
                low = self._kx[:, :cols] ** 2 + self._ky[rows] ** 2 < k_min * k_min
                block = spectra[:, rows, :cols]
                np.copyto(block, 0.0, where=low)
                spectra[:, rows, :cols] = block
            derived = self._irfft_scratch(spectra)
        # (ny, nx, 3) with the components' planes apart, as the facets' means read them
        return np.moveaxis(derived.astype(np.float64, copy=False), 0, -1)

    def _travelling_into(self, t: float, w: dict):
        """The travelling waves of :meth:`_travelling` at ``t``, in the scratch arrays
        ``w`` where nothing keeps them."""
        if self.share_travelling or self._omega_current is not None:
            return self._travelling(t)
        # _travelling_at(t), in w: the same operations (eq 12', eq 15)
        phase = w["phase"]
        np.multiply(self._minus_j_omega(), t, out=phase)
        np.exp(phase, out=phase)
        plus = np.multiply(self._a, phase, out=w["plus"])
        # as written there: numpy may reuse the temporary conj(phase) with the factors
        # swapped, and the complex product rounds differently with their order
        minus = self._b * np.conj(phase)
        return plus, minus

    def _spectrum_z(self, plus, minus, w: dict):
        """z_hat = plus + minus in ``w["z_hat"]``, as the derived fields' type."""
        z_hat = np.add(plus, minus, out=w["z_hat"])
        c = self._derivatives[0].dtype
        if c == z_hat.dtype:
            return z_hat
        np.copyto(w["z_c"], z_hat, casting="same_kind")
        return w["z_c"]

    def _fields(self, t: float, w: dict, slopes: bool = True) -> SurfaceFields:
        """:meth:`fields` with the scratch arrays ``w`` (:func:`_scratch`)."""
        plus, minus = self._travelling_into(t, w)
        z_c = self._spectrum_z(plus, minus, w)
        jkx, jky = self._derivatives[:2]
        spectra = w["spectra"]
        if slopes:
            np.multiply(jkx, z_c, out=spectra[0])  # dz/dx
            np.multiply(jky, z_c, out=spectra[1])  # dz/dy
        self._velocity_spectra(plus, minus, z_c, w)
        derived = self._irfft_scratch(spectra if slopes else spectra[2:])
        # last: the transform overwrites z_hat, which is z_c in double precision
        elevation = self._irfft_scratch(w["z_hat"])
        velocity = np.empty((*self.shape, 3))
        for i in range(3):
            velocity[..., i] = derived[i - 3]
        return SurfaceFields(
            t=float(t), elevation=elevation, velocity=velocity,
            slope_x=derived[0].astype(np.float64) if slopes else None,
            slope_y=derived[1].astype(np.float64) if slopes else None,
        )

    def _velocity_spectra(self, plus, minus, z_c, w: dict):
        """The spectra of the surface velocity (u, v, w) of the travelling waves ``plus``
        and ``minus`` (``z_c``: their sum, :meth:`_spectrum_z`), written into
        ``w["spectra"][2:]`` (:func:`_scratch`) and returned: the orbital velocity of
        linear waves (Lamb 1932, art. 228-229: ``u = (K / K) omega coth(K d)`` times the
        wave along +K minus the one along -K, ``w = -j omega`` times it), on a current
        the Eulerian rates at the nodes (eq C1). ``w["phase"]`` is overwritten."""
        jkx, jky, jw, ux, uy = self._derivatives
        c = jkx.dtype
        diff = np.subtract(plus, minus, out=w["phase"])  # wave along +K minus along -K
        if c != diff.dtype:
            diff = w["diff"]
            np.copyto(diff, w["phase"], casting="same_kind")
        spectra = w["spectra"]
        np.multiply(ux, diff, out=spectra[2])  # u
        np.multiply(uy, diff, out=spectra[3])  # v
        np.multiply(jw, diff, out=spectra[4])  # w = dz/dt
        if self._omega_current is not None:  # Eulerian rates: minus U . grad (eq C1)
            k_u = (-1j * (self._kx * self.current[0] + self._ky * self.current[1])).astype(c)
            with np.errstate(divide="ignore", invalid="ignore"):
                gain = np.where(self._omega > 0, 1j / self._omega, 0.0).astype(c)
            z_u = k_u * z_c
            spectra[2] += ux * gain * z_u  # u: D = j (K_x/K) coth z, D-rate - U . grad D
            spectra[3] += uy * gain * z_u
            spectra[4] += z_u  # dz/dt at the node: w - U . grad z
        return spectra[2:]


__all__ = ["PRECISIONS", "SeaSurface", "SurfaceFields", "cell_averaged_spectrum",
           "grid_coordinates"]
