"""The sea around a radar as a patchwork of tiles (``[sea] coverage = "radar"``).

A scanning radar sees sea out to its range window's end in every direction. One tile of
sub-metre facets cannot hold kilometres of sea, and the beam sees only a thin sector of
it at each pulse. The patchwork lays square tiles (each the FFT grid of
:class:`seaecho.ocean.surface.SeaSurface`, axis-aligned, its own realisation of the one
spectrum) around the radar's ground point ``c``, in range bands whose facets grow with
range (docs/scanning.md, "The sea over the whole coverage").

**Levels (T1).** Level j has the facet spacing Delta_j = Delta_0 2^j (Delta_0 the scene's
``size_x_m / nx``, the finest) on grids of n_j = n_0 / 2^j nodes: every tile has the
scene's extent L = n_0 Delta_0 (a tile holds the same band of long waves at every level,
those the single tile holds), for j = 0 .. J with Delta_J <= Delta_max < Delta_(J+1) and
n_J even and at least :data:`MIN_NODES` (J = 0 if Delta_0 >= Delta_max).

**Bands (T2).** Level j owns the ground ranges g in [R_j, R_(j+1)) from ``c``, with
R_j = N_b Delta_j / theta for 1 <= j <= J (N_b = :data:`FACETS_PER_BEAM` facets across
the angle theta = lambda / W of the antenna's width W, within 15 % of the half-power width
of the tapers of docs/scanning.md: at range g a facet is at most theta g / N_b wide), R_0
the window's nearest ground range and R_(J+1) its farthest (cut at the radar horizon of
eq E2 to a crest of :data:`CREST_M`).

**The largest facet (T3).** Delta_max = min(lambda_p / N_p, delta_r / N_r): the spectral
peak's wavelength lambda_p = 2 pi / k_p over N_p = :data:`FACETS_PER_PEAK_WAVE`, and the
range resolution delta_r = c / (2 B) over N_r = :data:`FACETS_PER_RANGE_CELL`. At low
grazing the waves that shadow are the long, steep ones around the peak (Smith 1967: the
shadowing function depends on the slopes' rms through nu = cot(theta_i) / (sqrt 2 s)); a
sinusoid sampled every lambda / 8 keeps sin(pi / 8) / (pi / 8) = 97.4 % of its slope in
the facets' finite differences, and the slopes the facets miss go to the sub-facet
statistics of the two-scale model (:func:`seaecho.ocean.twoscale.facet_slope_deficit`),
so the split stays consistent whatever the spacing (the NRCS is grid independent,
docs/scattering.md).

**Lattice and ownership (T4).** The tiles of level j sit on the lattice of pitch
p_j = (n - 1) Delta_j (the span of a grid's cells: its n nodes make n - 1 cells): tile
(ix, iy) has cells spanning [c_x + ix p_x, c_x + (ix + 1) p_x) x [c_y + iy p_y, ...), its
grid nodes at X + (k - n / 2) Delta, X = c_x + ix p_x + n Delta / 2. Every level-j
lattice square meeting band j is a tile. A point q belongs to exactly one tile, the
level-j square holding it with j the band of |q - c|: the squares of a level are
disjoint and cover the plane, the bands are disjoint and cover [R_0, R_(J+1)), so the
owners partition the annulus (:meth:`Patchwork.owner`). A facet belongs to the tile of
its cell's centre: a tile keeps its cells whose centre it owns, so adjacent tiles of
one level abut cell to cell and, across a band edge, cells of the two levels meet along
a staircase of the coarser cell (the circle cut by cell centres).

**Frames (T5).** Each tile is flat in its own frame, tangent to the Earth at its centre:
on a spherical Earth (:class:`seaecho.geometry.earth.SphericalEarth`) its centre O =
(X, Y, 0) in the scene's coordinates sits at P = E4(O) of the simulation frame with the
local vertical turned by T = tilt(O); a point q of the tile's frame is at
T (q - O) + P in the simulation frame (per-tile drop, eq E3, and local vertical: the
grazing angle of eq E1 at the tile), and the tile's own curvature across L_j is
neglected as for the single tile (L^2 / (8 k a): 0.1 m for a 2 km tile). Flat Earth: T = I,
P = O.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .earth import SphericalEarth, horizon_range

#: Facets across the angle lambda / W of the antenna's width (eq T2) [-].
FACETS_PER_BEAM = 8
#: Facets per wavelength of the spectral peak (eq T3) [-].
FACETS_PER_PEAK_WAVE = 8
#: Facets per range resolution (eq T3) [-].
FACETS_PER_RANGE_CELL = 2
#: Fewest grid nodes along a tile's side at the coarsest level (eq T1) [-].
MIN_NODES = 16
#: Crest height that the radar horizon of the layout reaches (eq T2) [m]: tiles beyond
#: the horizon to a 30 m crest cannot be seen (the margin of the sea's box, beyond sea
#: state 9); the facets of the tiles inside are cut one by one.
CREST_M = 30.0

_KEY_OFFSET = 1 << 20


def zigzag(i: ArrayLike) -> NDArray[np.int64]:
    """0, -1, 1, -2, 2, ... -> 0, 1, 2, 3, 4, ...: a lattice index as a stream index
    (>= 0) [-]."""
    i = np.asarray(i, dtype=np.int64)
    return np.where(i >= 0, 2 * i, -2 * i - 1)


@dataclass(frozen=True)
class Level:
    """One level of the patchwork (eqs T1-T2).

    Attributes
    ----------
    index : int
        j.
    spacing : (float, float)
        Facet spacing (dx, dy) [m].
    shape : (int, int)
        Grid nodes (ny, nx) [-].
    band : (float, float)
        Ground ranges [R_j, R_(j+1)) it owns [m].
    """

    index: int
    spacing: tuple[float, float]
    shape: tuple[int, int]
    band: tuple[float, float]

    @property
    def size(self) -> tuple[float, float]:
        """Tile extents (Lx, Ly) = (nx dx, ny dy) [m] (the FFT period)."""
        return self.shape[1] * self.spacing[0], self.shape[0] * self.spacing[1]

    @property
    def pitch(self) -> tuple[float, float]:
        """Lattice pitch ((nx - 1) dx, (ny - 1) dy) [m]: the span of a grid's cells."""
        return (self.shape[1] - 1) * self.spacing[0], (self.shape[0] - 1) * self.spacing[1]


