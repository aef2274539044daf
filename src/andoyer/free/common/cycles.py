r"""Phases reduced modulo one cycle and their ``sin``, ``cos``, written once: the kernels.

:func:`phase` reduces ``ν t`` with a double-double frequency ``ν = ν_hi + ν_lo`` to
``[−1/2, 1/2]`` cycles (the error of ``ν_hi t`` formed exactly), the per-state form of
:func:`andoyer.free.common.cycles_numpy.cycles`, whose derivation it shares;
:func:`sincos_cycles` gives ``sin(2πf)``, ``cos(2πf)`` of a reduced phase (from
:func:`sincos_half_cycles`, ``sin(πf)``, ``cos(πf)``).  Each is one text
of arithmetic (:func:`andoyer._jit.jitable`), inlined by the compiled drivers and run on
arrays by the numpy ones.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable
from andoyer.special.compensated import two_prod

__all__ = ["phase", "sincos_cycles", "sincos_half_cycles"]


@jitable
def phase(hi, lo, t):
    """``ν t`` reduced to ``[-1/2, 1/2]`` cycles, per state: the kernel form of ``cycles``.

    The same value as :func:`andoyer.free.common.cycles_numpy.cycles` (the error of ``ν_hi t`` is
    exact either way: a fused multiply-add when compiled, Dekker's product here), without the
    pre-split frequency that pays off only on arrays of epochs; compiled loops call it inline.

    Parameters
    ----------
    hi, lo : float or ndarray, shape (...)
        The double-double frequency ``ν`` in cycles per unit time.
    t : float or ndarray, shape (...)
        Times, broadcast with ``ν``.

    Returns
    -------
    float or ndarray, shape (...)
        The reduced phase in cycles.

    Examples
    --------
    >>> float(phase(1.0 / 3.0, 1.850371707708594e-17, 3e15))  # 1/3 as a double-double
    0.0
    """
    p, e = two_prod(hi, t)
    e += lo * t
    f = p - np.rint(p)
    f += e
    return f - np.rint(f)


# Polynomials in f² for sin(πf)/f and cos(πf) on |f| ≤ 1/2: least-squares fits on
# Chebyshev nodes at 50 digits (relative error 3e-19 for the sine, absolute 4e-18 for the
# cosine, so rounding dominates); nine terms where the Taylor series needs twelve.
_SIN = (
    3.141592653589793,
    -5.167712780049969,
    2.550164039877294,
    -0.5992645293187369,
    0.08214588656987074,
    -0.007370430478578422,
    0.0004662996879148879,
    -2.190318333528108e-05,
    7.694706725679123e-07,
)
_COS = (
    1.0,
    -4.934802200544676,
    4.058712126416498,
    -1.335262768843456,
    0.23533063012967062,
    -0.02580688873817758,
    0.001929556278037417,
    -0.00010456656706174584,
    4.149578027057121e-06,
)


@jitable
def sincos_half_cycles(f):
    """``sin(πf)`` and ``cos(πf)`` for ``|f| ≤ 1/2`` (a half angle: ``|πf| ≤ π/2``).

    The polynomials above; absolute error a few 1e-17 beyond the rounding of the result.

    Parameters
    ----------
    f : float or ndarray, shape (...)
        Half-cycles, ``|f| ≤ 1/2``.

    Returns
    -------
    sin, cos : float or ndarray, shape (...)

    Examples
    --------
    >>> s, c = sincos_half_cycles(np.array([0.25, -0.5]))
    >>> s.round(15).tolist(), c.round(15).tolist()
    ([0.707106781186548, -1.0], [0.707106781186548, 0.0])
    """
    # in place on arrays (this runs per epoch; fresh temporaries cost page faults), plain
    # arithmetic on floats: the same text is the compiled kernel (andoyer.free.triaxial.evaluate_compiled)
    u = f * f
    sh = u * _SIN[8]
    sh += _SIN[7]
    ch = u * _COS[8]
    ch += _COS[7]
    for k in range(6, -1, -1):
        sh *= u
        sh += _SIN[k]
        ch *= u
        ch += _COS[k]
    sh *= f
    return sh, ch


@jitable
def sincos_cycles(f):
    """``sin(2πf)`` and ``cos(2πf)`` for a phase ``|f| ≤ 1/2`` in cycles.

    Polynomials for the half angle ``πf`` (``|πf| ≤ π/2``, :func:`sincos_half_cycles`) and
    the double-angle formulas ``sin 2a = 2 sin a cos a``, ``cos 2a = (cos a − sin a)(cos a + sin a)``;
    absolute error a few 1e-16, and no argument reduction (the phase is already reduced).  It
    is several times cheaper than ``np.sin`` and ``np.cos`` on float64 arrays.

    Parameters
    ----------
    f : float or ndarray, shape (...)
        Phases in cycles, ``|f| ≤ 1/2``.

    Returns
    -------
    sin, cos : float or ndarray, shape (...)

    Examples
    --------
    >>> s, c = sincos_cycles(np.array([0.125, -0.25]))
    >>> s.round(15).tolist(), c.round(15).tolist()
    ([0.707106781186548, -1.0], [0.707106781186548, 0.0])
    """
    sh, ch = sincos_half_cycles(f)
    s = sh * ch
    s += s
    c = ch - sh
    ch += sh
    c *= ch
    return s, c
