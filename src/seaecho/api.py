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
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from html import escape
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pydantic import PrivateAttr

from .config import Scene as SceneModel
from .config import SceneError
from .config import load_scene as _load_scene
from .config import parse_scene as _parse_scene
from .config import with_overrides as _with_overrides

if TYPE_CHECKING:  # pragma: no cover
    import xarray as xr
    from numpy.typing import ArrayLike

    from .config.image import ImageConfig

__all__ = [
    "Scene",
    "SceneSummary",
    "compare",
    "figures",
    "image",
    "image_config",
    "image_measures",
    "load_scene",
    "open_dataset",
    "parse_scene",
    "permittivity",
    "save",
    "scene_summary",
    "sigma",
    "simulate",
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
class Scene(SceneModel):
    """A validated scene that knows its folder and shows a readable summary.

    The same fields as :class:`seaecho.config.Scene` (every builder takes it); made by
    :func:`load_scene`, :func:`parse_scene` and :func:`with_overrides`. Printed, or shown
    in a notebook, it gives :meth:`summary`. Frozen: change it with
    :func:`with_overrides`.
    """

    _base_dir: Path | None = PrivateAttr(default=None)

    @property
    def base_dir(self) -> Path | None:
        """Folder of the scene file (``[[objects]]`` paths are relative to it), or None."""
        return self._base_dir

    def summary(self) -> str:
        """Sea state, geometry, radar, resolution cells and run size, as text
        (:func:`scene_summary`)."""
        return scene_summary(self).text()

    def _repr_html_(self) -> str:
        return scene_summary(self).html()

    def __repr__(self) -> str:
        try:
            return scene_summary(self).text()
        except Exception as exc:  # a repr must not raise; the fields still say it all
            return f"{super().__repr__()}\n(no summary: {exc})"

    __str__ = __repr__


def _wrap(scene: SceneModel, base_dir: PathLike | None) -> Scene:
    """``scene`` as an API :class:`Scene` (no revalidation: it is valid already)."""
    if isinstance(scene, Scene) and (base_dir is None or scene.base_dir == Path(base_dir)):
        return scene
    out = Scene.model_construct(_fields_set=set(scene.model_fields_set),
                                **{name: getattr(scene, name)
                                   for name in SceneModel.model_fields})
    if base_dir is not None:
        out._base_dir = Path(base_dir)
    elif isinstance(scene, Scene):
        out._base_dir = scene.base_dir
    return out


def load_scene(path: PathLike) -> Scene:
    """Read and validate a TOML scene file.

    Parameters
    ----------
    path : path
        Scene file; ``[[objects]]`` mesh paths are relative to its folder.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        Missing, unreadable or not TOML, or not a valid scene: the message names the
        field (``[sea].wind_speed_m_s``), the value and what is allowed.
    """
    return _wrap(_load_scene(path), Path(path).resolve().parent)


def parse_scene(source: str | Mapping[str, Any], *, base_dir: PathLike | None = None) -> Scene:
    """A scene from TOML text or from a dict (the parsed TOML), validated.

    Parameters
    ----------
    source : str or mapping
        The text of a scene file, or its tables as nested dicts.
    base_dir : path, optional
        Folder that relative ``[[objects]]`` paths start from (default: the working
        directory when a run needs them).

    Raises
    ------
    SceneError
        Not TOML, or not a valid scene (field, value and what is allowed).
    """
    if isinstance(source, str):
        try:
            data = tomllib.loads(source)
        except tomllib.TOMLDecodeError as exc:
            hint = (" (to read a file, use seaecho.load_scene)"
                    if source.strip().endswith(".toml") else "")
            raise SceneError(f"<string>: not valid TOML ({exc}){hint}") from None
        where = "<string>"
    elif isinstance(source, Mapping):
        data, where = dict(source), "<dict>"
    else:
        raise SceneError(f"source: expected TOML text or a dict, got {type(source).__name__}")
    return _wrap(_parse_scene(data, source=where), base_dir)


def with_overrides(scene: SceneModel | Mapping[str, Any],
                   overrides: Mapping[str, Any]) -> Scene:
    """The scene with fields replaced by dotted name, validated like a scene file.

    Parameters
    ----------
    scene : Scene or mapping
        A scene, or the dict of a scene file.
    overrides : mapping of str to value
        ``{"sea.wind_speed_m_s": 8.0, "radar.n_pulses": 16, "targets.0.rcs_m2": 10}``:
        the path of a field through the sections of a scene file, arrays of tables
        indexed by position (:mod:`seaecho.config.overrides`).

    Returns
    -------
    Scene
        A new scene (the input is not changed), with the same folder.

    Raises
    ------
    SceneError
        Unknown name, or a value out of range: the message names the field, the value
        and what is allowed, e.g. ``[sea].wind_speed_m_s = -3.0: Input should be greater
        than 0``.
    """
    base = scene.base_dir if isinstance(scene, Scene) else None
    return _wrap(_with_overrides(scene, overrides), base)


def _base_dir(scene, base_dir: PathLike | None) -> Path:
    if base_dir is not None:
        return Path(base_dir)
    b = getattr(scene, "base_dir", None)
    return b if b is not None else Path(".")


def _scene(scene) -> SceneModel:
    if isinstance(scene, SceneModel):
        return scene
    if isinstance(scene, str | os.PathLike):
        raise SceneError(f"scene = {os.fspath(scene)!r}: expected a Scene; read a file with "
                         "seaecho.load_scene")
    raise SceneError(f"scene: expected a Scene (seaecho.load_scene / parse_scene), got "
                     f"{type(scene).__name__}")


# -------------------------------------------------------------------------- simulation
def first_pulses(scene: SceneModel, n: int) -> SceneModel:
    """The scene limited to its first ``n`` pulses, the sigma-map pulse kept inside
    (``simulate(pulses=n)``, ``--pulses N``)."""
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise SceneError(f"pulses = {n!r}: must be an integer >= 1")
    n = min(n, scene.radar.n_pulses)
    radar = scene.radar.model_copy(update={
        "n_pulses": n, "sigma_map_pulse": min(scene.radar.sigma_map_pulse, n - 1)})
    return scene.model_copy(update={"radar": radar})


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


def _format_bytes(n: float) -> str:
    for unit, size in (("GiB", 2.0**30), ("MiB", 2.0**20), ("KiB", 2.0**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


def simulate(scene: SceneModel, *, path: PathLike | None = None, pulses: int | None = None,
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

    from .build import build_radar, build_simulation, check_scene
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
        try:
            radar = RadarSystem(build_radar(scene))
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
    need = 32.0 * n_p * n_c * n_s
    if scene.radar.sea_clutter:  # static maps: surface (3), sigma0 (4), visibility
        ny, nx = scene.sea.shape
        need += 8.0 * 8 * nx * ny
    if limit is None:
        avail = _available_memory()
        if avail is None:
            return
        limit, source = MEMORY_FRACTION * avail, (
            f"half of the {_format_bytes(avail)} the system has available")
    else:
        if not (isinstance(limit, int | float) and limit > 0):
            raise SceneError(f"max_memory_bytes = {limit!r}: must be a positive number of "
                             "bytes")
        source = "max_memory_bytes"
    if need > limit:
        raise SceneError(
            f"the run holds {n_p} pulses x {n_c} channels x {n_s} samples of raw and "
            f"compressed echoes ({_format_bytes(need)}), more than {_format_bytes(limit)} "
            f"({source}): stream it to a file with simulate(scene, path='run.nc'), or "
            "simulate fewer pulses (pulses=N)")


def open_dataset(path: PathLike) -> xr.Dataset:
    """Open a seaecho file (run, image, surface, facets) lazily, complex variables
    included (h5netcdf), or a run's Zarr store (``*.zarr``). Close it, or use it in a
    ``with`` block."""
    from .io.run import quiet_invalid_netcdf
    from .io.zarr_run import open_run

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
        from .guards import check_image

        guard = check_image  # no Inf, NaN only at the undefined pixels
    with quiet_invalid_netcdf():
        return write_dataset_atomic(dataset, path, guard=guard)


# ------------------------------------------------------------------ stages on their own
def surface(scene: SceneModel, times: ArrayLike | None = None, *,
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


def trace(scene: SceneModel, time: float = 0.0, *, mode: str | None = None,
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


def compare(scene: SceneModel, time: float = 0.0, *, tx_position: ArrayLike | None = None,
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
        area x visibility x sigma_mn [m^2] with the simulation's sea model. Per facet
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
    from .scattering.facet import facet_sigma

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

    def summed(f):
        sig = facet_sigma(f.n_i, f.n_s, f.normal, *sea_model.facet_model, local=f)
        return (f.area * f.visibility) @ sig

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
          phi_s_deg: ArrayLike = 0.0, scene: SceneModel | None = None,
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
        Wave spectrum (``elfouhaily``, ``pierson-moskowitz``, ``jonswap``) and
        spreading (``elfouhaily``, ``longuet-higgins``); default Elfouhaily.
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
                  scene: SceneModel | None = None) -> xr.DataArray:
    """Omnidirectional wavenumber spectrum S(K) of a wind sea (the paper's eq 5 for
    Pierson-Moskowitz; :mod:`seaecho.ocean.spectra` for the others and their sources).

    Parameters
    ----------
    wavenumber_rad_m : float or sequence
        Wavenumbers K > 0 [rad/m].
    wind_speed_m_s : float
        U19.5 [m/s] (default 4.53, the paper's Fig. 3 sea).
    spectrum : str
        ``elfouhaily``, ``pierson-moskowitz`` or ``jonswap``.
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
        return focus(raw, cfg, backend=backend, progress=progress,
                     timings=timings if timings is not None else {})
    except ValueError as exc:  # grid, window, or a dataset that is not a raw run
        where = os.fspath(raw) if isinstance(raw, str | os.PathLike) else "raw dataset"
        raise SceneError(f"{where}: {exc}") from None


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
        (an empty dict for a channel without sea).
    """
    from .imaging.quality import paper_metrics

    if variable not in img:
        raise SceneError(f"variable = {variable!r}: not in the image (has "
                         f"{', '.join(sorted(map(str, img.data_vars)))})")
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
    if "raw" in dataset:
        from .io.figures import run_figures

        return run_figures(dataset, stem)
    if "image_json" in dataset.attrs:
        from .imaging.figures import image_figures

        cfg = json.loads(dataset.attrs["image_json"])
        return image_figures(dataset, stem, cfg["dynamic_range_db"])
    raise SceneError("dataset: neither a run (no 'raw') nor an image (no 'image_json' "
                     "attribute)")


# ----------------------------------------------------------------------------- summary
@dataclass(frozen=True)
class SceneSummary:
    """What a scene will simulate, in sections of (label, text) rows.

    Attributes
    ----------
    title : str
    sections : list of (str, list of (str, str))
        Section name and its rows.
    """

    title: str
    sections: list[tuple[str, list[tuple[str, str]]]] = field(default_factory=list)

    def text(self) -> str:
        """Plain text, one row per line."""
        width = max((len(k) for _, rows in self.sections for k, _ in rows), default=0)
        lines = [self.title]
        for name, rows in self.sections:
            lines.append(f"{name}")
            lines += [f"  {k:<{width}}  {v}" for k, v in rows]
        return "\n".join(lines)

    def html(self) -> str:
        """An HTML table (notebooks)."""
        out = ['<div class="seaecho-scene"><table style="text-align:left">',
               f'<caption style="text-align:left"><b>{escape(self.title)}</b></caption>']
        for name, rows in self.sections:
            out.append(f'<tr><th colspan="2" style="text-align:left">{escape(name)}</th></tr>')
            out += [f'<tr><td style="text-align:left;padding-left:1.5em">{escape(k)}</td>'
                    f'<td style="text-align:left">{escape(v)}</td></tr>' for k, v in rows]
        out.append("</table></div>")
        return "\n".join(out)


def _vec(v) -> str:
    return "(" + ", ".join(f"{float(c):.4g}" for c in v) + ")"


def _si(value: float, unit: str) -> str:
    for prefix, scale in (("G", 1e9), ("M", 1e6), ("k", 1e3), ("", 1.0), ("m", 1e-3),
                          ("u", 1e-6), ("n", 1e-9)):
        if abs(value) >= scale:
            return f"{value / scale:.4g} {prefix}{unit}"
    return f"{value:.4g} {unit}"


def scene_summary(scene: SceneModel) -> SceneSummary:
    """What a scene describes and what simulating it costs.

    Sea: spectrum, wind, water, the expected significant wave height
    H_s = 4 sqrt(int S(K) dK) of the whole spectrum and of the band the tile resolves
    (2 pi / L < K < pi / dx). Geometry at the tile centre, nominal tracks at the middle
    of the acquisition: incidence and grazing angles, ranges, bistatic angle. Radar:
    carrier, waveform, PRF, pulses, channels, and the resolution cells:

    - slant range resolution c / (2 B), and on the ground at the tile centre
      c / (B |grad_h (r_t + r_r)|), the gradient of the bistatic range sum projected on
      the ground: c / (2 B cos psi) monostatic at grazing psi, c / (2 B cos(beta / 2))
      in the bistatic plane (Willis 2005, ch. 8);
    - with a moving monostatic platform, the azimuth resolution lambda R / (2 L) of a
      synthetic aperture L, the flight over the acquisition or, if shorter, the beam's
      footprint lambda R / D for an aperture of length D (Cumming and Wong 2005, ch. 4),
      i.e. D / 2 in stripmap.

    Run: pulses x channels x samples of the receive window and the size of the raw and
    compressed arrays.

    References
    ----------
    N. J. Willis, *Bistatic Radar*, 2nd ed., SciTech, 2005.
    I. G. Cumming and F. H. Wong, *Digital Processing of Synthetic Aperture Radar Data*,
    Artech House, 2005.
    """
    import numpy as np

    from .build import build_radar, sea_spectrum
    from .constants import C0
    from .ocean.twoscale import height_variance

    scene = _scene(scene)
    sea = scene.sea
    title = f"seaecho scene '{scene.name}'" if scene.name else "seaecho scene"
    sections: list[tuple[str, list[tuple[str, str]]]] = []
    about = " ".join(scene.description.split())
    if about:
        sections.append(("About", [("description",
                                    about if len(about) <= 240 else about[:237] + "...")]))

    spec = sea_spectrum(scene)
    lx, ly = sea.size_m
    ny, nx = sea.shape
    dx, dy = lx / nx, ly / ny
    hs = 4.0 * math.sqrt(height_variance(spec, 0.0, 1.0e4))
    hs_tile = 4.0 * math.sqrt(height_variance(spec, 2 * math.pi / max(lx, ly),
                                              math.pi / min(dx, dy)))
    spreading = sea.spreading + (f" (s = {sea.spreading_s:g})"
                                 if sea.spreading == "longuet-higgins" else "")
    rows = [("spectrum", f"{sea.spectrum}, {spreading} spreading"
             + (f", fetch {sea.fetch_m:g} m" if sea.fetch_m else "")),
            ("wind", f"U19.5 = {sea.wind_speed_m_s:g} m/s towards {sea.wind_direction_deg:g} deg"),
            ("expected Hs", f"{hs:.3g} m (whole spectrum), {hs_tile:.3g} m in the tile's band"),
            ("water", f"{sea.temperature_c:g} degC, {sea.salinity_psu:g} psu, "
             + ("deep" if sea.depth_m is None else f"depth {sea.depth_m:g} m")),
            ("tile", f"{lx:g} x {ly:g} m on {nx} x {ny} nodes ({dx:.4g} x {dy:.4g} m), "
             f"{(nx - 1) * (ny - 1) * 2:,} facets")]
    sections.append(("Sea", rows))
    if scene.ship is not None:
        s = scene.ship
        wakes = ["Kelvin" if s.kelvin_wake else None, "turbulent"]
        sections.append(("Ship", [
            ("hull", f"{s.length_m:g} x {s.beam_m:g} m, draft {s.draft_m:g} m at "
             f"{_vec(s.position_m)} m"),
            ("track", f"{s.speed:.3g} m/s ({s.speed_kn:g} kn) heading {s.heading_deg:g} deg; "
             f"{' and '.join(w for w in wakes if w)} wake")]))
    if scene.objects:
        sections.append(("Objects", [(o.name or f"object {i}", f"{o.file}"
                                      + (", echoes" if o.scatterer else ", occludes"))
                                     for i, o in enumerate(scene.objects)]))

    if scene.radar is not None and scene.transmitter is not None:
        from .radar.system import RadarSystem

        r = scene.radar
        model = build_radar(scene)
        radar = RadarSystem(model)
        t_mid = r.start_time_s + 0.5 * (r.n_pulses - 1) / r.prf_hz
        tx = model.tx.nominal_state(np.array([t_mid])).position[0]
        rx = model.rx.nominal_state(np.array([t_mid])).position[0]
        centre = np.zeros(3)
        geo = []
        units = []
        for name, p in (("transmitter", tx), ("receiver", rx)):
            d = p - centre
            rng = float(np.linalg.norm(d))
            inc = math.degrees(math.acos(max(-1.0, min(1.0, d[2] / rng))))
            units.append(-d / rng)  # from the platform towards the centre
            if name == "receiver" and model.rx is model.tx:
                geo.append(("receiver", "the transmitter (monostatic)"))
                break
            geo.append((name, f"{_vec(p)} m: range {rng:.4g} m, incidence {inc:.3g} deg "
                        f"(grazing {90.0 - inc:.3g} deg)"))
        mono = model.rx is model.tx
        if not mono:
            beta = math.degrees(math.acos(float(np.clip(np.dot(units[0], units[1]), -1, 1))))
            geo.append(("bistatic angle", f"{beta:.3g} deg"))
        sections.append((f"Geometry at the tile centre (t = {t_mid:.3g} s)", geo))

        w = r.waveform
        bandwidth = w.bandwidth_hz if w.kind == "lfm" else 1.0 / w.duration_s
        lam = C0 / r.carrier_frequency_hz
        wave = (f"LFM {_si(w.bandwidth_hz, 'Hz')} x {_si(w.duration_s, 's')}"
                if w.kind == "lfm" else f"pulse {_si(w.duration_s, 's')}")
        duration = r.n_pulses / r.prf_hz
        rad = [("carrier", f"{_si(r.carrier_frequency_hz, 'Hz')} (lambda {lam * 100:.3g} cm)"),
               ("waveform", f"{wave}, sampled at {_si(r.sampling_rate_hz, 'Hz')}"),
               ("pulses", f"{r.n_pulses} at PRF {_si(r.prf_hz, 'Hz')} "
                f"({_si(duration, 's')}); sea held {r.sea_update_pulses} pulse(s)"),
               ("channels", " ".join(r.channels)),
               ("sea clutter", "on" if r.sea_clutter else "off")]
        if scene.targets:
            rad.append(("targets", f"{len(scene.targets)} point target(s)"))
        sections.append(("Radar", rad))

        grad = -(units[0] + (units[0] if mono else units[1]))  # grad of r_t + r_r
        gh = float(np.hypot(grad[0], grad[1]))
        res = [("range", f"c / 2B = {C0 / (2 * bandwidth):.3g} m slant")]
        if gh > 1e-9:
            ground = C0 / (bandwidth * gh)
            u = grad[:2] / gh
            across = lx * abs(u[0]) + ly * abs(u[1])
            res[0] = (res[0][0], res[0][1] + f", {ground:.3g} m on the ground: "
                      f"{across / ground:.3g} cells across the tile")
        v = model.tx.nominal_state(np.array([t_mid])).velocity[0]
        if mono and float(np.linalg.norm(v)) > 0:
            los = units[0]
            v_perp = float(np.linalg.norm(v - np.dot(v, los) * los))
            r_c = float(np.linalg.norm(tx))
            aperture = v_perp * duration
            ant = scene.transmitter.antenna
            if ant.pattern == "rectangular":
                aperture = min(aperture, lam * r_c / ant.width_m)
            if aperture > 0:
                res.append(("azimuth", f"lambda R / 2L = {lam * r_c / (2 * aperture):.3g} m "
                            f"(synthetic aperture L = {aperture:.3g} m)"))
        res.append(("sea grid", f"{dx * dy:.3g} m2 per cell, "
                    f"{(nx - 1) * (ny - 1):,} cells"))
        sections.append(("Resolution", res))

        n_s, n_c = radar.window.n_samples, len(radar.channels)
        size = 32.0 * r.n_pulses * n_c * n_s
        run = [("arrays", f"{r.n_pulses} pulses x {n_c} channels x {n_s} samples"),
               ("memory", f"raw + compressed {_format_bytes(size)} (in memory: simulate "
                "without path=); run time not estimated"),
               ("facet mode", f"{scene.tracing.mode}"
                + (f", re-traced every {scene.tracing.refresh_interval_s:g} s"
                   if scene.tracing.mode == "raytraced" and scene.tracing.refresh_interval_s
                   else ""))]
        # The resource model of `seaecho check` (peak memory and run time of a run, from
        # the grid, the channels and the window) belongs here once it is part of seaecho;
        # until then the rows give the size of the arrays the run produces.
        if scene.image is not None:
            run.append(("image", "focused after the run ([image])"))
        sections.append(("Run", run))
    return SceneSummary(title, sections)
