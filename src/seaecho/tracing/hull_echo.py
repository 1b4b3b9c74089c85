"""The echoes of a scene's hulls: ``[[objects]]`` with ``scatterer = true``, pulse by pulse.

:class:`HullEchoes` joins the SBR trace (:mod:`.sbr`), the scene (objects, ship track,
sea state, sea water) and the radar (:class:`seaecho.radar.system.RadarSystem`): for each
scatterer object it plans when its signature is traced (:func:`~seaecho.targets.centres.
refresh_schedule`: when the direction to the transmitter or the receiver has turned by
``signature_refresh_deg`` since the last trace, or ``signature_refresh_s`` has elapsed),
traces it at those pulses, moves the scattering centres rigidly with the object between
traces, and hands them to the radar kernel like sea facets (:meth:`HullEchoes.echoes`).

A pulse's echo depends only on (scene, pulse): the schedule is a function of the tracks,
and the trace of a refresh pulse depends only on the geometry at that pulse and the sea
surface held there (``surface(t)``, the simulation's held surface), so pulses can be
computed in any order. Traces are kept in a small cache in memory (a few MB each) and on
disk between runs (:mod:`seaecho.targets.cache`: keyed by a hash of every input of the
trace and of the code, written atomically; ``SEAECHO_CACHE=off`` or ``seaecho run
--no-cache`` disables it).

Each scatterer is traced alone, the other objects (scatterers or not) being occluders:
mutual bounces between two objects are not modelled.

On a spherical Earth (``[propagation] earth = "spherical"``) a hull is traced in the
scene's frame around its own position, and its scattering centres, read as the scene's
Earth-following coordinates like a target's, are placed on the sphere (eq E4 of
:mod:`seaecho.geometry.earth`); a centre echoes only when its straight segments to both
antennas clear the sphere (:func:`horizon_mask`): the part of a hull below the horizon's
tangent ray, the hidden height h_hid = (d - sqrt(2 k a h_1))^2 / (2 k a) at ground
distance d beyond the antenna's horizon (the tangent ray's height, eq E3 of
:mod:`seaecho.geometry.earth` at d - sqrt(2 k a h_1) past its tangent point),
is silent, the rest is heard; a hull wholly below returns nothing.

Identical hulls share traces. Two hulls of the same mesh, material and options whose
directions to the transmitter and the receiver, in each hull's own frame, agree within the
refresh step see the same signature up to a yaw and a shift: the later one (in a fixed
order, hull by hull and refresh by refresh, so the plan is a function of the tracks only)
takes the earlier one's centres turned and moved onto itself (:meth:`HullEchoes.
share_plan`), the approximation a hull already makes between two of its own refreshes. A
trace is shared only where neither hull has the held sea under it (the sea patch of its
trace) and no other object comes near the legs from either hull to the transmitter or the
receiver, or to their images in the sea (bounding spheres): there the trace would have
been the same but for those.
"""

from __future__ import annotations

import dataclasses
import hashlib
import warnings
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..constants import C0
from ..targets.cache import ArrayCache
from ..targets.centres import (
    PATH_NAMES,
    ScatteringCentres,
    coherent_total,
    refresh_schedule,
)
from .sbr import (
    SBROptions,
    SeaPlane,
    Signature,
    TraceMesh,
    material_permittivity,
    signature_arrays,
    signature_from_arrays,
    signature_key,
    trace_signature,
)

__all__ = ["SIGNATURE_NAMESPACE", "Hull", "HullEchoes", "horizon_mask"]

#: Sub-folder of the user cache (:mod:`seaecho.targets.cache`) holding hull signatures.
SIGNATURE_NAMESPACE = "hull-signatures"

#: Traces kept in memory (a trace of the 10 m boat holds ~10^4 centres, < 1 MB).
SIGNATURE_CACHE = 256
#: The sea patch traced around a hull: its bounding radius times this, each side.
_PATCH_MARGIN = 3.0


