"""Hull signatures by shooting and bouncing rays (SBR) with physical optics, on Mitsuba.

:func:`trace_signature` computes the polarimetric echo of a triangle mesh (a hull) seen
from a transmitter T and a receiver R, as scattering centres for the radar kernel
(:mod:`seaecho.targets.centres`). The method is that of Ling, Chou and Lee (1989), with
the physical-optics (PO) integral evaluated at every hit of every ray tube (Weinmann
2006), so that a tube hitting the hull k times contributes the mechanisms of orders
1..k (plate, dihedral, trihedral...):

1. **Launch.** Rays leave T (a point source: the spherical wave, valid in the near field
   of a large ship) through a square grid of spacing ``Delta = lambda / n`` (``n`` rays
   per wavelength, ``rays_per_wavelength``) on the plane through the hull's centre
   normal to the line of sight, over the rectangle that holds the hull's projection.
   Each ray is the axis of a tube of solid angle ``Delta^2 cos(alpha) / l^2``; its
   cross-section at unfolded distance s has edges ``s a~``, ``s b~``.
2. **Bounce.** A Mitsuba ray cast finds the first hit; the facet's normal (float64, from
   the mesh) gives the specular direction and the reflected field (Fresnel of the
   object's material, or the PEC limit for metal; eqs O1-O2 of
   :mod:`seaecho.targets.po`), the tube edges are mirrored, and the ray goes on, up to
   ``max_bounces`` hits.
3. **Radiate.** At every hit the PO currents of the tube's footprint radiate towards the
   receiver (eqs O3-O6): the contribution (eq C1 of :mod:`seaecho.targets.centres`) has
   amplitude ``a = -jk / sqrt(4 pi) A F (e_m . V_n)`` [m], path length
   ``L = s + |R - p|`` and spreading ``s |R - p|`` (a flat facet reflects a point
   source's wave as from its image: the unfolded distance carries the divergence).
4. **Visibility.** The incoming segment of every tube and the exit segment towards the
   receiver are shadow rays against the hull itself, the other ``[[objects]]`` and the
   traced sea surface near the hull (when given); without a traced sea, hull points
   below the mean sea level are under water. An exit is radiated only from the lit side
   of a facet (``s . n > 0``).
5. **Sea multipath** (:mod:`seaecho.targets.multipath`, image method over the mean sea
   plane): a second launch from the transmitter's image T' gives the paths
   T-sea-hull; every hit also radiates towards the receiver's image R' (paths
   hull-sea-R). The sea reflection (Fresnel of sea water times the rough-surface factor
   rho_s, eq M1) multiplies the field at the specular point, in the FSA bases; the legs
   T-sea and sea-R are shadow rays against the hull and the objects. Four path kinds:
   direct, sea-hull, hull-sea, sea-hull-sea (:data:`~seaecho.targets.centres.PATH_NAMES`).
6. **Centres.** Contributions are filed at their delay-equivalent positions and summed
   coherently in cells (eq C2), which the radar kernel takes like sea facets.
7. **Reciprocity** (``SBROptions.reciprocal``, on by default). A linear medium is
   reciprocal (Tsang, Kong and Ding 2000, sec. 1.4 [6]); in the FSA bases, where
   ``h(-n) = -h(n)`` and ``v(-n) = v(n)``, swapping T and R gives::

       S(R -> T) = E S(T -> R)^T E,   E = diag(-1, 1)                (X1)

   (monostatic: ``S_hv = -S_vh``). Steps 1-3 treat the two ends of a path unequally:
   geometrical optics from T up to the last hit, physical optics from there to R. Off
   the specular direction PO radiates with a polarisation that is not that of the
   reverse path (already for one plate, bistatic: HH goes as ``cos theta_i``, VV as
   ``cos theta_s`` [4]), so one-way SBR breaks eq X1. The trace is therefore the mean
   of the traces from T and from R, the latter mapped by eq X1 (its path kinds sea-hull
   and hull-sea exchanged)::

       S = (S_TR + E S_RT^T E) / 2                                   (X2)

   reciprocal by construction. Where one-way SBR is already reciprocal (monostatic
   single bounces, retro-reflecting corners, specular flashes) it changes nothing.
   Monostatic (T = R) the trace from R is the trace from T, so eq X2 costs nothing:
   each contribution is added with its mapped copy, which leaves HH and VV as they were
   and makes ``S_hv = -S_vh = (S_hv - S_vh) / 2``. Bistatic it doubles the trace. The
   mean is the reciprocal estimate, not a more accurate one (a reciprocal approximation
   need not be closer to the truth [5]); it removes the cross-polar artefact of
   off-specular multiple bounces (on the paper's boat at Simulation 2's aspect, a
   deck-deckhouse double bounce radiated by PO far from its specular direction gave
   ``|S_vh|^2`` 33 dB above ``|S_hv|^2``).

The transmitted (received) polarisation components are those of the FSA basis (normal
+z, :func:`seaecho.geometry.frames.polarisation_basis`) of the departure direction
from T (arrival direction at R): HH, HV, VH, VV in the project's convention. In these
bases a single (odd) bounce at normal incidence gives ``S_hh = -S_vv`` and a dihedral
(even) ``S_hh = S_vv``; in the backscatter alignment (BSA) of most RCS texts, ``S_BSA =
diag(-1, 1) S_FSA``, the familiar opposite statement.

Geometry goes to Mitsuba in float32 in a frame centred on the hull (so precision does not
depend on where the hull is in the world); ranges and phases stay float64.

The batches of rays are independent: they are traced on worker threads (numpy and
Mitsuba release the GIL; :data:`THREADS`), and their contributions are added to the
centres in batch order, so that the signature's bytes do not depend on the number of
threads.

Not modelled: edge diffraction (PTD, the ILDC of Michaeli), creeping waves, surface
waves, the curvature of the facets within a tube (faceted meshes), interactions
hull-sea-hull, multiple objects' mutual bounces (each scatterer is traced with the
others as occluders), and the PO field radiated through a body (forward scatter).

References
----------
.. [1] Ling, H., Chou, R.-C. and Lee, S.-W. (1989). Shooting and bouncing rays:
   calculating the RCS of an arbitrarily shaped cavity. *IEEE Trans. Antennas Propag.*
   37(2), 194-205.
.. [2] Weinmann, F. (2006). Ray tracing with PO/PTD for RCS modeling of large complex
   objects. *IEEE Trans. Antennas Propag.* 54(6), 1797-1806.
.. [3] Bhalla, R. and Ling, H. (1995). Image domain ray tube integration formula for the
   shooting and bouncing ray technique. *Radio Science* 30(5), 1435-1446.
.. [4] Balanis, C. A. (2012). *Advanced Engineering Electromagnetics*, 2nd ed., Wiley,
   sec. 11.3 (bistatic PO of a rectangular plate).
.. [5] On the usefulness of reciprocity in approximate scattering analyses (1983).
   *IEEE Trans. Antennas Propag.* 31(6), doi:10.1109/TAP.1983.1143170.
.. [6] Tsang, L., Kong, J. A. and Ding, K.-H. (2000). *Scattering of Electromagnetic
   Waves: Theories and Applications*, Wiley, sec. 1.4 (reciprocity of the scattering
   matrix).
.. [7] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper": its Simulation 2 and 10 m boat).
"""

