"""Physical-optics kernels of the shooting-and-bouncing-rays (SBR) method, per ray tube.

A ray tube carries a locally plane wave of direction ``d`` and complex field ``E`` (a
vector, for each transmitted polarisation). Where it hits a flat facet of unit normal
``n`` (turned towards the incoming wave, ``d . n < 0``), geometrical optics gives the
reflected wave and physical optics the equivalent currents on the tube's footprint; the
currents radiate towards the receiver. Symbols (code names in brackets):

===============================  ==========================================================
``d``, ``d_r``                    incident and reflected unit directions (eq O1)
``h_l = n x d / |n x d|``         TE (perpendicular) unit vector of the local plane of
                                  incidence, ``v_i = h_l x d``, ``v_r = h_l x d_r`` (eq F1
                                  with the facet normal)
``R_h``, ``R_v``                  Fresnel coefficients of the facet's material (or the PEC
                                  limit -1, +1) in those bases
``E``, ``E_r``                    incident and reflected field at the footprint (eq O2)
``J``, ``M``                      PO electric and magnetic surface currents (eq O3)
``s``                             unit direction from the footprint to the observer
``V = eta J_perp - s x M``        radiated vector (eq O4)
``a``, ``b``                      edge vectors of the footprint (a parallelogram) (eq O5)
``F``                             ray-tube shape function (eq O6)
===============================  ==========================================================

.. math::
    \\hat d_r = \\hat d - 2(\\hat d\\cdot\\hat n)\\hat n \\qquad \\text{(O1)}

    \\mathbf E_r = R_h (\\mathbf E\\cdot\\hat h_l)\\,\\hat h_l
                 + R_v (\\mathbf E\\cdot\\hat v_i)\\,\\hat v_r \\qquad \\text{(O2)}

    \\eta\\mathbf J = \\hat n\\times(\\hat d\\times\\mathbf E + \\hat d_r\\times\\mathbf E_r),
    \\qquad \\mathbf M = (\\mathbf E + \\mathbf E_r)\\times\\hat n \\qquad \\text{(O3)}

with ``eta H = d x E`` for each plane wave: the currents of the total (incident plus
reflected) field on the facet, ``J = n x H``, ``M = -n x E`` (Balanis 2012, sec. 7.8); a
perfect conductor gives ``M = 0``, ``J = 2 n x H_i``. Their far field in direction ``s``
at distance ``R`` from the footprint's centre ``p`` (Balanis 2012, eqs 6-122; time
convention exp(+j omega t)) is

.. math::
    \\mathbf E_s = \\frac{-jk\\,e^{-jkR}}{4\\pi R}\\,\\mathbf V \\int_{A}
        e^{jk(\\hat s - \\hat d)\\cdot(\\mathbf r' - \\mathbf p)}\\,dS', \\qquad
    \\mathbf V = \\eta(\\mathbf J - (\\mathbf J\\cdot\\hat s)\\hat s) - \\hat s\\times\\mathbf M
    \\qquad \\text{(O4)}

The footprint of a tube whose cross-section (normal to ``d``) has edge vectors
``a_perp``, ``b_perp`` is the parallelogram of edges projected along ``d`` on the facet

.. math::
    \\mathbf a = \\mathbf a_\\perp - \\hat d\\,\\frac{\\mathbf a_\\perp\\cdot\\hat n}
    {\\hat d\\cdot\\hat n} \\quad (\\text{same for } \\mathbf b), \\qquad
    A = |\\mathbf a\\times\\mathbf b| \\qquad \\text{(O5)}

and the integral of the linear phase over it is the ray-tube shape function (Ling, Chou
and Lee 1989, sec. III; Bhalla and Ling 1995, eq 6)

.. math::
    \\int_A e^{j\\mathbf w\\cdot(\\mathbf r' - \\mathbf p)}dS' = A\\,
    \\mathrm{sinc}\\frac{\\mathbf w\\cdot\\mathbf a}{2}\\,
    \\mathrm{sinc}\\frac{\\mathbf w\\cdot\\mathbf b}{2}, \\qquad
    \\mathbf w = k(\\hat s - \\hat d),\\quad \\mathrm{sinc}\\,x = \\frac{\\sin x}{x}
    \\qquad \\text{(O6)}

exact for a parallelogram on a flat facet, so that tubes tiling a flat plate integrate its
PO current exactly whatever their size (only the plate's edges, where a tube is counted
whole or not at all, depend on the ray density).

Check (PEC plate of area A at normal incidence, monostatic): ``V = 2 E``, so
``|E_s| = k A / (2 pi R)`` and ``sigma = 4 pi A^2 / lambda^2`` (Knott et al. 1993, table
6.1).

References
----------
.. [1] Ling, H., Chou, R.-C. and Lee, S.-W. (1989). Shooting and bouncing rays:
   calculating the RCS of an arbitrarily shaped cavity. *IEEE Trans. Antennas Propag.*
   37(2), 194-205.
.. [2] Bhalla, R. and Ling, H. (1995). Image domain ray tube integration formula for the
   shooting and bouncing ray technique. *Radio Science* 30(5), 1435-1446.
.. [3] Balanis, C. A. (2012). *Advanced Engineering Electromagnetics*, 2nd ed., Wiley,
   secs. 6.7-6.8 (far fields of electric and magnetic currents) and 7.8 (physical
   optics).
.. [4] Knott, E. F., Shaeffer, J. F. and Tuley, M. T. (1993). *Radar Cross Section*, 2nd
   ed., Artech House, ch. 5 (physical optics) and table 6.1.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..geometry.frames import polarisation_basis

__all__ = [
    "local_basis",
    "po_components",
    "po_vector",
    "reflect",
    "shape_function",
    "tube_footprint",
]


def _dot(a: NDArray, b: NDArray) -> NDArray:
    """Dot product over the last axis (real or complex, no conjugation)."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _cross(a: NDArray, b: NDArray) -> NDArray:
    """Cross product over the last axis, broadcasting (faster than np.cross here)."""
    out = np.empty(np.broadcast_shapes(a.shape, b.shape), dtype=np.result_type(a, b))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


