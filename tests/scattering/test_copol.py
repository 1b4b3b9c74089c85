"""Dual co-polarised decomposition (eq CP3, Kudryavtsev et al. 2013) against its limiting
cases and against seaecho's own two-scale + breaking model, whose non-polarised part is
known exactly (eq BR1: ``q sigma_wb``, the same in HH and VV at backscatter, eq BR6)."""

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.ocean.seawater import sea_water_permittivity
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.wind import u10_from_u19_5, u19_5_from_u10
from seaecho.scattering.breaking import breaking_sigma_mean_plane
from seaecho.scattering.copol import non_polarised_component
from seaecho.scattering.models import sea_sigma


def test_limits():
    """Equal co-pol levels are all non-polarised; a pair in the Bragg ratio has none; with
    no Bragg HH (p = 0) the whole HH is non-polarised; the two parts add up to VV."""
    np_part, reg = non_polarised_component(2e-3, 2e-3, 0.05)
    assert np_part == pytest.approx(2e-3, rel=1e-12) and reg == pytest.approx(0.0, abs=1e-18)
    np_part, reg = non_polarised_component(1e-2, 0.05 * 1e-2, 0.05)
    assert np_part == pytest.approx(0.0, abs=1e-15) and reg == pytest.approx(1e-2, rel=1e-12)
    np_part, reg = non_polarised_component(1e-2, 1e-4, 0.0)
    assert np_part == pytest.approx(1e-4, rel=1e-12)
    assert np_part + reg == pytest.approx(1e-2, rel=1e-12)


def test_more_polarised_than_bragg_gives_negative_np():
    """VV/HH above 1/p has no non-negative non-polarised part: CP3 says so by its sign."""
    np_part, _ = non_polarised_component(1e-2, 1e-4, 0.05)
    assert np_part < 0.0


@pytest.mark.parametrize(("field", "args"), [
    ("bragg_ratio", (1e-2, 1e-3, 1.0)), ("bragg_ratio", (1e-2, 1e-3, -0.1)),
    ("sigma_vv", (-1e-2, 1e-3, 0.1)), ("sigma_hh", (1e-2, np.nan, 0.1))])
def test_bad_input(field, args):
    with pytest.raises(ValueError, match=field):
        non_polarised_component(*args)


@pytest.mark.parametrize("grazing_deg", [5.0, 20.0, 30.0])
@pytest.mark.parametrize("u10", [4.5, 12.5])
def test_recovers_the_breaking_part_of_two_scale_plus_breaking(u10, grazing_deg):
    """Two independent routes to the same number: CP3 applied to seaecho's two-scale +
    breaking NRCS (monostatic, upwind, 9.3 GHz) with the two-scale model's own HH/VV returns
    eq BR1's ``q sigma_wb`` to 1e-9 relative, and the regular VV ``(1 - q) sigma_vv``."""
    f = 9.3e9
    spec = DirectionalSpectrum(spectrum="romeiser", u19_5=float(u19_5_from_u10(u10)))
    eps = sea_water_permittivity(f, 20.0, 35.0)
    t = np.radians(90.0 - grazing_deg)
    total = sea_sigma("two-scale+breaking", t, np.pi, t, 0.0, f, spec, eps)
    regular = sea_sigma("two-scale", t, np.pi, t, 0.0, f, spec, eps)
    s_wb, q = breaking_sigma_mean_plane(t, np.pi, t, 0.0, float(u10_from_u19_5(spec.u19_5)),
                                        2.0 * np.pi * f / C0)
    np_part, reg_vv = non_polarised_component(total[3], total[0], regular[0] / regular[3])
    assert s_wb[0] == pytest.approx(s_wb[3], rel=1e-12)  # eq BR6 at backscatter
    assert np_part == pytest.approx(q * s_wb[3], rel=1e-9)
    assert reg_vv == pytest.approx((1.0 - q) * regular[3], rel=1e-9)
