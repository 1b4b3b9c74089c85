"""Tracking the boats of a scanning coastal radar with Stone Soup: CFAR plots per sweep, a
multi-target tracker on bearing and range, scored by OSPA, GOSPA and SIAP.

Run: ``python examples/scanning_tracking.py [--quick] [--revolutions N] [--out DIR]
[--land-margin M] [--land-spread-db X] [--no-land-censor] [--table] [--spread-table]``
(default ``docs/figures``); needs Stone Soup (``pip install 'seaecho[tracking]'``).
The scene is ``scenes/coastal_vts_xband.toml`` (a VTS radar 35 m up on the coast, 1.0 deg
fan beam turning at 24 rpm, 100 ns pulse, sea state 4 on a 256 m tile 2 km north, two
buoys and three boats out to 6 km, 4/3 Earth) with one change to make several
revolutions affordable here: a PRF of 500 Hz in place of 1 kHz (0.29 deg per pulse,
3.5 pulses per beamwidth; the sea renewed every 125 pulses, 0.25 s as in the scene);
8 revolutions (20 s; ``--quick``: 4). Each sweep goes through ``seaecho.detect`` (2-D
CA-CFAR on the PPI, azimuth x range, train 4 x 8, guard 3 x 2, P_FA 1e-6 per cell;
the cells on the scene's coast and headland and those their echo spreads onto (the
two-way beam and the compressed pulse down to -65 dB, ``--land-spread-db X``; plus
``--land-margin M`` from the shore, default 0) blanked by the land mask and left out of
the CFAR's training windows, ``--no-land-censor``: kept in them),
which writes the plots and the truth for Stone Soup (``--stonesoup``; an object the
truth hides, such as the fishing boat behind the headland, is scored apart and is no
truth for the tracker);
``seaecho.stonesoup_readers`` gives each plot a bearing-range measurement model centred
on the radar (Stone Soup's bearing, counter-clockwise from east, is 90 deg minus the
PPI's azimuth). An extended Kalman filter with a nearly-constant-velocity model, a
global-nearest-neighbour associator, a three-plot initiator and a deleter after 2.5 scans
without a plot make the tracks. The metrics compare tracks and truth at the end of each
sweep (each predicted there from its last state): OSPA and GOSPA (c = 50 m, p = 1) and
the SIAP completeness, ambiguity, spuriousness and position accuracy (tracks assigned to
a truth within 50 m for 2 scans). Then (not with ``--quick``) the same run through
GO- and OS-CFAR and a four-plot initiation, as a table (``--table``: with ``--quick``
too). ``--spread-table``: the CA-CFAR's false alarms near the shore, the cells blanked and
the objects' P_D for several levels of the land's spread (docs/detection.md's choice of
the default). ``--run FILE`` keeps the run
(read again if it exists). Writes ``scanning_tracking.png`` and prints the numbers
docs/detection.md quotes.
"""

from __future__ import annotations

import argparse
import tempfile
import time
import warnings
from datetime import datetime, timedelta
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import seaecho  # noqa: E402
from seaecho.api import LAND_SPREAD_DB  # noqa: E402
from seaecho.warnings import SeaechoWarning  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"
PRF_HZ = 500.0
C_M = 50.0  # OSPA / GOSPA cut-off and the SIAP association distance [m]
# the land mask's margin from the shore (the chart's error): none here, the spread of
# the land's echo (seaecho.detect's land_spread_db) blanks the sea it reaches
LAND_MARGIN_M = 0.0
#: levels [dB] of --spread-table (None: no spread)
SPREAD_LEVELS = (None, 30.0, 40.0, 50.0, 55.0, 60.0, 65.0, 70.0)


