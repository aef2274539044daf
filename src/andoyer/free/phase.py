r"""Phases ``ν t`` reduced modulo one cycle, with a double-double frequency.

A phase of ``N`` cycles computed as ``fl(ν t)`` carries an error of about ``N`` ulps of
one cycle from the rounding of ``ν`` alone; at 100 periods of a near-separatrix body that
is already ``10⁻¹³`` of the body angular momentum.  Here ``ν = ν_hi + ν_lo`` is a
double-double and the product with the (exact, float64) time is formed error-free
(Dekker's product with ``ν_hi`` split once per body), so the reduced phase

.. math:: f = (\nu_{hi} t - \operatorname{round}(\nu_{hi} t)) + e + \nu_{lo} t + f_0
          \pmod 1, \qquad f \in [-\tfrac12, \tfrac12)

is exact to a few ulps of one cycle for any ``t``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import jitable
from andoyer.special.compensated import split, two_prod

__all__ = ["Frequency", "cycles", "frequency", "phase", "sincos_cycles"]


class Frequency(NamedTuple):
    """A double-double frequency (cycles per unit time) with ``hi`` pre-split.

    Attributes
    ----------
    hi, lo : ndarray
        ``ν = hi + lo``.
    hh, hl : ndarray
        Dekker halves of ``hi``.
    """

    hi: np.ndarray
    lo: np.ndarray
    hh: np.ndarray
    hl: np.ndarray


def frequency(hi, lo=0.0):
    """Build a :class:`Frequency` from a double-double ``(hi, lo)`` in cycles per unit time.

    Parameters
    ----------
    hi, lo : array_like
        High and low parts, broadcast together.

    Returns
    -------
    Frequency

    Examples
    --------
    >>> f = frequency(0.1)
    >>> float(f.hh + f.hl)
    0.1
    """
    hi, lo = np.broadcast_arrays(np.asarray(hi, dtype=np.float64), np.asarray(lo, dtype=np.float64))
    hh, hl = split(hi)
    return Frequency(hi, lo, hh, hl)


def cycles(freq: Frequency, t, tt=None, offset=0.0):
    """Fractional part of ``offset + ν t`` in ``[-1/2, 1/2)``, without losing the phase.

    Parameters
    ----------
    freq : Frequency
        Double-double frequency, broadcast against ``t``.
    t : ndarray
        Times (float64).
    tt : tuple of ndarray, optional
        ``split(t)``, when several phases share the same times.
    offset : array_like, optional
        Phase at ``t = 0`` in cycles.

    Returns
    -------
    ndarray
        The reduced phase in cycles.

    Examples
    --------
    >>> f = frequency(1.0 / 3.0, 1.850371707708594e-17)  # 1/3 as a double-double
    >>> float(cycles(f, np.float64(3e15)))
    0.0
    """
    th, tl = split(t) if tt is None else tt
    # in place: this runs per epoch, and fresh temporaries cost page faults
    p = np.asarray(freq.hi * t)  # 0-d arrays, not numpy scalars, accept out=
    e = np.asarray(freq.hh * th)
    e -= p
    tmp = np.asarray(freq.hh * tl)
    e += tmp
    np.multiply(freq.hl, th, out=tmp)
    e += tmp
    np.multiply(freq.hl, tl, out=tmp)
    e += tmp
    np.multiply(freq.lo, t, out=tmp)
    e += tmp
    f = np.asarray(np.round(p))
    np.subtract(p, f, out=f)
    f += e
    f += offset
    np.round(f, out=p)
    f -= p
    return f


@jitable
def phase(hi, lo, t):
    """``ν t`` reduced to ``[-1/2, 1/2]`` cycles, per state: the kernel form of :func:`cycles`.

    The same value as :func:`cycles` (the error of ``ν_hi t`` is exact either way: a
    fused multiply-add when compiled, Dekker's product here), without the pre-split
    frequency that pays off only on arrays of epochs; compiled loops call it inline.

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
def sincos_cycles(f):
    """``sin(2πf)`` and ``cos(2πf)`` for a phase ``|f| ≤ 1/2`` in cycles.

    Polynomials for the half angle ``πf`` (``|πf| ≤ π/2``) and the double-angle formulas
    ``sin 2a = 2 sin a cos a``, ``cos 2a = (cos a − sin a)(cos a + sin a)``; absolute error
    a few 1e-16, and no argument reduction (the phase is already reduced).  It is several
    times cheaper than ``np.sin`` and ``np.cos`` on float64 arrays.

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
    # in place on arrays (this runs per epoch; fresh temporaries cost page faults), plain
    # arithmetic on floats: the same text is the compiled kernel (andoyer.free.compiled_eval)
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
    s = sh * ch
    s += s
    c = ch - sh
    ch += sh
    c *= ch
    return s, c
