"""SAR image formation from a raw dataset: backprojection, calibration, products, truth.

:func:`focus` reads a ``seaecho run`` dataset through its variables and attributes only
(the raw product contract of ``docs/products.md``, ``product_version`` 1: ``compressed``
or ``raw`` + ``transmitted_pulse``, ``fast_time``, the ``tx_``/``rx_`` positions,
velocities and antenna axes per pulse, true and ``_nominal``, the ``tx_antenna_*`` and
``rx_antenna_*`` patterns, ``carrier_frequency_hz``, ``sampling_rate_hz``, ``prf_hz``,
``transmit_power_w``; never the scene), streams its pulses in
blocks, backprojects them (``imaging.backprojection``, eqs B1-B4) onto a horizontal grid
and calibrates the result (``imaging.calibration``, eqs K1-K3):

- ``image(channel, y, x)`` complex [m]: s = I / K, |s|^2 = RCS at a point target's peak;
- ``sigma0(channel, y, x)`` [m^2/m^2]: |I|^2 / (K^2 A_eff), the mean of a distributed
  target's image is its sigma0;
- ``pauli(pauli, y, x)``: Pauli powers in sigma0 units; optional speckle-filtered and
  multilooked intensities;
- calibration maps (``gain`` K, ``resolution_area`` A_eff, ``coverage``) and the ground
  truth of ``imaging.truth`` on the same grid.

The processor uses the nominal track (its navigation solution) unless told to use the
true one. Memory is bounded by one block of upsampled pulses (``block_pulses`` x channels
x U x samples x 8 bytes) plus the image.

References: see ``imaging.backprojection`` and ``imaging.calibration``.
"""

from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..config.image import ImageConfig
from ..constants import C0
from ..io.product import check_product_version, read_antenna
from .backprojection import PulseBlock, backproject, upsample
from .calibration import Track, calibration_at, compressed_pulse_energy
from .windows import AzimuthWindow

__all__ = ["ImageGrid", "RawData", "default_extent", "focus", "focus_points"]

#: Coverage (K / max K, amplitude) below which a pixel is flagged invalid (-20 dB).
MIN_COVERAGE = 0.1
#: Fraction of a pixel's weight whose echo must fall inside the receive window (valid).
MIN_INSIDE = 0.99
#: Most pixels an image may have (4096 x 4096: about 2.5 GB of arrays for 4 channels).
MAX_PIXELS = 4096 * 4096
#: Calibration nodes per axis at most (K and A_eff are smooth; cubic interpolation).
CALIBRATION_NODES = 65


@dataclass(frozen=True)
class ImageGrid:
    """A horizontal grid of pixel centres.

    Attributes
    ----------
    x, y : ndarray
        Pixel centres [m] (increasing).
    height : float
        z of the image plane [m].
    """

    x: NDArray[np.float64]
    y: NDArray[np.float64]
    height: float = 0.0

    @classmethod
    def from_extent(cls, extent: tuple[float, float, float, float], pixel: float,
                    height: float = 0.0) -> ImageGrid:
        """Pixels of size ``pixel`` [m] tiling (x_min, x_max, y_min, y_max) [m]."""
        x0, x1, y0, y1 = (float(v) for v in extent)
        if not (x1 > x0 and y1 > y0):
            raise ValueError(f"extent = {list(extent)} m: need x_min < x_max, y_min < y_max")
        if not pixel > 0:
            raise ValueError(f"pixel = {pixel} m: must be > 0")
        nx = max(1, int(round((x1 - x0) / pixel)))
        ny = max(1, int(round((y1 - y0) / pixel)))
        if nx * ny > MAX_PIXELS:
            raise ValueError(f"{ny} x {nx} pixels of {pixel} m over {list(extent)} m: more "
                             f"than {MAX_PIXELS}; use a larger pixel or a smaller extent")
        return cls(x0 + (np.arange(nx) + 0.5) * pixel, y0 + (np.arange(ny) + 0.5) * pixel,
                   float(height))

    @property
    def shape(self) -> tuple[int, int]:
        return (self.y.size, self.x.size)

    def points(self) -> NDArray[np.float64]:
        """Pixel positions (ny nx, 3), rows of y, x fastest [m]."""
        xx, yy = np.meshgrid(self.x, self.y)
        return np.stack([xx.ravel(), yy.ravel(), np.full(xx.size, self.height)], axis=-1)

    def nodes(self, n_max: int = CALIBRATION_NODES) -> ImageGrid:
        """Coarse grid spanning the same pixel centres, at most n_max nodes per axis."""
        def axis(v):
            n = min(v.size, n_max)
            return np.linspace(v[0], v[-1], n) if n > 1 else v.copy()

        return ImageGrid(axis(self.x), axis(self.y), self.height)


