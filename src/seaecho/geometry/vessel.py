"""A generic ship mesh for hull echoes, scaled to a ship's length, beam and draft.

The ship is a generic small freighter / offshore vessel, made of simple closed bodies so
that it holds the mechanisms that dominate a ship's radar signature (docs/ship.md): long
wall-sided hull flanks (specular flashes broadside), a transom (flat stern plate), a
raked bow, deck-superstructure and superstructure-superstructure corners (dihedrals),
tiered deckhouses with a bridge and bridge wings, a funnel, hatch covers, a crane and a
mast with a yardarm (corners of small plates: trihedrals). It is not a model of any real
ship. Frame: x forward (bow at +L/2), y to port, z up, waterline z = 0, centred on the
origin in x and y (the convention of :mod:`seaecho.geometry.hull`).

The reference body (:func:`vessel`): length overall 80 m, beam 13 m, draft 4.5 m,
freeboard 4.5 m amidships rising to 7 m at the bow (sheer), deckhouse aft with three
tiers up to 13.6 m above the waterline, mast top 21 m. :func:`vessel_mesh` scales it to
other dimensions: x by L / 80, y by B / 13, z by T / 4.5 below the waterline and by
L / 80 above it (the superstructure grows with the length). ``scenes/meshes/vessel_80m.ply``
is ``vessel()`` written by ``python tools/make_vessel_mesh.py``.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .hull import lofted_hull

__all__ = ["vessel", "vessel_mesh"]

LENGTH, BEAM, DRAFT = 80.0, 13.0, 4.5


def _hull(n_stations: int = 41):
    """Closed hull body from cross-sections (wall sides, bilge, flat bottom, V bow)."""

    xs = np.linspace(-LENGTH / 2, LENGTH / 2, n_stations)
    u = (xs + LENGTH / 2) / LENGTH  # 0 at the transom, 1 at the stem
    # Half-breadth: parallel middle body, fine entry forward, slight run aft
    half = 0.5 * BEAM * np.where(
        u > 0.7, np.sqrt(np.clip(1 - ((u - 0.7) / 0.3) ** 2, 0.0, 1.0)),
        np.where(u < 0.12, 0.85 + 0.15 * u / 0.12, 1.0))
    half = np.maximum(half, 0.15)
    # Keel: flat, rising at the stem (raked bow) and a little at the transom
    depth = DRAFT * np.where(u > 0.85, 1.0 - 0.8 * ((u - 0.85) / 0.15) ** 2,
                             np.where(u < 0.05, 0.6 + 0.4 * u / 0.05, 1.0))
    # Deck at the side: sheer forward
    deck = 4.5 + 2.5 * np.clip((u - 0.6) / 0.4, 0.0, 1.0) ** 2
    # Section polygon (port deck edge, side, bilge, keel, mirrored): fractions of the
    # half-breadth (y) and of the depth (z < 0) or the deck height (z > 0)
    prof_y = np.array([1.0, 1.0, 1.0, 0.93, 0.75, 0.0, -0.75, -0.93, -1.0, -1.0, -1.0])
    prof_z = np.array([1.0, 0.0, -0.75, -0.95, -1.0, -1.0, -1.0, -0.95, -0.75, 0.0, 1.0])
    m = prof_y.size
    verts = []
    for b, d, top in zip(half, depth, deck, strict=True):
        for py, pz in zip(prof_y, prof_z, strict=True):
            verts.append((py * b, pz * (top if pz > 0 else d)))
    verts = np.array([(x, y, z) for x, sec in zip(xs, np.array(verts).reshape(-1, m, 2),
                                                   strict=True) for y, z in sec])
    return lofted_hull(verts, n_stations, m)


def _box(extents, centre):
    import trimesh

    b = trimesh.creation.box(extents=extents)
    b.apply_translation(centre)
    return b


def vessel():
    """The 80 m ship as a ``trimesh.Trimesh``: hull plus superstructure (closed bodies,
    outward normals)."""
    import trimesh

    deck = 4.5
    parts = [_hull()]
    # Deckhouse aft, three tiers, the bridge with wings on top
    parts.append(_box((14.0, 11.0, 3.0), (-27.0, 0.0, deck + 1.5)))
    parts.append(_box((11.0, 10.0, 2.8), (-27.5, 0.0, deck + 3.0 + 1.4)))
    parts.append(_box((6.0, 15.0, 2.8), (-25.0, 0.0, deck + 5.8 + 1.4)))  # bridge + wings
    # Funnel behind the bridge and a mast on the bridge roof with a yardarm
    parts.append(_box((3.0, 2.6, 6.0), (-31.0, 0.0, deck + 5.8 + 3.0)))
    parts.append(_box((0.4, 0.4, 8.0), (-25.0, 0.0, deck + 8.6 + 4.0)))
    parts.append(_box((0.25, 6.0, 0.25), (-25.0, 0.0, deck + 8.6 + 6.5)))
    # Two hatch covers and a crane between them, a forecastle bulwark at the bow
    parts.append(_box((14.0, 9.0, 1.2), (-6.0, 0.0, deck + 0.6)))
    parts.append(_box((14.0, 9.0, 1.2), (12.0, 0.0, deck + 0.6)))
    parts.append(_box((1.4, 1.4, 7.0), (3.0, 0.0, deck + 3.5)))
    crane = _box((12.0, 0.6, 0.6), (0.0, 0.0, 0.0))
    crane.apply_transform(trimesh.transformations.rotation_matrix(np.deg2rad(-25.0),
                                                                  (0, 1, 0)))
    crane.apply_translation((3.0 + 5.0, 0.0, deck + 7.0 + 2.2))
    parts.append(crane)
    parts.append(_box((3.0, 8.0, 2.5), (31.0, 0.0, deck + 2.0 + 1.25)))
    return trimesh.util.concatenate(parts)



@lru_cache(maxsize=1)
def _reference() -> tuple[np.ndarray, np.ndarray]:
    ship = vessel()
    return np.asarray(ship.vertices, dtype=np.float64), np.asarray(ship.faces, dtype=np.int64)


@lru_cache(maxsize=64)
def _scaled(length: float, beam: float, draft: float) -> tuple[np.ndarray, np.ndarray]:
    v, f = _reference()
    z = v[:, 2]
    scale = np.stack([np.full_like(z, length / LENGTH), np.full_like(z, beam / BEAM),
                      np.where(z < 0.0, draft / DRAFT, length / LENGTH)], axis=-1)
    out = v * scale
    out.setflags(write=False)
    faces = f.astype(np.uint32)
    faces.setflags(write=False)
    return out, faces


def vessel_mesh(length: float = LENGTH, beam: float = BEAM, draft: float = DRAFT
                ) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) [m] and faces (F, 3) of the generic ship scaled to length L,
    beam B and draft T [m] (module docstring); ships of the same dimensions share the
    (read-only) arrays.
    """
    for name, value in (("length", length), ("beam", beam), ("draft", draft)):
        if not (np.isfinite(value) and value > 0.0):
            raise ValueError(f"{name} = {value!r} m: must be a finite number > 0")
    return _scaled(float(length), float(beam), float(draft))
