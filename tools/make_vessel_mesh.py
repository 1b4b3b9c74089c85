"""Write the meshes of the hull-echo scenes: a generic 80 m ship and a trihedral reflector.

    python tools/make_vessel_mesh.py            # writes scenes/meshes/vessel_80m.ply
                                                #    and scenes/meshes/trihedral_0p5m.ply

The ship is a generic small freighter / offshore vessel, made of simple closed bodies so
that it holds the mechanisms that dominate a ship's radar signature (docs/ship.md): long
wall-sided hull flanks (specular flashes broadside), a transom (flat stern plate), a
raked bow, deck-superstructure and superstructure-superstructure corners (dihedrals),
tiered deckhouses with a bridge and bridge wings, a funnel, hatch covers, a crane and a
mast with a yardarm (corners of small plates: trihedrals). It is not a model of any real
ship. Frame: x forward (bow at +L/2), y to port, z up, waterline z = 0, centred on the
origin in x and y (the convention of ``seaecho.geometry.hull``).

Dimensions: length overall 80 m, beam 13 m, draft 4.5 m, freeboard 4.5 m amidships rising
to 7 m at the bow (sheer), deckhouse aft with three tiers up to 13.6 m above the
waterline, mast top 21 m.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import trimesh

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from seaecho.targets.canonical import trihedral  # noqa: E402

LENGTH, BEAM, DRAFT = 80.0, 13.0, 4.5


def _hull(n_stations: int = 41) -> trimesh.Trimesh:
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
    faces = []
    for s in range(n_stations - 1):
        a, b = s * m, (s + 1) * m
        for k in range(m):  # closed ring: the deck is the edge from the last to the first
            k2 = (k + 1) % m
            faces += [(a + k, b + k, b + k2), (a + k, b + k2, a + k2)]
    for s in (0, n_stations - 1):  # transom and stem caps
        centre = len(verts)
        verts = np.vstack([verts, verts[s * m:(s + 1) * m].mean(axis=0)])
        for k in range(m):
            k1, k2 = s * m + k, s * m + (k + 1) % m
            faces.append((centre, k1, k2) if s == 0 else (centre, k2, k1))
    hull = trimesh.Trimesh(verts, np.array(faces), process=True)
    if hull.volume < 0:
        hull.invert()
    return hull


def _box(extents, centre) -> trimesh.Trimesh:
    b = trimesh.creation.box(extents=extents)
    b.apply_translation(centre)
    return b


def vessel() -> trimesh.Trimesh:
    """The 80 m ship: hull plus superstructure (closed bodies, outward normals)."""
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


def main(out_dir: Path = ROOT / "scenes" / "meshes") -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    ship = vessel()
    ship.export(out_dir / "vessel_80m.ply")
    v, f = trihedral(0.5)
    trimesh.Trimesh(v, f, process=False).export(out_dir / "trihedral_0p5m.ply")
    print(f"vessel_80m.ply: {len(ship.faces)} triangles, extents {ship.extents.round(2)} m")


if __name__ == "__main__":
    main()