class RawData:
    """Read-only access to a raw dataset through its variables and attributes.

    Parameters
    ----------
    ds : xarray.Dataset
        Opened with ``xarray.open_dataset(path, engine="h5netcdf")`` (lazy).
    """

    REQUIRED_VARS = ("fast_time", "transmitted_pulse", "tx_position", "rx_position",
                     "tx_velocity", "rx_velocity", "tx_antenna_axes", "rx_antenna_axes")
    REQUIRED_ATTRS = ("carrier_frequency_hz", "sampling_rate_hz", "prf_hz",
                      "transmit_power_w")

    def __init__(self, ds) -> None:
        check_product_version(ds.attrs)
        missing = [v for v in self.REQUIRED_VARS if v not in ds.variables]
        missing += [f"attribute {a}" for a in self.REQUIRED_ATTRS if a not in ds.attrs]
        if "compressed" not in ds and "raw" not in ds:
            missing.append("compressed (or raw)")
        if missing:
            raise ValueError("not a seaecho raw dataset (or one written before image "
                             f"formation existed): missing {', '.join(missing)}; run "
                             "`seaecho run` again")
        self.ds = ds
        a = ds.attrs
        self.carrier = float(a["carrier_frequency_hz"])
        self.wavelength = C0 / self.carrier
        self.sampling_rate = float(a["sampling_rate_hz"])
        self.prf = float(a["prf_hz"])
        self.transmit_power = float(a["transmit_power_w"])
        self.fast_time = np.asarray(ds["fast_time"].values, dtype=np.float64)
        self.t0 = float(self.fast_time[0])
        self.channels = [str(c) for c in ds["channel"].values]
        self.n_pulses = int(ds.sizes["pulse"])
        self.pulse = np.asarray(ds["transmitted_pulse"].values, dtype=np.complex128)
        self.range_weighting = str(a.get("range_weighting", "none"))
        self.bandwidth = float(a.get("waveform_bandwidth_hz", self.sampling_rate))
        if self.n_pulses < 1 or self.fast_time.size < 2:
            raise ValueError(f"the dataset has {self.n_pulses} pulses of "
                             f"{self.fast_time.size} samples: nothing to focus")

    def track(self, kind: str) -> Track:
        """The processor's platform states: 'nominal' or 'true'."""
        if kind not in ("nominal", "true"):
            raise ValueError(f"track = {kind!r}: allowed 'nominal', 'true'")
        suffix = "_nominal" if kind == "nominal" else ""
        names = ("tx_position", "rx_position", "tx_velocity", "rx_velocity",
                 "tx_antenna_axes", "rx_antenna_axes")
        arrays = []
        for n in names:
            name = n + suffix if n + suffix in self.ds else n
            arrays.append(np.asarray(self.ds[name].values, dtype=np.float64))
        return Track(*arrays)

    def antennas(self):
        """(transmit, receive) antenna patterns of the product's ``tx_antenna_*`` and
        ``rx_antenna_*`` variables at the carrier (``io.product``)."""
        return (read_antenna(self.ds, "tx", self.wavelength),
                read_antenna(self.ds, "rx", self.wavelength))

    def compressed(self, start: int, stop: int, weighting: str | None, nbar: int = 5,
                   sidelobe_db: float = 35.0) -> NDArray[np.complex128]:
        """Range-compressed pulses [start, stop) with ``weighting`` (None: as in the file)."""
        if weighting is None or ("compressed" in self.ds and weighting == self.range_weighting):
            if "compressed" in self.ds:
                return np.asarray(self.ds["compressed"][start:stop].values)
            weighting = self.range_weighting
        from ..processing.range_compression import range_compress

        if "raw" not in self.ds:
            raise ValueError(f"range weighting {weighting!r} needs the raw samples, which "
                             "the file does not hold")
        raw = np.asarray(self.ds["raw"][start:stop].values)
        return range_compress(raw, self.pulse, weighting, nbar=nbar, sidelobe_db=sidelobe_db)

    def default_extent(self) -> tuple[float, float, float, float]:
        """The sea tile, or the targets' bounding box plus 20 range resolutions."""
        return default_extent(self.ds, self.bandwidth)


