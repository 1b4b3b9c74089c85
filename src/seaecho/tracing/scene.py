"""The sea and the objects as Sionna RT / Mitsuba scenes, and shadow rays against them.

Design (measured, ``docs/tracing.md``): updating a mesh's vertices rebuilds the BVH of
the whole Mitsuba scene that holds it (0.15-0.18 s at 512 x 512 on 2 CPU cores). The sea
therefore lives alone in its own Mitsuba scene (:class:`SeaScene`); the ``[[objects]]``
live in two more (:class:`ObjectScene`): one for static objects (built once) and one for
moving objects (rebuilt when they move: a few thousand triangles, milliseconds). A shadow
ray is blocked if it hits any of them (:func:`shadow_rays`).

Mitsuba works in float32; geometry sent to it is cast at this boundary and every range,
direction and angle we return is computed in float64 on our side. The scenes are plain
Mitsuba scenes (the shadow rays need no radio material): Sionna RT is imported only to
read an XML scene file.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..backend import aligned
from ..geometry.mesh import grid_faces, grid_vertices
from .variant import active_variant, drjit_mitsuba, mitsuba_modules

__all__ = [
    "ObjectGeometry",
    "ObjectScene",
    "SeaScene",
    "load_mesh_file",
    "load_object",
    "rotation_matrix",
    "segments_blocked",
    "shadow_rays",
    "shadow_test",
]

def rotation_matrix(yaw: float, pitch: float, roll: float) -> np.ndarray:
    """Rotation ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (Sionna RT's orientation convention).

    Parameters
    ----------
    yaw, pitch, roll : float
        Angles about z, y and x [rad].

    Returns
    -------
    (3, 3) array
        ``world = R @ local``.

    References
    ----------
    3GPP TR 38.901 eq. (7.1-4); ``sionna.rt.utils.rotation_matrix``.
    """
    sa, ca = np.sin(yaw), np.cos(yaw)
    sb, cb = np.sin(pitch), np.cos(pitch)
    sc, cc = np.sin(roll), np.cos(roll)
    return np.array([
        [ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc],
        [sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc],
        [-sb, cb * sc, cb * cc],
    ])


@dataclass
class ObjectGeometry:
    """A rigid triangle mesh with a pose and a radio material.

    Attributes
    ----------
    name : str
        Unique name (the Mitsuba shape id).
    vertices : (V, 3) array
        Vertices in the object's own frame, scale applied [m].
    faces : (F, 3) uint32 array
        Vertex indices.
    position : (3,) array
        Position of the object's origin at time 0 [m].
    rotation : (3, 3) array
        Orientation, ``world = rotation @ local + position`` .
    velocity : (3,) array
        Constant velocity [m/s].
    relative_permittivity, conductivity : float
        Material eps' [-] and sigma [S/m] (as Sionna's ``RadioMaterial``; the hull
        traces read them, the shadow rays do not).
    itu_type : str or None
        ITU-R P.2040 material name when the material is an ITU one.
    """

    name: str
    vertices: np.ndarray
    faces: np.ndarray
    position: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rotation: np.ndarray = field(default_factory=lambda: np.eye(3))
    velocity: np.ndarray = field(default_factory=lambda: np.zeros(3))
    relative_permittivity: float = 1.0
    conductivity: float = 1.0e7
    itu_type: str | None = "metal"

    @property
    def moving(self) -> bool:
        """Whether the object moves."""
        return bool(np.any(self.velocity != 0.0))

    def world_vertices(self, t: float = 0.0) -> np.ndarray:
        """Vertex positions in the world frame at time ``t`` [s] (float64) [m]."""
        return self.vertices @ self.rotation.T + (self.position + self.velocity * t)


def _mesh_file(path: str) -> tuple[np.ndarray, np.ndarray]:
    import trimesh

    try:
        mesh = trimesh.load(path, force="mesh", process=False)
    except Exception as exc:  # noqa: BLE001 - trimesh raises many types
        raise ValueError(f"{path}: cannot read mesh ({exc})") from None
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if faces.size == 0:
        raise ValueError(f"{path}: mesh has no triangles")
    return vertices, faces.astype(np.uint32)


def load_mesh_file(path: str, what: str = "mesh") -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) [m] and faces (F, 3) uint32 of a mesh file (.ply, .obj, .stl);
    ``what`` names the scene field in the error of a missing file."""
    if not os.path.isfile(path):
        raise ValueError(f"{what}: file {path!r} not found")
    return _mesh_file(path)