def scene(revolutions: int):
    """The coastal VTS scene at 500 Hz for ``revolutions`` turns of the antenna."""
    base = seaecho.load_scene(SCENE)
    period_s = 60.0 / base.transmitter.antenna.scan.rate_rpm
    return seaecho.with_overrides(base, {
        "radar.prf_hz": PRF_HZ, "radar.n_pulses": int(round(revolutions * period_s * PRF_HZ)),
        "radar.sea_update_pulses": int(round(0.25 * PRF_HZ))}), period_s


def tracker(detector, scan_s: float, min_points: int = 3):
    """A Stone Soup multi-target tracker: EKF, nearly constant velocity, GNN, a track
    confirmed after ``min_points`` plots."""
    from stonesoup.dataassociator.neighbour import GNNWith2DAssignment
    from stonesoup.deleter.time import UpdateTimeDeleter
    from stonesoup.hypothesiser.distance import DistanceHypothesiser
    from stonesoup.initiator.simple import MultiMeasurementInitiator
    from stonesoup.measures import Mahalanobis
    from stonesoup.models.transition.linear import (
        CombinedLinearGaussianTransitionModel,
        ConstantVelocity,
    )
    from stonesoup.predictor.kalman import ExtendedKalmanPredictor
    from stonesoup.tracker.simple import MultiTargetTracker
    from stonesoup.types.state import GaussianState
    from stonesoup.updater.kalman import ExtendedKalmanUpdater

    transition = CombinedLinearGaussianTransitionModel([ConstantVelocity(0.05),
                                                        ConstantVelocity(0.05)])
    predictor = ExtendedKalmanPredictor(transition)
    updater = ExtendedKalmanUpdater(measurement_model=None)
    hypothesiser = DistanceHypothesiser(predictor, updater, measure=Mahalanobis(),
                                        missed_distance=4.0)
    associator = GNNWith2DAssignment(hypothesiser)
    deleter = UpdateTimeDeleter(timedelta(seconds=2.5 * scan_s))
    # position from the first plot; speed unknown up to ~10 m/s
    prior = GaussianState([[0.0], [0.0], [0.0], [0.0]], np.diag([0.0, 100.0, 0.0, 100.0]))
    initiator = MultiMeasurementInitiator(prior, deleter=deleter, data_associator=associator,
                                          updater=updater, min_points=min_points)
    return MultiTargetTracker(initiator=initiator, deleter=deleter, detector=detector,
                              data_associator=associator, updater=updater), predictor


def at_times(states, times, predictor, scan_s: float):
    """The latest state before each time, carried to it (predicted for a track, moved at
    constant velocity for a truth); None where the last state is older than a scan."""
    out = []
    stamps = [s.timestamp for s in states]
    for t in times:
        i = np.searchsorted(np.array(stamps, dtype="datetime64[us]"),
                            np.datetime64(t, "us"), side="right") - 1
        if i < 0 or (t - stamps[i]).total_seconds() > scan_s:
            out.append(None)
            continue
        s = states[i]
        if predictor is None:
            dt = (t - s.timestamp).total_seconds()
            v = np.asarray(s.state_vector, dtype=float).ravel()
            out.append(v + dt * np.array([v[1], 0.0, v[3], 0.0]))
        else:
            out.append(predictor.predict(s, timestamp=t))
    return out


def synchronised(tracks, paths, times, predictor, scan_s):
    """Tracks and truth at the same times (the end of each sweep), as Stone Soup types."""
    from stonesoup.types.groundtruth import GroundTruthPath, GroundTruthState
    from stonesoup.types.state import GaussianState
    from stonesoup.types.track import Track

    out_tracks, out_paths = set(), set()
    for trk in tracks:
        states = [GaussianState(p.state_vector, p.covar, timestamp=t)
                  for p, t in zip(at_times(list(trk), times, predictor, scan_s), times,
                                  strict=True) if p is not None]
        if states:
            out_tracks.add(Track(states, id=trk.id))
    for path in paths:
        states = [GroundTruthState(v.reshape(4, 1), timestamp=t)
                  for v, t in zip(at_times(list(path), times, None, scan_s), times,
                                  strict=True) if v is not None]
        if states:
            out_paths.add(GroundTruthPath(states, id=path.id))
    return out_tracks, out_paths