def default_extent(ds, bandwidth: float) -> tuple[float, float, float, float]:
    """The default image extent of a raw dataset [m]: its sea tile, or its targets'
    bounding box plus 20 range resolutions c / (2 B), B = ``bandwidth`` [Hz]."""
    if "x_cell" in ds and int(ds.attrs.get("sea_clutter", 1)):
        x, y = ds["x"].values, ds["y"].values
        dx, dy = x[1] - x[0], y[1] - y[0]
        return (float(x[0]), float(x[-1] + dx), float(y[0]), float(y[-1] + dy))
    if "target_position" in ds:
        p = ds["target_position"].values
        m = 20.0 * C0 / (2.0 * bandwidth)
        return (float(p[:, 0].min() - m), float(p[:, 0].max() + m),
                float(p[:, 1].min() - m), float(p[:, 1].max() + m))
    raise ValueError("the dataset has neither a sea tile nor targets: give the image "
                     "extent")


def _single(a) -> NDArray:
    """``a`` in single precision (complex64 if complex, else float32), for the products
    bounded by construction (fractions in [0, 1])."""
    a = np.asarray(a)
    return a.astype(np.complex64 if np.iscomplexobj(a) else np.float32)


def _calibrated(a, nodata: NDArray | None = None) -> NDArray:
    """A calibrated product (s, sigma0, A_eff, K, Pauli powers, their filtered and
    multilooked versions) in double precision, as computed and as the file holds it
    (float32 overflowed to Inf beyond 3.4e38: sigma0 = |I|^2 / (K^2 A_eff) of noise at
    pixels where K is a tiny fraction of its peak). A value that overflowed float64 too
    becomes NaN where ``nodata`` (broadcast over the leading axis) marks a pixel without
    data (``valid`` = 0: K < 0.1 max K, or the echoes outside the receive window); at a
    pixel with data every value is bounded (K >= 0.1 max K) and the image guard
    (``seaecho.checks.guards.check_image``) reports any that is not."""
    a = np.asarray(a)
    a = a.astype(np.complex128 if np.iscomplexobj(a) else np.float64)
    if nodata is None:
        return a
    bad = ~np.isfinite(a) & np.broadcast_to(nodata, a.shape)
    if bad.any():
        a = a.copy()
        a[bad] = np.nan
    return a


def _power_of_two_scale(y: NDArray) -> float:
    """2^e near the largest |y| (1 if none is finite and > 0): the samples over it are of
    order 1 in the kernels' float32, whatever the transmit power (1e-170 sqrt(W) echoes
    of a 5e-324 W transmitter flushed to 0 in float32, 1e20 ones would overflow); a power
    of two divides and multiplies back exactly, so data of ordinary magnitude keep their
    bytes."""
    with np.errstate(invalid="ignore", over="ignore"):
        peak = float(np.max(np.abs(y), initial=0.0))
    if not 0.0 < peak < np.inf:
        return 1.0
    return float(2.0 ** np.frexp(peak)[1])


