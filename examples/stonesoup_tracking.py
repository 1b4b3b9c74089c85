"""Tracking seaecho's detections with Stone Soup: a multi-target tracker on the CFAR plots
of two boats in sea clutter, scored by OSPA and GOSPA against the ground truth.

Run: ``python examples/stonesoup_tracking.py [--quick] [--out DIR]`` (default
``docs/figures``); needs Stone Soup (``pip install 'seaecho[tracking]'``). A monostatic
X-band radar (the scene of examples/detection_benchmark.py: 400 m, 5 deg grazing,
rectangular 0.6 m antenna, 1 m range resolution) watches an evolving Elfouhaily sea
(U19.5 = 6 m/s) with two 0.1 m^2 boats moving along its boresight (+4 m/s and -3 m/s),
one pulse every 0.2 s for 6 s (``--quick``: 2 s). ``seaecho.detect`` (CA-CFAR, P_FA
1e-4 per cell) writes the plots and the truth for Stone Soup (``--stonesoup``);
``seaecho.stonesoup_readers`` gives the readers; a Kalman filter with a nearly constant
velocity model, a global-nearest-neighbour associator, a two-plot initiator and a
covariance deleter make the tracks. The range profiles locate a plot only along the
boresight, so the tracks and the truth lie on that line. Writes
``stonesoup_tracks.png`` and prints the mean OSPA and GOSPA distances.
"""

from __future__ import annotations

import argparse
import tempfile
import warnings
from datetime import timedelta
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import seaecho  # noqa: E402
from seaecho.warnings import SeaechoWarning  # noqa: E402

BOATS = (("boat A", -14.0, 4.0), ("boat B", 16.0, -3.0))  # name, x [m], v_x [m/s]


def scene(n_pulses: int, prf_hz: float):
    """The benchmark's radar and sea (examples/detection_benchmark.py) with the boats."""
    from detection_benchmark import scene as benchmark_scene

    boats = [{"name": n, "position_m": [x, 0.0, 0.5], "velocity_m_s": [v, 0.0, 0.0],
              "rcs_m2": 0.1} for n, x, v in BOATS]
    return benchmark_scene(4, 6.0, n_pulses, prf_hz, targets=boats,
                           name="stonesoup-tracking")


def tracker(detector):
    """A Stone Soup multi-target tracker (Kalman, GNN, two-plot initiation)."""
    from stonesoup.dataassociator.neighbour import GNNWith2DAssignment
    from stonesoup.deleter.error import CovarianceBasedDeleter
    from stonesoup.hypothesiser.distance import DistanceHypothesiser
    from stonesoup.initiator.simple import MultiMeasurementInitiator
    from stonesoup.measures import Mahalanobis
    from stonesoup.models.transition.linear import (
        CombinedLinearGaussianTransitionModel,
        ConstantVelocity,
    )
    from stonesoup.predictor.kalman import KalmanPredictor
    from stonesoup.tracker.simple import MultiTargetTracker
    from stonesoup.types.state import GaussianState
    from stonesoup.updater.kalman import KalmanUpdater

    transition = CombinedLinearGaussianTransitionModel([ConstantVelocity(0.5),
                                                        ConstantVelocity(0.5)])
    predictor = KalmanPredictor(transition)
    updater = KalmanUpdater(measurement_model=None)
    hypothesiser = DistanceHypothesiser(predictor, updater, measure=Mahalanobis(),
                                        missed_distance=4.0)
    associator = GNNWith2DAssignment(hypothesiser)
    deleter = CovarianceBasedDeleter(covar_trace_thresh=200.0)
    prior = GaussianState([[0.0], [0.0], [0.0], [0.0]], np.diag([1.0, 25.0, 1.0, 25.0]))
    initiator = MultiMeasurementInitiator(prior, deleter=deleter, data_associator=associator,
                                          updater=updater, min_points=3)
    return MultiTargetTracker(initiator=initiator, deleter=deleter, detector=detector,
                              data_associator=associator, updater=updater)


def main(argv=None) -> list[Path]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="2 s of pulses")
    ap.add_argument("--out", default="docs/figures", help="output folder")
    args = ap.parse_args(argv)
    from stonesoup.measures import Euclidean
    from stonesoup.metricgenerator.manager import MultiManager
    from stonesoup.metricgenerator.ospametric import GOSPAMetric, OSPAMetric

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    prf = 5.0
    n = 10 if args.quick else 30
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SeaechoWarning)
        run = seaecho.simulate(scene(n, prf), progress=False)
    with tempfile.TemporaryDirectory() as tmp:
        det, truth = seaecho.detect(run, cfar="ca", pfa=1e-4, train=8, guard=2,
                                    stonesoup=tmp)
        s = seaecho.score(det, truth)
        detections, truths = seaecho.stonesoup_readers(tmp)
        tracks = set()
        for _, current in tracker(detections):
            tracks |= current
        paths = set()
        for _, current in truths:
            paths |= current
    gospa = GOSPAMetric(c=10.0, p=1.0, measure=Euclidean((0, 2)))
    ospa = OSPAMetric(c=10.0, p=1.0, measure=Euclidean((0, 2)))
    manager = MultiManager([gospa, ospa])
    manager.add_data({"tracks": tracks, "groundtruth_paths": paths})
    metrics = manager.generate_metrics()

    def mean_of(generator, name):
        values = metrics[generator][name].value
        return float(np.mean([v.value["distance"] if isinstance(v.value, dict) else v.value
                              for v in values]))

    g_name = next(k for k in metrics["gospa_generator"] if "GOSPA" in k)
    o_name = next(k for k in metrics["ospa_generator"] if "OSPA" in k)
    g_mean, o_mean = mean_of("gospa_generator", g_name), mean_of("ospa_generator", o_name)
    fig, ax = plt.subplots(figsize=(6, 4))
    t0 = min(p[0].timestamp for p in paths)
    for p in paths:
        ax.plot([(st.timestamp - t0) / timedelta(seconds=1) for st in p],
                [st.state_vector[0, 0] for st in p], "k-", lw=3, alpha=0.3)
    dt = (det.time.values - det.time.values.min())
    fa = det.object_index.values < 0
    ax.plot(dt[~fa], det.x_m.values[~fa], "g.", ms=4, label="plots on a boat")
    ax.plot(dt[fa], det.x_m.values[fa], "rx", ms=4, label="false alarms")
    for i, trk in enumerate(sorted(tracks, key=lambda t: t[0].timestamp)):
        ax.plot([(st.timestamp - t0) / timedelta(seconds=1) for st in trk],
                [st.state_vector[0, 0] for st in trk], "-", lw=1,
                label="tracks" if i == 0 else None)
    ax.set(xlabel="time [s]", ylabel="x [m] (east)",
           title=f"Stone Soup tracks: mean OSPA {o_mean:.2f} m, GOSPA {g_mean:.2f} m")
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = out / "stonesoup_tracks.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print(f"{det.sizes['detection']} plots ({int(fa.sum())} false alarms), P_D per boat "
          + ", ".join(f"{s['objects'][o]} {v[2]:.2f}" for o, v in s['pd_object'].items())
          + " (looks the truth hides, scored apart: "
          + (", ".join(f"{s['objects'][o]} {v[1]}" for o, v in s['hidden_object'].items())
             or "none") + ")"
          + f"; {len(tracks)} tracks for {len(paths)} boats; mean OSPA {o_mean:.2f} m, "
          f"mean GOSPA {g_mean:.2f} m (c = 10 m, p = 1)")
    return [png]


if __name__ == "__main__":
    main()
