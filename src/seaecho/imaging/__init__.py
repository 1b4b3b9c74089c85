"""seaecho.imaging: SAR image formation (time-domain backprojection), calibration,
polarimetric products, speckle filters, image quality and the paper's image metrics.

Entry point: :func:`seaecho.imaging.focus.focus` (``seaecho image``). Theory:
``docs/imaging.md``.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""
