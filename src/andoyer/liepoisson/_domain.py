"""Input validation for the Lie–Poisson layer and the singular-point convention.

Tolerances (documented in ``docs/liepoisson.md``):

* ``UNIT_TOL``: a vector that must be a unit vector (γ, λ) is accepted when
  ``| |v| - 1 | ≤ UNIT_TOL`` and then normalised;
* ``MOMENTUM_TOL``: ``|L| ≤ G`` and ``|H| ≤ G`` are accepted up to a relative
  excess ``MOMENTUM_TOL`` (rounding), and clipped;
* ``SINGULAR_TOL``: an Andoyer angle is declared undefined when the sine of the
  angle that carries it (``sin J`` for ``l``, ``sin I`` for ``h`` and, on e(3), ``g``)
  is at most ``SINGULAR_TOL``; the convention is then stated by the caller and a
  :class:`SingularChartWarning` is emitted.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from andoyer.state.singular import SingularChartWarning  # one warning class for every chart

UNIT_TOL = 1e-9
MOMENTUM_TOL = 8 * np.finfo(float).eps
SINGULAR_TOL = 1e-12
TWO_PI = 2.0 * np.pi


def as_components(name: str, value: Any, length: int) -> np.ndarray:
    """Float64 array with ``length`` components on the last axis, all finite."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0 or arr.shape[-1] != length:
        raise ValueError(f"expected {name} with last axis of length {length}, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"expected finite {name}, got non-finite values")
    return arr


def as_scalars(name: str, value: Any) -> np.ndarray:
    """Float64 array of finite values."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"expected finite {name}, got non-finite values")
    return arr


def leading_shape(**arrays: np.ndarray) -> tuple[int, ...]:
    """Broadcast shape of the leading axes (all but the last) of component arrays."""
    shapes = {name: arr.shape[:-1] for name, arr in arrays.items()}
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        described = ", ".join(f"{k} {v}" for k, v in shapes.items())
        raise ValueError(f"expected broadcastable leading shapes, got {described}") from None


def unit_vectors(name: str, v: np.ndarray) -> np.ndarray:
    """Check ``|v| = 1`` to ``UNIT_TOL`` and return ``v / |v|``."""
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    bad = np.abs(norm - 1.0) > UNIT_TOL
    if np.any(bad):
        worst = float(np.max(np.abs(norm - 1.0)))
        raise ValueError(
            f"expected {name} of unit norm (to {UNIT_TOL:g}), got | |{name}| - 1 | = {worst:.3g}"
        )
    return v / norm


def momenta(L: Any, G: Any, H: Any | None) -> tuple[np.ndarray, ...]:
    """Check ``G > 0``, ``|L| ≤ G``, ``|H| ≤ G``; return broadcast (L, G, H) clipped to ±G."""
    L = as_scalars("L", L)
    G = as_scalars("G", G)
    H = as_scalars("H", 0.0 if H is None else H)
    try:
        L, G, H = np.broadcast_arrays(L, G, H)
    except ValueError:
        raise ValueError(
            f"expected broadcastable L, G, H, got shapes {L.shape}, {G.shape}, {H.shape}"
        ) from None
    if np.any(G <= 0):
        raise ValueError(f"expected G > 0, got G = {float(np.min(G)):.6g}")
    for name, p in (("L", L), ("H", H)):
        excess = np.abs(p) - G * (1.0 + MOMENTUM_TOL)
        if np.any(excess > 0):
            i = np.unravel_index(np.argmax(excess), excess.shape)
            raise ValueError(
                f"expected |{name}| ≤ G, got |{name}| = {abs(float(p[i])):.17g} > G = {float(G[i]):.17g}"
            )
    return np.clip(L, -G, G), G, np.clip(H, -G, G)


def warn_singular(mask: np.ndarray, message: str, stacklevel: int) -> None:
    """Emit one :class:`SingularChartWarning` when any point of ``mask`` is singular."""
    count = int(np.count_nonzero(mask))
    if count:
        warnings.warn(
            f"{message} ({count} of {mask.size} points)",
            SingularChartWarning,
            stacklevel=stacklevel + 1,
        )


def wrap_angle(angle: np.ndarray, period: float = TWO_PI) -> np.ndarray:
    """Angle reduced to ``[0, period)`` (never ``period`` itself after rounding)."""
    out = np.mod(angle, period)
    return np.where(out >= period, 0.0, out)


def body_angle_l(m: np.ndarray, G: np.ndarray, stacklevel: int) -> tuple[np.ndarray, ...]:
    """``l, sin l, cos l, sin J, cos J`` from body momentum, with the l = 0 convention."""
    rho = np.hypot(m[..., 0], m[..., 1])
    sin_J = rho / G
    singular = sin_J <= SINGULAR_TOL
    warn_singular(
        singular,
        f"sin J ≤ {SINGULAR_TOL:g} (m along the body axis b3): l is undefined, set to 0",
        stacklevel + 1,
    )
    safe = np.where(singular, 1.0, rho)
    sin_l = np.where(singular, 0.0, m[..., 0] / safe)
    cos_l = np.where(singular, 1.0, m[..., 1] / safe)
    ell = np.where(singular, 0.0, wrap_angle(np.arctan2(m[..., 0], m[..., 1])))
    return ell, sin_l, cos_l, sin_J, m[..., 2] / G


def momentum_magnitude(m: np.ndarray) -> np.ndarray:
    """``|m|`` along the last axis; ``m = 0`` is outside every chart of this layer."""
    G = np.linalg.norm(m, axis=-1)
    if np.any(G == 0):
        raise ValueError("expected a non-zero angular momentum m, got |m| = 0")
    return G
