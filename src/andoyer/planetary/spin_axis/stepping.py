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

from andoyer._jit import jit, jitable
from andoyer.compositions import COMPOSITIONS, turn_about
from andoyer.planetary.orbits.secular import sample_normal

__all__ = ["rotate_on_samples", "rotate_stages", "stage_rate", "stage_times"]

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


@jitable
def stage_rate(parameters, m, t, f):
    """``α`` of run ``m`` at time ``t``: ``α_⊙ (1 + W T_d t)(1 + (Ḣ/H) t) [f + β (1 + 2N T_d t)]``.

    :meth:`~andoyer.planetary.spin_axis.SpinAxisModel.rate` from the run's five parameters (rows
    ``α_⊙, β, W T_d, 2N T_d, Ḣ/H`` of ``parameters``, shape (5, M)) and the orbit's
    ``f = (1 − e²)^{−3/2}``; for the compiled kernels (and floats).

    Examples
    --------
    >>> parameters = np.array([[2.0], [0.5], [0.0], [0.0], [0.0]])
    >>> float(stage_rate(parameters, 0, 100.0, 1.0))  # 2 (1 + 0.5)
    3.0
    """
    factor = (1 + parameters[2, m] * t) * (1 + parameters[4, m] * t)
    return parameters[0, m] * factor * (f + parameters[1, m] * (1 + parameters[3, m] * t))


@jitable
def _close_step(sx, sy, sz, out, j):
    """Renormalise the runs' axes at the end of step ``j`` and store them in ``out[:, j]``."""
    for m in range(sx.size):
        scale = 1.0 / np.sqrt(sx[m] * sx[m] + sy[m] * sy[m] + sz[m] * sz[m])
        sx[m] *= scale
        sy[m] *= scale
        sz[m] *= scale
        out[m, j, 0] = sx[m]
        out[m, j, 1] = sy[m]
        out[m, j, 2] = sz[m]