def metrics(tracks, paths) -> dict:
    """Mean OSPA and GOSPA distances and the SIAP measures of synchronised sets."""
    from stonesoup.dataassociator.tracktotrack import TrackToTruth
    from stonesoup.measures import Euclidean
    from stonesoup.metricgenerator.manager import MultiManager
    from stonesoup.metricgenerator.ospametric import GOSPAMetric, OSPAMetric
    from stonesoup.metricgenerator.tracktotruthmetrics import SIAPMetrics

    gens = [OSPAMetric(c=C_M, p=1.0, measure=Euclidean((0, 2))),
            GOSPAMetric(c=C_M, p=1.0, measure=Euclidean((0, 2))),
            SIAPMetrics(position_measure=Euclidean((0, 2)),
                        velocity_measure=Euclidean((1, 3)))]
    manager = MultiManager(gens, associator=TrackToTruth(association_threshold=C_M,
                                                        consec_pairs_confirm=2,
                                                        consec_misses_end=2))
    manager.add_data({"tracks": tracks, "groundtruth_paths": paths})
    m = manager.generate_metrics()

    def value(generator, startswith):
        name = next(k for k in m[generator] if k.startswith(startswith))
        v = m[generator][name].value
        if isinstance(v, list):  # a value per time
            return float(np.mean([x.value["distance"] if isinstance(x.value, dict)
                                  else x.value for x in v]))
        return float(v)

    return {"ospa": value("ospa_generator", "OSPA distances"),
            "gospa": value("gospa_generator", "GOSPA Metrics"),
            "completeness": value("siap_generator", "SIAP Completeness"),
            "ambiguity": value("siap_generator", "SIAP Ambiguity"),
            "spuriousness": value("siap_generator", "SIAP Spuriousness"),
            "position_accuracy_m": value("siap_generator", "SIAP Position Accuracy"),
            "velocity_accuracy_m_s": value("siap_generator", "SIAP Velocity Accuracy"),
            "longest_segment": value("siap_generator", "SIAP Longest Track Segment")}


