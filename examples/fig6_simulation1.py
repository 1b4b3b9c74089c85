"""The paper's Fig. 6: Simulation 1, bistatic returns of a 64 m sea with the motor boat.

    python examples/fig6_simulation1.py [--out docs/gallery] [--paper | --quick]

Runs ``scenes/paper_sim1_bistatic_64m.toml`` from Python (``seaecho.simulate``: the
10 m boat at 10 kt heading 35 deg with its wake and its hull echo, Tx 20 deg and Rx
30 deg from the vertical at the tile centre, 10 GHz, 150 MHz chirp, 8 pulses) and writes
``paper_fig6_simulation1.png``: (a) the sea + wake elevation, (b) the modulus of the
received signal of the first pulse (unit transmitted amplitude, as the paper's 6b), (c)
the range-compressed signal, (d-g) sigma_mn [dB] of every sea cell (the paper's
6c-6f), visibility included. By default a 32 m tile on the same 0.099 m grid with the
boat moved into it and 4 pulses; ``--paper``: the paper's 64 m tile and 8 pulses (the
README's ``seaecho run``); ``--quick``: a 10 m tile, one pulse, the hull traced with one ray
per wavelength.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from _gallery import SCENES, db, options, save, seaecho_warnings, sized

import seaecho

#: Reduced size: a 32 m tile on the paper's 0.099 m grid, the boat moved into it, 4 pulses
DEFAULT = {"sea.size_x_m": 32.0, "sea.nx": 324, "ship.position_m": [6.0, 4.0],
           "radar.n_pulses": 4}
#: Tiny: a 10 m tile, one pulse, the hull traced with one ray per wavelength
QUICK = {"sea.size_x_m": 10.0, "sea.nx": 102, "ship.position_m": [1.0, 1.0],
         "radar.n_pulses": 1, "objects.0.rays_per_wavelength": 1.0}


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    scene = sized(seaecho.load_scene(SCENES / "paper_sim1_bistatic_64m.toml"), args,
                  DEFAULT, QUICK)
    with seaecho_warnings():
        ds = seaecho.simulate(scene, progress=not args.quick)

    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(15.0, 8.8), layout="constrained")
    top, bottom = fig.subfigures(2, 1)
    upper = top.subplots(1, 3)
    lower = bottom.subplots(1, 4)
    ax = upper[0]
    z = ds["elevation"]
    lim = float(np.abs(z).max())
    im = ax.pcolormesh(ds["x"], ds["y"], z, cmap="RdBu_r", vmin=-lim, vmax=lim,
                       shading="auto")
    if "ship_position" in ds:
        ax.plot(*ds["ship_position"].values[0], "k^", ms=7, label="boat")
        ax.legend(loc="upper right", fontsize=8)
    ax.set_aspect("equal")
    ax.set_title("(a) sea + wake elevation [m]")
    ax.set_xlabel("x (east) [m]")
    ax.set_ylabel("y (north) [m]")
    top.colorbar(im, ax=ax, shrink=0.85)
    p_t = float(ds.attrs["transmit_power_w"])
    rng = ds["range"].values
    for col, (var, title) in enumerate((("raw", "(b) received signal |r| / sqrt(P_t)"),
                                        ("compressed", "(c) range compressed"))):
        ax = upper[1 + col]
        for c, ch in enumerate(ds["channel"].values):
            a = np.abs(ds[var].isel(pulse=0).sel(channel=ch).values) / np.sqrt(p_t)
            ax.semilogy(rng, a, color=f"C{c}", lw=0.9, label=str(ch))
        ax.set_xlabel("range c tau / 2 [m] (half the bistatic path)")
        ax.set_title(f"{title}, pulse 0")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, ncol=2)
    s = ds["sigma0"]
    vals = db(s.values, 1e-12)
    top = float(vals.max())
    for c, pol in enumerate(s["polarisation"].values):
        ax = lower[c]
        im = ax.pcolormesh(ds["x_cell"], ds["y_cell"], vals[c], vmin=top - 60, vmax=top,
                           cmap="magma", shading="auto")
        ax.set_aspect("equal")
        ax.set_title(f"({'defg'[c]}) sigma_{pol} [dB]")
        ax.set_xlabel("x [m]")
        if c == 0:
            ax.set_ylabel("y [m]")
    bottom.colorbar(im, ax=lower, shrink=0.85, label="sigma0 per horizontal area [dB]")
    fig.suptitle(f"Simulation 1: {scene.sea.size_m[0]:g} m sea, U19.5 = 4.53 m/s, 10 m boat "
                 "at 10 kt; Tx 20 deg, Rx 30 deg from the vertical, 10 GHz")
    return [save(fig, args.out, "paper_fig6_simulation1.png", dpi=100)]


if __name__ == "__main__":
    main()
