r"""The regime of torque-free rotation: one vocabulary (:class:`Regime`) and one classification.

With the sorted moments ``A ≤ B ≤ C``, the angular momentum ``G = |m|`` and twice the
kinetic energy ``D = 2T = Σ mᵢ²/Iᵢ``, the body angular momentum of a triaxial body
circulates around the axis of maximum inertia (SAM, ``G²/C ≤ D < G²/B``), around the
axis of minimum inertia (LAM, ``G²/B < D ≤ G²/A``), or lies on the separatrix
(``D = G²/B``).  The sign of

.. math:: P_2 = G^2/B - D = m_C^2 \Big(\frac1B - \frac1C\Big) - m_A^2 \Big(\frac1A - \frac1B\Big)

decides; times ``A B C > 0`` it is ``t₁ − t₂`` with ``t₁ = m_C² (C − B) A`` and
``t₂ = m_A² (B − A) C``, a difference of nearly equal numbers near the separatrix, so it is
formed in double-double arithmetic (:mod:`andoyer.special.compensated`) from error-free
products of the inputs: the differences of moments and the squares of the components are
exact, each factor is scaled into ``[1/2, 1)`` by its own power of two where one lies
outside ``[2⁻¹⁵⁰, 2¹⁵⁰]`` (so nothing overflows or underflows, whatever the units and
however small one component is beside the others), and the two terms carry about 106
bits.  The sign is therefore that of the exact rational value for the floating-point
inputs as given: exactly zero on the separatrix whenever the products fit in 106 bits
(inputs of up to about 26 significant bits, such as every example and test here), and
otherwise wrong only if the two terms agree to about 100 bits without being equal.  Two
equal moments make a body axisymmetric, three a sphere, and a zero momentum is rest,
whatever the rest.

:func:`regime_code` is that decision for one state, written once with
:func:`andoyer._jit.select` instead of ``if`` (and :func:`andoyer._jit.every` for its one
branch, the rescaling of extreme magnitudes): compiled by numba it runs per state in a loop
(:func:`andoyer.free.common.scaling_compiled.classify_and_scale`), and called from Python it runs
on whole arrays (:func:`classify`, :meth:`andoyer.RigidBody.regime`), with the same result
bit for bit.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._jit import every, exponent, jitable, select
from andoyer.special.compensated import dd_add, dd_mul, two_prod, two_sum

__all__ = [
    "Regime",
    "check_inputs",
    "classify",
    "regime_code",
    "regime_codes",
    "regime_names",
]


class Regime(IntEnum):
    """Kind of torque-free motion of one body and state: the package's one regime vocabulary.

    :meth:`andoyer.RigidBody.regime`, :func:`classify`, :class:`andoyer.free.FreeMotion` and
    :meth:`andoyer.FreeRotation.regime` all use these codes (or their names).
    """

    SAM = 0
    """Short-axis mode: the momentum circles the axis of maximum inertia (triaxial body, ``2T < G²/B``)."""
    LAM = 1
    """Long-axis mode: the momentum circles the axis of minimum inertia (triaxial body, ``2T > G²/B``)."""
    SEPARATRIX = 2
    """On the separatrix (``2T = G²/B``), including steady spin about the middle axis."""
    AXISYMMETRIC = 3
    """Two equal moments (not three): regular precession."""
    SPHERE = 4
    """Three equal moments: uniform rotation about the fixed momentum."""
    REST = 5
    """Zero angular momentum: the body does not move."""


# The codes as plain ints, constants of the compiled kernel.
_SAM, _LAM, _SEPARATRIX = int(Regime.SAM), int(Regime.LAM), int(Regime.SEPARATRIX)
_AXISYMMETRIC, _SPHERE, _REST = int(Regime.AXISYMMETRIC), int(Regime.SPHERE), int(Regime.REST)
_NAMES = np.array([r.name for r in Regime])


def check_inputs(moments: ArrayLike, m0: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Validate moments and body angular momenta and broadcast them to a common shape.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments along body axes b1, b2, b3: positive, finite, any order.  The
        solution does not need the triangle inequality ``A + B ≥ C`` of a mass distribution
        (:class:`~andoyer.RigidBody` warns where it fails).
    m0 : array_like, shape (..., 3)
        Body-frame angular momentum, finite.

    Returns
    -------
    moments, m0 : ndarray, shape (..., 3)
        Float64 arrays broadcast against each other.

    Raises
    ------
    ValueError
        On a wrong shape, a non-finite value or a non-positive moment.

    Examples
    --------
    >>> moments, m = check_inputs([1.0, 2.0, 2.5], [[0.1, 0.2, 1.0], [1.0, 0.0, 0.0]])
    >>> moments.shape, m.shape
    ((2, 3), (2, 3))
    """
    moments = np.asarray(moments, dtype=np.float64)
    m0 = np.asarray(m0, dtype=np.float64)
    for name, a in (("moments", moments), ("m0", m0)):
        if a.ndim == 0 or a.shape[-1] != 3:
            raise ValueError(f"expected {name} with shape (..., 3), got shape {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"expected finite {name}, got {a[~np.isfinite(a)].ravel()[:3]}")
    if np.any(moments <= 0):
        bad = moments[moments <= 0].ravel()[:3]
        raise ValueError(f"expected positive moments of inertia, got {bad}")
    if moments.shape == m0.shape:  # nothing to broadcast (one body per state, or one state)
        return moments, m0
    shape = np.broadcast_shapes(moments.shape, m0.shape)
    return np.broadcast_to(moments, shape), np.broadcast_to(m0, shape)


@jitable
def _moderate(x):
    """``2⁻¹⁵⁰ ≤ |x| ≤ 2¹⁵⁰``: products of five such factors (and their rounding errors) are normal."""
    return (np.abs(x) >= 7.006492321624085e-46) & (np.abs(x) <= 1.42724769270596e45)


@jitable
def _unit(x):
    """``x = f·2^e`` with ``1/2 ≤ |f| < 1`` (``f = e = 0`` for ``x = 0``): ``(f, e)``, exact."""
    e = exponent(x)
    return np.ldexp(x, -e), e


@jitable
def _term(m, dh, dl, c):
    """``m² (d_h + d_l) c = (t_h + t_l)·2^e`` with the double-double ``t`` in ``[1/16, 1)`` or 0.

    Each factor is scaled into ``[1/2, 1)`` by its own power of two, so that the squares and
    products neither overflow nor underflow whatever the magnitudes of the state.
    """
    mf, em = _unit(m)
    cf, ec = _unit(c)
    ed = exponent(dh)
    th, tl = dd_mul(*two_prod(mf, mf), *dd_mul(np.ldexp(dh, -ed), np.ldexp(dl, -ed), cf, 0.0))
    return th, tl, 2 * em + ed + ec


@jitable
def regime_code(i1, i2, i3, m1, m2, m3):
    r"""The :class:`Regime` code of a state: the package's one regime decision.

    Rest (``m = 0``) first, then a sphere (``A = C``), an axisymmetric body (``B = A`` or
    ``B = C``), then the sign of ``P₂ = G²/B − 2T`` in double-double arithmetic (module
    docstring): positive SAM, negative LAM, zero the separatrix.  Written once for floats
    and arrays: :func:`andoyer._jit.select` chooses and :func:`andoyer._jit.every` branches
    (to rescale where a factor lies outside ``[2⁻¹⁵⁰, 2¹⁵⁰]``: per state compiled, for the
    whole array if any state needs it on arrays), so numba compiles it per state and numpy
    evaluates it on whole arrays; the moments are sorted by ``min``/``max``
    (the median ``max(min(a, b), min(max(a, b), c))``).  Any finite state is classified
    exactly (module docstring), whatever its magnitudes.

    Parameters
    ----------
    i1, i2, i3 : float or ndarray, shape (...)
        Principal moments along the body axes (positive, finite, any order).
    m1, m2, m3 : float or ndarray, shape (...)
        Body angular momentum (finite), broadcast with the moments.

    Returns
    -------
    int or ndarray of int, shape (...)
        :class:`Regime` codes.

    Examples
    --------
    >>> Regime(int(regime_code(1.0, 2.0, 3.0, 0.0, 1.0, 0.0))).name
    'SEPARATRIX'
    >>> import numpy as np
    >>> regime_code(1.0, 2.0, 3.0, np.array([0.1, 1.0]), 0.2, np.array([1.0, 0.1])).tolist()
    [0, 1]
    """
    A = np.minimum(np.minimum(i1, i2), i3)
    C = np.maximum(np.maximum(i1, i2), i3)
    B = np.maximum(np.minimum(i1, i2), np.minimum(np.maximum(i1, i2), i3))
    # The components along A and C: unique where the body is triaxial, the only case they decide.
    ma = select(i1 == A, m1, select(i2 == A, m2, m3))
    mc = select(i1 == C, m1, select(i2 == C, m2, m3))
    # P₂ A B C = t₁ − t₂, t₁ = m_C² (C − B) A, t₂ = m_A² (B − A) C (differences exact, two_sum)
    d1h, d1l = two_sum(C, -B)
    d2h, d2l = two_sum(B, -A)
    if every(_moderate(A) & _moderate(C) & (_moderate(ma) | (ma == 0)) & (_moderate(mc) | (mc == 0))):
        # no product can overflow or underflow (the common case, and the fast one)
        t1 = dd_mul(*two_prod(mc, mc), *dd_mul(d1h, d1l, A, 0.0))
        t2 = dd_mul(*two_prod(ma, ma), *dd_mul(d2h, d2l, C, 0.0))
        p2 = dd_add(t1[0], t1[1], -t2[0], -t2[1])[0]
    else:
        t1h, t1l, e1 = _term(mc, d1h, d1l, A)
        t2h, t2l, e2 = _term(ma, d2h, d2l, C)
        # at the larger exponent: a term 64 binades below the other (≥ 1/16) cannot change the sign
        k = e1 - e2
        s1 = np.minimum(np.maximum(-k, 0), 64)
        s2 = np.minimum(np.maximum(k, 0), 64)
        p2 = dd_add(np.ldexp(t1h, -s1), np.ldexp(t1l, -s1), -np.ldexp(t2h, -s2), -np.ldexp(t2l, -s2))[0]
    code = select(p2 > 0, _SAM, select(p2 < 0, _LAM, _SEPARATRIX))
    code = select((B == A) | (B == C), _AXISYMMETRIC, code)
    code = select(A == C, _SPHERE, code)
    return select((m1 == 0) & (m2 == 0) & (m3 == 0), _REST, code)


def regime_codes(moments: NDArray[np.float64], m0: NDArray[np.float64]) -> NDArray[np.int8]:
    """:func:`regime_code` on arrays of validated states (:func:`check_inputs`), without checks.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)
        Positive finite moments and finite body angular momenta, broadcast together.

    Returns
    -------
    ndarray of int8, shape (...)
        :class:`Regime` codes.

    Examples
    --------
    >>> regime_codes(np.array([0.375, 0.5, 0.75]), np.array([0.0, 0.75, 0.0])).tolist()
    2
    """
    i1, i2, i3 = (moments[..., k] for k in range(3))
    m1, m2, m3 = (m0[..., k] for k in range(3))
    shape = np.broadcast_shapes(moments.shape, m0.shape)[:-1]
    return np.broadcast_to(regime_code(i1, i2, i3, m1, m2, m3), shape).astype(np.int8)


def classify(moments: ArrayLike, m0: ArrayLike) -> NDArray[np.int8]:
    """Regime of the torque-free motion of each body and state.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments (any order, positive).
    m0 : array_like, shape (..., 3)
        Body-frame angular momentum.

    Returns
    -------
    ndarray of int8, shape (...)
        :class:`Regime` codes.  Exact equalities decide: two equal moments make a body
        axisymmetric, and the separatrix is ``2T = G²/B`` for the floating-point inputs as
        given (evaluated in double-double arithmetic, :func:`regime_code`).

    Raises
    ------
    ValueError
        On the inputs :func:`check_inputs` refuses.

    Examples
    --------
    >>> moments = [1.0, 2.0, 3.0]
    >>> [Regime(int(r)).name for r in classify(moments, [[0.1, 0.2, 1.0], [1.0, 0.2, 0.1],
    ...                                              [0.0, 1.0, 0.0]])]
    ['SAM', 'LAM', 'SEPARATRIX']
    >>> Regime(int(classify([2.0, 2.0, 3.0], [0.3, 0.0, 1.0]))).name
    'AXISYMMETRIC'
    """
    moments, m0 = check_inputs(moments, m0)
    return regime_codes(moments, m0)


def regime_names(codes: ArrayLike) -> NDArray[np.str_]:
    """The :class:`Regime` names of ``codes``, same shape.

    Parameters
    ----------
    codes : array_like of int, shape (...)
        :class:`Regime` codes.

    Returns
    -------
    ndarray of str, shape (...)
        ``"SAM"``, ``"LAM"``, ``"SEPARATRIX"``, ``"AXISYMMETRIC"``, ``"SPHERE"`` or ``"REST"``.

    Examples
    --------
    >>> regime_names([0, 5]).tolist()
    ['SAM', 'REST']
    """
    return _NAMES[np.asarray(codes, dtype=np.intp)]