def figure(run, det, tracks, paths, out: Path, title: str) -> Path:
    """The last sweep's PPI (dB) with the truth, the plots and the tracks: the whole
    picture, the sea tile (the clutter's false alarms) and the pilot boat."""
    sweep = run["sweep"].values
    last = sweep == sweep.max()
    axes = run["tx_antenna_axes"].values[last]
    az = np.unwrap(np.arctan2(axes[:, 0, 0], axes[:, 1, 0]))  # clockwise from north
    rng = run["range"].values
    radar = run["tx_position"].values[last][0]
    # the cells' edges: half a ray and half a gate either side of the centres
    a_e = np.r_[az[0] - 0.5 * (az[1] - az[0]), 0.5 * (az[1:] + az[:-1]),
                az[-1] + 0.5 * (az[-1] - az[-2])]
    r_e = np.r_[rng[0] - 0.5 * (rng[1] - rng[0]), 0.5 * (rng[1:] + rng[:-1]),
                rng[-1] + 0.5 * (rng[-1] - rng[-2])]
    ground = np.sqrt(np.maximum(r_e ** 2 - radar[2] ** 2, 0.0))
    xx = radar[0] + ground[None, :] * np.sin(a_e)[:, None]
    yy = radar[1] + ground[None, :] * np.cos(a_e)[:, None]
    p_db = 10.0 * np.log10(np.abs(run["compressed"].values[last, 0]) ** 2 + 1e-30)
    p_db -= float(np.median(p_db))

    def xy(states):
        return (np.array([float(s.state_vector[0, 0]) for s in states]),
                np.array([float(s.state_vector[2, 0]) for s in states]))

    fig, axs = plt.subplots(1, 3, figsize=(15, 5.4), layout="constrained",
                            gridspec_kw={"width_ratios": [1.3, 1, 1]})
    pilot = next(p for p in paths if p.id == "pilot-boat")
    zx, zy = xy(list(pilot))
    views = ((axs[0], None, title),
             (axs[1], (-200.0, 200.0, -200.0, 200.0), "the sea tile (2 km north)"),
             (axs[2], (zx.mean() - 150, zx.mean() + 150, zy.mean() - 150, zy.mean() + 150),
              "the pilot boat (7 m/s north)"))
    fa = det.object_index.values < 0
    for ax, lim, name in views:
        step = 2 if lim is None else 1
        m = ax.pcolormesh(xx[::step, ::step] / 1e3, yy[::step, ::step] / 1e3,
                          p_db[::step, ::step][:(xx.shape[0] - 1) // step,
                                               :(xx.shape[1] - 1) // step],
                          vmin=0, vmax=40, cmap="gray_r", shading="flat", rasterized=True)
        ax.plot(det.x_m.values[fa] / 1e3, det.y_m.values[fa] / 1e3, "x", color="tab:red",
                ms=4, label="false alarms (all sweeps)")
        ax.plot(det.x_m.values[~fa] / 1e3, det.y_m.values[~fa] / 1e3, ".",
                color="tab:green", ms=5, label="plots on an object")
        for i, p in enumerate(paths):
            px, py = xy(list(p))
            ax.plot(px / 1e3, py / 1e3, "-", color="tab:blue", lw=5, alpha=0.35,
                    label="truth" if i == 0 else None)
        for i, trk in enumerate(sorted(tracks, key=lambda t: t[0].timestamp)):
            tx, ty = xy([s for s in trk if type(s).__name__.endswith("Update")])
            ax.plot(tx / 1e3, ty / 1e3, "-", color="tab:orange", lw=1.2,
                    label="tracks (updates)" if i == 0 else None)
        ax.plot(radar[0] / 1e3, radar[1] / 1e3, "k^", ms=7)
        ax.set_aspect("equal")
        ax.set(xlabel="x [km] (east)", ylabel="y [km] (north)")
        ax.set_title(name, fontsize=9)
        if lim is not None:
            ax.set(xlim=np.array(lim[:2]) / 1e3, ylim=np.array(lim[2:]) / 1e3)
    axs[0].legend(fontsize=7, loc="lower left")
    fig.colorbar(m, ax=axs, shrink=0.8, label="last sweep's power over its median [dB]")
    png = out / "scanning_tracking.png"
    fig.savefig(png, dpi=100)
    plt.close(fig)
    return png


def main(argv=None) -> list[Path]:
    from stonesoup.types.state import State

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="4 revolutions")
    ap.add_argument("--revolutions", type=int, default=None, help="revolutions (default 8)")
    ap.add_argument("--out", default="docs/figures", help="output folder")
    ap.add_argument("--run", help="the run's netCDF file: read if it exists (same scene), "
                    "else written")
    ap.add_argument("--no-land-censor", action="store_true",
                    help="leave the land's cells in the CFAR windows (the detector before "
                    "land censoring)")
    ap.add_argument("--land-margin", type=float, default=LAND_MARGIN_M, metavar="M",
                    help=f"the land mask's margin [m] (default {LAND_MARGIN_M:g})")
    ap.add_argument("--land-spread-db", type=float, default=LAND_SPREAD_DB,
                    metavar="X", help="the level of the land's echo spread [dB] (default "
                    f"{LAND_SPREAD_DB:g})")
    ap.add_argument("--spread-table", action="store_true",
                    help="false alarms near the shore against the level of the spread")
    ap.add_argument("--table", action="store_true",
                    help="the detector x initiation table with --quick too")
    args = ap.parse_args(argv)
    censor = not args.no_land_censor
    revs = args.revolutions or (4 if args.quick else 8)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sc, scan_s = scene(revs)
    t_cpu, t_wall = time.process_time(), time.perf_counter()
    if args.run and Path(args.run).is_file():
        run = seaecho.open_dataset(args.run).drop_vars("raw").load()
        if run.sizes["pulse"] != sc.radar.n_pulses:
            raise SystemExit(f"{args.run}: {run.sizes['pulse']} pulses, not "
                             f"{sc.radar.n_pulses} ({revs} revolutions)")
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeaechoWarning)
            run = seaecho.simulate(sc, path=args.run, progress=False)
    cpu, wall = time.process_time() - t_cpu, time.perf_counter() - t_wall
    sweep_end = [datetime(1970, 1, 1) + timedelta(seconds=float(t)) for t in
                 run["time"].groupby(run["sweep"]).max().values]
    det, s, tracks, paths, mt, meas = track_and_score(run, "ca", 3, sweep_end, scan_s,
                                                      censor, args.land_margin,
                                                      args.land_spread_db)
    # the plots' errors against the truth, in bearing and range (the model's noise)
    by_id = {p.id: p for p in paths}
    err_b, err_r = [], []
    for name, ds in meas.items():
        if name not in by_id:
            continue
        for d in ds:
            truth_now = at_times(list(by_id[name]), [d.timestamp], None, scan_s)[0]
            if truth_now is None:
                continue
            h = d.measurement_model.function(State(truth_now.reshape(4, 1)))
            err_b.append(float(d.state_vector[0, 0]) - float(h[0, 0]))
            err_r.append(float(d.state_vector[1, 0]) - float(h[1, 0]))
            model = d.measurement_model
    err_b = (np.array(err_b) + np.pi) % (2 * np.pi) - np.pi
    n_sweeps = int(run["sweep"].max()) + 1
    names = s["objects"]
    pd = ", ".join(f"{names[o]} {v[0]}/{v[1]}" for o, v in s["pd_object"].items())
    hidden = ", ".join(f"{names[o]} {v[1]} (plots in {v[0]})"
                       for o, v in s["hidden_object"].items()) or "none"
    title = (f"coastal_vts_xband, {revs} turns at {PRF_HZ:g} Hz: {len(tracks)} tracks, "
             f"OSPA {mt['ospa']:.1f} m")
    png = figure(run, det, tracks, paths, out, title)
    print(f"run: {run.sizes['pulse']} pulses, {n_sweeps} sweeps, {wall:.0f} s wall, "
          f"{cpu:.0f} s CPU")
    print(f"plots: {det.sizes['detection']} ({s['false_alarms']} false alarms, "
          f"{s['false_alarms_per_look']:.2f} per sweep, {s['false_alarms_per_km2']:.3f} per "
          f"km^2 and sweep, P_FA per cell {s['pfa_cell']:.2g} at design 1e-6); P_D per "
          f"object (sweeps): {pd}; sweeps where the truth hides an object: {hidden}")
    print(f"land mask: {det.attrs['cells_blanked']} cells blanked over {n_sweeps} sweeps "
          f"(margin {det.attrs['land_margin_m']:g} m; the land's echo spread at "
          f"-{det.attrs['land_spread_db']:g} dB: {det.attrs['land_spread_azimuth_deg']:.3f} deg"
          f" = {det.attrs['land_spread_rays']} rays, {det.attrs['land_spread_range_m']:.1f} m"
          f" = {det.attrs['land_spread_gates']} gates), {det.attrs['cells_tested']} tested; "
          + (f"land censoring: {det.attrs['cells_censored']} tested with the land left out "
             f"of their window, {det.attrs['cells_short']} untested (less than half their "
             "window on the sea)" if det.attrs["land_censor"] else "no land censoring"))
    on = det.object_index.values >= 0
    # the false alarms on the sea tile (|x|, |y| <= half its size): their cells over the
    # tile's cells of every sweep
    half = 0.5 * sc.sea.size_x_m
    tile = ~on & (np.abs(det.x_m.values) <= half) & (np.abs(det.y_m.values) <= half)
    n_tile_cells = tile_cells(run, half)
    print(f"false alarms on the sea tile: {int(tile.sum())} of {int((~on).sum())} "
          f"({int(det.n_cells.values[tile].sum())} cells of {n_tile_cells} x {n_sweeps} "
          f"sweeps: P_FA per cell there "
          f"{det.n_cells.values[tile].sum() / (n_tile_cells * n_sweeps):.2g})")
    print(f"plots on objects: SNR {det.snr_db.values[on].min():.0f} to "
          f"{det.snr_db.values[on].max():.0f} dB, {det.n_cells.values[on].min()} to "
          f"{det.n_cells.values[on].max()} cells")
    print(f"plots on objects vs truth: bearing error {np.rad2deg(err_b.mean()):+.3f} +- "
          f"{np.rad2deg(err_b.std()):.3f} deg, range error {np.mean(err_r):+.2f} +- "
          f"{np.std(err_r):.2f} m ({err_b.size} plots); the model's sigma "
          f"{np.rad2deg(np.sqrt(model.covar()[0, 0])):.3f} deg, "
          f"{np.sqrt(model.covar()[1, 1]):.2f} m")
    print(f"tracks: {len(tracks)} for {len(paths)} objects; at the {len(sweep_end)} sweep "
          f"ends: mean OSPA {mt['ospa']:.2f} m, mean GOSPA {mt['gospa']:.2f} m (c = "
          f"{C_M:g} m, p = 1); SIAP completeness {mt['completeness']:.2f}, ambiguity "
          f"{mt['ambiguity']:.2f}, spuriousness {mt['spuriousness']:.2f}, position "
          f"accuracy {mt['position_accuracy_m']:.2f} m, velocity accuracy "
          f"{mt['velocity_accuracy_m_s']:.2f} m/s, longest segment "
          f"{mt['longest_segment']:.2f}")
    if args.table or not args.quick:  # the same run through other detectors, initiations
        print("detector | initiation | false alarms | tracks | OSPA [m] | GOSPA [m] | "
              "completeness | spuriousness | position accuracy [m]")
        for cfar in ("ca", "go", "os"):
            for min_points in (3, 4):
                det_v, s_v, tr_v, _, m_v, _ = track_and_score(
                    run, cfar, min_points, sweep_end, scan_s, censor, args.land_margin,
                    args.land_spread_db)
                print(f"{cfar.upper()}-CFAR | {min_points} plots | {s_v['false_alarms']} | "
                      f"{len(tr_v)} | {m_v['ospa']:.1f} | {m_v['gospa']:.1f} | "
                      f"{m_v['completeness']:.2f} | {m_v['spuriousness']:.2f} | "
                      f"{m_v['position_accuracy_m']:.2f}")
    if args.spread_table:
        spread_table(run, censor, args.land_margin)
    return [png]