def _cross_rows(a: NDArray, b: NDArray) -> NDArray:
    """Cross product of vectors given as rows x, y, z (a (3, N) array or three rows)."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot_rows(a: NDArray, b: NDArray) -> NDArray:
    """Dot product of vectors given as rows x, y, z (the order of :func:`_dot`)."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def reflect(d: NDArray, n: NDArray, e: NDArray, r_h: NDArray, r_v: NDArray
            ) -> tuple[NDArray, NDArray]:
    """Reflected direction and field of ray tubes on flat facets, eqs O1-O2.

    Parameters
    ----------
    d : (N, 3) array
        Unit incident directions [-].
    n : (N, 3) array
        Unit facet normals turned towards the incoming wave (``d . n < 0``) [-].
    e : (N, P, 3) complex array
        Incident field vectors at the footprint, one per transmitted polarisation P.
    r_h, r_v : (N,) complex arrays
        Fresnel coefficients of the facet for the TE (h) and TM (v) components [-]
        (:func:`seaecho.scattering.fresnel.fresnel_coefficients`; -1, +1 for a perfect
        conductor).

    Returns
    -------
    d_r : (N, 3) array
        Reflected unit directions [-].
    e_r : (N, P, 3) complex array
        Reflected field vectors (same units as ``e``).
    """
    cos_i = -_dot(d, n)
    d_r = d + 2.0 * cos_i[:, None] * n  # Eq O1
    # Local TE basis: h_l = n x d / |n x d| with the FSA limit at normal incidence (eq F1)
    h_l, v_i = polarisation_basis(d, n)
    v_r = _cross(h_l, d_r)
    # Eq O2: Fresnel on the TE and TM components
    e_h = _dot(e, h_l[:, None, :])
    e_v = _dot(e, v_i[:, None, :])
    e_r = ((r_h[:, None] * e_h)[..., None] * h_l[:, None, :]
           + (r_v[:, None] * e_v)[..., None] * v_r[:, None, :])
    return d_r, e_r


def po_vector(d: NDArray, d_r: NDArray, n: NDArray, e: NDArray, e_r: NDArray,
              s: NDArray) -> NDArray:
    """Radiated vector ``V`` of the PO currents of the total field, eqs O3-O4.

    Parameters
    ----------
    d, d_r : (N, 3) arrays
        Unit incident and reflected directions [-].
    n : (N, 3) array
        Unit facet normals towards the incoming wave [-].
    e, e_r : (N, P, 3) complex arrays
        Incident and reflected fields at the footprint (eq O2).
    s : (N, 3) array
        Unit directions from the footprint to the observer [-].

    Returns
    -------
    (N, P, 3) complex array
        ``V``, transverse to ``s``: the far field is ``-jk e^{-jkR} / (4 pi R) V`` times
        the footprint integral (eq O4); same units as ``e``.
    """
    nb = n[:, None, :]
    sb = s[:, None, :]
    # Eq O3: eta J = n x (d x E + d_r x E_r), M = (E + E_r) x n
    eta_j = _cross(nb, _cross(d[:, None, :], e) + _cross(d_r[:, None, :], e_r))
    m = _cross(e + e_r, nb)
    # Eq O4: V = eta J_perp - s x M
    return eta_j - _dot(eta_j, sb)[..., None] * sb - _cross(sb, m)


def local_basis(d: NDArray, n: NDArray) -> tuple[NDArray, NDArray]:
    """TE and TM unit vectors ``h_l = n x d / |n x d|``, ``v_i = h_l x d`` (eq F1 with the
    facet normal; at normal incidence the limit of
    :func:`seaecho.geometry.frames.polarisation_basis`)."""
    h = _cross(n, d)
    norm = np.sqrt(_dot(h, h))
    bad = norm < 1e-9
    if np.any(bad):
        h[bad] = polarisation_basis(d[bad], n[bad])[0]
        norm[bad] = 1.0
    h /= norm[:, None]
    return h, _cross(h, d)


