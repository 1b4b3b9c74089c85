"""Write the meshes of the hull-echo scenes: a generic 80 m ship and a trihedral reflector.

    python tools/make_vessel_mesh.py            # writes scenes/meshes/vessel_80m.ply
                                                #    and scenes/meshes/trihedral_0p5m.ply

The ship is :func:`seaecho.geometry.vessel.vessel` (its module describes it); a scene's
``[[ships]]`` with ``hull_echo = true`` gets the same body scaled to its dimensions.
"""

from __future__ import annotations

import sys
from pathlib import Path

import trimesh

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from seaecho.geometry.vessel import vessel  # noqa: E402
from seaecho.targets.canonical import trihedral  # noqa: E402


def main(out_dir: Path = ROOT / "scenes" / "meshes") -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    ship = vessel()
    ship.export(out_dir / "vessel_80m.ply")
    v, f = trihedral(0.5)
    trimesh.Trimesh(v, f, process=False).export(out_dir / "trihedral_0p5m.ply")
    print(f"vessel_80m.ply: {len(ship.faces)} triangles, extents {ship.extents.round(2)} m")


if __name__ == "__main__":
    main()