def horizon_mask(earth, positions: NDArray, tx: NDArray, rx: NDArray
                 ) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Scattering centres (K, 3) [m] in the scene's Earth-following coordinates placed on
    the sphere (eq E4), and whether each is above both antennas' horizon.

    A centre is kept when the straight segments from the transmitter and the receiver
    (tangent frame, (3,) [m]) to it clear the sphere
    (:meth:`seaecho.geometry.earth.SphericalEarth.visible`); a sea-bounce centre, whose
    delay-equivalent position may lie below the mean sea, is tested at the height |z|
    of its hull point's side.

    Returns
    -------
    positions : (K, 3) array
        On the sphere, tangent frame [m].
    seen : (K,) bool array
    """
    p = np.asarray(positions, dtype=np.float64)
    on = earth.position(p)
    test = earth.position(np.concatenate([p[:, :2], np.abs(p[:, 2:])], axis=-1))
    return on, earth.visible(tx, test) & earth.visible(rx, test)


@dataclass(frozen=True)
class Hull:
    """One scatterer object: its meshes, motion, options and refresh schedule.

    Attributes
    ----------
    name : str
        The ``[[objects]]`` name.
    shapes : list of seaecho.tracing.scene.ObjectGeometry
        Its meshes (one for a mesh file, one per shape of an XML scene).
    eps_r : list of complex or None
        Material of each shape (None: perfect conductor).
    options : SBROptions
        Ray density, bounces, cell.
    multipath : bool
        Trace the sea-reflected paths.
    refresh_deg, refresh_s : float
        Refresh step [deg] and interval [s] (0: none).
    schedule : (R,) int array
        Pulses at which the signature is traced.
    waterplane : (float, float) or None
        (length, beam) [m] of the waterplane whose sea the hull follows (heave, pitch,
        roll of :mod:`seaecho.targets.motion`); None: no motion in the waves.
    track : seaecho.wake.Ship or None
        A ship on waypoints (:class:`seaecho.wake.ship.Route`) that carries the hull: its
        origin is the ship's midship position at each time and it turns with the
        route's heading (:meth:`pose`); None: the shapes' constant velocity and
        orientation.
    motion : seaecho.targets.motion.BoxHullMotion or None
        The hull's dynamic response to the waves (heave, pitch, roll as damped
        oscillators); None with a waterplane: the quasi-static plane fit (eq S1).
    """

    name: str
    shapes: list
    eps_r: list
    options: SBROptions
    multipath: bool
    refresh_deg: float
    refresh_s: float
    schedule: NDArray[np.intp]
    waterplane: tuple | None = None
    track: object = None
    motion: object = None

    @property
    def velocity(self) -> NDArray[np.float64]:
        """Rigid velocity [m/s] at time 0 (all shapes of an object share it)."""
        return self.velocity_at(0.0)

    def velocity_at(self, t: float | NDArray) -> NDArray[np.float64]:
        """Velocity of the origin at time(s) t [m/s], shape t.shape + (3,)."""
        t = np.asarray(t, dtype=np.float64)
        if self.track is None:
            v = np.asarray(self.shapes[0].velocity, dtype=np.float64)
            return np.broadcast_to(v, t.shape + (3,)).copy()
        v = self.track.velocity_at(t)
        return np.concatenate([v, np.zeros(t.shape + (1,))], axis=-1)

    def heading(self, t: float | NDArray) -> NDArray[np.float64]:
        """Heading of the object's +x axis, counter-clockwise from +x, at time(s) t [rad]."""
        t = np.asarray(t, dtype=np.float64)
        if self.track is None:
            rot = self.shapes[0].rotation
            return np.full(t.shape, float(np.arctan2(rot[1, 0], rot[0, 0])))
        return self.track.heading_at(t)

    def turn_rate(self, t: float | NDArray) -> NDArray[np.float64]:
        """Yaw rate at time(s) t [rad/s] (0 but on a route's turns)."""
        t = np.asarray(t, dtype=np.float64)
        return np.zeros(t.shape) if self.track is None else self.track.turn_rate_at(t)

    def origin(self, t: float | NDArray) -> NDArray[np.float64]:
        """The object's origin (its ``position_m``, on the ship track) at time(s) t [m]."""
        o = self.shapes[0]
        t = np.asarray(t, dtype=np.float64)
        if self.track is None:
            return np.asarray(o.position) + np.multiply.outer(t, o.velocity)
        p = self.track.position(t)
        return np.concatenate([p, np.full(t.shape + (1,), float(o.position[2]))], axis=-1)

    def pose(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(R, o): the rotation (3, 3) taking the shapes' time-0 orientation to the one at
        time ``t`` [s] (a yaw by h(t) - h(0)) and the origin (3,) at ``t`` [m]."""
        dh = float(self.heading(t) - self.heading(0.0))
        c, s = np.cos(dh), np.sin(dh)
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]), self.origin(t)

    def mesh(self, t: float) -> TraceMesh:
        """The object's meshes at time ``t`` in the world frame [m]."""
        if self.track is None:
            return TraceMesh.merge([TraceMesh.single(o.world_vertices(t), o.faces, e)
                                    for o, e in zip(self.shapes, self.eps_r, strict=True)])
        r, c = self.pose(t)
        o0 = self.origin(0.0)
        return TraceMesh.merge([TraceMesh.single((o.world_vertices(0.0) - o0) @ r.T + c,
                                                 o.faces, e)
                                for o, e in zip(self.shapes, self.eps_r, strict=True)])

    def carry(self, positions: NDArray, time: float, t: float
              ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Points (K, 3) [m] fixed on the hull at ``time`` [s], carried to time ``t`` [s]:
        their positions [m] and velocities [m/s] (K, 3), v = V(t) + omega z x (p - o)
        on a turn of rate omega."""
        p = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
        if self.track is None:
            v = np.asarray(self.shapes[0].velocity, dtype=np.float64)
            return p + v * (t - time), np.broadcast_to(v, p.shape)
        r0, o0 = self.pose(time)
        r1, o1 = self.pose(t)
        q = o1 + (p - o0) @ (r1 @ r0.T).T
        w = float(self.turn_rate(t))
        d = q - o1
        v = self.velocity_at(t) + w * np.stack([-d[:, 1], d[:, 0], np.zeros(len(d))], -1)
        return q, v


def _yaw(u: NDArray, angle: NDArray) -> NDArray[np.float64]:
    """Vectors u (..., 3) turned about +z by ``angle`` (...) [rad]."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * u[..., 0] - s * u[..., 1], s * u[..., 0] + c * u[..., 1],
                     u[..., 2]], axis=-1)


