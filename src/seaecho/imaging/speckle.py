"""Polarimetric products and speckle reduction: Pauli decomposition, multilook, filters.

Pauli decomposition (Cloude & Pottier 1996; Lee & Pottier 2009, section 3.3): the
scattering vector k = (S_hh + S_vv, S_hh - S_vv, S_hv + S_vh) / sqrt 2 whose squared
components are the powers of an odd-bounce (surface), an even-bounce (dihedral) and a
45-degree-dihedral / volume mechanism. The usual RGB composite shows
R = |S_hh - S_vv|^2 / 2, G = |S_hv + S_vh|^2 / 2, B = |S_hh + S_vv|^2 / 2. These are
written in the back-scattering alignment (BSA), where a reciprocal target has
S_hv = S_vh and a sphere S_hh = S_vv. Our channels are in the forward-scattering alignment
(FSA, ``docs/radar.md``), whose receive h axis is the opposite of BSA's:

.. math::

    S^{BSA} = \\begin{pmatrix} -1 & 0 \\\\ 0 & 1 \\end{pmatrix} S^{FSA}                  (S0)

(Ulaby & Elachi 1990, section 1.7; Lee & Pottier 2009, section 3.1), so in FSA a
backscattering sphere has S_hh = -S_vv and a reciprocal target S_hv = -S_vh. The Pauli
powers are computed from eq (S0): R = |S_hh + S_vv|^2 / 2, G = |S_vh - S_hv|^2 / 2,
B = |S_vv - S_hh|^2 / 2 in our (FSA) channels.

Multilook: intensities averaged over blocks of L_y x L_x pixels and decimated; for
independent single-look pixels the equivalent number of looks is L_y L_x (Lee & Pottier
2009, section 4.1). Our pixels are smaller than the resolution, so neighbouring pixels
are correlated and the ENL is lower (the resolution cell holds about A_eff / pixel^2
pixels).

Boxcar filter: the same mean over a sliding n x n window, on the original grid.

Refined Lee filter (Lee 1981; Lee, Grunes & de Grandi 1999 for polarimetric data): in a
7 x 7 window, the means of the nine 3 x 3 sub-windows give the gradients in four
directions; the one of largest magnitude picks an edge direction, and the half of the
window (one of eight edge-aligned masks of 28 pixels) whose sub-window mean is closer to
the centre's is kept. With the local mean m and variance v of the span
(HH + HV + VH + VV powers) in that mask, the minimum-mean-square-error weight

.. math::

    b = \\max\\!\\left(0, \\frac{v - m^2 \\sigma_v^2}{v (1 + \\sigma_v^2)}\\right),\\qquad
    \\hat y = \\bar y + b\\,(y - \\bar y)                                                 (S1)

(sigma_v^2 = 1 / L the speckle variance of L-look intensity) is applied to every channel
with the same mask and weight, which keeps the polarimetric ratios (Lee et al. 1999,
eqs 11-13).

References
----------
.. [1] S. R. Cloude and E. Pottier, "A review of target decomposition theorems in radar
   polarimetry", IEEE Trans. Geosci. Remote Sens. 34(2), 498-518, 1996.
.. [2] J.-S. Lee and E. Pottier, *Polarimetric Radar Imaging: From Basics to
   Applications*, CRC Press, 2009, sections 3.3, 4.1 and 4.4.
.. [3] J.-S. Lee, "Refined filtering of image noise using local statistics", Computer
   Graphics and Image Processing 15(4), 380-389, 1981.
.. [4] J.-S. Lee, M. R. Grunes and G. de Grandi, "Polarimetric SAR speckle filtering and
   its implication for classification", IEEE Trans. Geosci. Remote Sens. 37(5),
   2363-2373, 1999.
.. [5] F. T. Ulaby and C. Elachi (eds.), *Radar Polarimetry for Geoscience
   Applications*, Artech House, 1990, section 1.7.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "PAULI_NAMES",
    "boxcar",
    "edge_masks",
    "multilook",
    "pauli_powers",
    "refined_lee",
    "speckle_filter",
]

#: Names of the Pauli powers, in RGB order.
PAULI_NAMES = ("HH-VV", "HV+VH", "HH+VV")


def pauli_powers(channels: dict[str, NDArray]) -> NDArray[np.float64] | None:
    """Pauli powers (|HH - VV|^2, |HV + VH|^2, |HH + VV|^2) / 2 in BSA, RGB order.

    Parameters
    ----------
    channels : dict
        Complex images by channel name ('HH', 'HV', 'VH', 'VV') in the FSA convention of
        the dataset, same shape; converted to BSA by eq (S0).

    Returns
    -------
    ndarray (3, ...) or None
        None unless the four linear channels are present.
    """
    if not all(c in channels for c in ("HH", "HV", "VH", "VV")):
        return None
    hh, hv, vh, vv = (channels[c] for c in ("HH", "HV", "VH", "VV"))
    hh, hv = -hh, -hv  # eq (S0): FSA -> BSA
    return 0.5 * np.stack([np.abs(hh - vv) ** 2, np.abs(hv + vh) ** 2,
                           np.abs(hh + vv) ** 2])


def multilook(intensity: ArrayLike, looks: tuple[int, int]) -> NDArray[np.float64]:
    """Mean of intensities over blocks of (L_y, L_x) pixels (last two axes), decimated.

    Incomplete blocks at the end of each axis are dropped.
    """
    a = np.asarray(intensity, dtype=float)
    ly, lx = looks
    if ly < 1 or lx < 1:
        raise ValueError(f"looks = {looks}: each must be >= 1")
    ny, nx = a.shape[-2] // ly, a.shape[-1] // lx
    if ny == 0 or nx == 0:
        raise ValueError(f"looks = {looks}: larger than the image {a.shape[-2:]}")
    a = a[..., : ny * ly, : nx * lx]
    return a.reshape(a.shape[:-2] + (ny, ly, nx, lx)).mean(axis=(-3, -1))


def boxcar(intensity: ArrayLike, size: int) -> NDArray[np.float64]:
    """Sliding n x n mean of intensities over the last two axes (reflected edges)."""
    from scipy.ndimage import uniform_filter

    a = np.asarray(intensity, dtype=float)
    sizes = (1,) * (a.ndim - 2) + (size, size)
    return uniform_filter(a, size=sizes, mode="reflect")


def edge_masks() -> NDArray[np.float64]:
    """The eight edge-aligned 7 x 7 masks of the refined Lee filter, shape (8, 7, 7).

    Order: for each gradient direction d (0: vertical edge, 1: 45 deg, 2: horizontal edge,
    3: 135 deg) the two halves 2d (towards the positive side of the gradient) and 2d + 1;
    each holds the 28 pixels of one side including the centre line (Lee 1981, Fig. 2).
    """
    i, j = np.mgrid[-3:4, -3:4]  # i: row (y), j: column (x)
    halves = []
    for side in (j, j - i, i, j + i):  # gradient directions: x, diagonal, y, antidiagonal
        halves.append(side >= 0)
        halves.append(side <= 0)
    masks = np.array(halves, dtype=float)
    # Diagonal halves have 28 pixels with the diagonal; straight halves 28 with the line
    return masks


def _local_stats(a: NDArray, mask: NDArray) -> tuple[NDArray, NDArray]:
    from scipy.ndimage import correlate

    w = mask / mask.sum()
    m = correlate(a, w, mode="reflect")
    v = correlate(a * a, w, mode="reflect") - m * m
    return m, np.maximum(v, 0.0)


def refined_lee(intensities: ArrayLike, looks: float = 1.0) -> NDArray[np.float64]:
    """Refined Lee filter of a stack of intensities (C, ny, nx), eq (S1).

    Parameters
    ----------
    intensities : array_like (C, ny, nx) or (ny, nx)
        Intensities (powers) of the channels [any unit].
    looks : float
        Number of looks L of the input (speckle variance 1/L).

    Returns
    -------
    ndarray, same shape
        Filtered intensities.
    """
    from scipy.ndimage import uniform_filter

    a = np.asarray(intensities, dtype=float)
    single = a.ndim == 2
    if single:
        a = a[None]
    if looks <= 0:
        raise ValueError(f"looks = {looks}: must be > 0")
    # Eq (S1) is the same for intensities of any scale (b is homogeneous of degree 0):
    # the statistics of a / max|a| cannot overflow in their squares, whatever a's unit
    scale = float(np.max(np.abs(a), initial=0.0, where=np.isfinite(a)))
    scale = scale if 0.0 < scale < np.inf else 1.0
    a = a / scale
    span = a.sum(axis=0)
    # Means of the nine 3 x 3 sub-windows of each 7 x 7 window (offsets -2, 0, +2)
    m3 = uniform_filter(span, size=3, mode="reflect")
    pad = np.pad(m3, 2, mode="reflect")
    ny, nx = span.shape

    def sub(di, dj):
        return pad[2 + di: 2 + di + ny, 2 + dj: 2 + dj + nx]

    s = {(di, dj): sub(di, dj) for di in (-2, 0, 2) for dj in (-2, 0, 2)}
    # Gradients of the sub-window means in four directions (Lee 1981, eq 5 masks)
    g = np.stack([
        (s[-2, 2] + s[0, 2] + s[2, 2]) - (s[-2, -2] + s[0, -2] + s[2, -2]),  # along x
        (s[-2, 2] + s[0, 2] + s[-2, 0]) - (s[2, -2] + s[0, -2] + s[2, 0]),  # diagonal
        (s[2, -2] + s[2, 0] + s[2, 2]) - (s[-2, -2] + s[-2, 0] + s[-2, 2]),  # along y
        (s[2, 2] + s[0, 2] + s[2, 0]) - (s[-2, -2] + s[0, -2] + s[-2, 0]),  # antidiagonal
    ])
    direction = np.argmax(np.abs(g), axis=0)
    # The half whose outer sub-window mean is closer to the centre's
    c = s[0, 0]
    outer = [(s[0, 2], s[0, -2]), (s[-2, 2], s[2, -2]), (s[2, 0], s[-2, 0]),
             (s[2, 2], s[-2, -2])]
    choice = np.zeros(span.shape, dtype=int)
    for d, (pos, neg) in enumerate(outer):
        here = direction == d
        closer_pos = np.abs(pos - c) <= np.abs(neg - c)
        choice[here] = np.where(closer_pos[here], 2 * d, 2 * d + 1)
    masks = edge_masks()
    sv2 = 1.0 / looks
    mean_span = np.zeros(span.shape)
    var_span = np.zeros(span.shape)
    means = np.zeros(a.shape)
    for k, mask in enumerate(masks):  # eight masks, each a vectorised correlation
        sel = choice == k
        if not sel.any():
            continue
        m, v = _local_stats(span, mask)
        mean_span[sel], var_span[sel] = m[sel], v[sel]
        for ch in range(a.shape[0]):
            mc, _ = _local_stats(a[ch], mask)
            means[ch][sel] = mc[sel]
    # Eq (S1): MMSE weight from the span, applied to every channel
    with np.errstate(divide="ignore", invalid="ignore"):
        b = (var_span - mean_span**2 * sv2) / (var_span * (1.0 + sv2))
    b = np.clip(np.nan_to_num(b, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0)
    out = (means + b[None] * (a - means)) * scale
    return out[0] if single else out


def speckle_filter(intensities: ArrayLike, kind: str, size: int = 7, looks: float = 1.0
                   ) -> NDArray[np.float64]:
    """Filter intensities (C, ny, nx) by 'none', 'boxcar' or 'refined-lee'."""
    if kind == "none":
        return np.asarray(intensities, dtype=float)
    if kind == "boxcar":
        return boxcar(intensities, size)
    if kind == "refined-lee":
        return refined_lee(intensities, looks)
    raise ValueError(f"speckle filter = {kind!r}: allowed 'none', 'boxcar', 'refined-lee'")