def _xml_shapes(path: str, variant: str | None = None
                ) -> list[tuple[str, np.ndarray, np.ndarray, float, float]]:
    """(name, vertices, faces, eps', sigma) of each shape of a Mitsuba/Sionna XML scene."""
    dr, mi, rt = mitsuba_modules(variant)
    try:
        scene = rt.load_scene(path, merge_shapes=False)
    except Exception as exc:  # noqa: BLE001 - Mitsuba raises RuntimeError with a message
        raise ValueError(f"{path}: cannot load XML scene ({exc})") from None
    out = []
    for name, obj in scene.objects.items():
        params = mi.traverse(obj.mi_mesh)
        v = np.array(params["vertex_positions"].numpy(), dtype=np.float64).reshape(-1, 3)
        f = np.array(params["faces"].numpy(), dtype=np.uint32).reshape(-1, 3)
        mat = obj.radio_material
        eps = float(np.ravel(getattr(mat, "relative_permittivity", 1.0))[0])
        sigma = float(np.ravel(getattr(mat, "conductivity", 0.0))[0])
        out.append((name, v, f, eps, sigma))
    if not out:
        raise ValueError(f"{path}: XML scene has no shapes")
    return out


def load_object(cfg, base_dir: str = ".", ship=None, variant: str | None = None
                ) -> list[ObjectGeometry]:
    """Geometry of one ``[[objects]]`` entry (several for an XML scene of several shapes).

    Parameters
    ----------
    cfg : seaecho.config.tracing.ObjectConfig
        The entry.
    base_dir : str
        Folder that relative paths refer to (the scene file's).
    ship : seaecho.config.ShipConfig, optional
        Needed when ``cfg.follow_ship``.
    variant : str, optional
        Mitsuba variant of the run (an XML scene is loaded with Mitsuba): pass the
        scene's ``[tracing] variant``, which must be the one the tracer uses.

    Returns
    -------
    list of ObjectGeometry
    """
    path = cfg.file if os.path.isabs(cfg.file) else os.path.join(base_dir, cfg.file)
    if not os.path.isfile(path):
        raise ValueError(f"[[objects]] {cfg.name}: file {path!r} not found")
    yaw, pitch, roll = np.deg2rad(cfg.orientation_deg)
    position = np.array(cfg.position_m, dtype=np.float64)
    velocity = np.array(cfg.velocity_m_s, dtype=np.float64)
    if cfg.follow_ship:
        if ship is None:
            raise ValueError(f"[[objects]] {cfg.name}: follow_ship = true needs a [ship]")
        heading = np.deg2rad(ship.heading_deg)
        yaw = yaw + heading
        position[:2] += np.asarray(ship.position_m, dtype=np.float64)
        velocity = velocity + ship.speed * np.array([np.cos(heading), np.sin(heading), 0.0])
    rot = rotation_matrix(yaw, pitch, roll)
    if cfg.relative_permittivity is not None:
        material = dict(relative_permittivity=cfg.relative_permittivity,
                        conductivity=cfg.conductivity_s_m or 0.0, itu_type=None)
    else:
        material = dict(relative_permittivity=1.0, conductivity=1.0e7,
                        itu_type=cfg.material or "metal")
    if path.lower().endswith(".xml"):
        shapes = _xml_shapes(path, variant)
        keep_file_material = cfg.material is None and cfg.relative_permittivity is None
        out = []
        for name, v, f, eps, sigma in shapes:
            mat = (dict(relative_permittivity=eps, conductivity=sigma, itu_type=None)
                   if keep_file_material else material)
            out.append(ObjectGeometry(f"{cfg.name}-{name}", v * cfg.scale, f, position, rot,
                                      velocity, **mat))
        return out
    v, f = _mesh_file(path)
    return [ObjectGeometry(cfg.name, v * cfg.scale, f, position, rot, velocity, **material)]


