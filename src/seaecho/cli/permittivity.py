"""``seaecho permittivity``: complex permittivity of sea water for f, T, S and a model."""

from __future__ import annotations

import argparse


def register(sub: argparse._SubParsersAction) -> None:
    from ..ocean.seawater import PERMITTIVITY_MODELS

    p = sub.add_parser(
        "permittivity", help="complex relative permittivity of sea water",
        description="Print the complex relative permittivity eps' - j eps'' of sea water "
        "(exp(+j omega t) convention) for a frequency, temperature, salinity and model.")
    p.add_argument("--frequency-ghz", type=float, nargs="+", default=[10.0],
                   help="frequency or frequencies [GHz]")
    p.add_argument("--temperature-c", type=float, default=20.0, help="temperature [degC]")
    p.add_argument("--salinity-psu", type=float, default=35.0, help="salinity [psu]")
    p.add_argument("--model", choices=sorted(PERMITTIVITY_MODELS) + ["all"],
                   default="meissner-wentz", help="permittivity model (or all)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import sys
    import warnings

    from ..api import permittivity
    from ..ocean.seawater import PERMITTIVITY_MODELS
    from . import UsageError

    models = sorted(PERMITTIVITY_MODELS) if args.model == "all" else [args.model]
    for f in args.frequency_ghz:
        if not 0.0 < f <= 1000.0:
            raise UsageError(f"--frequency-ghz = {f}: must be in (0, 1000] GHz")
    print("model,frequency_ghz,temperature_c,salinity_psu,eps_real,eps_imag")
    for model in models:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            eps = permittivity([f * 1e9 for f in args.frequency_ghz], args.temperature_c,
                               args.salinity_psu, model=model)
        for w in caught:
            print(f"seaecho permittivity: warning: {w.message}", file=sys.stderr)
        for f, e in zip(args.frequency_ghz, eps.values, strict=True):
            print(f"{model},{f:g},{args.temperature_c:g},{args.salinity_psu:g},"
                  f"{e.real:.4f},{e.imag:.4f}")
    return 0
