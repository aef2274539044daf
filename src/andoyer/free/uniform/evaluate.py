r"""The per-epoch formulas of the uniform motions, written once: the kernels.

With the half angles ``β = λt/2`` and ``α = Ωt/2`` of the motion derived in
:mod:`andoyer.free.uniform.setup` (``cos``, ``sin`` of a phase: :func:`turn`), the momentum
``m(t) = R_ŝ(−λt) m₀`` (:func:`momentum`) and the attitude ``q(t) = R_m̂(Ωt) q₀ R_ŝ(λt)``
(:func:`attitude`) from the constants of the set-up.  Each is one function of arithmetic only,
so the same text runs on floats inside numba kernels (registered with
:func:`andoyer._jit.jitable`: :mod:`andoyer.free.uniform.evaluate_compiled` and
:mod:`andoyer.free.step_scalar` inline them) and on whole numpy arrays, one array per component
(:mod:`andoyer.free.uniform.evaluate_numpy`); both give the same bits
(``tests/free/uniform/test_free_uniform_kernels.py``).

Vectors and quaternions are passed as anything indexed by component: a 3- or 4-tuple, a
row of a table, or an array whose first axis holds the components.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable

__all__ = ["attitude", "momentum", "turn"]


@jitable
def turn(f):
    """``cos πf`` and ``sin πf`` of a phase ``f`` in cycles (the half angles ``β = λt/2``, ``α = Ωt/2``).

    Parameters
    ----------
    f : float or ndarray, shape (...)
        Phase in cycles, ``|f| ≤ 1/2``.

    Returns
    -------
    c, s : float or ndarray, shape (...)

    Examples
    --------
    >>> [round(float(v), 12) for v in turn(0.5)]
    [0.0, 1.0]
    """
    a = np.pi * f
    return np.cos(a), np.sin(a)


@jitable
def momentum(cb, sb, m_par, m_perp, m_cross):
    """``m(t) = R_ŝ(−λt) m₀ = m_par + cos(λt) m_perp − sin(λt) m_cross``, from ``β = λt/2``.

    Parameters
    ----------
    cb, sb : float or ndarray, shape (...)
        ``cos β``, ``sin β`` (:func:`turn`).
    m_par, m_perp, m_cross : indexable of 3 float or ndarray, shape (...)
        The constants of :func:`decomposition`, broadcast against ``cb``.

    Returns
    -------
    tuple of 3 float or ndarray, shape (...)

    Examples
    --------
    >>> [float(c) for c in momentum(0.0, 1.0, (0.0, 0.0, 3.0), (1.0, 2.0, 0.0), (-2.0, 1.0, 0.0))]  # λt = π
    [-1.0, -2.0, 3.0]
    """
    c2 = 1.0 - 2.0 * sb * sb
    s2 = -2.0 * sb * cb  # sin(−λt)
    return (
        m_par[0] + m_perp[0] * c2 + m_cross[0] * s2,
        m_par[1] + m_perp[1] * c2 + m_cross[1] * s2,
        m_par[2] + m_perp[2] * c2 + m_cross[2] * s2,
    )


@jitable
def attitude(cb, sb, ca, sa, q1, q2, q3, q4):
    """``q(t) = R_m̂(Ωt) q₀ R_ŝ(λt)`` from the half angles ``β = λt/2``, ``α = Ωt/2``.

    Parameters
    ----------
    cb, sb, ca, sa : float or ndarray, shape (...)
        ``cos β``, ``sin β``, ``cos α``, ``sin α`` (:func:`turn`).
    q1, q2, q3, q4 : indexable of 4 float or ndarray, shape (...)
        ``q₀`` and the quaternions of :func:`quaternions`.

    Returns
    -------
    tuple of 4 float or ndarray, shape (...)

    Examples
    --------
    >>> one, k = (0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 0.0)
    >>> [float(c) for c in attitude(1.0, 0.0, 0.0, 1.0, one, k, k, (0.0, 0.0, 0.0, -1.0))]  # Ωt = π about z
    [0.0, 0.0, 1.0, 0.0]
    """
    w1, w2, w3, w4 = ca * cb, ca * sb, sa * cb, sa * sb
    return (
        _combine(w1, w2, w3, w4, q1[0], q2[0], q3[0], q4[0]),
        _combine(w1, w2, w3, w4, q1[1], q2[1], q3[1], q4[1]),
        _combine(w1, w2, w3, w4, q1[2], q2[2], q3[2], q4[2]),
        _combine(w1, w2, w3, w4, q1[3], q2[3], q3[3], q4[3]),
    )


@jitable
def _combine(w1, w2, w3, w4, a, b, c, d):
    """``w₁ a + w₂ b + w₃ c + w₄ d``, summed left to right."""
    return w1 * a + w2 * b + w3 * c + w4 * d
