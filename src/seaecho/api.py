"""seaecho's Python API: scenes in, xarray objects out.

The functions behind the ``seaecho`` command line, for notebooks and scripts. Each takes a
scene (or plain values) and returns an :class:`xarray.Dataset` or
:class:`xarray.DataArray` with SI coordinates and the attributes the command line writes;
the command line parses its arguments, calls these functions and writes their results.

============================  ===============================  =========================
function                      gives                            command line
============================  ===============================  =========================
:func:`load_scene`            :class:`Scene` from a TOML file  ``seaecho check``
:func:`parse_scene`           :class:`Scene` from text / dict
:func:`with_overrides`        :class:`Scene` with fields set   ``--set NAME=VALUE``
:func:`simulate`              raw + compressed pulses          ``seaecho run``
:func:`surface`               sea + wake heights               ``seaecho surface``
:func:`trace`                 facets seen from Tx and Rx       ``seaecho trace``
:func:`compare`               ray-traced vs analytic facets    ``seaecho compare``
:func:`sigma`                 mean-plane sigma_mn of the sea   ``seaecho sigma``
:func:`wave_spectrum`         wave spectrum S(K), H_s, peak
:func:`permittivity`          sea-water permittivity           ``seaecho permittivity``
:func:`image`                 focused SAR image                ``seaecho image``
:func:`image_measures`        the paper's image measures       ``seaecho image``
:func:`figures`               the command line's PNG figures   ``run``, ``image``
:func:`detect`                CFAR detections, their truth     ``seaecho detect``
:func:`score`                 P_D, false alarms, P_FA          ``seaecho score``
:func:`roc`                   ROC curve of any detector
:func:`stonesoup_readers`     Stone Soup readers of an export  ``detect --stonesoup``
:func:`save`, :func:`open_dataset`  netCDF files (complex variables included)
============================  ===============================  =========================

Example::

    import seaecho
    scene = seaecho.load_scene("scenes/paper_sim1_bistatic_64m.toml")
    scene = seaecho.with_overrides(scene, {"sea.wind_speed_m_s": 8.0})
    ds = seaecho.simulate(scene)
    abs(ds.compressed).isel(pulse=0).plot.line(x="range", hue="channel")

Angles are given in degrees (names ending ``_deg``), everything else in SI units (names
ending ``_hz``, ``_m``, ``_s``...). Bad input raises :class:`seaecho.config.SceneError`
(a ``ValueError``) naming the field or parameter, the value and what is allowed.
Importing this module is cheap (pydantic and the scene schema): numpy, xarray and the
simulation stages are imported by the functions that need them.

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .config import Scene, SceneError, load_scene, parse_scene, with_overrides
from .summary import SceneSummary, format_bytes, scene_summary

if TYPE_CHECKING:  # pragma: no cover
    import xarray as xr
    from numpy.typing import ArrayLike

    from .config.image import ImageConfig

__all__ = [
    "Scene",
    "SceneSummary",
    "compare",
    "detect",
    "figures",
    "image",
    "image_config",
    "image_measures",
    "load_scene",
    "open_dataset",
    "parse_scene",
    "permittivity",
    "roc",
    "ppi",
    "save",
    "scene_summary",
    "score",
    "sigma",
    "simulate",
    "stonesoup_readers",
    "surface",
    "trace",
    "wave_spectrum",
    "with_overrides",
]

PathLike = str | os.PathLike

#: Frequencies ``sigma`` accepts [Hz] (the sea-water and spectrum models' validated span).
SIGMA_FREQUENCY_HZ = (0.1e9, 100.0e9)
#: Wind speeds U19.5 ``sigma`` accepts [m/s].
SIGMA_WIND_M_S = (0.0, 40.0)
#: Frequencies ``permittivity`` accepts [Hz] (exclusive lower bound).
PERMITTIVITY_FREQUENCY_HZ = (0.0, 1.0e12)
#: Defaults of :func:`sigma` without a scene: the paper's Fig. 3 sea (10 GHz,
#: U19.5 = 4.53 m/s, 20 degC, 35 psu) with the Elfouhaily spectrum.
SIGMA_DEFAULTS = {"frequency_hz": 10.0e9, "wind_speed_m_s": 4.53, "wind_direction_deg": 0.0,
                  "spectrum": "elfouhaily", "spreading": "elfouhaily", "temperature_c": 20.0,
                  "salinity_psu": 35.0}
#: Fraction of the available memory an in-memory :func:`simulate` may take.
MEMORY_FRACTION = 0.5


# ------------------------------------------------------------------------------ scenes
def _base_dir(scene, base_dir: PathLike | None) -> Path:
    if base_dir is not None:
        return Path(base_dir)
    b = getattr(scene, "base_dir", None)
    return b if b is not None else Path(".")


def _scene(scene) -> Scene:
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, str | os.PathLike):
        raise SceneError(f"scene = {os.fspath(scene)!r}: expected a Scene; read a file with "
                         "seaecho.load_scene")
    raise SceneError(f"scene: expected a Scene (seaecho.load_scene / parse_scene), got "
                     f"{type(scene).__name__}")


# -------------------------------------------------------------------------- simulation
def first_pulses(scene: Scene, n: int) -> Scene:
    """The scene limited to its first ``n`` pulses, the sigma-map pulse kept inside
    (``simulate(pulses=n)``, ``--pulses N``); ``[scattering] sea_motion = "auto"`` is
    resolved on the whole run (:func:`seaecho.build.sea_motion`), so that these are the
    run's first pulses."""
    from .build import sea_motion

    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise SceneError(f"pulses = {n!r}: must be an integer >= 1")
    n = min(n, scene.radar.n_pulses)
    radar = scene.radar.model_copy(update={
        "n_pulses": n, "sigma_map_pulse": min(scene.radar.sigma_map_pulse, n - 1)})
    scattering = scene.scattering.model_copy(update={"sea_motion": sea_motion(scene)})
    return scene.model_copy(update={"radar": radar, "scattering": scattering})


