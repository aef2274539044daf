"""Argument types for numbers on the command line: finite, or finite and positive.

argparse turns the ``ArgumentTypeError`` they raise into the one-line usage error (exit 2).
"""

from __future__ import annotations

import argparse
import math

__all__ = ["finite_number", "positive_number"]


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
