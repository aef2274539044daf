"""Argument types for numbers on the command line: finite, or finite and positive.

argparse turns the ``ArgumentTypeError`` they raise into the one-line usage error (exit 2).
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable

__all__ = ["finite_number", "physical", "positive_number"]


def finite_number(text: str) -> float:
    """``float(text)``, refusing NaN, infinities and non-numbers.

    Examples
    --------
    >>> finite_number("-1e3")
    -1000.0
    >>> finite_number("nan")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: expected a finite number, got 'nan'
    """
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        msg = f"expected a finite number, got {text!r}"
        raise argparse.ArgumentTypeError(msg)
    return value


def positive_number(text: str) -> float:
    """A finite number above zero.

    Examples
    --------
    >>> positive_number("2.5")
    2.5
    >>> positive_number("0")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: expected a positive number, got '0'
    """
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        msg = f"expected a positive number, got {text!r}"
        raise argparse.ArgumentTypeError(msg)
    return value


def physical(name: str, degrees: bool = False) -> Callable[[str], float]:
    """The argument type of the physical parameter ``name`` of :mod:`andoyer.planetary.parameters`.

    The value is checked against the parameter's range there, as the API checks it, so that a
    command and a function answer a value out of range with the same words.

    Parameters
    ----------
    name : str
        A key of :data:`andoyer.planetary.parameters.PARAMETERS`.
    degrees : bool
        For an angle: the command line's value is in degrees (and stays so).

    Examples
    --------
    >>> physical("tidal_dissipation")("1")
    1.0
    >>> physical("tidal_dissipation")("-5")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: expected a tidal dissipation 0 <= T_d <= 1.2 (...), got -5.0
    """
    from andoyer.planetary.parameters import PARAMETERS

    parameter = PARAMETERS[name]

    def convert(text: str) -> float:
        try:
            value: object = float(text)
        except ValueError:
            value = text
        try:
            return parameter.check(value, degrees)
        except ValueError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    convert.__name__ = name  # argparse names the type in some of its messages
    convert.parameter = parameter  # type: ignore[attr-defined]  # for the tests' bad-input table
    convert.degrees = degrees  # type: ignore[attr-defined]
    return convert