from __future__ import annotations

import copy
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import aligned
from ..constants import C0, EPS0
from ..geometry.frames import polarisation_basis
from ..scattering.fresnel import fresnel_coefficients
from ..targets.centres import CentreAccumulator, ScatteringCentres, equivalent_positions
from ..targets.multipath import ROUGHNESS_MODELS, mirror, sea_reflection
from ..targets.po import local_basis, po_components, shape_function, tube_footprint
from .variant import drjit_mitsuba, mitsuba_modules

__all__ = [
    "BOUNDING_MARGIN",
    "SBROptions",
    "bounding_sphere",
    "SeaPlane",
    "Signature",
    "TraceMesh",
    "material_permittivity",
    "trace_signature",
]

#: The vertical: normal of the FSA bases.
_Z = np.array([0.0, 0.0, 1.0])
#: Eq X1 entrywise: ``(E A^T E)_mn = SIGN_mn A_nm`` with ``E = diag(-1, 1)``.
_RECIPROCAL_SIGN = np.array([[1.0, -1.0], [-1.0, 1.0]])
#: Path kind of a contribution of the trace from R, seen from T: sea-hull <-> hull-sea.
_REVERSE_PATH = np.array([0, 2, 1, 3], dtype=np.int64)
#: Worker threads of a trace (batches of rays in parallel; the result does not depend
#: on it), opt-in through the environment variable ``SEAECHO_SBR_THREADS``. A scene of the
#: fuzzing suite once aborted the process inside Mitsuba's ray intersection on a worker
#: thread: an intersection of empty arrays (a batch with no ray left), which
#: :func:`_intersect` no longer makes; without that guard the abort is reproduced on a
#: worker thread ("jit_var(r0): unknown variable!", docs/checks.md). One thread stays the
#: default because the memory estimate (``seaecho.checks.resources``) counts one batch of rays
#: in flight, and N threads hold N + 1.
THREADS = max(1, int(os.environ.get("SEAECHO_SBR_THREADS", 1)))


#: An antenna must be farther than this many bounding radii from a hull's centre: the
#: rays are launched from a sphere around the hull (checked again by the preflight,
#: ``seaecho.checks.preflight.hull_problems``).
BOUNDING_MARGIN = 1.05


def bounding_sphere(vertices: NDArray) -> tuple[NDArray[np.float64], float]:
    """(centre, radius) of the sphere the rays are launched from: the centre of the
    vertices' axis-aligned box [m], and the largest distance of a vertex from it [m]."""
    v = np.asarray(vertices, dtype=np.float64)
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre = 0.5 * (lo + hi)
    d = v - centre
    return centre, float(np.sqrt(_dot(d, d)).max())


def _ordered_map(fn: Callable, jobs: Iterable) -> Iterator:
    """``fn(job)`` of every job, in job order, computed on :data:`THREADS` threads (two
    jobs ahead of the consumer at most, so memory holds a few batches)."""
    jobs = list(jobs)
    if THREADS <= 1 or len(jobs) <= 1:
        yield from map(fn, jobs)
        return
    with ThreadPoolExecutor(THREADS, thread_name_prefix="seaecho-sbr") as pool:
        ahead = THREADS + 1
        futures = [pool.submit(fn, j) for j in jobs[:ahead]]
        for i in range(len(jobs)):
            if i + ahead < len(jobs):
                futures.append(pool.submit(fn, jobs[i + ahead]))
            yield futures[i].result()
            futures[i] = None


def material_permittivity(frequency_hz: float, *, itu_type: str | None = None,
                          relative_permittivity: float = 1.0,
                          conductivity: float = 0.0) -> complex | None:
    """Complex relative permittivity of a hull material, or None for a perfect conductor.

    ``eps_r = eps' - j sigma / (omega eps0)`` (time convention exp(+j omega t)), with
    eps' and sigma from ITU-R P.2040 (through Sionna RT's table) for an ITU material.
    ITU "metal" (sigma = 1e7 S/m, ``|R| > 0.9998`` at X band) is taken in the PEC limit
    ``R_h = -1, R_v = +1``.

    Parameters
    ----------
    frequency_hz : float
        [Hz].
    itu_type : str, optional
        ITU-R P.2040 material name.
    relative_permittivity, conductivity : float
        eps' [-] and sigma [S/m] of a custom material (when ``itu_type`` is None).

    References
    ----------
    .. [1] ITU-R P.2040-3 (2023), sec. 2.1.4, table 3.
    """
    if itu_type == "metal":
        return None
    if itu_type is not None:
        from sionna.rt.radio_materials.itu import itu_material

        mitsuba_modules()  # the variant first
        eps, sigma = itu_material(itu_type, float(frequency_hz))
        relative_permittivity = float(np.ravel(eps)[0])
        conductivity = float(np.ravel(sigma)[0])
    omega = 2.0 * np.pi * frequency_hz
    return complex(relative_permittivity, -conductivity / (omega * EPS0))


@dataclass(frozen=True)
class TraceMesh:
    """A triangle mesh in the world frame with one material per face.

    Attributes
    ----------
    vertices : (V, 3) float64 array
        World positions at the time of the trace [m].
    faces : (F, 3) int array
        Vertex indices.
    eps_r : (F,) complex array
        Relative permittivity of each face [-]; NaN for a perfect conductor.
    """

    vertices: NDArray[np.float64]
    faces: NDArray[np.int64]
    eps_r: NDArray[np.complex128]

    @classmethod
    def single(cls, vertices: ArrayLike, faces: ArrayLike,
               eps_r: complex | None = None) -> TraceMesh:
        """A mesh of one material (None: perfect conductor)."""
        f = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
        e = np.full(f.shape[0], np.nan + 0j if eps_r is None else complex(eps_r))
        return cls(np.asarray(vertices, dtype=np.float64).reshape(-1, 3), f, e)

    @classmethod
    def merge(cls, meshes: Sequence[TraceMesh]) -> TraceMesh:
        """One mesh holding several (vertex indices shifted)."""
        offsets = np.cumsum([0] + [m.vertices.shape[0] for m in meshes[:-1]])
        return cls(np.concatenate([m.vertices for m in meshes]),
                   np.concatenate([m.faces + o for m, o in zip(meshes, offsets, strict=True)]),
                   np.concatenate([m.eps_r for m in meshes]))


@dataclass(frozen=True)
class SeaPlane:
    """The sea under a hull, for the trace.

    Attributes
    ----------
    level : float
        Height of the mean sea plane [m] (0 in the project's frame).
    eps_r : complex or None
        Sea-water permittivity [-]; None: no multipath (the sea only hides the hull below
        it).
    sigma_h : float
        Rms height of the sea [m] (rough-surface factor, eq M2).
    roughness : str
        Eq M2 model (:data:`~seaecho.targets.multipath.ROUGHNESS_MODELS`).
    patch : (x (nx,), y (ny,), z (ny, nx)) or None
        Traced sea elevation near the hull [m]: occludes the direct legs (and hides the
        hull below the waves). None: the mean plane hides what is below it.
    """

    level: float = 0.0
    eps_r: complex | None = None
    sigma_h: float = 0.0
    roughness: str = "miller-brown-vegh"
    patch: tuple[NDArray, NDArray, NDArray] | None = None

    def __post_init__(self) -> None:
        if self.roughness not in ROUGHNESS_MODELS:
            raise ValueError(f"roughness = {self.roughness!r}: allowed "
                             f"{', '.join(ROUGHNESS_MODELS)}")
        if not (np.isfinite(self.sigma_h) and self.sigma_h >= 0):
            raise ValueError(f"sigma_h = {self.sigma_h}: must be >= 0 [m]")

    @property
    def multipath(self) -> bool:
        """Whether the sea reflects (image paths are traced)."""
        return self.eps_r is not None