def shore_distance(run, x_m, y_m):
    """Distance of each point (x_m, y_m) to the nearest edge of the run's land outlines
    [m]."""
    from seaecho.io.detections import run_land_outlines

    p = np.stack([np.asarray(x_m, float), np.asarray(y_m, float)], -1)
    best = np.full(p.shape[0], np.inf)
    for v in run_land_outlines(run):
        ab = np.roll(v, -1, axis=0) - v
        q = p[:, None] - v[None]
        t = np.clip((q * ab).sum(-1) / (ab ** 2).sum(-1), 0.0, 1.0)
        best = np.minimum(best, np.sqrt(((q - t[..., None] * ab) ** 2).sum(-1)).min(1))
    return best


def spread_table(run, censor: bool, margin_m: float) -> None:
    """The CA-CFAR (the script's window, P_FA 1e-6) at each level of SPREAD_LEVELS: the
    extents, the cells blanked, the sea area tested per sweep, the false alarms (within
    50 and 100 m of the shore) and the P_D of the objects in sight."""
    print("land spread [dB] | azimuth [deg] (rays) | range [m] (gates) | cells blanked | "
          "area tested per sweep [km^2] | false alarms | within 50 m | within 100 m | "
          "objects in sight detected [sweeps]")
    for level in SPREAD_LEVELS:
        det, truth = seaecho.detect(run, cfar="ca", pfa=1e-6, train=(4, 8), guard=(3, 2),
                                    land_margin_m=margin_m, land_censor=censor,
                                    land_spread_db=level)
        s = seaecho.score(det, truth)
        fa = det.object_index.values < 0
        d = shore_distance(run, det.x_m.values[fa], det.y_m.values[fa])
        a = det.attrs
        found = sum(v[0] for v in s["pd_object"].values())
        looks = sum(v[1] for v in s["pd_object"].values())
        print(f"{'none' if level is None else f'{level:g}'} | "
              f"{a['land_spread_azimuth_deg']:.2f} ({a['land_spread_rays']}) | "
              f"{a['land_spread_range_m']:.1f} ({a['land_spread_gates']}) | "
              f"{a['cells_blanked']} | {a['area_m2'] / 1e6:.2f} | {int(fa.sum())} | "
              f"{int((d < 50).sum())} | {int((d < 100).sum())} | {found}/{looks}")


