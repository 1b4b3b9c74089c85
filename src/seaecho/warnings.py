"""Warning classes of seaecho.

Every warning that seaecho emits derives from :class:`SeaechoWarning`, so users can filter
them as one family (``warnings.simplefilter("ignore", SeaechoWarning)``) or one by one.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""


class SeaechoWarning(UserWarning):
    """Base class of all seaecho warnings."""


class SamplingWarning(SeaechoWarning):
    """A sea tile or grid does not resolve what it should.

    Raised when the tile is too small to hold the spectral peak wavelength, or when its
    pixels are coarse against the radar wavelength (paper section IV-A).
    """


class ValidityWarning(SeaechoWarning):
    """A physical model is used outside its domain of validity.

    For example the small perturbation model with roughness too large for the radar
    wavenumber, or the Kirchhoff approximation far from the specular direction.
    """


__all__ = ["SamplingWarning", "SeaechoWarning", "ValidityWarning"]
