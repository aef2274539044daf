"""Input validation shared by every public entry point.

Every check raises :class:`ValueError` with a message of the form
``"expected …, got …"`` so that bad input never becomes a wrong number.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "MAX_ANGLE",
    "MAX_MOMENTUM",
    "as_finite",
    "as_vectors",
    "broadcast",
    "broadcast_finite",
    "check_angle",
    "check_magnitude",
    "check_momenta",
    "describe",
]

#: Largest magnitude of an angular momentum (or any of its components or conjugate momenta):
#: its square, a sum of three squares and their ratios to the moments stay finite in float64
#: (``(10¹⁵⁰)² = 10³⁰⁰ < 1.8·10³⁰⁸``), so charts and energies never overflow.
MAX_MOMENTUM = 1e150
#: Largest angle (radians) accepted by a chart: at 2⁵² rad one ulp is a whole radian, and no digit
#: of the angle is left (``ulp(x) = x 2⁻⁵²``).
MAX_ANGLE = 2.0**52


def describe(value: Any) -> str:
    """Return a short description of ``value`` for error messages."""
    arr = np.asarray(value)
    if arr.ndim == 0:
        return repr(arr.item()) if arr.dtype.kind in "biufc" else repr(value)
    return f"array of shape {arr.shape}"


def as_finite(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """Convert ``value`` to a float64 array and reject NaN or infinity."""
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        msg = f"expected {name} to be real numbers, got {describe(value)}"
        raise ValueError(msg) from exc
    if not np.isfinite(arr).all():  # the method skips np.all's dispatch: this runs in ODE right-hand sides
        bad = float(arr[~np.isfinite(arr)].flat[0]) if arr.ndim else float(arr)
        msg = f"expected finite {name}, got {bad!r}"
        raise ValueError(msg)
    return arr


def as_vectors(value: ArrayLike, name: str, size: int = 3) -> NDArray[np.float64]:
    """Convert ``value`` to a finite array whose last axis has ``size`` components."""
    arr = as_finite(value, name)
    if arr.ndim == 0 or arr.shape[-1] != size:
        msg = f"expected {name} with shape (..., {size}), got shape {arr.shape}"
        raise ValueError(msg)
    return arr


def broadcast(*named: tuple[str, NDArray[np.float64]]) -> list[NDArray[np.float64]]:
    """Broadcast arrays together, naming them in the error if their shapes clash."""
    try:
        return list(np.broadcast_arrays(*(arr for _, arr in named)))
    except ValueError as exc:
        shapes = ", ".join(f"{name} {arr.shape}" for name, arr in named)
        msg = f"expected shapes that broadcast together, got {shapes}"
        raise ValueError(msg) from exc


def broadcast_finite(names: Sequence[str], values: Sequence[ArrayLike]) -> list[NDArray[np.float64]]:
    """Check each value is finite (named in errors) and broadcast them together."""
    return broadcast(*((name, as_finite(value, name)) for name, value in zip(names, values, strict=True)))


def check_magnitude(value: NDArray[np.float64], name: str, bound: float = MAX_MOMENTUM) -> None:
    """Refuse momenta of magnitude above ``bound`` (default :data:`MAX_MOMENTUM`), before they overflow.

    Examples
    --------
    >>> check_magnitude(np.array([1.0, -1e300]), "G")
    Traceback (most recent call last):
    ...
    ValueError: expected G of magnitude at most 1e+150 (so that its square stays finite), got G = -1e+300
    """
    big = np.abs(value) > bound
    if np.any(big):
        msg = (
            f"expected {name} of magnitude at most {bound:.0e} (so that its square stays finite), "
            f"got {name} = {float(np.asarray(value)[big].flat[0])!r}"
        )
        raise ValueError(msg)


def check_angle(value: NDArray[np.float64], name: str) -> None:
    """Refuse angles of magnitude above :data:`MAX_ANGLE`, where no digit of them is left.

    Examples
    --------
    >>> check_angle(np.array([0.3, -1e300]), "l")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected l of magnitude at most 4.5e+15 rad (beyond, ...), got l = -1e+300
    """
    big = np.abs(value) > MAX_ANGLE
    if np.any(big):
        msg = (
            f"expected {name} of magnitude at most {MAX_ANGLE:.2g} rad (beyond, not one digit of the "
            f"angle is left), got {name} = {float(np.asarray(value)[big].flat[0])!r}"
        )
        raise ValueError(msg)


def check_momenta(L: NDArray[np.float64], G: NDArray[np.float64], H: NDArray[np.float64]) -> None:
    """Check Andoyer momenta: ``G > 0``, ``|L| <= G``, ``|H| <= G`` and ``G <= MAX_MOMENTUM``."""
    check_magnitude(G, "G")
    if np.any(G <= 0):
        msg = f"expected G > 0, got G = {float(np.min(G))!r}"
        raise ValueError(msg)
    for name, value in (("L", L), ("H", H)):
        excess = np.abs(value) - G
        # A relative slack of a few ulp absorbs round-off of |m| computed from components.
        if np.any(excess > 4 * np.finfo(float).eps * G):
            i = np.unravel_index(np.argmax(excess), excess.shape) if excess.ndim else ()
            msg = (
                f"expected |{name}| <= G, got |{name}| = {float(abs(np.asarray(value)[i]))!r} "
                f"> G = {float(np.asarray(G)[i])!r}"
            )
            raise ValueError(msg)