def tile_cells(run, half_m: float) -> int:
    """PPI cells of one sweep whose point of the sea lies on the tile (|x|, |y| <=
    half_m)."""
    sweep = run["sweep"].values
    first = sweep == sweep.min()
    axes = run["tx_antenna_axes"].values[first]
    az = np.arctan2(axes[:, 0, 0], axes[:, 1, 0])
    radar = run["tx_position"].values[first][0]
    ground = np.sqrt(np.maximum(run["range"].values ** 2 - radar[2] ** 2, 0.0))
    x = radar[0] + ground[None, :] * np.sin(az)[:, None]
    y = radar[1] + ground[None, :] * np.cos(az)[:, None]
    return int(((np.abs(x) <= half_m) & (np.abs(y) <= half_m)).sum())


def track_and_score(run, cfar: str, min_points: int, sweep_end, scan_s: float,
                    censor: bool = True, margin_m: float = LAND_MARGIN_M,
                    spread_db: float | None = None):
    """Detect (``cfar`` at P_FA 1e-6; the land, ``margin_m`` round it and its echo's
    spread at -``spread_db`` dB (default seaecho.detect's), blanked and
    censored out of the CFAR's windows unless ``censor`` is False), export, track and
    score at the sweep ends: (detections, scores, tracks, truth paths, metrics, plots
    by object)."""
    with tempfile.TemporaryDirectory() as tmp:
        det, truth = seaecho.detect(run, cfar=cfar, pfa=1e-6, train=(4, 8), guard=(3, 2),
                                    land_margin_m=margin_m, land_censor=censor,
                                    land_spread_db=LAND_SPREAD_DB
                                    if spread_db is None else spread_db, stonesoup=tmp)
        s = seaecho.score(det, truth)
        detections, truths = seaecho.stonesoup_readers(tmp)
        trk, predictor = tracker(detections, scan_s, min_points)
        tracks = set()
        for _, current in trk:
            tracks |= current
        paths = set()
        for _, current in truths:
            paths |= current
        meas: dict[str, list] = {}
        for _, ds in seaecho.stonesoup_readers(tmp)[0]:
            for d in ds:
                meas.setdefault(d.metadata["object"], []).append(d)
    sync_tracks, sync_paths = synchronised(tracks, paths, sweep_end, predictor, scan_s)
    return det, s, tracks, paths, metrics(sync_tracks, sync_paths), meas


if __name__ == "__main__":
    main()
