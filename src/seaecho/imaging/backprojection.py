"""Time-domain backprojection of range-compressed pulses onto arbitrary pixels.

For a pixel at x (a point on the image surface, usually the mean sea level) and pulse p
emitted at t_p from the transmitter at t_p = tx(t_p) towards a receiver at r_p = rx(t_p)
moving at v_p, the echo of a static scatterer at x arrives after

.. math::

    \\tau_p(x) = \\frac{|x - t_p|}{c} + \\tau_r,\\qquad
    |r_p + v_p (\\tau_t + \\tau_r) - x| = c\\,\\tau_r                                  (B1)

(the time of flight of the echo model, ``docs/radar.md`` eq R3, with the receiver moving
during the flight; for a monostatic radar this is 2 R / c to within the 6 mm the
aircraft flies while the pulse travels). The backprojected image is

.. math::

    I(x) = \\sum_p w_p\\, y_p\\big(\\tau_p(x)\\big)\\, e^{+j 2\\pi f_c \\tau_p(x)}        (B2)

with y_p the range-compressed pulse p (sample m at delay t_0 + m / f_s, the dataset's
``fast_time``) and w_p(x) the azimuth weight of pulse p at pixel x, a window over the
processed Doppler band:

.. math::

    w_p(x) = W\\left(\\frac{f_p(x) - f_{c,p}}{B_a}\\right),\\quad
    f_p(x) = \\frac{\\mathbf v_{t,p}\\cdot\\hat{\\mathbf u}_{t,p}(x)
                   + \\mathbf v_{r,p}\\cdot\\hat{\\mathbf u}_{r,p}(x)}{\\lambda},\\quad
    f_{c,p} = \\frac{\\mathbf v_{t,p}\\cdot\\hat{\\mathbf b}_{t,p}
                   + \\mathbf v_{r,p}\\cdot\\hat{\\mathbf b}_{r,p}}{\\lambda}          (B4)

f_p(x) is the bistatic Doppler frequency of a static scatterer at x,
-(1/lambda) d(r_t + r_r)/dt (Willis 2005, eq 3.23; u the unit vectors from the platforms
to x), f_c,p the Doppler centroid of pulse p (that of the point on both boresights b),
B_a the processed Doppler bandwidth (default the PRF, the widest band without azimuth
ambiguities) and W a window on [-1/2, 1/2], zero outside (rectangular, Hamming or
Taylor: ``imaging.windows``). The band plays the part of the azimuth processing bandwidth
of a frequency-domain stripmap processor (Cumming & Wong 2005, section 4.5 and eq 4.37):
without it, backprojection adds every pulse at every pixel and a scatterer reappears at
its azimuth ambiguities (PRF lambda R / (2 v) away, 64 m in the paper's SAR scenes) with
its full strength, whereas with it those are left with the antenna's sidelobes.

The echo model carries exp(-j 2 pi f_c tau) (time convention exp(+j omega t)), so eq (B2)
brings every pulse of a static scatterer at x back in phase: its image peak is real and
positive times the scatterer's S_mn (times the antenna and range factors that
``imaging.calibration`` divides out). y_p(tau) between samples is the band-limited
interpolation of the samples (the compressed pulse is band-limited to |f| <= B/2 <=
f_s/2), approximated by FFT upsampling by a factor U followed by linear interpolation:

.. math::

    y_p(\\tau) \\approx (1 - \\varepsilon)\\, \\tilde y_p[i] + \\varepsilon\\,
    \\tilde y_p[i + 1],\\quad i + \\varepsilon = (\\tau - t_0)\\, U f_s                (B3)

whose amplitude error at baseband frequency f is at most 1 - cos(pi f / (U f_s)) (at
the mid-point between two upsampled samples): 0.3 % (0.03 dB) at the band edge for
B = 0.83 f_s and U = 16. Samples outside the window contribute nothing.

This is the standard time-domain (global) backprojection of Soumekh (1999, ch. 4 and
section 5.8 for the bistatic case) and Ulander, Hellsten & Stenstrom (2003, eq 4); it
makes no assumption on the track (straight, waypoints, perturbed), the look direction or
the bistatic geometry.

Two implementations give the same numbers (tests): :func:`backproject_numpy`, the
reference, vectorised over blocks of (pixels x pulses); and :func:`backproject_drjit`, one
Dr.Jit LLVM kernel over pixels with a symbolic loop over the pulses of a block (float64
delays, the carrier phase reduced modulo one cycle before a float32 sine and cosine,
float32 samples, accumulation in float32 per block then float64 across blocks).

References
----------
.. [1] M. Soumekh, *Synthetic Aperture Radar Signal Processing with MATLAB Algorithms*,
   Wiley, 1999, ch. 4 (backprojection) and section 5.8.
.. [2] L. M. H. Ulander, H. Hellsten and G. Stenstrom, "Synthetic-aperture radar
   processing using fast factorized back-projection", IEEE Trans. Aerosp. Electron.
   Syst. 39(3), 760-776, 2003.
.. [3] I. G. Cumming and F. H. Wong, *Digital Processing of Synthetic Aperture Radar
   Data*, Artech House, 2005, section 2.6 (interpolation by FFT zero padding).
.. [4] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.fft import next_fast_len

from ..backend import aligned
from ..constants import C0
from .windows import AzimuthWindow

__all__ = [
    "PulseBlock",
    "backproject",
    "backproject_drjit",
    "backproject_numpy",
    "delays",
    "doppler",
    "upsample",
]


@dataclass(frozen=True)
class PulseBlock:
    """A block of range-compressed pulses, upsampled, with the platform positions used.

    Attributes
    ----------
    samples : ndarray (N_b, C, N_u) complex64
        Upsampled compressed samples y~_p[i] of eq (B3) [sqrt(W)].
    t0 : float
        Delay of upsampled sample 0 after emission [s].
    rate : float
        Upsampled sampling rate U f_s [Hz].
    tx, rx : ndarray (N_b, 3)
        Transmitter and receiver positions at emission [m].
    tx_velocity, rx_velocity : ndarray (N_b, 3)
        Their velocities [m/s].
    doppler_centroid : ndarray (N_b,)
        f_c,p of eq (B4) [Hz].
    weight : ndarray (N_b,)
        Extra per-pulse weight (1, or 0 to leave a pulse out) [-].
    """

    samples: NDArray[np.complex64]
    t0: float
    rate: float
    tx: NDArray[np.float64]
    rx: NDArray[np.float64]
    tx_velocity: NDArray[np.float64]
    rx_velocity: NDArray[np.float64]
    doppler_centroid: NDArray[np.float64]
    weight: NDArray[np.float64]

    @property
    def n_pulses(self) -> int:
        return int(self.samples.shape[0])

    @property
    def n_channels(self) -> int:
        return int(self.samples.shape[1])


def upsample(compressed: ArrayLike, factor: int) -> NDArray[np.complex64]:
    """Band-limited upsampling of the fast-time axis (last) by FFT zero padding.

    The samples are first padded with zeros (at least 16, to a fast FFT length) so that
    the periodic extension of the DFT does not fold the end of the window onto its start;
    the spectrum is then padded in its middle (between +f_s/2 and -f_s/2) and inverted.

    Parameters
    ----------
    compressed : array_like (..., N_s) complex
        Range-compressed samples at rate f_s [sqrt(W)].
    factor : int
        Upsampling factor U >= 1.

    Returns
    -------
    ndarray (..., U N_s) complex64
        Samples at rate U f_s, sample U m equal to input sample m (to rounding).

    References
    ----------
    Cumming & Wong (2005), section 2.6.
    """
    if int(factor) != factor or factor < 1:
        raise ValueError(f"upsampling factor = {factor}: must be an integer >= 1")
    y = np.asarray(compressed)
    n = y.shape[-1]
    if factor == 1:
        return y.astype(np.complex64)
    n_fft = int(next_fast_len(n + 16))
    spec = np.fft.fft(y, n_fft, axis=-1)
    half = n_fft // 2
    up = np.zeros(y.shape[:-1] + (factor * n_fft,), dtype=np.complex128)
    up[..., :half] = spec[..., :half]
    up[..., -(n_fft - half):] = spec[..., half:]
    if n_fft % 2 == 0:  # split the Nyquist bin between +f_s/2 and -f_s/2
        up[..., half] = 0.5 * spec[..., half]
        up[..., -half] = 0.5 * spec[..., half]
    out = np.fft.ifft(up, axis=-1)[..., : factor * n] * factor
    return out.astype(np.complex64)


def _receive_delay(d: NDArray, v: NDArray) -> NDArray:
    """Positive root tau of |d + v tau| = c tau (eq R3 of docs/radar.md) [s]."""
    dv = np.einsum("...i,...i->...", d, v)
    a = C0 * C0 - np.einsum("...i,...i->...", v, v)
    return (dv + np.sqrt(dv * dv + a * np.einsum("...i,...i->...", d, d))) / a


def delays(pixels: ArrayLike, tx: ArrayLike, rx: ArrayLike, rx_velocity: ArrayLike
           ) -> NDArray[np.float64]:
    """Delays tau_p(x) of eq (B1) for every pixel and pulse [s].

    Parameters
    ----------
    pixels : array_like (P, 3)
        Pixel positions [m].
    tx, rx, rx_velocity : array_like (N, 3)
        Transmitter and receiver positions at emission [m], receiver velocity [m/s].

    Returns
    -------
    ndarray (P, N)
    """
    x = np.asarray(pixels, dtype=np.float64)[:, None, :]
    t = np.asarray(tx, dtype=np.float64)[None]
    r = np.asarray(rx, dtype=np.float64)[None]
    v = np.broadcast_to(np.asarray(rx_velocity, dtype=np.float64)[None],
                        (x.shape[0],) + r.shape[1:])
    tau_t = np.linalg.norm(x - t, axis=-1) / C0
    # Eq (B1): the receiver moves by v tau_t while the pulse reaches the pixel
    return tau_t + _receive_delay(r + v * tau_t[..., None] - x, v)


def doppler(pixels: ArrayLike, tx: ArrayLike, rx: ArrayLike, tx_velocity: ArrayLike,
            rx_velocity: ArrayLike, wavelength: float) -> NDArray[np.float64]:
    """Bistatic Doppler frequency f_p(x) of a static scatterer, eq (B4) [Hz].

    Parameters
    ----------
    pixels : array_like (P, 3)
        Positions [m].
    tx, rx : array_like (N, 3)
        Platform positions [m].
    tx_velocity, rx_velocity : array_like (N, 3)
        Platform velocities [m/s].
    wavelength : float
        lambda [m].

    Returns
    -------
    ndarray (P, N)
        -(1/lambda) d(r_t + r_r)/dt (Willis 2005, eq 3.23).
    """
    x = np.asarray(pixels, dtype=np.float64)[:, None, :]
    f = np.zeros(x.shape[:1] + np.shape(tx)[:1])
    for p, v in ((tx, tx_velocity), (rx, rx_velocity)):
        d = x - np.asarray(p, dtype=np.float64)[None]
        u = d / np.linalg.norm(d, axis=-1, keepdims=True)
        f += np.einsum("pni,ni->pn", u, np.asarray(v, dtype=np.float64))
    return f / wavelength


def backproject_numpy(pixels: ArrayLike, block: PulseBlock, carrier: float,
                      window: AzimuthWindow, max_elements: int = 2_000_000
                      ) -> NDArray[np.complex128]:
    """Eqs (B1)-(B4) with numpy, vectorised over tiles of pixels x the block's pulses.

    Parameters
    ----------
    pixels : array_like (P, 3)
        Pixel positions [m].
    block : PulseBlock
        Pulses, platform states, Doppler centroids and per-pulse weights.
    carrier : float
        Carrier frequency f_c [Hz].
    window : AzimuthWindow
        Processed Doppler band B_a and window W of eq (B4).
    max_elements : int
        Pixels x pulses per vectorised tile (bounds the memory).

    Returns
    -------
    image : ndarray (C, P) complex128
        The block's contribution to I(x) [sqrt(W)].
    weights : ndarray (2, P)
        sum_p w_p(x), and the same over the pulses whose echo of x is inside the receive
        window [-] (their ratio says whether the window covers the pixel).
    """
    x = np.asarray(pixels, dtype=np.float64).reshape(-1, 3)
    n_b, n_c, n_u = block.samples.shape
    out = np.zeros((n_c, x.shape[0]), dtype=np.complex128)
    wsum = np.zeros((2, x.shape[0]))
    flat = block.samples.reshape(n_b * n_c, n_u)
    step = max(1, max_elements // max(n_b, 1))
    wavelength = C0 / carrier
    for s in range(0, x.shape[0], step):  # tiles of pixels, each vectorised
        xs = x[s:s + step]
        tau = delays(xs, block.tx, block.rx, block.rx_velocity)  # (P, N)
        # Eq (B4): window over the Doppler offset from the centroid
        f = doppler(xs, block.tx, block.rx, block.tx_velocity, block.rx_velocity,
                    wavelength)
        w = window((f - block.doppler_centroid[None, :]) / window.bandwidth)
        w = w * block.weight[None, :]
        # Eq (B3): fractional index in the upsampled samples
        u = (tau - block.t0) * block.rate
        i0 = np.floor(u).astype(np.int64)
        eps = (u - i0).astype(np.float32)
        ok = (i0 >= 0) & (i0 + 1 < n_u)
        wsum[0, s:s + step] = np.sum(w, axis=1)
        wsum[1, s:s + step] = np.sum(w * ok, axis=1)
        i0 = np.where(ok, i0, 0)
        # Eq (B2): carrier phase exp(+j 2 pi f_c tau), reduced modulo one cycle
        cyc = carrier * tau
        cyc -= np.floor(cyc)
        rot = np.exp(2j * np.pi * cyc) * (w * ok)
        pulse = np.arange(n_b)[None, :]
        for c in range(n_c):  # the channels
            row = pulse * n_c + c
            y = (1.0 - eps) * flat[row, i0] + eps * flat[row, i0 + 1]
            out[c, s:s + step] = np.sum(y * rot, axis=1)
    return out, wsum


def _drjit():
    from .._llvm import configure_llvm

    configure_llvm()
    import drjit as dr
    from drjit import llvm

    return dr, llvm


def backproject_drjit(pixels: ArrayLike, block: PulseBlock, carrier: float,
                      window: AzimuthWindow, max_pixels: int = 1 << 20
                      ) -> NDArray[np.complex128]:
    """Eqs (B1)-(B4) as one Dr.Jit LLVM kernel per tile of pixels (same result as
    :func:`backproject_numpy`, see the module docstring).

    Per-run values (carrier, window, sampling) and per-block sizes enter as opaque
    parameters, so one compiled kernel serves every block of a run (and every run with
    the same number of channels and window length).

    Parameters
    ----------
    pixels : array_like (P, 3)
        Pixel positions [m].
    block : PulseBlock
        Pulses, platform states, Doppler centroids and per-pulse weights.
    carrier : float
        Carrier frequency f_c [Hz].
    window : AzimuthWindow
        Processed Doppler band B_a and window W of eq (B4).
    max_pixels : int
        Pixels per kernel launch (bounds the memory: 2 C float32 accumulators per pixel).

    Returns
    -------
    image : ndarray (C, P) complex128
    weights : ndarray (2, P)
        As :func:`backproject_numpy`.
    """
    dr, llvm = _drjit()
    Float64, Float32 = llvm.Float64, llvm.Float
    x = np.asarray(pixels, dtype=np.float64).reshape(-1, 3)
    n_b, n_c, n_u = block.samples.shape
    out = np.zeros((n_c, x.shape[0]), dtype=np.complex128)
    wsum = np.zeros((2, x.shape[0]))
    if n_b == 0 or x.shape[0] == 0:
        return out, wsum
    # Samples as float32 [pulse, i, channel, re/im]: one pixel's gathers are contiguous
    data = Float32(aligned(np.ascontiguousarray(block.samples.transpose(0, 2, 1))
                           .view(np.float32).reshape(-1), np.float32))
    cols = [Float64(aligned(a)) for a in (
        *block.tx.T, *block.rx.T, *block.tx_velocity.T, *block.rx_velocity.T,
        block.doppler_centroid, block.weight)]
    # Per-run values as opaque parameters: one compiled kernel for every block
    par = {"n_pulses": dr.opaque(llvm.UInt32, n_b), "t0": dr.opaque(Float64, block.t0),
           "rate": dr.opaque(Float64, block.rate), "fc": dr.opaque(Float64, carrier),
           "inv_lb": dr.opaque(Float64, carrier / (C0 * window.bandwidth)),
           "inv_b": dr.opaque(Float64, 1.0 / window.bandwidth),
           "n_up": dr.opaque(llvm.Int32, n_u),
           "coef": [dr.opaque(Float32, c) for c in window.normalised]}
    for s in range(0, x.shape[0], max_pixels):  # tiles of pixels, one kernel each
        pix = [Float64(aligned(x[s:s + max_pixels, k])) for k in range(3)]
        acc = _kernel(dr, llvm, pix, data, cols, par, n_c)
        vals = np.stack([np.asarray(a, dtype=np.float64) for a in acc])
        out[:, s:s + max_pixels] = vals[0:2 * n_c:2] + 1j * vals[1:2 * n_c:2]
        wsum[:, s:s + max_pixels] = vals[2 * n_c:]
    return out, wsum


def _kernel(dr, llvm, pix, data, cols, par, n_c):
    """The symbolic loop over pulses of :func:`backproject_drjit` for one tile of pixels;
    returns the 2 C + 2 accumulators (re, im per channel; sum of w, sum of w inside the
    window), evaluated."""
    Float64, Float32, UInt32, Int32 = llvm.Float64, llvm.Float, llvm.UInt32, llvm.Int32
    px, py, pz = pix
    n_pix = dr.width(px)
    t0, rate, fc, n_up = par["t0"], par["rate"], par["fc"], par["n_up"]
    inv_lb, inv_b, coef = par["inv_lb"], par["inv_b"], par["coef"]
    c2 = C0 * C0
    two_pi = float(2.0 * np.pi)
    stride = 2 * n_c
    acc = [dr.zeros(Float32, n_pix) for _ in range(stride + 2)]
    i = dr.zeros(UInt32, n_pix)

    def cond(i, *acc):
        return i < par["n_pulses"]

    def body(i, *acc):
        (tx, ty, tz, rx, ry, rz, ux, uy, uz, vx, vy, vz, fdc, wp) = (
            dr.gather(Float64, col, i) for col in cols)
        # Eq (B1): outbound leg, then the receiver's leg with its motion
        ax, ay, az = px - tx, py - ty, pz - tz
        r_t = dr.sqrt(ax * ax + ay * ay + az * az)
        tau_t = r_t / C0
        dx = rx + vx * tau_t - px
        dy = ry + vy * tau_t - py
        dz = rz + vz * tau_t - pz
        dv = dx * vx + dy * vy + dz * vz
        a = c2 - (vx * vx + vy * vy + vz * vz)
        tau = tau_t + (dv + dr.sqrt(dv * dv + a * (dx * dx + dy * dy + dz * dz))) / a
        # Eq (B4): Doppler offset from the centroid, normalised by B_a, and W
        bx, by, bz = px - rx, py - ry, pz - rz
        r_r = dr.sqrt(bx * bx + by * by + bz * bz)
        f = (ax * ux + ay * uy + az * uz) / r_t + (bx * vx + by * vy + bz * vz) / r_r
        xi = Float32(f * inv_lb - fdc * inv_b)
        cos1 = dr.cos(two_pi * xi)
        w = coef[0]
        if len(coef) > 1:
            prev, cur = dr.ones(Float32, n_pix), cos1
            w = w + coef[1] * cur
            for m in range(2, len(coef)):  # cos(m t) by the Chebyshev recurrence
                prev, cur = cur, 2.0 * cos1 * cur - prev
                w = w + coef[m] * cur
        # Eq (B3): linear interpolation of the upsampled samples
        u = (tau - t0) * rate
        fl = dr.floor(u)
        i0 = Int32(fl)
        eps = Float32(u - fl)
        band = dr.abs(xi) <= 0.5
        ok = (i0 >= 0) & (i0 + 1 < n_up) & band
        w_band = dr.select(band, w * Float32(wp), 0.0)
        w = dr.select(ok, w_band, 0.0)
        # Eq (B2): carrier phase, reduced modulo one cycle in float64
        cyc = fc * tau
        sn, cs = dr.sincos(Float32(cyc - dr.floor(cyc)) * two_pi)
        cs, sn = cs * w, sn * w
        base = UInt32((Int32(i) * n_up + dr.select(ok, i0, 0)) * stride)
        new = []
        for c in range(n_c):
            k = base + 2 * c
            re0 = dr.gather(Float32, data, k, ok)
            im0 = dr.gather(Float32, data, k + 1, ok)
            re1 = dr.gather(Float32, data, k + stride, ok)
            im1 = dr.gather(Float32, data, k + stride + 1, ok)
            yr = dr.fma(eps, re1 - re0, re0)
            yi = dr.fma(eps, im1 - im0, im0)
            new.append(acc[2 * c] + (yr * cs - yi * sn))
            new.append(acc[2 * c + 1] + (yr * sn + yi * cs))
        new.append(acc[stride] + w_band)
        new.append(acc[stride + 1] + w)
        return (i + 1, *new)

    i, *acc = dr.while_loop(state=(i, *acc), cond=cond, body=body)
    dr.eval(*acc)
    return acc


def backproject(pixels: ArrayLike, block: PulseBlock, carrier: float,
                window: AzimuthWindow, backend: str = "drjit"
                ) -> tuple[NDArray[np.complex128], NDArray[np.float64]]:
    """Eqs (B1)-(B4) by ``backend`` ('drjit' or 'numpy'): the (C, P) image [sqrt(W)] and
    the (2, P) weight sums of :func:`backproject_numpy`."""
    if backend == "drjit":
        return backproject_drjit(pixels, block, carrier, window)
    if backend == "numpy":
        return backproject_numpy(pixels, block, carrier, window)
    raise ValueError(f"backend = {backend!r}: allowed 'drjit', 'numpy'")
