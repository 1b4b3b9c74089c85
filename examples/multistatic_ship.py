"""Beyond the paper: one transmitter, three receivers over a boat and its wake.

    python examples/multistatic_ship.py [--out docs/gallery] [--quick]

The paper's first claim is a simulator "that can, in particular, be used in multistatic
configurations". ``scenes/multistatic_ship_3rx.toml`` has one airborne X-band transmitter
(Simulation 2's aircraft) and three airborne receivers (``[[receivers]]``) looking at a
64 m sea with a 10 m boat at 10 kt and its wake, at bistatic angles of about 28, 73 and
102 deg at the tile centre. One sea realisation and one set of sub-facet draws serve the
three pairs (docs/multistatic.md). ``seaecho.simulate`` then ``seaecho.image`` (each
pair focused by bistatic backprojection on one grid, and their incoherent combination)
and ``seaecho.figures`` write ``multistatic_<receiver>_sigma0.png`` /
``_pauli.png`` per receiver (``multistatic_formation_sigma0.png``,
``multistatic_south_sigma0.png``, ``multistatic_northeast_sigma0.png``) and
``multistatic_fused_sigma0.png``; this script adds
``multistatic_geometry.png`` (the tracks seen from above and each pair's bistatic angle
against time) and ``multistatic_polarimetry.png`` (the sea's NRCS per channel seen by
each receiver, from the run's per-receiver sigma0 maps). The image measures are printed.
By default the scene as it is (128 pulses); ``--quick``: a 16 m tile, 16 pulses.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

from _gallery import SCENES, db, options, save, seaecho_warnings, sized

#: ``--quick``: a 16 m tile, the boat and its echo moved into it, 16 pulses, 1 m pixels
QUICK = {"sea.size_x_m": 16.0, "sea.nx": 64, "ship.position_m": [1.0, 0.7],
         "targets.0.position_m": [1.0, 0.7, 1.0], "radar.n_pulses": 16,
         "radar.start_time_s": -8.0 / 222.0, "radar.sea_update_pulses": 16,
         "radar.sigma_map_pulse": 8}
QUICK_IMAGE = {"extent_m": [-8.0, 8.0, -8.0, 8.0], "pixel_m": 1.0}


def geometry_figure(raw, out: Path) -> Path:
    """Tracks from above and the bistatic angle of each pair against time."""
    import matplotlib.pyplot as plt
    import numpy as np

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6))
    tx = raw["tx_position"].values
    ax.plot(tx[:, 0], tx[:, 1], "k-", lw=3)
    ax.plot(*tx[0, :2], "k^", label="transmitter")
    t = raw["time"].values
    for name in raw["receiver"].values:
        rx = raw["rx_position"].sel(receiver=name).values
        line, = ax.plot(rx[:, 0], rx[:, 1], "-", lw=3)
        ax.plot(*rx[0, :2], "o", color=line.get_color(), label=f"receiver {name}")
        beta = np.rad2deg(raw["bistatic_angle"].sel(receiver=name).values)
        bx.plot(t, beta, color=line.get_color(), label=str(name))
    x, y = raw["x"].values, raw["y"].values
    ax.add_patch(plt.Rectangle((x[0], y[0]), x[-1] - x[0], y[-1] - y[0], fill=False,
                               ec="tab:blue"))
    ax.plot(0, 0, "b+")
    ax.set(xlabel="x (east) [m]", ylabel="y (north) [m]", aspect="equal",
           title="tracks over the aperture (sea tile at the centre)")
    ax.legend(fontsize=8, loc="lower left")
    bx.set(xlabel="time [s]", ylabel="bistatic angle at the tile centre [deg]",
           title="bistatic angle of each pair")
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    return save(fig, out, "multistatic_geometry.png")


def polarimetry_figure(raw, out: Path) -> Path:
    """Mean NRCS of the sea per channel for each receiver (the run's sigma0 maps)."""
    import matplotlib.pyplot as plt
    import numpy as np

    names = [str(n) for n in raw["receiver"].values]
    pols = [str(p) for p in raw["polarisation"].values]
    s0 = raw["sigma0"].mean(dim=("y_cell", "x_cell")).values  # (receiver, polarisation)
    beta = np.rad2deg(raw["bistatic_angle"].isel(pulse=raw.sizes["pulse"] // 2).values)
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    width = 0.8 / len(pols)
    for j, p in enumerate(pols):
        ax.bar(np.arange(len(names)) + (j - 1.5) * width, db(s0[:, j]), width, label=p)
    ax.set_xticks(np.arange(len(names)),
                  [f"{n}\nbeta = {b:.0f} deg" for n, b in zip(names, beta, strict=True)])
    ax.set(ylabel="sea NRCS sigma0 [dB]", title="one sea, three receivers: mean sigma0 "
           "of the tile per channel")
    ax.legend(ncol=4, fontsize=8)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    for n, row in zip(names, s0, strict=True):
        print(f"  {n}: sigma0 " + ", ".join(f"{p} {v:.2f} dB" for p, v
                                            in zip(pols, db(row), strict=True)))
    return save(fig, out, "multistatic_polarimetry.png")


def main(argv: list[str] | None = None) -> list[Path]:
    import seaecho

    args = options(__doc__, argv)
    scene = sized(seaecho.load_scene(SCENES / "multistatic_ship_3rx.toml"), args, {}, QUICK)
    fields = QUICK_IMAGE if args.quick else {}
    with seaecho_warnings():
        raw = seaecho.simulate(scene, progress=not args.quick)
        img = seaecho.image(raw, progress=not args.quick, **fields)
    for what, m in seaecho.image_measures(img).items():
        if m:
            print(f"  {what}: " + ", ".join(f"{k} {v:.2f}" for k, v in m.items()))
    paths = [geometry_figure(raw, args.out), polarimetry_figure(raw, args.out)]
    paths += seaecho.figures(img, Path(args.out) / "multistatic")
    for p in paths[2:]:
        print(f"wrote {p}")
    return paths


if __name__ == "__main__":
    main()