def _check_window(hull: Hull, radar, pulses) -> None:
    """Warn when part of a hull lies outside the receive window (its echo would be cut)."""
    from ..warnings import SeaechoWarning

    w = radar.window
    lo, hi = 0.5 * C0 * w.t0, 0.5 * C0 * (w.t0 + w.duration)
    r = []
    for p in pulses:
        geo = radar.geometry(p)
        v = hull.mesh(geo.time).vertices
        r.append(0.5 * (np.linalg.norm(v - geo.tx.position, axis=-1)
                        + np.linalg.norm(v - geo.rx.position, axis=-1)))
    r = np.concatenate(r)
    if r.min() < lo or r.max() > hi:
        warnings.warn(f"[[objects]] {hull.name}: the hull spans ranges {r.min():.1f}.."
                      f"{r.max():.1f} m, outside the receive window {lo:.1f}..{hi:.1f} m: "
                      "its echo is cut; give [radar] window_start_m / window_end_m",
                      SeaechoWarning, stacklevel=3)


@dataclass(frozen=True)
class HullOptions:
    """Scattering options of one ``[[objects]]`` entry with ``scatterer = true``.

    Attributes
    ----------
    name : str
    rays_per_wavelength : float
        Launch density of the SBR rays [rays per wavelength, along each axis].
    max_bounces : int
        Bounces on the hull followed per ray.
    cell_m : float
        Size of the cells the ray contributions are summed in [m].
    sea_multipath : bool
        Add the paths that bounce on the sea plane.
    refresh_deg, refresh_s : float
        Re-trace when the aspect changes by this much [deg] or after this time [s].
    waterplane : (float, float) or None
        (length, beam) [m]: the hull heaves, pitches and rolls with the sea under this
        waterplane (:attr:`Hull.waterplane`); None: it does not.
    track : seaecho.wake.Ship or None
        The ship on waypoints that carries the hull (:attr:`Hull.track`).
    motion : seaecho.targets.motion.BoxHullMotion or None
        Dynamic response to the waves (:attr:`Hull.motion`).
    """

    name: str
    rays_per_wavelength: float
    max_bounces: int
    cell_m: float
    sea_multipath: bool
    refresh_deg: float
    refresh_s: float
    waterplane: tuple | None = None
    track: object = None
    motion: object = None


@dataclass(frozen=True)
class HullModel:
    """What :class:`HullEchoes` needs, built from a scene by ``seaecho.build``.

    Attributes
    ----------
    objects : tuple of (HullOptions or None, list of ObjectGeometry)
        Every object: its options when it scatters (None: an occluder only), its shapes.
    sea_eps_r : complex
        Sea-water permittivity at the carrier [-].
    sigma_h : float
        Rms height of the sea [m] (rough-sea reflection factor of the multipath legs).
    earth : seaecho.geometry.earth.SphericalEarth or None
        The sphere that hides the hulls' parts below the horizon (None: flat Earth).
    """

    objects: tuple
    sea_eps_r: complex
    sigma_h: float
    earth: object = None


