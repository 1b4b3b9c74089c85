"""Peak resident memory of a benchmark's process, the number each benchmark prints with
its load.
"""

from __future__ import annotations

import resource
from pathlib import Path


def peak_rss_mb() -> float:
    """Peak resident memory of this program [MiB]: ``VmHWM`` of ``/proc/self/status``, the
    high-water mark of its own memory (``ru_maxrss`` would also hold the peak of the
    process that started it, which Linux carries over ``exec``: a benchmark started by a
    large pytest process read that), else ``ru_maxrss`` where there is no ``/proc``."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                return float(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
