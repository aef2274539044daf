r"""Lara's Fig. 1: the reduced phase space of the free body against the main problem of SAM rotation.

Lara (2013) writes the free Hamiltonian (eq. 4) and the main problem of SAM rotation (eqs. 6
and 8) in Andoyer's ``(ν, N; M)`` (the code's ``(l, L; G)``) and scales both as
``𝓗₀* = (2C𝓗₀/M² − 1)/α`` and ``𝓐* = (2C𝓐/M² − 1)/α``:

.. math:: \mathcal{H}_0^* = \Big(1 - \frac{N^2}{M^2}\Big)(1 - \beta\cos 2\nu), \qquad
          \mathcal{A}^* = 2\Big(1 - \frac{N}{M}\Big)(1 - \beta\cos 2\nu),

so that only Andoyer's triaxiality ``β`` is left.  With ``x = N/M`` and ``k = 1 − β cos 2ν`` the
contours ``𝓗₀* = q`` and ``𝓐* = q`` are, in closed form,

.. math:: x_{\mathcal{H}} = \sqrt{1 - q/k}, \qquad x_{\mathcal{A}} = 1 - \frac{q}{2k}.

Their difference is the neglected perturbation ``ε𝓟`` (eq. 7): with ``u = 1 − x_𝓐``, the free
contour at the same ``ν`` is ``1 − x_𝓗 = 1 − √(1 − 2u)``, i.e.

.. math:: x_{\mathcal{A}} - x_{\mathcal{H}} = \tfrac12 u^2 + \tfrac12 u^3 + O(u^4),

second order in Lara's small parameter ``δ = L/(G√(1−β²))`` since ``u = (1 − β²) δ / k ≤ (1 + β) δ``.
The figure shows ``β = 0.8``, ``0.88 ≤ N/M ≤ 1`` and the paper's levels ``q`` (Lara §3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.plot.projection import new_axes

__all__ = ["LARA_LEVELS", "LaraPortrait", "lara_portrait", "lara_portrait_data"]

Array = NDArray[np.float64]

#: The contour levels ``q`` of Lara's Fig. 1 (Lara 2013, §3, text after eq. 8).
LARA_LEVELS = (0.002, 0.007, 0.015, 0.023, 0.035, 0.048, 0.08, 0.12, 0.18, 0.25, 0.32, 0.38)


@dataclass(frozen=True)
class LaraPortrait:
    """What :func:`lara_portrait` draws.

    Attributes
    ----------
    beta : float
        Andoyer's triaxiality coefficient.
    levels : numpy.ndarray, shape (k,)
        The contour levels ``q``.
    nu : numpy.ndarray, shape (n,)
        Sample angles ``ν`` (radians).
    free : numpy.ndarray, shape (k, n)
        ``N/M`` on ``𝓗₀* = q`` (free body, Lara eq. 4); NaN where that contour has no point.
    main : numpy.ndarray, shape (k, n)
        ``N/M`` on ``𝓐* = q`` (main problem, Lara eq. 8).
    ratio_min : float
        Lower edge of the window in ``N/M``.
    """

    beta: float
    levels: Array
    nu: Array
    free: Array
    main: Array
    ratio_min: float


def lara_portrait_data(
    beta: float = 0.8,
    levels: ArrayLike = LARA_LEVELS,
    *,
    nu_range: tuple[float, float] = (0.0, np.pi),
    ratio_min: float = 0.88,
    n_points: int = 721,
) -> LaraPortrait:
    """The contours of Lara's Fig. 1 in closed form.

    Parameters
    ----------
    beta : float
        Triaxiality, ``0 ≤ β < 1`` (``RigidBody.beta``); Lara's figure uses 0.8.
    levels : array_like, shape (k,)
        Positive contour levels ``q``; default :data:`LARA_LEVELS`.
    nu_range : (float, float)
        Range of ``ν`` (radians).
    ratio_min : float
        Lower edge of the window in ``N/M`` (in ``[0, 1)``).
    n_points : int
        Samples in ``ν``.

    Returns
    -------
    LaraPortrait

    Examples
    --------
    >>> data = lara_portrait_data()
    >>> data.free.shape
    (12, 721)
    >>> i = len(data.nu) // 2                      # ν = π/2: 1 − q/3.6 and √(1 − q/1.8)
    >>> round(float(data.main[0, i]), 12), round(float(data.free[0, i]), 12)
    (0.999444444444, 0.999444290038)
    """
    b = float(as_finite(beta, "beta"))
    if not 0 <= b < 1:
        msg = f"expected 0 <= beta < 1, got beta = {b!r}"
        raise ValueError(msg)
    q = np.atleast_1d(as_finite(levels, "levels"))
    if q.ndim != 1 or q.size == 0 or np.any(q <= 0):
        msg = f"expected a 1-D sequence of positive levels, got {q.tolist()!r}"
        raise ValueError(msg)
    lo, hi = (float(x) for x in as_finite(nu_range, "nu_range"))
    if not lo < hi:
        msg = f"expected nu_range (lo, hi) with lo < hi, got {(lo, hi)!r}"
        raise ValueError(msg)
    r = float(as_finite(ratio_min, "ratio_min"))
    if not 0 <= r < 1:
        msg = f"expected 0 <= ratio_min < 1, got {r!r}"
        raise ValueError(msg)
    if int(n_points) != n_points or n_points < 2:
        msg = f"expected an integer n_points >= 2, got {n_points!r}"
        raise ValueError(msg)
    nu = np.linspace(lo, hi, int(n_points))
    k = 1 - b * np.cos(2 * nu)
    ratio = q[:, None] / k  # q/k
    arg = 1 - ratio
    free = np.where(arg >= 0, np.sqrt(np.abs(arg)), np.nan)
    main = 1 - 0.5 * ratio
    return LaraPortrait(b, q, nu, free, main, r)


def lara_portrait(
    beta: float = 0.8,
    levels: ArrayLike = LARA_LEVELS,
    *,
    nu_range: tuple[float, float] = (0.0, np.pi),
    ratio_min: float = 0.88,
    n_points: int = 721,
    ax: Axes | None = None,
) -> Figure:
    """Draw Lara's Fig. 1: free body (solid) and main problem of SAM rotation (dashed).

    Parameters
    ----------
    beta, levels, nu_range, ratio_min, n_points
        As in :func:`lara_portrait_data`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        With the drawn :class:`LaraPortrait` as ``figure.andoyer_data``.

    Examples
    --------
    >>> fig = lara_portrait()
    >>> fig.andoyer_data.beta, fig.andoyer_data.ratio_min
    (0.8, 0.88)
    """
    data = lara_portrait_data(beta, levels, nu_range=nu_range, ratio_min=ratio_min, n_points=n_points)
    fig, ax = new_axes(ax, figsize=(8.5, 4.8))
    for j in range(len(data.levels)):
        ax.plot(data.nu, data.free[j], color="k", lw=1.0, label="free body, eq. (4)" if j == 0 else None)
        ax.plot(
            data.nu,
            data.main[j],
            color="tab:red",
            lw=1.0,
            ls="--",
            label="main problem, eq. (8)" if j == 0 else None,
        )
    ax.set_xlim(data.nu[0], data.nu[-1])
    ax.set_ylim(data.ratio_min, 1.0)
    ax.set_xlabel("$\\nu = l$ (rad)")
    ax.set_ylabel("$N/M = L/G = \\cos J$")
    ax.set_title(
        f"Reduced phase space: $\\mathcal{{H}}_0^* = \\mathcal{{A}}^* = q$, $\\beta = {data.beta:g}$"
    )
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", frameon=False)
    fig.andoyer_data = data  # type: ignore[attr-defined]
    return fig