def po_components(alpha: NDArray, beta: NDArray, r_h: NDArray, r_v: NDArray,
                  n: NDArray, h_l: NDArray, v_i: NDArray, v_r: NDArray,
                  h_s: NDArray, v_s: NDArray) -> tuple[NDArray, NDArray]:
    """Components of ``V`` (eq O4) on the receive basis, from the TE/TM amplitudes.

    With ``E = alpha h_l + beta v_i`` (so ``E_r = R_h alpha h_l + R_v beta v_r``), the
    identities ``d x h_l = -v_i``, ``d x v_i = h_l`` (and the same for ``d_r``, ``v_r``)
    turn eq O3 into

    .. math::
        \\eta\\mathbf J = \\beta(1 + R_v)\\,\\hat n\\times\\hat h_l
            - \\alpha(\\hat n\\times\\hat v_i + R_h\\,\\hat n\\times\\hat v_r), \\quad
        \\mathbf M = -\\alpha(1 + R_h)\\,\\hat n\\times\\hat h_l
            - \\beta(\\hat n\\times\\hat v_i + R_v\\,\\hat n\\times\\hat v_r)

    and, with ``h_s x s = v_s`` and ``v_s x s = -h_s`` (FSA basis of ``s``), eq O4 into
    ``h_s . V = h_s . eta J - v_s . M``, ``v_s . V = v_s . eta J + h_s . M``: real dot
    products and complex scalars only (the same numbers as :func:`po_vector`).

    Parameters
    ----------
    alpha, beta : (N, P) complex arrays
        Incident TE and TM amplitudes for each transmitted polarisation.
    r_h, r_v : (N,) complex arrays
        Fresnel coefficients of the facet [-].
    n, h_l, v_i, v_r : (N, 3) arrays
        Facet normal (towards the incoming wave) and the local bases [-].
    h_s, v_s : (N, 3) arrays
        Receive basis (FSA of the direction to the observer) [-].

    Returns
    -------
    v_h, v_v : (N, P) complex arrays
        ``h_s . V`` and ``v_s . V``.
    """
    # the vectors as rows x, y, z (contiguous: the same operations as on (N, 3) rows,
    # to the bit, faster)
    n, h_l, v_i, v_r, h_s, v_s = (np.ascontiguousarray(np.asarray(x).T)
                                  for x in (n, h_l, v_i, v_r, h_s, v_s))
    a1, b1, c1 = _cross_rows(n, h_l), _cross_rows(n, v_i), _cross_rows(n, v_r)
    out = []
    for e1, e2 in ((h_s, v_s), (v_s, h_s)):
        # projections on e1 of eta J and on e2 of M
        e1a, e1b, e1c = (_dot_rows(e1, x)[:, None] for x in (a1, b1, c1))
        e2a, e2b, e2c = (_dot_rows(e2, x)[:, None] for x in (a1, b1, c1))
        rh, rv = r_h[:, None], r_v[:, None]
        j = beta * ((1.0 + rv) * e1a) - alpha * (e1b + rh * e1c)
        m = -alpha * ((1.0 + rh) * e2a) - beta * (e2b + rv * e2c)
        out.append((j, m))
    (jh, mv), (jv, mh) = out
    return jh - mv, jv + mh


def tube_footprint(a_perp: NDArray, b_perp: NDArray, d: NDArray, n: NDArray
                   ) -> tuple[NDArray, NDArray, NDArray]:
    """Edges and area of a ray tube's footprint on a flat facet, eq O5.

    Parameters
    ----------
    a_perp, b_perp : (N, 3) arrays
        Edge vectors of the tube's cross-section normal to ``d`` at the facet [m].
    d : (N, 3) array
        Unit ray directions [-].
    n : (N, 3) array
        Unit facet normals (either side) [-].

    Returns
    -------
    a, b : (N, 3) arrays
        Footprint edges in the facet's plane [m].
    area : (N,) array
        Footprint area ``|a x b|`` [m^2].
    """
    dn = _dot(d, n)
    a = a_perp - d * (_dot(a_perp, n) / dn)[:, None]
    b = b_perp - d * (_dot(b_perp, n) / dn)[:, None]
    c = _cross(a, b)
    return a, b, np.sqrt(_dot(c, c))


def shape_function(w: NDArray, a: NDArray, b: NDArray) -> NDArray:
    """Ray-tube shape function ``sinc(w.a / 2) sinc(w.b / 2)``, eq O6.

    Parameters
    ----------
    w : (N, 3) array
        Phase gradient ``k (s - d)`` [rad/m].
    a, b : (N, 3) arrays
        Footprint edges [m].

    Returns
    -------
    (N,) array
        [-]; 1 where the phase is stationary over the footprint.
    """
    # numpy's sinc is sin(pi x) / (pi x)
    return np.sinc(_dot(w, a) / (2.0 * np.pi)) * np.sinc(_dot(w, b) / (2.0 * np.pi))
