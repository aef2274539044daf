"""Exact rational numbers accepted by the series engine (never floats)."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import flint

__all__ = ["EXACT_TYPES", "as_rational", "to_fmpq"]

EXACT_TYPES = (int, Fraction, flint.fmpq, flint.fmpz)


def as_rational(value: Any, what: str = "an exact rational") -> Fraction:
    """Convert an int, Fraction, fmpz, fmpq or ``"p/q"`` string to a Fraction.

    Parameters
    ----------
    value : int, Fraction, flint.fmpz, flint.fmpq or str
        Floats (and bools) are refused: they are not exact.
    what : str
        Description used in the error message.

    Returns
    -------
    Fraction

    Examples
    --------
    >>> as_rational("3/4") + as_rational(1)
    Fraction(7, 4)
    """
    if isinstance(value, bool):
        msg = f"expected {what}, got {value!r}"
        raise ValueError(msg)
    if isinstance(value, (int, Fraction)):
        return Fraction(value)
    if isinstance(value, flint.fmpz):
        return Fraction(int(value))
    if isinstance(value, flint.fmpq):
        return Fraction(int(value.p), int(value.q))
    if isinstance(value, str):
        try:
            return Fraction(value)
        except ValueError:
            pass
    msg = f"expected {what}, got {value!r}"
    raise ValueError(msg)


def to_fmpq(value: Any) -> flint.fmpq:
    """Convert an exact rational (see :func:`as_rational`) to ``flint.fmpq``.

    Parameters
    ----------
    value : int, Fraction, flint.fmpz, flint.fmpq or str

    Returns
    -------
    flint.fmpq

    Examples
    --------
    >>> to_fmpq("-2/6")
    -1/3
    """
    if isinstance(value, flint.fmpq):
        return value
    r = as_rational(value)
    return flint.fmpq(r.numerator, r.denominator)
