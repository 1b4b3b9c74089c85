"""Ground truth of a run, pulse by pulse: where every ship and point target is, how it
moves, the RCS it presents, whether the radar can see it and in which range cell.

For each pulse p (emission time t_p) and object o (the ships of ``[ship]`` /
``[[ships]]``, then the ``[[targets]]``):

- position (x, y, z) [m]: a ship's hull centre (midship, on the waterline z = 0) on its
  course or route (eqs W1, W18 of :mod:`seaecho.wake.ship`); a target's p0 + v t_p;
- velocity [m/s] and heading (course over ground, counter-clockwise from +x) [rad]; a
  target at rest has heading 0;
- RCS per polarisation HH, HV, VH, VV [m^2]: a target's |s_mn|^2 times its Swerling
  factor of that pulse (:mod:`seaecho.targets.swerling`); a ship's hull RCS where its
  hull echoes (the apparent RCS of the ray-traced hull, sea multipath included,
  ``hull_rcs``), else 0 with ``rcs_known`` = 0;
- range (r_t + r_r) / 2 [m] at emission (the delay the object's echo has, neglecting
  its motion during the flight) and the range cell: the index along ``fast_time`` of
  the compressed sample nearest that delay, -1 outside the receive window;
- visibility: inside the receive window, above the radio horizon of both antennas,
  not behind the land and not behind a wave crest. The horizon: on a spherical Earth
  (``[propagation] earth = "spherical"``) the straight segments from both antennas to
  the object clear the sphere (:meth:`seaecho.geometry.earth.SphericalEarth.visible`,
  the test the targets' echo uses); on a flat Earth the smooth Earth of effective radius
  k R_e (k = 4/3, standard refraction) still bounds it: ground distance below
  sqrt(2 k R_e h_a) + sqrt(2 k R_e h_o) (eq T2) with h_a the antenna's height and h_o
  the object's (a ship: its waterline, h_o = 0, so a hull "below the horizon" may still
  show its superstructure; a target: its z). The land and the wave crests
  (``Simulation.targets_hidden``: a target's line of sight to either antenna hits a
  ``[[land]]`` triangle, or the sea surface held at the pulse; a ship's waterline point
  is tested against the land only) come in as ``hidden``. ``truth_hidden_reason`` says
  why an object is not visible (the first reason, in the order window, horizon, land,
  waves).

The frame. ``truth_position`` is in the scene's coordinates, those its ``[[targets]]``
and ships are given in: on a spherical Earth, Earth-following (x, y the distance along
the surface from the origin, z the height above the sphere; docs/scanning.md).
``truth_position_cartesian`` is the same point in the simulation's Cartesian frame, the
plane tangent to the sphere at the origin, where the platform tracks (``tx_position``)
are (eq E4 of :mod:`seaecho.geometry.earth`; on a flat Earth the two are equal). The
ranges, range cells and horizon are computed from the Cartesian positions, as the echo
is.

References
----------
.. [1] M. I. Skolnik, *Introduction to Radar Systems*, 3rd ed., McGraw-Hill (2001),
   chapter 8 (the 4/3 Earth radius and the radar horizon d = sqrt(2 k R_e h); section
   and equation numbers not checked here); Federal Standard 1037C (1996), "radio horizon
   range (RHR)": 2.23 (sqrt(h_t) + sqrt(h_r)) NM with the heights in metres, i.e.
   4.12 km sqrt(h [m]) for one end, on the 4/3 Earth (read).
.. [2] B. R. Bean and E. J. Dutton, *Radio Meteorology*, NBS Monograph 92 (1966),
   section 1.3 (the effective Earth radius of a standard atmosphere).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import C0
from ..geometry.earth import EARTH_RADIUS_M, STANDARD_REFRACTION_K, effective_radius, horizon_range


def radio_horizon_m(h_a: ArrayLike, h_o: ArrayLike, radius_m: float | None = None) -> NDArray:
    """Largest ground distance at which heights h_a and h_o [m] see each other over a
    smooth Earth of effective radius ``radius_m`` [m] (default k R_e, k = 4/3): the
    radar horizon of :func:`seaecho.geometry.earth.horizon_range` (eq E2, the sum of
    both ends' tangent distances; FS-1037C, "radio horizon range"), with heights below 0
    counted as 0."""
    radius = effective_radius() if radius_m is None else radius_m
    return horizon_range(np.maximum(np.asarray(h_a, dtype=np.float64), 0.0),
                         np.maximum(np.asarray(h_o, dtype=np.float64), 0.0), radius)


#: ``truth_hidden_reason`` values and their meanings (CF flags).
HIDDEN_REASONS = ("visible", "outside_window", "below_horizon", "behind_land",
                  "behind_waves")


def ground_truth(radar, ships: tuple = (), hull_rcs: dict | None = None,
                 hidden: NDArray | None = None) -> tuple[dict, dict]:
    """The per-pulse ground truth of a run (module docstring) as xarray variables.

    Parameters
    ----------
    radar : seaecho.radar.system.RadarSystem
        Pulses, platforms, receive window, targets of its model.
    ships : tuple of seaecho.wake.Ship
        The scene's ships (their ``name`` labels them).
    hull_rcs : dict, optional
        ``{ship name: (P, 4) array}`` [m^2]: hull RCS of the ships whose hull echoes.
    hidden : (2, P, O) bool array, optional
        Objects (ships then targets) hidden behind the land [0] and behind a wave crest
        [1] at each pulse (``Simulation.truth_hidden``); default none.

    Returns
    -------
    data, coords : dict
        ``truth_*`` variables (pulse, object, ...) and the ``object`` coordinates, as
        xarray takes them; empty when there is no object.
    """
    hull_rcs = hull_rcs or {}
    n = radar.n_pulses
    pulses = np.arange(n)
    t = radar.emission_time(pulses)
    targets = radar.model.targets
    n_t = 0 if targets is None else len(targets)
    n_s = len(ships)
    if n_s + n_t == 0:
        return {}, {}
    pos = np.zeros((n, n_s + n_t, 3))
    vel = np.zeros((n, n_s + n_t, 3))
    heading = np.zeros((n, n_s + n_t))
    rcs = np.zeros((n, n_s + n_t, 4))
    known = np.zeros(n_s + n_t, dtype=np.int8)
    names, kinds = [], []
    for i, s in enumerate(ships):
        pos[:, i, :2] = s.position(t)
        vel[:, i, :2] = s.velocity_at(t)
        heading[:, i] = s.heading_at(t)
        name = s.name or f"ship{i}"
        if name in hull_rcs:
            rcs[:, i] = hull_rcs[name]
            known[i] = 1
        names.append(name)
        kinds.append("ship")
    if n_t:
        sl = slice(n_s, n_s + n_t)
        pos[:, sl] = targets.positions[None] + t[:, None, None] * targets.velocities[None]
        vel[:, sl] = targets.velocities[None]
        heading[:, sl] = np.arctan2(targets.velocities[:, 1], targets.velocities[:, 0])[None]
        power = np.abs(targets.scattering.reshape(-1, 4)) ** 2
        rcs[:, sl] = power[None] * targets.rcs_factor(pulses)[..., None]
        known[sl] = 1
        names += list(targets.names)
        kinds += ["target"] * n_t
    p_tx = radar.tx.state(t).position[:, None, :]
    p_rx = radar.rx.state(t).position[:, None, :]
    earth = getattr(radar.model, "earth", None)  # the scene's sphere, else k = 4/3
    cart = pos if earth is None else earth.position(pos)  # the echo's frame (eq E4)
    r_t = np.linalg.norm(cart - p_tx, axis=-1)
    r_r = np.linalg.norm(cart - p_rx, axis=-1)
    rng = 0.5 * (r_t + r_r)
    w = radar.window
    cell = np.rint((2.0 * rng / C0 - w.t0) * w.sampling_rate).astype(np.int64)
    inside = (cell >= 0) & (cell < w.n_samples)
    cell = np.where(inside, cell, -1)
    above = np.ones_like(inside)
    if earth is not None:  # the targets' echo test: segments clear the sphere
        for p in (p_tx, p_rx):
            above &= earth.visible(np.broadcast_to(p, cart.shape), cart)
    else:
        for p in (p_tx, p_rx):
            ground = np.hypot(pos[..., 0] - p[..., 0], pos[..., 1] - p[..., 1])
            above &= ground <= radio_horizon_m(p[..., 2], pos[..., 2], None)
    if hidden is None:
        hidden = np.zeros((2,) + inside.shape, dtype=bool)
    land, waves = np.asarray(hidden[0], dtype=bool), np.asarray(hidden[1], dtype=bool)
    reason = np.select([~inside, ~above, land, waves], [1, 2, 3, 4], 0).astype(np.int8)
    frame = ("scene coordinates: on a spherical Earth x, y along the surface from the "
             "origin and z above the sphere (docs/scanning.md)") if earth is not None else (
             "scene coordinates (flat Earth: the Cartesian frame)")
    obj = ("pulse", "object")
    data = {
        "truth_position": (obj + ("xyz",), pos, {
            "units": "m", "long_name": "object position at emission: a ship's hull centre "
            "on the waterline, a target's point", "frame": frame}),
        "truth_position_cartesian": (obj + ("xyz",), cart, {
            "units": "m", "long_name": "truth_position in the simulation's Cartesian frame "
            "(tangent to the Earth at the origin, that of tx_position; eq E4)"}),
        "truth_velocity": (obj + ("xyz",), vel, {"units": "m s-1"}),
        "truth_heading": (obj, heading, {
            "units": "rad", "long_name": "course over ground, counter-clockwise from +x "
            "(east); 0 for a target at rest"}),
        "truth_rcs": (obj + ("polarisation",), rcs, {
            "units": "m2", "long_name": "RCS presented at this pulse: a target's "
            "|s_mn|^2 times its Swerling factor; a ship's hull RCS where it echoes, else 0 "
            "(truth_rcs_known = 0)"}),
        "truth_rcs_known": (("object",), known, {
            "units": "1", "long_name": "1 where truth_rcs is computed"}),
        "truth_range": (obj, rng, {
            "units": "m", "long_name": "(r_t + r_r) / 2 at emission"}),
        "truth_range_cell": (obj, cell, {
            "units": "1", "long_name": "fast_time index of the sample nearest the object's "
            "delay; -1 outside the receive window"}),
        "truth_in_window": (obj, inside.astype(np.int8), {"units": "1"}),
        "truth_above_horizon": (obj, above.astype(np.int8), {
            "units": "1", "long_name": "above the radio horizon of both antennas (a ship "
            "by its waterline): the segments clear the scene's sphere; on a flat Earth "
            "within the 4/3-Earth horizon"}),
        "truth_behind_land": (obj, land.astype(np.int8), {
            "units": "1", "long_name": "a line of sight to an antenna hits the [[land]]"}),
        "truth_behind_waves": (obj, waves.astype(np.int8), {
            "units": "1", "long_name": "a target's line of sight to an antenna hits the "
            "sea surface held at the pulse (the tile's waves)"}),
        "truth_visible": (obj, (reason == 0).astype(np.int8), {
            "units": "1", "long_name": "in the receive window, above the horizon, not "
            "behind the land or a wave crest"}),
        "truth_hidden_reason": (obj, reason, {
            "units": "1", "long_name": "why the object is not visible (the first reason)",
            "flag_values": np.arange(len(HIDDEN_REASONS), dtype=np.int8),
            "flag_meanings": " ".join(HIDDEN_REASONS)}),
    }
    coords = {"object": ("object", np.array(names)),
              "object_kind": ("object", np.array(kinds))}
    return data, coords


__all__ = ["EARTH_RADIUS_M", "HIDDEN_REASONS", "STANDARD_REFRACTION_K", "ground_truth",
           "radio_horizon_m"]
