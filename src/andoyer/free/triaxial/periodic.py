r"""Piecewise polynomials of one period, written once: locate the piece, evaluate it (the kernels).

A periodic function of a phase ``f ∈ [−1/2, 1/2)`` (in cycles) is held as ``n`` equal
pieces, each a polynomial of the local variable

.. math:: u = 2\bigl((f + \tfrac12)\,n - i\bigr) - 1 \in [-1, 1], \qquad
          i = \lfloor (f + \tfrac12)\,n \rfloor,

with monomial coefficients ``coef[base + i, j, k]`` of ``u^j`` for component ``k``.  The
functions below are written so that the same definition runs on floats (compiled
by numba through :func:`andoyer._jit.jit`, or as plain Python) and on numpy arrays
(the vectorised path): only arithmetic, ``np.floor``/``np.minimum``/``np.maximum`` and
indexing.  The representation is built and evaluated on arrays by
:mod:`andoyer.free.triaxial.periodic_numpy`, and evaluated per state and epoch by
:mod:`andoyer.free.triaxial.periodic_compiled`.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jit, jitable
from andoyer._quaternion import product

__all__ = ["DEGREE", "body_momentum", "horner", "locate", "turned"]

# the one Hamilton product, compiled inline into the kernels below
jitable(product)

#: Degree of every piece (a constant, so that compiled loops unroll).
DEGREE = 9


@jit(inline=True)
def locate(f, n):
    """Piece index (a float, to be cast by the caller) and local variable ``u`` of a phase.

    Parameters
    ----------
    f : float or ndarray
        Reduced phase in cycles, ``−1/2 ≤ f ≤ 1/2``.
    n : float or ndarray
        Number of pieces over one cycle.

    Returns
    -------
    i : float or ndarray
        ``⌊(f + 1/2) n⌋`` clipped to ``[0, n − 1]`` (``f = 1/2`` belongs to the last piece).
    u : float or ndarray
        Local variable in ``[−1, 1]``.

    Examples
    --------
    >>> [float(v) for v in locate(0.0, 4.0)]
    [2.0, -1.0]
    >>> [float(v) for v in locate(0.5, 4.0)]
    [3.0, 1.0]
    """
    x = (f + 0.5) * n
    i = np.minimum(np.maximum(np.floor(x), 0.0), n - 1.0)
    return i, 2.0 * (x - i) - 1.0


@jit(inline=True)  # the call boundary costs a third of the loop that calls it
def horner(piece, k, u):
    """Components ``k … k+3`` of one piece at ``u``: ``Σⱼ piece[j, k+i] uʲ``, by Horner's rule.

    Four independent chains advance together.  ``piece[j, k]`` is the coefficient of
    ``uʲ``: a float (the compiled path passes the piece's ``(DEGREE + 1, components)``
    row of the table) or an array (the numpy path passes the pieces of a block of epochs
    with those two axes first).

    Parameters
    ----------
    piece : ndarray, shape (DEGREE + 1, components, ...)
        Monomial coefficients of the piece (of each epoch).
    k : int
        First component.
    u : float or ndarray
        Local variable, shaped as the trailing axes of ``piece``.

    Returns
    -------
    tuple of 4 float or ndarray

    Examples
    --------
    >>> piece = np.zeros((DEGREE + 1, 4))
    >>> piece[:3, 1] = (1.0, 2.0, 3.0)  # component 1: 1 + 2u + 3u²
    >>> [float(v) for v in horner(piece, 0, 0.5)]
    [0.0, 2.75, 0.0, 0.0]
    """
    a0 = piece[DEGREE, k]
    a1 = piece[DEGREE, k + 1]
    a2 = piece[DEGREE, k + 2]
    a3 = piece[DEGREE, k + 3]
    for j in range(DEGREE - 1, -1, -1):
        a0 = a0 * u + piece[j, k]
        a1 = a1 * u + piece[j, k + 1]
        a2 = a2 * u + piece[j, k + 2]
        a3 = a3 * u + piece[j, k + 3]
    return a0, a1, a2, a3


@jit(inline=True)
def body_momentum(g, x, y, z, w):
    r"""``g R(a)ᵀ e_z`` for ``a = (x, y, z, w)`` taken as the unit quaternion ``a/|a|``.

    With the attitude ``q = Q ⊗ a`` and ``R(Q) e_z = n`` the direction of the angular
    momentum in the reference frame, the body momentum of norm ``g`` is
    ``g R(q)ᵀ n = g R(a)ᵀ e_z``, the third row of ``R(a)``:

    .. math:: m = \frac{g}{|a|^2}\bigl(2(xz - yw),\ 2(yz + xw),\ w^2 + z^2 - x^2 - y^2\bigr),

    homogeneous of degree 2, so ``a`` need not be normalised: ``1/|a|²`` is taken as
    ``2 − |a|²``, exact to ``(|a|² − 1)²`` (``|a|²`` is 1 to the pieces' fit, ~1e-15).

    Parameters
    ----------
    g : float or ndarray
        Norm of the momentum.
    x, y, z, w : float or ndarray
        The quaternion ``a`` (scalar last), broadcast with ``g``.

    Returns
    -------
    tuple of 3 float or ndarray

    Examples
    --------
    A quarter turn about ``x`` takes the body's ``y`` to ``e_z``:

    >>> h = np.sqrt(0.5)
    >>> [round(float(c), 15) for c in body_momentum(2.0, h, 0.0, 0.0, h)]
    [0.0, 2.0, 0.0]
    """
    xx = x * x
    yy = y * y
    zz = z * z
    ww = w * w
    h = g * (2.0 - ((xx + yy) + (zz + ww)))
    d = h + h
    return d * (x * z - y * w), d * (y * z + x * w), h * ((ww + zz) - (xx + yy))


@jit(inline=True)
def turned(qx, qy, qz, qw, s, c, x, y, z, w):
    """``Q ⊗ (s e_z, c) ⊗ a``: ``a``, the turn by ``2πg`` about ``e_z`` (``s, c = sin, cos(πg)``), ``Q``.

    ``(s e_z, c) ⊗ a`` is the one product written out for its zero components (a product
    by zeros is not folded away in IEEE arithmetic).

    Examples
    --------
    >>> [float(v) for v in turned(0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)]
    [0.0, 0.0, 1.0, 0.0]
    """
    return product(qx, qy, qz, qw, c * x - s * y, c * y + s * x, c * z + s * w, c * w - s * z)
