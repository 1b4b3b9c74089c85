"""Scattering centres: what the hull-echo stage hands to the radar kernel.

The shooting-and-bouncing-rays trace (:mod:`seaecho.tracing.sbr`) gives, for every ray
tube and every hit along it, a contribution to the field at the receiver:

.. math::
    \\frac{\\mathbf E_{rx}}{E_0} = \\mathsf a_i\\,\\frac{e^{-jkL_i}}{\\ell_i}
    \\qquad \\text{(C1)}

with ``L_i`` the unfolded length of its path (transmitter, or its image in the sea, to the
hull, along the bounces, to the receiver or its image), ``ell_i`` the product of the
spherical spreading distances (source to the last hit, times last hit to the observer)
and ``a_i`` a 2x2 amplitude [m] in the FSA bases of the departure and arrival
directions. The radar kernel (:meth:`seaecho.radar.system.RadarSystem.scatterer_echo`)
takes point scatterers: a position ``c`` and a 2x2 ``S`` whose received field is
``S exp(-jk (r_t + r_r)) / (r_t r_r)`` with ``r_t = |c - T|``, ``r_r = |c - R|``
(``|S|^2`` is an RCS, as the sea facets' eq P4 of :mod:`seaecho.scattering.facet`).

Delay. A contribution is filed at a *delay-equivalent* position ``c*``: the point nearest
to its last hit on the ellipsoid ``|c - T| + |c - R| = L_i`` (:func:`equivalent_positions`,
Newton steps along the gradient ``u_t + u_r`` of the bistatic range). The kernel's delay
of ``c*`` is then the path's: a trihedral's triple bounce appears at its apex's range, a
sea-reflected leg at its longer range (seen monostatically at grazing angle psi, a hull
point at height h echoes by the sea-hull-sea path about 2 h sin psi further in range:
the range of its image -h).

Clustering. Contributions are summed coherently in cubic cells of side ``delta`` on a
grid anchored at the hull's reference point (one set of cells per path kind), each cell
represented by its centre ``c`` (eq C2); the sum is exact at the geometry of the trace:

.. math::
    \\mathsf S_c = \\sum_{i \\in c} \\mathsf a_i\\, e^{-jk(L_i - L_c)}\\,
    \\frac{r_t(c)\\, r_r(c)}{\\ell_i}, \\qquad L_c = r_t(c) + r_r(c) \\qquad \\text{(C2)}

Between two traces the centres move rigidly with the hull (positions, velocity) and the
kernel recomputes every delay and Doppler phase; a cell's amplitude is held. The phase
error this makes for a contribution ``x`` from its cell centre after the geometry has
turned by an angle ``dtheta`` is at most ``2 k |x| dtheta`` (``|x| <= sqrt(3) delta / 2``),
so ``delta`` and the refresh step (:func:`refresh_schedule`) are chosen together
(``docs/ship.md``). Within the receiver bandwidth B the delay error ``<= sqrt(3) delta / c``
is small against the resolution ``1 / B`` when ``delta << c / (2 B)``.

Apparent RCS. :func:`coherent_total` sums centres into the 2x2 ``S`` of the whole hull
referred to one point, ``sigma_mn = |S_mn|^2`` (eq C3): the RCS a radar at T, R
would measure, multipath included.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "PATH_NAMES",
    "CentreAccumulator",
    "ScatteringCentres",
    "coherent_total",
    "equivalent_positions",
    "refresh_schedule",
]

#: Path kinds, index = sea_first + 2 * sea_last: T-hull-R, T-sea-hull-R, T-hull-sea-R,
#: T-sea-hull-sea-R.
PATH_NAMES = ("direct", "sea-hull", "hull-sea", "sea-hull-sea")


@dataclass(frozen=True)
class ScatteringCentres:
    """Point scatterers of a hull, held between two traces.

    Attributes
    ----------
    position : (K, 3) array
        World positions at ``time`` [m].
    s : (K, 2, 2) complex array
        Amplitudes [m] in (h, v) order (FSA bases), ``|s|^2`` an RCS [m^2].
    path : (K,) int8 array
        Path kind (index into :data:`PATH_NAMES`).
    time : float
        Time of the trace [s].
    velocity : (3,) array
        Rigid velocity of the hull [m/s].
    """

    position: NDArray[np.float64]
    s: NDArray[np.complex128]
    path: NDArray[np.int8]
    time: float
    velocity: NDArray[np.float64]

    def __len__(self) -> int:
        return int(self.path.size)

    def positions_at(self, t: float) -> NDArray[np.float64]:
        """World positions at time ``t`` [s], moved rigidly with the hull [m]."""
        return self.position + self.velocity * (t - self.time)


def _norm(a: NDArray) -> NDArray:
    return np.sqrt(a[..., 0] ** 2 + a[..., 1] ** 2 + a[..., 2] ** 2)


def equivalent_positions(points: ArrayLike, length: ArrayLike, tx: ArrayLike, rx: ArrayLike,
                         iterations: int = 4) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Points nearest to ``points`` whose bistatic range ``|c - T| + |c - R|`` is ``length``.

    Newton steps along the gradient ``g = u_t + u_r`` of the bistatic range (unit vectors
    from T and R): ``c <- c + (L - |c - T| - |c - R|) g / |g|^2``.

    Parameters
    ----------
    points : (N, 3) array_like
        Starting points (a path's last hit on the hull) [m].
    length : (N,) array_like
        Unfolded path lengths L [m].
    tx, rx : (3,) array_like
        Transmitter and receiver positions [m].
    iterations : int
        Newton steps (the bistatic range is smooth: the residual after a step is of
        order |c - p|^2 / r; four reach float64 precision for extra paths of tens of
        metres).

    Returns
    -------
    c : (N, 3) array
        Delay-equivalent positions [m].
    ok : (N,) bool array
        False where the gradient vanishes (|g| < 0.05, a bistatic angle above 177 deg,
        near forward scatter, where the delay does not locate a point).
    """
    # the coordinates as three contiguous rows (the same operations as on (N, 3) rows,
    # elementwise, to the bit; faster)
    c = np.array(np.asarray(points, dtype=np.float64).reshape(-1, 3).T, order="C")
    target = np.asarray(length, dtype=np.float64)
    t = np.asarray(tx, dtype=np.float64)
    r = np.asarray(rx, dtype=np.float64)
    ok = np.ones(c.shape[1], dtype=bool)
    g = np.empty_like(c)
    for _ in range(iterations):
        dt, dr = c - t[:, None], c - r[:, None]
        rt = np.sqrt(dt[0] ** 2 + dt[1] ** 2 + dt[2] ** 2)
        rr = np.sqrt(dr[0] ** 2 + dr[1] ** 2 + dr[2] ** 2)
        np.add(dt / rt, dr / rr, out=g)
        g2 = g[0] ** 2 + g[1] ** 2 + g[2] ** 2
        ok = g2 > 0.05**2
        step = np.where(ok, (target - rt - rr) / np.where(ok, g2, 1.0), 0.0)
        c += step * g
    return np.ascontiguousarray(c.T), ok


