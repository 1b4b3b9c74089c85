"""Every figure seaecho draws, made from datasets only (never from private state), as
PNG files written atomically (:func:`seaecho.io.dataset.atomic_savefig`). Headless (Agg).

- :mod:`.run`: a run (the paper's Fig. 6: signal, compressed, elevation, sigma0 maps) and
  a surface's elevation map (``seaecho surface``);
- :mod:`.image`: an image (the paper's Figs. 7-9: sigma0 per channel, filtered, Pauli);
- :mod:`.ppi`: a scanning run's sweeps on the plane;
- :mod:`.doppler`: range-Doppler maps and clutter spectra (``seaecho doppler``);
- :mod:`.facets`: facet maps (``seaecho trace``) and ``seaecho compare``'s figures;
- :mod:`.sigma`: the mean-plane sigma_mn of ``seaecho sigma``'s angle sweeps.

The package sits after ``io`` and ``imaging`` in the layers: it reads their datasets and
writes through ``io``; nothing before it draws. (It is not called ``figures``:
``seaecho.figures`` is the Python API's function that draws a dataset's figures.)

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""