def _mi_mesh(mi, name: str, vertices32: np.ndarray, faces: np.ndarray, keep: list):
    """A Mitsuba mesh from numpy arrays.

    Dr.Jit aliases numpy memory (``mi.Float(array)`` is zero-copy) and the LLVM backend
    runs kernels asynchronously, so every array handed to Mitsuba is appended to ``keep``,
    which the caller holds for the mesh's lifetime.
    """
    faces = np.ascontiguousarray(faces, dtype=np.uint32)
    keep += [vertices32, faces]
    mesh = mi.Mesh(name, vertices32.shape[0], faces.shape[0], has_vertex_normals=False)
    params = mi.traverse(mesh)
    params["vertex_positions"] = mi.Float(vertices32.ravel())
    params["faces"] = mi.UInt32(faces.ravel())
    params.update()
    return mesh


def _mi_scene(mi, shapes: dict):
    """A Mitsuba scene of the given shapes ``{id: mitsuba.Mesh}`` (ray queries only)."""
    return mi.load_dict({"type": "scene", **shapes})


class SeaScene:
    """The sea surface as a Mitsuba scene of one mesh, for the shadow rays.

    Parameters
    ----------
    x : (nx,) array
        Node abscissae [m].
    y : (ny,) array
        Node ordinates [m].
    elevation : (ny, nx) array
        Initial surface elevation [m].
    eps_r : complex, optional
        Sea-water relative permittivity ``eps' - j eps''`` [-] (from
        :func:`seaecho.ocean.seawater.sea_water_permittivity`); default 60 - 35j (10 GHz,
        20 degC, 35 psu, approximately). Kept as :attr:`eps_r` for a radio material;
        the shadow rays do not use it.
    frequency_hz : float
        Carrier frequency [Hz] (:attr:`frequency_hz`).
    variant : str, optional
        Mitsuba variant (:func:`seaecho.tracing.variant.set_variant`).

    Notes
    -----
    :meth:`update` writes new vertex positions; the BVH is rebuilt when :attr:`mi_scene`
    is next asked for (the grid walk of :mod:`seaecho.tracing.heightfield` needs only
    :attr:`vertices`).
    """

    def __init__(self, x: np.ndarray, y: np.ndarray, elevation: np.ndarray, *,
                 eps_r: complex | None = None, frequency_hz: float = 10.0e9,
                 variant: str | None = None) -> None:
        dr, mi = drjit_mitsuba(variant)
        self._mi = mi
        self.x = np.asarray(x, dtype=np.float64)
        self.y = np.asarray(y, dtype=np.float64)
        self.eps_r = complex(60.0 - 35.0j) if eps_r is None else complex(eps_r)
        self.frequency_hz = float(frequency_hz)
        self._vbuf = grid_vertices(self.x, self.y, elevation, dtype=np.float32)
        self._keep: list = []
        mesh = _mi_mesh(mi, "sea", self._vbuf, grid_faces(self.x.size, self.y.size), self._keep)
        self._scene = _mi_scene(mi, {"sea": mesh})
        self._params = mi.traverse(self._scene)
        self._key = "sea.vertex_positions"
        self._mesh_buf = self._vbuf  # the buffer the Mitsuba mesh aliases
        self._stale = False  # vertices written, BVH not rebuilt yet

    @property
    def mi_scene(self):
        """The Mitsuba scene (for ray queries), its BVH rebuilt first if the vertices
        changed since."""
        if self._stale:
            self._params[self._key] = self._mi.Float(self._vbuf.ravel())
            self._params.update()
            self._mesh_buf = self._vbuf
            self._stale = False
        return self._scene

    @property
    def vertices(self) -> np.ndarray:
        """The mesh's vertices (ny, nx, 3), float32, as the scene holds them [m] (not
        to be written)."""
        return self._vbuf

    def update(self, elevation: np.ndarray) -> None:
        """Move the sea's vertices to a new elevation [m]; the BVH is rebuilt on the next
        use of :attr:`mi_scene`."""
        z = np.asarray(elevation)
        if z.shape != self._vbuf.shape[:2]:
            raise ValueError(f"elevation shaped {z.shape}, expected {self._vbuf.shape[:2]}")
        # A fresh buffer each time: Dr.Jit may alias numpy memory, so the previous one must
        # not be overwritten while Mitsuba can still read it.
        buf = np.empty_like(self._vbuf)
        buf[..., :2] = self._vbuf[..., :2]
        buf[..., 2] = z
        self._vbuf = buf  # (the mesh still aliases _mesh_buf until it is updated)
        self._stale = True

    def move(self, x: np.ndarray, y: np.ndarray, elevation: np.ndarray) -> None:
        """Put the mesh on another grid of the same shape: node abscissae ``x`` (nx,),
        ordinates ``y`` (ny,) [m] and ``elevation`` (ny, nx) [m]; the BVH is rebuilt (the
        same scene as one built on that grid, without building a new one)."""
        x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
        buf = grid_vertices(x, y, elevation, dtype=np.float32)
        if buf.shape != self._vbuf.shape:
            raise ValueError(f"grid shaped {buf.shape[:2]}, expected {self._vbuf.shape[:2]}")
        self.x, self.y = x, y
        self._params[self._key] = self._mi.Float(buf.ravel())
        self._params.update()
        self._vbuf = buf