def _interpolate(nodes: ImageGrid, values: NDArray, grid: ImageGrid) -> NDArray:
    """Cubic (or lower, with few nodes) spline from the node grid to the pixels."""
    from scipy.interpolate import RectBivariateSpline

    v = values.reshape(nodes.shape)
    if nodes.x.size == grid.x.size and nodes.y.size == grid.y.size:
        return v
    ky, kx = min(3, nodes.y.size - 1), min(3, nodes.x.size - 1)
    if kx < 1 or ky < 1:
        return np.broadcast_to(v, grid.shape).copy()
    # scipy's kx is the degree along its first axis, here y
    spline = RectBivariateSpline(nodes.y, nodes.x, v, kx=ky, ky=kx)
    return spline(grid.y, grid.x)


def focus(source: str | os.PathLike | object, config: ImageConfig | None = None, *,
          backend: str = "drjit", block_pulses: int = 32, timings: dict | None = None,
          progress: bool = False):
    """Focus a raw dataset into a calibrated polarimetric SAR image.

    Parameters
    ----------
    source : path or xarray.Dataset
        The raw dataset (``seaecho run`` output).
    config : ImageConfig, optional
        Processing parameters (``[image]`` section); default all defaults.
    backend : {'drjit', 'numpy'}
        Backprojection kernel.
    block_pulses : int
        Pulses read and backprojected at a time.
    timings : dict, optional
        Filled with the time of each stage [s] (read, backprojection, calibration,
        products) and the throughput.
    progress : bool
        Show a progress bar over the pulse blocks.

    Returns
    -------
    xarray.Dataset
        The image dataset (module docstring).
    """
    import xarray as xr

    cfg = ImageConfig() if config is None else config
    own = not isinstance(source, xr.Dataset)
    ds = xr.open_dataset(source, engine="h5netcdf") if own else source
    try:
        return _focus(RawData(ds), cfg, backend, block_pulses,
                      timings if timings is not None else {}, progress,
                      str(source) if own else "")
    finally:
        if own:
            ds.close()


