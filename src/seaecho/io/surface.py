"""The surface dataset that ``seaecho surface`` writes.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from tqdm.auto import tqdm

from ..ocean.twoscale import height_variance

#: Upper end of the band whose height variance the dataset reports as unresolved
#: [rad/m] (0.6 mm waves: beyond any radar's Bragg wavenumber, so "all of it").
_K_TOP = 1.0e4


def surface_dataset(sea, times: Sequence[float], attrs: dict | None = None,
                    name: str = "", progress: bool = True) -> xr.Dataset:
    """Sea + wake at ``times`` [s] as a self-describing dataset.

    Dimensions ``time``, ``y``, ``x`` (SI coordinates); variables ``elevation`` (sea +
    wake), ``wake_elevation``, ``wake_mask``, ``slope_x``, ``slope_y``, ``velocity_x``,
    ``velocity_y``, ``velocity_z``, and the ship's track ``ship_x``, ``ship_y`` when there is
    a ship. Attributes carry ``attrs`` (the full scene as JSON and the package version,
    ``seaecho.build.scene_attrs``) and the sea's statistics (resolved variance, expected
    and realised significant wave height).

    Parameters
    ----------
    sea : seaecho.sea.Sea
        The sea (``seaecho.build.build_sea(scene)``).
    times : sequence of float
        Times [s].
    attrs : dict, optional
        Attributes saying how the file was made.
    name : str
        The scene's name.
    progress : bool
        Show a progress bar.
    """
    times = np.asarray(times, dtype=np.float64)
    ny, nx = sea.y.size, sea.x.size
    names = ("elevation", "wake_elevation", "wake_mask", "slope_x", "slope_y",
             "velocity_x", "velocity_y", "velocity_z")
    data = {n: np.empty((times.size, ny, nx)) for n in names}
    for i, t in enumerate(tqdm(times, desc="surface", unit="step", delay=1.0,
                               disable=not progress)):
        st = sea.state(float(t))
        data["elevation"][i] = st.elevation
        data["wake_elevation"][i] = st.wake_elevation
        data["wake_mask"][i] = st.wake_mask
        data["slope_x"][i] = st.slope_x
        data["slope_y"][i] = st.slope_y
        data["velocity_x"][i] = st.velocity[..., 0]
        data["velocity_y"][i] = st.velocity[..., 1]
        data["velocity_z"][i] = st.velocity[..., 2]
    meta = {
        "elevation": ("m", "sea surface elevation above mean sea level, sea + wake"),
        "wake_elevation": ("m", "Kelvin wake elevation alone"),
        "wake_mask": ("1", "wake's Bragg spectrum change d (the spectrum times 1 - d): 0 none, "
                      "1 short waves fully damped, < 0 narrow-V Bragg waves added"),
        "slope_x": ("1", "surface slope dz/dx, sea + wake"),
        "slope_y": ("1", "surface slope dz/dy, sea + wake"),
        "velocity_x": ("m s-1", "surface particle velocity along x (linear wave theory)"),
        "velocity_y": ("m s-1", "surface particle velocity along y (linear wave theory)"),
        "velocity_z": ("m s-1", "vertical surface velocity dz/dt, sea + wake"),
    }
    dims = ("time", "y", "x")
    ds = xr.Dataset(
        {n: (dims, data[n], {"units": meta[n][0], "long_name": meta[n][1]}) for n in names},
        coords={
            "time": ("time", times, {"units": "s", "long_name": "time since scene start"}),
            "y": ("y", sea.y, {"units": "m", "long_name": "northing (cell centre)"}),
            "x": ("x", sea.x, {"units": "m", "long_name": "easting (cell centre)"}),
        },
    )
    if sea.ship is not None:
        track = np.array([sea.ship.position(float(t)) for t in times]).reshape(-1, 2)
        ds["ship_x"] = ("time", track[:, 0], {"units": "m", "long_name": "ship hull centre x"})
        ds["ship_y"] = ("time", track[:, 1], {"units": "m", "long_name": "ship hull centre y"})
    surf = sea.surface
    k_cut = np.pi / max(surf.dx, surf.dy)
    ds.attrs.update(attrs or {})
    ds.attrs.update({
        "title": "seaecho sea surface",
        "scene_name": name,
        "resolved_variance_m2": surf.resolved_variance,
        "expected_hs_resolved_m": 4.0 * np.sqrt(surf.resolved_variance),
        "realised_hs_m": 4.0 * float(np.std(data["elevation"][0] - data["wake_elevation"][0])),
        "grid_cutoff_wavenumber_rad_m": k_cut,
        "unresolved_height_variance_m2": height_variance(sea.spectrum, k_cut, _K_TOP),
        "dispersion": "omega^2 = (g K + tau/rho K^3) tanh(K d), paper eq 15 with capillarity",
        "depth_m": "deep" if surf.depth is None else surf.depth,
    })
    return ds


__all__ = ["surface_dataset"]
