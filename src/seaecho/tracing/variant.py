"""Choosing the Mitsuba variant explicitly (never implicitly through ``import sionna.rt``).

``llvm_ad_mono_polarized`` (CPU, through libLLVM >= 16, see :mod:`seaecho._llvm`) is the
default; ``cuda_ad_mono_polarized`` is used when the scene or the CLI asks for it and a
CUDA GPU is present. Sionna RT sets a variant of its own choosing when imported with none
set, so :func:`set_variant` must run before :mod:`sionna.rt` is first imported; every
module of this package goes through :func:`mitsuba_modules`.
"""

from __future__ import annotations

DEFAULT_VARIANT = "llvm_ad_mono_polarized"
VARIANTS = ("llvm_ad_mono_polarized", "cuda_ad_mono_polarized")

__all__ = ["DEFAULT_VARIANT", "VARIANTS", "cuda_available", "mitsuba_modules", "set_variant"]


def cuda_available() -> bool:
    """Whether a CUDA device and Mitsuba's CUDA variant are usable here."""
    from .._llvm import configure_llvm

    configure_llvm()
    import mitsuba as mi

    if "cuda_ad_mono_polarized" not in mi.variants():
        return False
    try:
        import drjit as dr

        return bool(dr.has_backend(dr.JitBackend.CUDA))
    except Exception:  # noqa: BLE001 - no driver, no device: not available
        return False


def set_variant(variant: str | None = None) -> str:
    """Set (or check) the Mitsuba variant; returns the one in use.

    Parameters
    ----------
    variant : str, optional
        ``"llvm_ad_mono_polarized"`` (default) or ``"cuda_ad_mono_polarized"``.

    Raises
    ------
    ValueError
        Unknown variant, CUDA asked without a GPU, or a different variant already set in
        this process (Mitsuba objects of two variants cannot be mixed).
    """
    variant = DEFAULT_VARIANT if variant is None else variant
    if variant not in VARIANTS:
        raise ValueError(f"variant = {variant!r}: allowed {', '.join(VARIANTS)}")
    from .._llvm import configure_llvm

    configure_llvm()
    import mitsuba as mi

    current = mi.variant()
    if current == variant:
        return variant
    if variant.startswith("cuda") and not cuda_available():
        raise ValueError(f"variant = {variant!r}: no CUDA GPU available here; use "
                         f"{DEFAULT_VARIANT!r}")
    if current is not None and "sionna.rt" in __import__("sys").modules:
        raise ValueError(f"variant = {variant!r}: Mitsuba already runs {current!r} in this "
                         "process with Sionna RT loaded; start a new process")
    mi.set_variant(variant)
    return variant


def mitsuba_modules(variant: str | None = None):
    """``(dr, mi, rt)``: drjit, mitsuba and sionna.rt, with the variant set first."""
    set_variant(variant)
    import drjit as dr
    import mitsuba as mi
    import sionna.rt as rt

    return dr, mi, rt