class _Processor:
    """What one image needs from a raw dataset and a configuration: track, window,
    weighting, and the streamed backprojection (eqs B1-B4) onto any points."""

    def __init__(self, raw: RawData, cfg: ImageConfig, backend: str) -> None:
        if backend not in ("drjit", "numpy"):
            raise ValueError(f"backend = {backend!r}: allowed 'drjit', 'numpy'")
        self.raw, self.cfg, self.backend = raw, cfg, backend
        self.track = raw.track(cfg.track)
        self.window = AzimuthWindow.named(cfg.azimuth_window,
                                          cfg.doppler_bandwidth_hz or raw.prf,
                                          cfg.taylor_nbar, cfg.taylor_sidelobe_db)
        self.weighting = (cfg.range_weighting if cfg.range_weighting is not None
                          else raw.range_weighting)

    def backproject(self, points: NDArray, block_pulses: int = 32, timings: dict | None = None,
                    progress: bool = False
                    ) -> tuple[NDArray[np.complex128], NDArray[np.float64]]:
        """I(x) of eq (B2) at points (P, 3): (C, P) complex [sqrt(W)], pulses streamed;
        and the (2, P) sums of the weights w_p(x), all and inside the receive window."""
        from tqdm import tqdm

        if block_pulses < 1:
            raise ValueError(f"block_pulses = {block_pulses}: must be >= 1")
        raw, cfg, track = self.raw, self.cfg, self.track
        fdc = track.doppler_centroid(raw.wavelength)
        rate = raw.sampling_rate * cfg.upsample
        acc = np.zeros((len(raw.channels), points.shape[0]), dtype=np.complex128)
        wsum = np.zeros((2, points.shape[0]))
        t_read = t_bp = 0.0
        bar = tqdm(total=raw.n_pulses, unit="pulse", disable=not progress,
                   desc="seaecho image")
        try:
            for start in range(0, raw.n_pulses, block_pulses):  # pulses streamed in blocks
                stop = min(start + block_pulses, raw.n_pulses)
                t = time.perf_counter()
                y = raw.compressed(start, stop, cfg.range_weighting, cfg.taylor_nbar,
                                   cfg.taylor_sidelobe_db)
                scale = _power_of_two_scale(y)  # eq B2 is linear in the samples
                up = upsample(y / scale, cfg.upsample)
                t_read += time.perf_counter() - t
                sl = slice(start, stop)
                block = PulseBlock(up, raw.t0, rate, track.tx[sl], track.rx[sl],
                                   track.tx_velocity[sl], track.rx_velocity[sl], fdc[sl],
                                   np.ones(stop - start))
                t = time.perf_counter()
                img, w = backproject(points, block, raw.carrier, self.window, self.backend)
                acc += img * scale
                wsum += w
                t_bp += time.perf_counter() - t
                bar.update(stop - start)
        finally:
            bar.close()
        if timings is not None:
            timings.update(read_upsample=t_read, backprojection=t_bp)
        return acc, wsum

    def calibration(self, points: NDArray, window_cut: bool = True):
        """K and A_eff (eqs K2-K3) at points (P, 3), and E_chi [s]; ``window_cut``: leave
        out the pulses whose echo of a point falls outside the receive window."""
        raw, cfg = self.raw, self.cfg
        tx_ant, rx_ant = raw.antennas()
        e_chi = compressed_pulse_energy(raw.pulse, raw.sampling_rate, self.weighting,
                                        cfg.taylor_nbar, cfg.taylor_sidelobe_db)
        t_last = raw.t0 + (raw.fast_time.size - 1) / raw.sampling_rate
        cal = calibration_at(points, self.track, tx_ant, rx_ant, raw.transmit_power,
                             raw.carrier, self.window, e_chi,
                             delay_window=(raw.t0, t_last) if window_cut else None)
        return cal, e_chi


def focus_points(source, points, config: ImageConfig | None = None, *,
                 backend: str = "drjit") -> tuple[NDArray[np.complex128], NDArray[np.float64]]:
    """Calibrated image values at arbitrary points (impulse-response cuts, checks).

    Parameters
    ----------
    source : path or xarray.Dataset
        The raw dataset.
    points : array_like (P, 3)
        Positions [m].
    config : ImageConfig, optional
        Processing parameters (its grid fields are ignored).
    backend : {'drjit', 'numpy'}

    Returns
    -------
    image : ndarray (C, P) complex
        s = I / K [m] (eqs B2, K2), calibration evaluated at each point (no interpolation).
    area : ndarray (P,)
        A_eff [m^2] (eq K3): sigma0 = |s|^2 / A_eff.
    """
    import xarray as xr

    cfg = ImageConfig() if config is None else config
    own = not isinstance(source, xr.Dataset)
    ds = xr.open_dataset(source, engine="h5netcdf") if own else source
    try:
        proc = _Processor(RawData(ds), cfg, backend)
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        acc, _ = proc.backproject(pts)
        cal, _ = proc.calibration(pts)
    finally:
        if own:
            ds.close()
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(cal.gain > 0, acc / cal.gain, np.nan + 0j), cal.area


