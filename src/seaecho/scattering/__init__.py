"""seaecho.scattering: polarimetric bistatic sea scattering (paper section III).

Plain arrays in, plain arrays out; nothing here knows about meshes or radars.

- the polarisation bases (FSA), local bistatic angles and tilt rotation it uses are
  geometry: :mod:`seaecho.geometry.frames`
- :mod:`.fresnel` Fresnel coefficients of a lossy interface
- :mod:`.kirchhoff`, :mod:`.slopes` Kirchhoff / geometric optics (eq 7), slope densities
- :mod:`.spm` first-order small perturbation model (eqs 8-9)
- :mod:`.twoscale` two-scale model (SPM over tilted facets)
- :mod:`.blend` Kirchhoff / SPM blend (eqs 10-11)
- :mod:`.facet` per-facet sigma_mn and speckled complex amplitudes for the radar stage
- :mod:`.copol` dual co-polarised decomposition (the non-polarised part of a pair)
- :mod:`.models` mean-plane entry point (``seaecho sigma``)

Theory, equations and sources: ``docs/scattering.md``.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from .facet import (
    FacetTerms,
    bragg_vectors,
    facet_amplitudes,
    facet_sigma,
    facet_terms,
    hhvv_coherence,
    speckle_amplitudes,
)
from .models import sea_sigma
from .spectrum_table import BraggSpectrumTable

__all__ = [
    "BraggSpectrumTable",
    "FacetTerms",
    "bragg_vectors",
    "facet_amplitudes",
    "facet_sigma",
    "facet_terms",
    "hhvv_coherence",
    "sea_sigma",
    "speckle_amplitudes",
]
