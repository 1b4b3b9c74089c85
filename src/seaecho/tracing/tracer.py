"""Ray-traced facets: visibility of every sea facet from the transmitter and the receiver.

A facet is *lit* when it faces the transmitter (``-n_i . N > 0``) and the segment from
its centroid to the transmitter hits neither the sea nor any object; *seen* likewise for
the receiver (``n_s . N > 0``). The segments start ``eps`` above the centroid along the
normal, ``eps = max(1e-3 * cell size, 8 float32 ulps of the largest facet coordinate)``, so that
a ray does not hit its own triangle in float32. Everything else (ranges, directions,
angles, bases) is float64, computed by the Dr.Jit kernel
:func:`seaecho.tracing.kernels.facet_frames_drjit` (the formulas of the numpy
:func:`seaecho.geometry.facets.facet_frames`, faster), on the tracer's variant (CPU
``llvm_*`` or GPU ``cuda_*``).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.

Periodic apron
--------------
The FFT sea tile is periodic: the sea in front of it (towards the radar) is its own
periodic continuation. Traced alone, the tile leaves the facets near its edge towards the
radar without the waves in front of them: at a grazing angle psi a crest of height h
shadows h / tan psi behind it (190 m for 1 m at 0.3 deg, more than a 128 m tile). With
``period_m`` the tracer also tests every shadow ray against the tile's periodic copies
translated by (i L_x, j L_y) (eq A1: a segment blocked by the copy translated by T is the
segment translated by -T blocked by the tile), for every copy that a segment crosses
before it rises above the highest wave of the surface, z_max (its ground reach
(z_max - z_0) / tan(elevation), eq A2): the exact occlusion of the periodic model of the
sea by itself. The objects are not repeated.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..backend import Boundary, drjit_namespace
from ..geometry.facets import Facets
from ..geometry.mesh import facet_geometry, facet_geometry_in, grid_vertices, to_facets
from .heightfield import WALK_MAX_CELLS, heightfield_blocked, walk_cells
from .kernels import facet_frames_drjit
from .scene import ObjectGeometry, ObjectScene, SeaScene, shadow_test
from .variant import set_variant

__all__ = ["FacetTracer"]


class FacetTracer:
    """The sea (plus objects) in Sionna RT / Mitsuba scenes, traced facet by facet.

    Parameters
    ----------
    x : (nx,) array
        Node abscissae [m].
    y : (ny,) array
        Node ordinates [m].
    elevation : (ny, nx) array, optional
        Initial elevation [m] (default flat).
    objects : sequence of ObjectGeometry
        Occluding objects (:func:`seaecho.tracing.scene.load_object`); static ones go in
        one scene built once, moving ones in another (the sea's BVH is never rebuilt
        because an object moved).
    eps_r : complex, optional
        Sea-water permittivity [-] (kept by the sea scene; the shadow rays do not use it).
    frequency_hz : float
        Carrier frequency [Hz].
    variant : str, optional
        Mitsuba variant (default ``llvm_ad_mono_polarized``).
    period_m : (float, float), optional
        Periods (L_x, L_y) [m] of a periodic sea (an FFT tile: ``n * spacing``): the
        shadow rays are also traced against the tile's periodic copies (module
        docstring, "Periodic apron"). None: the tile alone.
    """

    def __init__(self, x: np.ndarray, y: np.ndarray, elevation: np.ndarray | None = None, *,
                 objects: Sequence[ObjectGeometry] = (), eps_r: complex | None = None,
                 frequency_hz: float = 10.0e9, variant: str | None = None,
                 period_m: tuple[float, float] | None = None) -> None:
        #: The Mitsuba variant of the scenes and of the frames kernel (one per process).
        self.variant = set_variant(variant)
        variant = self.variant
        self.x = np.asarray(x, dtype=np.float64)
        self.y = np.asarray(y, dtype=np.float64)
        z = np.zeros((self.y.size, self.x.size)) if elevation is None else elevation
        if period_m is not None and not (period_m[0] > 0 and period_m[1] > 0):
            raise ValueError(f"period_m = {period_m}: periods must be > 0 [m]")
        #: (L_x, L_y) of the periodic sea [m], or None (the tile alone)
        self.period_m = None if period_m is None else (float(period_m[0]),
                                                       float(period_m[1]))
        # a periodic sea's mesh closes its seams: the node row and column at x_0 + L_x,
        # y_0 + L_y repeat the first ones (the strip between the copies is sea too)
        x_mesh, y_mesh = self.x, self.y
        if self.period_m is not None:
            x_mesh = np.append(self.x, self.x[0] + self.period_m[0])
            y_mesh = np.append(self.y, self.y[0] + self.period_m[1])
        self.sea = SeaScene(x_mesh, y_mesh, self._mesh_elevation(z), eps_r=eps_r,
                            frequency_hz=frequency_hz, variant=variant)
        self._elevation = np.array(z, dtype=np.float64)
        static = [o for o in objects if not o.moving]
        moving = [o for o in objects if o.moving]
        self.static_objects = ObjectScene(static, variant=variant) if static else None
        self.moving_objects = ObjectScene(moving, variant=variant) if moving else None
        #: trace the sea's shadow rays by the grid walk where it is short (no BVH
        #: rebuild for a new surface; :mod:`seaecho.tracing.heightfield`: the same
        #: masks); False: always Embree's / OptiX's BVH
        self.walk = bool(np.allclose(np.diff(self.x), self.x[1] - self.x[0], rtol=1e-9)
                         and np.allclose(np.diff(self.y), self.y[1] - self.y[0], rtol=1e-9))
        cell = min(np.min(np.diff(self.x)), np.min(np.diff(self.y)))
        self._cell = float(cell)
        self._scale_of: tuple[np.ndarray, float] | None = None

    def move(self, x: np.ndarray, y: np.ndarray, elevation: np.ndarray,
             period_m: tuple[float, float] | None = None) -> None:
        """Put the sea on another grid of the same shape (node abscissae ``x``, ordinates
        ``y``, ``elevation`` (ny, nx) [m], the periods ``period_m`` [m] of a periodic sea,
        as the constructor's): the tracer of a tile of the same level reused for the
        next one, as a new tracer of that grid traces (its sea scene moved,
        :meth:`SeaScene.move`); the objects stay."""
        x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
        if x.shape != self.x.shape or y.shape != self.y.shape:
            raise ValueError(f"grid of {y.size} x {x.size} nodes, expected "
                             f"{self.y.size} x {self.x.size}")
        if (period_m is None) != (self.period_m is None):
            raise ValueError("move: a periodic sea stays periodic (period_m)")
        if period_m is not None:
            self.period_m = (float(period_m[0]), float(period_m[1]))
        x_mesh, y_mesh = x, y
        if self.period_m is not None:
            x_mesh = np.append(x, x[0] + self.period_m[0])
            y_mesh = np.append(y, y[0] + self.period_m[1])
        z = np.asarray(elevation, dtype=np.float64)
        self.sea.move(x_mesh, y_mesh, self._mesh_elevation(z))
        self.x, self.y = x, y
        self._elevation = np.array(z, dtype=np.float64)
        self._cell = float(min(np.min(np.diff(x)), np.min(np.diff(y))))
        self._scale_of = None

    @property
    def mi_scenes(self) -> list:
        """The Mitsuba scenes every shadow ray is tested against."""
        out = [self.sea.mi_scene]
        out += [s.mi_scene for s in (self.static_objects, self.moving_objects) if s is not None]
        return out

    def set_surface(self, elevation: np.ndarray) -> bool:
        """New sea elevation (ny, nx) [m]: vertex update of the sea scene (its BVH is
        rebuilt when next traced, :class:`~seaecho.tracing.scene.SeaScene`).

        Returns False (and rebuilds nothing) when the elevation equals the current one, as
        when the surface is held between pulses (paper section V-B).
        """
        z = np.asarray(elevation, dtype=np.float64)
        if z is self._elevation or np.array_equal(z, self._elevation):
            return False
        self.sea.update(self._mesh_elevation(z))
        self._elevation = np.array(z)
        return True

    def _mesh_elevation(self, z: np.ndarray) -> np.ndarray:
        """The sea mesh's node heights [m]: ``z`` (ny, nx), with the wrapped row and
        column of a periodic sea (ny + 1, nx + 1)."""
        z = np.asarray(z, dtype=np.float64)
        if self.period_m is None:
            return z
        return np.pad(z, ((0, 1), (0, 1)), mode="wrap")

    def set_time(self, t: float) -> None:
        """Move the moving objects to their positions at time ``t`` [s]."""
        if self.moving_objects is not None:
            self.moving_objects.move_to(t)

    def occluded(self, centroid: np.ndarray, normal: np.ndarray, position: np.ndarray,
                 mask: np.ndarray | None = None, *, device: bool = False):
        """Whether the segments from the facets to a position hit the sea or an object.

        The rays are set up (origin, direction, length, in float64) and tested on the
        tracer's back end: read-only facet arrays (a held sea's geometry) are on the device
        already (:func:`seaecho.backend.resident`), and with ``device=True`` the result
        stays there too.

        Parameters
        ----------
        centroid, normal : (N, 3) arrays, or namespace vectors
            Facet centroids [m] and unit normals [-] of the current surface (namespace
            vectors: :meth:`surface_geometry`, with ``mask`` None).
        position : (3,) array
            Transmitter or receiver position [m].
        mask : (N,) bool array, optional
            Only trace these facets (others come back False).
        device : bool
            Return the namespace's Bool array (``drjit.llvm`` or ``drjit.cuda``, no read
            back) instead of numpy; needs ``mask`` None.

        Returns
        -------
        (N,) bool array, or a Dr.Jit Bool array when ``device``
        """
        xp = drjit_namespace(self.variant)
        p = np.asarray(position, dtype=np.float64)
        if not isinstance(centroid, np.ndarray):  # on the device already
            if mask is not None:
                raise ValueError("occluded: a mask needs numpy centroids and normals")
            return self._occluded_device(xp, centroid, normal, p, device)
        idx = None if mask is None else np.flatnonzero(mask)
        if idx is not None and idx.size == centroid.shape[0]:
            idx = None  # every facet traced: no gather, no scatter
        if device and idx is not None:
            raise ValueError("occluded(device=True) traces every facet (mask must be None)")
        c = centroid if idx is None else centroid[idx]
        nrm = normal if idx is None else normal[idx]
        n = c.shape[0]
        if n == 0:
            return xp.Bool(np.zeros(0, dtype=bool)) if device else np.zeros(
                centroid.shape[0], dtype=bool)
        io = Boundary(xp, n)
        blocked = self._blocked(xp, io, io.vec3(c), io.vec3(nrm), self._scale(c), p,
                                lambda: c)
        if device:
            xp.eval(blocked)
            return blocked
        hit_sub = np.asarray(xp.host(blocked), dtype=bool)
        if idx is None:
            return hit_sub.copy()
        hit = np.zeros(centroid.shape[0], dtype=bool)
        hit[idx] = hit_sub
        return hit

    def surface_geometry(self):
        """Centroids [m] and unit normals [-] of the current surface's facets as
        namespace vectors, computed on the device from the nodes
        (:func:`seaecho.geometry.mesh.facet_geometry_in`: the numbers of the numpy
        :func:`~seaecho.geometry.mesh.facet_geometry`), for :meth:`occluded`."""
        xp = drjit_namespace(self.variant)
        io = Boundary(xp)
        z = io.array(self._elevation.ravel())
        f = facet_geometry_in(xp, io.array(self.x), io.array(self.y), z,
                              xp.vec(z, z, z), self.x.size, self.y.size)
        c, nrm = f["centroid"], f["normal"]
        xp.eval(c, nrm)
        self._keep_io = io  # the node copies, until the kernel has run
        return c, nrm

    def _occluded_device(self, xp, c, nrm, p: np.ndarray, device: bool):
        """:meth:`occluded` of every facet, centroids and normals on the device."""
        dr = xp.dr
        n = dr.width(c.x)
        if n == 0:
            return xp.Bool(np.zeros(0, dtype=bool)) if device else np.zeros(0, dtype=bool)
        scale = float(dr.max(dr.maximum(dr.maximum(dr.abs(c.x), dr.abs(c.y)),
                                        dr.abs(c.z)))[0])
        io = Boundary(xp, n)
        blocked = self._blocked(xp, io, c, nrm, scale, p, lambda: np.column_stack(
            [np.asarray(xp.host(a), dtype=np.float64) for a in (c.x, c.y, c.z)]))
        if device:
            xp.eval(blocked)
            return blocked
        return np.asarray(xp.host(blocked), dtype=bool).copy()

    def _blocked(self, xp, io, c_dev, nrm_dev, scale: float, p: np.ndarray, c_host):
        """The shadow test of the segments from the facets (namespace vectors
        ``c_dev``, ``nrm_dev``; ``c_host()`` their numpy centroids, for the apron) to
        ``p``: namespace Bool."""
        # float32 resolution at the ray origins (the facets), not at the far end
        eps = max(1e-3 * self._cell, 8.0 * np.finfo(np.float32).eps * scale)
        origin = c_dev + nrm_dev * xp.const(eps)
        d = xp.vconst(p) - origin
        r = xp.sqrt(xp.dot(d, d))
        d = d / r
        maxt = r * (1.0 - 1e-6)
        if self._walks(p):  # the sea by the grid walk, the objects by their BVHs
            reach = None
            if self.period_m is not None:
                reach = io.array(self.apron_copies(c_host(), p)[1])
            blocked = heightfield_blocked(xp, self.sea.vertices, origin, d, maxt,
                                          period_m=self.period_m, reach=reach)
            objects = [s.mi_scene for s in (self.static_objects, self.moving_objects)
                       if s is not None]
            if objects:
                blocked = blocked | xp.Bool(shadow_test(objects, origin, d, maxt,
                                                        variant=self.variant))
        else:
            blocked = xp.Bool(shadow_test(self.mi_scenes, origin, d, maxt,
                                          variant=self.variant))
            if self.period_m is not None:
                blocked = self._apron(c_host(), p, origin, d, blocked, xp, io)
        return blocked

    def _walks(self, position: np.ndarray) -> bool:
        """Whether the sea's shadow rays to ``position`` take the grid walk
        (:mod:`seaecho.tracing.heightfield`: :attr:`walk` on, a CPU variant, and an
        estimated walk of at most ``WALK_MAX_CELLS`` cells) rather than the BVH."""
        if not self.walk or not self.variant.startswith("llvm"):
            return False
        z = self.sea.vertices[..., 2]
        return walk_cells(self.x, self.y, float(z.min()), float(z.max()),
                          position) <= WALK_MAX_CELLS

    def apron_copies(self, centroid: np.ndarray, position: np.ndarray
                     ) -> tuple[list[tuple[int, int]], np.ndarray]:
        """The tile's periodic copies that the segments from the facets to a position
        cross below the highest wave (module docstring, "Periodic apron").

        Parameters
        ----------
        centroid : (N, 3) array
            Facet centroids [m].
        position : (3,) array
            Transmitter or receiver position [m].

        Returns
        -------
        copies : list of (i, j)
            Indices of the copies translated by (i L_x, j L_y), the tile (0, 0) excluded.
        reach : (N,) array
            Length of each segment up to the height of the highest wave [m] (eq A2; the
            whole segment where it does not rise).
        """
        if self.period_m is None:
            return [], np.zeros(centroid.shape[0])
        lx, ly = self.period_m
        v = np.asarray(position, dtype=np.float64) - centroid
        r = np.sqrt(np.einsum("ij,ij->i", v, v))
        up = v[:, 2] / r  # sine of the segment's elevation
        z_top = float(np.max(self._elevation))
        with np.errstate(divide="ignore", invalid="ignore"):
            # (A2) the segment is above every wave beyond (z_max - z_0) / sin(elevation)
            reach = np.where(up > 0.0, np.minimum(
                r, np.maximum(z_top - centroid[:, 2], 0.0) / up), r)
        ends = centroid[:, :2] + v[:, :2] * (reach / r)[:, None]
        lo = np.minimum(centroid[:, :2], ends)
        hi = np.maximum(centroid[:, :2], ends)
        origin = np.array([self.x[0], self.y[0]])
        period = np.array([lx, ly])
        i_lo, j_lo = np.floor((lo.min(axis=0) - origin) / period).astype(int)
        i_hi, j_hi = np.floor((hi.max(axis=0) - origin) / period).astype(int)
        copies = [(i, j) for j in range(j_lo, j_hi + 1) for i in range(i_lo, i_hi + 1)
                  if (i, j) != (0, 0)]
        return copies, reach

    def _apron(self, c: np.ndarray, p: np.ndarray, origin, d, blocked, xp, io):
        """``blocked`` or'ed with the segments' hits on the tile's periodic copies (eq A1:
        the segment translated by -T against the tile), on the device."""
        copies, reach = self.apron_copies(c, p)
        if not copies:
            return blocked
        maxt = io.array(reach)
        for i, j in copies:
            shift = xp.vconst(np.array([i * self.period_m[0], j * self.period_m[1], 0.0]))
            hit = shadow_test([self.sea.mi_scene], origin - shift, d, maxt,
                              variant=self.variant)  # (A1)
            blocked = blocked | xp.Bool(hit)
        return blocked

    def _scale(self, c: np.ndarray) -> float:
        """Largest coordinate magnitude of the ray origins [m] (memoised per read-only
        array: a held surface's centroids are traced at every refresh)."""
        if not c.flags.writeable and self._scale_of is not None and self._scale_of[0] is c:
            return self._scale_of[1]
        value = float(np.max(np.abs(c)))
        if not c.flags.writeable:
            self._scale_of = (c, value)
        return value

    def to_numpy(self, hidden) -> np.ndarray:
        """numpy copy of an occlusion mask from :meth:`occluded` (either form)."""
        if isinstance(hidden, np.ndarray):
            return hidden
        return np.array(drjit_namespace(self.variant).host(hidden), dtype=bool)

    def facets(self, elevation: np.ndarray | None, velocity: np.ndarray | None,
               tx: np.ndarray, rx: np.ndarray | None = None, *, t: float = 0.0,
               update: bool = True, geometry: tuple | None = None) -> Facets:
        """Ray-traced facets of a surface seen from a transmitter and a receiver.

        Parameters
        ----------
        elevation : (ny, nx) array or None
            Surface elevation [m]; None keeps the current one.
        velocity : (ny, nx, 3) array or None
            Surface velocity at the nodes [m/s] (None: zero).
        tx : (3,) array
            Transmitter position [m].
        rx : (3,) array, optional
            Receiver position [m]; None for monostatic.
        t : float
            Time [s]: moving objects are placed at their time-``t`` positions.
        update : bool
            Push ``elevation`` to the sea scene (rebuild its BVH) before tracing.
        geometry : (centroid, area, normal, facet_velocity), optional
            The facets' geometry of ``elevation`` and their velocities, if already known
            (:meth:`seaecho.tracing.engine.FacetEngine.geometry`: computed once per held
            surface); ``velocity`` is then ignored.

        Returns
        -------
        Facets
            ``lit``, ``seen``, ``visibility`` are 0 or 1.
        """
        tx = np.asarray(tx, dtype=np.float64)
        rx = tx if rx is None else np.asarray(rx, dtype=np.float64)
        if elevation is not None and update:
            self.set_surface(elevation)
        self.set_time(t)
        z = self._elevation if elevation is None else np.asarray(elevation, dtype=np.float64)
        if geometry is None:
            centroid, area, normal = facet_geometry(grid_vertices(self.x, self.y, z))
            vel = (np.zeros_like(centroid) if velocity is None
                   else to_facets(np.asarray(velocity, dtype=np.float64)))
        else:
            centroid, area, normal, vel = geometry
        geo = facet_frames_drjit(centroid, normal, tx, rx, variant=self.variant)
        facing_tx = geo["theta_i"] < np.pi / 2
        facing_rx = geo["theta_s"] < np.pi / 2
        lit = facing_tx & ~self.occluded(centroid, normal, tx, mask=facing_tx)
        if np.array_equal(tx, rx):
            seen = lit.copy()
        else:
            seen = facing_rx & ~self.occluded(centroid, normal, rx, mask=facing_rx)
        return Facets(mode="raytraced", time_s=float(t), visibility_time_s=float(t),
                      grid_shape=(self.y.size - 1, self.x.size - 1, 2), centroid=centroid,
                      area=area, normal=normal, velocity=vel, lit=lit.astype(np.float64),
                      seen=seen.astype(np.float64), visibility=(lit & seen).astype(np.float64),
                      **geo)