#: Cell indices are packed in 20 bits per axis (+-2^19 cells: +-52 km at 0.1 m).
_BITS = 20
_HALF = 1 << (_BITS - 1)


def _pack(path: NDArray, idx: NDArray) -> NDArray[np.int64]:
    """One int64 key per (path kind, cell index)."""
    if np.any(np.abs(idx) >= _HALF):
        raise ValueError("scattering centres farther than 2^19 cells from the hull's "
                         "reference point: increase the cell size")
    u = (idx + _HALF).astype(np.int64)
    return (((path.astype(np.int64) << _BITS | u[:, 0]) << _BITS | u[:, 1]) << _BITS
            | u[:, 2])


def _unpack(key: NDArray[np.int64]) -> tuple[NDArray, NDArray]:
    mask = (1 << _BITS) - 1
    idx = np.stack([(key >> (2 * _BITS)) & mask, (key >> _BITS) & mask, key & mask],
                   axis=1) - _HALF
    return key >> (3 * _BITS), idx


def _reduce(keys: NDArray[np.int64], values: NDArray) -> tuple[NDArray, NDArray]:
    """Sum the rows of ``values`` (N, 4) complex that share a key."""
    uniq, inv = np.unique(keys, return_inverse=True)
    out = np.zeros((uniq.size, values.shape[1]), dtype=np.complex128)
    for c in range(values.shape[1]):  # each channel a bincount over the cells
        out[:, c] = (np.bincount(inv, values[:, c].real, uniq.size)
                     + 1j * np.bincount(inv, values[:, c].imag, uniq.size))
    return uniq, out