@dataclass(frozen=True)
class SBROptions:
    """Numerical options of the trace.

    Attributes
    ----------
    rays_per_wavelength : float
        Rays per wavelength along each axis of the launch grid [-] (``n^2`` rays per
        lambda^2); the grid spacing is ``lambda / n``.
    max_bounces : int
        Hits followed per ray (1: PO of the lit surface only).
    cell : float
        Side of the cells the contributions are summed in [m] (eq C2).
    batch : int
        Rays traced at once (memory: about 1 kB per ray).
    edge_refine : int
        Launch cells at surface edges are split into ``edge_refine^2`` sub-tubes (1: no
        refinement; :meth:`_Tracer.launch`).
    prune : float
        Fraction of the centres' summed power that the weakest dropped centres may hold
        (0: keep every centre, the sum is then exact at the trace's geometry; a
        fraction p changes the apparent RCS by up to about sqrt(p) times the incoherent
        sum of the centres, which can be large against a coherent null).
    reciprocal : bool
        The reciprocal mean of the traces from T and from R (eq X2 of the module
        docstring; free when monostatic, twice the rays bistatic). False: one-way SBR
        (GO from T, PO towards R), the textbook PO of each path.
    """

    rays_per_wavelength: float = 4.0
    max_bounces: int = 3
    cell: float = 0.1
    batch: int = 1 << 18
    prune: float = 0.0
    edge_refine: int = 4
    reciprocal: bool = True

    def __post_init__(self) -> None:
        if not 0.5 <= self.rays_per_wavelength <= 64:
            raise ValueError(f"rays_per_wavelength = {self.rays_per_wavelength}: allowed "
                             "0.5 .. 64")
        if not (isinstance(self.max_bounces, int) and 1 <= self.max_bounces <= 10):
            raise ValueError(f"max_bounces = {self.max_bounces}: allowed 1 .. 10")
        if not self.cell > 0:
            raise ValueError(f"cell = {self.cell}: must be > 0 [m]")
        if not self.batch >= 1024:
            raise ValueError(f"batch = {self.batch}: must be >= 1024")
        if not 0 <= self.prune < 1:
            raise ValueError(f"prune = {self.prune}: allowed [0, 1)")
        if not (isinstance(self.edge_refine, int) and 1 <= self.edge_refine <= 16):
            raise ValueError(f"edge_refine = {self.edge_refine}: allowed 1 .. 16")
        if not isinstance(self.reciprocal, bool):
            raise ValueError(f"reciprocal = {self.reciprocal!r}: allowed True or False")


@dataclass(frozen=True)
class Signature:
    """A traced hull signature.

    Attributes
    ----------
    centres : ScatteringCentres
        For the radar kernel (world positions at ``centres.time``).
    totals : (4, max_bounces, 2, 2) complex array
        Coherent 2x2 amplitude [m] per path kind and bounce order, referred to
        ``reference`` (eq C3): ``|totals.sum((0, 1))|^2`` is the apparent RCS.
    reference : (3,) array
        Reference point [m].
    tx, rx : (3,) arrays
        Transmitter and receiver of the trace [m].
    ray_spacing : float
        Launch-grid spacing [m].
    n_rays : int
        Rays launched (every source).
    n_hits : int
        Ray-hull hits radiated.
    """

    centres: ScatteringCentres
    totals: NDArray[np.complex128]
    reference: NDArray[np.float64]
    tx: NDArray[np.float64]
    rx: NDArray[np.float64]
    ray_spacing: float
    n_rays: int
    n_hits: int

    @property
    def s(self) -> NDArray[np.complex128]:
        """Total 2x2 amplitude [m] referred to the reference point (all paths)."""
        return self.totals.sum(axis=(0, 1))

    @property
    def rcs(self) -> NDArray[np.float64]:
        """Apparent RCS per channel HH, HV, VH, VV [m^2] (all paths)."""
        s = self.s.reshape(4)
        return s.real**2 + s.imag**2


# ------------------------------------------------------------------------ Mitsuba glue
def _mi_scene(mi, vertices: NDArray, faces: NDArray, keep: list):
    """A Mitsuba scene of one mesh (arrays kept alive in ``keep``: Dr.Jit aliases them)."""
    v32 = aligned(vertices.reshape(-1), np.float32)
    f32 = aligned(np.asarray(faces, dtype=np.uint32).reshape(-1), np.uint32)
    keep += [v32, f32]
    mesh = mi.Mesh("m", vertices.shape[0], faces.shape[0], has_vertex_normals=False)
    params = mi.traverse(mesh)
    params["vertex_positions"] = mi.Float(v32)
    params["faces"] = mi.UInt32(f32)
    params.update()
    return mi.load_dict({"type": "scene", "mesh": mesh})


def _intersect(mi, scene, o: NDArray, d: NDArray) -> tuple[NDArray, NDArray]:
    """Distance [m] (inf on a miss) and triangle index of each ray's first hit (the
    index is meaningless on a miss)."""
    if o.shape[0] == 0:  # Dr.Jit aborts the process on a ray of empty arrays
        return np.zeros(0), np.zeros(0, dtype=np.int64)
    import drjit as dr

    cols = [aligned(o[:, k], np.float32) for k in range(3)]
    cols += [aligned(d[:, k], np.float32) for k in range(3)]
    ray = mi.Ray3f(mi.Point3f(*(mi.Float(c) for c in cols[:3])),
                   mi.Vector3f(*(mi.Float(c) for c in cols[3:])))
    pi = scene.ray_intersect_preliminary(ray)
    dr.eval(pi.t, pi.prim_index)  # one kernel (reading each alone traced the rays twice)
    t = np.array(pi.t.numpy(), dtype=np.float64)
    prim = np.array(pi.prim_index.numpy(), dtype=np.int64)
    del cols
    return t, prim


def _blocked(scenes: list, o: NDArray, target: NDArray, eps: float = 0.0,
             radius: float = np.inf) -> NDArray:
    """Whether the segments from ``o`` to ``target`` hit any of ``scenes``.

    ``radius`` [m] bounds the geometry (a sphere about the local origin): a segment is
    cut where it leaves that sphere, at most ``|o| + radius`` from its origin. (Shadow
    rays of float32 length ~1e6 m self-hit their own facet in Mitsuba, so far
    transmitters and receivers must not make long rays.)
    """
    from .scene import shadow_rays

    if not scenes or o.shape[0] == 0:
        return np.zeros(o.shape[0], dtype=bool)
    d = target - o
    r = np.sqrt(np.einsum("ij,ij->i", d, d))
    d = d / np.maximum(r, 1e-300)[:, None]
    reach = np.sqrt(np.einsum("ij,ij->i", o, o)) + radius
    return shadow_rays(scenes, o, d, np.minimum(np.maximum(r - eps, 0.0), reach))


