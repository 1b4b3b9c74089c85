"""What a scene will simulate, as text or HTML: a scene's summary (``print(scene)``, a
notebook's display of a scene, :func:`seaecho.scene_summary`).

Sea state and expected wave heights, the geometry at the tile centre, the radar, its
resolution cells and the size of the run. Every number is computed by the module that
owns its law (the builder, :mod:`seaecho.ocean.twoscale`,
:mod:`seaecho.geometry.bistatic`, :mod:`seaecho.radar.resolution`); this module arranges
and formats them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from html import escape
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .config import Scene

__all__ = ["SceneSummary", "format_bytes", "scene_summary"]


def format_bytes(n: float) -> str:
    """A size in bytes as text: ``1.5 GiB``, ``640 MiB``, ``12 KiB``, ``100 B``."""
    for unit, size in (("GiB", 2.0**30), ("MiB", 2.0**20), ("KiB", 2.0**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


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


def scene_summary(scene: Scene) -> SceneSummary:
    """What a scene describes and what simulating it costs.

    Sea: spectrum, wind, water, the expected significant wave height
    H_s = 4 sqrt(int S(K) dK) of the whole spectrum and of the band the tile resolves
    (2 pi / L < K < pi / dx) (the spectral H_m0 = 4 sqrt(m_0): US Army Corps of
    Engineers, *Coastal Engineering Manual*, 2002, Part II, ch. 1, eq II-1-147, after
    Longuet-Higgins 1952). Geometry at the tile centre, nominal tracks at the middle
    of the acquisition: incidence and grazing angles, ranges, bistatic angle. Radar:
    carrier, waveform, PRF, pulses, channels, and the resolution cells:

    - slant range resolution c / (2 B), and on the ground at the tile centre
      c / (B |grad_h (r_t + r_r)|) (:mod:`seaecho.radar.resolution`, eqs R1-R2);
    - with a moving monostatic platform, the azimuth resolution lambda R / (2 L) of a
      synthetic aperture L, the flight over the acquisition or, if shorter, the beam's
      footprint lambda R / D (eq R3).

    Run: pulses x channels x samples of the receive window and the size of the raw and
    compressed arrays.

    The geometry and the resolution cells come from the physics modules
    (:func:`seaecho.geometry.bistatic.bistatic_angle`, :mod:`seaecho.radar.resolution`);
    this function only arranges them.
    """
    import numpy as np

    from .build import build_radar, sea_motion, sea_spectrum
    from .config import Scene, SceneError
    from .constants import C0, KNOT
    from .geometry.bistatic import bistatic_angle
    from .ocean.twoscale import height_variance
    from .radar.resolution import (
        azimuth_resolution,
        footprint_length,
        ground_range_resolution,
        slant_range_resolution,
        synthetic_aperture,
    )

    if not isinstance(scene, Scene):
        raise SceneError(f"scene: expected a Scene (seaecho.load_scene / parse_scene), got "
                         f"{type(scene).__name__}")
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
    for s, name in zip(scene.all_ships, scene.ship_names(), strict=True):
        wakes = ["Kelvin" if s.kelvin_wake else None, "turbulent"]
        track = (f"through {len(s.waypoints_m)} waypoints, turns of radius "
                 f"{s.turn_radius:.3g} m" if s.waypoints_m is not None
                 else f"heading {s.heading_deg:g} deg")
        sections.append(("Ship" if scene.ship is not None else f"Ship {name}", [
            ("hull", f"{s.length_m:g} x {s.beam_m:g} m, draft {s.draft_m:g} m at "
             f"{_vec(s.position_m if s.waypoints_m is None else s.waypoints_m[0])} m"
             + (", echoes" if s.hull_echo else "")),
            ("track", f"{s.speed:.3g} m/s ({s.speed / KNOT:.3g} kn) {track}; "
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
            beta = math.degrees(float(bistatic_angle(tx, rx, centre)))
            geo.append(("bistatic angle", f"{beta:.3g} deg"))
        sections.append((f"Geometry at the tile centre (t = {t_mid:.3g} s)", geo))

        w = r.waveform
        bandwidth = radar.waveform.bandwidth  # 1 / T for a plain pulse
        lam = C0 / r.carrier_frequency_hz
        wave = (f"LFM {_si(w.bandwidth_hz, 'Hz')} x {_si(w.duration_s, 's')}"
                if w.kind == "lfm" else f"pulse {_si(w.duration_s, 's')}")
        duration = r.n_pulses / r.prf_hz
        rad = [("carrier", f"{_si(r.carrier_frequency_hz, 'Hz')} (lambda {lam * 100:.3g} cm)"),
               ("waveform", f"{wave}, sampled at {_si(r.sampling_rate_hz, 'Hz')}"),
               ("pulses", f"{r.n_pulses} at PRF {_si(r.prf_hz, 'Hz')} "
                f"({_si(duration, 's')}); sea surface every {r.sea_update_pulses} "
                f"pulse(s), {sea_motion(scene)} between"),
               ("channels", " ".join(r.channels)),
               ("sea clutter", "on" if r.sea_clutter else "off")]
        if scene.targets:
            rad.append(("targets", f"{len(scene.targets)} point target(s)"))
        if model.scan_period is not None:
            scan = (scene.transmitter.antenna.scan if scene.transmitter.antenna.scan.scanning
                    else scene.receiver.antenna.scan)
            per = model.scan_period * r.prf_hz
            step = 6.0 * scan.rate_rpm / r.prf_hz
            rad.append(("scan", f"{scan.mode} at {scan.rate_rpm:g} rpm, clockwise: period "
                        f"{model.scan_period:.4g} s = {per:.4g} pulses, {step:.3g} deg per "
                        f"pulse; {r.n_pulses / per:.3g} period(s) simulated"))
        if model.earth is not None:
            from .geometry.earth import horizon_range

            h = float(scene.transmitter.position_m[2]) if scene.transmitter.position_m \
                else float(tx[2])
            rad.append(("Earth", f"spherical, k = {scene.propagation.earth_radius_factor:.4g}"
                        f": the transmitter's horizon at sea level "
                        f"{horizon_range(max(h, 0.0), 0.0, model.earth.radius) / 1e3:.4g} km"))
        sections.append(("Radar", rad))

        res = [("range", f"c / 2B = {slant_range_resolution(bandwidth):.3g} m slant")]
        ground = ground_range_resolution(bandwidth, units[0], units[0] if mono else units[1])
        if ground is not None:
            cell, u = ground
            across = lx * abs(u[0]) + ly * abs(u[1])
            res[0] = (res[0][0], res[0][1] + f", {cell:.3g} m on the ground: "
                      f"{across / cell:.3g} cells across the tile")
        v = model.tx.nominal_state(np.array([t_mid])).velocity[0]
        if mono and float(np.linalg.norm(v)) > 0:
            r_c = float(np.linalg.norm(tx))
            aperture = synthetic_aperture(v, units[0], duration)
            ant = scene.transmitter.antenna
            if ant.pattern == "rectangular":
                aperture = min(aperture, footprint_length(lam, r_c, ant.width_m))
            if aperture > 0:
                res.append(("azimuth", f"lambda R / 2L = "
                            f"{azimuth_resolution(lam, r_c, aperture):.3g} m "
                            f"(synthetic aperture L = {aperture:.3g} m)"))
        res.append(("sea grid", f"{dx * dy:.3g} m2 per cell, "
                    f"{(nx - 1) * (ny - 1):,} cells"))
        sections.append(("Resolution", res))

        n_s, n_c = radar.window.n_samples, len(radar.channels)
        size = 32.0 * r.n_pulses * n_c * n_s
        run = [("arrays", f"{r.n_pulses} pulses x {n_c} channels x {n_s} samples"),
               ("memory", f"raw + compressed {format_bytes(size)} (in memory: simulate "
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
