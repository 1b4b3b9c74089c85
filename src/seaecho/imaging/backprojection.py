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

The per-pixel, per-pulse terms (delay, Doppler offset and window, interpolation index,
carrier phase: :func:`pulse_terms`, :func:`interpolate`) are written once over an array
namespace (:mod:`seaecho.backend`), the delay being the radar equation's own
(:func:`seaecho.radar.equation.flight`, eq R3). Two evaluations give the same numbers
(tests): :func:`backproject_numpy`, the reference, on (pixels x pulses) tiles summed over
the pulses; and :func:`backproject_drjit`, one Dr.Jit kernel over pixels with a symbolic
loop over the pulses of a block, on the CPU (``drjit.llvm``) or a CUDA GPU
(``drjit.cuda``) by the Mitsuba variant. Both take float64 delays, the carrier phase
reduced modulo one cycle before a float32 sine and cosine, float32 samples; the kernel
accumulates in float32 per block (float64 across blocks), numpy in float64.

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
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.fft import next_fast_len

from ..backend import NUMPY, Boundary, Vec3, aligned, drjit_namespace
from ..constants import C0
from ..processing.windows import cosine_series
from ..radar.equation import flight
from .windows import AzimuthWindow

__all__ = [
    "PulseBlock",
    "backproject",
    "backproject_drjit",
    "backproject_numpy",
    "delays",
    "doppler",
    "interpolate",
    "pulse_terms",
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


# ------------------------------------------------------------ formulas (any namespace)
def echo_delay(xp, x: Any, tx: Any, rx: Any, rx_velocity: Any) -> Any:
    """tau_p(x) of eq (B1) [s]: eq R3 of the echo model for a static scatterer at ``x``."""
    tau_t, tau_r, _ = flight(xp, tx, x, xp.vec(0.0, 0.0, 0.0), rx, rx_velocity)
    return tau_t + tau_r


def doppler_frequency(xp, x: Any, tx: Any, rx: Any, tx_velocity: Any, rx_velocity: Any
                      ) -> Any:
    """lambda f_p(x) of eq (B4) [m/s]: the bistatic range rate -d(r_t + r_r)/dt of a
    static scatterer at ``x`` (Willis 2005, eq 3.23)."""
    a, b = x - tx, x - rx
    return xp.dot(a, tx_velocity) / xp.norm(a) + xp.dot(b, rx_velocity) / xp.norm(b)


def pulse_terms(xp, x: Any, pulse: dict[str, Any], par: dict[str, Any]) -> dict[str, Any]:
    """Eqs (B1)-(B4) for pixels ``x`` and one pulse (or broadcast pulses), namespace ``xp``.

    Parameters
    ----------
    xp : array namespace
    x : vector
        Pixel positions [m].
    pulse : dict
        ``tx, rx, tx_velocity, rx_velocity`` (vectors [m, m/s]), ``doppler_centroid``
        f_c,p [Hz] and ``weight`` [-] of the pulse.
    par : dict
        Constants: ``t0`` [s], ``rate`` U f_s [Hz], ``fc`` [Hz], ``inv_lb`` 1/(lambda B_a)
        [s/m], ``inv_b`` 1/B_a [s], ``n_up`` (samples per channel), ``coef`` (window).

    Returns
    -------
    dict
        ``index`` of the left sample and ``eps`` (float32) of eq (B3), ``ok`` (inside the
        window and the band), ``w_band`` (w_p(x) where the band holds, 0 elsewhere),
        ``w`` (w_p(x) where the sample also exists), ``cos``, ``sin`` (the carrier phase
        factor of eq (B2) times ``w``, float32).
    """
    tau = echo_delay(xp, x, pulse["tx"], pulse["rx"], pulse["rx_velocity"])  # (B1)
    # Eq (B4): Doppler offset from the centroid, normalised by B_a, and W
    f = doppler_frequency(xp, x, pulse["tx"], pulse["rx"], pulse["tx_velocity"],
                          pulse["rx_velocity"])
    xi = xp.single(f * par["inv_lb"] - pulse["doppler_centroid"] * par["inv_b"])
    band = xp.abs(xi) <= 0.5
    w_band = xp.select(band, cosine_series(xp, xi, par["coef"])
                       * xp.single(pulse["weight"]), 0.0)
    # Eq (B3): the left upsampled sample and the fraction
    u = (tau - par["t0"]) * par["rate"]
    left = xp.floor(u)
    ok = (left >= 0.0) & (left + 1.0 < par["n_up"]) & band
    w = xp.select(ok, w_band, 0.0)
    # Eq (B2): carrier phase exp(+j 2 pi f_c tau), reduced modulo one cycle in float64
    cyc = par["fc"] * tau
    phase = xp.single(cyc - xp.floor(cyc)) * (2.0 * np.pi)
    return dict(index=xp.index(xp.select(ok, left, 0.0)), eps=xp.single(u - left), ok=ok,
                w_band=w_band, w=w, cos=xp.cos(phase) * w, sin=xp.sin(phase) * w)


def interpolate(xp, data: Any, base: Any, eps: Any, ok: Any, channel: int, stride: int
                ) -> tuple[Any, Any]:
    """y_p(tau) of eq (B3), real and imaginary parts, from the flat float32 samples
    ``data`` laid out [pulse, sample, channel, re/im]: entry ``base + 2 channel`` is the
    left sample's real part, ``+ stride`` the next sample's."""
    k = base + 2 * channel
    re0, im0 = xp.gather(data, k, ok), xp.gather(data, k + 1, ok)
    re1, im1 = xp.gather(data, k + stride, ok), xp.gather(data, k + (stride + 1), ok)
    return re0 + eps * (re1 - re0), im0 + eps * (im1 - im0)


def _flat_samples(block: PulseBlock) -> NDArray[np.float32]:
    """The block's samples as float32 [pulse, sample, channel, re/im] (one pixel's
    gathers are contiguous)."""
    return np.ascontiguousarray(block.samples.transpose(0, 2, 1)).view(np.float32).reshape(-1)


def _constants(xp, block: PulseBlock, carrier: float, window: AzimuthWindow) -> dict:
    return {"t0": xp.const(block.t0), "rate": xp.const(block.rate), "fc": xp.const(carrier),
            "inv_lb": xp.const(carrier / (C0 * window.bandwidth)),
            "inv_b": xp.const(1.0 / window.bandwidth),
            "n_up": xp.const(float(block.samples.shape[2])),
            "coef": [xp.const32(c) for c in window.normalised]}


# ------------------------------------------------------------------------- numpy API
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
    x, t, r, v = _pixel_pulse(pixels, tx, rx, rx_velocity)
    tau = echo_delay(NUMPY, x, t, r, v)
    return np.broadcast_to(tau, (x.x.shape[0], t.x.shape[1])).copy()


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
    x, t, r, vt, vr = _pixel_pulse(pixels, tx, rx, tx_velocity, rx_velocity)
    f = doppler_frequency(NUMPY, x, t, r, vt, vr) / wavelength
    return np.broadcast_to(f, (x.x.shape[0], t.x.shape[1])).copy()


def _pixel_pulse(pixels: ArrayLike, *per_pulse: ArrayLike) -> list[Vec3]:
    """Pixels as (P, 1) and per-pulse vectors as (1, N) numpy namespace vectors."""
    io = Boundary(NUMPY)
    out = [io.vec3(np.asarray(pixels, dtype=np.float64).reshape(-1, 3)[:, None, :])]
    out += [io.vec3(np.asarray(a, dtype=np.float64).reshape(-1, 3)[None]) for a in per_pulse]
    return out


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
    xp = NUMPY
    x = np.asarray(pixels, dtype=np.float64).reshape(-1, 3)
    n_b, n_c, n_u = block.samples.shape
    out = np.zeros((n_c, x.shape[0]), dtype=np.complex128)
    wsum = np.zeros((2, x.shape[0]))
    if n_b == 0 or x.shape[0] == 0:
        return out, wsum
    data = _flat_samples(block)
    par = _constants(xp, block, carrier, window)
    _, tx, rx, tv, rv = _pixel_pulse(x[:1], block.tx, block.rx, block.tx_velocity,
                                     block.rx_velocity)
    pulse = dict(tx=tx, rx=rx, tx_velocity=tv, rx_velocity=rv,
                 doppler_centroid=block.doppler_centroid[None, :],
                 weight=block.weight[None, :])
    stride = 2 * n_c
    first = (np.arange(n_b) * n_u)[None, :]
    step = max(1, max_elements // max(n_b, 1))
    for s in range(0, x.shape[0], step):  # tiles of pixels, each vectorised
        (xs,) = _pixel_pulse(x[s:s + step])
        with np.errstate(over="ignore", invalid="ignore"):  # B_a of 5e-324 Hz: 1/B_a is
            t = pulse_terms(xp, xs, pulse, par)  # inf, xi NaN or inf, outside the band
        wsum[0, s:s + step] = np.sum(t["w_band"], axis=1, dtype=np.float64)
        wsum[1, s:s + step] = np.sum(t["w"], axis=1, dtype=np.float64)
        base = (first + t["index"]) * stride
        for c in range(n_c):  # the channels
            yr, yi = interpolate(xp, data, base, t["eps"], t["ok"], c, stride)
            out[c, s:s + step] = (np.sum(yr * t["cos"] - yi * t["sin"], axis=1,
                                         dtype=np.float64)
                                  + 1j * np.sum(yr * t["sin"] + yi * t["cos"], axis=1,
                                                dtype=np.float64))
    return out, wsum


def backproject_drjit(pixels: ArrayLike, block: PulseBlock, carrier: float,
                      window: AzimuthWindow, max_pixels: int = 1 << 20, *,
                      variant: str | None = None) -> NDArray[np.complex128]:
    """Eqs (B1)-(B4) as one Dr.Jit kernel per tile of pixels (same result as
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
    variant : str, optional
        Mitsuba variant choosing ``drjit.llvm`` (CPU, default) or ``drjit.cuda`` (GPU)
        (:func:`seaecho.backend.drjit_namespace`).

    Returns
    -------
    image : ndarray (C, P) complex128
    weights : ndarray (2, P)
        As :func:`backproject_numpy`.
    """
    xp = drjit_namespace(variant)
    x = np.asarray(pixels, dtype=np.float64).reshape(-1, 3)
    n_b, n_c, n_u = block.samples.shape
    out = np.zeros((n_c, x.shape[0]), dtype=np.complex128)
    wsum = np.zeros((2, x.shape[0]))
    if n_b == 0 or x.shape[0] == 0:
        return out, wsum
    io = Boundary(xp)
    data = xp.Float32(aligned(_flat_samples(block), np.float32))
    cols = {"tx": io.vec3(block.tx), "rx": io.vec3(block.rx),
            "tx_velocity": io.vec3(block.tx_velocity),
            "rx_velocity": io.vec3(block.rx_velocity),
            "doppler_centroid": io.array(block.doppler_centroid),
            "weight": io.array(block.weight)}
    par = _constants(xp, block, carrier, window)
    par["n_pulses"] = xp.index(xp.const(float(n_b)))
    for s in range(0, x.shape[0], max_pixels):  # tiles of pixels, one kernel each
        tile = Boundary(xp)
        acc = _loop(xp, tile.vec3(x[s:s + max_pixels]), data, cols, par, n_c)
        vals = Boundary(xp, int(x[s:s + max_pixels].shape[0])).numpy(*acc)
        for c in range(n_c):
            out[c, s:s + max_pixels] = vals[2 * c] + 1j * vals[2 * c + 1]
        wsum[:, s:s + max_pixels] = vals[2 * n_c:]
    return out, wsum


def _loop(xp, px: Any, data: Any, cols: dict, par: dict, n_c: int) -> list:
    """The symbolic loop over pulses of :func:`backproject_drjit` for one tile of pixels:
    the 2 C + 2 accumulators (re, im per channel; sum of w, sum of w inside the window)."""
    n_pix = xp.width(px.x)
    stride = 2 * n_c
    acc = [xp.single(xp.zeros(n_pix)) for _ in range(stride + 2)]
    first = xp.index(xp.zeros(n_pix))

    def cond(i, *acc):
        return i < par["n_pulses"]

    def body(i, *acc):
        pulse = {k: (xp.vec(*(xp.gather(c, i) for c in v)) if xp.is_vector(v)
                     else xp.gather(v, i)) for k, v in cols.items()}
        t = pulse_terms(xp, px, pulse, par)
        base = (i * xp.index(par["n_up"]) + t["index"]) * stride
        new = []
        for c in range(n_c):
            yr, yi = interpolate(xp, data, base, t["eps"], t["ok"], c, stride)
            new.append(acc[2 * c] + (yr * t["cos"] - yi * t["sin"]))
            new.append(acc[2 * c + 1] + (yr * t["sin"] + yi * t["cos"]))
        new.append(acc[stride] + t["w_band"])
        new.append(acc[stride + 1] + t["w"])
        return (i + 1, *new)

    _, *acc = xp.while_loop((first, *acc), cond, body)
    xp.eval(*acc)
    return acc


def backproject(pixels: ArrayLike, block: PulseBlock, carrier: float,
                window: AzimuthWindow, backend: str = "drjit", *, variant: str | None = None
                ) -> tuple[NDArray[np.complex128], NDArray[np.float64]]:
    """Eqs (B1)-(B4) by ``backend`` ('drjit' or 'numpy'): the (C, P) image [sqrt(W)] and
    the (2, P) weight sums of :func:`backproject_numpy`. ``variant`` selects the Dr.Jit
    back end (``llvm_*`` CPU, default; ``cuda_*`` GPU)."""
    if backend == "drjit":
        return backproject_drjit(pixels, block, carrier, window, variant=variant)
    if backend == "numpy":
        return backproject_numpy(pixels, block, carrier, window)
    raise ValueError(f"backend = {backend!r}: allowed 'drjit', 'numpy'")