class ObjectScene:
    """Objects (``[[objects]]``) in a Mitsuba scene of their own (for the shadow rays).

    Parameters
    ----------
    objects : sequence of ObjectGeometry
        The objects (non-empty).
    t : float
        Time of the initial pose [s].
    variant : str, optional
        Mitsuba variant.
    """

    def __init__(self, objects: Sequence[ObjectGeometry], t: float = 0.0,
                 variant: str | None = None) -> None:
        if not objects:
            raise ValueError("ObjectScene needs at least one object")
        names = [o.name for o in objects]
        if len(set(names)) != len(names):
            raise ValueError(f"object names must be unique, got {names}")
        dr, mi = drjit_mitsuba(variant)
        self._mi = mi
        self.objects = list(objects)
        self._bufs = {}
        self._keep: list = []  # arrays aliased by Dr.Jit (faces, initial vertices)
        shapes = {}
        for o in self.objects:
            buf = np.ascontiguousarray(o.world_vertices(t), dtype=np.float32)
            self._bufs[o.name] = buf
            shapes[o.name] = _mi_mesh(mi, o.name, buf, o.faces, self._keep)
        self._scene = _mi_scene(mi, shapes)
        self._params = mi.traverse(self._scene)
        self.t = float(t)

    @property
    def mi_scene(self):
        """The Mitsuba scene (for ray queries)."""
        return self._scene

    @property
    def moving(self) -> bool:
        """Whether any object of this scene moves."""
        return any(o.moving for o in self.objects)

    def move_to(self, t: float) -> None:
        """Place the moving objects at their time-``t`` positions [s]; one BVH rebuild."""
        if t == self.t or not self.moving:
            self.t = float(t)
            return
        for o in self.objects:
            if o.moving:
                buf = np.ascontiguousarray(o.world_vertices(t), dtype=np.float32)
                self._params[f"{o.name}.vertex_positions"] = self._mi.Float(buf.ravel())
                self._bufs[o.name] = buf  # keep alive (aliased by Dr.Jit)
        self._params.update()
        self.t = float(t)


