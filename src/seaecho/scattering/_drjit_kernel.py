"""Dr.Jit (LLVM) kernel of :func:`seaecho.scattering.facet.facet_terms`.

The same equations as the numpy path of ``facet.py`` (eqs F1-F4, R1-R2, S3-S7, K1-K4,
B1-B4, P1-P3), fused into one JIT-compiled kernel over facets, in float64. The Bragg
spectrum comes from a :class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable`
(bilinear in ``log K`` and azimuth). Only this module imports drjit; callers fall back to
numpy when it is unavailable. Tests check both paths agree.
"""

from __future__ import annotations

import math

import numpy as np

from .._llvm import configure_llvm
from ..drjit_buffers import aligned

configure_llvm()
import drjit as dr  # noqa: E402
from drjit.llvm import Float64 as F  # noqa: E402
from drjit.llvm import UInt32  # noqa: E402

_LN10 = math.log(10.0)


def _dot(a, b):
    return dr.fma(a[0], b[0], dr.fma(a[1], b[1], a[2] * b[2]))


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _norm(a):
    return dr.sqrt(_dot(a, a))


def _sel(c, a, b):
    return (dr.select(c, a[0], b[0]), dr.select(c, a[1], b[1]), dr.select(c, a[2], b[2]))


def _cmul(a, b):
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def _cdiv(a, b):
    den = dr.rcp(b[0] * b[0] + b[1] * b[1])
    return ((a[0] * b[0] + a[1] * b[1]) * den, (a[1] * b[0] - a[0] * b[1]) * den)


def _csqrt(a):
    # Principal branch, as numpy: Re >= 0, Im with the sign of Im(a).
    r = dr.sqrt(a[0] * a[0] + a[1] * a[1])
    re = dr.sqrt(dr.maximum((r + a[0]) * 0.5, 0.0))
    im = dr.sqrt(dr.maximum((r - a[0]) * 0.5, 0.0))
    return (re, dr.select(a[1] < 0.0, -im, im))


