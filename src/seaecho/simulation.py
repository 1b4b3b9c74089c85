"""The simulation: every stage joined, pulse by pulse, streamed to a netCDF file.

This is the only module that knows every stage (``shared/DESIGN.md``):

``Sea`` (ocean + wake) -> ``FacetEngine`` (ray-traced or analytic facets) ->
``scattering.facet`` (per-facet 2x2 amplitudes with speckle) -> ``RadarSystem`` (antennas,
radar equation, time of flight, NUFFT accumulation, noise) -> range compression -> file.

Per-pulse work is a pure function of (scene, pulse index): :meth:`Simulation.pulse`.
Pulse p is emitted at t_p = t_start + p / PRF. The sea surface used by pulse p is that of
the first pulse of its block, t_s = t_(N floor(p / N)) with N = ``sea_update_pulses``
(the paper's section V-B keeps the map between pings); platforms and facet geometry are
those of t_p. Speckle is drawn per block (``"speckle"`` stream, block index), so the
clutter stays coherent while its surface is held and decorrelates when it is renewed;
noise is drawn per pulse (``"noise"`` stream, pulse index).

:meth:`Simulation.run` writes pulses to a temporary file beside the destination as they
are computed (memory bounded by one block of pulses) and renames it into place at the end;
an exception or an interrupt removes it (``seaecho.io.dataset.atomic_path``).
"""

from __future__ import annotations

import contextlib
import os
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .constants import C0
from .guards import check_dataset, check_pulse
from .processing.range_compression import range_compress
from .radar.system import RadarSystem, ScattererEcho
from .rng import generator

#: Names of the 2x2 scattering channels, (h, v) order flattened.
POLARISATIONS = ("HH", "HV", "VH", "VV")


@dataclass(frozen=True)
class SeaEcho:
    """The sea's contribution to one pulse.

    Attributes
    ----------
    echo : ScattererEcho
        Delays and amplitudes of the visible facets.
    sigma : ndarray (N, 4) or None
        Per-facet scattering coefficients sigma_mn (HH, HV, VH, VV) [m^2/m^2] times the
        visibility, all facets, when asked for.
    facets : seaecho.geometry.facets.Facets
        The facets of the pulse.
    """

    echo: ScattererEcho
    sigma: NDArray[np.float64] | None
    facets: object


