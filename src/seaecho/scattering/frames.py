"""Former home of :mod:`seaecho.geometry.frames` (polarisation bases, local frames).

Frames are geometry: the module moved to ``seaecho.geometry.frames`` so that the geometry
stage never imports the scattering stage. This alias keeps ``seaecho.scattering.frames``
importable for code not yet updated; new code imports ``seaecho.geometry.frames``.
"""

import sys

from ..geometry import frames as _frames

sys.modules[__name__] = _frames