def _keep(mask: NDArray, *arrays: NDArray) -> tuple[NDArray, ...]:
    """The rows of each array where ``mask`` is True (``np.compress``: the same rows as
    ``a[mask]``, several times faster for (N, 3) and (N, 2, 2) arrays)."""
    return tuple(np.compress(mask, a, axis=0) for a in arrays)


def _rows(a: NDArray, idx: NDArray) -> NDArray:
    """``a[idx]`` (rows by index, ``take``: several times faster for (N, 3) arrays)."""
    return a.take(idx, axis=0)


def _dot(a: NDArray, b: NDArray) -> NDArray:
    """Dot product over the last axis (faster than einsum for (N, 3))."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _face_normals(v: NDArray, f: NDArray) -> tuple[NDArray, NDArray]:
    """Unit normals (right-hand rule) and areas of triangles (float64)."""
    c = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    a = np.sqrt(_dot(c, c))
    return c / np.where(a > 0, a, 1.0)[:, None], 0.5 * a


def _covered(gu: NDArray, gv: NDArray, faces: NDArray, u_lo: float, v_lo: float,
             delta: float, nu: int, nv: int) -> NDArray[np.bool_]:
    """Launch cells (nu, nv) whose ray may hit a triangle: those within the bounding box
    (grown by half a cell) of some projected triangle, marked with a 2-D difference
    array (no loop over triangles)."""
    fu, fv = gu[faces], gv[faces]
    i0 = np.clip(np.floor((fu.min(axis=1) - u_lo) / delta - 0.5), 0, nu - 1).astype(np.int64)
    i1 = np.clip(np.ceil((fu.max(axis=1) - u_lo) / delta - 0.5), 0, nu - 1).astype(np.int64)
    j0 = np.clip(np.floor((fv.min(axis=1) - v_lo) / delta - 0.5), 0, nv - 1).astype(np.int64)
    j1 = np.clip(np.ceil((fv.max(axis=1) - v_lo) / delta - 0.5), 0, nv - 1).astype(np.int64)
    diff = np.zeros((nu + 1, nv + 1), dtype=np.int32)
    np.add.at(diff, (i0, j0), 1)
    np.add.at(diff, (i0, j1 + 1), -1)
    np.add.at(diff, (i1 + 1, j0), -1)
    np.add.at(diff, (i1 + 1, j1 + 1), 1)
    cover = np.cumsum(np.cumsum(diff, axis=0, dtype=np.int32), axis=1, dtype=np.int32)
    return (cover[:nu, :nv] > 0).ravel()


# ---------------------------------------------------------------------------- the trace
class _Tracer:
    """State shared by the launches of one trace (local frame centred on the hull)."""

    def __init__(self, hull: TraceMesh, tx, rx, frequency, options, sea, occluders,
                 reference, variant) -> None:
        self.dr, self.mi = drjit_mitsuba(variant)
        self.k = 2.0 * np.pi * frequency / C0
        self.wavelength = C0 / frequency
        self.opt = options
        self.sea = sea
        v = hull.vertices
        self.centre, self.radius = bounding_sphere(v)
        self.hv = v - self.centre
        normals, area = _face_normals(self.hv, hull.faces)
        good = area > 0
        self.faces = hull.faces[good]
        self.normals = normals[good]
        self.eps = hull.eps_r[good]
        self.keep: list = []
        self.hull_scene = _mi_scene(self.mi, self.hv, self.faces, self.keep)
        # float32 resolution at the hull's size: offsets of ray origins off a facet
        self.eps_off = max(1e-6, 64.0 * np.finfo(np.float32).eps * self.radius)
        self.tx_w = np.asarray(tx, dtype=np.float64)
        self.rx_w = np.asarray(rx, dtype=np.float64)
        self.tx = self.tx_w - self.centre
        self.rx = self.rx_w - self.centre
        for name, p in (("transmitter", self.tx), ("receiver", self.rx)):
            if np.sqrt(_dot(p, p)) < BOUNDING_MARGIN * self.radius:
                raise ValueError(f"the {name} is within the hull's bounding sphere (radius "
                                 f"{self.radius:.1f} m about {self.centre.round(2).tolist()}"
                                 " m): SBR needs it outside")
        self.object_scene = None
        geo_local = []
        if occluders:
            m = TraceMesh.merge(list(occluders))
            geo_local.append(m.vertices - self.centre)
            self.object_scene = _mi_scene(self.mi, geo_local[-1], m.faces, self.keep)
        self.sea_scene = None
        self.patch_box = None
        self.z_sea = None
        if sea is not None:
            self.z_sea = sea.level - self.centre[2]
            if sea.patch is not None:
                from ..geometry.mesh import grid_faces, grid_vertices

                x, y, z = sea.patch
                gv = grid_vertices(np.asarray(x, float) - self.centre[0],
                                   np.asarray(y, float) - self.centre[1],
                                   np.asarray(z, float) - self.centre[2]).reshape(-1, 3)
                geo_local.append(gv)
                self.sea_scene = _mi_scene(self.mi, gv, grid_faces(len(x), len(y)), self.keep)
                self.patch_box = (x[0] - self.centre[0], x[-1] - self.centre[0],
                                  y[0] - self.centre[1], y[-1] - self.centre[1])
                self.patch_local = (np.asarray(x, float) - self.centre[0],
                                    np.asarray(y, float) - self.centre[1],
                                    np.asarray(z, float) - self.centre[2])
                self.patch_top = max(float(self.patch_local[2].max()), self.z_sea)
        # Radius about the hull's centre holding every mesh traced (hull, objects, sea)
        self.geo_radius = max([self.radius] + [float(np.sqrt(_dot(x, x)).max())
                                               for x in geo_local])
        ref = self.centre if reference is None else np.asarray(reference, dtype=np.float64)
        self.reference = ref
        self.acc = CentreAccumulator(self.k, self.tx_w, self.rx_w, ref, options.cell,
                                     4 * options.max_bounces)
        self.n_rays = 0
        self.n_hits = 0
        #: How contributions enter the centres (:meth:`_add`): "one-way", "forward" (the
        #: half of eq X2 traced from T), "reverse" (from R), "monostatic" (both halves)
        self.mode = "one-way"
        if options.reciprocal:
            self.mode = "monostatic" if np.array_equal(self.tx_w, self.rx_w) else "forward"

    def reversed(self) -> _Tracer:
        """The trace from R towards T (eq X2), sharing the scenes and the centres."""
        r = copy.copy(self)
        r.tx, r.rx, r.tx_w, r.rx_w = self.rx, self.tx, self.rx_w, self.tx_w
        r.n_rays = r.n_hits = 0
        r.mode = "reverse"
        return r

    def _add(self, args: tuple) -> None:
        """Add one batch of contributions (:meth:`CentreAccumulator.add`'s arguments) to
        the centres, as eq X2 takes them.

        A contribution of the trace from R (amplitude ``a`` on the FSA bases of its
        departure from R and arrival at T, path kind ``p``) is, seen from T, the
        amplitude ``E a^T E`` of path kind ``_REVERSE_PATH[p]`` at the same position,
        length and spreading (both symmetric in T and R). Monostatic, the trace from R is
        this one: every contribution is added with its mapped copy (one row when the
        path kind is its own reverse).
        """
        if self.mode == "one-way":
            self.acc.add(*args)
            return
        c, amp, length, spreading, path, mech = args
        if self.mode == "forward":
            self.acc.add(c, 0.5 * amp, length, spreading, path, mech)
            return
        amp_t = _RECIPROCAL_SIGN * amp.swapaxes(1, 2)
        path_t = _REVERSE_PATH[path]
        mech_t = mech + (path_t - path) * self.opt.max_bounces
        if self.mode == "reverse":
            self.acc.add(c, 0.5 * amp_t, length, spreading, path_t, mech_t)
            return
        own = path_t == path
        a = 0.5 * amp
        if own.all():  # a batch holds one path kind: one of these two, no row indexing
            a += 0.5 * amp_t
            self.acc.add(c, a, length, spreading, path, mech)
            return
        if not own.any():
            self.acc.add(*(np.concatenate(x) for x in (
                (c, c), (a, 0.5 * amp_t), (length, length), (spreading, spreading),
                (path, path_t), (mech, mech_t))))
            return
        a[own] += 0.5 * amp_t[own]
        other = ~own
        self.acc.add(np.concatenate([c, c[other]]), np.concatenate([a, 0.5 * amp_t[other]]),
                     np.concatenate([length, length[other]]),
                     np.concatenate([spreading, spreading[other]]),
                     np.concatenate([path, path_t[other]]),
                     np.concatenate([mech, mech_t[other]]))

    # ----------------------------------------------------------------- occluder sets
    def _scenes(self, hull: bool, sea: bool) -> list:
        out = [self.hull_scene] if hull else []
        if self.object_scene is not None:
            out.append(self.object_scene)
        if sea and self.sea_scene is not None:
            out.append(self.sea_scene)
        return out

    def _blocked(self, scenes: list, o: NDArray, target: NDArray, eps: float = 0.0
                 ) -> NDArray:
        return _blocked(scenes, o, target, eps, radius=self.geo_radius + 1.0)

    def _under_water(self, p: NDArray) -> NDArray:
        """Hull points below the sea surface: the traced sea's elevation (bilinear) over
        the patch, the mean plane elsewhere. (The shadow rays against the patch decide
        for the points above it; a point below the local surface is wet whatever the ray,
        even when its ray leaves the patch under water.)"""
        if self.z_sea is None:
            return np.zeros(p.shape[0], dtype=bool)
        level = np.full(p.shape[0], self.z_sea)
        if self.patch_box is not None:
            x, y, z = self.patch_local
            # only the points below the patch's crest can be under it (the others keep
            # the mean level, which is below the crest: the same answer, no interpolation)
            inside = ((p[:, 2] < self.patch_top) & (p[:, 0] >= x[0]) & (p[:, 0] <= x[-1])
                      & (p[:, 1] >= y[0]) & (p[:, 1] <= y[-1]))
            if inside.any():
                from scipy.interpolate import RegularGridInterpolator

                interp = RegularGridInterpolator((y, x), z)
                level[inside] = interp(p[inside][:, [1, 0]])
        return p[:, 2] < level - self.eps_off

    # ------------------------------------------------------------------------- launch
    def launch(self, image: bool) -> None:
        """Trace every ray from T (or from its image T' for the sea-first paths).

        Multiresolution at surface edges (Suk et al. 2001): a launch cell whose first or
        second hit is not on the plane of a neighbour's (an edge, a depth step, a miss
        next to a hit, a corner's aperture) is split into ``edge_refine^2`` sub-tubes.
        A tube straddling an edge counts whole or not at all, so the lit region's
        boundary is a staircase of the grid's step; its periodic error radiates
        grating-like lobes away from specular (the level between a hull's flashes),
        which the finer step at edges lowers.
        """
        q = mirror(self.tx, self.z_sea) if image else self.tx
        d0 = float(np.sqrt(_dot(q, q)))
        u0 = -q / d0
        e1, e2 = polarisation_basis(u0)
        # Central projection of the hull on the plane through its centre normal to u0
        w = self.hv - q
        depth = w @ u0
        g = q + w * (d0 / depth)[:, None]
        gu, gv = g @ e1, g @ e2
        delta = self.wavelength / self.opt.rays_per_wavelength
        self.delta = delta
        # Tubes tile the rectangle that holds the projection: centres at (i + 1/2) delta
        nu = max(1, int(np.ceil((gu.max() - gu.min()) / delta - 1e-6)))
        nv = max(1, int(np.ceil((gv.max() - gv.min()) / delta - 1e-6)))
        if nu * nv > 4e8:
            raise ValueError(f"a launch grid of {nu} x {nv} rays ({delta * 1e3:.2f} mm apart) "
                             "is too large: lower rays_per_wavelength")
        u_lo = 0.5 * (gu.max() + gu.min()) - 0.5 * nu * delta
        v_lo = 0.5 * (gv.max() + gv.min()) - 0.5 * nv * delta
        cells = np.flatnonzero(_covered(gu, gv, self.faces, u_lo, v_lo, delta, nu, nv))

        def centres(idx):
            return u_lo + (idx // nv + 0.5) * delta, v_lo + (idx % nv + 0.5) * delta

        m = self.opt.edge_refine
        first = None
        if m > 1:
            plain, edge, first = self._edge_cells(q, e1, e2, cells, centres, delta, nu, nv,
                                                  image)
        else:
            plain, edge = cells, cells[:0]
        self.n_rays += plain.size + edge.size * m * m
        step = self.opt.batch
        jobs = [(plain[a:a + step], 1, None if first is None else
                 tuple(x[a:a + step] for x in first))
                for a in range(0, plain.size, step)]
        # Edge cells: m x m sub-tubes of side delta / m
        per = max(1, self.opt.batch // (m * m))
        jobs += [(edge[a:a + per], m, None) for a in range(0, edge.size, per)]
        sub = (np.arange(m) + 0.5) / m - 0.5
        su, sv = (np.repeat(sub, m) * delta, np.tile(sub, m) * delta)

        def trace(job):
            ui, vj = centres(job[0])
            if job[1] == 1:
                return self._trace(q, u0, e1, e2, ui, vj, delta, image, job[2])
            ui = (ui[:, None] + su).ravel()
            vj = (vj[:, None] + sv).ravel()
            return self._trace(q, u0, e1, e2, ui, vj, delta / m, image)

        for hits, contributions in _ordered_map(trace, jobs):  # added in batch order
            self.n_hits += hits
            for args in contributions:
                self._add(args)

    def _rays(self, q, e1, e2, ui, vj, image: bool):
        """Launch rays through the grid points (ui, vj): directions, distances to the
        grid, origins near the hull and their distance from the source, and the mask of
        the rays kept (those that meet the bounding sphere, above the sea for T')."""
        # coordinates as contiguous rows (x, y, z) until the end (faster than (N, 3))
        dv = np.empty((3, ui.size))
        for k in range(3):
            np.subtract(ui * e1[k] + vj * e2[k], q[k], out=dv[k])
        ell = np.sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2])
        d = dv / ell
        # Entry into the bounding sphere: origin of the Mitsuba ray (near the hull)
        # (the discriminant from the ray's distance to the centre, not b^2 - |q|^2 + r^2,
        # which cancels catastrophically for a far source), with a margin outside
        b = np.ascontiguousarray(d.T) @ q  # (BLAS, as the rows it replaced: the same bits)
        perp = q[:, None] - b * d
        disc = self.radius**2 - (perp[0] * perp[0] + perp[1] * perp[1] + perp[2] * perp[2])
        ok = disc > 0
        tau = -b - np.sqrt(np.maximum(disc, 0.0)) - 1e-3 * self.radius
        if image:
            # The ray from T' crosses the mean sea plane at the specular point S; the
            # trace starts there (the segment T'-S is the image of the real leg T-S)
            ok &= d[2] > 1e-9
            t_s = (self.z_sea - q[2]) / np.where(ok, d[2], 1.0)
            tau = np.maximum(tau, t_s)
        d = np.ascontiguousarray(np.compress(ok, d, axis=1).T)  # (N, 3) C-ordered, as before
        ell, tau = _keep(ok, ell, tau)
        return d, ell, tau, q + tau[:, None] * d, ok

    def _edge_cells(self, q, e1, e2, cells, centres, delta, nu, nv, image):
        """Split the launch cells into plain hit cells and edge cells (see :meth:`launch`).

        A pair of neighbouring cells is an edge when, at the first or at the second hit
        (the specular continuation), one ray hits and the other misses, or the two hits
        are not on one plane (normals 1e-3 rad apart, or a hit 0.01 delta off the
        other's plane): the boundaries of the lit surfaces and of the apertures of
        corners. Cells next to a cell outside the launch mask (a miss) are edges when
        they hit. Plain cells that miss are dropped.
        """
        n_c = cells.size
        # First and second hits of each cell's ray: hit flag, facet normal, point (the
        # coordinates as rows x, y, z: contiguous gathers below)
        hit = np.zeros((2, n_c), dtype=bool)
        nrm = np.zeros((2, 3, n_c), dtype=np.float32)
        pts = np.zeros((2, 3, n_c), dtype=np.float32)
        # First hit of each cell's ray, reused by the trace of the plain cells (Mitsuba's
        # distances are float32: kept exactly)
        first_t = np.full(n_c, np.inf, dtype=np.float32)
        first_prim = np.zeros(n_c, dtype=np.int32)
        # and the launch rays (direction, distance to the grid, origin's distance from the
        # source: :meth:`_rays`), so that the plain cells' trace does not make them again
        ray_d = np.zeros((3, n_c))
        ray_ell = np.zeros(n_c)
        ray_tau = np.zeros(n_c)

        def first_hits(start):
            sl = slice(start, min(start + self.opt.batch, n_c))
            ui, vj = centres(cells[sl])
            d, ell, tau, o, ok = self._rays(q, e1, e2, ui, vj, image)
            rows = np.flatnonzero(ok) + start
            ray_ell[rows], ray_tau[rows] = ell, tau
            for c in range(3):
                ray_d[c, rows] = d[:, c]
            for k in range(min(2, self.opt.max_bounces)):
                t, prim = _intersect(self.mi, self.hull_scene, o, d)
                h = np.isfinite(t)
                rows, o, d, t, prim = _keep(h, rows, o, d, t, prim)
                if k == 0:
                    first_t[rows], first_prim[rows] = t, prim
                ng = _rows(self.normals, prim)
                p = o + t[:, None] * d
                hit[k, rows] = True
                for c in range(3):
                    nrm[k, c, rows], pts[k, c, rows] = ng[:, c], p[:, c]
                if k == 1 or self.opt.max_bounces == 1:
                    break
                # the specular continuation, from the lit side
                n = np.where((_dot(d, ng) > 0)[:, None], -ng, ng)
                d = d - 2.0 * _dot(d, n)[:, None] * n
                o = p + self.eps_off * n

        for _ in _ordered_map(first_hits, range(0, n_c, self.opt.batch)):
            pass  # each batch fills its own rows
        index = np.full(nu * nv, -1, dtype=np.int64)
        index[cells] = np.arange(n_c)
        i, j = np.divmod(cells, nv)
        edge = np.zeros(n_c, dtype=bool)
        tol = 0.01 * delta

        def gather(x, idx):  # rows x, y, z of x (3, n_c) float32 at idx, as float64
            return [x[c].take(idx).astype(np.float64) for c in range(3)]

        def dot3(x, y):  # as _dot, on rows (the same operations, the same bits)
            return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]

        # Each pair of neighbours once (right and up; the test is symmetric in the pair,
        # to the last bit: dp changes sign, the dot products only their sign)
        for di, dj in ((1, 0), (0, 1)):
            ii, jj = i + di, j + dj
            inside = (ii >= 0) & (ii < nu) & (jj >= 0) & (jj < nv)
            nb = np.full(n_c, -1, dtype=np.int64)
            nb[inside] = index.take(ii[inside] * nv + jj[inside])
            has = nb >= 0
            a_all = np.flatnonzero(has)
            b_all = nb.take(a_all)
            has_prev = np.zeros(n_c, dtype=bool)  # the cell on the other side exists
            has_prev[b_all] = True
            for k in range(2):
                # a missing neighbour (off the grid or not covered): an edge if it hits
                edge |= hit[k] & ~(has & has_prev)
                ha, hb = hit[k].take(a_all), hit[k].take(b_all)
                rel = ha != hb
                both = np.flatnonzero(ha & hb)
                if both.size:
                    a, b = a_all.take(both), b_all.take(both)
                    na, nb_n = gather(nrm[k], a), gather(nrm[k], b)
                    dp = [pb - pa for pa, pb in zip(gather(pts[k], a), gather(pts[k], b),
                                                    strict=True)]
                    rel[both] = ((np.abs(dot3(na, nb_n)) < 1.0 - 5e-7)
                                 | (np.abs(dot3(na, dp)) > tol) | (np.abs(dot3(nb_n, dp)) > tol))
                edge[a_all[rel]] = True
                edge[b_all[rel]] = True
        plain = hit[0] & ~edge
        return cells[plain], cells[edge], (*_keep(plain, first_t, first_prim),
                                           np.compress(plain, ray_d, axis=1).T.copy(),
                                           *_keep(plain, ray_ell, ray_tau))

    def _trace(self, q, u0, e1, e2, ui, vj, delta, image: bool, first=None
               ) -> tuple[int, list]:
        """Trace one batch of rays: (hits radiated, the contributions for
        ``CentreAccumulator.add`` in order). ``first``: the rays' first hits (distance,
        triangle) and the rays (:meth:`_rays`, every one kept) when :meth:`_edge_cells`
        traced them already."""
        # First hits (rays that miss the hull cost nothing more)
        if first is not None:
            t, prim = first[0].astype(np.float64), first[1].astype(np.int64)
            d, ell, tau = first[2:]
            o = q + tau[:, None] * d  # as :meth:`_rays` made it (the same bits)
        else:
            d, ell, tau, o, _ = self._rays(q, e1, e2, ui, vj, image)
            t, prim = _intersect(self.mi, self.hull_scene, o, d)
        hit = np.isfinite(t)
        if not hit.all():
            d, ell, tau, o, t, prim = _keep(hit, d, ell, tau, o, t, prim)
        # Tube cross-section per unit distance (normal to d)
        a1, b1 = delta * e1, delta * e2
        ta = (a1 - d * (d @ a1)[:, None]) / ell[:, None]
        tb = (b1 - d * (d @ b1)[:, None]) / ell[:, None]
        # The field of each transmitted polarisation (h, v of the FSA basis of the
        # departure direction) as coefficients on a real basis (p1, p2) normal to d
        p1, p2 = local_basis(d, np.broadcast_to(_Z, d.shape))
        c = np.zeros((d.shape[0], 2, 2), dtype=np.complex128)
        sea_pt = None
        if image:
            sea_pt = q + ((self.z_sea - q[2]) / d[:, 2])[:, None] * d
            # Eq M1 at S: grazing angle asin(d_z), FSA bases of the incident and the
            # reflected (upward) directions
            gh, gv = sea_reflection(np.arcsin(np.clip(d[:, 2], 0.0, 1.0)), self.sea.eps_r,
                                    self.sea.sigma_h, self.k, self.sea.roughness)
            c[:, 0, 0], c[:, 1, 1] = gh, gv
        else:
            c[:, 0, 0], c[:, 1, 1] = 1.0, 1.0
        out: list = []
        return self._bounce(o, d, tau, (p1, p2, c), ta, tb, image, sea_pt, (t, prim),
                            out), out

    # ------------------------------------------------------------------------ bounces
    def _bounce(self, o, d, s0, e, ta, tb, image: bool, sea_pt, first_hit, out: list
                ) -> int:
        """Follow a batch of tubes from their first hit; contributions appended to
        ``out``; returns the number of hits radiated."""
        mi = self.mi
        first = 1 if image else 0
        hits = 0
        for bounce in range(self.opt.max_bounces):
            if d.shape[0] == 0:
                return hits
            if bounce == 0:
                t, prim = first_hit
            else:
                t, prim = _intersect(mi, self.hull_scene, o, d)
                hit = np.isfinite(t)
                if not hit.all():
                    o, d, s0, ta, tb, t, prim = _keep(hit, o, d, s0, ta, tb, t, prim)
                    e = _keep(hit, *e)
            p = o + t[:, None] * d
            s = s0 + t
            ng = _rows(self.normals, prim)
            cosd = _dot(d, ng)
            n = np.where((cosd > 0)[:, None], -ng, ng)
            off = p + self.eps_off * n
            # Visibility of the incoming segment
            if bounce == 0 and image:
                blocked = self._blocked(self._scenes(False, False), off, sea_pt)
                blocked |= self._blocked(self._scenes(True, False),
                                    sea_pt + self.eps_off * np.array([0.0, 0.0, 1.0]),
                                    np.broadcast_to(self.tx, sea_pt.shape))
            elif bounce == 0:
                blocked = self._blocked(self._scenes(False, True), off,
                                   np.broadcast_to(self.tx, p.shape))
            else:
                blocked = self._blocked(self._scenes(False, True), off, o, eps=self.eps_off)
            blocked |= self._under_water(p)
            if blocked.any():
                keep = ~blocked
                o, d, s, ta, tb, p, n, prim, off = _keep(keep, o, d, s, ta, tb, p, n, prim,
                                                         off)
                e = _keep(keep, *e)
            if d.shape[0] == 0:
                return hits
            hits += d.shape[0]
            # Eqs O1-O2 with the facet's material
            eps = self.eps.take(prim)
            pec = np.isnan(eps.real)
            cos_i = -_dot(d, n)
            r_h = np.full(d.shape[0], -1.0 + 0j)
            r_v = np.full(d.shape[0], 1.0 + 0j)
            if not pec.all():
                rh, rv = fresnel_coefficients(cos_i[~pec], eps[~pec])
                r_h[~pec], r_v[~pec] = rh, rv
            # Eqs O1-O2: TE/TM amplitudes of the incident field, reflected direction
            h_l, v_i = local_basis(d, n)
            p1, p2, c = e
            w1, w2 = _dot(p1, h_l)[:, None], _dot(p2, h_l)[:, None]
            alpha = c[:, :, 0] * w1 + c[:, :, 1] * w2
            w1, w2 = _dot(p1, v_i)[:, None], _dot(p2, v_i)[:, None]
            beta = c[:, :, 0] * w1 + c[:, :, 1] * w2
            d_r = d + 2.0 * cos_i[:, None] * n
            v_r = np.cross(h_l, d_r)
            # Eq O5: the footprint of the tube (cross-section at unfolded distance s)
            a_fp, b_fp, area = tube_footprint(s[:, None] * ta, s[:, None] * tb, d, n)
            self._radiate(p, off, d, n, (alpha, beta, r_h, r_v, h_l, v_i, v_r),
                          a_fp, b_fp, area, s, first, bounce, out)
            # Next segment: the reflected field on the basis (h_l, v_r) normal to d_r
            c = np.empty_like(c)
            c[:, :, 0] = r_h[:, None] * alpha
            c[:, :, 1] = r_v[:, None] * beta
            e = (h_l, v_r, c)
            o = off
            d = d_r
            s0 = s
            ta = ta - 2.0 * _dot(ta, n)[:, None] * n
            tb = tb - 2.0 * _dot(tb, n)[:, None] * n
            sea_pt = None
        return hits

    def _radiate(self, p, off, d, n, fields, a_fp, b_fp, area, s, first, bounce, out):
        """PO of the footprints towards R (and R'), eqs O3-O6 and C1: the contributions
        (``CentreAccumulator.add``'s arguments) appended to ``out``."""
        k = self.k
        exits = [(self.rx, 0)]
        if self.sea is not None and self.sea.multipath:
            exits.append((mirror(self.rx, self.z_sea), 1))
        for target, last in exits:
            sv = target - p
            dist = np.sqrt(_dot(sv, sv))
            sh = sv / dist[:, None]
            ok = _dot(sh, n) > 0  # radiate from the lit side only
            if last:
                ok &= sh[:, 2] < -1e-9
            idx = np.flatnonzero(ok)
            if idx.size == 0:
                continue
            ps, offs, shs = _rows(p, idx), _rows(off, idx), _rows(sh, idx)
            if last:
                # Specular point S2 on the mean plane, then the leg S2 -> R
                s2 = ps + ((self.z_sea - ps[:, 2]) / shs[:, 2])[:, None] * shs
                blocked = self._blocked(self._scenes(True, False), offs, s2)
                blocked |= self._blocked(self._scenes(True, False),
                                    s2 + self.eps_off * np.array([0.0, 0.0, 1.0]),
                                    np.broadcast_to(self.rx, s2.shape))
            else:
                blocked = self._blocked(self._scenes(True, True), offs,
                                   np.broadcast_to(self.rx, ps.shape))
            idx = idx[~blocked]
            if idx.size == 0:
                continue
            shs = _rows(sh, idx)
            # Eqs O3-O4 (on the receive basis) and O6
            h_s, v_s = local_basis(shs, np.broadcast_to(_Z, shs.shape))
            alpha, beta, r_h, r_v, h_l, v_i, v_r = (_rows(a, idx) for a in fields)
            comp = np.empty((idx.size, 2, 2), dtype=np.complex128)
            comp[:, 0, :], comp[:, 1, :] = po_components(alpha, beta, r_h, r_v, _rows(n, idx), h_l,
                                                         v_i, v_r, h_s, v_s)
            f = shape_function(k * (shs - _rows(d, idx)), _rows(a_fp, idx), _rows(b_fp, idx))
            if last:
                gh, gv = sea_reflection(np.arcsin(np.clip(-shs[:, 2], 0.0, 1.0)),
                                        self.sea.eps_r, self.sea.sigma_h, k,
                                        self.sea.roughness)
                comp[:, 0, :] *= gh[:, None]
                comp[:, 1, :] *= gv[:, None]
            # Eq C1: a = -jk / sqrt(4 pi) A F (e_m . V_n)
            amp = comp * ((-1j * k / np.sqrt(4.0 * np.pi)) * area.take(idx) * f)[:, None, None]
            s_i, dist_i = s.take(idx), dist.take(idx)
            length = s_i + dist_i
            spreading = s_i * dist_i
            pw = _rows(p, idx) + self.centre
            c, good = equivalent_positions(pw, length, self.tx_w, self.rx_w)
            path = first + 2 * last
            n_good = int(good.sum())
            if not good.all():
                c, amp, length, spreading = _keep(good, c, amp, length, spreading)
            out.append((c, amp, length, spreading,
                        np.full(n_good, path, dtype=np.int64),
                        np.full(n_good, path * self.opt.max_bounces + bounce,
                                dtype=np.int64)))


def trace_signature(hull: TraceMesh, tx: ArrayLike, rx: ArrayLike, frequency_hz: float, *,
                    options: SBROptions | None = None, sea: SeaPlane | None = None,
                    occluders: Sequence[TraceMesh] = (), reference: ArrayLike | None = None,
                    time: float = 0.0, velocity: ArrayLike = (0.0, 0.0, 0.0),
                    variant: str | None = None) -> Signature:
    """The polarimetric echo of a hull as scattering centres (module docstring).

    Parameters
    ----------
    hull : TraceMesh
        The hull at ``time`` (world frame) with its materials.
    tx, rx : (3,) array_like
        Transmitter and receiver positions [m] (equal for monostatic), outside the hull's
        bounding sphere.
    frequency_hz : float
        Carrier frequency [Hz].
    options : SBROptions, optional
        Ray density, bounces, cell size.
    sea : SeaPlane, optional
        The sea under the hull (None: free space).
    occluders : sequence of TraceMesh
        Other objects (world frame) that block rays.
    reference : (3,) array_like, optional
        Point the totals refer to and the cells' anchor (default: the centre of the
        hull's bounding box).
    time : float
        Time of the geometry [s] (stored in the centres).
    velocity : (3,) array_like
        Rigid velocity of the hull [m/s] (stored in the centres).
    variant : str, optional
        Mitsuba variant.

    Returns
    -------
    Signature
    """
    options = SBROptions() if options is None else options
    if not (np.isfinite(frequency_hz) and frequency_hz > 0):
        raise ValueError(f"frequency_hz = {frequency_hz}: must be > 0 [Hz]")
    tr = _Tracer(hull, tx, rx, frequency_hz, options, sea, occluders, reference, variant)
    multipath = sea is not None and sea.multipath
    if multipath and (tr.tx[2] <= tr.z_sea or tr.rx[2] <= tr.z_sea):
        raise ValueError("sea multipath needs the transmitter and the receiver above "
                         "the mean sea level")
    # Eq X2: bistatic, the trace from R too (into the same centres, after the trace from T)
    tracers = [tr] + ([tr.reversed()] if tr.mode == "forward" else [])
    for t in tracers:
        t.launch(image=False)
        if multipath:
            t.launch(image=True)
    centres = tr.acc.centres(time, velocity, prune=options.prune)
    totals = tr.acc.totals.reshape(4, options.max_bounces, 2, 2)
    return Signature(centres, totals, tr.reference, tr.tx_w, tr.rx_w, tr.delta,
                     sum(t.n_rays for t in tracers), sum(t.n_hits for t in tracers))


# ------------------------------------------------------------------------ the cache
def signature_key(hull: TraceMesh, tx: ArrayLike, rx: ArrayLike, frequency_hz: float, *,
                  options: SBROptions | None = None, sea: SeaPlane | None = None,
                  occluders: Sequence[TraceMesh] = (), reference: ArrayLike | None = None,
                  time: float = 0.0, velocity: ArrayLike = (0.0, 0.0, 0.0),
                  variant: str | None = None) -> str:
    """The cache key of :func:`trace_signature` with these arguments (same parameters).

    A hash (:func:`seaecho.targets.cache.digest`) of every argument, arrays by their
    bytes, and of the code: every input the trace's result depends on, so that two
    calls with one key give the same bytes.
    """
    from ..backend import DEFAULT_VARIANT
    from ..targets.cache import digest

    options = SBROptions() if options is None else options

    def mesh(name: str, m: TraceMesh) -> list:
        return [(f"{name}.vertices", np.asarray(m.vertices, np.float64)),
                (f"{name}.faces", np.asarray(m.faces, np.int64)),
                (f"{name}.eps_r", np.asarray(m.eps_r, np.complex128))]

    items = [("kind", "sbr-signature"), *mesh("hull", hull),
             ("tx", np.asarray(tx, np.float64)), ("rx", np.asarray(rx, np.float64)),
             ("frequency", float(frequency_hz))]
    items += [(f"options.{f}", getattr(options, f))
              for f in SBROptions.__dataclass_fields__]
    if sea is None:
        items.append(("sea", None))
    else:
        items += [("sea.level", float(sea.level)),
                  ("sea.eps_r", None if sea.eps_r is None else complex(sea.eps_r)),
                  ("sea.sigma_h", float(sea.sigma_h)), ("sea.roughness", sea.roughness),
                  ("sea.patch", None if sea.patch is None else
                   [np.asarray(a, np.float64) for a in sea.patch])]
    items.append(("occluders", len(occluders)))
    for i, m in enumerate(occluders):
        items += mesh(f"occluder{i}", m)
    items += [("reference", None if reference is None else np.asarray(reference, np.float64)),
              ("time", float(time)), ("velocity", np.asarray(velocity, np.float64)),
              ("variant", DEFAULT_VARIANT if variant is None else variant)]
    return digest(items)


def signature_arrays(sig: Signature) -> dict[str, NDArray]:
    """A signature as named arrays (for :class:`seaecho.targets.cache.ArrayCache`)."""
    c = sig.centres
    return {"position": c.position, "s": c.s, "path": c.path, "time": np.float64(c.time),
            "velocity": c.velocity, "totals": sig.totals, "reference": sig.reference,
            "tx": sig.tx, "rx": sig.rx, "ray_spacing": np.float64(sig.ray_spacing),
            "n_rays": np.int64(sig.n_rays), "n_hits": np.int64(sig.n_hits)}


def signature_from_arrays(a: dict[str, NDArray]) -> Signature:
    """The inverse of :func:`signature_arrays` (the same bytes)."""
    from ..targets.centres import ScatteringCentres

    centres = ScatteringCentres(a["position"], a["s"], a["path"], float(a["time"]),
                                a["velocity"])
    return Signature(centres, a["totals"], a["reference"], a["tx"], a["rx"],
                     float(a["ray_spacing"]), int(a["n_rays"]), int(a["n_hits"]))