class CentreAccumulator:
    """Coherent sums of SBR contributions into cells (eq C2) and per-mechanism totals.

    Parameters
    ----------
    k : float
        Wavenumber [rad/m].
    tx, rx : (3,) arrays
        Transmitter and receiver positions [m] (world).
    reference : (3,) array
        Grid anchor and the point the totals refer to [m].
    cell : float
        Cell side delta [m].
    n_mechanisms : int
        Number of mechanism labels of :meth:`add` (e.g. path kinds x bounce orders).
    """

    def __init__(self, k: float, tx: ArrayLike, rx: ArrayLike, reference: ArrayLike,
                 cell: float, n_mechanisms: int) -> None:
        if not cell > 0:
            raise ValueError(f"cell = {cell}: must be > 0 [m]")
        self.k = float(k)
        self.tx = np.asarray(tx, dtype=np.float64)
        self.rx = np.asarray(rx, dtype=np.float64)
        self.reference = np.asarray(reference, dtype=np.float64)
        self.cell = float(cell)
        rt = _norm(self.reference - self.tx)
        rr = _norm(self.reference - self.rx)
        self._ref = (rt + rr, rt * rr)
        self.totals = np.zeros((n_mechanisms, 2, 2), dtype=np.complex128)
        self._keys: list[NDArray] = []
        self._sums: list[NDArray] = []

    def add(self, position: NDArray, amplitude: NDArray, length: NDArray,
            spreading: NDArray, path: NDArray, mechanism: NDArray) -> None:
        """Add contributions (eq C1).

        Parameters
        ----------
        position : (N, 3) array
            Delay-equivalent positions c* [m].
        amplitude : (N, 2, 2) complex array
            ``a_i`` [m].
        length : (N,) array
            ``L_i`` [m].
        spreading : (N,) array
            ``ell_i`` [m^2].
        path : (N,) int array
            Path kind (:data:`PATH_NAMES`).
        mechanism : (N,) int array
            Mechanism label for :attr:`totals`.
        """
        if length.size == 0:
            return
        k = self.k
        # Totals referred to the reference point (eq C3 of every contribution)
        l_ref, rr_ref = self._ref
        w = np.exp(-1j * k * (length - l_ref)) * (rr_ref / spreading)
        np.add.at(self.totals, mechanism, amplitude * w[:, None, None])
        # Cells (eq C2): integer cell index per axis, keyed with the path kind
        idx = np.floor((position - self.reference) / self.cell).astype(np.int64)
        centre = self.reference + (idx + 0.5) * self.cell
        rt = _norm(centre - self.tx)
        rr = _norm(centre - self.rx)
        w = np.exp(-1j * k * (length - rt - rr)) * (rt * rr / spreading)
        uniq, sums = _reduce(_pack(path, idx), amplitude.reshape(-1, 4) * w[:, None])
        self._keys.append(uniq)
        self._sums.append(sums)

    def centres(self, time: float, velocity: ArrayLike, prune: float = 0.0
                ) -> ScatteringCentres:
        """The cells as scattering centres.

        Parameters
        ----------
        time : float
            Time of the trace [s].
        velocity : (3,) array
            Hull velocity [m/s].
        prune : float
            Drop the weakest centres whose summed power ``sum |S|^2`` (four channels) is
            at most this fraction of the total (0 keeps every non-zero centre).
        """
        v = np.asarray(velocity, dtype=np.float64)
        if not self._keys:
            return ScatteringCentres(np.zeros((0, 3)), np.zeros((0, 2, 2), complex),
                                     np.zeros(0, np.int8), float(time), v)
        keys, s = _reduce(np.concatenate(self._keys), np.concatenate(self._sums))
        path, idx = _unpack(keys)
        power = np.sum(s.real**2 + s.imag**2, axis=1)
        order = np.argsort(power, kind="stable")
        cum = np.cumsum(power[order])
        total = cum[-1] if cum.size else 0.0
        drop = order[cum <= prune * total] if total > 0 else order
        keep = np.ones(power.size, dtype=bool)
        keep[drop] = False
        keep &= power > 0
        pos = self.reference + (idx[keep] + 0.5) * self.cell
        return ScatteringCentres(pos, s[keep].reshape(-1, 2, 2),
                                 path[keep].astype(np.int8), float(time), v)