def shadow_rays(mi_scenes: Sequence, origins: np.ndarray, directions: np.ndarray,
                maxt: np.ndarray, *, variant: str | None = None) -> np.ndarray:
    """Whether each ray segment is blocked by any of the scenes.

    Parameters
    ----------
    mi_scenes : sequence of mitsuba.Scene
        Scenes to test against.
    origins : (N, 3) array
        Ray origins [m] (cast to float32).
    directions : (N, 3) array
        Unit directions [-].
    maxt : (N,) array
        Segment lengths [m].
    variant : str, optional
        Mitsuba variant the scenes were built with; by default the one Mitsuba runs
        (never the default variant while another one runs: that would be an error).

    Returns
    -------
    (N,) bool array
        True where the segment hits something.
    """
    _, mi = drjit_mitsuba(active_variant() if variant is None else variant)
    n = origins.shape[0]
    hit = np.zeros(n, dtype=bool)
    if n == 0 or not mi_scenes:
        return hit
    # Contiguous float32 copies that stay referenced until the results are read back.
    # 64-byte aligned (seaecho.backend.aligned): one compiled ray-test kernel per scene
    o = [aligned(origins[:, k], np.float32) for k in range(3)]
    d = [aligned(directions[:, k], np.float32) for k in range(3)]
    t = aligned(maxt, np.float32)
    blocked = shadow_test(mi_scenes, [mi.Float(a) for a in o], [mi.Float(a) for a in d],
                          mi.Float(t), variant=variant)
    hit[:] = np.asarray(blocked.numpy(), dtype=bool)
    return hit


def segments_blocked(mi_scenes: Sequence, start: np.ndarray, end: np.ndarray, *,
                     variant: str | None = None) -> np.ndarray:
    """Whether the straight segments from ``start`` to ``end`` (N, 3) [m] (either may be
    (3,), broadcast) hit any of the scenes: the line of sight between two points, e.g. an
    antenna and a target behind a wave crest or a headland (:func:`shadow_rays`; a
    segment of zero length is not blocked)."""
    start, end = np.broadcast_arrays(np.asarray(start, dtype=np.float64).reshape(-1, 3),
                                     np.asarray(end, dtype=np.float64).reshape(-1, 3))
    d = end - start
    r = np.linalg.norm(d, axis=-1)
    out = np.zeros(r.size, dtype=bool)
    ok = r > 0
    if ok.any() and mi_scenes:
        out[ok] = shadow_rays(mi_scenes, np.ascontiguousarray(start[ok]), d[ok] / r[ok, None],
                              r[ok] * (1.0 - 1e-6), variant=variant)
    return out


def shadow_test(mi_scenes: Sequence, origins: Sequence, directions: Sequence, maxt: Any, *,
                variant: str | None = None) -> Any:
    """Whether each ray segment is blocked by any of the scenes, on the device.

    Parameters
    ----------
    mi_scenes : sequence of mitsuba.Scene
        Scenes to test against (non-empty).
    origins, directions : three Dr.Jit arrays each
        Ray origins [m] and unit directions [-] of the variant's back end (float64 or
        float32: converted to Mitsuba's float32 without leaving the device).
    maxt : Dr.Jit array
        Segment lengths [m].
    variant : str, optional
        As :func:`shadow_rays`.

    Returns
    -------
    mitsuba.Bool
        True where the segment hits something (the scenes' hit masks combined by Dr.Jit,
        not read back).
    """
    dr, mi = drjit_mitsuba(active_variant() if variant is None else variant)
    ray = mi.Ray3f(mi.Point3f(*(mi.Float(a) for a in origins)),
                   mi.Vector3f(*(mi.Float(a) for a in directions)))
    ray.maxt = mi.Float(maxt)
    # OptiX (CUDA variants) binds one shader table per kernel: with several scenes the
    # rays are evaluated first and each scene's test is a kernel of its own.
    split = len(mi_scenes) > 1 and mi.variant().startswith("cuda")
    if split:
        dr.eval(ray)
    blocked = None
    for sc in mi_scenes:  # combined on the device
        t = sc.ray_test(ray)
        if split:
            dr.eval(t)
        blocked = t if blocked is None else blocked | t
    return blocked
