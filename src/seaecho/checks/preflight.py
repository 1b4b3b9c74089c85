"""Checks of a scene before it runs: what the schema cannot see.

The schema (``seaecho.config``) checks each value and the consistency of the sections;
this module checks what needs the platforms' tracks, the sea's spectrum or the files
beside the scene, for `seaecho check` and `seaecho run` alike (so that ``check`` refuses
everything ``run`` would):

- **Degenerate geometry**, evaluated at every pulse's emission time t_p = t_0 + p / PRF,
  where the run evaluates it:

  * each antenna must stay above the sea: z > 0 (the mean sea surface) at every pulse,
    and with sea clutter z > 2 H_s, H_s = 4 sqrt(m0) the significant wave height of the
    tile's spectrum (the elevation of a Gaussian sea exceeds 2 H_s = 8 standard
    deviations with probability 6e-16 per grid point, so no facet reaches the antenna);
  * a point target must stay out of each antenna's reactive near field,
    r >= d_min = max(lambda / (2 pi), 0.62 sqrt(D^3 / lambda), D) with D the antenna's
    largest dimension (Balanis, *Antenna Theory*, 4th ed., 2016, section 2.2.4: the
    reactive near-field boundary, lambda / 2 pi for a small antenna): closer, the
    point-scatterer radar equation (R1), written with the far-field gains, has no meaning,
    and at zero range the echo is 0/0;
  * an antenna's ``look_at_m`` must be as far (the boresight is the direction to it, and
    the pattern has a direction only outside the reactive region): at the first pulse on
    the nominal track for a fixed mounting, at every pulse for ``track_look_at``.

  The nominal tracks are piecewise linear (fixed, linear, waypoints), so the distance of a
  point moving at constant velocity is convex on each segment and its minimum over the
  pulse times is at one of the two pulses that bracket the continuous minimum (or at the
  segment's first or last pulse): two evaluations per point and segment. A Gauss-Markov
  perturbation moves the true track by less than 8 sigma (probability of more 1e-15 per
  sample); points whose nominal clearance is smaller than that are checked at every pulse
  on the true track.

- **The two-scale model's domain**: with sea clutter the grid must leave the Bragg waves
  unresolved, max(dx, dy) > lambda / 4, i.e. k_N = pi / max(dx, dy) < 2 k: finer facets
  resolve every Bragg wave (K <= 2 k), so the small-perturbation part has no roughness
  left and the facets, smaller than a quarter wavelength, are outside the Kirchhoff
  tangent-plane approximation (paper section III: "the curvature of the waves [must be]
  large enough in front of the electromagnetic wavelength").

- **Sub-facet shadowing** (``[tracing] subfacet_shadowing``) needs slope in the tilting
  band in both directions: the facet engine takes a shadowing function of the upwind and
  the crosswind slope variances, each > 0.

- **Files and devices** the run needs: every ``[[objects]]`` file the ray-traced sea
  or a hull's echo loads exists beside the scene and loads; the ``[tracing] variant``
  can run here (a CUDA variant has a CUDA GPU).

- **Something to receive**: sea clutter on, a target, or an explicit receive window.

- **The radar horizon** on a spherical Earth (``[propagation] earth = "spherical"``):
  with sea clutter, the whole tile above each antenna's horizon at the first and the
  last pulse (point targets beyond it are simply not seen, at every pulse).
- **The land** (``[[land]]``): its grid at ``resolution_m`` at most
  :data:`MAX_LAND_CELLS` cells, at least one cell inside its outline, and no antenna at
  or below its ground at the first or the last pulse.
- **The hulls' traces** (``[[objects]]`` with ``scatterer = true``): at every pulse where
  the run traces a hull's signature (its refresh schedule), each antenna is outside the
  sphere the rays are launched from (1.05 times the hull's bounding radius about its
  centre, ``seaecho.tracing.sbr.bounding_sphere``), which the tracer requires.

- **The output** `seaecho run` would write (``[run] output``, or ``-o``): its folder
  exists, the output is not a folder (a netCDF file is renamed onto it); a Zarr store
  (``*.zarr``) only without ``[image]`` (the focusing reads a netCDF run).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona, NY,
USA, 2006, doi:10.1109/RADAR.2006.1631862.

Every problem found is reported at once in one :class:`~seaecho.config.SceneError` whose
lines name the field (``[transmitter].position_m``, ``[[targets]] #2``...).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..config import SceneError
from ..config.base import short_repr
from ..constants import C0, K_B, T0
from .resources import PERTURBATION_SIGMAS, Segment, nominal_segments, perturbation_bound

#: Crest bound of a Gaussian sea in significant wave heights (2 H_s = 8 sigma).
CREST_HS = 2.0
#: Most distance evaluations spent on points checked at every pulse of a perturbed track.
MAX_EXHAUSTIVE = 50_000_000


# ---------------------------------------------------------------------- pulse times
@dataclass(frozen=True)
class Pulses:
    """Emission times t_p = t_0 + p / PRF, p = 0 .. n - 1 [s]."""

    t0: float
    prf: float
    n: int

    def time(self, p) -> NDArray[np.float64]:
        return self.t0 + np.asarray(p, dtype=float) / self.prf

    def index_range(self, t_a: float, t_b: float) -> tuple[int, int]:
        """First and last pulse whose time is in [t_a, t_b] (with a rounding margin);
        (1, 0) if none."""
        lo = 0 if not np.isfinite(t_a) else int(np.ceil((t_a - self.t0) * self.prf - 1e-6))
        hi = self.n - 1 if not np.isfinite(t_b) else int(
            np.floor((t_b - self.t0) * self.prf + 1e-6))
        return max(lo, 0), min(hi, self.n - 1)


def pulses_of(scene) -> Pulses:
    r = scene.radar
    return Pulses(r.start_time_s, r.prf_hz, r.n_pulses)


def min_distance(cfg, platform, pulses: Pulses, q: NDArray, w: NDArray
                 ) -> tuple[NDArray[np.float64], NDArray[np.intp]]:
    """Smallest distance of points q + w t to a platform over the pulse times.

    Parameters
    ----------
    cfg : PlatformConfig
        The platform's section (its nominal track).
    platform : seaecho.radar.platforms.Platform
        The same platform (its true, perturbed track).
    pulses : Pulses
    q, w : ndarray (K, 3)
        Positions at t = 0 [m] and velocities [m/s] of K points.

    Returns
    -------
    distance : ndarray (K,)
        Minimum distance over the pulses on the true track [m] (see module docstring;
        for a perturbed track, points whose nominal clearance exceeds the perturbation
        bound get a lower bound, nominal distance minus bound).
    pulse : ndarray (K,)
        A pulse where it is reached.
    """
    q = np.asarray(q, dtype=float).reshape(-1, 3)
    w = np.asarray(w, dtype=float).reshape(-1, 3)
    k = q.shape[0]
    best = np.full(k, np.inf)
    where = np.zeros(k, dtype=np.intp)
    for seg in nominal_segments(cfg):
        i_a, i_b = pulses.index_range(seg.t_a, seg.t_b)
        if i_a > i_b:
            continue
        t_lo, t_hi = pulses.time(i_a), pulses.time(i_b)
        a = q - seg.c  # relative position a + b t
        b = w - seg.v
        bb = np.einsum("ij,ij->i", b, b)
        with np.errstate(divide="ignore", invalid="ignore"):
            t_star = np.where(bb > 0, -np.einsum("ij,ij->i", a, b) / bb, t_lo)
        t_star = np.clip(t_star, t_lo, t_hi)
        u = (t_star - pulses.t0) * pulses.prf
        for cand in (np.floor(u), np.ceil(u)):
            p = np.clip(cand, i_a, i_b).astype(np.intp)
            t = pulses.time(p)
            d = np.linalg.norm(a + b * t[:, None], axis=-1)
            better = d < best
            best = np.where(better, d, best)
            where = np.where(better, p, where)
    if cfg.perturbation is None:
        return best, where
    # True track: nominal distance minus the perturbation bound, or every pulse
    bound = perturbation_bound(cfg)
    return best - bound, where


def exhaustive_min_distance(platform, pulses: Pulses, q: NDArray, w: NDArray,
                            chunk: int = 100_000) -> tuple[float, int]:
    """Smallest distance of one point q + w t to the true track over every pulse [m].

    With ``q = None`` it is the lowest height z of the track instead.
    """
    best, where = np.inf, 0
    for start in range(0, pulses.n, chunk):
        p = np.arange(start, min(start + chunk, pulses.n))
        t = pulses.time(p)
        pos = platform.state(t).position
        d = pos[:, 2] if q is None else np.linalg.norm(q + w * t[:, None] - pos, axis=-1)
        i = int(np.argmin(d))
        if d[i] < best:
            best, where = float(d[i]), int(p[i])
    return best, where


def min_height(cfg, pulses: Pulses) -> tuple[float, int]:
    """Lowest nominal height z over the pulses [m] and a pulse where it is reached
    (z is linear on each segment: its minimum is at a segment's first or last pulse)."""
    best, where = np.inf, 0
    for seg in nominal_segments(cfg):
        i_a, i_b = pulses.index_range(seg.t_a, seg.t_b)
        for i in (i_a, i_b) if i_a <= i_b else ():
            z = float(seg.c[2] + seg.v[2] * pulses.time(i))
            if z < best:
                best, where = z, i
    return best, where


class _Budget:
    """Distance evaluations left for exhaustive checks on perturbed tracks."""

    def __init__(self, n: int = MAX_EXHAUSTIVE) -> None:
        self.left = n

    def take(self, n: int) -> bool:
        if n > self.left:
            return False
        self.left -= n
        return True


def _clearance(cfg, platform, pulses, q, w, d_min, budget: _Budget):
    """(distance, pulse, exact) per point: ``exact`` False where only the lower bound
    (nominal distance minus the perturbation bound) is known and it is below ``d_min``."""
    d, p = min_distance(cfg, platform, pulses, q, w)
    exact = np.ones(d.shape, dtype=bool)
    if cfg.perturbation is not None:
        exact = d >= d_min  # a bound that clears d_min settles it
        for j in np.flatnonzero(~exact):
            if budget.take(pulses.n):
                d[j], p[j] = exhaustive_min_distance(platform, pulses, q[j], w[j])
                exact[j] = True
    return d, p, exact


def _height(cfg, platform, pulses, floor, budget: _Budget) -> tuple[float, int, bool]:
    """(lowest z, pulse, exact) of a platform, as :func:`_clearance`."""
    z, p = min_height(cfg, pulses)
    if cfg.perturbation is None:
        return z, p, True
    z -= PERTURBATION_SIGMAS * cfg.perturbation.position_sigma_m[2]
    if z > floor:
        return z, p, True
    if budget.take(pulses.n):
        z, p = exhaustive_min_distance(platform, pulses, None, None)
        return z, p, True
    return z, p, False


# ---------------------------------------------------------------------------- checks
def near_field_distance(antenna_cfg, wavelength: float) -> float:
    """Outer boundary of an antenna's reactive near field [m]: max(lambda / (2 pi),
    0.62 sqrt(D^3 / lambda), D), D its largest dimension (0 for patterns without one).

    References
    ----------
    C. A. Balanis, *Antenna Theory: Analysis and Design*, 4th ed., Wiley, 2016,
    section 2.2.4 (field regions).
    """
    d = max([0.0, *(x for x in (antenna_cfg.width_m, antenna_cfg.height_m) if x is not None)])
    return max(wavelength / (2.0 * np.pi), 0.62 * np.sqrt(d**3 / wavelength), d)


def crest_bound(scene) -> float:
    """2 H_s of the tile's sea [m]: H_s = 4 sqrt(m0), m0 the height variance of every
    wavenumber the grid holds (0 < K < sqrt(2) pi / min(dx, dy))."""
    from ..build import sea_spectrum
    from ..ocean.twoscale import height_variance

    sea = scene.sea
    spectrum = sea_spectrum(scene)
    (lx, ly), (ny, nx) = sea.size_m, sea.shape
    k_max = np.sqrt(2.0) * np.pi / min(lx / nx, ly / ny)
    m0 = height_variance(spectrum, 0.0, k_max)
    return CREST_HS * 4.0 * float(np.sqrt(m0))


def _platforms(scene) -> list[tuple[str, object, object]]:
    """[(section name, config, Platform)] of the transmitter and (if any) the receiver."""
    from ..build import _platforms as build_platforms

    tx, rx = build_platforms(scene)
    out = [("transmitter", scene.transmitter, tx)]
    if scene.receiver is not None:
        out.append(("receiver", scene.receiver, rx))
    return out


def geometry_problems(scene) -> list[str]:
    """Degenerate geometry of a scene with [radar] and [transmitter] (module docstring)."""
    problems: list[str] = []
    radar = scene.radar
    lam = C0 / radar.carrier_frequency_hz
    pulses = pulses_of(scene)
    try:
        platforms = _platforms(scene)
    except ValueError as exc:  # e.g. a perturbation grid too fine for the run's span
        return [f"[transmitter/receiver].perturbation: {exc}"]
    floor, why = 0.0, "above the mean sea surface z = 0"
    if radar.sea_clutter:
        floor = crest_bound(scene)
        why = (f"above the sea's crest bound 2 H_s = {floor:.3g} m (H_s the significant "
               "wave height of [sea]'s spectrum)")
    budget = _Budget()
    for name, cfg, platform in platforms:
        z, p, exact = _height(cfg, platform, pulses, floor, budget)
        if not z > floor:
            what = f"is at z = {z:.4g} m" if exact else f"may come down to z = {z:.4g} m"
            problems.append(f"[{name}].position_m: the antenna {what} at pulse {p} "
                            f"(t = {float(pulses.time(p)):.6g} s); it must stay {why}")
        ant = cfg.antenna
        d_min = near_field_distance(ant, lam)
        if ant.look_at_m is not None:
            look = np.array([ant.look_at_m], dtype=float)
            if ant.track_look_at:
                d, p, _ = _clearance(cfg, platform, pulses, look, np.zeros((1, 3)), d_min,
                                     budget)
                dist, at = float(d[0]), f"at pulse {p[0]}"
            else:
                nominal = platform.nominal_state(radar.start_time_s).position
                # hypot: no overflow of the squares, whatever the coordinates
                dist = float(np.hypot.reduce(np.abs(look[0] - nominal)))
                at = "at the first pulse"
            if not dist >= d_min:
                problems.append(
                    f"[{name}].antenna.look_at_m = {short_repr(ant.look_at_m)}: "
                    f"{max(dist, 0.0):.3g} m from the antenna {at}; the boresight points at "
                    f"it, so it must be outside the antenna's reactive near field, at least "
                    f"{d_min:.3g} m away")
        if scene.targets:
            q = np.array([t.position_m for t in scene.targets], dtype=float)
            w = np.array([t.velocity_m_s for t in scene.targets], dtype=float)
            d, p, exact = _clearance(cfg, platform, pulses, q, w, d_min, budget)
            bad = np.flatnonzero(~(d >= d_min))
            for j in bad[:5]:
                t = scene.targets[j]
                label = f"'{short_repr(t.name)[1:-1]}'" if t.name else f"#{j}"
                dist = f"{d[j]:.3g} m" if exact[j] else f"possibly {max(d[j], 0.0):.3g} m"
                problems.append(
                    f"[[targets]] {label} (position_m = {short_repr(t.position_m)}, "
                    f"velocity_m_s = {short_repr(t.velocity_m_s)}): {dist} from the "
                    f"{name}'s antenna at pulse {p[j]}; a point target must stay out of the "
                    f"antenna's reactive near field, at least {d_min:.3g} m away (closer, "
                    "the far-field radar equation has no meaning)")
            if bad.size > 5:
                problems.append(f"... and {bad.size - 5} more [[targets]] too close to the "
                                f"{name}'s antenna")
    return problems


def two_scale_problems(scene) -> list[str]:
    """The two-scale domain with sea clutter: max(dx, dy) > lambda / 4 (module docstring)."""
    if not scene.radar.sea_clutter:
        return []
    lam = C0 / scene.radar.carrier_frequency_hz
    (lx, ly), (ny, nx) = scene.sea.size_m, scene.sea.shape
    dx = max(lx / nx, ly / ny)
    if dx > lam / 4.0:
        from ..build import build_sea_model

        try:  # the builder's own check: sub-facet slopes in the tilting band
            model = build_sea_model(scene)
        except ValueError as exc:
            return [str(exc)]
        up, cross = model.mss_upwind, model.mss_crosswind
        if scene.tracing.subfacet_shadowing and not (up > 0 and cross > 0):
            # (the facet engine's requirement: a shadowing function per direction)
            return [f"[tracing].subfacet_shadowing = true: the slope variances of the waves "
                    f"between the grid and the two-scale split are {up:.3g} upwind and "
                    f"{cross:.3g} crosswind; sub-facet shadowing needs both > 0 (another "
                    "[sea] grid spacing or fetch, or subfacet_shadowing = false)"]
        return []
    return [f"[sea].size_x_m / nx = {dx:.3g} m: grid spacing at most a quarter of the radar "
            f"wavelength ({lam:.3g} m at [radar].carrier_frequency_hz = "
            f"{scene.radar.carrier_frequency_hz:g}); the grid resolves every Bragg wave and "
            "its facets are too small for the Kirchhoff approximation: the two-scale model "
            "needs a spacing above lambda / 4 (coarser grid or higher carrier)"]


def object_problems(scene, base_dir) -> list[str]:
    """``[[objects]]`` the run would load and cannot (a missing or unreadable file), and a
    ``[tracing] variant`` that cannot run here (a CUDA variant without a CUDA GPU).

    The run loads every object for a ray-traced sea (occluders), and every object as soon
    as one has ``scatterer = true`` (the hulls' echoes, whatever the facet mode:
    :func:`seaecho.build.build_hulls`).
    """
    from ..backend import check_variant

    out = []
    try:
        check_variant(scene.tracing.variant)
    except ValueError as exc:
        out.append(f"[tracing].variant = {short_repr(scene.tracing.variant)}: {exc}")
    raytraced = scene.radar.sea_clutter and scene.tracing.mode == "raytraced"
    hulls = any(o.scatterer for o in scene.objects) or any(
        s.hull_echo for s in scene.all_ships)
    for name, s in zip(scene.ship_names(), scene.all_ships, strict=True):
        if s.hull_mesh is not None and not (Path(base_dir) / s.hull_mesh).is_file():
            out.append(f"[[ships]] {name}: hull_mesh = {short_repr(s.hull_mesh)}: no such "
                       f"file in {Path(base_dir).resolve()}")
    if not (raytraced or hulls):
        return out
    for i, obj in enumerate(scene.objects):
        path = Path(base_dir) / obj.file
        if not path.is_file():
            out.append(f"[[objects]] #{i} ({obj.name}): file = {short_repr(obj.file)}: no such "
                       f"file in {Path(base_dir).resolve()}")
            continue
        from ..tracing.scene import load_object

        try:
            shapes = load_object(obj, base_dir=str(base_dir), ship=scene.ship)
        except ValueError as exc:
            out.append(f"[[objects]] #{i} ({obj.name}): {short_repr(str(exc), 300)[1:-1]}")
            continue
        out += _material_problems(i, obj, shapes, scene.radar.carrier_frequency_hz)
    return out


def _material_problems(i: int, obj, shapes, frequency: float) -> list[str]:
    """An ITU-R P.2040 material the table does not define at the carrier (the tracer's
    radio material and the hull echo's Fresnel coefficients need it)."""
    from ..tracing.sbr import material_permittivity

    for itu in sorted({sh.itu_type for sh in shapes if sh.itu_type is not None}):
        try:
            material_permittivity(frequency, itu_type=itu)
        except ValueError as exc:
            return [f"[[objects]] #{i} ({obj.name}): material = {short_repr(itu)} at "
                    f"[radar].carrier_frequency_hz = {frequency:g}: {exc} (ITU-R P.2040-3, "
                    "table 3, gives each material's frequency range); choose another "
                    "material or give relative_permittivity and conductivity_s_m"]
    return []


def hull_problems(scene, base_dir=".") -> list[str]:
    """An antenna inside a scatterer hull's launch sphere at a pulse where the run traces
    the hull (module docstring): the run's own hull echoes and schedule
    (:meth:`seaecho.tracing.hull_echo.HullEchoes.from_model`) on the run's radar, the
    tracer's sphere (:func:`seaecho.tracing.sbr.bounding_sphere`)."""
    if not (any(o.scatterer for o in scene.objects)
            or any(s.hull_echo for s in scene.all_ships)):
        return []
    import warnings

    from ..build import build_hulls, build_radar
    from ..radar.system import RadarSystem
    from ..tracing.hull_echo import HullEchoes
    from ..tracing.sbr import BOUNDING_MARGIN, bounding_sphere

    with warnings.catch_warnings():  # (the window's warning is the run's to give)
        warnings.simplefilter("ignore")
        radar = RadarSystem(build_radar(scene))
        hulls = HullEchoes.from_model(build_hulls(scene, base_dir=base_dir), radar)
    out = []
    ships = set(scene.ship_names()) if scene.all_ships else set()
    for h in hulls.hulls if hulls is not None else ():
        what = (f"[[ships]] '{h.name}' (hull_echo)" if h.name in ships
                else f"[[objects]] '{h.name}' (scatterer)")
        for p in h.schedule:
            geo = radar.geometry(int(p))
            centre, radius = bounding_sphere(h.mesh(geo.time).vertices)
            antennas = [("transmitter", geo.tx)] + ([("receiver", geo.rx)]
                                                    if scene.receiver is not None else [])
            for name, state in antennas:
                d = float(np.linalg.norm(state.position - centre))
                if d < BOUNDING_MARGIN * radius:
                    out.append(f"[{name}].position_m: the {name}'s antenna is {d:.3g} m "
                               f"from the centre of {what} at "
                               f"pulse {int(p)} (t = {geo.time:.6g} s), where the run traces "
                               f"it; the ray tracer launches its rays from a sphere of "
                               f"{BOUNDING_MARGIN:g} x its bounding radius "
                               f"{radius:.3g} m and needs the antenna outside: move the "
                               "antenna or the object")
                    return out
    return out


#: Largest noise-equivalent RCS [m^2] an ``[image]`` may have at its best pixel: its
#: noise pixels (Rayleigh, up to ~20 times their mean over 4096^2 pixels), over areas
#: down to 1e-4 m^2, stay below float32's 3.4e38 (the image file's precision).
MAX_IMAGE_NOISE_RCS = 1.0e30


def image_noise_rcs(scene) -> float:
    """A lower bound of the noise-equivalent RCS of the ``[image]`` [m^2]: the RCS the
    calibrated image s = I / K (eqs B2, K2 of ``seaecho.imaging``) gives the thermal
    noise at the best-calibrated pixel; 0 without thermal noise.

    The noise of one range-compressed sample (matched filter normalised to chi(0) = 1,
    constant-envelope pulse of N_s = T f_s + 1 samples at most, any weighting raising it)
    is at least sigma_c^2 = k T0 F B_n / N_s (Skolnik 2008, eq 1.8, for k T0 F B_n); over
    the pulses, E|I_n|^2 = sigma_c^2 sum w_p^2 and K = sum w_p A_p <= sqrt(sum w_p^2
    N_p) A_max (Cauchy-Schwarz), so the noise-equivalent RCS E|I_n|^2 / K^2 is at least
    sigma_c^2 / (N_p A_max^2), with A_max of eq K1 at the antennas' largest possible
    gains (4 pi a b / lambda^2 for an a x b aperture, Balanis 2016, eq 12-38, twice for
    margin; else 10, above every built-in pattern's peak) and the ranges at least each
    antenna's height above the image plane (or lambda / 2 pi).
    """
    r = scene.radar
    if scene.image is None or not r.thermal_noise:
        return 0.0
    lam = C0 / r.carrier_frequency_hz
    b_n = r.noise_bandwidth_hz or r.sampling_rate_hz
    n_s = r.waveform.duration_s * r.sampling_rate_hz + 1.0
    log_noise = (np.log10(K_B * T0) + np.log10(b_n) + r.noise_figure_db / 10.0
                 - np.log10(n_s))  # (logs of each: B_n of 5e-324 Hz times k T0 is 0)
    pulses = pulses_of(scene)
    log_gains = log_ranges = 0.0
    platforms = [scene.transmitter, scene.receiver or scene.transmitter]
    for cfg in platforms:
        ant = cfg.antenna
        g = 10.0
        if ant.pattern == "rectangular" and ant.width_m and ant.height_m:
            g = max(g, 2.0 * 4.0 * np.pi * ant.width_m * ant.height_m / lam**2)
        z, _ = min_height(cfg, pulses)
        log_gains += np.log10(g)
        log_ranges += 2.0 * np.log10(max(z - scene.image.height_m, lam / (2.0 * np.pi)))
    log_a2 = (np.log10(r.transmit_power_w) + log_gains + 2.0 * np.log10(lam)
              - 3.0 * np.log10(4.0 * np.pi) - log_ranges)
    return float(10.0 ** min(log_noise - np.log10(r.n_pulses) - log_a2, 308.0))


def image_problems(scene) -> list[str]:
    """``[image]`` the run cannot focus after writing the raw data (which would leave the
    raw file and no image): no extent given and nothing that sets a default one (no sea
    clutter, no targets); fewer than 2 x 2 pixels or more than the focusing takes; more
    looks than pixels; a receive window of fewer than 2 samples."""
    from ..imaging.focus import MAX_PIXELS
    from .resources import image_shape

    cfg = scene.image
    if cfg is None:
        return []
    if cfg.extent_m is None and not (scene.radar.sea_clutter or scene.targets):
        return ["[image].extent_m: needed when there is neither sea clutter nor [[targets]] "
                "(the default image is the sea tile, or the targets' box); give (x_min, "
                "x_max, y_min, y_max) [m]"]
    ny, nx = image_shape(scene)
    out = []
    if ny * nx > MAX_PIXELS:
        out.append(f"[image].pixel_m = {short_repr(cfg.pixel_m)}, extent_m = "
                   f"{short_repr(cfg.extent_m)}: {ny} x {nx} pixels, more than {MAX_PIXELS}; "
                   "use a larger pixel or a smaller extent (without them: the sea tile or "
                   "the targets' box at a quarter of the range resolution)")
    from .resources import window_size

    if window_size(scene)[0] < 2:
        out.append("[image]: the receive window holds fewer than 2 samples per pulse: "
                   "nothing to focus (widen window_start_m / window_end_m)")
    if ny < 2 or nx < 2:
        out.append(f"[image].pixel_m = {short_repr(cfg.pixel_m)}, extent_m = "
                   f"{short_repr(cfg.extent_m)}: an image of {ny} x {nx} pixels; it needs at "
                   "least 2 x 2 (a smaller pixel or a larger extent; without them: a quarter "
                   "of the range resolution over the sea tile or the targets' box)")
    elif cfg.looks[0] > ny or cfg.looks[1] > nx:
        out.append(f"[image].looks = {short_repr(cfg.looks)}: more looks (azimuth y, range "
                   f"x) than the image's {ny} x {nx} pixels")
    noise = image_noise_rcs(scene)
    if noise > MAX_IMAGE_NOISE_RCS:
        r = scene.radar
        out.append(f"[radar].transmit_power_w = {short_repr(r.transmit_power_w)}, "
                   f"noise_figure_db = {short_repr(r.noise_figure_db)}: the [image]'s "
                   f"thermal noise calibrates to an RCS of at least {noise:.3g} m^2 (noise-"
                   f"equivalent, at its best pixel), more than {MAX_IMAGE_NOISE_RCS:g} m^2 "
                   "the image can hold; raise transmit_power_w, lower noise_figure_db or "
                   "noise_bandwidth_hz, or turn thermal_noise off")
    return out


def receive_problems(scene) -> list[str]:
    """Nothing to receive: no sea clutter, no target, no explicit window."""
    r = scene.radar
    if (r.sea_clutter or scene.targets or r.window_start_m is not None
            or any(g.echo for g in scene.land)):
        return []
    return ["[radar]: nothing to receive: sea_clutter is off and there are no [[targets]]; "
            "turn sea_clutter on, add a target, or give window_start_m / window_end_m"]


#: Most grid cells of a ``[[land]]``'s bounding box (two facets each) a run accepts [-].
MAX_LAND_CELLS = 1 << 21


def land_problems(scene) -> list[str]:
    """``[[land]]`` the run cannot build or would hide an antenna in: a bounding-box grid
    of more than :data:`MAX_LAND_CELLS` cells (refused before the mesh is built), an
    outline with no cell inside at its ``resolution_m``, and an antenna below the
    ground of a piece of land at the first or the last pulse (eq G1 of
    ``seaecho.geometry.land``; the antenna would see nothing)."""
    import numpy as np

    from ..geometry.land import distance_to_outline, inside_polygon, land_mesh, shore_height

    if not scene.land:
        return []
    try:
        platforms = _platforms(scene)
    except ValueError:  # reported by geometry_problems
        platforms = []
    pulses = pulses_of(scene) if platforms else None
    out = []
    for i, land in enumerate(scene.land):
        tag = f"[[land]] #{i} ({land.name})"
        v = np.asarray(land.outline_m, dtype=float)
        span = v.max(axis=0) - v.min(axis=0)
        cells = float(np.prod(np.ceil(span / land.resolution_m) + 1.0))
        if cells > MAX_LAND_CELLS:
            out.append(f"{tag}: resolution_m = {land.resolution_m:g} over its outline's "
                       f"{span[0]:.4g} m x {span[1]:.4g} m box makes {cells:.3g} grid cells; "
                       f"at most {MAX_LAND_CELLS} (two facets each): coarsen resolution_m or "
                       "split the land")
            continue
        try:
            land_mesh(v, land.height_m, land.shore_width_m, land.resolution_m)
        except ValueError as exc:
            out.append(f"{tag}: {exc}")
            continue
        for name, _, platform in platforms:
            for p in sorted({0, scene.radar.n_pulses - 1}):
                q = platform.nominal_state(float(pulses.time(p))).position
                if not inside_polygon(q[:2], v):
                    continue
                ground = float(shore_height(distance_to_outline(q[None, :2], v)[0],
                                            land.height_m, max(land.shore_width_m,
                                                               land.resolution_m)))
                if q[2] <= ground:
                    out.append(f"[{name}].position_m: at pulse {p} the antenna "
                               f"({q[0]:.6g}, {q[1]:.6g}, {q[2]:.4g}) m is at or below the "
                               f"ground of {tag} ({ground:.4g} m there); raise it or move "
                               "it off the land")
                    break
    return out


def horizon_problems(scene) -> list[str]:
    """A spherical Earth with sea clutter: the tile must be above each antenna's radar
    horizon (eq E2 of ``seaecho.geometry.earth``) at the first and the last pulse; a
    tile partly beyond it is refused too (the sea model has no partial occlusion by the
    Earth's bulge)."""
    from ..build import build_earth
    from ..geometry.earth import horizon_range
    from ..geometry.frames import tile_outline

    earth = build_earth(scene)
    if earth is None or not scene.radar.sea_clutter or scene.sea.coverage == "radar":
        return []  # a radar-wide sea is cut by the horizon facet by facet
    try:
        platforms = _platforms(scene)
    except ValueError:  # reported by geometry_problems
        return []
    pulses = pulses_of(scene)
    outline = tile_outline(*scene.sea.size_m, n_edge=2)
    problems = []
    for name, _, platform in platforms:
        for p in sorted({0, scene.radar.n_pulses - 1}):
            state = platform.nominal_state(float(pulses.time(p)))
            seen = earth.visible(state.position, earth.position(outline))
            if not seen.all():
                h = float(state.position[2])
                problems.append(
                    f"[{name}].position_m: at pulse {p} the sea tile ([sea] size_x_m/"
                    f"size_y_m around the origin) is {'partly ' if seen.any() else ''}"
                    f"beyond the antenna's radar horizon ([propagation] earth = "
                    f"'spherical': {horizon_range(max(h, 0.0), 0.0, earth.radius):.4g} m "
                    "from its height); move the radar closer, raise it, or use earth = "
                    "'flat'")
                break
    return problems
def output_problems(scene, output, field: str = "[run].output") -> list[str]:
    """The output file ``output`` of `seaecho run` that it cannot write: a folder that
    does not exist (relative to the working directory, as the run resolves it), an
    existing folder where a netCDF file goes, or a Zarr store for a scene with
    ``[image]``. ``field`` names where the path came from."""
    from ..io.zarr_run import is_zarr

    path = Path(output)
    out = []
    folder = path.parent
    if str(folder) and not folder.is_dir():
        out.append(f"{field} = {short_repr(str(output))}: the folder {folder} does not exist "
                   f"(relative to the working directory {Path.cwd()}); create it or name "
                   "another output")
    if path.is_dir() and not is_zarr(path):  # a netCDF file is renamed onto it
        out.append(f"{field} = {short_repr(str(output))}: an existing folder, not a file; "
                   "name the file to write (e.g. run.nc)")
    image = image_output(path) if path.name else None
    if scene.image is not None and image is not None and image.is_dir():
        out.append(f"{field} = {short_repr(str(output))}: the image goes to {image}, an "
                   "existing folder; name another output or move the folder")
    if is_zarr(path) and scene.image is not None:
        out.append(f"{field} = {short_repr(str(output))}: a Zarr store, and the scene has "
                   "[image]: focusing reads a netCDF run; write the run to a .nc file")
    return out


def image_output(output) -> Path:
    """Where `seaecho run` writes the ``[image]`` of a run written to ``output``."""
    path = Path(output)
    return path.with_name(path.stem + "_image.nc")


def default_output(scene, scene_file) -> tuple[Path, str]:
    """(path, field) of the file `seaecho run SCENE` writes without ``-o``: ``[run]
    output``, else ``SCENE``'s stem with ``.nc`` in the working directory."""
    if scene.run.output:
        return Path(scene.run.output), "[run].output"
    return Path(Path(scene_file).stem + ".nc"), "the default output"


def coverage_problems(scene) -> list[str]:
    """``[sea] coverage = "radar"`` on a scene it does not take
    (:func:`seaecho.build.coverage_refusal`)."""
    from ..build import coverage_refusal

    why = coverage_refusal(scene)
    return [why] if why else []


def run_problems(scene, base_dir=".") -> list[str]:
    """Every problem of this module for a scene that has [radar] and [transmitter]."""
    out = (coverage_problems(scene) + two_scale_problems(scene) + receive_problems(scene)
           + image_problems(scene) + object_problems(scene, base_dir) + land_problems(scene))
    return (out + (hull_problems(scene, base_dir) if not out else [])
            + geometry_problems(scene) + horizon_problems(scene))


def check_run(scene, source: str, base_dir=".", max_memory_gb: float | None = None,
              figures: bool = True, workers: int | None = None,
              block: int | None = None, output=None,
              output_field: str = "[run].output") -> str:
    """Refuse a scene `seaecho run` cannot simulate; return its resource estimate.

    The cheap checks and the memory estimate (``seaecho.checks.resources``) come first, so that
    a scene too large for memory is refused before its tracks are drawn; then the
    geometry. Every problem found is listed in one :class:`~seaecho.config.SceneError`.

    Parameters
    ----------
    scene : seaecho.config.Scene
        With [radar] and [transmitter] sections.
    source : str
        The scene file's name, to start the message.
    base_dir : path
        Folder of the scene file.
    max_memory_gb : float or None
        Memory limit [GB] (``--max-memory-gb``); default the environment's.
    figures : bool
        The run draws figures.
    workers, block : int, optional
        ``--workers`` (a local cluster of that many processes) and ``--block-pulses``.
    output : path, optional
        The file the run writes (:func:`output_problems`), named ``output_field`` in the
        messages; None: not checked (a sweep writes its own files).

    Returns
    -------
    str
        One line: estimated peak memory against the limit, and run time.
    """

    from .resources import check_memory

    if scene.receivers:  # [[receivers]]: each receiver's bistatic scene (docs/multistatic.md)
        return _check_multistatic(scene, source, base_dir, max_memory_gb, figures,
                                  workers, block)
    problems = coverage_problems(scene)
    if problems:  # the estimate below needs the patchwork
        raise SceneError(f"{source}: cannot be simulated\n" + "\n".join(problems))
    problems = (two_scale_problems(scene) + receive_problems(scene) + image_problems(scene)
                + object_problems(scene, base_dir) + land_problems(scene))
    if not problems:  # (needs the objects' files and the radar's values)
        problems += hull_problems(scene, base_dir)
    if output is not None:
        problems += output_problems(scene, output, output_field)
    try:
        _, line = check_memory(scene, source, max_memory_gb, figures, workers=workers,
                               block=block, base_dir=base_dir)
    except SceneError as exc:
        raise SceneError("\n".join([str(exc), *problems])) from None
    problems += geometry_problems(scene) + horizon_problems(scene)
    if problems:
        raise SceneError(f"{source}: cannot be simulated\n" + "\n".join(problems))
    return line


def _check_multistatic(scene, source: str, base_dir, max_memory_gb, figures, workers,
                       block) -> str:
    """:func:`check_run` of a scene with ``[[receivers]]``: the sea's and the objects'
    problems once, each receiver's geometry and image problems named by its receiver,
    the memory of every receiver together (``seaecho.checks.resources.multistatic_estimate``)."""
    from ..build import receiver_scene
    from .resources import check_memory

    subs = [receiver_scene(scene, i) for i in range(len(scene.receivers))]
    problems = (two_scale_problems(subs[0]) + receive_problems(subs[0])
                + object_problems(subs[0], base_dir))
    def named(i: int, problems: list[str]) -> list[str]:
        tag = f"[[receivers]] #{i} ({scene.receivers[i].name})"
        return [p.replace("[receiver]", tag, 1) if p.startswith("[receiver]")
                else f"{tag}: {p}" for p in problems]

    own = []
    for i, sub in enumerate(subs):
        own += named(i, image_problems(sub))
    try:
        _, line = check_memory(scene, source, max_memory_gb, figures, workers=workers,
                               block=block, base_dir=base_dir)
    except SceneError as exc:
        raise SceneError("\n".join([str(exc), *problems, *own])) from None
    for i, sub in enumerate(subs):
        own += named(i, [p for p in geometry_problems(sub)
                         if not p.startswith("[transmitter]") or i == 0])
    problems += own
    if problems:
        raise SceneError(f"{source}: cannot be simulated\n" + "\n".join(problems))
    return line


__all__ = [
    "CREST_HS",
    "MAX_IMAGE_NOISE_RCS",
    "PERTURBATION_SIGMAS",
    "Pulses",
    "Segment",
    "near_field_distance",
    "check_run",
    "crest_bound",
    "exhaustive_min_distance",
    "horizon_problems",
    "geometry_problems",
    "land_problems",
    "MAX_LAND_CELLS",
    "image_noise_rcs",
    "image_problems",
    "min_distance",
    "min_height",
    "nominal_segments",
    "object_problems",
    "hull_problems",
    "output_problems",
    "default_output",
    "image_output",
    "receive_problems",
    "run_problems",
    "two_scale_problems",
]
