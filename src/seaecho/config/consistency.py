"""Checks across sections of a scene file, run when the scene is validated.

A single section's model cannot see its neighbours: the channels of ``[radar]`` are
only meaningful with the polarisation bases of ``[transmitter.antenna]`` and
``[receiver.antenna]``; an object that follows the ship needs a ``[ship]``. (The checks
that need the sea's spectrum, ``[sea]``'s fetch and depth against its waves, are the
builder's: :func:`seaecho.build.check_sea`.) Each check
raises ``ValueError`` with a message that starts with the field it names
(``[radar].channels = ...``), which the loader prints as it is.
"""

from __future__ import annotations

from ..conventions import PORTS
from .base import short_repr


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


def check_land(scene) -> None:
    """``[[land]]``: unique names (among themselves and the ``[[objects]]``, whose meshes
    share the occluders' scene); the land is ray traced (``[tracing] mode``)."""
    taken = {o.name for o in scene.objects}
    for i, land in enumerate(scene.land):
        if land.name in taken:
            raise ValueError(f"[[land]] #{i}: name = {short_repr(land.name)} is used by "
                             "another [[land]] or [[objects]] entry; names must be unique")
        taken.add(land.name)
    if scene.land and scene.tracing.mode != "raytraced":
        raise ValueError(f"[tracing].mode = '{scene.tracing.mode}' with [[land]]: the land "
                         "occludes by ray tracing; use mode = 'raytraced'")


def check_targets(scene) -> None:
    """``[[targets]]``: a ``preset`` needs a ``[radar]`` carrier in a band it has."""
    from .radar import preset_rcs_m2

    for i, g in enumerate(scene.targets):
        if g.preset is None:
            continue
        if scene.radar is None:
            raise ValueError(f"[[targets]] #{i}: preset = '{g.preset}' needs a [radar] "
                             "section (its RCS depends on the carrier band)")
        try:
            preset_rcs_m2(g.preset, scene.radar.carrier_frequency_hz)
        except ValueError as exc:
            raise ValueError(f"[[targets]] #{i}: {exc}") from None


def check_ships(scene) -> None:
    """``[ship]`` or ``[[ships]]``, not both; unique names; an object that follows the
    ship needs a straight course."""
    if scene.ship is not None and scene.ships:
        raise ValueError("[ship] and [[ships]]: give one ship as [ship], or all of them as "
                         "[[ships]] (a [ship] is the same as one [[ships]] entry)")
    names = scene.ship_names()
    for i, n in enumerate(names):
        if n in names[:i]:
            raise ValueError(f"[[ships]] #{i}: name = {short_repr(n)} is used by an earlier "
                             "ship; names must be unique")
    moving = [n for n, s in zip(names, scene.all_ships, strict=True) if s.wave_motion]
    if moving and (scene.radar is None or not scene.radar.sea_clutter):
        raise ValueError(f"[[ships]] {moving[0]}: wave_motion = true needs the sea: [radar] "
                         "sea_clutter = true")
    dynamic = [n for n, s in zip(names, scene.all_ships, strict=True)
               if s.wave_motion and s.wave_response == "dynamic"]
    if dynamic and (any(scene.sea.current_m_s)
                    or scene.sea.wind_drift not in ("none", "auto")):
        raise ValueError(f"[[ships]] {dynamic[0]}: wave_response = 'dynamic' on a sea with "
                         f"[sea] current_m_s = {list(scene.sea.current_m_s)}, wind_drift = "
                         f"'{scene.sea.wind_drift}': not implemented yet (the travelling "
                         "waves of a sea on a current); use wave_response = 'quasi-static' "
                         "or still water")
    if scene.ship is not None and scene.ship.waypoints_m is not None and any(
            o.follow_ship for o in scene.objects):
        raise ValueError("[[objects]] follow_ship = true with a [ship] on waypoints_m: not "
                         "implemented yet (an object follows a straight course only)")
def check_receivers(scene) -> None:
    """``[[receivers]]``: not with ``[receiver]``, unique names, each receiver's channels
    (its own or ``[radar]``'s) ports of its antenna and the transmitter's."""
    if not scene.receivers:
        return
    if scene.receiver is not None:
        raise ValueError(f"[[receivers]] ({len(scene.receivers)} given) and [receiver]: give "
                         "one or the other ([receiver] is the one-receiver shorthand)")
    if scene.scattering.sea_motion == "evolving":
        raise ValueError("[scattering].sea_motion = 'evolving' with [[receivers]]: not "
                         "implemented yet (the Bragg lifetimes depend on each pair's Bragg "
                         "wavenumber); use 'held'")
    seen: set[str] = set()
    for i, r in enumerate(scene.receivers):
        if r.name in seen:
            raise ValueError(f"[[receivers]] #{i}: name = {short_repr(r.name)} is used by an "
                             "earlier receiver; names must be unique")
        seen.add(r.name)
        if scene.transmitter is None:
            continue
        tx = scene.transmitter.antenna.basis
        allowed = [m + n for m in PORTS[r.antenna.basis] for n in PORTS[tx]]
        own = r.channels is not None
        channels = r.channels if own else (scene.radar.channels if scene.radar else ())
        bad = [c for c in channels if c not in allowed]
        if bad:
            where = (f"[[receivers]] #{i} ({r.name}).channels" if own else
                     f"[radar].channels (receiver #{i}, {r.name})")
            raise ValueError(
                f"{where} = {short_repr(channels)}: channel '{short_repr(bad[0])[1:-1]}' is "
                f"not one of these antennas; a channel is a receive port of the receiver's "
                f"'{r.antenna.basis}' basis followed by a transmit port of the "
                f"transmitter's '{tx}' basis: allowed {', '.join(allowed)}")


def check_scene(scene) -> None:
    """Every check of this module (called by :class:`~seaecho.config.scene.Scene`)."""
    check_receivers(scene)
    if not scene.receivers:  # (each receiver's channels checked against its own antenna)
        check_channels(scene)
    check_objects(scene)
    check_land(scene)
    check_targets(scene)
    check_ships(scene)


__all__ = ["allowed_channels", "check_channels", "check_land", "check_objects",
           "check_receivers",
           "check_scene", "check_ships", "check_targets"]
