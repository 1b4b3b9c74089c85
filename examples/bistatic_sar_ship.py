"""Beyond the paper: a bistatic SAR image of Simulation 2's sea with the boat.

    python examples/bistatic_sar_ship.py [--out docs/gallery] [--paper | --quick]

The paper (section V-B) notes that bistatic SAR "may be readily used as well"; this
script does it with ``scenes/bistatic_sar_128m_wind55.toml``: the transmitter is
Simulation 2's aircraft (stripmap, 3000 m up, looking east), the receiver a second
aircraft in formation 1500 m south and 1000 m lower, the same sea (state 2, wind towards
55 deg), the 10 m boat at 10 kt with its wake (the scene's boat mesh occludes the sea
but is not a scatterer: no hull echo). ``seaecho.simulate`` then
``seaecho.image`` (bistatic backprojection) and ``seaecho.figures`` write
``imaging_bistatic_sigma0.png`` and ``imaging_bistatic_pauli.png``; the image measures
(``seaecho.image_measures``) are printed. Sizes as ``fig7_simulation2.py``: by default a
64 m tile on the 0.25 m grid, the boat moved into it, a 96 m image; ``--paper``: the
scene's 128 m tile; ``--quick``: a 16 m tile, 16 pulses.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

from _gallery import (
    SAR_DEFAULT,
    SAR_DEFAULT_IMAGE,
    SAR_QUICK,
    SAR_QUICK_IMAGE,
    options,
    sar_figures,
)

#: The sizes of Simulations 2-3 (the boat here is no scatterer: no ray density to set)
DEFAULT, QUICK = ({k: v for k, v in d.items() if not k.startswith("objects.")}
                  for d in (SAR_DEFAULT, SAR_QUICK))


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    return sar_figures("bistatic_sar_128m_wind55.toml", "imaging_bistatic", args,
                       default=DEFAULT, default_image=SAR_DEFAULT_IMAGE, quick=QUICK,
                       quick_image=SAR_QUICK_IMAGE)


if __name__ == "__main__":
    main()
