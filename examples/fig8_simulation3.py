"""The paper's Fig. 8: Simulation 3, airborne SAR images of a sea of state 2 with the boat.

    python examples/fig8_simulation3.py [--out docs/gallery] [--paper | --quick]

Simulates ``scenes/paper_sim3_*.toml`` (monostatic stripmap SAR at 3000 m altitude,
3000 m ground range, 222 m/s, PRF 222 Hz, 10 GHz, 75 MHz chirp, 160 pulses; 128 m sea
on 512 x 512, wind towards 0 deg; the 10 m boat at 10 kt heading 45 deg, its wake and its hull
echo), focuses it with the scene's ``[image]`` section (backprojection, 0.5 m pixels,
nominal track, no weighting) and writes ``imaging_sim3_sigma0.png`` (sigma0 per channel,
one dB scale) and ``imaging_sim3_pauli.png``; prints the image measures of
docs/imaging.md (sea level, wake contrast, secondary peaks). By default a 64 m tile on
the same 0.25 m grid with the boat moved into it, the full aperture, a 96 m image;
``--paper``: the paper's 128 m tile and 192 m image; ``--quick``: a 16 m tile, 16 pulses.

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


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    return sar_figures("paper_sim3_sar_128m_wind0.toml", "imaging_sim3", args, default=SAR_DEFAULT,
                       default_image=SAR_DEFAULT_IMAGE, quick=SAR_QUICK,
                       quick_image=SAR_QUICK_IMAGE)


if __name__ == "__main__":
    main()