def level_spacings(finest_m: float, max_m: float, nodes: int | None = None) -> list[float]:
    """Delta_j = Delta_0 2^j for j = 0 .. J, Delta_J <= max(max_m, Delta_0) and, given the
    finest grid's ``nodes`` n_0, n_0 / 2^J an even integer >= :data:`MIN_NODES` (eq T1)
    [m]."""
    if not (finest_m > 0 and max_m > 0):
        raise ValueError(f"spacings {finest_m}, {max_m} m: must be > 0")
    j = max(int(np.floor(np.log2(max_m / finest_m) + 1e-12)), 0)
    if nodes is not None:
        while j > 0 and (nodes % 2 ** (j + 1) or nodes // 2 ** j < MIN_NODES):
            j -= 1
    return [finest_m * 2.0 ** i for i in range(j + 1)]


def max_spacing(peak_wavelength_m: float, range_resolution_m: float) -> float:
    """Delta_max = min(lambda_p / N_p, delta_r / N_r) (eq T3) [m]."""
    return min(peak_wavelength_m / FACETS_PER_PEAK_WAVE,
               range_resolution_m / FACETS_PER_RANGE_CELL)


def band_edges(spacings: list[float], beam_rad: float, r_min: float, r_max: float
               ) -> NDArray[np.float64]:
    """R_0 .. R_(J+1) of eq T2 [m], nondecreasing: R_j = N_b Delta_j / theta clipped to
    [r_min, r_max] (a level whose band is empty owns nothing)."""
    if not r_max > r_min >= 0:
        raise ValueError(f"ground ranges [{r_min}, {r_max}] m: need 0 <= r_min < r_max")
    inner = [FACETS_PER_BEAM * d / beam_rad for d in spacings[1:]]
    return np.clip(np.array([r_min, *inner, r_max], dtype=float), r_min, r_max)


@dataclass(frozen=True)
class TileFrame:
    """A tile's flat frame (eq T5): q (tile frame) -> T (q - O) + P (simulation frame).

    Attributes
    ----------
    rotation : ndarray (3, 3)
        T, columns the tile's east, north, up in the simulation frame.
    origin : ndarray (3,)
        P [m].
    centre : ndarray (3,)
        O = (X, Y, 0) [m].
    """

    rotation: NDArray[np.float64]
    origin: NDArray[np.float64]
    centre: NDArray[np.float64]

    def to_world(self, q: ArrayLike) -> NDArray[np.float64]:
        """Simulation-frame positions of tile-frame points (..., 3) [m]."""
        return (np.asarray(q, dtype=float) - self.centre) @ self.rotation.T + self.origin

    def to_tile(self, p: ArrayLike) -> NDArray[np.float64]:
        """Tile-frame positions of simulation-frame points (..., 3) [m]."""
        return (np.asarray(p, dtype=float) - self.origin) @ self.rotation + self.centre

    def vector_to_tile(self, v: ArrayLike) -> NDArray[np.float64]:
        """Tile-frame components of simulation-frame vectors (..., 3)."""
        return np.asarray(v, dtype=float) @ self.rotation

    def matrix_to_tile(self, m: ArrayLike) -> NDArray[np.float64]:
        """T^T M: a body-to-simulation rotation (..., 3, 3) as body-to-tile."""
        return np.einsum("ji,...jk->...ik", self.rotation, np.asarray(m, dtype=float))


@dataclass(frozen=True)
class Patchwork:
    """The tiles around a radar (module docstring, eqs T1-T5).

    Attributes
    ----------
    centre : (float, float)
        The radar's ground point c in the scene's coordinates [m].
    levels : tuple of Level
    level, ix, iy : ndarray (T,) int
        Each tile's level and lattice indices, sorted by (level, ix, iy).
    earth : SphericalEarth or None
        None: flat Earth.
    """

    centre: tuple[float, float]
    levels: tuple[Level, ...]
    level: NDArray[np.int64]
    ix: NDArray[np.int64]
    iy: NDArray[np.int64]
    earth: SphericalEarth | None = None
    _keys: NDArray[np.int64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_keys", self._key(self.level, self.ix, self.iy))
        if np.any(np.diff(self._keys) <= 0):
            raise ValueError("Patchwork: tiles must be sorted by (level, ix, iy), unique")

    @staticmethod
    def _key(level, ix, iy) -> NDArray[np.int64]:
        level, ix, iy = (np.asarray(a, dtype=np.int64) for a in (level, ix, iy))
        return (level << 42) + ((ix + _KEY_OFFSET) << 21) + (iy + _KEY_OFFSET)

    @classmethod
    def around(cls, centre: tuple[float, float], finest: tuple[float, float],
               shape: tuple[int, int], ground_range: tuple[float, float], beam_rad: float,
               max_spacing_m: float, earth: SphericalEarth | None = None) -> Patchwork:
        """The patchwork of eqs T1-T4.

        Parameters
        ----------
        centre : (float, float)
            The radar's ground point [m].
        finest : (float, float)
            Finest spacing (dx, dy) [m] (level 0).
        shape : (int, int)
            Grid nodes (ny, nx) of the finest tiles (level j: divided by 2^j).
        ground_range : (float, float)
            Ground ranges [R_0, R_(J+1)) to cover [m].
        beam_rad : float
            theta = lambda / W [rad] (eq T2).
        max_spacing_m : float
            Delta_max (eq T3) [m], compared with the larger of dx, dy.
        earth : SphericalEarth or None
        """
        d0 = max(finest)
        spacings = level_spacings(d0, max_spacing_m, min(shape))
        edges = band_edges(spacings, beam_rad, *ground_range)
        levels, lv, lx, ly = [], [], [], []
        cx, cy = (float(v) for v in centre)
        for j, _ in enumerate(spacings):
            f = 2 ** j
            lev = Level(j, (finest[0] * f, finest[1] * f), (shape[0] // f, shape[1] // f),
                        (float(edges[j]), float(edges[j + 1])))
            levels.append(lev)
            r0, r1 = lev.band
            if r1 <= r0:
                continue
            px, py = lev.pitch
            ia = np.arange(int(np.floor(-r1 / px)) - 1, int(np.ceil(r1 / px)) + 1)
            ib = np.arange(int(np.floor(-r1 / py)) - 1, int(np.ceil(r1 / py)) + 1)
            gx, gy = np.meshgrid(ia, ib, indexing="ij")
            x0, y0 = gx * px, gy * py  # the square [x0, x0 + px) x [y0, y0 + py) - c
            # nearest and farthest distance of each square from c
            nx_ = np.clip(0.0, x0, x0 + px)
            ny_ = np.clip(0.0, y0, y0 + py)
            near = np.hypot(nx_, ny_)
            far = np.hypot(np.maximum(np.abs(x0), np.abs(x0 + px)),
                           np.maximum(np.abs(y0), np.abs(y0 + py)))
            keep = (near < r1) & (far >= r0)
            lv.append(np.full(int(keep.sum()), j))
            lx.append(gx[keep])
            ly.append(gy[keep])
        level = np.concatenate(lv) if lv else np.zeros(0, np.int64)
        ix = np.concatenate(lx) if lx else np.zeros(0, np.int64)
        iy = np.concatenate(ly) if ly else np.zeros(0, np.int64)
        order = np.lexsort((iy, ix, level))
        return cls((cx, cy), tuple(levels), level[order].astype(np.int64),
                   ix[order].astype(np.int64), iy[order].astype(np.int64), earth)

    # ------------------------------------------------------------------ the tiles
    def __len__(self) -> int:
        return int(self.level.size)

    @property
    def edges(self) -> NDArray[np.float64]:
        """R_0 .. R_(J+1) [m]."""
        return np.array([lv.band[0] for lv in self.levels] + [self.levels[-1].band[1]])

    def span(self, i: int) -> tuple[float, float, float, float]:
        """Cells of tile ``i``: [x0, x1) x [y0, y1) in the scene's coordinates [m]."""
        lev = self.levels[int(self.level[i])]
        px, py = lev.pitch
        x0 = self.centre[0] + int(self.ix[i]) * px
        y0 = self.centre[1] + int(self.iy[i]) * py
        return x0, x0 + px, y0, y0 + py

    def tile_centre(self, i: int) -> tuple[float, float]:
        """(X, Y): the grid's centre node (index n / 2) of tile ``i`` [m] (eq T4)."""
        lev = self.levels[int(self.level[i])]
        x0, _, y0, _ = self.span(i)
        return (x0 + lev.shape[1] // 2 * lev.spacing[0], y0 + lev.shape[0] // 2 * lev.spacing[1])

    def grid(self, i: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Node coordinates (x (nx,), y (ny,)) of tile ``i`` in the scene's coordinates [m]."""
        lev = self.levels[int(self.level[i])]
        (ny, nx), (dx, dy) = lev.shape, lev.spacing
        cx, cy = self.tile_centre(i)
        return cx + (np.arange(nx) - nx // 2) * dx, cy + (np.arange(ny) - ny // 2) * dy

    def seed(self, i: int, seed: int) -> int:
        """The seed of tile ``i`` (stream ``"sea-tile"``, index (level, zigzag(ix),
        zigzag(iy))): the same tile has the same sea whatever the window."""
        from ..rng import philox_key

        return philox_key(seed, "sea-tile", int(self.level[i]), int(zigzag(self.ix[i])),
                          int(zigzag(self.iy[i])))

    def frame(self, i: int) -> TileFrame:
        """Tile ``i``'s frame (eq T5)."""
        o = np.array([*self.tile_centre(i), 0.0])
        if self.earth is None:
            return TileFrame(np.eye(3), o.copy(), o)
        return TileFrame(self.earth.tilt(o), self.earth.position(o), o)

    def owner(self, points: ArrayLike) -> NDArray[np.int64]:
        """The tile that owns each point (..., 2) of the scene's ground (eq T4), -1
        outside the bands [-]."""
        q = np.asarray(points, dtype=float)
        d = q - np.asarray(self.centre)
        g = np.hypot(d[..., 0], d[..., 1])
        edges = self.edges
        j = np.searchsorted(edges, g, side="right") - 1
        inside = (g >= edges[0]) & (g < edges[-1])
        # the band of level j is [edges[j], edges[j + 1]); empty bands repeat an edge,
        # and searchsorted(side="right") lands on the last of equal edges: a nonempty band
        j = np.clip(j, 0, len(self.levels) - 1)
        px = np.array([lv.pitch[0] for lv in self.levels])[j]
        py = np.array([lv.pitch[1] for lv in self.levels])[j]
        key = self._key(j, np.floor(d[..., 0] / px).astype(np.int64),
                        np.floor(d[..., 1] / py).astype(np.int64))
        k = np.clip(np.searchsorted(self._keys, key), 0, max(len(self) - 1, 0))
        found = inside & (len(self) > 0) & (self._keys[k] == key if len(self) else False)
        return np.where(found, k, -1).astype(np.int64)

    def cell_owned(self, i: int) -> NDArray[np.bool_]:
        """Which cells (ny - 1, nx - 1) of tile ``i`` it owns: those whose centre's owner
        is ``i`` (eq T4)."""
        x, y = self.grid(i)
        xc, yc = 0.5 * (x[1:] + x[:-1]), 0.5 * (y[1:] + y[:-1])
        pts = np.stack(np.broadcast_arrays(xc[None, :], yc[:, None]), axis=-1)
        return self.owner(pts) == i

    def boxes(self, margin_m: float) -> NDArray[np.float64]:
        """The 8 corners of every tile's box, its cells' span plus ``margin_m`` on every
        side and +-``margin_m`` of height, in the simulation frame, (T, 8, 3) [m]."""
        out = np.empty((len(self), 8, 3))
        for i in range(len(self)):  # once per run, per tile (a few hundred)
            x0, x1, y0, y1 = self.span(i)
            c = np.array([[a, b, z] for a in (x0 - margin_m, x1 + margin_m)
                          for b in (y0 - margin_m, y1 + margin_m)
                          for z in (-margin_m, margin_m)])
            out[i] = self.frame(i).to_world(c)
        return out


def ground_range_window(window_m: tuple[float, float], height_m: float,
                        margin_m: float, earth: SphericalEarth | None) -> tuple[float, float]:
    """Ground ranges [g_0, g_1] the patchwork covers [m]: those of the slant ranges of the
    window (g = sqrt(r^2 - h^2), the farther side r itself), widened by ``margin_m`` and
    cut at the horizon to a crest of :data:`CREST_M` (eq E2) on a spherical Earth."""
    r0, r1 = window_m
    g0 = max(np.sqrt(max(r0 * r0 - height_m * height_m, 0.0)) - margin_m, 0.0)
    g1 = r1 + margin_m
    if earth is not None:
        g1 = min(g1, float(horizon_range(max(height_m, 0.0), CREST_M, earth.radius)))
    return float(g0), float(g1)


#: Grid nodes of the tiles held between pulses [-] (the memory of a pulse:
#: :class:`seaecho.coverage.CoverageSea`): 2^19, eight tiles of 256 x 256.
CACHE_NODES = 1 << 19
#: Memory of the unit-gain facet echoes held between pulses [bytes] (the held sea's
#: path of :class:`seaecho.coverage.CoverageSea`, eqs U1-U2): 512 MiB, the facets of
#: several pulses' footprints.
CACHE_BYTES = 1 << 29
#: Grid nodes of the tiles of one level made together (the held sea's unit echoes of
#: :meth:`seaecho.coverage.CoverageSea.unit_echoes`: their facet model in one kernel)
#: [-]: 2^13, eight tiles of 32 x 32, two of 64 x 64 (a larger tile alone).
BATCH_NODES = 1 << 13
#: Margin of a tile's box in the beam's bound [m] (as the single tile's, sea elevations
#: and the facets' horizontal displacements stay below it).
TILE_MARGIN_M = 30.0


__all__ = ["BATCH_NODES", "CACHE_BYTES", "CACHE_NODES", "CREST_M", "FACETS_PER_BEAM",
           "FACETS_PER_PEAK_WAVE", "FACETS_PER_RANGE_CELL", "Level", "MIN_NODES", "Patchwork",
           "TILE_MARGIN_M", "TileFrame", "band_edges", "ground_range_window", "level_spacings",
           "max_spacing", "zigzag"]
