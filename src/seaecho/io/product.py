"""The raw product contract: what a processor reads from a ``seaecho run`` dataset.

A raw dataset carries, under the attribute ``product_version`` (:data:`PRODUCT_VERSION`),
everything an image processor needs, as plain variables and attributes (docs/products.md):
the waveform and sampling, the calibration constant (transmit power), the tracks and
antenna axes per pulse, and each antenna's gain pattern as its aperture parameters
(``tx_antenna_*``, ``rx_antenna_*``: pattern, aperture width and height, illumination,
Taylor design; a multistatic run has one ``rx_antenna_*`` per receiver). A processor never
needs the scene (``scene_json`` is a record of how the file was made, not the contract):
a file whose stored scene another seaecho version cannot parse still focuses, as does a
file seaecho did not write, provided it follows the contract.

The antenna's pattern is the gain G(d_local) of :class:`seaecho.radar.antennas.Antenna`
(eqs A1-A4 of ``radar.antennas``); this module only writes its parameters and rebuilds it.
"""

from __future__ import annotations

import numpy as np

from ..conventions import PORTS
from ..radar.antennas import ILLUMINATIONS, Antenna

#: Version of the raw product contract. Readers refuse any other (docs/products.md).
PRODUCT_VERSION = 1
#: Antenna patterns, in the order of their codes (``flag_values`` 0, 1, ...).
PATTERNS = ("rectangular", "isotropic", "dipole", "hw_dipole", "tr38901")
#: Polarisation bases, in the order of their codes.
BASES = tuple(PORTS)


def _flags(names: tuple[str, ...], long_name: str) -> dict:
    return {"long_name": long_name, "flag_values": np.arange(len(names), dtype=np.int8),
            "flag_meanings": " ".join(names)}


def antenna_variables(prefix: str, antenna: Antenna) -> dict:
    """The product variables of one antenna, ``<prefix>_antenna_*`` (0-d), as xarray takes
    them: pattern, aperture width and height [m] (0 when the pattern is not an aperture),
    illumination, Taylor sidelobe level [dB] and nbar, port basis."""
    if antenna.pattern not in PATTERNS:
        raise ValueError(f"pattern = {antenna.pattern!r}: not implemented yet in the raw "
                         f"product (version {PRODUCT_VERSION} holds {', '.join(PATTERNS)})")
    aperture = antenna.pattern == "rectangular"
    p = f"{prefix}_antenna_"
    return {
        p + "pattern": ((), np.int8(PATTERNS.index(antenna.pattern)),
                        _flags(PATTERNS, "gain pattern (radar.antennas.Antenna)")),
        p + "width_m": ((), float(antenna.width) if aperture else 0.0, {
            "units": "m", "long_name": "aperture width, along the antenna's width axis "
            "(0: not an aperture)"}),
        p + "height_m": ((), float(antenna.height) if aperture else 0.0, {
            "units": "m", "long_name": "aperture height, along the antenna's height axis "
            "(0: not an aperture)"}),
        p + "illumination": ((), np.int8(ILLUMINATIONS.index(antenna.illumination)),
                             _flags(ILLUMINATIONS, "aperture illumination along the width")),
        p + "taylor_sidelobe_db": ((), float(antenna.taylor_sidelobe_db), {
            "units": "dB", "long_name": "Taylor illumination's design sidelobe level"}),
        p + "taylor_nbar": ((), np.int16(antenna.taylor_nbar), {
            "units": "1", "long_name": "Taylor illumination's nbar"}),
        p + "basis": ((), np.int8(BASES.index(antenna.basis)),
                      _flags(BASES, "polarisation basis of the ports")),
    }


def _code(ds, name: str, names: tuple[str, ...]) -> str:
    if name not in ds.variables:
        raise ValueError(f"the raw product has no {name} (docs/products.md)")
    code = int(np.asarray(ds[name].values))
    if not 0 <= code < len(names):
        raise ValueError(f"{name} = {code}: allowed 0 .. {len(names) - 1} "
                         f"({', '.join(names)})")
    return names[code]


def _value(ds, name: str) -> float:
    if name not in ds.variables:
        raise ValueError(f"the raw product has no {name} (docs/products.md)")
    return float(np.asarray(ds[name].values))


def read_antenna(ds, prefix: str, wavelength_m: float) -> Antenna:
    """The antenna ``<prefix>_antenna_*`` of a raw product at ``wavelength_m`` [m].

    Raises
    ------
    ValueError
        A variable missing or out of its range (named, with the value and what is
        allowed).
    """
    p = f"{prefix}_antenna_"
    pattern = _code(ds, p + "pattern", PATTERNS)
    width = height = None
    if pattern == "rectangular":
        width, height = _value(ds, p + "width_m"), _value(ds, p + "height_m")
        for name, v in ((p + "width_m", width), (p + "height_m", height)):
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"{name} = {v} m: a rectangular aperture needs a "
                                 "finite size > 0")
    nbar = _value(ds, p + "taylor_nbar")
    if not (nbar >= 1 and nbar == int(nbar)):
        raise ValueError(f"{p}taylor_nbar = {nbar}: allowed an integer >= 1")
    sidelobe = _value(ds, p + "taylor_sidelobe_db")
    if not np.isfinite(sidelobe):
        raise ValueError(f"{p}taylor_sidelobe_db = {sidelobe} dB: must be finite")
    return Antenna(pattern, float(wavelength_m), width, height,
                   _code(ds, p + "basis", BASES), None,
                   _code(ds, p + "illumination", ILLUMINATIONS), sidelobe, int(nbar))


def check_product_version(attrs, source: str = "the dataset") -> None:
    """Refuse a dataset without ``product_version`` or with another version than
    :data:`PRODUCT_VERSION` (ValueError naming the value and the one this seaecho reads)."""
    if "product_version" not in attrs:
        raise ValueError(f"{source} has no product_version attribute: written before the "
                         f"raw product contract (version {PRODUCT_VERSION}) or not a raw "
                         "run; run `seaecho run` again with this seaecho")
    v = attrs["product_version"]
    v = v.item() if isinstance(v, np.generic) else v
    try:
        same = int(v) == PRODUCT_VERSION and float(v) == PRODUCT_VERSION
    except (TypeError, ValueError):
        same = False
    if not same:
        raise ValueError(f"product_version = {v!r}: this seaecho reads raw "
                         f"products of version {PRODUCT_VERSION} only (docs/products.md); "
                         "focus it with the seaecho version that wrote it, or run "
                         "`seaecho run` again")


__all__ = ["BASES", "PATTERNS", "PRODUCT_VERSION", "antenna_variables",
           "check_product_version", "read_antenna"]
