"""The land of ``[[land]]``: what it hides and what it echoes, pulse by pulse.

:class:`LandEchoes` holds the land's triangles (``seaecho.geometry.land``, mapped onto a
spherical Earth where the scene has one) in a Mitsuba scene of their own and:

- **hides** points behind it (:meth:`LandEchoes.hidden`): a point is hidden from an
  antenna when the straight segment between them hits a land triangle (a shadow ray,
  :func:`seaecho.tracing.scene.shadow_rays`). The same triangles are occluders of the
  sea's facets (the builder adds them to ``[[objects]]``'s occluders) and of the hulls'
  rays;
- **echoes** (:meth:`LandEchoes.echo`): each triangle f is a scatterer at its centroid
  with RCS

  .. math::

      \\sigma_f = \\gamma \\sqrt{\\sin\\psi_i \\sin\\psi_s}\\, A_f\\, w_f\\, V_f      (L5)

  (eq L2 of :mod:`seaecho.scattering.land` on the triangle's own area A_f at its local
  grazing angles sin psi_i = -n_i . N, sin psi_s = n_s . N), w_f its unit-mean Weibull
  power (eq L4) and V_f = 1 when it is lit and seen: facing both antennas, its segments
  to them hitting no land and clearing the Earth's sphere
  (:meth:`seaecho.geometry.earth.SphericalEarth.visible`), else 0. Its scattering
  amplitude is sqrt(sigma_f) e^(j phi_f) on HH and VV, 0 on HV and VH (the
  cross-polarised land echo is not modelled), w_f and phi_f drawn once per run from the
  ``"land"`` stream (index: the land's entry), so the land is steady from pulse to pulse
  as low-angle land clutter mostly is (Billingsley 2002, chapter 4). The radar equation
  and the accumulation are the radar's (``radar.scatterer_echo``), as for sea facets:
  the mean received power of the land is sum_f P_t G_t G_r lambda^2 <sigma_f> /
  ((4 pi)^3 r_t^2 r_r^2) (eq R2 of :mod:`seaecho.radar.equation`).

The facets are grouped in square patches (:data:`PATCH_CELLS` cells a side) with a
bounding box each, so that a scanning radar's pulse can skip the patches its beams do
not reach, with the sea's bound (docs/scanning.md, eq C3; the simulation decides).

What is left out: the land hides nothing from the sea surface's own shadow rays but
those (the waves in front of the land do not hide its foot), multiple scattering and
the land's diffraction (a knife-edge would let some energy past a crest; here the
shadow is geometric).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..rng import generator
from ..scattering.land import constant_gamma_sigma0, weibull_power
from .sbr import _face_normals
from .scene import ObjectGeometry, ObjectScene, segments_blocked, shadow_rays
from .variant import set_variant

__all__ = ["PATCH_CELLS", "LandEchoes", "LandModel", "LandPiece"]

#: Side of a patch of land facets (a skip unit) [grid cells].
PATCH_CELLS = 8
#: Ray origins are lifted this far along the facet's normal (float32 at km: ~1e-3 m) [m].
_LIFT_M = 0.05


def _cat(arrays: list, shape: tuple = (0,)) -> NDArray:
    """The arrays concatenated, or an empty array of ``shape`` when there are none."""
    return np.concatenate(arrays) if arrays else np.zeros(shape)


@dataclass(frozen=True)
class LandPiece:
    """One ``[[land]]`` entry as plain values.

    Attributes
    ----------
    name : str
    vertices : (V, 3) array
        Vertices in the simulation frame (mapped onto a spherical Earth) [m].
    faces : (F, 3) uint32 array
        Triangles, normals up.
    cell : (F,) int array
        Patch index of each triangle (:data:`PATCH_CELLS`).
    gamma : float
        gamma of eq (L5) at the carrier [-] (linear).
    weibull_shape : float
        a_w [-].
    echo : bool
        Whether the land echoes.
    outline : (N, 2) array or None
        The shore polygon in the scene's coordinates [m] (datasets and figures).
    """

    name: str
    vertices: NDArray[np.float64]
    faces: NDArray[np.uint32]
    cell: NDArray[np.int64]
    gamma: float
    weibull_shape: float
    echo: bool = True
    outline: NDArray[np.float64] | None = None

    def geometry(self) -> ObjectGeometry:
        """The land as a static occluder (:class:`~seaecho.tracing.scene.ObjectGeometry`)."""
        return ObjectGeometry(self.name, self.vertices, self.faces, itu_type=None,
                              relative_permittivity=1.0, conductivity=0.0)


@dataclass(frozen=True)
class LandModel:
    """Every ``[[land]]`` of a scene and the Earth they sit on.

    Attributes
    ----------
    pieces : tuple of LandPiece
    earth : seaecho.geometry.earth.SphericalEarth or None
        The sphere segments must clear (None: flat Earth).
    """

    pieces: tuple
    earth: object = None


class LandEchoes:
    """The land of a scene (module docstring).

    Parameters
    ----------
    model : LandModel
    radar : seaecho.radar.system.RadarSystem
        The scene's radar (platforms, ``scatterer_echo``).
    seed : int
        The run's seed (``"land"`` stream).
    variant : str, optional
        Mitsuba variant.
    """

    def __init__(self, model: LandModel, radar, seed: int, variant: str | None = None
                 ) -> None:
        if not model.pieces:
            raise ValueError("LandEchoes needs at least one piece of land")
        self.model = model
        self.radar = radar
        #: Mitsuba variant of the land's scene (one per process, as the sea tracer's)
        self.variant = set_variant(variant)
        self.earth = model.earth
        self.scene = ObjectScene([p.geometry() for p in model.pieces], variant=self.variant)
        cents, areas, norms, gam, w, phi, patch, boxes = [], [], [], [], [], [], [], []
        for i, p in enumerate(model.pieces):
            if not p.echo:
                continue
            n, a = _face_normals(p.vertices, p.faces)
            cents.append(p.vertices[p.faces].mean(axis=1))
            areas.append(a)
            norms.append(n)
            gam.append(np.full(a.size, p.gamma))
            rng = generator(seed, "land", i)
            w.append(weibull_power(p.weibull_shape, a.size, rng))
            phi.append(rng.uniform(0.0, 2.0 * np.pi, a.size))
            # patches: renumbered after the earlier pieces'
            ids, local = np.unique(p.cell, return_inverse=True)
            patch.append(local + len(boxes))
            for k in range(ids.size):
                v = p.vertices[p.faces[local == k]].reshape(-1, 3)
                lo, hi = v.min(axis=0), v.max(axis=0)
                boxes.append(np.array([[x, y, z] for x in (lo[0], hi[0])
                                       for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]))
        #: centroids (F, 3) [m], areas (F,) [m^2], unit normals (F, 3) of echoing facets
        self.centroid = _cat(cents, (0, 3))
        self.area = _cat(areas)
        self.normal = _cat(norms, (0, 3))
        self.gamma = _cat(gam)
        #: unit-mean Weibull powers w_f (eq L4) and phases phi_f [rad] of the facets
        self.power = _cat(w)
        self.phase = _cat(phi)
        #: patch index of each facet, and the patches' bounding box corners (P, 8, 3) [m]
        self.patch = _cat(patch).astype(np.int64)
        self.patch_boxes = np.array(boxes).reshape(-1, 8, 3)
        order = np.argsort(self.patch, kind="stable")  # facets of patch i: a slice
        self._order = order
        self._starts = np.searchsorted(self.patch[order], np.arange(len(boxes) + 1))
        self._vis: tuple | None = None  # ((tx, rx), visibility)

    @property
    def n_facets(self) -> int:
        """Number of echoing land facets."""
        return int(self.area.size)

    def dataset_variables(self) -> tuple[dict, dict]:
        """The land's description for a run's dataset: outlines, gamma, Weibull shape,
        facet counts (xarray ``(dims, values, attrs)`` tuples and coordinates)."""
        pieces = self.model.pieces
        outline = [np.zeros((0, 2)) if p.outline is None else p.outline for p in pieces]
        which = np.concatenate([np.full(len(o), i, dtype=np.int16)
                                for i, o in enumerate(outline)])
        data = {
            "land_outline": (("land_vertex", "xy"), np.concatenate(outline), {
                "units": "m", "long_name": "shore polygons of the [[land]] in the scene's "
                "coordinates (the vertices of land_outline_land's piece, in order)"}),
            "land_outline_land": (("land_vertex",), which, {
                "long_name": "index along the land dimension of each outline vertex"}),
            "land_gamma": (("land",), 10.0 * np.log10([p.gamma for p in pieces]), {
                "units": "dB", "long_name": "gamma of the constant-gamma law sigma0 = "
                "gamma sin(psi) at the carrier (docs/land.md)"}),
            "land_weibull_shape": (("land",), np.array([p.weibull_shape for p in pieces]),
                                   {"units": "1", "long_name": "Billingsley's a_w"}),
            "land_facets": (("land",), np.array([len(p.faces) for p in pieces]),
                            {"units": "1", "long_name": "triangles of the land's mesh"}),
        }
        return data, {"land": ("land", np.array([p.name for p in pieces]))}

    # ------------------------------------------------------------------ occlusion
    def hidden(self, points: NDArray, position: NDArray) -> NDArray[np.bool_]:
        """Whether the segments from ``position`` (3,) or (N, 3) to ``points`` (N, 3) [m]
        hit the land (True: hidden behind it)."""
        return segments_blocked([self.scene.mi_scene], position, points,
                                variant=self.variant)

    def visibility(self, tx: NDArray, rx: NDArray) -> NDArray[np.float64]:
        """V_f of eq (L5) for every echoing facet: 1 when lit and seen (module docstring);
        memoised on the antennas' positions (a fixed radar traces once)."""
        tx, rx = np.asarray(tx, dtype=np.float64), np.asarray(rx, dtype=np.float64)
        if self._vis is not None and np.array_equal(self._vis[0][0], tx) \
                and np.array_equal(self._vis[0][1], rx):
            return self._vis[1]
        c, n = self.centroid, self.normal
        vis = np.zeros(c.shape[0], dtype=bool)
        facing = (np.einsum("ij,ij->i", tx - c, n) > 0) & (np.einsum("ij,ij->i", rx - c, n) > 0)
        idx = np.flatnonzero(facing)
        if idx.size:
            lifted = c[idx] + _LIFT_M * n[idx]
            ok = ~self._blocked(lifted, tx)
            if not np.array_equal(tx, rx):
                ok &= ~self._blocked(lifted, rx)
            if self.earth is not None:
                ok &= self.earth.visible(tx, c[idx]) & self.earth.visible(rx, c[idx])
            vis[idx] = ok
        out = vis.astype(np.float64)
        out.setflags(write=False)
        self._vis = ((tx.copy(), rx.copy()), out)
        return out

    def _blocked(self, origins: NDArray, position: NDArray) -> NDArray[np.bool_]:
        d = position - origins
        r = np.linalg.norm(d, axis=-1)
        return shadow_rays([self.scene.mi_scene], origins, d / r[:, None], r * (1.0 - 1e-6),
                           variant=self.variant)

    # ------------------------------------------------------------------- the echo
    def rcs(self, tx: NDArray, rx: NDArray, index: NDArray | None = None
            ) -> NDArray[np.float64]:
        """sigma_f of eq (L5) [m^2] of the echoing facets (all, or those of ``index``)
        seen from tx and rx (3,) [m]."""
        sel = slice(None) if index is None else index
        c, n = self.centroid[sel], self.normal[sel]
        n_i = c - tx
        n_i /= np.linalg.norm(n_i, axis=-1, keepdims=True)
        n_s = rx - c
        n_s /= np.linalg.norm(n_s, axis=-1, keepdims=True)
        sin_i = -np.einsum("ij,ij->i", n_i, n)
        sin_s = np.einsum("ij,ij->i", n_s, n)
        # Eq (L5): eq L2 per facet, times area, Weibull power and visibility
        sigma0 = (constant_gamma_sigma0(1.0, sin_i) if np.array_equal(tx, rx)
                  else constant_gamma_sigma0(1.0, sin_i, sin_s)) * self.gamma[sel]
        return sigma0 * self.area[sel] * self.power[sel] * self.visibility(tx, rx)[sel]

    def echo(self, geometry, patches: NDArray[np.bool_] | None = None, *,
             variant: str | None = None):
        """The land's echo at one pulse (a ``ScattererEcho``, or a ``DeviceEcho`` where the
        radar keeps it on its GPU: ``RadarSystem.scatterer_echo``'s ``on_device``), or
        None when no facet of the kept ``patches`` (bool per :attr:`patch_boxes`; default
        all) is lit and seen.

        Parameters
        ----------
        geometry : seaecho.radar.system.PulseGeometry
            ``radar.geometry(pulse)``.
        patches : (P,) bool array, optional
            Patches to compute (the others skipped).
        variant : str, optional
            Mitsuba variant of the radar kernel.
        """
        if self.n_facets == 0:
            return None
        index = None
        if patches is not None:
            keep = np.flatnonzero(np.asarray(patches, dtype=bool))
            if keep.size == 0:
                return None
            if keep.size < len(self.patch_boxes):  # the kept patches' facets, in order
                index = np.sort(np.concatenate([
                    self._order[self._starts[i]:self._starts[i + 1]] for i in keep]))
        tx, rx = geometry.tx.position, geometry.rx.position
        sigma = self.rcs(tx, rx, index)
        lit = np.flatnonzero(sigma > 0)
        if lit.size == 0:
            return None
        facet = lit if index is None else index[lit]
        a = np.sqrt(sigma[lit]) * np.exp(1j * self.phase[facet])
        s = np.zeros((a.size, 2, 2), dtype=np.complex128)
        s[:, 0, 0] = a
        s[:, 1, 1] = a
        pos = self.centroid[facet]
        return self.radar.scatterer_echo(geometry, pos, np.zeros_like(pos), s,
                                         variant=variant, on_device=True)
