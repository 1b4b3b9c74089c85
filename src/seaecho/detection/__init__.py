"""Detection on plain arrays: CFAR detectors (CA, GO, SO, OS; 1-D and 2-D), a clutter map,
M-of-N integration, plot extraction, the sea a range cell covers, association with the
ground truth, scores and ROC curves (docs/detection.md). Range profiles (pulse x range),
PPI sweeps (azimuth x range) and SAR images (y x x) in; detections out. Reading datasets
and writing tables is :mod:`seaecho.io.detections`; :func:`seaecho.detect` and
:func:`seaecho.score` join them.
"""

from .association import associate, ground_point, half_path, interpolate_truth, nearest_object
from .cfar import CFAR, KINDS, Censored
from .clutter_map import ClutterMap, m_of_n
from .footprint import clutter_cell_area, half_power_width
from .frames import Frame, ObjectTruth, detect_frames, opportunity_groups, opportunity_visible
from .plots import extract_plots
from .scoring import opportunity_peaks, pd_at_pfa, roc, roc_from_statistic, score_tables

__all__ = ["CFAR", "KINDS", "Censored", "ClutterMap", "Frame", "ObjectTruth", "associate",
           "clutter_cell_area", "detect_frames", "half_power_width",
           "extract_plots", "ground_point", "nearest_object", "opportunity_groups",
           "half_path", "interpolate_truth", "m_of_n", "opportunity_peaks",
           "opportunity_visible", "pd_at_pfa",
           "roc", "roc_from_statistic", "score_tables"]
