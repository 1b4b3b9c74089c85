"""A simple closed hull mesh for the paper's small motor boat (section V-A).

The paper's boat is 10 m long, 4 m in beam with a 1.5 m draft. Its shape is not given;
:func:`motor_boat_hull` builds a plausible planing-hull-like body from stations: a
transom stern, a pointed bow with a rising keel, a V bottom with a chine, a flat deck
``freeboard`` above the waterline and a deckhouse. Frame: x forward (bow at +L/2), y to
port, z up, waterline z = 0, the hull centred on the origin in x and y. The bundled
``scenes/meshes/motor_boat_10m.ply`` is ``motor_boat_hull()`` written by
``python -m seaecho.geometry.hull scenes/meshes/motor_boat_10m.ply``.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import sys

import numpy as np

__all__ = ["motor_boat_hull"]


def motor_boat_hull(length: float = 10.0, beam: float = 4.0, draft: float = 1.5,
                    freeboard: float = 1.0, cabin_height: float = 1.2, n_stations: int = 21
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of a closed (watertight) motor-boat hull with a deckhouse.

    Parameters
    ----------
    length : float
        Overall length [m] (x extent).
    beam : float
        Maximum breadth [m] (y extent).
    draft : float
        Depth of the keel below the waterline [m] (z min = -draft).
    freeboard : float
        Deck height above the waterline [m].
    cabin_height : float
        Deckhouse height above the deck [m] (0: none).
    n_stations : int
        Number of cross-sections along the length [-].

    Returns
    -------
    vertices : (V, 3) float64 array
        [m].
    faces : (F, 3) int64 array
        Outward-oriented triangles (two closed bodies: hull and deckhouse).
    """
    import trimesh

    if min(length, beam, draft, freeboard) <= 0 or beam >= length:
        raise ValueError("length > beam > 0, draft > 0 and freeboard > 0 are required [m]")
    xs = np.linspace(-length / 2, length / 2, n_stations)
    u = (xs + length / 2) / length  # 0 at the transom, 1 at the bow
    # Half-breadth: full aft, tapering to a point (small width) at the bow.
    half = 0.5 * beam * np.where(u < 0.5, 1.0, np.sqrt(np.clip(1 - ((u - 0.5) / 0.5) ** 2,
                                                               0.0, 1.0)))
    half = np.maximum(half, 0.02 * beam)
    # Keel depth: full over most of the length, rising to 30 % at the stem.
    depth = draft * np.where(u < 0.6, 1.0, 1.0 - 0.7 * ((u - 0.6) / 0.4) ** 2)
    # Cross-section polygon (counter-clockwise seen from the bow): deck edge, chine, keel.
    prof_y = np.array([1.0, 1.0, 0.55, 0.0, -0.55, -1.0, -1.0])
    prof_z = np.array([None, -0.35, -0.8, -1.0, -0.8, -0.35, None], dtype=object)
    m = prof_y.size
    verts = []
    for x, b, d in zip(xs, half, depth, strict=True):
        for py, pz in zip(prof_y, prof_z, strict=True):
            z = freeboard if pz is None else float(pz) * d
            verts.append((x, py * b, z))
    parts = [lofted_hull(np.array(verts), n_stations, m)]
    if cabin_height > 0:
        cabin = trimesh.creation.box(extents=(0.3 * length, 0.6 * beam, cabin_height))
        cabin.apply_translation((-0.05 * length, 0.0, freeboard + cabin_height / 2))
        parts.append(cabin)
    mesh = trimesh.util.concatenate(parts)
    return np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int64)


def lofted_hull(verts: np.ndarray, n_stations: int, m: int):
    """Closed hull lofted through ``n_stations`` sections of ``m`` points each
    (``verts`` (n_stations m, 3) [m], section by section, each a closed ring whose last
    point joins its first across the deck): quads between neighbouring sections, fans
    capping the transom and the stem, triangles facing outwards (a ``trimesh.Trimesh``)."""
    import trimesh

    faces = []
    for s in range(n_stations - 1):
        a, b = s * m, (s + 1) * m
        for k in range(m):  # closed ring: the deck is the edge from the last to the first
            k2 = (k + 1) % m
            faces += [(a + k, b + k, b + k2), (a + k, b + k2, a + k2)]
    # End caps (transom and stem): fans around each section's centre.
    for s in (0, n_stations - 1):
        centre = len(verts)
        verts = np.vstack([verts, verts[s * m: (s + 1) * m].mean(axis=0)])
        for k in range(m):
            k1, k2 = s * m + k, s * m + (k + 1) % m
            faces.append((centre, k1, k2) if s == 0 else (centre, k2, k1))
    hull = trimesh.Trimesh(verts, np.array(faces), process=True)
    if hull.volume < 0:  # make the triangles face outwards
        hull.invert()
    return hull


def _main(argv: list[str]) -> int:
    import trimesh

    if len(argv) != 1:
        print("usage: python -m seaecho.geometry.hull OUT.ply", file=sys.stderr)
        return 2
    v, f = motor_boat_hull()
    trimesh.Trimesh(v, f, process=False).export(argv[0])
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(_main(sys.argv[1:]))