def _focus(raw: RawData, cfg: ImageConfig, backend: str, block_pulses: int, timings: dict,
           progress: bool, source: str):
    """Focus ``raw`` on the image grid of ``cfg``: :func:`focus` after its checks.

    The steps, each its own function: the backprojection of every pulse block onto the
    pixels (:meth:`_Processor.backproject`, eqs B1-B4); the calibration maps K and
    K^2 A_eff on the grid's nodes, interpolated to the pixels (:func:`_calibration_maps`,
    eqs K1-K3); the calibrated products (:func:`_products`: image, sigma0, A_eff,
    coverage, validity, Pauli powers, filtered and multilooked sigma0); the truth on the
    grid (:func:`seaecho.imaging.truth.truth_on_grid`); the attributes
    (:func:`_image_attrs`). ``timings`` receives the seconds of each step, the pixel and
    pulse counts and the pixel-pulse rate; ``source`` is the raw file's name (an
    attribute).
    """
    import xarray as xr

    from .truth import truth_on_grid

    proc = _Processor(raw, cfg, backend)
    pixel = cfg.pixel_m if cfg.pixel_m is not None else C0 / (8.0 * raw.bandwidth)
    extent = cfg.extent_m if cfg.extent_m is not None else raw.default_extent()
    grid = ImageGrid.from_extent(extent, pixel, cfg.height_m)
    points = grid.points()
    acc, wsum = proc.backproject(points, block_pulses, timings, progress)
    t = time.perf_counter()
    gain, q, inside, g0, e_chi = _calibration_maps(proc, grid, wsum)
    t_cal = time.perf_counter() - t
    t = time.perf_counter()
    coords, data = _products(raw, cfg, grid, acc, gain, q, inside, g0)
    truth, truth_attrs = truth_on_grid(raw.ds, grid.x, grid.y, raw.channels)
    data.update(truth)
    if "ship_track" in data:
        coords["xy"] = ("xy", np.array(["x", "y"]))
    for name in ("tx_position", "rx_position"):
        data[f"{name}_used"] = (("pulse", "xyz"), getattr(proc.track, name[:2]),
                                {"units": "m", "long_name": f"{name} of the {cfg.track} "
                                 "track, used by the processor"})
    attrs = _image_attrs(raw, cfg, proc, source, pixel, extent, e_chi)
    attrs.update(truth_attrs)
    out = xr.Dataset(data, coords=coords, attrs=attrs)
    t_prod = time.perf_counter() - t
    n_pp = points.shape[0] * raw.n_pulses
    t_bp = timings["backprojection"]
    timings.update(calibration=t_cal, products=t_prod, pixels=points.shape[0],
                   pulses=raw.n_pulses, channels=len(raw.channels),
                   pixel_pulses_per_s=n_pp / t_bp if t_bp > 0 else np.inf)
    return out