def _cadd(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _creal(a, s):
    return (a[0] * s, a[1] * s)


def _reference(nn):
    # frames.reference_direction: x projected on the plane, or y when x is along N.
    rx = (1.0 - nn[0] * nn[0], -nn[0] * nn[1], -nn[0] * nn[2])
    ry = (-nn[1] * nn[0], 1.0 - nn[1] * nn[1], -nn[1] * nn[2])
    r = _sel(_norm(rx) < 0.5, ry, rx)
    return _scale(r, dr.rcp(_norm(r)))


def _global_basis(n):
    # Eqs F1-F2 with N = z: h = z x t / |t|, t = (n_x, n_y, 0); reference y at nadir.
    t = dr.sqrt(n[0] * n[0] + n[1] * n[1])
    deg = t < 1e-9
    inv = dr.rcp(dr.select(deg, 1.0, t))
    h = (dr.select(deg, 0.0, -n[1] * inv), dr.select(deg, 1.0, n[0] * inv), F(0.0) * n[0])
    return h, _cross(h, n)


def facet_kernel(n_i, n_s, nn, damping, k, eps, mss_u, mss_c, wind, table, cox_munk, model,
                 speckle=None):
    """Evaluate eqs P1-P3 for all facets; returns numpy arrays (K (N,4), B (N,4), w (N,4)).

    Parameters mirror :func:`seaecho.scattering.facet.facet_terms`; ``n_i``, ``n_s``,
    ``nn`` are (N, 3) numpy arrays, ``damping`` (N,) or None, ``table`` a
    BraggSpectrumTable, ``cox_munk`` CoxMunkParameters or None.

    With ``speckle = (g_K, g_B, area)`` ((N,) complex draws of eq P4 and (N,) areas [m^2])
    the kernel goes on to eq P4 and returns only the speckled amplitudes a (N, 4) complex
    [m]: K, B and w never leave the kernel (fewer passes over memory than
    ``speckle_amplitudes`` on the returned terms; same values within rounding).
    """
    keep = []  # input buffers (64-byte aligned: one compiled kernel, seaecho.drjit_buffers)

    def col(a):
        a = aligned(a)
        keep.append(a)
        return F(a)

    ni = tuple(col(n_i[:, j]) for j in range(3))
    ns = tuple(col(n_s[:, j]) for j in range(3))
    nv = tuple(col(nn[:, j]) for j in range(3))
    kk = dr.opaque(F, float(k))
    er = dr.opaque(F, float(np.real(eps)))
    ei = dr.opaque(F, float(np.imag(eps)))
    epsc = (er, ei)
    mu = col(np.broadcast_to(mss_u, (n_i.shape[0],))) if np.ndim(
        mss_u) else dr.opaque(F, float(mss_u))
    mc = col(np.broadcast_to(mss_c, (n_i.shape[0],))) if np.ndim(
        mss_c) else dr.opaque(F, float(mss_c))
    mu = dr.maximum(mu, 1e-12)
    mc = dr.maximum(mc, 1e-12)
    cw = dr.opaque(F, math.cos(wind))
    sw = dr.opaque(F, math.sin(wind))

    # Scattering vector direction and beta (eqs B1-B4, beta in degrees).
    d = _sub(ns, ni)
    qn = _norm(d)
    qok = qn > 1e-12
    qs = dr.select(qok, qn, 1e-12)
    dn = _dot(d, nv)
    cosb = dr.select(qok, dn / qs, 0.0)
    beta = dr.acos(dr.clip(cosb, -1.0, 1.0)) * (180.0 / math.pi)
    if model == "blend":
        w1 = dr.exp(-_LN10 * dr.power(beta * (1.0 / (6.0 * math.pi)), 8.0))
        w2 = dr.exp(-_LN10 * dr.power(beta * (1.0 / (20.0 * math.pi)), 1.5))
    else:
        w1 = w2 = F(1.0 if model == "kirchhoff" else 0.0) + 0.0 * qn

    # Local angles (frames.local_angles) and bases.
    ci = -_dot(ni, nv)
    cs = _dot(ns, nv)
    lit = (ci > 1e-12) & (cs > 1e-12)
    ti = (ni[0] + ci * nv[0], ni[1] + ci * nv[1], ni[2] + ci * nv[2])
    ts = (ns[0] - cs * nv[0], ns[1] - cs * nv[1], ns[2] - cs * nv[2])
    nti = _norm(ti)
    nts = _norm(ts)
    ref = _reference(nv)
    ti = _sel(nti < 1e-9, ref, ti)
    ts = _sel(nts < 1e-9, ref, ts)
    e1 = _scale(ti, dr.rcp(_norm(ti)))
    es = _scale(ts, dr.rcp(_norm(ts)))
    e2 = _cross(nv, e1)
    cphi = _dot(es, e1)
    sphi = _dot(es, e2)
    ci_c = dr.clip(ci, 0.0, 1.0)
    cs_c = dr.clip(cs, 0.0, 1.0)
    si = dr.sqrt(dr.maximum(1.0 - dr.clip(ci, -1.0, 1.0) ** 2, 0.0))
    ss = dr.sqrt(dr.maximum(1.0 - dr.clip(cs, -1.0, 1.0) ** 2, 0.0))

    hig, vig = _global_basis(ni)
    hsg, vsg = _global_basis(ns)

    out = {}
    # Bragg part (eqs S3-S7, P2).
    if model != "kirchhoff":
        hil = e2
        vil = _cross(hil, ni)
        hsl = _cross(nv, es)
        vsl = _cross(hsl, ns)
        ai = (_dot(hil, hig), _dot(hil, vig), _dot(vil, hig), _dot(vil, vig))
        as_ = (_dot(hsl, hsg), _dot(hsl, vsg), _dot(vsl, hsg), _dot(vsl, vsg))
        ri = _csqrt((er - si * si, ei))
        rs = _csqrt((er - ss * ss, ei))
        em1 = (er - 1.0, ei)
        dhi = (ci_c + ri[0], ri[1])
        dhs = (cs_c + rs[0], rs[1])
        dvi = _cadd(_creal(epsc, ci_c), ri)
        dvs = _cadd(_creal(epsc, cs_c), rs)
        a00 = _creal(_cdiv(em1, _cmul(dhi, dhs)), cphi)
        a01 = _creal(_cdiv(_cmul(em1, ri), _cmul(dvi, dhs)), sphi)
        a10 = _creal(_cdiv(_cmul(em1, rs), _cmul(dhi, dvs)), sphi)
        num = _cmul(em1, _sub2(_creal(epsc, si * ss), _creal(_cmul(ri, rs), cphi)))
        a11 = _cdiv(num, _cmul(dvi, dvs))
        t00 = _cadd(_creal(a00, ai[0]), _creal(a01, ai[2]))
        t01 = _cadd(_creal(a00, ai[1]), _creal(a01, ai[3]))
        t10 = _cadd(_creal(a10, ai[0]), _creal(a11, ai[2]))
        t11 = _cadd(_creal(a10, ai[1]), _creal(a11, ai[3]))
        b = (_cadd(_creal(t00, as_[0]), _creal(t10, as_[2])),
             _cadd(_creal(t01, as_[0]), _creal(t11, as_[2])),
             _cadd(_creal(t00, as_[1]), _creal(t10, as_[3])),
             _cadd(_creal(t01, as_[1]), _creal(t11, as_[3])))
        # Bragg vector: tangential part of q, horizontal components (eq S7).
        qtx = kk * (d[0] - dn * nv[0])
        qty = kk * (d[1] - dn * nv[1])
        w_b = table.lookup_drjit(qtx, qty)
        amp = (4.0 * math.sqrt(math.pi)) * kk * kk * ci_c * cs_c * dr.sqrt(w_b)
        if damping is not None:
            amp = amp * dr.sqrt(dr.clip(1.0 - col(damping), 0.0, 1.0))
        amp = dr.select(lit, amp, 0.0)
        out["bragg"] = [_creal(c, amp) for c in b]

    # Specular part (eqs K1-K4, P1).
    if model != "spm":
        nsp = _sel(qok, _scale(d, dr.rcp(qs)), nv)
        c = dr.clip(-_dot(ni, nsp), 0.0, 1.0)
        root = _csqrt((er - (1.0 - c * c), ei))
        r_h = _cdiv((c - root[0], -root[1]), (c + root[0], root[1]))
        ec = _creal(epsc, c)
        r_v = _cdiv(_sub2(ec, root), _cadd(ec, root))
        hp = _cross(nsp, ni)
        nhp = _norm(hp)
        hp = _sel(nhp < 1e-9, _cross(nsp, _reference(nsp)), hp)
        hp = _scale(hp, dr.rcp(_norm(hp)))
        vpi = _cross(hp, ni)
        vps = _cross(hp, ns)
        hi_h, hi_v = _dot(hp, hig), _dot(hp, vig)
        vi_h, vi_v = _dot(vpi, hig), _dot(vpi, vig)
        hs_h, hs_v = _dot(hp, hsg), _dot(hp, vsg)
        vs_h, vs_v = _dot(vps, hsg), _dot(vps, vsg)
        f = (_cadd(_creal(r_h, hs_h * hi_h), _creal(r_v, vs_h * vi_h)),
             _cadd(_creal(r_h, hs_h * hi_v), _creal(r_v, vs_h * vi_v)),
             _cadd(_creal(r_h, hs_v * hi_h), _creal(r_v, vs_v * vi_h)),
             _cadd(_creal(r_h, hs_v * hi_v), _creal(r_v, vs_v * vi_v)))
        cos_n = _dot(nsp, nv)
        valid = cos_n > 1e-12
        cn = dr.select(valid, cos_n, 1e-12)
        u = (cw, sw, F(0.0) * cw)
        eu = _sub(u, _scale(nv, _dot(u, nv)))
        eu = _scale(eu, dr.rcp(_norm(eu)))
        ec_ = _cross(nv, eu)
        inv_cn = dr.rcp(cn)
        zu = -_dot(nsp, eu) * inv_cn
        zc = -_dot(nsp, ec_) * inv_cn
        if cox_munk is None:
            log_p = -0.5 * (zu * zu / mu + zc * zc / mc) - math.log(2.0 * math.pi) \
                - 0.5 * dr.log(mu * mc)
            gc = F(1.0) + 0.0 * zu
        else:
            p = cox_munk
            log_p = -0.5 * (zu * zu / p.mss_upwind + zc * zc / p.mss_crosswind) \
                - math.log(2.0 * math.pi) - 0.5 * math.log(p.mss_upwind * p.mss_crosswind)
            xi = zc * (1.0 / math.sqrt(p.mss_crosswind))
            eta = -zu * (1.0 / math.sqrt(p.mss_upwind))
            xi2 = xi * xi
            eta2 = eta * eta
            gc = (1.0 - 0.5 * p.c21 * (xi2 - 1.0) * eta - p.c03 / 6.0 * (eta2 * eta - 3.0 * eta)
                  + p.c40 / 24.0 * (xi2 * xi2 - 6.0 * xi2 + 3.0)
                  + 0.25 * p.c22 * (xi2 - 1.0) * (eta2 - 1.0)
                  + p.c04 / 24.0 * (eta2 * eta2 - 6.0 * eta2 + 3.0))
            gc = dr.maximum(gc, 0.0)
        log_w = dr.minimum(math.log(math.pi) - 4.0 * dr.log(cn) + log_p, 700.0)
        sk = dr.select(lit & valid, dr.sqrt(gc) * dr.exp(0.5 * log_w), 0.0)
        out["specular"] = [_creal(c_, sk) for c_ in f]

    if speckle is not None:
        # Eq P4: a = sqrt(A) (sqrt(w) K g_K + sqrt(1 - w) B g_B), per channel
        g_k, g_b, area = speckle
        gk = (col(np.real(g_k)), col(np.imag(g_k)))
        gb = (col(np.real(g_b)), col(np.imag(g_b)))
        sa = dr.sqrt(col(area))
        ws = (w1, w2, w2, w1)
        amps = []
        for j in range(4):
            acc = None
            for key, g, wj in (("specular", gk, ws[j]), ("bragg", gb, 1.0 - ws[j])):
                if key not in out:  # kirchhoff / spm: that mechanism's weight is 0
                    continue
                t = _creal(_cmul(out[key][j], g), dr.sqrt(wj) * sa)
                acc = t if acc is None else _cadd(acc, t)
            amps.append(acc)
        dr.eval(*[c_ for a in amps for c_ in a])
        res = np.empty((n_i.shape[0], 4), dtype=complex)
        for j, a in enumerate(amps):
            res[:, j].real = a[0].numpy()
            res[:, j].imag = a[1].numpy()
        return res

    flat = [w1, w2]
    for key in ("specular", "bragg"):
        if key in out:
            for c_ in out[key]:
                flat.extend(c_)
    dr.eval(*flat)
    n = n_i.shape[0]
    w1n, w2n = w1.numpy(), w2.numpy()
    weight = np.stack([w1n, w2n, w2n, w1n], axis=-1) if model == "blend" else np.full(
        (n, 4), 1.0 if model == "kirchhoff" else 0.0)
    res = {}
    for key in ("specular", "bragg"):
        if key in out:
            arr = np.empty((n, 4), dtype=complex)
            for j, c_ in enumerate(out[key]):
                arr[:, j].real = c_[0].numpy()
                arr[:, j].imag = c_[1].numpy()
            res[key] = arr
        else:
            res[key] = np.zeros((n, 4), dtype=complex)
    return res["specular"], res["bragg"], weight


def _sub2(a, b):
    return (a[0] - b[0], a[1] - b[1])


def table_lookup(values: F, log_k0: float, dlog_k: float, n_k: int, n_psi: int, kx, ky):
    """Bilinear lookup of log W in (log K, azimuth); 0 outside [k_min, k_max]."""
    kmag = dr.sqrt(kx * kx + ky * ky)
    u = (dr.log(dr.maximum(kmag, 1e-300)) - log_k0) * (1.0 / dlog_k)
    inside = (u >= 0.0) & (u <= n_k - 1)
    u = dr.clip(u, 0.0, n_k - 1.000001)
    i0 = dr.floor(u)
    fu = u - i0
    psi = dr.atan2(ky, kx)
    v = (psi + math.pi) * (n_psi / (2.0 * math.pi))
    j0 = dr.floor(v)
    fv = v - j0
    i0u = UInt32(i0)
    j0u = UInt32(dr.clip(j0, 0.0, n_psi - 1.0))
    j1u = dr.select(j0u + 1 >= n_psi, j0u + 1 - n_psi, j0u + 1)
    base0 = i0u * n_psi
    base1 = base0 + n_psi
    v00 = dr.gather(F, values, base0 + j0u)
    v01 = dr.gather(F, values, base0 + j1u)
    v10 = dr.gather(F, values, base1 + j0u)
    v11 = dr.gather(F, values, base1 + j1u)
    lw = (1.0 - fu) * ((1.0 - fv) * v00 + fv * v01) + fu * ((1.0 - fv) * v10 + fv * v11)
    return dr.select(inside, dr.exp(lw), 0.0)


__all__ = ["facet_kernel", "table_lookup"]