class HullEchoes:
    """Echoes of the scatterer objects of a scene (module docstring).

    Parameters
    ----------
    hulls : list of Hull
        The scatterers.
    others : list of ObjectGeometry
        Every object (occluders of each other's rays).
    radar : seaecho.radar.system.RadarSystem
        The scene's radar (platform tracks, emission times, carrier, kernel).
    sea_eps_r : complex
        Sea-water permittivity [-].
    sigma_h : float
        Rms sea height [m] (rough-sea reflection factor).
    surface : callable, optional
        ``t [s] -> SurfaceState`` (``x``, ``y``, ``elevation``): the sea held at time t,
        whose elevation near a hull occludes its direct legs. None: the mean plane.
    variant : str, optional
        Mitsuba variant.
    disk_cache : seaecho.targets.cache.ArrayCache, optional
        Where traced signatures are kept between runs (default: the user cache folder of
        :mod:`seaecho.targets.cache`, unless ``SEAECHO_CACHE=off``).
    """

    def __init__(self, hulls: list[Hull], others: list, radar, sea_eps_r: complex,
                 sigma_h: float, surface: Callable | None = None,
                 variant: str | None = None, disk_cache: ArrayCache | None = None,
                 earth=None, waves=None) -> None:
        #: the sphere hiding the hulls' parts below the horizon (None: flat Earth)
        self.earth = earth
        self.hulls = hulls
        self.others = others
        self.radar = radar
        self.sea_eps_r = complex(sea_eps_r)
        self.sigma_h = float(sigma_h)
        self.surface = surface
        self.variant = variant
        self.roughness = "miller-brown-vegh"
        self._cache: OrderedDict[tuple[int, int], Signature] = OrderedDict()
        self.disk_cache = (ArrayCache(namespace=SIGNATURE_NAMESPACE) if disk_cache is None
                           else disk_cache)
        #: the random sea as wave components (seaecho.targets.motion.WaveComponents) that
        #: drive the hulls' dynamic motion, or None
        self.waves = waves
        #: (hull, refresh pulse) -> (hull, refresh pulse) whose trace it takes
        #: (:meth:`share_plan`); absent: its own trace
        self.donors: dict[tuple[int, int], tuple[int, int]] = {}
        #: grid nodes (x, y) [m] of the held sea, whose patch a trace near it takes
        self.tile: tuple | None = None
        #: (centres, corners (8, 3) [m] of their box) of the traces used, by id
        self._boxes: dict[int, tuple] = {}

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_model(cls, model: HullModel | None, radar, surface: Callable | None = None,
                   variant: str | None = None, sea_surface=None) -> HullEchoes | None:
        """The hull echoes of a :class:`HullModel` (``seaecho.build.build_hulls``), or
        None when it has no scatterer.

        Parameters
        ----------
        model : HullModel or None
            The objects, their SBR options and the sea's reflection parameters.
        radar : seaecho.radar.system.RadarSystem
            The scene's radar.
        surface : callable, optional
            The held sea surface at a time (:attr:`surface`).
        variant : str, optional
            Mitsuba variant.
        sea_surface : seaecho.ocean.surface.SeaSurface, optional
            The random sea whose wave components drive the hulls' dynamic motion
            (:class:`seaecho.targets.motion.BoxHullMotion`).
        """
        if model is None or not any(spec is not None for spec, _ in model.objects):
            return None
        f = radar.carrier
        t = radar.emission_time(np.arange(radar.n_pulses))
        tx = radar.tx.state(t).position
        rx = radar.rx.state(t).position
        hulls = []
        for spec, shapes in model.objects:
            if spec is None:
                continue
            eps = [material_permittivity(f, itu_type=o.itu_type,
                                         relative_permittivity=o.relative_permittivity,
                                         conductivity=o.conductivity) for o in shapes]
            options = SBROptions(rays_per_wavelength=spec.rays_per_wavelength,
                                 max_bounces=spec.max_bounces, cell=spec.cell_m)
            hull = Hull(spec.name, shapes, eps, options, spec.sea_multipath,
                        spec.refresh_deg, spec.refresh_s, np.zeros(1, dtype=np.intp),
                        spec.waterplane, spec.track, spec.motion)
            # Aspect of the transmitter and the receiver from the hull at every pulse, in
            # the hull's own (yawing) frame: a turn changes the aspect as a radar would
            c = hull.origin(t)
            ut = _yaw((tx - c) / np.linalg.norm(tx - c, axis=-1, keepdims=True),
                      -hull.heading(t))
            ur = _yaw((rx - c) / np.linalg.norm(rx - c, axis=-1, keepdims=True),
                      -hull.heading(t))
            sched = refresh_schedule(ut, ur, t, np.deg2rad(spec.refresh_deg), spec.refresh_s)
            hulls.append(dataclasses.replace(hull, schedule=sched))
            _check_window(hull, radar, (0, radar.n_pulses - 1))
        others = [o for _, shapes in model.objects for o in shapes]
        waves = None
        if sea_surface is not None and any(h.motion is not None for h in hulls):
            from ..targets.motion import WaveComponents

            waves = WaveComponents(*sea_surface.components())
        out = cls(hulls, others, radar, model.sea_eps_r, model.sigma_h, surface=surface,
                  variant=variant, earth=model.earth, waves=waves)
        if surface is not None:
            out.tile = ((np.asarray(sea_surface.x), np.asarray(sea_surface.y))
                        if sea_surface is not None else None)
        if surface is None or out.tile is not None:
            out.donors = out.share_plan()
        return out

    # ------------------------------------------------------------------ sharing
    @staticmethod
    def _shape_key(hull: Hull) -> str | None:
        """A digest of what a trace depends on besides the geometry (the mesh in its own
        frame, materials, options, multipath, refresh step), or None when the hull cannot
        share (several shapes, or an orientation other than a yaw)."""
        if len(hull.shapes) != 1:
            return None
        o = hull.shapes[0]
        rot = np.asarray(o.rotation, dtype=np.float64)
        if not np.allclose(rot[2], [0.0, 0.0, 1.0], atol=1e-12):
            return None
        d = hashlib.sha256()
        for a in (np.asarray(o.vertices, dtype=np.float64), np.asarray(o.faces)):
            d.update(np.ascontiguousarray(a).tobytes())
        d.update(repr((hull.eps_r, hull.options, hull.multipath, hull.refresh_deg,
                       hull.refresh_s, float(o.position[2]))).encode())
        return d.hexdigest()

    def _free(self, index: int, pulse: int) -> bool:
        """Whether the trace of hull ``index`` at ``pulse`` would see neither the held sea
        (no sea patch) nor another object near its legs to T and R or their sea images."""
        h = self.hulls[index]
        t = float(self.radar.emission_time(pulse))
        v = h.mesh(t).vertices
        lo, hi = v.min(axis=0), v.max(axis=0)
        c, r = 0.5 * (lo + hi), 0.5 * float(np.linalg.norm(hi - lo))
        if self.tile is not None:  # as _patch: a patch where nodes fall near the hull
            x, y = self.tile
            if (np.count_nonzero(np.abs(x - c[0]) <= _PATCH_MARGIN * r) >= 2
                    and np.count_nonzero(np.abs(y - c[1]) <= _PATCH_MARGIN * r) >= 2):
                return False
        geo = self.radar.geometry(pulse)
        ends = [geo.tx.position, geo.rx.position]
        ends += [e * np.array([1.0, 1.0, -1.0]) for e in ends]
        own = {id(o) for o in h.shapes}
        carried = {id(o): g for g in self.hulls if g is not h for o in g.shapes}
        for o in self.others:
            if id(o) in own:
                continue
            w = (carried[id(o)].mesh(t).vertices if id(o) in carried
                 else o.world_vertices(t))
            lo2, hi2 = w.min(axis=0), w.max(axis=0)
            c2, r2 = 0.5 * (lo2 + hi2), 0.5 * float(np.linalg.norm(hi2 - lo2))
            for e in ends:  # distance from c2 to the segment c-e
                d = e - c
                u = float(np.clip((c2 - c) @ d / (d @ d), 0.0, 1.0))
                if np.linalg.norm(c + u * d - c2) <= r + r2:
                    return False
        return True

    def _aspect(self, index: int, pulse: int) -> tuple[NDArray, NDArray]:
        """Unit directions to T and R in hull ``index``'s frame at ``pulse`` [-]."""
        h = self.hulls[index]
        t = float(self.radar.emission_time(pulse))
        geo = self.radar.geometry(pulse)
        c = h.origin(t)
        out = []
        for e in (geo.tx.position, geo.rx.position):
            u = (e - c) / np.linalg.norm(e - c)
            out.append(_yaw(u, -h.heading(t)))
        return out[0], out[1]

    def share_plan(self) -> dict[tuple[int, int], tuple[int, int]]:
        """Which (hull, refresh pulse) takes which earlier one's trace (module docstring).

        Hulls in index order, each one's refresh pulses in order: a free refresh
        (:meth:`_free`) of a shareable hull takes the first free trace of the same
        :meth:`_shape_key` whose directions to T and R, each in its hull's frame, are
        within the refresh step of its own; else it is traced and may serve later ones.
        """
        keys = [self._shape_key(h) for h in self.hulls]
        counts: dict[str, int] = {}
        for k in keys:
            if k is not None:
                counts[k] = counts.get(k, 0) + 1
        donors: dict[str, list] = {}
        plan: dict[tuple[int, int], tuple[int, int]] = {}
        for i, h in enumerate(self.hulls):
            k = keys[i]
            if k is None or counts[k] < 2:
                continue
            cos_step = np.cos(np.deg2rad(h.refresh_deg))
            for ref in h.schedule.tolist():
                if not self._free(i, ref):
                    continue
                ut, ur = self._aspect(i, ref)
                pool = donors.setdefault(k, [])
                for j, rj, vt, vr in pool:
                    if j != i and ut @ vt >= cos_step and ur @ vr >= cos_step:
                        plan[(i, ref)] = (j, rj)
                        break
                else:
                    pool.append((i, ref, ut, ur))
        return plan

    def _moved(self, sig: Signature, donor: tuple[int, int], index: int,
               pulse: int) -> Signature:
        """The donor's signature turned and moved onto hull ``index`` at ``pulse``."""
        j, rj = donor
        tj = float(self.radar.emission_time(rj))
        ti = float(self.radar.emission_time(pulse))
        hj, hi = self.hulls[j], self.hulls[index]
        dh = float(hi.heading(ti) - hj.heading(tj))
        c, s = np.cos(dh), np.sin(dh)
        rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        oj, oi = hj.origin(tj), hi.origin(ti)
        cj = sig.centres
        centres = ScatteringCentres(oi + (cj.position - oj) @ rot.T, cj.s, cj.path, ti,
                                    hi.velocity_at(ti))
        geo = self.radar.geometry(pulse)
        return dataclasses.replace(sig, centres=centres,
                                   reference=oi + rot @ (sig.reference - oj),
                                   tx=geo.tx.position, rx=geo.rx.position)

    # ---------------------------------------------------------------------- traces
    def refresh_pulse(self, hull: int, pulse: int) -> int:
        """The pulse whose trace serves ``pulse`` for hull number ``hull``."""
        sched = self.hulls[hull].schedule
        return int(sched[np.searchsorted(sched, pulse, side="right") - 1])

    def signature(self, hull: int, pulse: int) -> Signature:
        """The trace serving ``pulse`` (computed at its refresh pulse, or another
        identical hull's moved onto this one (:meth:`share_plan`), cached)."""
        ref = self.refresh_pulse(hull, pulse)
        key = (hull, ref)
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        donor = self.donors.get(key)
        if donor is None:
            sig = self._trace(hull, ref)
        else:
            sig = self._moved(self.signature(*donor), donor, hull, ref)
        self._cache[key] = sig
        if len(self._cache) > SIGNATURE_CACHE:
            self._cache.popitem(last=False)
        return sig

    def _trace(self, index: int, pulse: int) -> Signature:
        h = self.hulls[index]
        t = float(self.radar.emission_time(pulse))
        geo = self.radar.geometry(pulse)
        mesh = h.mesh(t)
        own = {id(o) for o in h.shapes}
        # the other hulls where their tracks put them, the other objects on their own
        carried = {id(o): g for g in self.hulls if g is not h for o in g.shapes}
        occluders = [TraceMesh.single(o.world_vertices(t), o.faces)
                     for o in self.others if id(o) not in own and id(o) not in carried]
        occluders += [TraceMesh.single(g.mesh(t).vertices, g.mesh(t).faces)
                      for g in {id(g): g for g in carried.values()}.values()]
        patch = None
        if self.surface is not None:
            patch = self._patch(mesh, self.surface(t))
        sea = SeaPlane(level=0.0, eps_r=self.sea_eps_r if h.multipath else None,
                       sigma_h=self.sigma_h, roughness=self.roughness, patch=patch)
        args = (mesh, geo.tx.position, geo.rx.position, self.radar.carrier)
        kw = {"options": h.options, "sea": sea, "occluders": occluders,
              "reference": h.origin(t), "time": t, "velocity": h.velocity_at(t),
              "variant": self.variant}
        if not self.disk_cache.enabled:
            return trace_signature(*args, **kw)
        # On disk, keyed by every input and the code (seaecho.targets.cache): a hit is
        # the bytes the trace would give
        key = signature_key(*args, **kw)
        hit = self.disk_cache.get(key)
        if hit is not None:
            return signature_from_arrays(hit)
        sig = trace_signature(*args, **kw)
        self.disk_cache.put(key, signature_arrays(sig))
        return sig

    @staticmethod
    def _patch(mesh: TraceMesh, state):
        """The held sea elevation around a hull (None when the hull is off the tile)."""
        v = mesh.vertices
        lo, hi = v.min(axis=0), v.max(axis=0)
        c, r = 0.5 * (lo + hi), 0.5 * float(np.linalg.norm(hi - lo))
        x, y = state.x, state.y
        ix = np.flatnonzero(np.abs(x - c[0]) <= _PATCH_MARGIN * r)
        iy = np.flatnonzero(np.abs(y - c[1]) <= _PATCH_MARGIN * r)
        if ix.size < 2 or iy.size < 2:
            return None
        sl = (slice(iy[0], iy[-1] + 1), slice(ix[0], ix[-1] + 1))
        return x[sl[1]], y[sl[0]], np.asarray(state.elevation)[sl]

    # ---------------------------------------------------------------------- pulses
    def echoes(self, geometry, pulse: int, seen: Callable | None = None) -> list:
        """Echoes of every hull for one pulse (a ``ScattererEcho`` each, or a
        ``DeviceEcho`` where the radar keeps it on its GPU:
        ``RadarSystem.scatterer_echo``'s ``on_device``).

        Parameters
        ----------
        geometry : seaecho.radar.system.PulseGeometry
            ``radar.geometry(pulse)``.
        pulse : int
            Pulse index.
        seen : callable, optional
            ``corners (8, 3) [m] -> bool``: False skips a hull whose scattering centres
            at this pulse lie in the convex hull of these corners (the beams do not
            reach it; ``seaecho.simulation``). The corners are those of the box of the
            trace's centres, carried with the hull and its motion in the waves (rigid
            motions keep a point of the box inside the carried corners' hull).
        """
        out = []
        for i in range(len(self.hulls)):
            c = self.signature(i, pulse).centres
            if len(c) == 0:
                continue
            if seen is not None:
                kept = self._boxes.get(id(c))
                if kept is not None and kept[0] is c:
                    box = kept[1]
                else:  # the corners of the trace's centres, kept with them
                    lo, hi = c.position.min(axis=0), c.position.max(axis=0)
                    box = np.array([[x, y, z] for x in (lo[0], hi[0])
                                    for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
                    if len(self._boxes) > 4 * SIGNATURE_CACHE:
                        self._boxes.clear()
                    self._boxes[id(c)] = (c, box)
                box = self.hulls[i].carry(box, c.time, geometry.time)[0]
                if self.hulls[i].waterplane is not None:
                    box = self.in_waves(i, box, geometry.time)
                if not seen(box):
                    continue
            pos, vel = self.hulls[i].carry(c.position, c.time, geometry.time)
            if self.hulls[i].waterplane is not None:
                pos = self.in_waves(i, pos, geometry.time)
            s = c.s
            if s.flags.writeable:  # held until the next trace: uploaded once on a device
                s.flags.writeable = False
            if self.earth is not None:  # on the sphere; the part below the horizon hidden
                pos, above = horizon_mask(self.earth, pos, geometry.tx.position,
                                          geometry.rx.position)
                if not above.any():
                    continue
                if not above.all():
                    pos, vel, s = pos[above], vel[above], s[above]
            out.append(self.radar.scatterer_echo(geometry, pos, vel, s, on_device=True))
        return out

    def attitude(self, hull: int, t: float) -> tuple[float, float, float]:
        """(heave [m], pitch [rad], roll [rad]) of hull number ``hull`` at time ``t``
        [s]: its dynamic response to the random sea
        (:class:`seaecho.targets.motion.BoxHullMotion`) or the plane fitted to the held sea
        (:func:`seaecho.targets.motion.waterplane_motion`); zeros without a sea or a
        waterplane."""
        from ..targets.motion import waterplane_motion

        h = self.hulls[hull]
        if h.motion is not None:  # the dynamic response to the random sea (eq S3)
            if self.waves is None:
                return 0.0, 0.0, 0.0
            return h.motion.attitude(self.waves, h.origin(t)[:2], float(h.heading(t)),
                                     h.velocity_at(t)[:2], t)
        if h.waterplane is None or self.surface is None:
            return 0.0, 0.0, 0.0
        st = self.surface(t)
        heading = float(h.heading(t))
        return waterplane_motion(st.x, st.y, st.elevation, h.origin(t)[:2], heading,
                                 *h.waterplane)

    def in_waves(self, hull: int, positions: NDArray, t: float) -> NDArray[np.float64]:
        """Scattering-centre positions (K, 3) [m] of hull number ``hull`` moved rigidly
        by its heave, pitch and roll at ``t`` [s] (:meth:`attitude`) about its origin.

        The signature is not traced again for the tilted hull: the centres (sea-bounce
        images included) turn and rise with it, which moves their delays and Doppler;
        their amplitudes are those of the upright hull (docs/targets.md)."""
        from ..targets.motion import hull_rotation

        heave, pitch, roll = self.attitude(hull, t)
        if heave == 0.0 and pitch == 0.0 and roll == 0.0:
            return positions
        r = hull_rotation(float(self.hulls[hull].heading(t)), pitch, roll)
        o = self.hulls[hull].origin(t)
        return o + (np.asarray(positions) - o) @ r.T + np.array([0.0, 0.0, heave])

    # ---------------------------------------------------------------- ground truth
    def truth(self, pulse: int) -> tuple[dict, dict]:
        """Dataset variables and coordinates: centres of ``pulse``, RCS over the run.

        Returns
        -------
        data, coords : dict
            xarray ``(dims, values, attrs)`` tuples.
        """
        radar = self.radar
        n = radar.n_pulses
        t = radar.emission_time(np.arange(n))
        tx = radar.tx.state(t).position
        rx = radar.rx.state(t).position
        k = 2.0 * np.pi * radar.carrier / C0
        nh = len(self.hulls)
        rcs = np.zeros((nh, n, 4))
        rcs_free = np.zeros((nh, n, 4))
        origin = np.zeros((nh, n, 3))
        served = np.zeros((nh, n), dtype=np.int64)
        served_by = np.zeros((nh, n), dtype=np.int64)
        pos, s, path, which = [], [], [], []
        for i, h in enumerate(self.hulls):
            origin[i] = h.origin(t)
            for p in range(n):  # per pulse: one coherent sum over the centres (eq C3)
                c = self.signature(i, p).centres
                served[i, p] = self.refresh_pulse(i, p)
                d = self.donors.get((i, int(served[i, p])))
                if d is not None:
                    served[i, p] = d[1]
                served_by[i, p] = i if d is None else d[0]
                x = h.carry(c.position, c.time, t[p])[0]
                tot = coherent_total(x, c.s, tx[p], rx[p], k, origin[i, p])
                direct = c.path == 0
                free = coherent_total(x[direct], c.s[direct], tx[p], rx[p], k, origin[i, p])
                rcs[i, p] = np.abs(tot.reshape(4)) ** 2
                rcs_free[i, p] = np.abs(free.reshape(4)) ** 2
            c = self.signature(i, pulse).centres
            pos.append(h.carry(c.position, c.time, float(t[pulse]))[0])
            s.append(c.s.reshape(-1, 4))
            path.append(c.path)
            which.append(np.full(len(c), i, dtype=np.int16))
        pol = "polarisation"
        data = {
            "hull_rcs": (("hull", "pulse", pol), rcs, {
                "units": "m2", "long_name": "apparent RCS |sum of centres|^2 of each hull "
                "referred to its origin, sea multipath included (eq C3, docs/ship.md)"}),
            "hull_rcs_free_space": (("hull", "pulse", pol), rcs_free, {
                "units": "m2", "long_name": "RCS of the direct paths only (no sea bounce)"}),
            "hull_position": (("hull", "pulse", "xyz"), origin, {
                "units": "m", "long_name": "hull origin (object position_m on its track)"}),
            "hull_trace_pulse": (("hull", "pulse"), served, {
                "long_name": "pulse whose ray trace (signature) serves this pulse; "
                "centres move rigidly with the hull in between"}),
            "hull_trace_hull": (("hull", "pulse"), served_by, {
                "long_name": "index of the hull whose trace serves this pulse (another "
                "than its own: an identical hull's trace at the same aspect, turned and "
                "moved onto it; docs/ship.md)"}),
            "hull_centre_position": (("centre", "xyz"), np.concatenate(pos), {
                "units": "m", "long_name": f"scattering centres at pulse {pulse} "
                "(delay-equivalent positions)"}),
            "hull_centre_scattering": (("centre", pol), np.concatenate(s), {
                "units": "m", "long_name": "centre amplitude s_mn (FSA bases), "
                "|s|^2 = RCS"}),
            "hull_centre_path": (("centre",), np.concatenate(path), {
                "long_name": "path kind", "flag_values": np.arange(4, dtype=np.int8),
                "flag_meanings": " ".join(PATH_NAMES)}),
            "hull_centre_hull": (("centre",), np.concatenate(which),
                                 {"long_name": "index along the hull dimension"}),
        }
        opts = {
            "hull_rays_per_wavelength": [h.options.rays_per_wavelength for h in self.hulls],
            "hull_max_bounces": [h.options.max_bounces for h in self.hulls],
            "hull_cell": [h.options.cell for h in self.hulls],
            "hull_refresh_deg": [h.refresh_deg for h in self.hulls],
            "hull_refresh_s": [h.refresh_s for h in self.hulls],
            "hull_sea_multipath": [int(h.multipath) for h in self.hulls],
        }
        units = {"hull_cell": "m", "hull_refresh_deg": "degree", "hull_refresh_s": "s"}
        for name, values in opts.items():
            data[name] = (("hull",), np.asarray(values), {"units": units.get(name, "1")})
        data["hull_sea_sigma_h"] = ((), self.sigma_h, {
            "units": "m", "long_name": "rms sea height of the rough-sea specular factor "
            f"({self.roughness}), applied to the sea-reflected legs"})
        coords = {"hull": ("hull", np.array([h.name for h in self.hulls]))}
        return data, coords
