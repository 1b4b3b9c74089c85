"""The sea's synthesis in kept scratch arrays gives the bytes of fresh arrays.

``SeaSurface.fields`` writes its spectra into scratch arrays taken from a pool (no pages
to fault in at every time); the surface that keeps its travelling waves
(``share_travelling``) computes them in fresh arrays by the expressions of eq 12' and
15. Both must give the same bytes, in either precision, on a current, and from several
threads at once (the next pulse's sea is computed ahead on a thread).
"""

import hashlib
import threading

import numpy as np
import pytest

from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface

SPEC = DirectionalSpectrum("pierson-moskowitz", "longuet-higgins", u19_5=7.0, s=2.0)


def _surface(**kw) -> SeaSurface:
    return SeaSurface(SPEC, (64.0, 48.0), (128, 96), np.random.default_rng(3), **kw)


def _bytes(f) -> list[str]:
    return [hashlib.sha256(a.tobytes()).hexdigest()
            for a in (f.elevation, f.slope_x, f.slope_y, f.velocity)]


@pytest.mark.parametrize("precision", ["single", "double"])
@pytest.mark.parametrize("current", [(0.0, 0.0), (0.4, -0.3)])
def test_scratch_fields_equal_fresh_fields(precision, current):
    scratch, fresh = _surface(precision=precision, current=current), _surface(
        precision=precision, current=current)
    fresh.share_travelling = True  # eq 12' in fresh arrays (SeaSurface._travelling_at)
    for t in (0.0, 0.37, 12.5):
        assert _bytes(scratch.fields(t)) == _bytes(fresh.fields(t))
    assert _bytes(scratch.fields(1.0)) != _bytes(scratch.fields(2.0))


def test_scratch_fields_from_several_threads():
    s = _surface()
    times = (1.0, 2.0, 3.0, 4.0, 5.0)
    out: dict = {}
    threads = [threading.Thread(target=lambda t=t: out.__setitem__(t, s.fields(t)))
               for t in times]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for t in times:
        assert _bytes(out[t]) == _bytes(s.fields(t))


@pytest.mark.parametrize("precision", ["single", "double"])
def test_fields_without_slopes_and_slopes_later(precision):
    # three transforms instead of five, and the two slopes later: the same bytes
    s = _surface(precision=precision)
    full = s.fields(0.37)
    part = s.fields(0.37, slopes=False)
    assert part.slope_x is None and part.slope_y is None
    for a, b in ((full.elevation, part.elevation), (full.velocity, part.velocity)):
        assert a.tobytes() == b.tobytes()
    sx, sy = s.slopes(0.37)
    assert sx.tobytes() == full.slope_x.tobytes() and sy.tobytes() == full.slope_y.tobytes()
