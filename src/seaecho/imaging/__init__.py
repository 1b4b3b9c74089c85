"""seaecho.imaging: SAR image formation (time-domain backprojection), calibration,
polarimetric products, speckle filters, image quality and the paper's image metrics.

Entry point: :func:`seaecho.imaging.focus.focus` (``seaecho image``). Theory:
``docs/imaging.md``.
"""
