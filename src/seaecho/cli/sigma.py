"""``seaecho sigma``: mean-plane bistatic sigma_mn of a wind sea for angle sweeps.

Writes one CSV row per geometry (columns ``theta_i_deg, theta_s_deg, phi_i_deg,
phi_s_deg, sigma_hh_db, sigma_hv_db, sigma_vh_db, sigma_vv_db``) and a PNG beside it.
Each angle option takes a value or an inclusive ``start:stop:step`` range; the rows are
the Cartesian product of the four angle lists. Monostatic: ``--phi-s-deg 180`` (with
``--phi-i-deg 0``) and ``--theta-s-deg`` equal to ``--theta-i-deg``.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse

#: sigma below this is written as this many dB (an exact 0, e.g. cross-pol in plane).
DB_FLOOR = -300.0


def parse_range(text: str, name: str, lo: float, hi: float):
    """``"20"`` -> [20.0]; ``"0:180:5"`` -> 0, 5, ..., 180 (stop included on the grid)."""
    import numpy as np

    from . import UsageError

    parts = text.split(":")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise UsageError(f"{name} = {text!r}: expected a number or start:stop:step") from None
    if len(values) == 1:
        out = np.array(values)
    elif len(values) == 3:
        start, stop, step = values
        if step <= 0 or stop < start:
            raise UsageError(f"{name} = {text!r}: need step > 0 and stop >= start")
        n = int(np.floor((stop - start) / step + 1e-9)) + 1
        if n > 100_000:
            raise UsageError(f"{name} = {text!r}: {n} values, at most 100000")
        out = start + step * np.arange(n)
    else:
        raise UsageError(f"{name} = {text!r}: expected a number or start:stop:step")
    if np.any(out < lo) or np.any(out > hi):
        raise UsageError(f"{name} = {text!r}: values must lie in [{lo:g}, {hi:g}] deg")
    return out


def register(sub: argparse._SubParsersAction) -> None:
    from ..ocean.seawater import PERMITTIVITY_MODELS
    from ..ocean.twoscale import TWO_SCALE_CUT_RATIO
    from ..scattering.models import MEAN_PLANE_MODELS, SLOPE_MODELS

    p = sub.add_parser(
        "sigma", help="bistatic polarimetric sigma_mn of the sea for angle sweeps (CSV + PNG)",
        description="Mean-plane bistatic scattering coefficients sigma_mn of a wind sea "
        "(paper eqs 7-11) for angle sweeps. Angles: a value or start:stop:step (inclusive). "
        "Monostatic: --phi-s-deg 180 and --theta-s-deg equal to --theta-i-deg. With --scene, "
        "the sea state, the water and the carrier are the scene's.")
    p.add_argument("--scene", metavar="SCENE.toml",
                   help="take the sea state ([sea]: spectrum, spreading, wind, fetch, "
                   "temperature, salinity) and the carrier ([radar]) from a scene file; "
                   "the sea options below are then not allowed")
    p.add_argument("--model", choices=MEAN_PLANE_MODELS, default="blend",
                   help="scattering model (default: blend, eqs 10-11)")
    p.add_argument("--frequency-ghz", type=float,
                   help="radar frequency [GHz] (default 10, or the scene's carrier)")
    p.add_argument("--wind-speed", type=float,
                   help="wind speed U19.5 at 19.5 m [m/s] (default 4.53, paper Fig. 3)")
    p.add_argument("--wind-direction-deg", type=float,
                   help="direction the wind blows towards, CCW from +x [deg] (default 0)")
    p.add_argument("--spectrum", choices=("elfouhaily", "pierson-moskowitz", "jonswap",
                                          "romeiser", "kudryavtsev"),
                   help="omnidirectional wave spectrum (default elfouhaily)")
    p.add_argument("--spreading", choices=("elfouhaily", "longuet-higgins", "romeiser"),
                   help="directional spreading (default elfouhaily)")
    p.add_argument("--fetch-m", type=float, default=None, help="fetch [m] (jonswap)")
    p.add_argument("--slopes", choices=SLOPE_MODELS, default="gaussian",
                   help="slope density of the Kirchhoff part (default gaussian)")
    p.add_argument("--cut-ratio", type=float, default=TWO_SCALE_CUT_RATIO,
                   help="two-scale split k_cut / k [-] (default 1/3, the split every stage "
                   "uses): slopes of the longer waves for Kirchhoff and two-scale tilts")
    p.add_argument("--temperature-c", type=float,
                   help="sea temperature [degC] (default 20)")
    p.add_argument("--salinity-psu", type=float, help="salinity [psu] (default 35)")
    p.add_argument("--permittivity-model", choices=sorted(PERMITTIVITY_MODELS),
                   default="meissner-wentz", help="sea-water permittivity model")
    p.add_argument("--theta-i-deg", default="20", help="incidence angle(s) [deg], 0..90")
    p.add_argument("--theta-s-deg", default="30", help="scattering angle(s) [deg], 0..90")
    p.add_argument("--phi-i-deg", default="0", help="incidence azimuth(s) [deg]")
    p.add_argument("--phi-s-deg", default="0:180:2", help="scattering azimuth(s) [deg]")
    p.add_argument("-o", "--output", default="sigma.csv", help="output CSV file")
    p.add_argument("--no-figure", action="store_true", help="do not write the PNG")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import sys
    import warnings
    from pathlib import Path

    import numpy as np

    from ..api import SIGMA_FREQUENCY_HZ, SIGMA_WIND_M_S, load_scene, sigma
    from ..io.dataset import atomic_path
    from ..plotting.sigma import sigma_sweep_figure
    from . import UsageError

    sea_options = {"wind_speed": "--wind-speed", "wind_direction_deg": "--wind-direction-deg",
                   "spectrum": "--spectrum", "spreading": "--spreading",
                   "fetch_m": "--fetch-m", "temperature_c": "--temperature-c",
                   "salinity_psu": "--salinity-psu"}
    scene = None
    if args.scene is not None:
        given = [flag for name, flag in sea_options.items() if getattr(args, name) is not None]
        if given:
            raise UsageError(f"--scene takes the sea state from the scene file; do not give "
                             f"{', '.join(given)}")
        scene = load_scene(args.scene)
    # Flags in their own units; the API checks the same bounds (in SI) again
    (f_lo, f_hi), u_hi = (b / 1e9 for b in SIGMA_FREQUENCY_HZ), SIGMA_WIND_M_S[1]
    if args.frequency_ghz is not None and not f_lo <= args.frequency_ghz <= f_hi:
        raise UsageError(f"--frequency-ghz = {args.frequency_ghz}: must be in [{f_lo:g}, "
                         f"{f_hi:g}] GHz")
    if args.wind_speed is not None and not 0.0 < args.wind_speed <= u_hi:
        raise UsageError(f"--wind-speed = {args.wind_speed}: must be in (0, {u_hi:g}] m/s")
    if not 0.0 < args.cut_ratio <= 1.0:
        raise UsageError(f"--cut-ratio = {args.cut_ratio}: must be in (0, 1]")
    if args.spectrum == "jonswap" and args.fetch_m is None:
        raise UsageError("--spectrum jonswap needs --fetch-m")
    angles = [
        parse_range(args.theta_i_deg, "--theta-i-deg", 0.0, 90.0),
        parse_range(args.theta_s_deg, "--theta-s-deg", 0.0, 90.0),
        parse_range(args.phi_i_deg, "--phi-i-deg", -360.0, 360.0),
        parse_range(args.phi_s_deg, "--phi-s-deg", -360.0, 360.0),
    ]
    n_rows = int(np.prod([len(a) for a in angles]))
    if n_rows > 1_000_000:
        raise UsageError(f"{n_rows} geometries: at most 1000000")
    out = Path(args.output)
    if out.suffix.lower() != ".csv":
        raise UsageError(f"-o {out}: the output must be a .csv file")
    if not (out.parent if str(out.parent) else Path(".")).is_dir():
        raise UsageError(f"-o {out}: directory {out.parent} does not exist")

    sea = {} if scene is not None else {
        "wind_speed_m_s": args.wind_speed, "wind_direction_deg": args.wind_direction_deg,
        "spectrum": args.spectrum, "spreading": args.spreading, "fetch_m": args.fetch_m,
        "temperature_c": args.temperature_c, "salinity_psu": args.salinity_psu}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s = sigma(args.model, theta_i_deg=angles[0], theta_s_deg=angles[1],
                  phi_i_deg=angles[2], phi_s_deg=angles[3], scene=scene,
                  frequency_hz=None if args.frequency_ghz is None else args.frequency_ghz * 1e9,
                  permittivity_model=args.permittivity_model, slopes=args.slopes,
                  cut_ratio=args.cut_ratio, **sea)
    for w in {str(w.message): w for w in caught}.values():
        print(f"seaecho sigma: warning: {w.message}", file=sys.stderr)
    a = s.attrs
    with np.errstate(divide="ignore"):
        db = np.maximum(10.0 * np.log10(s.values.reshape(-1, 4)), DB_FLOOR)
    grids = np.meshgrid(*angles, indexing="ij")
    rows = np.column_stack([g.ravel() for g in grids] + [db])
    header = ("theta_i_deg,theta_s_deg,phi_i_deg,phi_s_deg,"
              "sigma_hh_db,sigma_hv_db,sigma_vh_db,sigma_vv_db")
    with atomic_path(out) as tmp:
        np.savetxt(tmp, rows, delimiter=",", header=header, comments="", fmt="%.6g")
    print(f"wrote {out} ({n_rows} geometries, model {args.model}, eps_r = "
          f"{a['eps_r_real']:.2f}{a['eps_r_imag']:+.2f}j)")
    if not args.no_figure:
        varying = [(i, v) for i, v in enumerate(angles) if len(v) > 1]
        png = out.with_suffix(".png")
        if len(varying) <= 2:
            title = (f"{args.model}, {a['frequency_hz'] / 1e9:g} GHz, U19.5 = "
                     f"{a['wind_speed_m_s']:g} m/s towards {a['wind_direction_deg']:g} deg, "
                     f"{a['spectrum']}")
            sigma_sweep_figure(rows, varying, png, title, DB_FLOOR)
            print(f"wrote {png}")
        else:
            print("no figure: more than two angles vary", file=sys.stderr)
    return 0
