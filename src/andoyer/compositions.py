r"""Exact rotations about an axis, and the symmetric compositions that raise a step's order.

Two ideas shared by the steppers of :mod:`andoyer.integrate` and of
:mod:`andoyer.planetary.spin_axis`, written once here, below both.

**The exact rotation.** The flow of ``ẋ = c (k·x) (k × x)`` about a fixed unit axis ``k``
conserves ``k·x``, so in a time ``h`` it turns ``x`` about ``k`` by ``φ = c h (k·x)``
(Rodrigues, with ``1 − cos φ = 2 sin²(φ/2)`` so that small angles lose no digits):

.. math:: \mathbf x' = \mathbf x + \sin\varphi\,(\mathbf k\times\mathbf x)
   + 2\sin^2\tfrac\varphi2\,\big((\mathbf k\cdot\mathbf x)\,\mathbf k - \mathbf x\big).

:func:`turn_about` is that map on scalars (compiled) or arrays; :func:`turn_about_series`
is the same map for compiled scalars, with ``sin φ`` and ``1 − cos φ`` from their Taylor
series at small angles.

**The compositions.** A symmetric step ``S(h)`` of order 2 (a Strang splitting, an
exponential midpoint) composed as ``S(γ_s h) ⋯ S(γ_1 h)`` with palindromic weights
``γ`` summing to 1 is of a higher even order. Two families are in use, each kept bit for
bit as its stepper has always run it:

* :data:`COMPOSITIONS` (orders 2, 4, 6, 8; arrays): Yoshida's triple jump for order 4,
  Kahan & Li (1997), Math. Comp. 66, 1089, s9odr6a and s15odr8 for orders 6 and 8: the
  secular rotations (:mod:`andoyer.integrate.secular.rotations`) and the spin axis
  (:mod:`andoyer.planetary.spin_axis.stepping`);
* :func:`splitting_coefficients` (orders 2, 4, 6; lists): Yoshida (1990), the triple jump
  for order 4 and solution A for order 6: the symplectic splitting
  (:mod:`andoyer.integrate.splitting`) and the precession rates of
  :mod:`andoyer.planetary.precession`.

Examples
--------
>>> [round(float(sum(COMPOSITIONS[order])), 14) for order in (2, 4, 6, 8)]
[1.0, 1.0, 1.0, 1.0]
>>> len(splitting_coefficients(6)), len(COMPOSITIONS[6])
(7, 9)
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import jit

__all__ = ["COMPOSITIONS", "splitting_coefficients", "turn_about", "turn_about_series"]

Array = NDArray[np.float64]

_YOSHIDA4 = 1 / (2 - 2 ** (1 / 3))
_KL6 = (0.39216144400731413928, 0.33259913678935943860, -0.70624617255763935981, 0.08221359629355080023)
_KL8 = (
    0.74167036435061295344822780,
    -0.40910082580003159399730010,
    0.19075471029623837995387626,
    -0.57386247111608226665638773,
    0.29906418130365592384446354,
    0.33462491824529818378495798,
    0.31529309239676659663205666,
)


def _palindrome(half: tuple[float, ...]) -> Array:
    """Symmetric coefficients whose middle one makes them sum to 1."""
    return np.array([*half, 1.0 - 2.0 * sum(half), *half[::-1]])


#: Palindromic composition coefficients of a symmetric second-order step by order: Yoshida's
#: triple jump (order 4); Kahan & Li (1997), Math. Comp. 66, 1089, s9odr6a and s15odr8.
COMPOSITIONS = {
    2: np.array([1.0]),
    4: _palindrome((_YOSHIDA4,)),
    6: _palindrome(_KL6),
    8: _palindrome(_KL8),
}


def _triple_jump(inner: list[float], order: int) -> list[float]:
    root = 2.0 ** (1.0 / (order + 1))
    outer = 1.0 / (2.0 - root)
    middle = -root / (2.0 - root)
    return [w * outer for w in inner] + [w * middle for w in inner] + [w * outer for w in inner]


#: Yoshida (1990) solution A: the 7-stage 6th-order composition of Strang steps.
_YOSHIDA6_A = (-1.17767998417887, 0.235573213359357, 0.784513610477560)


def splitting_coefficients(order: int) -> list[float]:
    """Fractions of the step taken by each Strang substep for an ``order``-th order scheme.

    Parameters
    ----------
    order : {2, 4, 6}

    Returns
    -------
    list of float
        1, 3 or 7 weights, palindromic, summing to 1 (to round-off).

    Raises
    ------
    ValueError
        For another order.

    Examples
    --------
    >>> splitting_coefficients(2)
    [1.0]
    >>> round(sum(splitting_coefficients(6)), 14)
    1.0
    """
    if order == 2:
        return [1.0]
    if order == 4:
        return _triple_jump([1.0], 2)
    if order == 6:
        w1, w2, w3 = _YOSHIDA6_A
        w0 = 1.0 - 2.0 * (w1 + w2 + w3)
        return [w3, w2, w1, w0, w1, w2, w3]
    msg = f"expected a splitting order of 2, 4 or 6, got {order!r}"
    raise ValueError(msg)


@jit(inline=True)
def turn_about(x, y, z, kx, ky, kz, rate):
    r"""The exact unit-time flow of ``ẋ = rate (k·x) (k × x)`` about a fixed unit axis ``k``.

    ``k·x`` is conserved, so the flow turns ``x`` about ``k`` by ``φ = rate (k·x)``:
    ``x' = x + sin φ (k × x) + 2 sin²(φ/2) ((k·x) k − x)`` (Rodrigues, written so that small
    angles lose no digits). The one kernel of the secular gravity gradient and the spin axis;
    scalars (compiled) or arrays of the same shape.

    Parameters
    ----------
    x, y, z : float or numpy.ndarray, shape (...)
        The vector turned.
    kx, ky, kz : float or numpy.ndarray, shape (...)
        The unit axis.
    rate : float or numpy.ndarray, shape (...)
        ``c h``: the rate coefficient times the time.

    Returns
    -------
    tuple of float or numpy.ndarray, shape (...)
        ``x'``, ``y'``, ``z'``.

    Examples
    --------
    >>> [round(float(c), 12) for c in turn_about(1.0, 0.0, 1.0, 0.0, 0.0, 1.0, np.pi / 2)]
    [0.0, 1.0, 1.0]
    """
    d = x * kx + y * ky + z * kz
    angle = rate * d
    s = np.sin(angle)
    v = 2.0 * np.sin(0.5 * angle) ** 2
    cx = ky * z - kz * y
    cy = kz * x - kx * z
    cz = kx * y - ky * x
    return x + s * cx + v * (d * kx - x), y + s * cy + v * (d * ky - y), z + s * cz + v * (d * kz - z)


#: Below this angle (rad) :func:`turn_about_series` takes ``sin φ`` and ``1 − cos φ`` from their
#: Taylor series to ``φ⁵`` and ``φ⁶``: the first neglected terms, ``φ⁷/7!`` and ``φ⁸/8!``, are
#: below 4e-19 and multiply vectors no longer than ``x``, far below an ulp of ``x``.
_SMALL_ANGLE = 0.0078125


@jit(inline=True)
def turn_about_series(x, y, z, kx, ky, kz, angle):
    """:func:`turn_about` by ``angle`` (rate × time), for scalars: series at small angles.

    ``s = sin φ`` and ``v = 2 sin²(φ/2) = 1 − cos φ`` by Horner in ``φ²`` (an ulp from
    libm's). A rotation is a chain of dependent operations; the series is a shorter chain
    than two calls of ``sin`` (the secular steps turn ``M`` by ~1e-3 rad).

    Parameters
    ----------
    x, y, z, kx, ky, kz : float
        The vector turned and the unit axis.
    angle : float
        ``c h``, as ``rate`` of :func:`turn_about`.

    Returns
    -------
    tuple of float
        ``x'``, ``y'``, ``z'``.

    Examples
    --------
    >>> [round(c, 12) for c in turn_about_series(1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1e-3)]
    [0.9999995, 0.000999999833, 1.0]
    """
    d = x * kx + y * ky + z * kz
    phi = angle * d
    if abs(phi) <= _SMALL_ANGLE:
        u = phi * phi
        s = phi + phi * u * (-1.0 / 6 + u * (1.0 / 120))
        v = u * (0.5 + u * (-1.0 / 24 + u * (1.0 / 720)))
    else:
        s = math.sin(phi)
        v = 2.0 * math.sin(0.5 * phi) ** 2
    cx = ky * z - kz * y
    cy = kz * x - kx * z
    cz = kx * y - ky * x
    return x + s * cx + v * (d * kx - x), y + s * cy + v * (d * ky - y), z + s * cz + v * (d * kz - z)
