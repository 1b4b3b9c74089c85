"""The radar stage's rectangular aperture (eq A1 of :mod:`seaecho.radar.antennas`) as a
Sionna RT antenna pattern.

Only :mod:`seaecho.tracing` imports mitsuba and sionna (docs/design.md), so the
Sionna form of the antenna lives here. The tracing stage comes before the radar stage and
does not import it: the caller passes the normalisation of eq A1, the integral of |F|^2
over the sphere (:func:`seaecho.radar.antennas.aperture_radiated_power`).

References
----------
.. [1] Balanis, C. A. (2016). *Antenna Theory: Analysis and Design*, 4th ed., Wiley,
   sec. 12.5 (uniform rectangular aperture), as in :mod:`seaecho.radar.antennas`.
"""

from __future__ import annotations

import numpy as np

from .variant import mitsuba_modules

__all__ = ["register_sionna_aperture", "sionna_aperture_v_pattern"]


def sionna_aperture_v_pattern(width: float, height: float, wavelength: float,
                              radiated_power: float, variant: str | None = None):
    """A Dr.Jit-traceable vertically polarised pattern ``f(theta, phi) -> C_theta`` of eq (A1).

    For ``sionna.rt.antenna_pattern.PolarizedAntennaPattern(v_pattern=...)``: Sionna's
    antenna frame has its boresight on +x, theta from +z, phi from +x, which is the frame
    of :mod:`seaecho.radar.antennas`. The amplitude is sqrt(G), G normalised as eq (A1).

    Parameters
    ----------
    width, height : float
        Aperture sides along the antenna's y and z axes [m].
    wavelength : float
        Wavelength [m].
    radiated_power : float
        Integral of |F|^2 over the sphere [sr] for eq (A1)'s normalisation
        (:func:`seaecho.radar.antennas.aperture_radiated_power`).
    variant : str, optional
        Mitsuba variant (:func:`seaecho.tracing.variant.set_variant`; default LLVM).
    """
    if not radiated_power > 0:
        raise ValueError(f"radiated_power = {radiated_power} sr: must be > 0")
    dr, mi, _ = mitsuba_modules(variant)
    scale = float(np.sqrt(4.0 * np.pi / radiated_power))
    ka = float(np.pi * width / wavelength)
    kb = float(np.pi * height / wavelength)

    def sinc(x):
        return dr.select(dr.abs(x) < 1e-6, 1.0, dr.sin(x) / dr.select(dr.abs(x) < 1e-6, 1.0, x))

    def v_pattern(theta, phi):
        st, ct = dr.sin(theta), dr.cos(theta)
        sp, cp = dr.sin(phi), dr.cos(phi)
        cos_b = st * cp  # cosine from the boresight (+x)
        # Eq (A1) in Sionna's angles: u = sin(theta) sin(phi), v = cos(theta)
        amp = scale * 0.5 * (1.0 + cos_b) * sinc(ka * st * sp) * sinc(kb * ct)
        return mi.Complex2f(dr.abs(amp), 0)

    return v_pattern


def register_sionna_aperture(width: float, height: float, wavelength: float,
                             radiated_power: float, name: str | None = None,
                             variant: str | None = None) -> str:
    """Register eq (A1) as a Sionna RT antenna pattern; returns its registered name.

    Use the name as ``PlanarArray(pattern=name, polarization="VH", ...)``.

    Parameters
    ----------
    width, height : float
        Aperture sides [m].
    wavelength : float
        Wavelength [m].
    radiated_power : float
        Integral of |F|^2 over the sphere [sr] (eq A1's normalisation).
    name : str, optional
        Registered name (default from the dimensions).
    variant : str, optional
        Mitsuba variant, set before ``sionna.rt`` is imported.
    """
    v_pattern = sionna_aperture_v_pattern(width, height, wavelength, radiated_power,
                                          variant)
    from sionna.rt.antenna_pattern import PolarizedAntennaPattern, register_antenna_pattern

    if name is None:
        name = f"seaecho_rect_{width:g}x{height:g}m_{wavelength:g}m"

    def factory(*, polarization: str, polarization_model: str = "tr38901_2"):
        return PolarizedAntennaPattern(v_pattern=v_pattern, polarization=polarization,
                                       polarization_model=polarization_model)

    register_antenna_pattern(name, factory)
    return name