class Simulation:
    """A scene's radar simulation (module docstring).

    Parameters
    ----------
    scene : seaecho.config.Scene
        Needs ``[radar]`` and ``[transmitter]``.
    base_dir : path
        Folder of the scene file (``[[objects]]`` paths are relative to it).
    """

    def __init__(self, scene, base_dir: str | os.PathLike = ".") -> None:
        self.scene = scene
        self.radar = RadarSystem(scene)
        self.config = scene.radar
        self.block = scene.radar.sea_update_pulses
        self.sea = None
        self.engine = None
        self._state_cache: tuple[float, object] | None = None
        # Per-sea-state quantities, computed once per block of held pulses and reused by
        # its pulses: (block, {"damping": ..., "draws": ...}). A pulse's result still
        # depends only on (scene, pulse): the cache holds what the block index determines.
        self._block_cache: tuple[int, dict] | None = None
        if self.config.sea_clutter:
            self._init_sea(base_dir)

    # --------------------------------------------------------------------- the sea
    def _init_sea(self, base_dir) -> None:
        from .ocean.seawater import sea_water_permittivity
        from .ocean.twoscale import unresolved_statistics
        from .sea import Sea
        from .tracing.engine import FacetEngine

        scene = self.scene
        self.sea = Sea.from_scene(scene)
        self.engine = FacetEngine.from_scene(scene, base_dir=base_dir, sea=self.sea)
        # The occlusion of a refresh time t_ref is traced on the surface held at t_ref
        self.engine.surface_state = self.surface_state_at
        self.k = 2.0 * np.pi / self.radar.wavelength
        self.eps_r = complex(sea_water_permittivity(self.radar.carrier,
                                                    scene.sea.temperature_c,
                                                    scene.sea.salinity_psu))
        lx, ly = scene.sea.size_m
        nx, ny = scene.sea.grid_shape
        # Sub-facet slopes: waves between the grid's Nyquist and k/3 tilt the specular
        # points (two-scale cut-off of Brown 1978); shorter ones are the Bragg roughness.
        self.unresolved = unresolved_statistics(self.sea.spectrum, lx / nx, ly / ny,
                                                self.k / 3.0)
        self.wind_direction = np.deg2rad(scene.sea.wind_direction_deg)
        # Bragg roughness: the height spectrum of the waves the grid does not resolve,
        # tabulated once (it enables the scattering stage's Dr.Jit kernel)
        from .scattering.spectrum_table import BraggSpectrumTable

        self.bragg_spectrum = BraggSpectrumTable(self.sea.spectrum.height_spectrum,
                                                 k_min=self.unresolved.k_cut,
                                                 k_max=20.0 * self.k)
        # Validity of the Bragg part, checked once here rather than at every pulse
        from .scattering.twoscale import check_spm_validity

        check_spm_validity(self.k, self.unresolved.height_variance)

    def surface_time(self, pulse: int) -> float:
        """Time of the sea surface used by ``pulse`` [s] (start of its block)."""
        return float(self.radar.emission_time((pulse // self.block) * self.block))

    def surface_state(self, pulse: int):
        """Sea state of ``pulse``'s block (memoised: the same for every pulse of a block)."""
        t = self.surface_time(pulse)
        if self._state_cache is None or self._state_cache[0] != t:
            self._state_cache = (t, self.sea.state(t))
        return self._state_cache[1]

    def surface_state_at(self, t: float):
        """Sea state held at time ``t`` [s]: that of the pulse emitted at or before t
        (the first pulse before the start, the last after the end)."""
        p = int(np.floor((t - self.radar.start_time) * self.radar.prf + 1e-9))
        return self.surface_state(min(max(p, 0), self.radar.n_pulses - 1))

    def _block_quantities(self, pulse: int, state, n_facets: int) -> dict:
        """Wake damping per facet and speckle draws of ``pulse``'s block (memoised).

        The speckle draws come from the ``"speckle"`` stream of the block index, one pair
        (g_K, g_B) per facet, so that facet j gets the same draw at every pulse of its
        block whatever order the pulses are computed in.
        """
        from .geometry.mesh import to_facets
        from .scattering.facet import speckle_draws

        block = pulse // self.block
        if self._block_cache is None or self._block_cache[0] != block:
            rng = generator(self.scene.run.seed, "speckle", block)
            q = {"damping": to_facets(state.wake_mask).reshape(-1),
                 "draws": speckle_draws(n_facets, rng)}
            self._block_cache = (block, q)
        return self._block_cache[1]

    def sea_echo(self, pulse: int, geometry=None, sigma: bool = False) -> SeaEcho:
        """Echo of the sea facets for one pulse.

        Parameters
        ----------
        pulse : int
            Pulse index.
        geometry : PulseGeometry, optional
            ``self.radar.geometry(pulse)`` if already computed.
        sigma : bool
            Also return the per-facet sigma_mn (all facets, times visibility).
        """
        if self.sea is None:
            raise ValueError("sea clutter is off in this scene ([radar] sea_clutter)")
        from .scattering.facet import facet_terms, speckled_facet_amplitudes

        geo = self.radar.geometry(pulse) if geometry is None else geometry
        st = self.surface_state(pulse)
        facets = self.engine.facets(geo.time, state=st)
        vis = facets.visibility
        held = self._block_quantities(pulse, st, vis.size)
        damping = held["damping"]
        un = self.unresolved
        # All facets, so that facet j always gets the j-th speckle draw of its block
        # (visibility may change from pulse to pulse within a block). Eq P4 of
        # scattering.facet: |a|^2 is the facet's RCS [m^2]; visibility weights it. The
        # draws are the block's (drawn once per held surface); eqs P1-P4 run in one kernel
        args = (facets.n_i, facets.n_s, facets.normal)
        model = (self.k, self.eps_r, self.bragg_spectrum, un.mss_upwind, un.mss_crosswind,
                 self.wind_direction)
        amp = speckled_facet_amplitudes(*args, facets.area * vis, *model,
                                        draws=held["draws"], wake_damping=damping,
                                        local=facets)
        visible = vis > 0
        if visible.all():  # the usual case: no copies
            pos, vel = facets.centroid, facets.velocity
        else:
            pos, vel, amp = facets.centroid[visible], facets.velocity[visible], amp[visible]
        echo = self.radar.scatterer_echo(geo, pos, vel, amp.reshape(-1, 2, 2))
        sig = None
        if sigma:
            sig = facet_terms(*args, *model, wake_damping=damping,
                              local=facets).sigma() * vis[:, None]
        return SeaEcho(echo, sig, facets)

    # ------------------------------------------------------------------- one pulse
    def pulse(self, pulse: int) -> NDArray[np.complex128]:
        """Raw samples of one pulse, shape (channels, fast_time) [sqrt(W)]."""
        if not 0 <= pulse < self.radar.n_pulses:
            raise ValueError(f"pulse = {pulse}: must be in [0, {self.radar.n_pulses})")
        geo = self.radar.geometry(pulse)
        echoes = []
        if self.sea is not None:
            echoes.append(self.sea_echo(pulse, geo).echo)
        t = self.radar.target_echo(geo)
        if t is not None:
            echoes.append(t)
        raw = self.radar.receive(pulse, echoes)
        check_pulse(self, pulse, raw, echoes)  # NaN/Inf: NonFiniteEchoError (guards.py)
        return raw

    def compress(self, raw: NDArray[np.complex128]) -> NDArray[np.complex128]:
        """Range-compressed samples with the scene's weighting (same shape as ``raw``)."""
        c = self.config
        return range_compress(raw, self.radar.waveform.samples, c.range_weighting,
                              nbar=c.taylor_nbar, sidelobe_db=c.taylor_sidelobe_db)

    # ------------------------------------------------------------------ the dataset
    def static_dataset(self):
        """Everything but the pulses: coordinates, tracks, surface, sigma maps, truth."""
        import xarray as xr

        from .io.dataset import scene_attrs

        radar, scene = self.radar, self.scene
        pulses = np.arange(radar.n_pulses)
        t = radar.emission_time(pulses)
        fast = radar.window.fast_time
        coords = {
            "pulse": ("pulse", pulses, {"long_name": "pulse index"}),
            "time": ("pulse", t, {"units": "s", "long_name": "emission time"}),
            "channel": ("channel", np.array(radar.channel_names),
                        {"long_name": "receive port, transmit port"}),
            "fast_time": ("fast_time", fast,
                          {"units": "s", "long_name": "delay after emission"}),
            "range": ("fast_time", 0.5 * C0 * fast,
                      {"units": "m", "long_name": "c * delay / 2 (half bistatic path)"}),
            "xyz": ("xyz", np.array(["x", "y", "z"])),
        }
        data = {}
        for name, platform in (("tx", radar.tx), ("rx", radar.rx)):
            true, nominal = platform.state(t), platform.nominal_state(t)
            for kind, st in (("", true), ("_nominal", nominal)):
                data[f"{name}_position{kind}"] = (("pulse", "xyz"), st.position,
                                                  {"units": "m"})
                data[f"{name}_velocity{kind}"] = (("pulse", "xyz"), st.velocity,
                                                  {"units": "m s-1"})
                data[f"{name}_attitude{kind}"] = (
                    ("pulse", "angle"), st.attitude,
                    {"units": "rad", "long_name": "yaw, pitch, roll"})
        coords["angle"] = ("angle", np.array(["yaw", "pitch", "roll"]))
        if scene.targets:
            data["target_position"] = (
                ("target", "xyz"), np.array([g.position_m for g in scene.targets]),
                {"units": "m", "long_name": "target position at t = 0"})
            data["target_velocity"] = (
                ("target", "xyz"), np.array([g.velocity_m_s for g in scene.targets]),
                {"units": "m s-1"})
            s = np.stack([g.scattering_matrix().reshape(4) for g in scene.targets])
            data["target_scattering"] = (("target", "polarisation"), s,
                                         {"units": "m", "long_name": "s_mn, |s|^2 = RCS"})
            coords["target"] = ("target", np.array([g.name or f"target{i}" for i, g in
                                                    enumerate(scene.targets)]))
        if self.sea is not None:
            data.update(self._sea_truth())
            coords.update(x=("x", self.sea.x, {"units": "m"}),
                          y=("y", self.sea.y, {"units": "m"}))
            dx, dy = np.diff(self.sea.x[:2])[0], np.diff(self.sea.y[:2])[0]
            coords.update(x_cell=("x_cell", self.sea.x[:-1] + 0.5 * dx, {"units": "m"}),
                          y_cell=("y_cell", self.sea.y[:-1] + 0.5 * dy, {"units": "m"}))
        coords["polarisation"] = ("polarisation", np.array(POLARISATIONS))
        data["transmitted_pulse"] = (
            ("pulse_sample",), radar.waveform.samples,
            {"units": "1", "long_name": "transmitted pulse samples s[n] (unit amplitude), "
             "the matched filter's reference"})
        attrs = scene_attrs(scene)
        attrs.update({
            "carrier_frequency_hz": radar.carrier,
            "wavelength_m": radar.wavelength,
            "sampling_rate_hz": radar.window.sampling_rate,
            "prf_hz": radar.prf,
            "transmit_power_w": radar.transmit_power,
            "window_t0_s": radar.window.t0,
            "waveform_bandwidth_hz": radar.waveform.bandwidth,
            "waveform_duration_s": radar.waveform.duration,
            "monostatic": int(radar.monostatic),
            "sea_clutter": int(self.sea is not None),
            "sea_update_pulses": self.block,
            "sea_update_interval_s": self.block / radar.prf,
            "tracing_mode": scene.tracing.mode,
            "tracing_refresh_interval_s": scene.tracing.refresh_interval_s,
            "sigma_map_pulse": self.config.sigma_map_pulse,
            "range_weighting": self.config.range_weighting,
            "raw_units": "sqrt(W): |raw|^2 is the received power [W]",
        })
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def _sea_truth(self) -> dict:
        """Surface and per-facet sigma maps at the sigma-map pulse, and the ship track."""
        p = self.config.sigma_map_pulse
        st = self.surface_state(p)
        se = self.sea_echo(p, sigma=True)
        f = se.facets
        grid = se.sigma.reshape(f.grid_shape + (4,)).mean(axis=2)  # 2 triangles per cell
        vis = f.as_grid("visibility").mean(axis=2)
        data = {
            "elevation": (("y", "x"), st.elevation,
                          {"units": "m", "long_name": "sea + wake height at the "
                           "sigma-map pulse's surface time"}),
            "wake_elevation": (("y", "x"), st.wake_elevation, {"units": "m"}),
            "wake_mask": (("y", "x"), st.wake_mask,
                          {"units": "1", "long_name": "turbulent wake, 1 = Bragg damped"}),
            "sigma0": (("polarisation", "y_cell", "x_cell"), np.moveaxis(grid, -1, 0),
                       {"units": "m2 m-2", "long_name": "per-facet sigma_mn times "
                        "visibility (cell mean) at the sigma-map pulse"}),
            "visibility": (("y_cell", "x_cell"), vis, {"units": "1"}),
        }
        if self.sea.ship is not None:
            s = self.scene.ship
            heading = np.deg2rad(s.heading_deg)
            t = self.radar.emission_time(np.arange(self.radar.n_pulses))
            pos = np.array(s.position_m)[None, :] + s.speed * t[:, None] * np.array(
                [np.cos(heading), np.sin(heading)])
            data["ship_position"] = (("pulse", "xy"), pos,
                                     {"units": "m", "long_name": "hull centre (x, y)"})
        return data

    # ------------------------------------------------------------------------ run
    def run(self, path: str | os.PathLike, progress: bool = True, chunk: int = 16) -> Path:
        """Simulate every pulse and write the dataset to ``path`` atomically.

        Parameters
        ----------
        path : path
            Output netCDF file (h5netcdf, complex variables as HDF5 compounds).
        progress : bool
            Show a tqdm progress bar.
        chunk : int
            Pulses buffered per write (memory: chunk x channels x samples x 32 bytes).

        Returns
        -------
        Path
        """
        import h5netcdf
        from tqdm import tqdm

        from .io.dataset import atomic_path

        ds = self.static_dataset()
        check_dataset(ds)  # NaN/Inf in tracks, surface, maps: NonFiniteEchoError
        n_p, n_c, n_s = self.radar.n_pulses, len(self.radar.channels), self.radar.window.n_samples
        chunk = max(1, min(chunk, n_p))
        with atomic_path(path) as tmp, _quiet_invalid_netcdf():
            ds.to_netcdf(tmp, engine="h5netcdf", invalid_netcdf=True)
            del ds
            with h5netcdf.File(tmp, "a", invalid_netcdf=True) as f:
                raw_v = f.create_variable("raw", ("pulse", "channel", "fast_time"),
                                          dtype=np.complex128, chunks=(1, n_c, n_s))
                raw_v.attrs.update(units="sqrt(W)", long_name="complex baseband raw echo")
                rc_v = f.create_variable("compressed", ("pulse", "channel", "fast_time"),
                                         dtype=np.complex128, chunks=(1, n_c, n_s))
                rc_v.attrs.update(units="sqrt(W)", long_name="range-compressed echo",
                                  weighting=self.config.range_weighting)
                buf = np.empty((chunk, n_c, n_s), dtype=np.complex128)
                bar = tqdm(total=n_p, unit="pulse", disable=not progress, desc="seaecho run")
                try:
                    for start in range(0, n_p, chunk):
                        stop = min(start + chunk, n_p)
                        for i, p in enumerate(range(start, stop)):
                            buf[i] = self.pulse(p)
                            bar.update(1)
                        raw_v[start:stop] = buf[: stop - start]
                        rc_v[start:stop] = self.compress(buf[: stop - start])
                finally:
                    bar.close()
        return Path(path)


@contextlib.contextmanager
def _quiet_invalid_netcdf():
    """Silence h5netcdf's notice that complex variables are not classic netCDF-4."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*invalid netcdf features.*")
        yield


__all__ = ["POLARISATIONS", "SeaEcho", "Simulation"]
