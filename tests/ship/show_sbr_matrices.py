"""Print the SBR scattering matrices per bounce order (a diagnostic, not a test).

``python tests/ship/show_sbr_matrices.py [boat] [dihedral] [trihedral]`` prints, in
dBsm, HH, HV, VH, VV of the direct paths per bounce order, the phase of S_hv / S_vh
(reciprocity in the FSA bases: S_hv = -S_vh monostatic, so 180 deg) and the total, for

- the paper's 10 m boat at Simulation 2's monostatic aspect (the middle pulse of
  ``scenes/paper_sim2_sar_128m_wind55.toml``), in free space;
- a 0.3 x 0.4 m dihedral on its bisector (elevation 45 deg) rolled about the line of
  sight by 0, 22.5 and 45 deg (BSA closed form ``[[cos 2a, sin 2a], [sin 2a,
  -cos 2a]]``), and off its bisector (elevation 35 deg, azimuth 10 deg);
- a triangular trihedral (a = 0.3 m) on its axis and off it.

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006), "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar,
doi:10.1109/RADAR.2006.1631862 (its Simulation 2 and 10 m boat).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from ship_helpers import direction, trace  # noqa: E402

from seaecho.targets import canonical  # noqa: E402

BSA = np.diag([-1.0, 1.0])


def _db(x):
    return 10.0 * np.log10(np.maximum(np.abs(x) ** 2, 1e-300))


def _roll(u, angle):
    """Rotation by ``angle`` [rad] about the unit vector u (Rodrigues)."""
    c, s = np.cos(angle), np.sin(angle)
    ux = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return c * np.eye(3) + s * ux + (1 - c) * np.outer(u, u)


def show(name, sig):
    print(f"== {name}: {sig.n_rays} rays, {sig.n_hits} hits")
    rows = [(f"order {b + 1}", sig.totals[0, b]) for b in range(sig.totals.shape[1])]
    for label, s in rows + [("all paths", sig.s)]:
        ph = np.degrees(np.angle(s[0, 1] / s[1, 0])) if abs(s[1, 0]) > 0 else np.nan
        print(f"  {label:9s}: HH {_db(s[0, 0]):8.2f}  HV {_db(s[0, 1]):8.2f}  "
              f"VH {_db(s[1, 0]):8.2f}  VV {_db(s[1, 1]):8.2f} dBsm   "
              f"arg(S_hv / S_vh) {ph:7.1f} deg")


def boat():
    from seaecho.build import build_hulls, build_radar
    from seaecho.config.loading import load_scene
    from seaecho.radar.system import RadarSystem
    from seaecho.tracing.hull_echo import HullEchoes
    from seaecho.tracing.sbr import trace_signature

    scenes = HERE.parents[1] / "scenes"
    scene = load_scene(scenes / "paper_sim2_sar_128m_wind55.toml")
    radar = RadarSystem(build_radar(scene))
    hulls = HullEchoes.from_model(build_hulls(scene, scenes), radar)
    h = hulls.hulls[0]
    pulse = radar.n_pulses // 2
    t = float(radar.emission_time(pulse))
    geo = radar.geometry(pulse)
    sig = trace_signature(h.mesh(t), geo.tx.position, geo.rx.position, radar.carrier,
                          options=h.options, reference=h.origin(t))
    show(f"boat, Simulation 2 pulse {pulse}, free space ({h.options})", sig)


def dihedral():
    v, f = canonical.dihedral(0.3, 0.4)
    u = direction(45.0)
    for a in (0.0, 22.5, 45.0):
        sig = trace((v @ _roll(u, np.deg2rad(a)).T, f), u)
        show(f"dihedral on its bisector, rolled {a} deg", sig)
        s = BSA @ sig.s
        print("  BSA S / |S|_F * sqrt 2:", np.round(s / np.linalg.norm(s) * np.sqrt(2), 3)
              .tolist())
    u = direction(35.0, 10.0)
    for a in (0.0, 22.5):
        show(f"dihedral off its bisector (35, 10 deg), rolled {a} deg",
             trace((v @ _roll(u, np.deg2rad(a)).T, f), u))


def trihedral():
    v, f = canonical.trihedral(0.3)
    show("trihedral on its axis", trace((v, f), np.ones(3) / np.sqrt(3)))
    show("trihedral off its axis (45, 30 deg)", trace((v, f), direction(45.0, 30.0)))


if __name__ == "__main__":
    which = sys.argv[1:] or ["boat", "dihedral", "trihedral"]
    for name in which:
        {"boat": boat, "dihedral": dihedral, "trihedral": trihedral}[name]()