def _calibration_maps(proc: _Processor, grid: ImageGrid, wsum: NDArray
                      ) -> tuple[NDArray, NDArray, NDArray, float, float]:
    """Calibration (eqs K1-K3) on the node grid, interpolated to the pixels.

    Returns K [sqrt(W) / m] and K^2 A_eff / g0^2 at the pixels, the fraction of each
    pixel's weight inside the receive window, the scale g0 (a power of two near the
    largest K) and the compressed pulse's energy E_chi [s]. The receive window cuts K
    sharply, which no interpolation follows: the nodes ignore it and each pixel's K is
    scaled by the fraction of its weight inside the window (exact where the window covers
    the pixel's whole aperture, the valid pixels).
    """
    nodes = grid.nodes()
    cal, e_chi = proc.calibration(nodes.points(), window_cut=False)
    if not np.isfinite(cal.area).any():
        import warnings

        from ..warnings import SamplingWarning

        warnings.warn("the aperture does not turn over the image (platforms at rest or "
                      "one pulse): no azimuth resolution, so sigma0 (eq K3) is undefined; "
                      "the calibrated image (RCS) is still given", SamplingWarning,
                      stacklevel=4)
    # K^2 A_eff (smooth), over g0^2, g0 ~ the largest K: a 5e-324 W transmitter's K^2
    # (1e-340) underflowed to 0, and sigma0 with it
    g0 = _power_of_two_scale(cal.gain)
    q_nodes = np.nan_to_num(cal.area * (cal.gain / g0) ** 2, nan=0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        inside = np.where(wsum[0] > 0, wsum[1] / wsum[0], 0.0).reshape(grid.shape)
    gain = np.maximum(_interpolate(nodes, cal.gain, grid), 0.0) * inside
    q = np.maximum(_interpolate(nodes, q_nodes, grid), 0.0) * inside
    return gain, q, inside, g0, e_chi


def _products(raw: RawData, cfg: ImageConfig, grid: ImageGrid, acc: NDArray, gain: NDArray,
              q: NDArray, inside: NDArray, g0: float) -> tuple[dict, dict]:
    """The image dataset's coordinates and calibrated variables (no truth yet): the image
    s = I / K, sigma0 = |I|^2 / (K^2 A_eff), K, A_eff, coverage, the fraction inside the
    window, the validity mask, the Pauli powers, and the filtered and multilooked sigma0
    that ``cfg`` asks for. ``acc`` holds the backprojected sums I (channel, pixel)."""
    from .speckle import PAULI_NAMES, multilook, pauli_powers, speckle_filter

    n_c = len(raw.channels)
    k_max = float(gain.max()) if gain.size else 0.0
    coverage = gain / k_max if k_max > 0 else np.zeros_like(gain)
    valid = (coverage >= MIN_COVERAGE) & (inside >= MIN_INSIDE)
    img = acc.reshape((n_c,) + grid.shape)
    nodata = ~valid
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        s = _calibrated(np.where(gain > 0, img / gain, np.nan + 0j), nodata)
        # ratios before squares: a finite sigma0 or A_eff does not overflow on the way
        sigma0 = _calibrated(np.where(q > 0, (np.abs(img) / g0 / np.sqrt(q)) ** 2, np.nan),
                             nodata)
        # A_eff is undefined (NaN) where sigma0 is: no pulse weighted, or an aperture that
        # does not turn (q = 0); a 0 here made the Pauli powers / A_eff infinite
        area = _calibrated(np.where((gain > 0) & (q > 0), (np.sqrt(q) / (gain / g0)) ** 2,
                                    np.nan), nodata)
    coords = {
        "channel": ("channel", np.array(raw.channels)),
        "x": ("x", grid.x, {"units": "m", "long_name": "pixel centre, east"}),
        "y": ("y", grid.y, {"units": "m", "long_name": "pixel centre, north"}),
        "xyz": ("xyz", np.array(["x", "y", "z"])),
        "polarisation": ("polarisation", np.array(["HH", "HV", "VH", "VV"])),
    }
    data = {
        "image": (("channel", "y", "x"), _calibrated(s),
                  {"units": "m", "long_name": "calibrated complex image s = I / K: |s|^2 "
                   "is the RCS sigma_mn at a point target's peak"}),
        "sigma0": (("channel", "y", "x"), _calibrated(sigma0),
                   {"units": "m2 m-2", "long_name": "|I|^2 / (K^2 A_eff): the mean over a "
                    "distributed target is its sigma0"}),
        "gain": (("y", "x"), _calibrated(gain),
                 {"units": "sqrt(W) m-1", "long_name": "K = sum_p w_p A_p (eq K2)"}),
        "resolution_area": (("y", "x"), _calibrated(area),
                            {"units": "m2", "long_name": "A_eff (eq K3): integral of the "
                             "squared normalised impulse response"}),
        "coverage": (("y", "x"), _single(coverage),
                     {"units": "1", "long_name": "K / max K"}),
        "inside_window": (("y", "x"), _single(inside),
                          {"units": "1", "long_name": "fraction of the weight sum_p w_p "
                           "whose echo is inside the receive window"}),
        "valid": (("y", "x"), valid.astype(np.uint8),
                  {"units": "1", "long_name": f"coverage >= {MIN_COVERAGE} and "
                   f"inside_window >= {MIN_INSIDE}"}),
    }
    chans = dict(zip(raw.channels, s, strict=True))
    with np.errstate(over="ignore"):  # squares past 1e308 at no-data pixels: NaN below
        pauli = pauli_powers(chans)
    if pauli is not None:
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            pauli = _calibrated(pauli / area[None], nodata)
        coords["component"] = ("component", np.array(PAULI_NAMES))
        data["pauli"] = (("component", "y", "x"), _calibrated(pauli),
                         {"units": "m2 m-2", "long_name": "Pauli powers (|HH-VV|^2, "
                          "|HV+VH|^2, |HH+VV|^2) / 2 in sigma0 units"})
    if cfg.speckle_filter != "none":
        stack = np.nan_to_num(sigma0)
        data["sigma0_filtered"] = (
            ("channel", "y", "x"),
            _calibrated(speckle_filter(stack, cfg.speckle_filter, cfg.filter_size), nodata),
            {"units": "m2 m-2", "long_name": f"sigma0, {cfg.speckle_filter} filter"})
        if pauli is not None:
            data["pauli_filtered"] = (
                ("component", "y", "x"),
                _calibrated(speckle_filter(np.nan_to_num(pauli), cfg.speckle_filter,
                                           cfg.filter_size), nodata),
                {"units": "m2 m-2", "long_name": f"Pauli powers, {cfg.speckle_filter} "
                 "filter"})
    if cfg.looks != (1, 1):
        ly, lx = cfg.looks
        coords["y_look"] = ("y_look", multilook(grid.y[None, :], (1, ly))[0],
                            {"units": "m", "long_name": "centre of the look block"})
        coords["x_look"] = ("x_look", multilook(grid.x[None, :], (1, lx))[0],
                            {"units": "m", "long_name": "centre of the look block"})
        data["sigma0_multilook"] = (("channel", "y_look", "x_look"),
                                    _calibrated(multilook(np.nan_to_num(sigma0), cfg.looks),
                                                multilook(nodata[None], cfg.looks) > 0),
                                    {"units": "m2 m-2", "long_name": f"sigma0, {ly} x {lx} "
                                     "looks (y, x)"})
    return coords, data


def _image_attrs(raw: RawData, cfg: ImageConfig, proc: _Processor, source: str,
                 pixel: float, extent, e_chi: float) -> dict:
    """The image dataset's attributes: provenance, the processing and calibration
    parameters, the formulas (eqs B1-B4, K1-K3)."""
    from .. import __version__

    window, weighting = proc.window, proc.weighting
    attrs = {
        "title": "seaecho SAR image (time-domain backprojection)",
        "seaecho_version": __version__,
        "source": os.path.basename(source) if source else "",
        "scene_json": raw.ds.attrs.get("scene_json", ""),  # a record, not read
        "image_json": json.dumps(cfg.model_dump(mode="json"), sort_keys=True),
        "track": cfg.track,
        "pixel_m": float(pixel),
        "extent_m": np.array(extent, dtype=float),
        "height_m": float(cfg.height_m),
        "azimuth_window": window.name,
        "doppler_bandwidth_hz": float(window.bandwidth),
        "range_weighting": weighting,
        "upsample": int(cfg.upsample),
        "carrier_frequency_hz": raw.carrier,
        "prf_hz": raw.prf,
        "n_pulses": raw.n_pulses,
        "compressed_pulse_energy_s": e_chi,
        "calibration": "image s = I / K, K = sum_p w_p A_p, A_p = sqrt(P_t G_t G_r) lambda / "
                       "((4 pi)^1.5 r_t r_r): |s|^2 = RCS at a point target's peak [m^2]; "
                       "sigma0 = |I|^2 / (K^2 A_eff), A_eff = E_chi sum_p (w_p A_p)^2 / "
                       "(f_c |g_p x dg_p/dp|) / K^2 (docs/imaging.md, eqs K1-K3)",
        "backprojection": "I(x) = sum_p w_p(x) y_p(tau_p(x)) exp(+j 2 pi f_c tau_p(x)), "
                          "w_p(x) = W((f_D - f_c,p) / B_a) (docs/imaging.md, eqs B1-B4)",
        "Conventions": "CF-1.8",
    }
    return attrs