def _available_memory() -> float | None:
    """Memory the system can give without swapping [bytes] (``MemAvailable``), or None."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024.0
    except OSError:
        pass
    try:
        return float(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return None


def simulate(scene: Scene, *, path: PathLike | None = None, pulses: int | None = None,
             progress: bool = True, base_dir: PathLike | None = None,
             max_memory_bytes: float | None = None, workers: int | None = None,
             scheduler: str | None = None, block_pulses: int | None = None,
             resume: bool = False) -> xr.Dataset:
    """Simulate the radar echoes of a scene (``seaecho run``).

    Every pulse of ``[radar]``: sea clutter, targets, hull echoes, thermal noise, then
    range compression, through the same code as ``seaecho run``
    (:meth:`seaecho.simulation.Simulation.run` and ``dataset``, :mod:`seaecho.io.run`):
    the same variables, attributes and bytes for the same scene and seed, computed in
    this process or on a Dask cluster (:mod:`seaecho.distributed`).

    Parameters
    ----------
    scene : Scene
        Needs ``[radar]`` and ``[transmitter]``.
    path : path, optional
        Stream the pulses to this netCDF file (atomically, memory bounded by a few
        blocks of pulses) or Zarr store (``*.zarr``, block by block, resumable) and
        return it opened lazily; without it the run is held in memory.
    pulses : int, optional
        Only the first ``pulses`` pulses (a quick look; ``seaecho run --pulses``).
    progress : bool
        Show a progress bar over the pulses.
    base_dir : path, optional
        Folder that ``[[objects]]`` paths start from (default the scene file's folder,
        else the working directory).
    max_memory_bytes : float, optional
        In memory only: the most the run's arrays may take [bytes] (default half the
        memory the system has available).
    workers : int, optional
        Compute the blocks of pulses on a local Dask cluster of this many worker
        processes (``seaecho run --workers``; same bytes as a serial run).
    scheduler : str, optional
        Or on an existing Dask cluster, e.g. ``"tcp://host:8786"`` (``--scheduler``).
    block_pulses : int, optional
        Pulses per block of work and per Zarr chunk (default about 16, aligned with the
        held sea and the occlusion refresh: :func:`seaecho.io.run.block_size`).
    resume : bool
        Zarr ``path`` only: continue an interrupted run of the same scene.

    Returns
    -------
    xarray.Dataset
        ``raw`` and ``compressed`` (pulse, channel, fast_time) complex [sqrt(W)],
        platform tracks, targets, the sea surface and NRCS map of the sigma-map pulse,
        the full scene in ``attrs["scene_json"]`` (:mod:`seaecho.io.run`). With ``path``,
        opened lazily from the file: close it (or use ``with``) when done.

    Raises
    ------
    SceneError
        No ``[radar]`` or ``[transmitter]``, a bad ``pulses``, ``workers``,
        ``block_pulses`` or ``path``, both ``workers`` and ``scheduler``, a scene the
        stages refuse, or (in memory) a run larger than ``max_memory_bytes``.
    seaecho.io.zarr_run.StoreError
        A Zarr ``path`` holds an interrupted run and ``resume`` is not set, or the run
        to continue is of another scene.
    """
    import contextlib

    from .build import build_multistatic, build_radar, build_simulation, check_scene, receiver_scene
    from .io.zarr_run import is_zarr
    from .radar.system import RadarSystem
    from .simulation import Simulation

    scene = _scene(scene)
    label = f"scene '{scene.name}'" if scene.name else "the scene"
    if scene.radar is None or scene.transmitter is None:
        raise SceneError(f"{label}: simulate needs [radar] and [transmitter] sections")
    if pulses is not None:
        scene = first_pulses(scene, pulses)
    for name, value in (("workers", workers), ("block_pulses", block_pulses)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int)
                                  or value < 1):
            raise SceneError(f"{name} = {value!r}: must be an integer >= 1")
    if workers is not None and scheduler is not None:
        raise SceneError(f"workers = {workers}, scheduler = {scheduler!r}: give one of them "
                         "(a local cluster, or an existing one)")
    if path is None:
        if resume:
            raise SceneError("resume = True: needs a Zarr path (*.zarr) to continue")
        try:  # [[receivers]]: the first receiver's window (all have its length)
            radar = RadarSystem(build_radar(receiver_scene(scene, 0) if scene.receivers
                                            else scene))
        except ValueError as exc:
            raise SceneError(f"{label}: {exc}") from None
        _check_fits_in_memory(scene, radar, max_memory_bytes)
    else:
        path = Path(path)
        if str(path.parent) and not path.parent.is_dir():
            raise SceneError(f"path = {os.fspath(path)!r}: directory {path.parent} does not "
                             "exist")
        if resume and not is_zarr(path):
            raise SceneError(f"resume = True: {os.fspath(path)} is not a Zarr store "
                             "(*.zarr); a netCDF run is written atomically and starts over")
    if scene.radar.sea_clutter:
        check_scene(scene)  # SamplingWarning if the tile or the grid is too coarse
    base = _base_dir(scene, base_dir)
    try:
        if scene.receivers:  # one transmitter, several receivers (docs/multistatic.md)
            from .multistatic import MultistaticSimulation

            sim = MultistaticSimulation.from_models(build_multistatic(scene, base))
        else:
            sim = Simulation.from_models(build_simulation(scene, base))
    except ValueError as exc:
        raise SceneError(f"{label}: {exc}") from None
    with contextlib.ExitStack() as stack:
        runner = None
        if workers is not None or scheduler is not None:
            from . import distributed

            client = stack.enter_context(distributed.cluster(workers, scheduler))
            runner = distributed.DaskBlocks(client, distributed.Job.of(scene, base),
                                            block=block_pulses)
        if path is None:
            return sim.dataset(progress=progress, chunk=block_pulses, runner=runner)
        sim.run(path, progress=progress, chunk=block_pulses, resume=resume, runner=runner)
    return open_dataset(path)


def _check_fits_in_memory(scene, radar, limit: float | None) -> None:
    """Refuse an in-memory run whose arrays exceed ``limit`` (default: a fraction of the
    available memory). The arrays are ``raw`` and ``compressed``: pulses x channels x
    samples x 2 x 16 bytes, the receive window's samples being the radar's own."""
    n_p, n_c, n_s = radar.n_pulses, len(radar.channels), radar.window.n_samples
    if scene.receivers:  # every receiver's window has the first one's length
        n_c *= len(scene.receivers)
    need = 32.0 * n_p * n_c * n_s
    if scene.radar.sea_clutter:  # static maps: surface (3), sigma0 (4), visibility
        ny, nx = scene.sea.shape
        need += 8.0 * 8 * nx * ny
    if limit is None:
        avail = _available_memory()
        if avail is None:
            return
        limit, source = MEMORY_FRACTION * avail, (
            f"half of the {format_bytes(avail)} the system has available")
    else:
        if not (isinstance(limit, int | float) and limit > 0):
            raise SceneError(f"max_memory_bytes = {limit!r}: must be a positive number of "
                             "bytes")
        source = "max_memory_bytes"
    if need > limit:
        raise SceneError(
            f"the run holds {n_p} pulses x {n_c} channels x {n_s} samples of raw and "
            f"compressed echoes ({format_bytes(need)}), more than {format_bytes(limit)} "
            f"({source}): stream it to a file with simulate(scene, path='run.nc'), or "
            "simulate fewer pulses (pulses=N)")


def open_dataset(path: PathLike) -> xr.Dataset:
    """Open a seaecho file (run, image, surface, facets) lazily, complex variables
    included (h5netcdf), or a run's Zarr store (``*.zarr``). Close it, or use it in a
    ``with`` block."""
    from .io.run import open_run, quiet_invalid_netcdf

    with quiet_invalid_netcdf():
        return open_run(path)


def save(dataset: xr.Dataset, path: PathLike) -> Path:
    """Write a dataset to netCDF-4 atomically (a temporary file renamed into place), with
    complex variables as HDF5 compounds that :func:`open_dataset` reads back.

    Returns
    -------
    Path
    """
    from .io.dataset import write_dataset_atomic
    from .io.run import quiet_invalid_netcdf

    path = Path(path)
    if str(path.parent) and not path.parent.is_dir():
        raise SceneError(f"path = {os.fspath(path)!r}: directory {path.parent} does not exist")
    guard = None
    if str(dataset.attrs.get("title", "")).startswith("seaecho SAR image"):
        from .checks.guards import check_image

        guard = check_image  # no Inf, NaN only at the undefined pixels
    with quiet_invalid_netcdf():
        return write_dataset_atomic(dataset, path, guard=guard)


# ------------------------------------------------------------------ stages on their own
def surface(scene: Scene, times: ArrayLike | None = None, *,
            progress: bool = False) -> xr.Dataset:
    """The sea surface and ship wake of a scene at given times (``seaecho surface``).

    Parameters
    ----------
    scene : Scene
    times : float or sequence of float, optional
        Times [s] (default ``[run] surface_times_s``).
    progress : bool
        Show a progress bar over the times.

    Returns
    -------
    xarray.Dataset
        ``elevation``, ``wake_elevation``, ``wake_mask``, slopes and velocities on
        (time, y, x), the ship's track, the expected and realised significant wave
        heights in the attributes (:func:`seaecho.io.surface.surface_dataset`).

    Warns
    -----
    SamplingWarning
        The tile does not hold the spectral peak, or the grid is too coarse.
    """
    import numpy as np

    from .build import build_sea, check_scene, scene_attrs
    from .io.surface import surface_dataset

    scene = _scene(scene)
    t = np.atleast_1d(np.asarray(scene.run.surface_times_s if times is None else times,
                                 dtype=np.float64))
    if t.ndim != 1 or t.size == 0 or not np.all(np.isfinite(t)):
        raise SceneError(f"times = {t.tolist()}: need one or more finite times [s]")
    check_scene(scene)
    return surface_dataset(build_sea(scene), t, attrs=scene_attrs(scene), name=scene.name,
                           progress=progress)


@dataclass
class _Geometry:
    """Engine and its sea for :func:`trace` / :func:`compare`."""

    scene: Any
    sea: Any
    engine: Any
    frequency: float | None


def _engine(scene, time: float, *, mode, tx_position, rx_position, variant, frequency_hz,
            base_dir) -> _Geometry:
    from .build import build_engine, build_sea

    scene = _scene(scene)
    if not (isinstance(time, int | float) and math.isfinite(time)):
        raise SceneError(f"time = {time!r}: must be a finite number of seconds")
    if rx_position is not None and tx_position is None:
        raise SceneError("rx_position needs tx_position (the receiver alone has no "
                         "transmitter to go with it)")
    if tx_position is None and scene.transmitter is None:
        raise SceneError("the scene has no [transmitter] section; give tx_position")
    try:
        sea = build_sea(scene)
        engine = build_engine(scene, sea.state, _base_dir(scene, base_dir),
                              frequency=frequency_hz, mode=mode, variant=variant,
                              tx_position=tx_position, rx_position=rx_position)
    except ValueError as exc:
        raise SceneError(str(exc)) from None
    return _Geometry(scene, sea, engine, frequency_hz)


def trace(scene: Scene, time: float = 0.0, *, mode: str | None = None,
          tx_position: ArrayLike | None = None, rx_position: ArrayLike | None = None,
          variant: str | None = None, frequency_hz: float | None = None,
          base_dir: PathLike | None = None) -> xr.Dataset:
    """The sea's facets at one time, seen from the transmitter and the receiver
    (``seaecho trace``).

    Parameters
    ----------
    scene : Scene
    time : float
        Time of the surface and the platforms [s].
    mode : {'raytraced', 'analytic'}, optional
        Facet mode (default ``[tracing] mode``).
    tx_position, rx_position : (3,) array_like, optional
        Fixed positions [m] instead of the scene's platforms (``tx_position`` alone:
        monostatic).
    variant : str, optional
        Mitsuba variant (default ``[tracing] variant``).
    frequency_hz : float, optional
        Carrier [Hz] (default ``[radar]``'s; needed without ``[radar]``): the sea-water
        permittivity and the two-scale split.
    base_dir : path, optional
        Folder of the ``[[objects]]`` paths (default the scene file's).

    Returns
    -------
    xarray.Dataset
        Per-facet arrays on (y_cell, x_cell, triangle): visibility (``lit``, ``seen``,
        ``visibility``), float64 ranges, local angles and basis rotations
        (:func:`seaecho.io.facets.facets_dataset`); the area-weighted fractions
        ``lit_fraction_tx``, ``seen_fraction_rx``, ``visible_fraction`` in the attributes.
    """
    from .build import scene_attrs
    from .io.facets import facets_dataset, visibility_summary

    g = _engine(scene, time, mode=mode, tx_position=tx_position, rx_position=rx_position,
                variant=variant, frequency_hz=frequency_hz, base_dir=base_dir)
    f = g.engine.facets(float(time))
    tx, rx = g.engine.positions(float(time))
    ds = facets_dataset(f, g.sea.x, g.sea.y, tx, rx, attrs=scene_attrs(g.scene))
    ds.attrs.update(visibility_summary(f))
    return ds


def compare(scene: Scene, time: float = 0.0, *, tx_position: ArrayLike | None = None,
            rx_position: ArrayLike | None = None, variant: str | None = None,
            frequency_hz: float | None = None,
            base_dir: PathLike | None = None) -> xr.Dataset:
    """Ray-traced against analytic facets on the same sea and geometry
    (``seaecho compare``).

    Parameters
    ----------
    scene, time, tx_position, rx_position, variant, frequency_hz, base_dir
        As :func:`trace`.

    Returns
    -------
    xarray.Dataset
        On ``mode`` = (raytraced, analytic): cell-mean ``visibility`` (y_cell, x_cell),
        the area-weighted ``lit_fraction_tx``, ``seen_fraction_rx``,
        ``visible_fraction``, and ``sigma_sum`` (polarisation): the sum over facets of
        area x visibility x sigma_mn [m^2] with the simulation's whole per-facet model
        (:func:`seaecho.simulation.facet_sigma0`: the blend, the unresolved-tilt
        average, the breaking zones and the wake's damping), so that its ray-traced
        value divided by the tile's area is the mean ``sigma0`` that ``seaecho run``
        writes for the same sea and geometry. Per facet
        (y_cell, x_cell, triangle), NaN where a mode does not see the facet: the
        differences analytic - ray traced of ``theta_i``, ``theta_s``, ``phi`` [deg]
        and the angle between the two ``normal`` s [deg]. Attribute ``shadowing``: the
        analytic mode's shadowing.
    """
    import numpy as np
    import xarray as xr

    from .build import build_engine, build_sea_model, scene_attrs
    from .conventions import CHANNELS
    from .io.facets import visibility_summary
    from .simulation import breaking_fraction, facet_sigma0, wake_damping

    g = _engine(scene, time, mode="raytraced", tx_position=tx_position,
                rx_position=rx_position, variant=variant, frequency_hz=frequency_hz,
                base_dir=base_dir)
    try:
        sea_model = build_sea_model(g.scene, frequency_hz)
    except ValueError as exc:
        raise SceneError(str(exc)) from None
    analytic = build_engine(g.scene, g.sea.state, _base_dir(g.scene, base_dir),
                            frequency=frequency_hz, mode="analytic", tx_position=tx_position,
                            rx_position=rx_position, sea_model=sea_model)
    st = g.sea.state(float(time))
    ft = g.engine.facets(float(time), state=st)
    fa = analytic.facets(float(time), state=st)
    both = (ft.visibility > 0) & (fa.visibility > 0)
    grid = ft.grid_shape  # (ny - 1, nx - 1, 2)

    def on_grid(a):
        return np.where(both, a, np.nan).reshape(grid)

    cos_n = np.clip(np.einsum("ij,ij->i", ft.normal, fa.normal), -1.0, 1.0)
    facet_dims = ("y_cell", "x_cell", "triangle")
    diffs = {
        "theta_i_difference": fa.theta_i - ft.theta_i,
        "theta_s_difference": fa.theta_s - ft.theta_s,
        "phi_difference": np.angle(np.exp(1j * (fa.phi - ft.phi))),
        "normal_difference": np.arccos(cos_n),
    }
    data = {name: (facet_dims, on_grid(np.degrees(d)),
                   {"units": "deg", "long_name": f"{name.split('_difference')[0]}: analytic "
                    "- ray traced (facets visible in both modes)"})
            for name, d in diffs.items()}
    data["normal_difference"][2]["long_name"] = ("angle between the two modes' normals "
                                                 "(facets visible in both)")
    summaries = [visibility_summary(ft), visibility_summary(fa)]
    for key in summaries[0]:
        data[key] = ("mode", [s[key] for s in summaries], {"units": "1"})
    data["visibility"] = (("mode", "y_cell", "x_cell"),
                          np.stack([ft.cell_mean("visibility"), fa.cell_mean("visibility")]),
                          {"units": "1", "long_name": "lit and seen, cell mean"})

    damping = wake_damping(st)  # the per-facet quantities of the run's held sea
    breaking = (None if sea_model.breaking is None
                else breaking_fraction(sea_model, g.sea, st, ft.area))

    def summed(f):
        sig = facet_sigma0(sea_model, f, damping, breaking,
                           variant=variant or g.scene.tracing.variant)
        return f.area @ sig  # facet_sigma0 includes the visibility

    data["sigma_sum"] = (("mode", "polarisation"), np.stack([summed(ft), summed(fa)]),
                         {"units": "m2", "long_name": "sum over facets of area x "
                          "visibility x sigma_mn"})
    x, y = g.sea.x, g.sea.y
    coords = {"mode": ["raytraced", "analytic"], "polarisation": list(CHANNELS),
              "x_cell": ("x_cell", 0.5 * (x[1:] + x[:-1]), {"units": "m"}),
              "y_cell": ("y_cell", 0.5 * (y[1:] + y[:-1]), {"units": "m"}),
              "triangle": [0, 1]}
    attrs = dict(scene_attrs(g.scene), time_s=float(time), shadowing=analytic.shadowing,
                 title="seaecho: ray-traced against analytic facets")
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _angles(value: ArrayLike, name: str, lo: float, hi: float):
    import numpy as np

    a = np.asarray(value, dtype=np.float64)
    if a.ndim > 1 or a.size == 0:
        raise SceneError(f"{name}: expected a number or a 1-D sequence of angles [deg]")
    if not np.all(np.isfinite(a)) or np.any(a < lo) or np.any(a > hi):
        raise SceneError(f"{name} = {a.tolist()}: values must lie in [{lo:g}, {hi:g}] deg")
    return a


def sigma(model: str = "blend", *, theta_i_deg: ArrayLike = 20.0,
          theta_s_deg: ArrayLike = 30.0, phi_i_deg: ArrayLike = 0.0,
          phi_s_deg: ArrayLike = 0.0, scene: Scene | None = None,
          frequency_hz: float | None = None, wind_speed_m_s: float | None = None,
          wind_direction_deg: float | None = None, spectrum: str | None = None,
          spreading: str | None = None, spreading_s: float | None = None,
          fetch_m: float | None = None, temperature_c: float | None = None,
          salinity_psu: float | None = None,
          permittivity_model: str = "meissner-wentz", slopes: str = "gaussian",
          cut_ratio: float | None = None) -> xr.DataArray:
    """Mean-plane bistatic scattering coefficients sigma_mn of a wind sea
    (``seaecho sigma``; the paper's eqs 7-11 and the models of
    :mod:`seaecho.scattering.models`).

    Each angle is a number or a 1-D sequence; a sequence becomes a dimension of the
    result, a number a scalar coordinate: ``sigma(phi_s_deg=range(0, 181))`` is the
    paper's Fig. 3 cut. Monostatic: ``phi_s_deg = phi_i_deg + 180`` and
    ``theta_s_deg = theta_i_deg``.

    Parameters
    ----------
    model : str
        ``kirchhoff``, ``spm``, ``two-scale``, ``blend`` (eqs 10-11),
        ``two-scale+breaking`` or ``blend+breaking``.
    theta_i_deg, theta_s_deg : float or sequence
        Incidence and scattering angles from the vertical [deg], 0 to 90.
    phi_i_deg, phi_s_deg : float or sequence
        Incidence and scattering azimuths [deg], -360 to 360.
    scene : Scene, optional
        Take the sea state, the water and the carrier from it (the sea parameters
        below must then be left out; ``frequency_hz`` replaces the scene's carrier).
    frequency_hz : float, optional
        Radar frequency [Hz] (default 10 GHz).
    wind_speed_m_s : float, optional
        U19.5 [m/s] (default 4.53, the paper's Fig. 3).
    wind_direction_deg : float, optional
        Direction the wind blows towards, counter-clockwise from +x [deg] (default 0).
    spectrum, spreading : str, optional
        Wave spectrum (``elfouhaily``, ``pierson-moskowitz``, ``jonswap``, ``romeiser``,
        ``kudryavtsev``) and spreading (``elfouhaily``, ``longuet-higgins``, ``romeiser``); default
        Elfouhaily.
    spreading_s : float, optional
        Longuet-Higgins spreading exponent s [-] (default 1, the paper's).
    fetch_m : float, optional
        Fetch [m] (JONSWAP).
    temperature_c, salinity_psu : float, optional
        Sea water [degC], [psu] (default 20, 35).
    permittivity_model : str
        ``meissner-wentz`` or ``klein-swift``.
    slopes : {'gaussian', 'cox-munk'}
        Slope density of the Kirchhoff part.
    cut_ratio : float, optional
        Two-scale split k_cut / k [-] (default 1/3, the split every stage uses).

    Returns
    -------
    xarray.DataArray
        sigma_mn [m^2/m^2], dimensions: the angles given as sequences (``theta_i_deg``,
        ``theta_s_deg``, ``phi_i_deg``, ``phi_s_deg``, in that order) then
        ``polarisation`` (HH, HV, VH, VV). Attributes: the model, the carrier, the sea
        and ``eps_r`` (real and imaginary parts).

    Warns
    -----
    ValidityWarning
        A model used outside its domain (Kirchhoff far from specular, SPM with k h > 0.3).
    """
    import numpy as np
    import xarray as xr

    from .build import carrier_frequency, sea_spectrum
    from .conventions import CHANNELS
    from .ocean.seawater import sea_water_permittivity
    from .ocean.spectra import DirectionalSpectrum
    from .ocean.twoscale import TWO_SCALE_CUT_RATIO
    from .scattering.models import MEAN_PLANE_MODELS, sea_sigma

    if model not in MEAN_PLANE_MODELS:
        raise SceneError(f"model = {model!r}: allowed {', '.join(MEAN_PLANE_MODELS)}")
    sea_args = {"wind_speed_m_s": wind_speed_m_s, "wind_direction_deg": wind_direction_deg,
                "spectrum": spectrum, "spreading": spreading, "spreading_s": spreading_s,
                "fetch_m": fetch_m,
                "temperature_c": temperature_c, "salinity_psu": salinity_psu}
    values = dict(SIGMA_DEFAULTS)
    spec = None
    if scene is not None:
        scene = _scene(scene)
        given = [k for k, v in sea_args.items() if v is not None]
        if given:
            raise SceneError(f"scene gives the sea state; do not give {', '.join(given)}")
        spec = sea_spectrum(scene)
        try:
            values["frequency_hz"] = carrier_frequency(scene, frequency_hz)
        except ValueError as exc:
            raise SceneError(str(exc)) from None
        values.update(temperature_c=scene.sea.temperature_c,
                      salinity_psu=scene.sea.salinity_psu, wind_speed_m_s=spec.u19_5,
                      wind_direction_deg=float(np.degrees(spec.wind_direction)),
                      spectrum=spec.spectrum, spreading=spec.spreading)
    else:
        values.update({k: v for k, v in sea_args.items() if v is not None})
        if frequency_hz is not None:
            values["frequency_hz"] = frequency_hz
    f = float(values["frequency_hz"])
    lo, hi = SIGMA_FREQUENCY_HZ
    if not lo <= f <= hi:
        raise SceneError(f"frequency_hz = {f:g}: must be in [{lo:g}, {hi:g}] Hz")
    u = float(values["wind_speed_m_s"])
    if not SIGMA_WIND_M_S[0] < u <= SIGMA_WIND_M_S[1]:
        raise SceneError(f"wind_speed_m_s = {u:g}: must be in (0, {SIGMA_WIND_M_S[1]:g}] m/s")
    cut = TWO_SCALE_CUT_RATIO if cut_ratio is None else float(cut_ratio)
    if not 0.0 < cut <= 1.0:
        raise SceneError(f"cut_ratio = {cut_ratio}: must be in (0, 1]")
    if values["spectrum"] == "jonswap" and values.get("fetch_m") is None and spec is None:
        raise SceneError("spectrum 'jonswap' needs fetch_m")
    named = [("theta_i_deg", _angles(theta_i_deg, "theta_i_deg", 0.0, 90.0)),
             ("theta_s_deg", _angles(theta_s_deg, "theta_s_deg", 0.0, 90.0)),
             ("phi_i_deg", _angles(phi_i_deg, "phi_i_deg", -360.0, 360.0)),
             ("phi_s_deg", _angles(phi_s_deg, "phi_s_deg", -360.0, 360.0))]
    try:
        eps = complex(sea_water_permittivity(f, values["temperature_c"],
                                             values["salinity_psu"],
                                             model=permittivity_model))
        if spec is None:
            spec = DirectionalSpectrum(
                spectrum=values["spectrum"], spreading=values["spreading"], u19_5=u,
                wind_direction=float(np.radians(values["wind_direction_deg"])),
                fetch=values.get("fetch_m"), s=float(values.get("spreading_s") or 1.0))
    except ValueError as exc:
        raise SceneError(str(exc)) from None
    grids = np.meshgrid(*(np.atleast_1d(a) for _, a in named), indexing="ij")
    ti, ts, pi_, ps = (np.radians(g.ravel()) for g in grids)
    s = sea_sigma(model, ti, pi_, ts, ps, f, spec, eps, slopes=slopes, cut_ratio=cut)
    shape = tuple(a.size for _, a in named)
    dims = [name for name, a in named if a.ndim == 1]
    s = s.reshape(shape + (4,))[tuple(slice(None) if a.ndim == 1 else 0 for _, a in named)]
    coords: dict[str, Any] = {name: ((name,) if a.ndim == 1 else (), a, {"units": "deg"})
                              for name, a in named}
    coords["polarisation"] = list(CHANNELS)
    attrs = {"units": "m2 m-2", "long_name": f"sigma_mn of the sea, {model} model",
             "model": model, "frequency_hz": f, "wind_speed_m_s": u,
             "wind_direction_deg": float(np.degrees(spec.wind_direction)),
             "spectrum": spec.spectrum, "spreading": spec.spreading, "spreading_s": spec.s,
             "temperature_c": float(values["temperature_c"]),
             "salinity_psu": float(values["salinity_psu"]), "eps_r_real": eps.real,
             "eps_r_imag": eps.imag, "slopes": slopes, "cut_ratio": cut}
    return xr.DataArray(s, dims=dims + ["polarisation"], coords=coords, name="sigma",
                        attrs=attrs)


def wave_spectrum(wavenumber_rad_m: ArrayLike, *, wind_speed_m_s: float = 4.53,
                  spectrum: str = "elfouhaily", fetch_m: float | None = None,
                  scene: Scene | None = None) -> xr.DataArray:
    """Omnidirectional wavenumber spectrum S(K) of a wind sea (the paper's eq 5 for
    Pierson-Moskowitz; :mod:`seaecho.ocean.spectra` for the others and their sources).

    Parameters
    ----------
    wavenumber_rad_m : float or sequence
        Wavenumbers K > 0 [rad/m].
    wind_speed_m_s : float
        U19.5 [m/s] (default 4.53, the paper's Fig. 3 sea).
    spectrum : str
        ``elfouhaily``, ``pierson-moskowitz``, ``jonswap``, ``romeiser`` or ``kudryavtsev``.
    fetch_m : float, optional
        Fetch [m] (JONSWAP; Elfouhaily's wave age).
    scene : Scene, optional
        Take the spectrum, wind and fetch from the scene's ``[sea]`` instead.

    Returns
    -------
    xarray.DataArray
        S(K) [m^3] over ``wavenumber`` [rad/m], with attributes ``spectrum``,
        ``wind_speed_m_s``, ``significant_wave_height_m`` (H_s = 4 sqrt(int S dK) over
        0 < K < 10^4 rad/m) and ``peak_wavenumber_rad_m`` (the maximum of S, found by a
        bounded search over 10^-4 < K < 10^2 rad/m).
    """
    import numpy as np
    import xarray as xr
    from scipy.optimize import minimize_scalar

    from .build import sea_spectrum
    from .ocean.spectra import DirectionalSpectrum
    from .ocean.twoscale import height_variance

    k = np.asarray(wavenumber_rad_m, dtype=np.float64)
    if k.ndim > 1 or not np.all(np.isfinite(k)) or np.any(k <= 0):
        raise SceneError(f"wavenumber_rad_m = {np.ravel(k)[:8].tolist()}...: expected "
                         "positive numbers [rad/m], a number or a 1-D sequence")
    if scene is not None:
        spec = sea_spectrum(_scene(scene))
    else:
        if not SIGMA_WIND_M_S[0] < wind_speed_m_s <= SIGMA_WIND_M_S[1]:
            raise SceneError(f"wind_speed_m_s = {wind_speed_m_s!r}: must be in "
                             f"(0, {SIGMA_WIND_M_S[1]:g}] m/s")
        try:
            spec = DirectionalSpectrum(spectrum=spectrum, spreading="longuet-higgins",
                                       u19_5=float(wind_speed_m_s), fetch=fetch_m)
        except ValueError as exc:
            raise SceneError(str(exc)) from None
    peak = minimize_scalar(lambda lk: -float(spec.omni(np.exp(lk))),
                           bounds=(math.log(1e-4), math.log(1e2)), method="bounded",
                           options={"xatol": 1e-10})
    attrs = {"units": "m3", "long_name": f"omnidirectional {spec.spectrum} spectrum",
             "spectrum": spec.spectrum, "wind_speed_m_s": float(spec.u19_5),
             "significant_wave_height_m": 4.0 * math.sqrt(height_variance(spec, 0.0, 1e4)),
             "peak_wavenumber_rad_m": float(math.exp(peak.x))}
    dims = ("wavenumber",) if k.ndim else ()
    return xr.DataArray(spec.omni(k), dims=dims, name="spectrum", attrs=attrs,
                        coords={"wavenumber": (dims, k, {"units": "rad m-1"})})


def permittivity(frequency_hz: ArrayLike = 10.0e9, temperature_c: float = 20.0,
                 salinity_psu: float = 35.0, model: str = "meissner-wentz") -> xr.DataArray:
    """Complex relative permittivity of sea water, eps' - j eps''
    (``seaecho permittivity``; exp(+j omega t) convention).

    Parameters
    ----------
    frequency_hz : float or sequence
        Frequency [Hz], in (0, 1e12]; a sequence becomes the ``frequency_hz`` dimension.
    temperature_c : float
        Temperature [degC].
    salinity_psu : float
        Salinity [psu].
    model : {'meissner-wentz', 'klein-swift'}
        Meissner and Wentz (2004) or Klein and Swift (1977).

    Returns
    -------
    xarray.DataArray
        complex eps_r [-].

    Warns
    -----
    ValidityWarning
        Outside the model's fitted range of frequency, temperature or salinity.
    """
    import numpy as np
    import xarray as xr

    from .ocean.seawater import sea_water_permittivity

    f = np.asarray(frequency_hz, dtype=np.float64)
    lo, hi = PERMITTIVITY_FREQUENCY_HZ
    if f.ndim > 1 or f.size == 0 or not np.all((f > lo) & (f <= hi)):
        raise SceneError(f"frequency_hz = {f.tolist()}: must be in ({lo:g}, {hi:g}] Hz")
    try:
        eps = np.asarray(sea_water_permittivity(f, temperature_c, salinity_psu, model=model),
                         dtype=np.complex128)
    except ValueError as exc:
        raise SceneError(str(exc)) from None
    dims = ("frequency_hz",) if f.ndim == 1 else ()
    return xr.DataArray(
        eps, dims=dims, coords={"frequency_hz": (dims, f, {"units": "Hz"})}, name="eps_r",
        attrs={"units": "1", "long_name": "relative permittivity of sea water, eps' - j eps''",
               "model": model, "temperature_c": float(temperature_c),
               "salinity_psu": float(salinity_psu)})


# ------------------------------------------------------------------------------- image
def image_config(raw: xr.Dataset | PathLike | Mapping[str, Any] | None = None,
                 **fields: Any) -> ImageConfig:
    """The ``[image]`` section of a raw dataset's scene with fields replaced, validated.

    Parameters
    ----------
    raw : xarray.Dataset, path or mapping, optional
        A raw dataset (its ``scene_json``), its file, or an ``[image]`` dict; None for
        the defaults.
    **fields
        ``[image]`` fields (``pixel_m``, ``extent_m``, ``track``, ``azimuth_window``,
        ``looks``, ... : docs/scene-files.md); None leaves a field as it is.

    Raises
    ------
    SceneError
        ``[image].pixel_m = -1: ...``: the field, the value and what is allowed.
    """
    import json

    import xarray as xr
    from pydantic import ValidationError

    from .config.image import ImageConfig

    if raw is None:
        values: dict[str, Any] = {}
    elif isinstance(raw, xr.Dataset):  # before Mapping: a Dataset is one
        values = dict(json.loads(raw.attrs.get("scene_json", "{}")).get("image") or {})
    elif isinstance(raw, str | os.PathLike):
        try:
            with open_dataset(raw) as ds:
                text = ds.attrs.get("scene_json", "{}")
        except (OSError, ValueError) as exc:
            raise SceneError(f"{os.fspath(raw)}: not a readable netCDF dataset "
                             f"({exc})") from None
        values = dict(json.loads(text).get("image") or {})
    elif isinstance(raw, Mapping):
        values = dict(raw)
    else:
        raise SceneError(f"raw: expected a dataset, a file or an [image] dict, got "
                         f"{type(raw).__name__}")
    for name, v in fields.items():
        if v is not None:
            values[name] = tuple(v) if isinstance(v, list) else v
    try:
        return ImageConfig.model_validate(values)
    except ValidationError as exc:
        err = exc.errors()[0]
        msg = err["msg"].removeprefix("Value error, ")
        if not err["loc"]:  # a check across fields: its message names them
            raise SceneError(f"[image]: {msg}") from None
        loc = ".".join(str(p) for p in err["loc"])
        raise SceneError(f"[image].{loc} = {err.get('input')!r}: {msg}") from None


def image(raw: xr.Dataset | PathLike, config: ImageConfig | None = None, *,
          backend: str = "drjit", progress: bool = False, timings: dict | None = None,
          **fields: Any) -> xr.Dataset:
    """Focus a raw dataset into a calibrated polarimetric SAR image (``seaecho image``).

    Time-domain backprojection onto a horizontal grid, calibrated in RCS and sigma0
    (:func:`seaecho.imaging.focus.focus`, docs/imaging.md).

    Parameters
    ----------
    raw : xarray.Dataset or path
        The output of :func:`simulate` or ``seaecho run``.
    config : ImageConfig, optional
        Processing parameters; default the ``[image]`` section of the raw dataset's
        scene (its defaults where it has none), with ``fields`` replacing its fields.
    backend : {'drjit', 'numpy'}
        Backprojection kernel.
    progress : bool
        Show a progress bar over the blocks of pulses.
    timings : dict, optional
        Filled with the time of each stage [s] and the throughput.
    **fields
        ``[image]`` fields: ``pixel_m``, ``extent_m``, ``height_m``, ``track``
        (``'nominal'`` or ``'true'``), ``azimuth_window``, ``range_weighting``,
        ``doppler_bandwidth_hz``, ``looks``, ``speckle_filter``, ``filter_size``...

    Returns
    -------
    xarray.Dataset
        ``image`` (channel, y, x) complex [m], ``sigma0`` [m^2/m^2], ``pauli``, the
        calibration maps and the ground truth on the same grid.

    Raises
    ------
    SceneError
        A bad ``[image]`` field (named), or a grid or a file the processor cannot use.
    """
    from .imaging.focus import focus

    if config is not None and fields:
        raise SceneError(f"give config or [image] fields ({', '.join(fields)}), not both")
    if isinstance(raw, str | os.PathLike) and not Path(raw).is_file():
        raise SceneError(f"raw dataset {os.fspath(raw)} does not exist")
    cfg = config if config is not None else image_config(raw, **fields)
    try:
        if _multistatic(raw):  # each receiver's image and their combination
            import contextlib

            import xarray as xr

            from .multistatic import image_multistatic

            with contextlib.ExitStack() as stack:
                ds = raw if isinstance(raw, xr.Dataset) else stack.enter_context(
                    open_dataset(raw))
                return image_multistatic(ds, cfg, backend=backend, progress=progress,
                                         timings=timings).load()
        return focus(raw, cfg, backend=backend, progress=progress,
                     timings=timings if timings is not None else {})
    except ValueError as exc:  # grid, window, or a dataset that is not a raw run
        where = os.fspath(raw) if isinstance(raw, str | os.PathLike) else "raw dataset"
        raise SceneError(f"{where}: {exc}") from None


def _multistatic(raw) -> bool:
    """Whether a raw dataset (or file) is a multistatic run (``[[receivers]]``)."""
    import xarray as xr

    if isinstance(raw, xr.Dataset):
        return bool(int(raw.attrs.get("multistatic", 0)))
    with open_dataset(raw) as ds:
        return bool(int(ds.attrs.get("multistatic", 0)))


def image_measures(img: xr.Dataset, variable: str = "sigma0") -> dict[str, dict[str, float]]:
    """The paper's image claims measured per channel of a focused image over the sea
    (what ``seaecho image`` prints; docs/imaging.md, :mod:`seaecho.imaging.quality`).

    Parameters
    ----------
    img : xarray.Dataset
        :func:`image` of a run with sea clutter.
    variable : str
        ``sigma0``, or ``sigma0_filtered`` with a speckle filter.

    Returns
    -------
    dict
        ``{channel: {"sea_db": ..., "wake_db": ..., "contrast_db": ...,
        "secondary_peak_db": ..., "modulation": ...}}``: the measures the image allows
        (an empty dict for a channel without sea). A multistatic image (several
        receivers) is measured per receiver, keys ``"<receiver> <channel>"``.
    """
    from .imaging.quality import paper_metrics

    if variable not in img:
        raise SceneError(f"variable = {variable!r}: not in the image (has "
                         f"{', '.join(sorted(map(str, img.data_vars)))})")
    if "receiver" in img.dims:  # [[receivers]]: each receiver's image (docs/multistatic.md)
        from .multistatic import receiver_image

        return {f"{name} {ch}": m for name in img["receiver"].values
                for ch, m in paper_metrics(receiver_image(img, str(name)),
                                           variable).items()}
    return paper_metrics(img, variable)


def figures(dataset: xr.Dataset, stem: PathLike) -> list[Path]:
    """Write the PNG figures the command line draws for a dataset, ``<stem>_<what>.png``.

    A run (:func:`simulate`, ``seaecho run``): the signal of the first pulse, raw and
    range compressed, and with sea clutter the elevation and sigma0 maps (the paper's
    Fig. 6 panels). An image (:func:`image`, ``seaecho image``): sigma0 per channel on
    one dB scale (its ``[image].dynamic_range_db``), the speckle-filtered sigma0, the
    Pauli composite (the paper's Figs. 7-9).

    Returns
    -------
    list of Path
        The files written (each atomically).
    """
    import json

    stem = Path(stem)
    if str(stem.parent) and not stem.parent.is_dir():
        raise SceneError(f"stem = {os.fspath(stem)!r}: directory {stem.parent} does not "
                         "exist")
    if "raw" in dataset and int(dataset.attrs.get("multistatic", 0)):
        from .multistatic import receiver_dataset
        from .plotting.run import run_figures

        # each receiver's product as it is (its figures read no scene: docs/products.md)
        return [png for name in dataset["receiver"].values for png in run_figures(
            receiver_dataset(dataset, str(name), receiver_scene=False), f"{stem}_{name}")]
    if "raw" in dataset:
        from .plotting.run import run_figures

        out = run_figures(dataset, stem)
        if "sweep" in dataset:  # a scanning radar: a PPI per sweep
            from .plotting.ppi import ppi_figures

            out += ppi_figures(dataset, stem)
        return out
    if "image_json" in dataset.attrs and "receiver" in dataset.dims:
        from .multistatic import multistatic_figures

        cfg = json.loads(dataset.attrs["image_json"])
        return multistatic_figures(dataset, stem, cfg["dynamic_range_db"])
    if "image_json" in dataset.attrs:
        from .plotting.image import image_figures

        cfg = json.loads(dataset.attrs["image_json"])
        return image_figures(dataset, stem, cfg["dynamic_range_db"])
    raise SceneError("dataset: neither a run (no 'raw') nor an image (no 'image_json' "
                     "attribute)")


def ppi(dataset: xr.Dataset, path: PathLike | None = None):
    """The sweeps of a scanning run in the CfRadial 2 / FM 301 layout (xradar's).

    Parameters
    ----------
    dataset : xarray.Dataset
        A run (:func:`simulate`) whose antenna scans.
    path : path, optional
        Also write the tree to this netCDF-4 file (atomically).

    Returns
    -------
    xarray.DataTree
        Root metadata and one ``sweep_N`` group per revolution or sector pass, dims
        ``azimuth`` x ``range`` (:mod:`seaecho.io.cfradial`, docs/scanning.md).
    """
    from .io.cfradial import ppi_tree, write_ppi

    if "sweep" not in dataset:
        raise SceneError("dataset: the run's antenna does not scan (no 'sweep'); a PPI "
                         "product needs [transmitter.antenna.scan]")
    if path is not None:
        write_ppi(dataset, path)
    return ppi_tree(dataset)


# ------------------------------------------------------------------ detection, scores
#: CFAR kinds :func:`detect` takes: the sliding windows of seaecho.detection.cfar and the
#: clutter map ('map', scan to scan).
DETECTORS = ("ca", "go", "so", "os", "map")
#: :func:`detect`'s default ``land_spread_db``: the level [dB] below the two-way beam's
#: peak out to which the land's echo is taken to spread onto the sea (docs/detection.md,
#: "Land blanking": the land's contrast over the sea clutter, chosen on the coastal
#: scanning example)
LAND_SPREAD_DB = 65.0


def _detection_frames(dataset, channel, truth, radar_position_m, azimuth_gate_deg):
    """(frames, kind, source) of a run, an image or a CfRadial 2 file."""
    from .io import detections as iod

    source = ""
    if isinstance(dataset, list | tuple):  # several images of one grid: a stack
        images = []
        for d in dataset:
            if isinstance(d, str | os.PathLike):
                if not Path(d).exists():
                    raise SceneError(f"dataset {os.fspath(d)} does not exist")
                with open_dataset(d) as ds:
                    d = ds.load()
            if "image" not in d:
                raise SceneError("dataset: a list of datasets is a stack of images of "
                                 "`seaecho image` (for the clutter map); one is not an "
                                 "image (no 'image')")
            images.append(d)
        return iod.image_stack_frames(images, channel, truth), "image", ", ".join(
            os.fspath(d) for d in dataset if isinstance(d, str | os.PathLike))
    if isinstance(dataset, str | os.PathLike):
        source = os.fspath(dataset)
        if not Path(dataset).exists():
            raise SceneError(f"dataset {source} does not exist")
        try:
            ds = open_dataset(dataset)
        except (OSError, ValueError) as exc:
            raise SceneError(f"{source}: not a seaecho run or image ({exc})") from None
        with ds:
            if "compressed" in ds or "image" in ds:  # the raw pulses stay on disk
                ds = ds.drop_vars(["raw"], errors="ignore").load()
                return _detection_frames(ds, channel, truth, radar_position_m,
                                         azimuth_gate_deg)[:2] + (source,)
        try:
            frames = iod.cfradial_sweeps(dataset, channel, radar_position_m, truth,
                                         azimuth_gate_deg)
        except (OSError, KeyError) as exc:
            raise SceneError(f"{source}: neither a run, an image nor a CfRadial 2 file "
                             f"({exc})") from None
        return frames, "ppi", source
    if "compressed" in dataset and "sweep" in dataset:
        return iod.run_sweeps(dataset, channel, truth, azimuth_gate_deg), "ppi", source
    if "compressed" in dataset:
        return iod.profile_frames(dataset, channel, truth), "profile", source
    if "image" in dataset:
        return iod.image_frames(dataset, channel, truth), "image", source
    raise SceneError("dataset: neither a run (no 'compressed'), a scanning run, nor an image "
                     "(no 'image')")


def _detector(kind: str, frames, cfar: str, train, guard, rank, map_weight):
    """(noise callable, detector with ``scale(pfa)``, description) for these frames."""
    import numpy as np

    from .detection import CFAR, ClutterMap

    if cfar not in DETECTORS:
        raise SceneError(f"cfar = {cfar!r}: allowed {', '.join(DETECTORS)}")
    if cfar == "map":
        cm = ClutterMap(weight=map_weight if map_weight is not None else 0.125)
        shapes = {f.power.shape for f in frames}
        if kind == "profile":  # pulses as scans of the range cells
            return cm.noise, cm, f"clutter map w = {cm.weight:g}, warm-up {cm.warmup}"
        looks = "sweeps" if kind == "ppi" else "images"
        if len(shapes) == 1 and len(frames) > cm.warmup:  # sweeps or a stack of images
            stack = np.stack([f.power for f in frames])
            est = cm.noise(stack)
            table = {id(f.power): est[i] for i, f in enumerate(frames)}
            return (lambda p: table[id(p)]), cm, f"clutter map w = {cm.weight:g}, " \
                f"warm-up {cm.warmup} {looks}"
        if kind == "image":
            raise SceneError(
                f"cfar = 'map': {len(frames)} image(s): a clutter map estimates each "
                "pixel's clutter from the same pixel in earlier images, so it needs a "
                f"stack of more than {cm.warmup} images of one grid (give a list of "
                "images; a single SAR image has no past: use a sliding-window CFAR)")
        raise SceneError(f"cfar = 'map': needs range profiles, or more than {cm.warmup} "
                         "PPI sweeps of one shape")
    train_t = tuple(np.atleast_1d(train).tolist())
    guard_t = tuple(np.atleast_1d(guard).tolist())
    if kind == "image" and len(train_t) == 1:
        train_t, guard_t = train_t * 2, (guard_t * 2 if len(guard_t) == 1 else guard_t)
    circular = kind == "ppi" and all(f.extra.get("circular") for f in frames)
    det = CFAR(cfar, train_t if len(train_t) > 1 else train_t[0],
               guard_t if len(guard_t) > 1 else guard_t[0], rank=rank,
               circular=circular and len(train_t) == 2)
    return det.noise, det, f"{cfar.upper()}-CFAR train {train_t} guard {guard_t}" + (
        f" rank {det.rank}" if det.kind == "os" else "")


def detect(dataset: xr.Dataset | PathLike, *, cfar: str = "ca", pfa: float = 1e-6,
           train: int | tuple[int, int] = 16, guard: int | tuple[int, int] = 2,
           rank: int | None = None, channel: str | None = None,
           m_of_n: tuple[int, int] | None = None, map_weight: float | None = None,
           truth: Any = None, radar_position_m: ArrayLike | None = None,
           azimuth_gate_deg: float | None = None,
           stonesoup: PathLike | None = None, land_mask: bool | None = None,
           land_margin_m: float = 0.0, land_censor: bool | None = None,
           censor_min_fraction: float = 0.5,
           land_spread_db: float | None = LAND_SPREAD_DB) -> tuple[xr.Dataset, xr.Dataset]:
    """Detect targets in a run, a SAR image or PPI sweeps (``seaecho detect``;
    docs/detection.md).

    Range profiles (``|compressed|^2``, pulse x range, 1-D CFAR along range, a look per
    pulse) for a run; PPI sweeps (azimuth x range, a look per sweep) for a scanning run
    or a CfRadial 2 file; the image (y x x, 2-D CFAR, one look) for ``seaecho image``'s
    output. Detected cells join into plots; each plot belongs to the nearest object of
    the truth within its gate, or to none (a false alarm).

    Parameters
    ----------
    dataset : xarray.Dataset or path, or a list of them
        A run, a scanning run, an image, or a CfRadial 2 file; a list: images of one
        grid, one look each in their order (a stack for the clutter map).
    cfar : {'ca', 'go', 'so', 'os', 'map'}
        Detector (:data:`DETECTORS`).
    pfa : float
        Design false-alarm probability per cell, in (0, 1).
    train, guard : int or (int, int)
        Training and guard cells each side: one number along range, two (azimuth or y,
        range or x) for a 2-D window (an image with one number: a square window).
    rank : int, optional
        OS-CFAR's order statistic (default 3N/4).
    channel : str, optional
        Channel (default the first).
    m_of_n : (int, int), optional
        Range profiles: M-of-N over consecutive pulses before the plots.
    map_weight : float, optional
        Clutter map's weight of the newest scan (default 1/8).
    truth : seaecho.detection.ObjectTruth, optional
        The objects, in place of the dataset's own.
    radar_position_m : array_like, optional
        A CfRadial 2 file's radar in the scene frame [m].
    azimuth_gate_deg : float, optional
        PPI: the azimuth part of the objects' gates [deg].
    stonesoup : path, optional
        Directory for the Stone Soup export (:func:`stonesoup_readers`); its truth holds
        the visible opportunities only.
    land_mask : bool, optional
        PPI sweeps of a run with ``[[land]]``: blank the cells whose ground point lies
        on the land (its ``land_outline`` polygons) or within ``land_margin_m`` of the
        shore: never tested, no plot (:func:`seaecho.detection.landmask.land_mask`).
        Default: on where the run has land; False: off.
    land_margin_m : float
        The land mask's margin outward from the shore [m] (>= 0; default 0): the chart's
        error, added to the spread of the land's echo.
    land_spread_db : float or None
        The land mask also blanks the sea cells the land's echo spreads onto: within the
        azimuth where the run's two-way antenna pattern is above -``land_spread_db`` dB
        (its sidelobes included) and the range where its compressed pulse is (main lobe,
        c / (2 B), and band-limited tails) of a land cell, a dilation of the mask by
        whole rays and gates
        (:func:`seaecho.io.detections.land_spread`,
        :func:`seaecho.detection.landmask.spread`). A level > 0 dB (default
        :data:`LAND_SPREAD_DB`), or None: no spread.
    land_censor : bool, optional
        Land-censored CFAR: the land mask's cells are also left out of every training
        window, each estimate uses the sea cells its window keeps, with the threshold
        multiplier of the design P_FA for that number of cells
        (:meth:`seaecho.detection.CFAR.censored`). Default: on wherever the land mask
        is on (a sliding-window CFAR); False: the land stays in the windows; True
        refuses a detection without the land mask.
    censor_min_fraction : float
        Land censoring: a cell whose window keeps fewer than this fraction of its
        training cells is not tested (counted in ``cells_short``); in (0, 1].

    Returns
    -------
    detections : xarray.Dataset
        Dimension ``detection``: ``time`` [s], ``look``, ``pulse`` (profiles) or
        ``sweep``, ``azimuth_deg`` (PPI), ``range_m``, ``x_m``, ``y_m``, ``power``
        (peak, [W] or [m^2] for an image), ``snr_db`` (estimate: peak over the noise
        estimate, minus one), ``n_cells``, ``object`` (name, '' for a false alarm),
        ``object_index`` (-1); attributes: the detector, ``alpha``, ``cells_tested``,
        ``n_looks``, ``area_m2`` (per look; NaN when unknown), ``position_sigma_m`` (a
        plot's position error, the Stone Soup measurement noise), ``land_mask``,
        ``cells_blanked``, ``land_censor``, ``cells_censored`` (tested with a window
        that lost land cells), ``cells_short`` (left untested: too few sea cells).
    truth : xarray.Dataset
        Dimension ``opportunity`` (one object in one look, inside the tested cells):
        ``look``, ``time``, ``object``, ``object_index``, ``x_m``, ``y_m``, ``vx_m_s``,
        ``vy_m_s``, ``snr_db`` (largest SNR estimate in the object's gate), ``visible``
        (1 where the truth says the radar can see the object, 0 where it is hidden:
        behind the land, below the horizon, behind a crest; scored apart).
    """
    import numpy as np
    import xarray as xr

    from .detection import detect_frames
    from .detection.theory import pfa_m_of_n

    if not (isinstance(pfa, int | float) and 0.0 < pfa < 1.0):
        raise SceneError(f"pfa = {pfa}: the design false-alarm probability must be in "
                         "(0, 1)")
    try:
        frames, kind, source = _detection_frames(dataset, channel, truth,
                                                 radar_position_m, azimuth_gate_deg)
        blanked, spread_attrs = _land_blanking(dataset, kind, frames, land_mask,
                                               land_margin_m, land_spread_db)
        noise, det, text = _detector(kind, frames, cfar, train, guard, rank, map_weight)
        censored = _land_censoring(det, blanked, land_censor, censor_min_fraction, pfa)
        alpha = det.scale(pfa)
        if m_of_n is not None:
            if kind != "profile":
                raise ValueError(f"m_of_n = {m_of_n}: M-of-N over pulses applies to range "
                                 "profiles")
            if len(m_of_n) != 2:
                raise ValueError(f"m_of_n = {m_of_n}: give (M, N)")
        dets, opps, totals = detect_frames(frames, noise, alpha,
                                           integrate=tuple(m_of_n) if m_of_n else None,
                                           censored=censored)
    except ValueError as exc:
        if isinstance(exc, SceneError):
            raise
        raise SceneError(str(exc)) from None
    names = _object_names(dataset, truth, kind)
    obj = dets["object"]
    name_of = np.array(list(names) + [""], dtype=object)
    columns = {"time": ("detection", dets["time_s"], {"units": "s"}),
               "look": ("detection", dets["look"])}
    for k in ("pulse", "sweep", "azimuth_deg", "range_m", "x_m", "y_m", "radar_x_m",
              "radar_y_m", "cell_area_m2"):
        if k in dets:
            columns[k] = ("detection", dets[k], {"units": "degree" if k.endswith("deg")
                                                 else "m" if k.endswith("_m") else
                                                 "m2" if k.endswith("_m2") else "1"})
    power_units = "m2" if kind == "image" else "W"
    columns.update(
        power=("detection", dets["power"], {"units": power_units, "long_name": "peak"}),
        snr_db=("detection", 10.0 * np.log10(dets["snr"]), {"units": "dB"}),
        n_cells=("detection", dets["n_cells"]),
        object=("detection", name_of[obj].astype(str)),
        object_index=("detection", obj))
    attrs = {"kind": kind, "detector": text, "cfar": cfar, "pfa": float(pfa),
             "alpha": float(alpha),
             "channel": str(frames[0].extra.get("channel", channel or "")) if frames else "",
             "source": source,
             "cells_tested": int(totals["cells_tested"]), "n_looks": int(totals["n_looks"]),
             "area_m2": float(totals["area_m2"]),
             "m_of_n": "" if m_of_n is None else f"{m_of_n[0]}/{m_of_n[1]}",
             # P_FA of a cell after M of N independent pulses (Richards 2014, ch. 6)
             "pfa_integrated": float(pfa) if m_of_n is None else float(
                 pfa_m_of_n(pfa, int(m_of_n[0]), int(m_of_n[1]))),
             "position_sigma_m": float(frames[0].extra.get("position_sigma_m", 1.0))
             if frames else 1.0,
             "land_mask": int(blanked is not None),
             "land_margin_m": float(land_margin_m) if blanked is not None else 0.0,
             "cells_blanked": int(blanked or 0), **spread_attrs,
             "land_censor": int(censored is not None),
             "censor_min_fraction": float(censor_min_fraction) if censored else 0.0,
             "cells_censored": int(totals["cells_censored"]),
             "cells_short": int(totals["cells_short"])}
    for k in ("range_sigma_m", "azimuth_sigma_deg", "beamwidth_deg"):  # PPI, profiles
        if frames and k in frames[0].extra:
            attrs[k] = float(frames[0].extra[k])
    detections = xr.Dataset(columns, attrs=attrs)
    vel = _truth_velocity(frames, opps)
    t_cols = {"look": ("opportunity", opps["look"]),
              "time": ("opportunity", opps["time_s"], {"units": "s"}),
              "object": ("opportunity", name_of[opps["object"]].astype(str)),
              "object_index": ("opportunity", opps["object"]),
              "x_m": ("opportunity", opps["x_m"], {"units": "m"}),
              "y_m": ("opportunity", opps["y_m"], {"units": "m"}),
              "vx_m_s": ("opportunity", vel[:, 0], {"units": "m s-1"}),
              "vy_m_s": ("opportunity", vel[:, 1], {"units": "m s-1"}),
              "snr_db": ("opportunity", 10.0 * np.log10(opps["snr"]), {"units": "dB"}),
              "visible": ("opportunity", np.asarray(opps["visible"]).astype(np.int8),
                          {"units": "1", "long_name": "1: the truth says the radar can "
                           "see the object (0: hidden, scored apart)"})}
    truth_ds = xr.Dataset(t_cols, attrs=dict(attrs))
    if stonesoup is not None:
        write_stonesoup_dir(detections, truth_ds, stonesoup)
    return detections, truth_ds


def _land_blanking(dataset, kind, frames, land_mask, margin_m, spread_db
                   ) -> tuple[int | None, dict]:
    """Set the frames' land mask (:func:`detect`'s ``land_mask``, ``land_margin_m`` and
    ``land_spread_db``): (the cells blanked in all, or None when there is no mask; the
    detections' attributes of the spread)."""
    import numpy as np

    from .detection.landmask import land_mask as mask_of
    from .detection.landmask import spread, spread_bins
    from .io.detections import land_spread, run_land_outlines

    no_spread = {"land_spread_db": 0.0, "land_spread_azimuth_deg": 0.0,
                 "land_spread_range_m": 0.0, "land_spread_rays": 0, "land_spread_gates": 0}
    if spread_db is not None and not (
            isinstance(spread_db, int | float) and not isinstance(spread_db, bool)
            and np.isfinite(spread_db) and spread_db > 0):
        raise SceneError(f"land_spread_db = {spread_db!r}: the level below the two-way "
                         "beam's peak out to which the land's echo spreads must be a number "
                         "> 0 dB, or none (no spread)")

    if land_mask not in (None, True, False):
        raise SceneError(f"land_mask = {land_mask!r}: allowed true, false or none "
                         "(default: on where the run has land)")
    if not (isinstance(margin_m, int | float) and np.isfinite(margin_m) and margin_m >= 0):
        raise SceneError(f"land_margin_m = {margin_m}: the land mask's margin must be a "
                         "number >= 0 [m]")
    if land_mask is False:
        return None, no_spread
    extent = None  # (azimuth [rad], range [m]) of the land's echo spread

    def read(ds):
        nonlocal extent
        found = run_land_outlines(ds)
        if found and spread_db is not None and kind == "ppi":
            extent = land_spread(ds, float(spread_db))
        return found

    outlines = read(dataset) if hasattr(dataset, "data_vars") else []
    if not outlines and isinstance(dataset, str | os.PathLike) and Path(dataset).exists():
        try:
            with open_dataset(dataset) as ds:
                outlines = read(ds)
        except OSError:  # a CfRadial 2 file: no outlines
            outlines = []
        except ValueError as exc:
            if "land_spread_db" in str(exc):
                raise
            outlines = []
    if kind != "ppi" or not outlines:
        if land_mask:
            raise SceneError(f"land_mask = true: the land mask blanks PPI sweeps of a run "
                             f"with [[land]]; this dataset has {kind} frames and "
                             f"{len(outlines)} land outline(s)")
        return None, no_spread
    n, attrs = 0, dict(no_spread)
    for f in frames:
        f.blanked = mask_of(f.cell_coord, outlines, float(margin_m))
        if extent is not None:
            rays = spread_bins(float(np.rad2deg(extent[0])), f.extra["azimuth_step_deg"])
            gates = spread_bins(extent[1], f.extra["range_step_m"])
            f.blanked = spread(np.broadcast_to(f.blanked, f.power.shape), rays, gates,
                               bool(f.extra.get("circular")))
            attrs = {"land_spread_db": float(spread_db),
                     "land_spread_azimuth_deg": float(np.rad2deg(extent[0])),
                     "land_spread_range_m": float(extent[1]),
                     "land_spread_rays": max(rays, attrs["land_spread_rays"]),
                     "land_spread_gates": max(gates, attrs["land_spread_gates"])}
        n += int(np.broadcast_to(f.blanked, f.power.shape).sum())
    return n, attrs


def _land_censoring(det, blanked, land_censor, min_fraction, pfa):
    """:func:`detect`'s ``land_censor``: the censored estimate of ``det`` (a callable
    ``(power, exclude) -> Censored`` at ``pfa``), or None."""
    import functools

    from .detection import CFAR

    if land_censor not in (None, True, False):
        raise SceneError(f"land_censor = {land_censor!r}: allowed true, false or none "
                         "(default: on wherever the land mask is on)")
    if not (isinstance(min_fraction, int | float) and not isinstance(min_fraction, bool)
            and 0.0 < min_fraction <= 1.0):
        raise SceneError(f"censor_min_fraction = {min_fraction!r}: the fraction of a "
                         "window's training cells a land-censored estimate needs must be "
                         "in (0, 1]")
    if land_censor is False:
        return None
    if blanked is None or not isinstance(det, CFAR):
        if land_censor:
            why = "no land mask (PPI sweeps of a run with [[land]], land_mask not false)" \
                if blanked is None else "a clutter map has no training window"
            raise SceneError(f"land_censor = true: it leaves the land mask's cells out of "
                             f"a sliding-window CFAR's training cells; here {why}")
        return None
    return functools.partial(det.censored, pfa=pfa, min_fraction=float(min_fraction))


def _object_names(dataset, truth, kind) -> tuple[str, ...]:
    if truth is not None:
        return tuple(truth.names)
    from .io.detections import image_truth, run_truth

    if isinstance(dataset, list | tuple):  # a stack of images: the first one's objects
        return _object_names(dataset[0], None, kind) if dataset else ()
    if isinstance(dataset, str | os.PathLike):
        with open_dataset(dataset) as ds:
            return _object_names(ds, None, kind) if ("compressed" in ds or "image" in ds) \
                else ()
    return image_truth(dataset)[0].names if kind == "image" else run_truth(dataset).names


def _truth_velocity(frames, opps):
    """Horizontal velocity of each opportunity's object at its time [m/s] (finite
    differences of the truth between the rows of each frame), (n, 2)."""
    import numpy as np

    out = np.zeros((opps["look"].size, 2))
    if not frames or not opps["look"].size:
        return out
    fr = frames[0]
    if fr.truth_coord.shape[1] == 0:
        return out
    # the frames share one ObjectTruth: its positions come back through truth_xyz at the
    # rows' times; differences between the rows of a frame give the velocity
    t, o = opps["time_s"], opps["object"]
    for f in frames:
        tt = f.time_s
        if tt.size < 2 or np.ptp(tt) == 0:
            continue
        sel = (t >= tt[0]) & (t <= tt[-1])
        for k in np.unique(o[sel]):
            m = sel & (o == k)
            vx = np.gradient(f.truth_xyz[:, k, 0], tt)
            vy = np.gradient(f.truth_xyz[:, k, 1], tt)
            out[m, 0] = np.interp(t[m], tt, vx)
            out[m, 1] = np.interp(t[m], tt, vy)
    return np.nan_to_num(out)


def write_stonesoup_dir(detections: xr.Dataset, truth: xr.Dataset,
                        directory: PathLike) -> dict:
    """Write :func:`detect`'s tables in the forms Stone Soup's CSV readers take
    (:func:`seaecho.io.detections.write_stonesoup`); returns the paths."""

    import numpy as np

    from .io.detections import write_stonesoup

    d = Path(directory)
    if d.exists() and not d.is_dir():
        raise SceneError(f"stonesoup = {os.fspath(d)!r}: exists and is not a directory")
    if not d.parent.is_dir():
        raise SceneError(f"stonesoup = {os.fspath(d)!r}: directory {d.parent} does not "
                         "exist")
    det = {k: detections[v].values for k, v in
           (("time_s", "time"), ("x_m", "x_m"), ("y_m", "y_m"))}
    for k in ("range_m", "snr_db", "power", "object", "look", "pulse", "sweep",
              "azimuth_deg", "radar_x_m", "radar_y_m"):
        if k in detections:
            det[k] = detections[k].values
    tr = {k: truth[v].values for k, v in (("time_s", "time"), ("object", "object"),
                                          ("x_m", "x_m"), ("y_m", "y_m"),
                                          ("vx_m_s", "vx_m_s"), ("vy_m_s", "vy_m_s"))}
    if "visible" in truth:  # a hidden object is no truth a tracker could follow
        seen = np.asarray(truth["visible"].values) > 0
        tr = {k: np.asarray(v)[seen] for k, v in tr.items()}
    # the plots' position error: the range resolution (range profiles; the arc of a ray
    # spacing at mid range if larger, PPI), half the image's resolution (images)
    sigma = float(detections.attrs.get("position_sigma_m", 1.0))
    # PPI: a resolution cell's spread in bearing and range (io.detections.sweep_frames)
    polar = (math.radians(float(detections.attrs["azimuth_sigma_deg"])),
             float(detections.attrs["range_sigma_m"])) \
        if "azimuth_sigma_deg" in detections.attrs else None
    return write_stonesoup(d, det, tr, (sigma, sigma), polar)


def stonesoup_readers(directory: PathLike, measurement: str = "auto",
                      noise: tuple[float, float] | None = None) -> tuple[Any, Any]:
    """Stone Soup readers of a ``seaecho detect --stonesoup DIR`` export.

    Parameters
    ----------
    directory : path
        The export.
    measurement : {'auto', 'cartesian', 'bearing-range'}
        The detections' measurement model: a
        :class:`~stonesoup.models.measurement.linear.LinearGaussian` on (x, y), or
        (PPI sweeps) :class:`~stonesoup.models.measurement.nonlinear.CartesianToBearingRange`
        on (bearing counter-clockwise from east [rad], ground range [m]) from the radar's
        position at each plot; 'auto': bearing-range where the export has it
        (:func:`seaecho.io.detections.stonesoup_readers`).
    noise : (float, float), optional
        The model's standard deviations in place of the export's ((x, y) [m] or
        (bearing [rad], range [m])).

    Returns
    -------
    (CSVDetectionReader, CSVGroundTruthReader)
        Configured on ``DIR/detections.csv`` (every detection with its measurement model
        on a constant-velocity state (x, vx, y, vy)) and ``DIR/truth.csv`` (paths by
        ``object``, state x, vx, y, vy); times are seconds since the scene's t = 0 read
        as seconds since 1970-01-01 UTC.

    Raises
    ------
    SceneError
        No export in ``directory``, or a measurement it does not have; ImportError
        without Stone Soup (``pip install seaecho[tracking]``).
    """
    from .io.detections import STONESOUP_FILES
    from .io.detections import stonesoup_readers as readers

    d = Path(directory)
    settings_path = d / STONESOUP_FILES["settings"]
    if not settings_path.is_file():
        raise SceneError(f"directory = {os.fspath(d)!r}: no {STONESOUP_FILES['settings']} "
                         "(write one with `seaecho detect ... --stonesoup DIR`)")
    try:
        return readers(d, measurement, noise)
    except ValueError as exc:
        raise SceneError(str(exc)) from None


def score(detections: xr.Dataset | PathLike, truth: xr.Dataset | PathLike | None = None,
          *, snr_bins_db: ArrayLike = (-math.inf, 0.0, 5.0, 10.0, 15.0, 20.0, math.inf)
          ) -> dict:
    """Scores of :func:`detect`'s output (``seaecho score``; docs/detection.md).

    Parameters
    ----------
    detections, truth : xarray.Dataset or path
        :func:`detect`'s two tables, or the CSV files ``seaecho detect`` writes (truth
        default: ``<detections>_truth.csv`` beside it).
    snr_bins_db : array_like
        SNR bin edges [dB] (an object is binned by its mean SNR over its looks).

    Returns
    -------
    dict
        :func:`seaecho.detection.score_tables`, with ``objects`` (index -> name).
    """
    import numpy as np

    from .detection import score_tables

    det, tru = _tables(detections, truth)
    attrs = det["attrs"]
    out = score_tables(det["look"], det["object_index"], det["n_cells"], tru["look"],
                       tru["object_index"], 10.0 ** (np.asarray(tru["snr_db"], float) / 10),
                       n_looks=int(attrs["n_looks"]), cells_tested=int(attrs["cells_tested"]),
                       area_m2=float(attrs["area_m2"]) if str(attrs["area_m2"]) not in
                       ("", "nan") else float("nan"), snr_bins_db=snr_bins_db,
                       opp_visible=tru.get("visible"))
    names = {}
    for i, n in zip(tru["object_index"], tru["object"], strict=True):
        names[int(i)] = str(n)
    out["objects"] = names
    out["detector"] = str(attrs.get("detector", ""))
    out["pfa_design"] = float(attrs.get("pfa", "nan"))
    return out


def _tables(detections, truth) -> tuple[dict, dict]:
    """Columns and attributes of the two tables, from datasets or CSV files."""
    import numpy as np

    from .io.detections import read_table

    def cols(x, what):
        if isinstance(x, str | os.PathLike):
            if not Path(x).is_file():
                raise SceneError(f"{what} = {os.fspath(x)!r}: no such file")
            try:
                c, h = read_table(x)
            except (OSError, ValueError) as exc:
                raise SceneError(f"{what} = {os.fspath(x)!r}: {exc}") from None
            out = dict(c)
            out["attrs"] = h
            return out
        out = {k: x[k].values for k in x.data_vars}
        out["attrs"] = dict(x.attrs)
        return out

    if truth is None:
        if not isinstance(detections, str | os.PathLike):
            raise SceneError("truth: give the truth table with a detections dataset")
        p = Path(detections)
        truth = p.with_name(p.stem + "_truth" + p.suffix)
    det, tru = cols(detections, "detections"), cols(truth, "truth")
    for need, table, what in ((("look", "object_index", "n_cells"), det, "detections"),
                              (("look", "object_index", "object", "snr_db"), tru, "truth")):
        missing = [k for k in need if k not in table]
        if missing:
            raise SceneError(f"{what}: missing column(s) {', '.join(missing)} (not a table "
                             "of `seaecho detect`)")
    for k in ("n_looks", "cells_tested", "area_m2"):
        if k not in det["attrs"]:
            raise SceneError(f"detections: no {k} (not a table of `seaecho detect`)")
    for k in ("look", "object_index", "n_cells"):
        det[k] = np.asarray(det[k]).astype(np.int64) if np.size(det[k]) else \
            np.zeros(0, np.int64)
    for k in ("look", "object_index"):
        tru[k] = np.asarray(tru[k]).astype(np.int64) if np.size(tru[k]) else \
            np.zeros(0, np.int64)
    return det, tru


def write_detections(detections: xr.Dataset, truth: xr.Dataset, path: PathLike
                     ) -> list[Path]:
    """Write :func:`detect`'s tables as CSV: ``path`` and ``<path>_truth.csv``, with the
    attributes as ``# key = value`` lines (atomically)."""
    from .io.detections import write_table

    p = Path(path)
    if str(p.parent) and not p.parent.is_dir():
        raise SceneError(f"output = {os.fspath(p)!r}: directory {p.parent} does not exist")
    header = dict(detections.attrs)
    a = write_table(p, {k: detections[k].values for k in detections.data_vars}, header)
    b = write_table(p.with_name(p.stem + "_truth" + p.suffix),
                    {k: truth[k].values for k in truth.data_vars}, header)
    return [a, b]


def roc(datasets: Any, detector: Any, *, channel: str | None = None,
        thresholds: ArrayLike | None = None, truth: Any = None,
        exclusion: float = 4.0) -> dict:
    """ROC curve of a detector on runs, images or PPI sweeps, by sweeping its threshold
    (docs/detection.md).

    Parameters
    ----------
    datasets : dataset, path, or a list of them
        What :func:`detect` takes; a list pools its looks (scenes x seeds).
    detector : callable
        ``power (rows, cols) -> statistic`` of the same shape, larger for a target, NaN
        where not tested: a :class:`seaecho.detection.CFAR` (1-D along the columns,
        range; 2-D over both) or a user's function.
    channel : str, optional
        Channel (default the first).
    thresholds : array_like, optional
        Thresholds on the statistic (default: from the statistics' quantiles).
    truth : seaecho.detection.ObjectTruth, optional
        The objects, in place of each dataset's own.
    exclusion : float
        Cells within ``exclusion`` gates of an object but outside its gate (its range
        sidelobes, its spread) are left out of the background.

    Returns
    -------
    dict
        ``threshold``, ``pfa`` (fraction of the background's tested cells above: cells
        beyond every object's exclusion zone), ``pd`` (fraction of the visible
        opportunities, an object in a look, whose largest statistic in its gate is
        above; one the truth hides is left out, as in :func:`score`),
        ``n_background``, ``n_opportunities`` (visible), ``n_hidden``, and per
        opportunity (hidden ones included) ``opportunity_object`` (name),
        ``opportunity_peak`` (largest statistic in the gate) and
        ``opportunity_visible``: P_D per object at any threshold.
    """
    import numpy as np

    from .detection import (
        opportunity_groups,
        opportunity_peaks,
        opportunity_visible,
        roc_from_statistic,
    )

    def f_names(frame, item):
        return list(truth.names) if truth is not None else list(
            _object_names(item, None, frame.kind))

    if not callable(detector):
        raise SceneError(f"detector = {detector!r}: a callable power -> statistic")
    items = datasets if isinstance(datasets, list | tuple) else [datasets]
    stats, groups, n, objects, seen = [], [], 0, [], []
    for item in items:
        try:
            frames = _detection_frames(item, channel, truth, None, None)[0]
        except ValueError as exc:
            raise SceneError(str(exc)) from None
        for f in frames:
            stat = np.asarray(detector(f.power), dtype=float)
            if stat.shape != f.power.shape:
                raise SceneError(f"detector returned shape {stat.shape} for power of shape "
                                 f"{f.power.shape}: one statistic per cell")
            g, table = opportunity_groups(f, np.isfinite(stat), n, exclusion)
            n += table["look"].size
            seen.append(opportunity_visible(f, table))
            objects.append(np.asarray(f_names(f, item))[table["object"]]
                           if table["object"].size else np.zeros(0, str))
            stats.append(stat.ravel())
            groups.append(g.ravel())
    stat, g = np.concatenate(stats), np.concatenate(groups)
    visible = np.concatenate(seen) if seen else np.zeros(0, bool)
    out = roc_from_statistic(stat, g, n, thresholds, visible)
    out["n_background"] = int(((g == -1) & np.isfinite(stat)).sum())
    out["n_opportunities"] = int(visible.sum())
    out["n_hidden"] = int((~visible).sum())
    out["opportunity_object"] = np.concatenate(objects) if objects else np.zeros(0, str)
    out["opportunity_peak"] = opportunity_peaks(stat, g, n)
    out["opportunity_visible"] = visible
    return out
