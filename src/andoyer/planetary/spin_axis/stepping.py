r"""Norm-preserving, high-order stepping of ``ṡ = α(t) (s·n(t)) (s×n(t))``.

With ``n`` and ``α`` frozen at a time ``τ`` the flow conserves ``s·n`` and is therefore an
exact rotation of ``s`` about ``n`` by the angle ``θ = −α (s·n) h`` in a time ``h``
(Rodrigues: ``s cos θ + n×s sin θ + n (n·s)(1 − cos θ)``, with ``1 − cos θ = 2 sin²(θ/2)``;
:func:`~andoyer.compositions.turn_about`, the kernel the secular gravity gradient turns ``M`` with).
The *exponential midpoint* step ``E(h)``, that rotation with ``n, α`` taken at the middle of
the step ``t + h/2``, is symmetric (``E(−h)`` from ``t + h`` undoes it: the rotation about
``n(t + h/2)`` conserves ``s·n``, so the angle is the same), hence of order 2, and the
palindromic compositions ``E(γ_S h)⋯E(γ_1 h)`` of
:data:`~andoyer.compositions.COMPOSITIONS` raise it to order 4, 6 or 8 (Yoshida
1990; Kahan & Li 1997). Every stage is a rotation, so ``|s| = 1`` to round-off; ``s`` is
also rescaled to unit length after each step so that round-off cannot accumulate.

The orbit is sampled once, vectorised, at every stage's midpoint time; the loop over the
stages runs compiled by :func:`andoyer._jit.jit` when numba is installed, or as the same
Python source otherwise.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import jit
from andoyer.compositions import COMPOSITIONS, turn_about

__all__ = ["rotate_stages", "stage_times"]

Array = NDArray[np.float64]


def stage_times(starts: Array, steps: Array, order: int) -> tuple[Array, Array]:
    """Midpoint times and durations of every stage of every step.

    Parameters
    ----------
    starts : ndarray, shape (K,)
        Start time of each step.
    steps : ndarray, shape (K,)
        Signed step sizes.
    order : {2, 4, 6, 8}

    Returns
    -------
    midpoints, durations : ndarray, shape (K·S,)
        ``S`` the number of stages of the composition.

    Examples
    --------
    >>> m, d = stage_times(np.array([0.0, 1.0]), np.array([1.0, 1.0]), 2)
    >>> m.tolist(), d.tolist()
    ([0.5, 1.5], [1.0, 1.0])
    """
    if order not in COMPOSITIONS:
        msg = f"expected an order in {sorted(COMPOSITIONS)}, got {order!r}"
        raise ValueError(msg)
    gamma = COMPOSITIONS[order]
    before = np.concatenate([[0.0], np.cumsum(gamma)[:-1]])
    mid = starts[:, None] + steps[:, None] * (before + 0.5 * gamma)[None, :]
    return mid.ravel(), (steps[:, None] * gamma[None, :]).ravel()


@jit
def rotate_stages(s0: Array, normals: Array, rates: Array, durations: Array, stages: int, out: Array) -> None:
    """Apply the exact frozen-orbit rotations stage by stage; store ``s`` after every step.

    Parameters
    ----------
    s0 : ndarray, shape (M, 3)
        Initial unit axes of ``M`` independent runs.
    normals : ndarray, shape (K·S, 3)
        Orbit normal at each stage's midpoint (shared by the runs).
    rates : ndarray, shape (M, K·S)
        ``α`` at each stage's midpoint, per run.
    durations : ndarray, shape (K·S,)
        Signed stage durations.
    stages : int
        ``S``.
    out : ndarray, shape (M, K, 3)
        Filled with the axes at the end of each step.

    Examples
    --------
    A quarter turn about ``n = z`` of an axis at 60° (``s·n = 1/2``, rate ``π``, time 1):

    >>> out = np.empty((1, 1, 3))
    >>> s0 = np.array([[np.sqrt(0.75), 0.0, 0.5]])
    >>> rotate_stages(s0, np.array([[0.0, 0.0, 1.0]]), np.array([[np.pi]]), np.array([1.0]), 1, out)
    >>> np.round(out[0, 0], 12).tolist()  # turned by -π/2 about z
    [0.0, -0.866025403784, 0.5]
    """
    for m in range(s0.shape[0]):
        sx, sy, sz = s0[m, 0], s0[m, 1], s0[m, 2]
        for k in range(durations.shape[0]):
            nx, ny, nz = normals[k, 0], normals[k, 1], normals[k, 2]
            sx, sy, sz = turn_about(sx, sy, sz, nx, ny, nz, -rates[m, k] * durations[k])
            if k % stages == stages - 1:
                scale = 1.0 / np.sqrt(sx * sx + sy * sy + sz * sz)
                sx, sy, sz = sx * scale, sy * scale, sz * scale
                j = k // stages
                out[m, j, 0] = sx
                out[m, j, 1] = sy
                out[m, j, 2] = sz
