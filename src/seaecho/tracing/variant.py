"""Choosing the Mitsuba variant explicitly (never implicitly through ``import sionna.rt``).

``llvm_ad_mono_polarized`` (CPU, through libLLVM >= 16, see :mod:`seaecho._llvm`) is the
default; ``cuda_ad_mono_polarized`` is used when the scene or the CLI asks for it and a
CUDA GPU is present. Sionna RT sets a variant of its own choosing when imported with none
set, so :func:`set_variant` must run before :mod:`sionna.rt` is first imported; every
module of this package goes through :func:`mitsuba_modules`, or :func:`drjit_mitsuba`
where Sionna RT is not needed (the ray tests, the hull traces). The per-facet Dr.Jit
kernels follow the same variant (``drjit.llvm`` or ``drjit.cuda``,
:func:`seaecho.backend.drjit_namespace`).
"""

from __future__ import annotations

from ..backend import DEFAULT_VARIANT, VARIANTS

__all__ = ["DEFAULT_VARIANT", "VARIANTS", "active_variant", "cuda_available",
           "drjit_mitsuba", "mitsuba_modules", "set_variant"]


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
    if variant.startswith("cuda"):
        from ..backend import exact_cuda_math

        exact_cuda_math()
    if current is not None and "sionna.rt" in __import__("sys").modules:
        raise ValueError(f"variant = {variant!r}: Mitsuba already runs {current!r} in this "
                         "process with Sionna RT loaded; start a new process")
    mi.set_variant(variant)
    return variant


def active_variant() -> str:
    """The variant Mitsuba runs in this process, or the default when none is set yet.

    For code that works on Mitsuba objects already built (their variant is fixed): it
    must not ask for the default while a CUDA variant runs.
    """
    import sys

    mi = sys.modules.get("mitsuba")
    current = mi.variant() if mi is not None else None
    return current if current in VARIANTS else DEFAULT_VARIANT


def drjit_mitsuba(variant: str | None = None):
    """``(dr, mi)``: drjit and mitsuba with the variant set first, without Sionna RT
    (whose import takes about a second: the ray tests need Mitsuba only).

    ``variant`` None means the default variant (:func:`set_variant`).
    """
    set_variant(variant)
    import drjit as dr
    import mitsuba as mi

    return dr, mi


def mitsuba_modules(variant: str | None = None):
    """``(dr, mi, rt)``: drjit, mitsuba and sionna.rt, with the variant set first.

    ``variant`` None means the default variant (:func:`set_variant`).
    """
    dr, mi = drjit_mitsuba(variant)
    import sionna.rt as rt

    return dr, mi, rt