@jit
def rotate_stages(
    s0: Array,
    normals: Array,
    times: Array,
    orbit_factor: Array,
    parameters: Array,
    durations: Array,
    stages: int,
    out: Array,
) -> None:
    """Apply the exact frozen-orbit rotations stage by stage; store ``s`` after every step.

    One kernel for one run and many: the runs share the orbit (its normal and eccentricity
    factor are read once per stage) and are the innermost loop, so that it vectorises; a
    single history is a chunk of one run. Each run's
    ``α = α_⊙ (1 + W T_d t)(1 + (Ḣ/H) t) [f(e) + β (1 + 2N T_d t)]``
    (:meth:`~andoyer.planetary.spin_axis.SpinAxisModel.rate`) is formed here from its five
    parameters and the shared ``f(e) = (1 − e²)^{−3/2}``, so no (stages × runs) array is stored.

    Parameters
    ----------
    s0 : ndarray, shape (M, 3)
        Initial unit axes of ``M`` independent runs.
    normals : ndarray, shape (K·S, 3)
        Orbit normal at each stage's midpoint (shared by the runs).
    times : ndarray, shape (K·S,)
        The stages' midpoint times ``t`` (Julian years from J2000).
    orbit_factor : ndarray, shape (K·S, M) or (K·S, 1)
        ``f(e)`` at the midpoints: shared (one column) or per run (a run's own fixed ``e``).
    parameters : ndarray, shape (5, M)
        Rows ``α_⊙, β, W T_d, 2N T_d, Ḣ/H`` of every run.
    durations : ndarray, shape (K·S,)
        Signed stage durations.
    stages : int
        ``S``.
    out : ndarray, shape (M, K, 3)
        Filled with the axes at the end of each step.

    Examples
    --------
    A quarter turn about ``n = z`` of an axis at 60° (``s·n = 1/2``, ``α = π``, time 1):

    >>> out = np.empty((1, 1, 3))
    >>> s0 = np.array([[np.sqrt(0.75), 0.0, 0.5]])
    >>> parameters = np.array([[np.pi], [0.0], [0.0], [0.0], [0.0]])
    >>> one = np.ones((1, 1))
    >>> rotate_stages(s0, np.array([[0.0, 0.0, 1.0]]), np.zeros(1), one, parameters, np.ones(1), 1, out)
    >>> np.round(out[0, 0], 12).tolist()  # turned by -π/2 about z
    [0.0, -0.866025403784, 0.5]
    """
    runs = s0.shape[0]
    count = durations.shape[0]
    if normals.shape[0] != count or times.shape[0] != count or orbit_factor.shape[0] != count:
        raise ValueError("expected normals, times and orbit factors with one row per stage")
    if parameters.shape[0] != 5 or parameters.shape[1] != runs or orbit_factor.shape[1] not in (1, runs):
        raise ValueError("expected parameters of shape (5, M) and orbit factors of 1 or M columns")
    shared = orbit_factor.shape[1] == 1
    sx = s0[:, 0].copy()
    sy = s0[:, 1].copy()
    sz = s0[:, 2].copy()
    for k in range(count):
        nx, ny, nz = normals[k, 0], normals[k, 1], normals[k, 2]
        t = times[k]
        h = durations[k]
        for m in range(runs):
            f = orbit_factor[k, 0] if shared else orbit_factor[k, m]
            alpha = stage_rate(parameters, m, t, f)
            sx[m], sy[m], sz[m] = turn_about(sx[m], sy[m], sz[m], nx, ny, nz, -alpha * h)
        if k % stages == stages - 1:
            _close_step(sx, sy, sz, out, k // stages)


@jit
def rotate_on_samples(
    s0: Array, starts: Array, sizes: Array, gamma: Array, w: Array, dw: Array, spacing: float, cx: int,
    cy: int, Lambda: float, rotation: Array, parameters: Array, out: Array,
) -> None:  # fmt: skip
    """:func:`rotate_stages` on a secular orbit's samples: each stage's normal and ``f(e)`` computed here.

    The orbit is the planet's Poincaré ``x, y`` (columns ``cx, cy`` of ``w``) and their rates
    ``dw``, every ``spacing`` years (signed) from J2000 (:class:`~andoyer.planetary.orbits.SecularOrbit`'s
    samples); at a stage's midpoint ``t``
    :func:`~andoyer.planetary.orbits.secular.sample_normal` interpolates ``x, y`` and gives the
    normal and ``√(1−e²)``, so ``f = (1 − e²)^{−3/2} = (√(1−e²))^{−3}`` — what
    ``SecularOrbit.normal_and_eccentricity`` gives, without the arrays of every stage.

    Parameters
    ----------
    s0 : ndarray, shape (M, 3)
    starts, sizes : ndarray, shape (K,)
        The steps' start times and signed sizes.
    gamma : ndarray, shape (S,)
        The composition's coefficients (:data:`~andoyer.compositions.COMPOSITIONS`).
    w, dw : ndarray of complex, shape (N, K')
    spacing : float
    cx, cy : int
    Lambda : float
    rotation : ndarray, shape (3, 3)
    parameters : ndarray, shape (5, M)
    out : ndarray, shape (M, K, 3)
        Filled with the axes at the end of each step.
    """
    runs = s0.shape[0]
    if parameters.shape[0] != 5 or parameters.shape[1] != runs or sizes.shape[0] != starts.shape[0]:
        raise ValueError("expected parameters of shape (5, M) and one size per step")
    sx = s0[:, 0].copy()
    sy = s0[:, 1].copy()
    sz = s0[:, 2].copy()
    for k in range(starts.size):
        before = 0.0
        for g in range(gamma.size):
            t = starts[k] + sizes[k] * (before + 0.5 * gamma[g])
            before += gamma[g]
            nx, ny, nz, root = sample_normal(w, dw, spacing, cx, cy, Lambda, rotation, t)
            f = 1.0 / (root * root * root)
            h = sizes[k] * gamma[g]
            for m in range(runs):
                alpha = stage_rate(parameters, m, t, f)
                sx[m], sy[m], sz[m] = turn_about(sx[m], sy[m], sz[m], nx, ny, nz, -alpha * h)
        _close_step(sx, sy, sz, out, k)
