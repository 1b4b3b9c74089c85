"""Ground truth of a raw dataset brought onto an image grid.

Everything here is read from the raw dataset's variables (``docs/radar.md``, section 7):
the per-facet sigma_mn map of the sigma-map pulse (``sigma0``), the surface and wake
elevations, the turbulent wake mask, the ship track and the point targets. On the image
grid (nearest cell; NaN / 0 outside the sea tile):

- ``sigma0_truth(channel, y, x)``: the cell-mean sigma_mn x visibility of the facets;
- ``turbulent_wake``: the dataset's turbulent-wake mask (Bragg damping, dark in images);
- ``kelvin_wake``: where the Kelvin wake's local amplitude exceeds the sea's rms height.
  The local amplitude is sqrt(2 <z_w^2>), <.> a Gaussian average of standard deviation
  a quarter of the transverse wavelength 2 pi V^2 / g (:func:`seaecho.wake.michell.
  transverse_wavelength`, V from the ship's track; so that it follows the envelope of
  the divergent waves, not their crests); the sea's rms height is that of elevation minus
  wake elevation. Inside it and outside the turbulent wake are the wake arms. A run of
  one pulse does not give the speed: no arms are marked;
- ``open_sea``: inside the tile, where the Kelvin amplitude is below a tenth of the sea's
  rms height (with an unknown speed: the wake elevation itself) and outside the turbulent
  wake: the reference for sea levels;
- ``tile``: inside the simulated sea tile.

The ship's position is that at the time of the sea surface the echoes were computed on
(the first pulse of the sigma-map pulse's block of ``sea_update_pulses``); it is where the
wake is.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..wake.michell import transverse_wavelength

__all__ = ["surface_time_index", "truth_on_grid"]


def surface_time_index(raw) -> int:
    """Index of the pulse whose emission time is the sea surface's time (held sea)."""
    block = int(raw.attrs.get("sea_update_pulses", 1))
    p = int(raw.attrs.get("sigma_map_pulse", 0))
    return (p // block) * block


def _nearest_index(centres: NDArray, values: NDArray) -> tuple[NDArray, NDArray]:
    """Index of the cell of `centres` (uniform) nearest to each value and an inside mask."""
    d = centres[1] - centres[0]
    k = np.rint((values - centres[0]) / d).astype(np.int64)
    inside = (values >= centres[0] - 0.5 * d) & (values <= centres[-1] + 0.5 * d)
    return np.clip(k, 0, centres.size - 1), inside


def truth_on_grid(raw, x: NDArray, y: NDArray, channels: list[str]) -> tuple[dict, dict]:
    """Ground-truth variables of a raw dataset on the image grid.

    Parameters
    ----------
    raw : xarray.Dataset
        The raw dataset of ``seaecho run``.
    x, y : ndarray
        Pixel centres [m].
    channels : list of str
        Image channel names.

    Returns
    -------
    data : dict
        xarray variable tuples for the image dataset.
    attrs : dict
        Scalar truth (ship position, wake parameters) for its attributes.
    """
    data, attrs = {}, {}
    if "target_position" in raw:
        data["target_position"] = (("target", "xyz"), raw["target_position"].values,
                                   {"units": "m", "long_name": "target position at t = 0"})
        data["target_velocity"] = (("target", "xyz"), raw["target_velocity"].values,
                                   {"units": "m s-1"})
        data["target_scattering"] = (("target", "polarisation"),
                                     raw["target_scattering"].values,
                                     {"units": "m", "long_name": "s_mn, |s|^2 = RCS"})
    if "sigma0" not in raw:
        return data, attrs
    xc, yc = raw["x_cell"].values, raw["y_cell"].values
    ix, in_x = _nearest_index(xc, x)
    iy, in_y = _nearest_index(yc, y)
    tile = in_y[:, None] & in_x[None, :]
    data["tile"] = (("y", "x"), tile.astype(np.uint8),
                    {"units": "1", "long_name": "inside the simulated sea tile"})
    pol = [str(p) for p in raw["polarisation"].values]
    s0 = raw["sigma0"].values
    truth = np.full((len(channels), y.size, x.size), np.nan)
    for k, name in enumerate(channels):
        if name in pol:
            truth[k] = np.where(tile, s0[pol.index(name)][np.ix_(iy, ix)], np.nan)
    # float64, as the raw file's map: a float32 copy overflowed to Inf beyond 3.4e38
    data["sigma0_truth"] = (("channel", "y", "x"), truth,
                            {"units": "m2 m-2", "long_name": "cell-mean sigma_mn x visibility "
                             "of the facets (sigma-map pulse), nearest cell"})
    # Node grids (elevation, wake) have the cells' spacing; nodes are x_cell - dx/2
    xn, yn = raw["x"].values, raw["y"].values
    jx, _ = _nearest_index(xn, x)
    jy, _ = _nearest_index(yn, y)
    elev = raw["elevation"].values
    wake = raw["wake_elevation"].values
    turbulent = raw["wake_mask"].values
    sea_rms = float(np.std(elev - wake))
    attrs["sea_rms_height_m"] = sea_rms
    data["turbulent_wake"] = (("y", "x"), np.where(tile, turbulent[np.ix_(jy, jx)] > 0.5,
                                                   False).astype(np.uint8),
                              {"units": "1", "long_name": "turbulent wake (Bragg damped)"})
    kelvin = np.zeros(tile.shape, dtype=bool)
    speed = _ship_speed(raw) if "ship_position" in raw else 0.0
    if np.any(wake != 0) and speed > 0:
        from scipy.ndimage import gaussian_filter

        lam_t = transverse_wavelength(speed)
        dx = float(xn[1] - xn[0])
        amp = np.sqrt(2.0 * gaussian_filter(wake * wake, 0.25 * lam_t / dx, mode="nearest"))
        kelvin = np.where(tile, amp[np.ix_(jy, jx)] > sea_rms, False)
        quiet = amp[np.ix_(jy, jx)] < 0.1 * sea_rms
        attrs["kelvin_transverse_wavelength_m"] = lam_t
    elif np.any(wake != 0):
        # the track does not give the speed (one pulse): the arms are not located, and
        # the open sea is where the wake's own elevation is below a tenth of the sea's
        quiet = np.abs(wake[np.ix_(jy, jx)]) < 0.1 * sea_rms
    else:
        quiet = np.ones(tile.shape, dtype=bool)
    turb = data["turbulent_wake"][1].astype(bool)
    data["kelvin_wake"] = (("y", "x"), (kelvin & ~turb).astype(np.uint8),
                           {"units": "1", "long_name": "wake arms: Kelvin wake amplitude "
                            "above the sea's rms height, outside the turbulent wake"})
    data["open_sea"] = (("y", "x"), (tile & quiet & ~turb).astype(np.uint8),
                        {"units": "1", "long_name": "sea without wake (Kelvin amplitude "
                         "below a tenth of the sea's rms height)"})
    if "ship_position" in raw:
        track = raw["ship_position"].values
        k = surface_time_index(raw)
        data["ship_track"] = (("pulse", "xy"), track,
                              {"units": "m", "long_name": "hull centre (x, y) per pulse"})
        attrs["ship_x_m"], attrs["ship_y_m"] = (float(v) for v in track[k])
        attrs["ship_time_s"] = float(raw["time"].values[k])
    return data, attrs


def _ship_speed(raw) -> float:
    """Ship speed [m/s] from its track (0 if it does not move)."""
    track = raw["ship_position"].values
    t = raw["time"].values
    if track.shape[0] < 2 or t[-1] == t[0]:
        return 0.0
    return float(np.linalg.norm(track[-1] - track[0]) / (t[-1] - t[0]))
