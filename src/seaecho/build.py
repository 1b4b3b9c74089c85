"""The builder: the only code that reads a validated scene.

Everything downstream of the scene file works on frozen, plain-valued stage models (SI
numbers, arrays and small immutable objects) that this module makes from a
:class:`seaecho.config.Scene`; the stages never see the scene or its pydantic sections.

=========================  ===================================  ==========================
function                   reads                                gives (stage model)
=========================  ===================================  ==========================
:func:`sea_spectrum`       ``[sea]``                            ``DirectionalSpectrum``
:func:`build_sea`          ``[sea]``, ``[ship]``, ``[run]``     ``Sea`` (surface + wake)
:func:`carrier_frequency`  ``[radar]`` or an explicit value     carrier [Hz] (no default)
:func:`build_sea_model`    ``[sea]``, carrier                   ``scattering.SeaModel``
:func:`sea_motion`         ``[scattering]``, ``[radar]``        "held" or "evolving"
:func:`build_radar`        ``[radar]``, ``[transmitter]``,      ``radar.RadarModel``
                           ``[receiver]``, ``[[targets]]``
:func:`build_tracing`      ``[tracing]``, ``[[objects]]``,      ``tracing.TracingModel``
                           carrier, ``[sea]`` water
:func:`build_engine`       the above                            ``tracing.FacetEngine``
:func:`build_land`         ``[[land]]``, ``[propagation]``,     ``tracing.land.LandModel``
                           carrier
:func:`build_simulation`   everything                           :class:`SimulationModels`
:func:`check_scene`        ``[sea]``, carrier                   ``SamplingWarning`` s
=========================  ===================================  ==========================

Named constants live with the physics they belong to and are defined once: the two-scale
split ``k_cut = k / 3``, the Bragg roughness band up to ``20 k`` and the small
perturbation bound ``k h <= 0.3`` in :mod:`seaecho.ocean.twoscale`; the wind-height
conversions in :mod:`seaecho.ocean.wind`; the physical constants in
:mod:`seaecho.constants`. A scene without ``[radar]`` has no carrier: the functions that
need one take it explicitly (``frequency``) and raise a ``ValueError`` otherwise.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from .constants import C0
from .geometry.earth import SphericalEarth, effective_radius
from .ocean.seawater import sea_water_permittivity
from .ocean.spectra import DirectionalSpectrum
from .ocean.surface import SeaSurface
from .ocean.twoscale import (
    ROUGHNESS_K_MAX_RATIO,
    TWO_SCALE_CUT_RATIO,
    facet_slope_deficit,
    height_variance,
    unresolved_statistics,
)
from .ocean.wind import u10_from_u19_5
from .radar.antennas import Antenna
from .radar.model import RadarModel, TargetSet
from .radar.platforms import Platform, draw_perturbation
from .radar.pointing import Pointing, Scan
from .radar.propagation import TwoRay
from .radar.waveform import Waveform
from .rng import generator
from .scattering.breaking import breaking_statistics
from .scattering.dynamics import SeaDynamics
from .scattering.facet import TiltQuadrature
from .scattering.sea_model import SeaModel
from .scattering.spectrum_table import BraggSpectrumTable
from .sea import Sea
from .tracing.model import TracingModel
from .wake import Ship

if TYPE_CHECKING:  # pragma: no cover
    from .tracing.engine import FacetEngine

__all__ = [
    "MultistaticModels",
    "SimulationModels",
    "build_multistatic",
    "build_engine",
    "build_radar",
    "build_sea",
    "build_sea_dynamics",
    "build_sea_model",
    "build_ships",
    "receiver_scene",
    "build_simulation",
    "build_tracing",
    "carrier_frequency",
    "check_scene",
    "check_sea",
    "dwell_pulses",
    "platform_positions",
    "scene_attrs",
    "sea_spectrum",
    "sea_motion",
    "section_spectrum",
    "wind_drift",
]


# ----------------------------------------------------------------------------- the sea
def sea_spectrum(scene) -> DirectionalSpectrum:
    """The directional spectrum of ``[sea]`` (degrees -> radians).

    Raises
    ------
    seaecho.config.SceneError
        ``[sea]``'s fetch or depth outside what its spectrum describes
        (:func:`check_sea`).
    """
    check_sea(scene.sea)
    return section_spectrum(scene.sea)


def check_sea(sea) -> None:
    """Raise :class:`~seaecho.config.SceneError` if a ``[sea]`` section's fetch or depth
    is outside what its spectrum describes (:mod:`seaecho.ocean.limits`: the fetch law's
    seas, McCowan's breaking depth). The fetch comes first: the depth check integrates
    the spectrum the fetch sets. Every use of the sea goes through :func:`sea_spectrum`,
    so ``check``, ``surface``, ``run``, ``trace`` and each case of a sweep refuse alike.
    """
    from .config import SceneError
    from .ocean.limits import BREAKING_RATIO, fetch_range, min_depth, significant_height

    # The fetch laws that read fetch_m: the spectrum's (Kudryavtsev et al.'s long waves
    # are Elfouhaily's), and Elfouhaily's spreading's
    own = "elfouhaily" if sea.spectrum == "kudryavtsev" else sea.spectrum
    laws = [own] if own in ("jonswap", "elfouhaily") else []
    if sea.spreading == "elfouhaily" and "elfouhaily" not in laws:
        laws.append("elfouhaily")
    for law in laws if sea.fetch_m is not None else ():
        lo, hi = fetch_range(law, sea.wind_speed_m_s)
        if not lo <= sea.fetch_m <= hi:
            span = f"[{lo:.3g}, {hi:.3g}]" if np.isfinite(hi) else f">= {lo:.3g}"
            what = "spectrum's" if law == own else "spreading's"
            raise SceneError(
                f"[sea].fetch_m = {sea.fetch_m:g}: outside the fetches the {law} {what} "
                f"fetch law describes at U19.5 = {sea.wind_speed_m_s:g} m/s, {span} m "
                "(inverse wave age from 5, a young sea, to 0.84, fully developed: "
                "Elfouhaily et al. 1997); for a fully developed sea use "
                "'pierson-moskowitz', or 'elfouhaily' without fetch_m")
    if sea.depth_m is not None:
        spectrum = section_spectrum(sea)
        if sea.depth_m < min_depth(spectrum):
            h_s = significant_height(spectrum)
            raise SceneError(
                f"[sea].depth_m = {sea.depth_m:g}: shallower than this sea's waves allow, "
                f"H_s / {BREAKING_RATIO} = {h_s / BREAKING_RATIO:.3g} m (H_s = {h_s:.3g} m, "
                "significant height of the spectrum; waves break where H > 0.78 d, "
                "McCowan 1894)")


def section_spectrum(sea) -> DirectionalSpectrum:
    """The directional spectrum of a ``[sea]`` section, unchecked (:func:`sea_spectrum`)."""
    return DirectionalSpectrum(spectrum=sea.spectrum, spreading=sea.spreading,
                               u19_5=sea.wind_speed_m_s,
                               wind_direction=float(np.deg2rad(sea.wind_direction_deg)),
                               fetch=sea.fetch_m, s=sea.spreading_s)


def build_ships(scene) -> tuple[Ship, ...]:
    """The ships of ``[ship]`` or ``[[ships]]`` (wake stage :class:`~seaecho.wake.Ship`,
    with its :class:`~seaecho.wake.ship.Route` when on waypoints), in scene order."""
    from .wake.ship import Route

    cfgs = scene.all_ships
    if not cfgs:
        return ()
    k_b = None
    if scene.radar is not None:
        k_b = _scene_bragg_wavenumber(scene, 2.0 * np.pi * carrier_frequency(scene) / C0)
    out = []
    for cfg, name in zip(cfgs, scene.ship_names(), strict=True):
        route = None
        if cfg.waypoints_m is not None:
            r = cfg.turn_radius
            # a straight route has no corner: any radius serves
            route = Route(tuple(map(tuple, cfg.waypoints_m)), r if np.isfinite(r) else 1.0)
        out.append(Ship(
            length=float(cfg.length_m), beam=float(cfg.beam_m), draft=float(cfg.draft_m),
            speed=float(cfg.speed), heading=float(np.deg2rad(cfg.heading_deg)),
            position0=(float(cfg.position_m[0]), float(cfg.position_m[1])),
            turbulent_wake_length=(None if cfg.turbulent_wake_length_m is None
                                   else float(cfg.turbulent_wake_length_m)),
            wake_amplitude=cfg.wake_amplitude,
            wake_breaking_limit=cfg.wake_breaking_limit,
            turbulent_wake_film_contrast_db=cfg.turbulent_wake_film_contrast_db,
            turbulent_wake_film_elasticity=1e-3 * cfg.turbulent_wake_film_elasticity_mn_m,
            bragg_wavenumber=k_b, route=route, name=name))
    return tuple(out)


def wind_drift(scene) -> str:
    """The drift law of ``[sea] wind_drift`` (``"none"``, ``"3pct"`` or ``"wu"``): the one
    place that resolves ``"auto"``.

    ``"auto"`` is ``"3pct"`` (the total surface drift, 3 % of U10: AMS Glossary of
    Meteorology; Wu 1975; :func:`seaecho.ocean.wind.surface_drift_3pct`) when the sea
    evolves between pulses (:func:`sea_motion` resolves to ``"evolving"``) on a tile, and
    ``"none"`` otherwise: a held sea has no Doppler for a drift to shift (one surface per
    block), ``coverage = "radar"`` has no current yet, and neither has a dynamic hull
    response (``config.consistency``).
    """
    law = scene.sea.wind_drift
    if law != "auto":
        return law
    if (sea_motion(scene) != "evolving" or scene.sea.coverage != "tile"
            or any(s.wave_motion and s.wave_response == "dynamic" for s in scene.all_ships)):
        return "none"
    return "3pct"


def sea_current(scene) -> tuple[float, float]:
    """The uniform surface current of ``[sea]`` (U_x, U_y) [m/s]: ``current_m_s`` plus the
    drift of the law :func:`wind_drift` resolves (:data:`seaecho.ocean.wind.WIND_DRIFT_LAWS`)
    along the wind."""
    from .ocean.wind import WIND_DRIFT_LAWS

    cfg = scene.sea
    ux, uy = (float(u) for u in cfg.current_m_s)
    law = wind_drift(scene)
    if law != "none":
        dx, dy = WIND_DRIFT_LAWS[law](float(u10_from_u19_5(cfg.wind_speed_m_s)),
                                      float(np.deg2rad(cfg.wind_direction_deg)))
        ux, uy = ux + dx, uy + dy
    return ux, uy


def build_sea(scene, spectrum: DirectionalSpectrum | None = None) -> Sea:
    """The sea of a scene: the surface realisation of its seed (``"surface"`` stream) on
    the ``[sea]`` grid, plus the wakes of ``[ship]`` or ``[[ships]]``.

    Parameters
    ----------
    scene : seaecho.config.Scene
    spectrum : DirectionalSpectrum, optional
        ``sea_spectrum(scene)`` if already made.
    """
    cfg = scene.sea
    spectrum = sea_spectrum(scene) if spectrum is None else spectrum
    surface = SeaSurface(spectrum, size=cfg.size_m, shape=cfg.shape,
                         rng=generator(scene.run.seed, "surface"), depth=cfg.depth_m,
                         current=sea_current(scene))
    ships = build_ships(scene)
    kelvin = [bool(c.kelvin_wake) for c in scene.all_ships]
    narrow = [bool(c.narrow_v) for c in scene.all_ships]
    k_b = None
    if any(narrow) and scene.radar is not None:
        k_b = _scene_bragg_vector(scene, 2.0 * np.pi * carrier_frequency(scene) / C0)
    return Sea(surface, list(ships) or None, kelvin_wake=kelvin, narrow_v=narrow,
               narrow_v_bragg_vector=k_b)


def carrier_frequency(scene, frequency: float | None = None) -> float:
    """The radar carrier of a scene [Hz]: ``frequency`` if given, else ``[radar]``'s.

    Raises
    ------
    ValueError
        The scene has no ``[radar]`` and no frequency was given (there is no default
        carrier: the sea's permittivity and its two-scale split depend on it).
    """
    if frequency is not None:
        if not (np.isfinite(frequency) and 1.0e6 < frequency <= 1.0e12):
            raise ValueError(f"frequency = {frequency} Hz: must be in (1e6, 1e12] Hz")
        return float(frequency)
    if scene.radar is None:
        raise ValueError("the scene has no [radar] section: give the carrier frequency "
                         "(e.g. --frequency-ghz) for the sea-water permittivity and the "
                         "two-scale split")
    return float(scene.radar.carrier_frequency_hz)


def build_sea_model(scene, frequency: float | None = None,
                    spectrum: DirectionalSpectrum | None = None) -> SeaModel:
    """The sea as the facet scattering model sees it at the scene's carrier.

    Two bands of the unresolved waves (:mod:`seaecho.ocean.twoscale`): the slope
    variances of k_grid < K < k/3 and the height spectrum of k_grid < K < 20 k,
    tabulated (:class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable`).

    Parameters
    ----------
    scene : seaecho.config.Scene
    frequency : float, optional
        Carrier [Hz]; default ``[radar]``'s (:func:`carrier_frequency`).
    spectrum : DirectionalSpectrum, optional
        ``sea_spectrum(scene)`` if already made.

    Raises
    ------
    ValueError
        No carrier, or a grid so fine that it resolves every wave of the tilting band
        (its spacing below 3 lambda / 2): the sub-facet slope variance would be zero.
    """
    f = carrier_frequency(scene, frequency)
    spectrum = sea_spectrum(scene) if spectrum is None else spectrum
    cfg = scene.sea
    k = 2.0 * np.pi * f / C0
    lx, ly = cfg.size_m
    ny, nx = cfg.shape
    dx, dy = lx / nx, ly / ny
    k_cut = TWO_SCALE_CUT_RATIO * k
    k_max = ROUGHNESS_K_MAX_RATIO * k
    band = unresolved_statistics(spectrum, dx, dy, k_cut)
    if not (band.mss_upwind > 0 and band.mss_crosswind > 0) and band.k_grid < k_cut:
        raise ValueError(
            f"[sea]: the unresolved waves between the grid's {2 * np.pi / band.k_grid:.4g} m "
            f"and the two-scale split 2 pi / k_cut = {2 * np.pi / k_cut:.4g} m at "
            f"{f / 1e9:g} GHz carry no slope (U19.5 = {cfg.wind_speed_m_s:g} m/s"
            + (f", fetch {cfg.fetch_m:g} m" if cfg.fetch_m is not None else "")
            + "): the facets would have no sub-facet slopes; a stronger wind, a longer "
            "fetch, or a coarser grid")
    if not (band.mss_upwind > 0 and band.mss_crosswind > 0):
        raise ValueError(
            f"[sea] grid spacing {max(dx, dy):.4g} m resolves every wave longer than the "
            f"two-scale split 2 pi / k_cut = {2 * np.pi / k_cut:.4g} m at "
            f"{f / 1e9:g} GHz: the facets carry no sub-facet slopes; use a spacing above "
            f"{np.pi / k_cut:.4g} m")
    eps_r = complex(sea_water_permittivity(f, cfg.temperature_c, cfg.salinity_psu))
    table = _bragg_table(spectrum, band.k_grid, float(k_max))
    opts = scene.scattering
    mss_u, mss_c = band.mss_upwind, band.mss_crosswind
    quadrature = None
    if opts.unresolved_tilt:
        # Two scales done right: the sub-facet slopes are those the facets do not carry,
        # the band above the grid's Nyquist wavenumber plus the resolved waves that the
        # facets' normals filter out (eq U1), and the Bragg term is averaged over them
        # (eq P6).
        normals = "mesh" if scene.tracing.mode == "raytraced" else "vertex-mean"
        du, dc = facet_slope_deficit(spectrum, cfg.size_m, cfg.shape, normals)
        # the mesh's finite differences can give the facets more slope across the wind
        # than the surface has (a deficit < 0, off the grid's axes): sub-facet slopes
        # can add none then, not less than none
        mss_u, mss_c = max(mss_u + du, 0.0), max(mss_c + dc, 0.0)
        quadrature = TiltQuadrature.unscented(mss_u, mss_c)
    breaking = None
    u10 = float(u10_from_u19_5(cfg.wind_speed_m_s))
    if opts.model == "blend+breaking":
        breaking = breaking_statistics(u10, float(k))
    dynamics = None
    if sea_motion(scene) == "evolving":
        dynamics = build_sea_dynamics(scene, spectrum, float(k), band.k_grid, float(k_cut),
                                      u10)
    return SeaModel(frequency=f, k=float(k), eps_r=eps_r,
                    wind_direction=float(spectrum.wind_direction), k_grid=band.k_grid,
                    k_cut=float(k_cut), k_max=float(k_max), mss_upwind=mss_u,
                    mss_crosswind=mss_c,
                    roughness_height_variance=height_variance(spectrum, band.k_grid, k_max),
                    bragg_spectrum=table, tilt=quadrature, breaking=breaking,
                    dynamics=dynamics)


@functools.lru_cache(maxsize=8)
def _bragg_table(spectrum: DirectionalSpectrum, k_min: float, k_max: float
                 ) -> BraggSpectrumTable:
    """The sea state's tabulated height spectrum on ``k_min <= K <= k_max`` [rad/m] (eq
    T2 of :mod:`seaecho.scattering.spectrum_table`), made once per process for the same
    (frozen) spectrum and band: a table is never modified after it is made, and making it
    evaluates the spectrum at 368 640 wavenumbers, most of :func:`build_sea_model`'s time
    on a small grid (a run and its check, a multistatic scene's receivers, the seeds of
    one sea state each build the same table)."""
    return BraggSpectrumTable(spectrum.height_spectrum, k_min=k_min, k_max=k_max)


def sea_motion(scene) -> str:
    """The sea's motion between surface updates, ``"held"`` or ``"evolving"``: the one
    place that resolves ``[scattering] sea_motion = "auto"`` (everything downstream sees
    only the two concrete values).

    ``"auto"`` is ``"evolving"`` when the sea is renewed within the run,
    ``[radar] sea_update_pulses < n_pulses``: a held sea would then be frozen within
    each block and independent from one block to the next, i.e. clutter whose Doppler
    spectrum is white over the PRF (renewed every pulse) or a comb of the block rate,
    where real sea clutter has a Bragg-shifted spectrum a few tens of hertz wide at X band
    (docs/dynamics.md). It is ``"held"`` when one surface serves every pulse
    (``sea_update_pulses >= n_pulses``: the paper's SAR scenes hold the sea for the
    aperture, its section V-B), without ``[radar]`` and without sea clutter. A scene with
    ``[[receivers]]`` is held too: the evolving sea of several receivers is not
    implemented yet (its Bragg lifetimes depend on each pair's Bragg wavenumber).
    """
    motion = scene.scattering.sea_motion
    if motion != "auto":
        return motion
    r = scene.radar
    if (r is None or not r.sea_clutter or r.sea_update_pulses >= r.n_pulses
            or getattr(scene, "receivers", ())):
        return "held"
    return "evolving"


def _scene_bragg_wavenumber(scene, k: float) -> float:
    """Mean-plane Bragg wavenumber at the tile centre at the first pulse [rad/m]
    (``k |(n_s - n_i)_h|``; 2 k sin 45 deg without a transmitter, or with a platform at
    the tile centre; with ``[[receivers]]``, the first receiver's pair)."""
    return float(np.hypot(*_scene_bragg_vector(scene, k)))


def _scene_bragg_vector(scene, k: float) -> tuple[float, float]:
    """Mean-plane Bragg vector ``k (n_s - n_i)_h`` at the tile centre at the first pulse
    [rad/m]; (2 k sin 45 deg, 0) without a transmitter, or with a platform at the tile
    centre (no direction to it); with ``[[receivers]]``, the first receiver's pair."""
    if scene.transmitter is None:
        return float(2.0 * k * np.sin(np.pi / 4)), 0.0
    if scene.receivers:  # the first pair's (each receiver's own: build_multistatic)
        scene = receiver_scene(scene, 0)
    tx, rx = _platforms(scene)
    t0 = scene.radar.start_time_s if scene.radar is not None else 0.0
    p_tx, p_rx = tx.state(t0).position, rx.state(t0).position
    r_tx, r_rx = np.linalg.norm(p_tx), np.linalg.norm(p_rx)
    if not (r_tx > 0.0 and r_rx > 0.0):  # a platform at the tile centre (the preflight
        return float(2.0 * k * np.sin(np.pi / 4)), 0.0  # refuses it): no direction to it
    n_i, n_s = -p_tx / r_tx, p_rx / r_rx
    q = k * (n_s - n_i)[:2]
    return float(q[0]), float(q[1])


def build_sea_dynamics(scene, spectrum: DirectionalSpectrum, k: float, k_grid: float,
                       k_cut: float, u10: float) -> SeaDynamics:
    """The evolving speckle's parameters (:mod:`seaecho.scattering.dynamics`, eqs D2-D8):
    lifetimes of the Bragg waves (at the scene's mean Bragg wavenumber), of the specular
    points (tilting band) and of the breakers; the tilting band's orbital velocity
    covariance; the breakers' velocity; the travel-direction split of the Bragg waves."""
    from .ocean.twoscale import mean_wave_period, orbital_velocity_covariance
    from .scattering.dynamics import bragg_lifetime, travel_fraction

    stats = breaking_statistics(u10, k)
    depth = scene.sea.depth_m
    lifetimes = {
        "specular": mean_wave_period(spectrum, k_grid, k_cut, "slope", depth),
        "bragg+": bragg_lifetime(_scene_bragg_wavenumber(scene, k), u10),
        "bragg-": bragg_lifetime(_scene_bragg_wavenumber(scene, k), u10),
        "breaking": max(stats.mean_period, 1e-3),
    }
    w = float(spectrum.wind_direction)
    travel = BraggSpectrumTable(lambda kx, ky: travel_fraction(spectrum, kx, ky, u10),
                                k_min=k_grid, k_max=ROUGHNESS_K_MAX_RATIO * k, n_k=256,
                                n_psi=180)
    return SeaDynamics(lifetimes=lifetimes,
                       velocity_covariance=orbital_velocity_covariance(spectrum, k_grid,
                                                                       k_cut, depth),
                       breaker_velocity=stats.mean_velocity * np.array(
                           [np.cos(w), np.sin(w), 0.0]),
                       travel=travel, current=sea_current(scene))


def check_scene(scene, frequency: float | None = None) -> None:
    """Warn (``SamplingWarning``) when the scene's tile or grid is too coarse.

    The tile must hold the spectral peak and resolve its -3 dB band (paper section IV-A);
    with a carrier (``frequency`` or ``[radar]``'s) the Bragg roughness must keep
    k h <= 0.3 (:func:`seaecho.ocean.sampling.check_sampling`).
    """
    from .ocean.sampling import check_sampling

    f = frequency
    if f is None and scene.radar is not None:
        f = scene.radar.carrier_frequency_hz
    check_sampling(sea_spectrum(scene), scene.sea.size_m, scene.sea.shape, f)


# ---------------------------------------------------------------------------- the radar
def _platform(cfg, seed: int, stream_index: int, t_span: tuple[float, float],
              earth: SphericalEarth | None = None) -> Platform:
    """Platform of a ``[transmitter]`` / ``[receiver]`` section (perturbation drawn from
    the ``"platform"`` stream, index 0 for the transmitter, 1 for the receiver)."""
    if cfg.motion == "fixed":
        times = np.array([0.0])
        positions = np.array([cfg.position_m], dtype=float)
    elif cfg.motion == "linear":
        times = np.array([0.0, 1.0])
        p0 = np.array(cfg.position_m, dtype=float)
        positions = np.stack([p0, p0 + np.array(cfg.velocity_m_s, dtype=float)])
    else:
        times = np.array(cfg.waypoint_times_s, dtype=float)
        positions = np.array(cfg.waypoint_positions_m, dtype=float)
    pert = None
    g = cfg.perturbation
    if g is not None:
        pert = draw_perturbation(t_span, generator(seed, "platform", stream_index),
                                 step=g.step_s, position_sigma=g.position_sigma_m,
                                 position_tau=g.position_tau_s,
                                 attitude_sigma=np.deg2rad(g.attitude_sigma_deg),
                                 attitude_tau=g.attitude_tau_s)
    yaw = None if cfg.yaw_deg is None else float(np.deg2rad(cfg.yaw_deg))
    return Platform(times, positions, yaw=yaw, pitch=float(np.deg2rad(cfg.pitch_deg)),
                    roll=float(np.deg2rad(cfg.roll_deg)), perturbation=pert, earth=earth)


def _antenna(cfg, wavelength: float) -> Antenna:
    return Antenna(cfg.pattern, wavelength, cfg.width_m, cfg.height_m, cfg.basis,
                   cfg.cross_polar_isolation_db, cfg.illumination, cfg.taylor_sidelobe_db,
                   cfg.taylor_nbar)


def build_earth(scene) -> SphericalEarth | None:
    """The ``[propagation]`` Earth: a :class:`SphericalEarth` of radius k a, or None
    (flat)."""
    p = scene.propagation
    if p.earth == "flat":
        return None
    return SphericalEarth(effective_radius(p.earth_radius_factor))


def build_antennas(scene) -> tuple[Antenna, Antenna]:
    """(transmit, receive) antennas of a scene's ``[transmitter]`` / ``[receiver]``
    (the transmitter's for a monostatic scene), at the ``[radar]`` carrier."""
    wavelength = C0 / carrier_frequency(scene)
    rx = scene.transmitter if scene.receiver is None else scene.receiver
    return _antenna(scene.transmitter.antenna, wavelength), _antenna(rx.antenna, wavelength)


def _pointing(cfg, platform: Platform, t_ref: float) -> Pointing:
    scan = cfg.scan
    if scan.mode == "rotating":
        return Pointing(scan=Scan("rotating", 2.0 * np.pi * scan.rate_rpm / 60.0,
                                  float(np.deg2rad(cfg.depression_deg)),
                                  start=float(np.deg2rad(scan.start_deg or 0.0))))
    if scan.mode == "sector":
        return Pointing(scan=Scan.sector(2.0 * np.pi * scan.rate_rpm / 60.0,
                                         float(np.deg2rad(cfg.depression_deg)),
                                         *np.deg2rad(scan.sector_deg)))
    if cfg.look_at_m is not None:
        return Pointing.aimed_at(cfg.look_at_m, platform, t_ref, track=cfg.track_look_at)
    return Pointing.by_angles(float(np.deg2rad(cfg.azimuth_deg)),
                              float(np.deg2rad(cfg.depression_deg)))


def _platforms(scene, receiver_stream: int = 1) -> tuple[Platform, Platform]:
    """(transmitter, receiver); the same object twice when monostatic. Perturbations
    cover the pulses of ``[radar]`` (plus 1 ms), or t = 0 without a radar; the
    receiver's is drawn from ``"platform"`` stream index ``receiver_stream``."""
    if scene.transmitter is None:
        raise ValueError("the scene has no [transmitter] section")
    if scene.receivers:
        raise ValueError(f"the scene has {len(scene.receivers)} [[receivers]]: take one "
                         "receiver's bistatic scene (receiver_scene(scene, i))")
    t_span = (0.0, 0.0)
    if scene.radar is not None:
        r = scene.radar
        t_span = (r.start_time_s, r.start_time_s + (r.n_pulses - 1) / r.prf_hz + 1.0e-3)
    seed = scene.run.seed
    earth = build_earth(scene)
    tx = _platform(scene.transmitter, seed, 0, t_span, earth)
    if scene.receiver is None:
        return tx, tx
    return tx, _platform(scene.receiver, seed, receiver_stream, t_span, earth)


def dwell_pulses(scene) -> int:
    """Pulses per dwell of the fluctuating targets (Swerling 1 and 3 draw once per
    dwell): ``[radar] cpi_pulses``, default every pulse of the run. The one place that
    decides what a dwell is (a scanning antenna would take its scan period here)."""
    r = scene.radar
    return int(r.cpi_pulses) if r.cpi_pulses is not None else int(r.n_pulses)


def _targets(scene) -> TargetSet | None:
    if not scene.targets:
        return None
    t = scene.targets
    f = scene.radar.carrier_frequency_hz
    return TargetSet(positions=np.array([g.position_m for g in t], dtype=float).reshape(-1, 3),
                     velocities=np.array([g.velocity_m_s for g in t], dtype=float).reshape(-1, 3),
                     scattering=np.stack([g.scattering_matrix(f) for g in t]).astype(complex),
                     names=tuple(g.name or f"target{i}" for i, g in enumerate(t)),
                     swerling=np.array([g.swerling_case for g in t], dtype=np.int64),
                     dwell_pulses=dwell_pulses(scene), seed=int(scene.run.seed))


def build_radar(scene, *, receiver_stream: int = 1) -> RadarModel:
    """The radar of ``[radar]``, ``[transmitter]``, ``[receiver]`` and ``[[targets]]``.

    ``receiver_stream`` is the ``"platform"`` stream index of the receiver's perturbation
    (1; receiver i of ``[[receivers]]`` has 1 + i, :func:`build_multistatic`).

    Raises
    ------
    ValueError
        The scene lacks ``[radar]`` or ``[transmitter]``.
    """
    if scene.radar is None or scene.transmitter is None:
        raise ValueError("the scene needs [radar] and [transmitter] sections")
    r = scene.radar
    if scene.receivers:
        raise ValueError("a scene with [[receivers]] has one radar per receiver: "
                         "build_multistatic (or build_radar(receiver_scene(scene, i)))")
    tx, rx = _platforms(scene, receiver_stream)
    mono = rx is tx
    wavelength = C0 / r.carrier_frequency_hz
    w = r.waveform
    if w.kind == "lfm":
        waveform = Waveform.lfm(w.bandwidth_hz, w.duration_s, r.sampling_rate_hz, w.up_chirp)
    else:
        waveform = Waveform.pulse(w.duration_s, r.sampling_rate_hz)
    rx_cfg = scene.transmitter if mono else scene.receiver
    window = None if r.window_start_m is None else (r.window_start_m, r.window_end_m)
    land = land_window_points(scene)
    if land is not None and build_earth(scene) is not None:
        land = build_earth(scene).position(land)
    return RadarModel(
        window_points=land,
        carrier=r.carrier_frequency_hz, sampling_rate=r.sampling_rate_hz, prf=r.prf_hz,
        n_pulses=r.n_pulses, start_time=r.start_time_s, transmit_power=r.transmit_power_w,
        waveform=waveform, tx=tx, rx=rx,
        tx_antenna=_antenna(scene.transmitter.antenna, wavelength),
        rx_antenna=_antenna(rx_cfg.antenna, wavelength),
        tx_pointing=_pointing(scene.transmitter.antenna, tx, r.start_time_s),
        rx_pointing=_pointing(rx_cfg.antenna, rx, r.start_time_s),
        channels=tuple(r.channels), noise_figure_db=r.noise_figure_db,
        noise_bandwidth=r.noise_bandwidth_hz or r.sampling_rate_hz,
        thermal_noise=r.thermal_noise, window_m=window,
        tile_size=tuple(scene.sea.size_m), sea_clutter=r.sea_clutter,
        targets=_targets(scene), seed=scene.run.seed, range_weighting=r.range_weighting,
        taylor_nbar=r.taylor_nbar, taylor_sidelobe_db=r.taylor_sidelobe_db,
        sea_update_pulses=r.sea_update_pulses, sigma_map_pulse=r.sigma_map_pulse,
        accumulation_precision=r.accumulation_precision, earth=build_earth(scene),
        transmit_phase=r.transmit_phase, multipath=build_multipath(scene),
        sea_gain_floor=(None if r.sea_gain_floor_db == "off"
                        else 10.0 ** (r.sea_gain_floor_db / 10.0)))


# -------------------------------------------------------------------------- the facets
def build_tracing(scene, base_dir: str | os.PathLike = ".", *, frequency: float | None = None,
                  mode: str | None = None, variant: str | None = None,
                  sea_model: SeaModel | None = None) -> TracingModel:
    """Facet mode, shadowing and occluders of ``[tracing]`` and ``[[objects]]``.

    Parameters
    ----------
    scene : seaecho.config.Scene
    base_dir : path
        Folder of the scene file (``[[objects]]`` paths are relative to it).
    frequency : float, optional
        Carrier [Hz] (:func:`carrier_frequency`): the sea-water material, and the
        tilting band of the sub-facet shadowing.
    mode, variant : str, optional
        Override ``[tracing] mode`` / ``variant``.
    sea_model : SeaModel, optional
        ``build_sea_model(scene, frequency)`` if already made (sub-facet shadowing).
    """
    from .tracing.scene import load_object

    cfg = scene.tracing
    mode = cfg.mode if mode is None else mode
    variant = cfg.variant if variant is None else variant
    f = carrier_frequency(scene, frequency)
    objects: list = []
    if mode == "raytraced":
        for o in scene.objects:
            objects += load_object(o, base_dir=str(base_dir), ship=scene.ship,
                                   variant=variant)
        land = build_land(scene, frequency=f)  # the coastline occludes the sea too
        if land is not None:
            objects += [p.geometry() for p in land.pieces]
    subfacet = None
    if cfg.subfacet_shadowing:
        sm = build_sea_model(scene, f) if sea_model is None else sea_model
        subfacet = sm.subfacet
    eps_r = (sea_model.eps_r if sea_model is not None else
             complex(sea_water_permittivity(f, scene.sea.temperature_c,
                                            scene.sea.salinity_psu)))
    return TracingModel(mode=mode, shadowing=cfg.shadowing,
                        refresh_interval_s=cfg.refresh_interval_s,
                        variant=variant,
                        objects=tuple(objects), frequency=f, eps_r=eps_r, subfacet=subfacet,
                        periodic_apron=cfg.periodic_apron)


def platform_positions(scene, radar: RadarModel | None = None,
                       tx_position: Any = None, rx_position: Any = None
                       ) -> tuple[Callable[[float], np.ndarray],
                                  Callable[[float], np.ndarray] | None]:
    """(tx, rx) position functions ``t -> (3,)`` [m] of the scene's platforms, or of
    fixed positions that replace them (``rx_position`` None with ``tx_position``:
    monostatic)."""
    if tx_position is not None:
        p_tx = np.asarray(tx_position, dtype=np.float64).reshape(3)
        p_rx = None if rx_position is None else np.asarray(rx_position,
                                                           dtype=np.float64).reshape(3)
        return (lambda t: p_tx), (None if p_rx is None else (lambda t: p_rx))
    if scene.transmitter is None:
        raise ValueError("the scene has no [transmitter]: facets need a transmitter")
    tx, rx = (radar.tx, radar.rx) if radar is not None else _platforms(scene)
    tx_fn = lambda t: tx.state(t).position  # noqa: E731
    rx_fn = None if rx is tx else (lambda t: rx.state(t).position)
    return tx_fn, rx_fn


def build_engine(scene, surface: Callable[[float], object], base_dir: str | os.PathLike = ".",
                 *, tracing: TracingModel | None = None, radar: RadarModel | None = None,
                 frequency: float | None = None, mode: str | None = None,
                 variant: str | None = None, tx_position: Any = None,
                 rx_position: Any = None, sea_model: SeaModel | None = None) -> FacetEngine:
    """The :class:`~seaecho.tracing.engine.FacetEngine` of a scene on a surface provider.

    Parameters
    ----------
    scene : seaecho.config.Scene
    surface : callable
        ``t -> SurfaceState`` (e.g. ``build_sea(scene).state``).
    base_dir : path
        Folder of the scene file.
    tracing : TracingModel, optional
        ``build_tracing(...)`` if already made (then ``frequency``, ``mode``,
        ``variant`` are ignored).
    radar : RadarModel, optional
        Its platforms give the positions (else they are built from the scene).
    frequency, mode, variant, sea_model
        As for :func:`build_tracing`.
    tx_position, rx_position : (3,) arrays, optional
        Fixed positions [m] replacing the scene's platforms.
    """
    from .tracing.engine import FacetEngine

    if tracing is None:
        tracing = build_tracing(scene, base_dir, frequency=frequency, mode=mode,
                                variant=variant, sea_model=sea_model)
    tx_fn, rx_fn = platform_positions(scene, radar, tx_position, rx_position)
    return FacetEngine.from_model(tracing, surface, tx_fn, rx_fn)


# ---------------------------------------------------------------------- the simulation
def scene_attrs(scene) -> dict[str, Any]:
    """Dataset attributes that say how a file was made: the full scene (JSON), the
    package version and the seed (:func:`seaecho.io.dataset.scene_attrs`)."""
    from .io.dataset import scene_attrs as attrs

    return attrs(scene)


def land_window_points(scene) -> np.ndarray | None:
    """The points of the echoing ``[[land]]`` that the automatic receive window covers, in
    the scene's coordinates [m], (K, 3): each outline vertex at the sea level and at the
    land's height (its echo lies between them); None without echoing land."""
    pts = [np.concatenate([np.column_stack([np.asarray(g.outline_m, dtype=float),
                                            np.full(len(g.outline_m), z)])
                           for z in (0.0, g.height_m)]) for g in scene.land if g.echo]
    return np.concatenate(pts) if pts else None


def build_land(scene, *, frequency: float | None = None):
    """The ``[[land]]`` of a scene (:class:`seaecho.tracing.land.LandModel`), or None.

    Each entry's mesh (:func:`seaecho.geometry.land.land_mesh`, eq G1) is mapped onto
    the spherical Earth (eq E4) where the scene has one; its gamma is the given
    ``gamma_db`` or the terrain's at the carrier (eq L3 of
    :mod:`seaecho.scattering.land`).
    """
    if not scene.land:
        return None
    from .geometry.land import land_mesh
    from .scattering.land import terrain_gamma_db
    from .tracing.land import PATCH_CELLS, LandModel, LandPiece

    earth = build_earth(scene)
    f = carrier_frequency(scene, frequency)
    pieces = []
    for cfg in scene.land:
        v, faces, cells = land_mesh(cfg.outline_m, cfg.height_m, cfg.shore_width_m,
                                    cfg.resolution_m)
        if earth is not None:
            v = earth.position(v)
        gamma_db = (cfg.gamma_db if cfg.gamma_db is not None
                    else terrain_gamma_db(cfg.terrain, f))
        patch = (cells[:, 0] // PATCH_CELLS) * (1 << 31) + cells[:, 1] // PATCH_CELLS
        pieces.append(LandPiece(cfg.name, v, faces, patch, float(10.0 ** (gamma_db / 10.0)),
                                float(cfg.weibull_shape), bool(cfg.echo),
                                np.asarray(cfg.outline_m, dtype=np.float64)))
    return LandModel(pieces=tuple(pieces), earth=earth)


def _box_motion(cfg):
    """The dynamic wave response of a ``[[ships]]`` hull (None unless wave_motion with
    wave_response = "dynamic"; :class:`seaecho.targets.motion.BoxHullMotion`)."""
    if not (cfg.wave_motion and cfg.wave_response == "dynamic"):
        return None
    from .targets.motion import BoxHullMotion

    return BoxHullMotion(float(cfg.length_m), float(cfg.beam_m), float(cfg.draft_m),
                         cfg.metacentric_height)


def build_hulls(scene, base_dir: str | os.PathLike = ".", *, frequency: float | None = None,
                variant: str | None = None):
    """The hull model of the ``[[objects]]`` with ``scatterer = true``
    (:class:`seaecho.tracing.hull_echo.HullModel`), or None when none scatters.

    Every object is loaded (the others occlude the scatterers' rays); the sea's
    permittivity and rms height (waves up to twice the radar wavenumber) set the
    reflection of the multipath legs (docs/ship.md).
    """
    ship_hulls = [(c, n) for c, n in zip(scene.all_ships, scene.ship_names(), strict=True)
                  if c.hull_echo]
    if not any(o.scatterer for o in scene.objects) and not ship_hulls:
        return None
    from .config.tracing import ObjectConfig
    from .tracing.hull_echo import HullModel, HullOptions
    from .tracing.scene import ObjectGeometry, load_mesh_file, load_object, rotation_matrix

    f = carrier_frequency(scene, frequency)
    objects = []
    defaults = ObjectConfig.model_fields
    tracks = {s.name: s for s in build_ships(scene) if s.route is not None}
    for cfg, name in ship_hulls:  # [[ships]] hull_echo: the ship's own (or generic) hull
        if cfg.hull_mesh is not None:
            path = cfg.hull_mesh if os.path.isabs(cfg.hull_mesh) else os.path.join(
                str(base_dir), cfg.hull_mesh)
            v, fc = load_mesh_file(path, f"[[ships]] {name}: hull_mesh")
        else:
            from .geometry.vessel import vessel_mesh

            v, fc = vessel_mesh(cfg.length_m, cfg.beam_m, cfg.draft_m)
        track = tracks.get(name)  # on waypoints: the route carries and turns the hull
        h = float(np.deg2rad(cfg.heading_deg)) if track is None else float(track.heading)
        p0 = cfg.position_m if track is None else track.position0
        shape = ObjectGeometry(
            name, np.asarray(v, dtype=np.float64), np.asarray(fc, dtype=np.uint32),
            np.array([p0[0], p0[1], 0.0]), rotation_matrix(h, 0.0, 0.0),
            cfg.speed * np.array([np.cos(h), np.sin(h), 0.0]))
        spec = HullOptions(name=name,
                           rays_per_wavelength=(
                               defaults["rays_per_wavelength"].default
                               if cfg.hull_rays_per_wavelength is None
                               else float(cfg.hull_rays_per_wavelength)),
                           max_bounces=defaults["max_bounces"].default,
                           cell_m=defaults["signature_cell_m"].default,
                           sea_multipath=defaults["sea_multipath"].default,
                           refresh_deg=defaults["signature_refresh_deg"].default,
                           refresh_s=defaults["signature_refresh_s"].default,
                           waterplane=((float(cfg.length_m), float(cfg.beam_m))
                                       if cfg.wave_motion else None),
                           track=track, motion=_box_motion(cfg))
        objects.append((spec, [shape]))
    for cfg in scene.objects:
        shapes = load_object(cfg, base_dir=str(base_dir), ship=scene.ship, variant=variant)
        spec = None
        if cfg.scatterer:
            spec = HullOptions(name=cfg.name, rays_per_wavelength=cfg.rays_per_wavelength,
                               max_bounces=cfg.max_bounces, cell_m=cfg.signature_cell_m,
                               sea_multipath=cfg.sea_multipath,
                               refresh_deg=cfg.signature_refresh_deg,
                               refresh_s=cfg.signature_refresh_s)
        objects.append((spec, shapes))
    land = build_land(scene, frequency=f)  # the coastline occludes the hulls' rays
    if land is not None:
        objects += [(None, [p.geometry()]) for p in land.pieces]
    eps_sea, sigma_h = sea_mirror(scene, f)
    return HullModel(objects=tuple(objects), sea_eps_r=eps_sea, sigma_h=sigma_h,
                     earth=build_earth(scene))


def sea_mirror(scene, f: float) -> tuple[complex, float]:
    """The sea as a mirror at carrier f [Hz]: sea water's permittivity eps_r [-]
    (:func:`seaecho.ocean.seawater.sea_water_permittivity`) and the rms height sigma_h
    [m] of the waves up to 2 k (the scene's spectrum; Hs / 4), for the hulls' SBR
    multipath and the two-ray factor (``[propagation] multipath``)."""
    sea = scene.sea
    eps_sea = complex(sea_water_permittivity(f, sea.temperature_c, sea.salinity_psu))
    k = 2.0 * np.pi * f / C0
    sigma_h = float(np.sqrt(height_variance(sea_spectrum(scene), 0.0, 2.0 * k)))
    return eps_sea, sigma_h


def sea_slope_covariance(scene, f: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """Covariance of the slopes (dz/dx, dz/dy) [-] of the waves up to 2 k at carrier f
    [Hz] (the band of :func:`sea_mirror`'s sigma_h), in the scene's frame: the upwind and
    crosswind variances (:func:`seaecho.ocean.twoscale.slope_variances`) turned to the
    wind's direction, for the shadowing of the two-ray factor's reflected legs."""
    from .ocean.twoscale import slope_variances

    spec = sea_spectrum(scene)
    up, cross = slope_variances(spec, 0.0, 2.0 * (2.0 * np.pi * f / C0))
    c, s = np.cos(spec.wind_direction), np.sin(spec.wind_direction)
    cxy = (up - cross) * c * s
    return ((up * c * c + cross * s * s, cxy), (cxy, up * s * s + cross * c * c))


def build_multipath(scene) -> TwoRay | None:
    """The ``[propagation] multipath`` two-ray factor (:mod:`seaecho.radar.propagation`)
    of a scene with ``[radar]``: None for ``"none"``; its reflected legs shadowed by the
    waves with ``multipath_shadowing``."""
    if scene.propagation.multipath == "none":
        return None
    f = scene.radar.carrier_frequency_hz
    eps_sea, sigma_h = sea_mirror(scene, f)
    earth = build_earth(scene)
    slopes = (sea_slope_covariance(scene, f) if scene.propagation.multipath_shadowing
              else None)
    return TwoRay(wavelength=C0 / f, eps_r=eps_sea, sigma_h=sigma_h,
                  radius=np.inf if earth is None else earth.radius, slope_cov=slopes)


@dataclass(frozen=True)
class SimulationModels:
    """Everything a :class:`seaecho.simulation.Simulation` needs, built from a scene.

    Attributes
    ----------
    radar : RadarModel
    sea : Sea or None
        The sea (None when ``[radar] sea_clutter`` is off).
    sea_model : SeaModel or None
        Its radar-frequency view.
    tracing : TracingModel or None
        Facet mode and occluders.
    attrs : dict
        Dataset attributes that say how the output was made (scene JSON, version, seed).
    variant : str or None
        Mitsuba variant of the Dr.Jit kernels and the tracer (``[tracing] variant``).
    hulls : seaecho.tracing.hull_echo.HullModel or None
        The objects that echo (``scatterer = true``), None when none does.
    ships : tuple of seaecho.wake.Ship
        The ships of ``[ship]`` / ``[[ships]]`` (ground truth; their wakes are the sea's).
    land : seaecho.tracing.land.LandModel or None
        The ``[[land]]`` (occluders and land clutter), None when there is none.
    """

    radar: RadarModel
    sea: Sea | None
    sea_model: SeaModel | None
    tracing: TracingModel | None
    attrs: dict
    variant: str | None = None
    hulls: object = None
    ships: tuple = ()
    land: object = None
    #: the radar-wide sea (:class:`CoverageModel`) of ``[sea] coverage = "radar"``, else
    #: None (then ``sea`` is the one tile)
    coverage: object = None


def build_simulation(scene, base_dir: str | os.PathLike = ".") -> SimulationModels:
    """The stage models of a scene's radar simulation.

    Warns (``SPMValidityWarning``) when the Bragg roughness of the grid's unresolved
    waves has k h > 0.3 (:func:`check_scene` says the same with a suggested spacing).

    Raises
    ------
    ValueError
        ``[tracing] variant`` cannot run here (a CUDA variant without a CUDA GPU, or a
        back end other than the one Mitsuba already runs in this process):
        :func:`seaecho.backend.check_variant`, at the start rather than mid-run.
    """
    from .backend import check_variant
    from .scattering.twoscale import check_spm_validity

    try:
        variant = check_variant(scene.tracing.variant)
    except ValueError as exc:
        raise ValueError(f"[tracing].variant: {exc}") from None
    radar = build_radar(scene)
    sea = sea_model = tracing = coverage = None
    if radar.sea_clutter and scene.sea.coverage == "radar":
        coverage = build_coverage(scene, radar, base_dir)
        sea_model = coverage.levels[0][0]
    elif radar.sea_clutter:
        spectrum = sea_spectrum(scene)
        sea = build_sea(scene, spectrum)
        sea_model = build_sea_model(scene, spectrum=spectrum)
        check_spm_validity(sea_model.k, sea_model.roughness_height_variance)
        tracing = build_tracing(scene, base_dir, sea_model=sea_model)
    hulls = build_hulls(scene, base_dir, variant=variant)
    ships = (sea.ships if sea is not None else coverage.ships if coverage is not None
             else build_ships(scene))
    return SimulationModels(radar=radar, sea=sea, sea_model=sea_model, tracing=tracing,
                            attrs=scene_attrs(scene), variant=variant, hulls=hulls,
                            ships=tuple(ships), land=build_land(scene),
                            coverage=coverage)


# ----------------------------------------------------------------- the radar-wide sea
@dataclass(frozen=True)
class CoverageModel:
    """The sea of ``[sea] coverage = "radar"``: the patchwork of tiles around a fixed
    monostatic radar (:mod:`seaecho.geometry.patchwork`) and what makes each tile's sea.

    Attributes
    ----------
    patchwork : seaecho.geometry.patchwork.Patchwork
    levels : tuple of (SeaModel, TracingModel)
        The sea as the facet model sees it at each level's spacing (its own sub-facet
        statistics: the two-scale split at every spacing) and its facet engine's model.
    spectrum : DirectionalSpectrum
    depth : float or None
        Water depth [m].
    ships : tuple of seaecho.wake.Ship
    kelvin_wake, narrow_v : tuple of bool
        Per ship.
    narrow_v_bragg_vector : (float, float) or None
    seed : int
        The scene's seed (each tile's: :meth:`Patchwork.seed`).
    window_m : (float, float)
        The receive window [m].
    """

    patchwork: object
    levels: tuple
    spectrum: DirectionalSpectrum
    depth: float | None
    ships: tuple
    kelvin_wake: tuple
    narrow_v: tuple
    narrow_v_bragg_vector: tuple[float, float] | None
    seed: int
    window_m: tuple[float, float]

    def cell_spectrum(self, level: int) -> np.ndarray:
        """The spectrum averaged over the wavenumber cells of ``level``'s grid (FFT
        order), computed once per level and shared by its tiles [m^4]."""
        from .ocean.surface import cell_averaged_spectrum

        cache = self.__dict__.setdefault("_psi", {})
        if level not in cache:
            lev = self.patchwork.levels[level]
            (ny, nx), (lx, ly) = lev.shape, lev.size
            kx = 2 * np.pi * np.fft.fftfreq(nx, lx / nx)
            ky = 2 * np.pi * np.fft.fftfreq(ny, ly / ny)
            cache[level] = cell_averaged_spectrum(self.spectrum, kx[None, :], ky[:, None],
                                                  2 * np.pi / lx, 2 * np.pi / ly)
            cache[level].setflags(write=False)
        return cache[level]

    def sea(self, i: int) -> Sea:
        """The sea of tile ``i``: its own realisation (``"surface"`` stream of the tile's
        seed) on its grid in the scene's coordinates, plus the ships' wakes there."""
        pw = self.patchwork
        lev = pw.levels[int(pw.level[i])]
        surface = SeaSurface(self.spectrum, size=lev.size, shape=lev.shape,
                             rng=generator(pw.seed(i, self.seed), "surface"),
                             depth=self.depth, centre=pw.tile_centre(i),
                             cell_spectrum=self.cell_spectrum(int(pw.level[i])))
        return Sea(surface, list(self.ships) or None, kelvin_wake=list(self.kelvin_wake),
                   narrow_v=list(self.narrow_v),
                   narrow_v_bragg_vector=self.narrow_v_bragg_vector)


def coverage_layout(scene, radar: RadarModel, spectrum: DirectionalSpectrum):
    """The patchwork of a ``coverage = "radar"`` scene (eqs T1-T4 of
    :mod:`seaecho.geometry.patchwork`): centred on the transmitter's ground point, from
    the window's nearest to its farthest ground range (cut at the horizon), facets from
    ``[sea]``'s spacing up to Delta_max = min(lambda_p / 8, delta_r / 2).

    Raises
    ------
    ValueError
        The scene is not one the radar-wide sea takes (:func:`coverage_refusal`).
    """
    from .geometry.patchwork import Patchwork, ground_range_window, max_spacing

    why = coverage_refusal(scene)
    if why:
        raise ValueError(why)
    cfg = scene.sea
    (lx, ly), (ny, nx) = cfg.size_m, cfg.shape
    pos = scene.transmitter.position_m
    earth = radar.earth
    ground = ground_range_window(radar.window_m, float(pos[2]), 30.0, earth)
    beam = radar.tx_antenna.wavelength / radar.tx_antenna.width
    d_max = max_spacing(2.0 * np.pi / spectrum.peak_wavenumber(),
                        C0 / (2.0 * radar.waveform.bandwidth))
    return Patchwork.around((float(pos[0]), float(pos[1])), (lx / nx, ly / ny), (ny, nx),
                            ground, beam, d_max, earth)


def coverage_refusal(scene) -> str | None:
    """Why a scene with ``[sea] coverage = "radar"`` cannot run (one message naming the
    field), or None. The radar-wide sea is built around one fixed monostatic radar whose
    rectangular (fan-beam) antenna selects the tiles at each pulse."""
    if scene.sea.coverage != "radar" or scene.radar is None or not scene.radar.sea_clutter:
        return None
    where = "[sea].coverage = 'radar'"
    if scene.receivers or scene.receiver is not None:
        return (f"{where}: not implemented yet for a bistatic or multistatic radar; "
                "a monostatic radar (no [receiver], no [[receivers]]) or coverage = 'tile'")
    t = scene.transmitter
    if t is None or t.motion != "fixed" or t.perturbation is not None:
        return (f"{where}: needs [transmitter].motion = 'fixed' without a perturbation "
                f"(got {None if t is None else t.motion!r}): the patchwork is laid around "
                "one ground point; a moving radar is not implemented yet")
    if t.antenna.pattern != "rectangular":
        return (f"{where}: needs [transmitter.antenna].pattern = 'rectangular' (got "
                f"{t.antenna.pattern!r}): its beam's bound selects the tiles of each pulse")
    r = scene.radar
    if r.window_start_m is None:
        return (f"{where}: needs [radar].window_start_m and window_end_m: the window is "
                "where the sea is")
    if r.sea_gain_floor_db == "off":
        return (f"{where}: needs [radar].sea_gain_floor_db as a number (got 'off'): every "
                "tile of the coverage would be computed at every pulse")
    if not scene.tracing.subfacet_shadowing:
        return (f"{where}: needs [tracing].subfacet_shadowing = true (got false): the "
                "coarser levels' facets leave the shadowing by the waves they do not "
                "resolve to it (docs/scanning.md: 4 m facets 0.6 dB above 1 m ones at "
                "1 deg grazing without it)")
    if t.position_m[2] <= 0.0:
        return (f"{where}: needs the antenna above the sea ([transmitter].position_m z = "
                f"{t.position_m[2]:g} m)")
    return None


def build_coverage(scene, radar: RadarModel, base_dir: str | os.PathLike = "."
                   ) -> CoverageModel:
    """The radar-wide sea of a ``coverage = "radar"`` scene (:class:`CoverageModel`):
    its patchwork, and per level the sea model and the tracing of ``[sea]`` at that
    level's spacing (the same tile extent)."""
    from .scattering.twoscale import check_spm_validity

    spectrum = sea_spectrum(scene)
    pw = coverage_layout(scene, radar, spectrum)
    levels = []
    for lev in pw.levels:
        sub = scene.model_copy(update={"sea": scene.sea.model_copy(update={
            "size_x_m": lev.size[0], "size_y_m": lev.size[1], "nx": lev.shape[1],
            "ny": lev.shape[0]})})
        sm = build_sea_model(sub, spectrum=spectrum)
        if lev.index == 0:
            check_spm_validity(sm.k, sm.roughness_height_variance)
        levels.append((sm, build_tracing(sub, base_dir, sea_model=sm)))
    ships = build_ships(scene)
    narrow = tuple(bool(c.narrow_v) for c in scene.all_ships)
    k_b = None
    if any(narrow):
        k_b = _scene_bragg_vector(scene, 2.0 * np.pi * carrier_frequency(scene) / C0)
    return CoverageModel(patchwork=pw, levels=tuple(levels), spectrum=spectrum,
                         depth=scene.sea.depth_m, ships=tuple(ships),
                         kelvin_wake=tuple(bool(c.kelvin_wake) for c in scene.all_ships),
                         narrow_v=narrow, narrow_v_bragg_vector=k_b, seed=scene.run.seed,
                         window_m=tuple(radar.window_m))


# ------------------------------------------------------------------ several receivers
def receiver_scene(scene, index: int):
    """The bistatic scene of receiver ``index`` of ``[[receivers]]``: the same scene with
    that receiver as its ``[receiver]`` (its ``channels``, if it has its own, as
    ``[radar] channels``) and no ``[[receivers]]``.

    Receiver ``index`` of a multistatic run equals the run of this scene
    (docs/multistatic.md: same seed, its receive window, and a perturbed receiver's path
    errors drawn from ``"platform"`` stream index 1 + ``index``).
    """
    n = len(scene.receivers)
    if not 0 <= index < n:
        raise ValueError(f"receiver index {index}: the scene has {n} [[receivers]]")
    r = scene.receivers[index]
    # the multistatic scene's resolved sea motion, so that the pair sees the same sea
    update: dict[str, Any] = {"receiver": r.platform(), "receivers": (),
                              "scattering": scene.scattering.model_copy(
                                  update={"sea_motion": sea_motion(scene)})}
    if r.channels is not None and scene.radar is not None:
        update["radar"] = scene.radar.model_copy(update={"channels": tuple(r.channels)})
    return scene.model_copy(update=update)


@dataclass(frozen=True)
class MultistaticModels:
    """Stage models of a scene with ``[[receivers]]``: one transmitter, several receivers.

    Attributes
    ----------
    receivers : tuple of SimulationModels
        One per receiver, each the bistatic models of :func:`receiver_scene` (its radar
        with the receiver's platform drawn from ``"platform"`` stream 1 + i); the sea
        model, the tracing and the hull models are the same objects in all of them, and
        the sea's surface too: a receiver's ``Sea`` differs only by its ship, whose
        turbulent-wake film damping is evaluated at that pair's Bragg wavenumber.
    names : tuple of str
        The receivers' names.
    attrs : dict
        Dataset attributes of the whole scene (scene JSON, version, seed).
    """

    receivers: tuple[SimulationModels, ...]
    names: tuple[str, ...]
    attrs: dict


def build_multistatic(scene, base_dir: str | os.PathLike = ".") -> MultistaticModels:
    """The stage models of a multistatic scene (``[[receivers]]``): the sea, sea model,
    tracing and hulls built once and shared, one radar per receiver.

    Raises
    ------
    ValueError
        The scene has no ``[[receivers]]``; or as :func:`build_simulation`.
    """
    if not scene.receivers:
        raise ValueError("the scene has no [[receivers]]: use build_simulation")
    if scene.scattering.sea_motion == "evolving":
        raise ValueError("[scattering].sea_motion = 'evolving' with [[receivers]]: not "
                         "implemented yet (the Bragg lifetimes depend on each pair's "
                         "Bragg wavenumber); use 'held'")
    first = build_simulation(receiver_scene(scene, 0), base_dir)
    attrs = scene_attrs(scene)
    models = [dataclasses.replace(first, attrs=attrs)]
    for i in range(1, len(scene.receivers)):
        sub = receiver_scene(scene, i)
        radar = build_radar(sub, receiver_stream=1 + i)
        sea = first.sea
        if sea is not None and sea.ships:  # the wakes' film damping at its Bragg k
            sea = copy.copy(sea)
            sea.ships = build_ships(sub)
            sea.ship = sea.ships[0]
            if sea.narrow_v_ships:  # its narrow-V wakes at its own Bragg vector
                narrow = [bool(c.narrow_v) for c in sub.all_ships]
                sea.narrow_v_ships = tuple(s for s, n in zip(sea.ships, narrow, strict=True)
                                           if n)
                sea.narrow_v_bragg_vector = _scene_bragg_vector(
                    sub, 2.0 * np.pi * carrier_frequency(sub) / C0)
        models.append(dataclasses.replace(first, radar=radar, sea=sea))
    return MultistaticModels(receivers=tuple(models),
                             names=tuple(r.name for r in scene.receivers), attrs=attrs)
