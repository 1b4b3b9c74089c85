"""Antennas: gain patterns, polarisation ports and pointing, evaluated in the world frame.

Antenna frame (as Sionna RT's): x along the boresight, y along the aperture's width
(horizontal, to the left looking out), z along its height (up). A direction d in the
world frame has antenna coordinates d_a = A^T d, where the columns of A are the antenna
axes in the world (:func:`antenna_axes`).

Patterns (power gain G, normalised so that the directivity integrates to 4 pi):

- ``rectangular``: uniformly illuminated aperture of width a and height b (the paper's
  section V), Huygens-source obliquity factor,

  .. math::

      F(\\hat d) = \\frac{1 + \\cos\\theta}{2}\\,
          \\mathrm{sinc}\\!\\left(\\frac{a\\,u}{\\lambda}\\right)
          \\mathrm{sinc}\\!\\left(\\frac{b\\,v}{\\lambda}\\right),\\quad
      G = \\frac{4\\pi\\,|F|^2}{\\oint |F|^2\\, d\\Omega}                           (A1)

  with u = d_a . y, v = d_a . z, cos(theta) = d_a . x and sinc(x) = sin(pi x)/(pi x);
  the peak tends to 4 pi a b / lambda^2 for a, b >> lambda (Balanis 2016, eq 12-38).
  A tapered width (cosine, eq A5, or Taylor, eq A4: :func:`line_pattern`) replaces the
  width's sinc: marine fan beams have -25 to -30 dB azimuth sidelobes.
- ``isotropic`` (G = 1), and Sionna RT's built-ins by name: ``dipole``
  (G = 1.5 sin^2 theta, Balanis eq 4-26a), ``hw_dipole``
  (G = 1.643 cos^2(pi/2 cos theta)/sin^2 theta, Balanis eq 4-84), ``tr38901``
  (3GPP TR 38.901 Table 7.3-1), with theta from the antenna's z axis as in Sionna.

Polarisation ports. For a wave propagating along n (n = d from a transmitting antenna
towards the scatterer, n = -d arriving at a receiving one) the antenna's own basis is

.. math::

    \\hat h_a = \\frac{\\hat z_a \\times \\hat n}{|\\hat z_a \\times \\hat n|},\\quad
    \\hat v_a = \\hat h_a \\times \\hat n                                               (A2)

(the forward scattering alignment of docs/conventions.md with the platform's vertical
z_a, body z in the world, in place of the world z: on a level platform a port H excites
exactly the world basis h of eq F1 in every direction; roll and attitude errors mix the
ports). Port states: H = h_a, V = v_a, P = (v_a + h_a)/sqrt 2 (+45 deg),
M = (v_a - h_a)/sqrt 2 (-45 deg), R = (v_a - j h_a)/sqrt 2, L = (v_a + j h_a)/sqrt 2
(IEEE handedness for exp(+j omega t), (v, h, n) right-handed). A cross-polar isolation
X [dB] mixes in x = 10^(-X/20) of the other port: e_1' = (e_1 + x e_2)/sqrt(1 + x^2).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] C. A. Balanis, *Antenna Theory: Analysis and Design*, 4th ed., Wiley, 2016,
   sections 4.2, 4.6 and 12.5 (rectangular apertures), eq 12-38.
.. [2] 3GPP TR 38.901 v17.0.0, Table 7.3-1 (antenna element pattern).
.. [3] IEEE Std 145-2013, Definitions of Terms for Antennas (handedness of circular
   polarisation).
.. [4] T. T. Taylor, "Design of line-source antennas for narrow beamwidth and low side
   lobes", *IRE Trans. Antennas Propag.* 3(1), 16-28, 1955.
.. [5] M. I. Skolnik, *Introduction to Radar Systems*, 3rd ed., McGraw-Hill, 2001,
   section 9.4 and table 9.1 (tapered apertures).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary
from ..conventions import PORTS

_SQRT_HALF = np.sqrt(0.5)
_DEGENERATE = 1e-12


def _normalise(a: NDArray) -> NDArray:
    return a / np.linalg.norm(a, axis=-1, keepdims=True)


# --------------------------------------------------------------------------- patterns
def _local(d_local, xp):
    """(namespace, direction vector): numpy (..., 3) arrays become a numpy Vec3."""
    if xp is None:
        return NUMPY, Boundary(NUMPY).vec3(d_local)
    return xp, d_local


def _sinc(xp, t):
    """sin(pi t) / (pi t), 1 at 0 (numpy's ``sinc``)."""
    arg = np.pi * t
    small = xp.abs(arg) < 1e-8
    return xp.select(small, 1.0, xp.sin(arg) / xp.select(small, 1.0, arg))


#: Illuminations of an aperture along its width (:func:`line_pattern`).
ILLUMINATIONS = ("uniform", "cosine", "taylor")


def taylor_zeros(sidelobe_db: float, nbar: int) -> NDArray[np.float64]:
    """Pattern zeros u_n, n = 1 .. nbar - 1, of Taylor's line source, eq (A4) [-].

    A = arccosh(eta) / pi with eta = 10^(SLL / 20), sigma = nbar / sqrt(A^2 + (nbar - 1/2)^2),
    u_n = sigma sqrt(A^2 + (n - 1/2)^2) (Taylor 1955, eqs 19-21; Skolnik 2001, section
    9.4; Balanis 2016, section 7.6.3).

    Parameters
    ----------
    sidelobe_db : float
        Design peak sidelobe level below the peak, SLL > 0 [dB].
    nbar : int
        Number of nearly equal sidelobes next to the main lobe [-], >= 1.
    """
    if not sidelobe_db > 0 or int(nbar) < 1:
        raise ValueError(f"sidelobe_db = {sidelobe_db}, nbar = {nbar}: need SLL > 0 dB "
                         "and nbar >= 1")
    a = np.arccosh(10.0 ** (sidelobe_db / 20.0)) / np.pi
    n = np.arange(1, int(nbar))
    sigma = nbar / np.sqrt(a * a + (nbar - 0.5) ** 2)
    return sigma * np.sqrt(a * a + (n - 0.5) ** 2)


def line_pattern(t, illumination: str = "uniform", sidelobe_db: float = 30.0,
                 nbar: int = 4, *, xp=NUMPY):
    """Far-field amplitude of a line source of length L at t = L u / lambda, 1 at t = 0.

    - ``uniform``: sinc(t) = sin(pi t) / (pi t) (Balanis 2016, section 12.5);
    - ``cosine``: illumination cos(pi x / L), |x| <= L/2:

      .. math:: F(t) = \\frac{\\cos\\pi t}{1 - 4 t^2}                                  (A5)

      first sidelobe -23.0 dB, half-power width 1.19 lambda / L, aperture efficiency
      8 / pi^2 = 0.81 (Skolnik 2001, table 9.1; Balanis 2016, table 12.2);
    - ``taylor``: Taylor's n-bar line source,

      .. math:: F(t) = \\mathrm{sinc}(t)\\prod_{n=1}^{\\bar n - 1}
                \\frac{1 - t^2 / u_n^2}{1 - t^2 / n^2}                                 (A4)

      with the zeros u_n of :func:`taylor_zeros`: the first nbar - 1 sidelobes near the
      design level, the farther ones decaying as sinc's (Taylor 1955, eq 19; Skolnik
      2001, section 9.4). The removable 0/0 at t = n is its limit (-1)^(n+1)/2 times the
      other factors.

    Parameters
    ----------
    t : array (namespace ``xp``)
        L u / lambda [-] (u the direction cosine along the line).
    illumination : {'uniform', 'cosine', 'taylor'}
    sidelobe_db, nbar : float, int
        Taylor design peak sidelobe level [dB] and nbar [-] (``taylor`` only).
    xp : array namespace (:mod:`seaecho.backend`), numpy by default.

    References
    ----------
    Taylor, T. T. (1955). Design of line-source antennas for narrow beamwidth and low
    side lobes. *IRE Trans. Antennas Propag.* 3(1), 16-28; Skolnik (2001) section 9.4;
    Balanis (2016) sections 7.6.3 and 12.5.
    """
    if illumination == "uniform":
        return _sinc(xp, t)
    if illumination == "cosine":
        d = 1.0 - 4.0 * t * t
        near = xp.abs(d) < 1e-9
        # Eq (A5); pi / 4 at t = +-1/2
        return xp.select(near, 0.25 * np.pi, xp.cos(np.pi * t) / xp.select(near, 1.0, d))
    if illumination == "taylor":
        zeros = taylor_zeros(sidelobe_db, nbar)
        f = _sinc(xp, t)
        a = xp.abs(t)
        nears = [xp.abs(a - n) < 1e-6 for n in range(1, int(nbar))]
        for n, near in enumerate(nears, start=1):  # the 0/0 limit at t = n
            f = xp.select(near, 0.5 * (-1.0) ** (n + 1), f)
        for n, (near, u_n) in enumerate(zip(nears, zeros, strict=True), start=1):
            # Eq (A4): the sinc's zero at n moved to u_n
            f = f * (1.0 - t * t / (u_n * u_n)) / xp.select(near, 1.0, 1.0 - t * t / n ** 2)
        return f
    raise ValueError(f"illumination = {illumination!r}: unknown; allowed: "
                     f"{', '.join(ILLUMINATIONS)}")


def aperture_field(d_local: ArrayLike, width: float, height: float, wavelength: float, *,
                   xp=None, illumination: str = "uniform", sidelobe_db: float = 30.0,
                   nbar: int = 4) -> NDArray[np.float64]:
    """Un-normalised far-field amplitude F of a rectangular aperture, eq (A1).

    Uniform along its height; along its width uniform (eq A1) or tapered (``illumination``,
    ``sidelobe_db``, ``nbar`` of :func:`line_pattern`): the width's sinc of eq (A1)
    becomes the line pattern of that illumination (separable aperture, Balanis 2016,
    section 12.5).

    Parameters
    ----------
    d_local : array_like (..., 3)
        Unit directions in the antenna frame (x boresight, y width, z height) [-].
    width, height : float
        Aperture width a and height b [m].
    wavelength : float
        Wavelength lambda [m].

    Returns
    -------
    ndarray (...)
        F [-], 1 at boresight.

    References
    ----------
    Balanis (2016), section 12.5: the uniform aperture's sinc pattern; the Huygens
    obliquity (1 + cos theta)/2 of section 12.2.

    ``xp``: array namespace of ``d_local`` (a vector of :mod:`seaecho.backend`), numpy
    (..., 3) arrays by default; the radar kernel calls this same formula on Dr.Jit arrays.
    """
    xp, d = _local(d_local, xp)
    # Eq (A1): line patterns in the two direction cosines, Huygens obliquity factor
    return (0.5 * (1.0 + d.x)
            * line_pattern(width * d.y / wavelength, illumination, sidelobe_db, nbar, xp=xp)
            * _sinc(xp, height * d.z / wavelength))


def aperture_quadrature(width: float, height: float, wavelength: float) -> tuple[int, int]:
    """Nodes ``(n_u, n_phi)`` of :func:`aperture_radiated_power`'s quadrature of eq A3:
    the band of each integrand plus the margin ``4 z^(1/3) + 32`` (its docstring).
    (``seaecho.checks.resources`` sizes the normalisation's time from them.)

    Parameters
    ----------
    width, height, wavelength : float
        Aperture width, height and wavelength [m].
    """
    a, b = sorted((width / wavelength, height / wavelength), reverse=True)
    band_u, band_phi = 0.5 * np.pi * (a + b), np.pi * b
    n_u = int(np.ceil(band_u + 4.0 * np.cbrt(band_u))) + 32
    n_phi = int(np.ceil(band_phi + 4.0 * np.cbrt(band_phi))) + 32
    return n_u, n_phi


@lru_cache(maxsize=64)
def aperture_radiated_power(width: float, height: float, wavelength: float,
                            illumination: str = "uniform", sidelobe_db: float = 30.0,
                            nbar: int = 4) -> float:
    """Integral of |F|^2 over the sphere [sr] for eq (A1)'s normalisation.

    With the polar axis along the longer side of the aperture (say the width, direction
    cosine u, so that A = a / lambda >= B = b / lambda) and the azimuth phi about it,
    d Omega = du d phi and the other two direction cosines are r cos phi (boresight) and
    r sin phi (height), r = sqrt(1 - u^2). Pairing phi with pi - phi folds the obliquity
    factor of eq (A1), ((1 + r cos phi)^2 + (1 - r cos phi)^2) / 8 = (1 + r^2 cos^2 phi)/4:

    .. math::

        \\oint |F|^2 d\\Omega = 2 \\int_0^1 \\mathrm{sinc}^2(A u) \\int_0^{2\\pi}
            \\frac{1 + r^2 \\cos^2\\phi}{4}\\,
            \\mathrm{sinc}^2(B\\, r \\sin\\phi)\\, d\\phi\\, du          (A3)

    Both integrands are entire (sinc^2 is even, so the inner one depends on r^2 only):
    Gauss-Legendre in u (``scipy.special.roots_legendre``, symmetric Golub-Welsch, the
    positive half of a rule on [-1, 1]) and the trapezoid in phi (period pi) converge
    spectrally once the nodes exceed the band of the oscillations: pi (A + B) / 2 in u
    and pi B in phi, plus a margin of 4 z^(1/3) + 32 nodes (z the band: the transition
    region of the Bessel-like tails, beyond which they decay faster than exponentially).
    Relative error below 1e-12 for apertures up to 150 x 150 wavelengths (doubling the
    nodes changes the result by less than that; tests: the Huygens element's 4 pi / 3
    and the closed form of the line source).

    A tapered width (``illumination``, :func:`line_pattern`) replaces sinc(A u) or
    sinc(B r sin phi), whichever belongs to the width, by its line pattern: the
    Fourier transform of an illumination of the same extent, entire and of the same band,
    so the same nodes hold.

    Parameters
    ----------
    width, height, wavelength : float
        Aperture width, height and wavelength [m].
    illumination, sidelobe_db, nbar
        The width's illumination (:func:`line_pattern`).

    Returns
    -------
    float
        The integral of |F|^2 d Omega [sr]; the peak directivity is 4 pi / this value.

    References
    ----------
    Balanis (2016), section 12.5 (the aperture's pattern) and eq 2-16 (the directivity's
    normalisation); Golub, G. H. and Welsch, J. H. (1969), Calculation of Gauss
    quadrature rules, *Math. Comp.* 23, 221-230; Trefethen, L. N. and Weideman, J. A. C.
    (2014), The exponentially convergent trapezoidal rule, *SIAM Review* 56(3), 385-458.
    """
    from scipy.special import roots_legendre

    a, b = sorted((width / wavelength, height / wavelength), reverse=True)
    width_first = width >= height  # the width is the polar axis (direction cosine u)

    def taper(t):
        return line_pattern(t, illumination, sidelobe_db, nbar)

    f_a = taper if width_first else np.sinc
    f_b = np.sinc if width_first else taper
    n_u, n_phi = aperture_quadrature(width, height, wavelength)
    x, w = roots_legendre(2 * n_u)
    u, w = x[n_u:], w[n_u:]  # u > 0 (the integrand is even in u)
    phi = np.pi * (np.arange(n_phi) + 0.5) / n_phi  # period pi: both halves of 2 pi
    sin_phi, cos2_phi = np.sin(phi), np.cos(phi) ** 2
    inner = np.empty(n_u)
    rows = max(1, 2_000_000 // n_phi)
    for i in range(0, n_u, rows):  # chunks bound the memory of very large apertures
        r2 = (1.0 - u[i:i + rows] ** 2)[:, None]
        s = f_b(b * np.sqrt(r2) * sin_phi)  # numpy's sinc: sin(pi x) / (pi x)
        inner[i:i + rows] = np.sum(s * s * (1.0 + r2 * cos2_phi), axis=1)
    inner *= 0.5 * np.pi / n_phi  # the trapezoid over 2 pi, 1/4 of eq (A3) folded in
    return 2.0 * float(np.sum(w * f_a(a * u) ** 2 * inner))


def builtin_gain(name: str, d_local: ArrayLike, *, xp=None) -> NDArray[np.float64]:
    """Power gain of the isotropic and Sionna RT built-in patterns [-].

    Parameters
    ----------
    name : {'isotropic', 'dipole', 'hw_dipole', 'tr38901'}
    d_local : array_like (..., 3)
        Unit directions in the antenna frame [-]; theta from +z, phi from +x.

    References
    ----------
    Balanis (2016) eqs 4-26a (short dipole), 4-84 (half-wave dipole); 3GPP TR 38.901
    Table 7.3-1; the same formulas as ``sionna.rt.antenna_pattern``.

    ``xp``: array namespace of ``d_local`` (a vector of :mod:`seaecho.backend`), numpy
    (..., 3) arrays by default; the radar kernel calls this same formula on Dr.Jit arrays.
    """
    shape = np.shape(d_local)[:-1] if xp is None else None
    xp, d = _local(d_local, xp)
    cos_t = xp.clip(d.z, -1.0, 1.0)
    sin2_t = xp.maximum(1.0 - cos_t * cos_t, 0.0)
    if name == "isotropic":
        return np.ones(shape) if shape is not None else 1.0
    if name == "dipole":
        return 1.5 * sin2_t  # Balanis eq 4-26a, D = 1.5
    if name == "hw_dipole":
        small = sin2_t < 1e-10
        c = xp.cos(0.5 * np.pi * cos_t)
        g = 1.643 * c * c / xp.select(small, 1.0, sin2_t)  # Balanis eq 4-84
        return xp.select(small, 0.0, g)
    if name == "tr38901":
        theta = xp.acos(cos_t)
        phi = xp.atan2(d.y, d.x)
        t3 = np.deg2rad(65.0)
        # 3GPP TR 38.901 Table 7.3-1: vertical and horizontal cuts, 30 dB floor, 8 dBi
        u = (theta - 0.5 * np.pi) / t3
        a_v = -xp.minimum(12.0 * u * u, 30.0)
        a_h = -xp.minimum(12.0 * (phi / t3) * (phi / t3), 30.0)
        a_db = -xp.minimum(-(a_v + a_h), 30.0) + 8.0
        return xp.exp(a_db * (np.log(10.0) / 10.0))
    raise ValueError(f"pattern = {name!r}: unknown; allowed: isotropic, dipole, hw_dipole, "
                     f"tr38901, rectangular")


# --------------------------------------------------------------------------- pointing
def antenna_axes(boresight: ArrayLike, up: ArrayLike) -> NDArray[np.float64]:
    """Antenna axes in the world: columns (boresight x_a, width y_a, height z_a).

    y_a = up x b / |up x b| is horizontal with respect to ``up``; z_a = b x y_a. At a
    boresight along ``up`` the width axis falls back to the world y axis.

    Parameters
    ----------
    boresight : array_like (..., 3)
        Boresight direction (normalised here) [-].
    up : array_like (..., 3)
        The platform's up axis (body z in the world) [-].

    Returns
    -------
    ndarray (..., 3, 3)
        A with ``d_local = A^T d_world``.
    """
    b = _normalise(np.asarray(boresight, dtype=float))
    up = np.broadcast_to(np.asarray(up, dtype=float), b.shape)
    y = np.cross(up, b)
    norm = np.linalg.norm(y, axis=-1, keepdims=True)
    if np.any(norm < 1e-9):
        # Boresight along `up`: width axis = world y made orthogonal to b
        ey = np.broadcast_to([0.0, 1.0, 0.0], b.shape)
        alt = ey - b * np.sum(ey * b, axis=-1, keepdims=True)
        y = np.where(norm < 1e-9, alt, y)
    y = _normalise(y)
    z = np.cross(b, y)
    return np.stack([b, y, z], axis=-1)


# ------------------------------------------------------------------------ polarisation
def port_states(basis: str, h: NDArray, v: NDArray, cross_polar_isolation_db: float | None
                ) -> NDArray[np.complex128]:
    """The two port polarisation states of ``basis`` from the unit vectors h_a, v_a.

    Parameters
    ----------
    basis : {'hv', 'slant', 'circular'}
    h, v : ndarray (..., 3)
        Eq (A2) basis vectors (world or antenna frame) [-].
    cross_polar_isolation_db : float or None
        Isolation X [dB]; None for ideal ports.

    Returns
    -------
    ndarray (..., 2, 3) complex
        Port 1 and port 2 unit polarisation vectors, in the order of ``PORTS[basis]``:
        ``e_p = C[p, 0] h + C[p, 1] v`` with ``C`` of :func:`port_coefficients`.
    """
    c = port_coefficients(basis, cross_polar_isolation_db)
    h = np.asarray(h, dtype=float)[..., None, :]
    v = np.asarray(v, dtype=float)[..., None, :]
    return c[:, 0, None] * h + c[:, 1, None] * v


def port_coefficients(basis: str, cross_polar_isolation_db: float | None
                      ) -> NDArray[np.complex128]:
    """Port states as coefficients on (h_a, v_a): C[port, (h, v)], so e_p = C[p] . (h, v).

    H = h_a, V = v_a, P = (v_a + h_a)/sqrt 2, M = (v_a - h_a)/sqrt 2,
    R = (v_a - j h_a)/sqrt 2, L = (v_a + j h_a)/sqrt 2 (module docstring), then the
    cross-polar mixing. :func:`port_states` and the radar kernel
    (``seaecho.radar.kernels``) both build the states from these.
    """
    r = _SQRT_HALF
    table = {"hv": [[1.0, 0.0], [0.0, 1.0]],
             "slant": [[r, r], [-r, r]],
             "circular": [[-1j * r, r], [1j * r, r]]}
    if basis not in table:
        raise ValueError(f"basis = {basis!r}: unknown; allowed: {sorted(PORTS)}")
    c = np.array(table[basis], dtype=complex)
    if cross_polar_isolation_db is not None:
        x = 10.0 ** (-cross_polar_isolation_db / 20.0)
        c = np.stack([c[0] + x * c[1], c[1] + x * c[0]]) / np.sqrt(1 + x * x)
    return c


def wave_basis(n: NDArray, up: NDArray) -> tuple[NDArray, NDArray]:
    """Eq (A2): h = up x n / |up x n|, v = h x n, with a fallback at n parallel to up.

    Eqs F1-F2 with the antenna's reference axis as the normal
    (:func:`seaecho.geometry.frames.polarisation_basis`, the same formula as the world
    bases; at ``n`` along ``up``, the limit from the reference azimuth).

    Parameters
    ----------
    n : ndarray (..., 3)
        Unit propagation direction [-].
    up : ndarray (..., 3) or (3,)
        Reference (antenna height) axis [-].
    """
    from ..geometry.frames import polarisation_basis

    return polarisation_basis(n, up)


# ---------------------------------------------------------------------------- antenna
@dataclass(frozen=True)
class Antenna:
    """An antenna: pattern, polarisation ports (evaluation only; pointing is separate).

    Attributes
    ----------
    pattern : str
        'rectangular', 'isotropic', 'dipole', 'hw_dipole' or 'tr38901'.
    wavelength : float
        Carrier wavelength [m].
    width, height : float or None
        Aperture size [m] (rectangular).
    basis : str
        'hv', 'slant' or 'circular'.
    cross_polar_isolation_db : float or None
        Port isolation [dB].
    illumination : str
        Illumination along the width (rectangular): 'uniform', 'cosine' or 'taylor'
        (:func:`line_pattern`).
    taylor_sidelobe_db, taylor_nbar : float, int
        Taylor design sidelobe level [dB] and nbar [-].
    """

    pattern: str
    wavelength: float
    width: float | None = None
    height: float | None = None
    basis: str = "hv"
    cross_polar_isolation_db: float | None = None
    illumination: str = "uniform"
    taylor_sidelobe_db: float = 30.0
    taylor_nbar: int = 4

    @property
    def ports(self) -> tuple[str, str]:
        """Port letters, e.g. ('H', 'V')."""
        return PORTS[self.basis]

    @property
    def peak_gain(self) -> float:
        """Directivity at boresight [-] (1 for isotropic)."""
        return float(self.gain_local(np.array([1.0, 0.0, 0.0])))

    def gain_local(self, d_local: ArrayLike, *, xp=None) -> NDArray[np.float64]:
        """Power gain G [-] for unit directions in the antenna frame (..., 3), eq (A1).

        ``xp``: array namespace of ``d_local`` (:mod:`seaecho.backend`), numpy by default.
        """
        if self.pattern == "rectangular":
            taper = (self.illumination, self.taylor_sidelobe_db, self.taylor_nbar)
            f = aperture_field(d_local, self.width, self.height, self.wavelength, xp=xp,
                               illumination=taper[0], sidelobe_db=taper[1], nbar=taper[2])
            norm = 4.0 * np.pi / aperture_radiated_power(self.width, self.height,
                                                         self.wavelength, *taper)
            return norm * f * f
        return builtin_gain(self.pattern, d_local, xp=xp)

    def response(self, d_world: ArrayLike, axes: ArrayLike, receive: bool,
                 up: ArrayLike | None = None
                 ) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
        """Gain and port polarisation vectors towards world directions.

        Parameters
        ----------
        d_world : array_like (..., 3)
            Unit directions from the antenna towards the scatterers (world) [-].
        axes : array_like (3, 3) or (..., 3, 3)
            Antenna axes in the world (:func:`antenna_axes`).
        receive : bool
            False: states of the wave leaving along d (transmit). True: states of the
            wave arriving along -d, conjugated, so that the received voltage of port m is
            ``sum(out[..., m, :] * E)`` (projection on the port's polarisation state).
        up : array_like (3,) or None
            Polarisation reference axis of eq (A2): the platform's vertical (body z in
            the world), so that "H" means horizontal for a level platform whatever the
            antenna's tilt; default the antenna's height axis.

        Returns
        -------
        gain : ndarray (...)
            Power gain [-].
        ports : ndarray (..., 2, 3) complex
            Port vectors in the world frame [-].
        """
        d = np.asarray(d_world, dtype=float)
        a = np.asarray(axes, dtype=float)
        d_local = np.einsum("...ji,...j->...i", a, d)
        gain = self.gain_local(d_local)
        n = -d if receive else d
        ref = a[..., :, 2] if up is None else np.asarray(up, dtype=float)
        h, v = wave_basis(n, ref)
        ports = port_states(self.basis, h, v, self.cross_polar_isolation_db)
        return gain, (np.conj(ports) if receive else ports)


def project_ports(ports: NDArray[np.complex128], h: NDArray, v: NDArray
                  ) -> NDArray[np.complex128]:
    """Components of port vectors on a wave basis (h, v): shape (..., 2 ports, 2 (h, v)).

    Parameters
    ----------
    ports : ndarray (..., 2, 3) complex
        Port vectors in the world (from :meth:`Antenna.response`).
    h, v : ndarray (..., 3)
        World FSA basis of the wave (``seaecho.geometry.frames.polarisation_basis``).
    """
    return np.stack([np.einsum("...pi,...i->...p", ports, h),
                     np.einsum("...pi,...i->...p", ports, v)], axis=-1)


__all__ = [
    "ILLUMINATIONS",
    "Antenna",
    "antenna_axes",
    "aperture_field",
    "aperture_quadrature",
    "aperture_radiated_power",
    "builtin_gain",
    "line_pattern",
    "port_coefficients",
    "port_states",
    "project_ports",
    "taylor_zeros",
    "wave_basis",
]
