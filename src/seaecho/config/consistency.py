"""Checks across sections of a scene file, run when the scene is validated.

A single section's model cannot see its neighbours: the channels of ``[radar]`` are
only meaningful with the polarisation bases of ``[transmitter.antenna]`` and
``[receiver.antenna]``; an object that follows the ship needs a ``[ship]``; the fetch and
the depth of ``[sea]`` must suit the waves of its wind. Each check
raises ``ValueError`` with a message that starts with the field it names
(``[radar].channels = ...``), which the loader prints as it is.
"""

from __future__ import annotations

import numpy as np

from .base import short_repr
from .radar import PORTS


def allowed_channels(scene) -> list[str]:
    """Channel names a scene's antennas have: receive port then transmit port.

    The receiver's basis is the transmitter's for a monostatic scene (no ``[receiver]``).
    """
    tx = scene.transmitter.antenna.basis
    rx = (scene.receiver or scene.transmitter).antenna.basis
    return [m + n for m in PORTS[rx] for n in PORTS[tx]]


def check_channels(scene) -> None:
    """``[radar].channels`` must be ports of the antennas' bases (upper case, e.g. HV)."""
    if scene.radar is None or scene.transmitter is None:
        return
    allowed = allowed_channels(scene)
    bad = [c for c in scene.radar.channels if c not in allowed]
    if bad:
        tx = scene.transmitter.antenna.basis
        rx = (scene.receiver or scene.transmitter).antenna.basis
        raise ValueError(
            f"[radar].channels = {short_repr(scene.radar.channels)}: "
            f"channel '{short_repr(bad[0])[1:-1]}' is not one of these antennas; a channel is a "
            f"receive port of the receiver's '{rx}' basis followed by a transmit port of "
            f"the transmitter's '{tx}' basis: allowed {', '.join(allowed)}")


def check_objects(scene) -> None:
    """``[[objects]]``: unique names; ``follow_ship`` needs a ``[ship]``."""
    seen: set[str] = set()
    for i, obj in enumerate(scene.objects):
        if obj.name in seen:
            raise ValueError(f"[[objects]] #{i}: name = {short_repr(obj.name)} is used by "
                             "an earlier object; names must be unique")
        seen.add(obj.name)
        if obj.follow_ship and scene.ship is None:
            raise ValueError(f"[[objects]] #{i} ({obj.name}): follow_ship = true needs a "
                             "[ship] section")


#: McCowan's limit on the height of a wave in water of depth d: H <= 0.78 d.
BREAKING_RATIO = 0.78


def significant_height(sea) -> float:
    """Significant wave height H_s = 4 sqrt(m0) of a ``[sea]`` section's spectrum [m]
    (m0 its integral over 0 < K < 1e4 rad/m)."""
    import warnings

    from ..ocean.spectra import DirectionalSpectrum
    from ..ocean.twoscale import height_variance

    with warnings.catch_warnings():  # validity warnings come with the run, not here
        warnings.simplefilter("ignore")
        spectrum = DirectionalSpectrum.from_sea_config(sea)
        return 4.0 * height_variance(spectrum, 0.0, 1.0e4) ** 0.5


def check_depth(scene) -> None:
    """``[sea].depth_m`` must hold the sea's waves: d >= H_s / 0.78.

    Shallower, the waves of the spectrum would break (McCowan 1894: a wave of height H
    breaks in water of depth d < H / 0.78), so linear waves on finite depth (paper eq 15)
    do not describe them; the limit also keeps k d from underflowing (a depth of 1e-300 m
    gave NaN wave velocities).

    References
    ----------
    J. McCowan, "On the highest wave of permanent type", Philosophical Magazine 38(5),
    351-358, 1894.
    """
    depth = scene.sea.depth_m
    if depth is None:
        return
    h_s = significant_height(scene.sea)
    if depth < h_s / BREAKING_RATIO:
        raise ValueError(
            f"[sea].depth_m = {depth:g}: shallower than this sea's waves allow, "
            f"H_s / 0.78 = {h_s / BREAKING_RATIO:.3g} m (H_s = {h_s:.3g} m, significant "
            "height of the spectrum; waves break where H > 0.78 d, McCowan 1894)")


