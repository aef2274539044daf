r"""Phases ``ν t`` reduced modulo one cycle on arrays, with a double-double frequency (numpy driver).

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

from andoyer.special.compensated import split

__all__ = ["Frequency", "cycles", "frequency"]


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


