"""Least-squares amplitudes of nutation terms over a span, and which terms a span can tell apart.

Rule: a span resolves a term when it covers one of its periods, and two terms
when it covers one period of their difference frequency (18.613 years for the
principal terms, set by Ω).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.perturbations.lunar_theory import delaunay_arguments, delaunay_rates
from andoyer.planetary.nutation.analytic import NutationSeries
from andoyer.planetary.nutation.model import PRINCIPAL_TERMS

__all__ = ["fit_terms", "minimum_span"]

Array = NDArray[np.float64]

# Regressors of the fits: the series' terms above this, arcsec (smaller ones barely leak into the rest).
_FIT_THRESHOLD = 1e-4


def minimum_span(multipliers: ArrayLike | None = None, epoch: float = 0.0) -> float:
    """The shortest span (Julian years) over which the terms ``multipliers`` (K, 5) can be fitted.

    The rule: the span must cover one period of the slowest term (18.613 years
    with ``Ω`` among the terms), which also separates every pair of the
    principal terms.

    Examples
    --------
    >>> round(minimum_span(), 3)
    18.613
    """
    if multipliers is None:
        multipliers = list(PRINCIPAL_TERMS.values())
    k = as_finite(multipliers, "multipliers")
    if k.ndim != 2 or k.shape[-1] != 5 or k.shape[0] == 0 or np.any(k != np.round(k)):
        msg = f"expected integer multipliers of (l, l', F, D, Omega) with shape (K, 5), got {k.tolist()!r}"
        raise ValueError(msg)
    rates = np.abs(k @ delaunay_rates(as_finite(epoch, "epoch")))
    if np.min(rates) == 0:
        msg = "expected terms with nonzero frequencies, got a constant term among the multipliers"
        raise ValueError(msg)
    return float(2 * np.pi / np.min(rates))


def fit_terms(t: ArrayLike, dpsi: ArrayLike, deps: ArrayLike, multipliers: ArrayLike) -> Array:
    """Least-squares amplitudes ``(ψs, ψc, εc, εs)`` (K, 4) of the terms ``multipliers`` (K, 5).

    Fits ``Δψ = a + b t + Σ ψs sin θ + ψc cos θ`` and likewise ``Δε`` (with
    ``θ = n·(l, l′, F, D, Ω)(t)``), the constant and the trend absorbing the
    mean pole.

    Parameters
    ----------
    t : array_like, shape (T,)
        Julian years from J2000, spanning at least :func:`minimum_span`.
    dpsi, deps : array_like, shape (T,)
    multipliers : array_like, shape (K, 5)

    Returns
    -------
    numpy.ndarray, shape (K, 4)

    Examples
    --------
    >>> t = np.linspace(0.0, 20.0, 2001)
    >>> theta = delaunay_arguments(t)[:, 4]
    >>> fit_terms(t, 1 + 2 * np.sin(theta), 3 * np.cos(theta), [(0, 0, 0, 0, 1)]).round(12).tolist()
    [[2.0, 0.0, 3.0, 0.0]]
    """
    t = np.asarray(t, dtype=float)
    n = np.atleast_2d(np.asarray(multipliers, dtype=float))
    values = np.stack([np.asarray(dpsi, dtype=float), np.asarray(deps, dtype=float)], axis=-1)
    if t.ndim != 1 or values.shape != (t.size, 2) or n.shape[-1] != 5:
        msg = (
            "expected t (T,), dpsi and deps (T,) and multipliers (K, 5), "
            f"got {t.shape}, {values.shape}, {n.shape}"
        )
        raise ValueError(msg)
    span = float(t.max() - t.min()) if t.size else 0.0
    need = minimum_span(n, float(np.mean(t)) if t.size else 0.0)
    if span < need * (1 - 1e-9):
        msg = f"expected a span of at least {need:.3f} years to fit these terms, got {span:.3f}"
        raise ValueError(msg)
    theta = delaunay_arguments(t) @ n.T
    design = np.concatenate([np.ones((t.size, 1)), (t - t.mean())[:, None], np.sin(theta), np.cos(theta)], 1)
    coefficients = np.linalg.lstsq(design, values, rcond=None)[0]
    K = n.shape[0]
    sin_part, cos_part = coefficients[2 : 2 + K], coefficients[2 + K :]
    return np.stack([sin_part[:, 0], cos_part[:, 0], cos_part[:, 1], sin_part[:, 1]], axis=-1)


def _large(series: NutationSeries) -> Array:
    """The series' multipliers with an amplitude above ``_FIT_THRESHOLD``."""
    size = np.max(np.abs([series.psi_sin, series.psi_cos, series.eps_cos, series.eps_sin]), axis=0)
    return series.multipliers[size > _FIT_THRESHOLD]


def _resolved(multipliers: Array, span: float, epoch: float, first: Array | None = None) -> Array:
    """Regressors for a fit over ``span``: ``first``, then the rows of ``multipliers`` in order.

    A row is kept when its period fits in ``span`` (slower terms fold into the
    mean pole's trend) and its frequency differs from every kept row's by at
    least one cycle over the span (else the two cannot be told apart).
    """
    return _split(multipliers, span, epoch, first)[0]


def _split(multipliers: Array, span: float, epoch: float, first: Array | None = None) -> tuple[Array, Array]:
    """:func:`_resolved`'s regressors, and the rows left out as too close to one of them (not too slow)."""
    rates = delaunay_rates(epoch)
    kept = [] if first is None else [np.asarray(row, dtype=float) for row in first]
    kept_rates = [abs(float(row @ rates)) for row in kept]
    close = []
    resolution = 2 * np.pi / span
    for row in multipliers:
        if any(np.array_equal(row, other) for other in kept):
            continue
        rate = abs(float(row @ rates))
        if rate < resolution:
            continue
        if all(abs(rate - other) >= resolution for other in kept_rates):
            kept.append(np.asarray(row, dtype=float))
            kept_rates.append(rate)
        else:
            close.append(np.asarray(row, dtype=float))
    return np.asarray(kept).reshape(-1, 5), np.asarray(close).reshape(-1, 5)