#: Inverse wave age U10 / c_p of the fetch laws' seas: 0.84 fully developed to 5 young
#: (Elfouhaily et al. 1997: 0.84 fully developed, about 1 mature, 2 to 5 young).
OMEGA_RANGE = (0.84, 5.0)
#: Elfouhaily's fetch law Omega_c = 0.84 tanh((X / X0)^0.4)^-0.75 reaches 5 at this
#: dimensionless fetch X = g F / U10^2 (X0 = 2.2e4); it saturates at 0.84 for long fetch.
MIN_DIMENSIONLESS_FETCH = 2.2e4 * float(np.arctanh((0.84 / 5.0) ** (4.0 / 3.0))) ** 2.5


def fetch_range(sea) -> tuple[float, float]:
    """Fetches [m] whose sea the ``[sea]`` spectrum's fetch law describes at its wind.

    JONSWAP's peak law U10 omega_p / g = 22 X^(-1/3) (Hasselmann et al. 1973) and
    Elfouhaily's fetch law must give an inverse wave age within :data:`OMEGA_RANGE`:
    younger than 5 is beyond the fitted seas; JONSWAP's law older than 0.84 overshoots
    the fully developed sea (its energy keeps growing with fetch: H_s = 26 m at 19 m/s for
    X = 1e5, where Pierson-Moskowitz gives 7.7 m).
    """
    from ..constants import G
    from ..ocean.spectra import u10_from_u19_5

    u10 = float(u10_from_u19_5(sea.wind_speed_m_s))
    scale = u10**2 / G  # F = X U10^2 / g
    if sea.spectrum == "jonswap":
        lo, hi = OMEGA_RANGE
        return (22.0 / hi) ** 3 * scale, (22.0 / lo) ** 3 * scale
    return MIN_DIMENSIONLESS_FETCH * scale, float("inf")


def check_fetch(scene) -> None:
    """``[sea].fetch_m`` within :func:`fetch_range` (a fetch of 1e-300 m divided by zero;
    a fetch of 20,000 km gave JONSWAP waves of 37 m at 19 m/s).

    References
    ----------
    K. Hasselmann et al., "Measurements of wind-wave growth and swell decay during the
    Joint North Sea Wave Project (JONSWAP)", Dtsch. Hydrogr. Z. A8(12), 1973.
    T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified directional
    spectrum for long and short wind-driven waves", J. Geophys. Res. 102(C7),
    15781-15796, 1997.
    """
    sea = scene.sea
    if sea.fetch_m is None or sea.spectrum == "pierson-moskowitz":
        return
    lo, hi = fetch_range(sea)
    if not lo <= sea.fetch_m <= hi:
        span = f"[{lo:.3g}, {hi:.3g}]" if np.isfinite(hi) else f">= {lo:.3g}"
        raise ValueError(
            f"[sea].fetch_m = {sea.fetch_m:g}: outside the fetches the {sea.spectrum} "
            f"fetch law describes at U19.5 = {sea.wind_speed_m_s:g} m/s, {span} m (inverse "
            "wave age from 5, a young sea, to 0.84, fully developed: Elfouhaily et al. "
            "1997); for a fully developed sea use 'pierson-moskowitz', or 'elfouhaily' "
            "without fetch_m")


def check_scene(scene) -> None:
    """Every check of this module (called by :class:`~seaecho.config.scene.Scene`)."""
    check_channels(scene)
    check_objects(scene)
    check_fetch(scene)
    check_depth(scene)


__all__ = ["BREAKING_RATIO", "MIN_DIMENSIONLESS_FETCH", "OMEGA_RANGE", "allowed_channels",
           "check_channels", "check_depth", "check_fetch", "check_objects", "check_scene",
           "fetch_range", "significant_height"]