def coherent_total(position: ArrayLike, s: ArrayLike, tx: ArrayLike, rx: ArrayLike,
                   k: float, reference: ArrayLike) -> NDArray[np.complex128]:
    """2x2 scattering amplitude of a set of centres referred to one point (eq C3).

    .. math::
        \\mathsf S = \\sum_c \\mathsf S_c\\, e^{-jk(L_c - L_0)}
        \\frac{r_t(0)\\,r_r(0)}{r_t(c)\\,r_r(c)} \\qquad \\text{(C3)}

    (index 0: the reference point), so that ``|S_mn|^2`` is the RCS [m^2] a radar at
    T, R measures when it refers the echo's range to that point (the apparent RCS: the
    sea multipath included when the centres hold it).

    Parameters
    ----------
    position : (K, 3) array_like
        Centre positions [m].
    s : (K, 2, 2) array_like
        Centre amplitudes [m].
    tx, rx : (3,) array_like
        Transmitter and receiver [m].
    k : float
        Wavenumber [rad/m].
    reference : (3,) array_like
        Reference point [m].

    Returns
    -------
    (2, 2) complex array [m]
    """
    p = np.asarray(position, dtype=np.float64).reshape(-1, 3)
    s = np.asarray(s, dtype=np.complex128).reshape(-1, 2, 2)
    t = np.asarray(tx, dtype=np.float64)
    r = np.asarray(rx, dtype=np.float64)
    p0 = np.asarray(reference, dtype=np.float64)
    rt, rr = _norm(p - t), _norm(p - r)
    rt0, rr0 = _norm(p0 - t), _norm(p0 - r)
    w = np.exp(-1j * k * (rt + rr - rt0 - rr0)) * (rt0 * rr0 / (rt * rr))
    return np.einsum("k,kij->ij", w, s)


def refresh_schedule(tx_direction: ArrayLike, rx_direction: ArrayLike, times: ArrayLike,
                     step: float, interval: float = 0.0) -> NDArray[np.intp]:
    """Indices of the times at which a hull signature is traced again.

    The first time is always one; time ``i`` starts a new trace when the direction from
    the hull to the transmitter, or to the receiver, has turned by more than ``step``
    since the last trace, or (``interval > 0``) when ``interval`` has elapsed since it.
    The schedule is a function of the tracks only, so a pulse's signature does not
    depend on which pulses were computed before.

    Parameters
    ----------
    tx_direction, rx_direction : (P, 3) array_like
        Unit directions from the hull's reference point to the transmitter and the
        receiver in the hull's frame, at each time [-].
    times : (P,) array_like
        Times, increasing [s].
    step : float
        Aspect step [rad] (> 0).
    interval : float
        Time step [s] (0: none).

    Returns
    -------
    (R,) int array
        Increasing indices into ``times``, starting with 0.
    """
    ut = np.asarray(tx_direction, dtype=np.float64).reshape(-1, 3)
    ur = np.asarray(rx_direction, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(times, dtype=np.float64).reshape(-1)
    if not step > 0:
        raise ValueError(f"step = {step}: must be > 0 [rad]")
    if interval < 0:
        raise ValueError(f"interval = {interval}: must be >= 0 [s]")
    cos_step = np.cos(step)
    out = [0]
    last = 0
    for i in range(1, t.size):  # a walk over the pulse times (a few vector ops each)
        turned = (ut[i] @ ut[last] < cos_step) or (ur[i] @ ur[last] < cos_step)
        late = interval > 0 and t[i] - t[last] >= interval * (1.0 - 1e-9)
        if turned or late:
            out.append(i)
            last = i
    return np.asarray(out, dtype=np.intp)
