"""The Doppler product of a run: range-Doppler maps, Doppler spectra and their moments.

:func:`doppler_dataset` applies :mod:`seaecho.processing.doppler` (eqs DP1-DP2) to the
``compressed`` pulses of a dataset written by ``seaecho run``;
:func:`seaecho.plotting.doppler.doppler_figure` draws it. ``seaecho doppler RAW.nc -o
OUT.nc`` writes both.
"""

from __future__ import annotations

import numpy as np

from ..processing.doppler import (
    autocorrelation,
    clutter_cells,
    doppler_moments,
    doppler_spectrum,
    range_doppler,
)


def doppler_dataset(raw, cpi: int | None = None, window: str = "hann",
                    floor_db: float = 20.0, max_lag: int | None = None):
    """Range-Doppler product of a run's dataset.

    Parameters
    ----------
    raw : xarray.Dataset
        Written by ``seaecho run`` (needs ``compressed``, the ``pulse``, ``channel`` and
        ``range`` coordinates and the ``prf_hz`` and ``wavelength_m`` attributes).
    cpi : int, optional
        Pulses per coherent processing interval (default all).
    window : {"hann", "hamming", "none"}
        Taper over the pulses.
    floor_db : float
        Range cells within this many dB of the strongest make the clutter spectrum [dB].
    max_lag : int, optional
        Lags of the temporal autocorrelation [pulses] (default min(64, P - 1)).

    Returns
    -------
    xarray.Dataset
        ``range_doppler`` (channel, doppler, range) [W/Hz], ``doppler_spectrum``
        (channel, doppler) [W/Hz], ``doppler_centroid`` and ``doppler_width`` (channel)
        [Hz], ``autocorrelation`` (channel, lag) complex, ``clutter_cell`` (range) bool;
        the Doppler coordinate also as a line-of-sight velocity
        ``lambda f / 2`` [m/s] (monostatic meaning); attributes of the run kept.
    """
    import xarray as xr

    missing = [n for n in ("compressed",) if n not in raw]
    missing += [a for a in ("prf_hz", "wavelength_m") if a not in raw.attrs]
    if missing:
        raise ValueError(f"not a dataset of `seaecho run`: missing {', '.join(missing)}")
    x = np.asarray(raw["compressed"].values)
    prf = float(raw.attrs["prf_hz"])
    lam = float(raw.attrs["wavelength_m"])
    freq, psd = range_doppler(x, prf, cpi, window)
    cells = clutter_cells(psd, floor_db)
    spec = doppler_spectrum(freq, psd, cells)
    cen, wid = doppler_moments(freq, spec)
    lags = min(64, x.shape[0] - 1) if max_lag is None else int(max_lag)
    rho = autocorrelation(x, lags, cells)
    attrs = {k: v for k, v in raw.attrs.items()}
    attrs.update(doppler_cpi_pulses=int(len(freq)), doppler_window=window,
                 doppler_floor_db=float(floor_db),
                 doppler_definition="power spectral density over pulses, Welch average of "
                 "half-overlapping CPIs (docs/dynamics.md, eq DP1); f > 0: approaching")
    ds = xr.Dataset(
        {"range_doppler": (("channel", "doppler", "range"), psd,
                           {"units": "W Hz-1", "long_name": "Doppler power spectral density "
                            "per range cell"}),
         "doppler_spectrum": (("channel", "doppler"), spec,
                              {"units": "W Hz-1", "long_name": "clutter Doppler spectrum "
                               "(sum over the clutter cells)"}),
         "doppler_centroid": (("channel",), cen, {"units": "Hz", "long_name": "first "
                                                  "moment of doppler_spectrum"}),
         "doppler_width": (("channel",), wid, {"units": "Hz", "long_name": "rms width of "
                                               "doppler_spectrum"}),
         "autocorrelation": (("channel", "lag"), rho,
                             {"units": "1", "long_name": "normalised temporal "
                              "autocorrelation of the clutter cells"}),
         "clutter_cell": (("range",), cells, {"long_name": "range cell in the clutter "
                                              "spectrum"})},
        coords={"channel": raw["channel"].values,
                "doppler": ("doppler", freq, {"units": "Hz"}),
                "velocity": ("doppler", 0.5 * lam * freq,
                             {"units": "m s-1", "long_name": "lambda f / 2 (monostatic "
                              "line-of-sight velocity, towards the radar > 0)"}),
                "range": ("range", np.asarray(raw["range"].values), {"units": "m"}),
                "lag": ("lag", np.arange(lags + 1), {"units": "pulse"}),
                "lag_time": ("lag", np.arange(lags + 1) / prf, {"units": "s"})},
        attrs=attrs)
    return ds


__all__ = ["doppler_dataset"]
