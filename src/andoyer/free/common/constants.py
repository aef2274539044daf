"""Per-state constant tables of the kernels: selecting states and shaping for broadcast.

The numpy driver of each regime (:mod:`andoyer.free.triaxial.setup_numpy`,
:mod:`andoyer.free.separatrix.setup_numpy`, :mod:`andoyer.free.uniform.setup_numpy`) keeps its
constants as a NamedTuple of arrays whose last axis runs over states (scalars ``(N,)``, vectors
``(k, N)``), possibly nested (:class:`andoyer.free.common.cycles_numpy.Frequency`, plain
tuples).  Evaluation takes a block of states as rows against epochs as columns, so the
constants are shaped ``(r, 1)`` and ``(k, r, 1)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["concatenate", "rows", "subset"]


def _map(fn, tree):
    if isinstance(tree, tuple):
        items = (_map(fn, x) for x in tree)
        return type(tree)(*items) if hasattr(tree, "_fields") else tuple(items)
    return fn(np.asarray(tree))


def subset(const, sel):
    """Constants of the states ``sel`` (indices or mask on the last axis), same layout.

    Parameters
    ----------
    const : NamedTuple
        Constant table (arrays with the state axis last).
    sel : array_like of int or bool
        States to keep.

    Returns
    -------
    NamedTuple
        Same type and layout.

    Examples
    --------
    >>> from andoyer.free.common.cycles_numpy import frequency
    >>> subset(frequency(np.array([1.0, 2.0, 3.0])), [2]).hi.tolist()
    [3.0]
    """
    return _map(lambda a: a[..., sel], const)


def rows(const, sel):
    """Constants of the states ``sel`` shaped as rows: ``(r, 1)`` and ``(k, r, 1)``.

    Parameters
    ----------
    const : NamedTuple
        Constant table (arrays with the state axis last).
    sel : array_like of int
        States to take, in row order.

    Returns
    -------
    NamedTuple
        Same type, arrays with a trailing axis of length one.

    Examples
    --------
    >>> from andoyer.free.common.cycles_numpy import frequency
    >>> rows(frequency(np.array([1.0, 2.0, 3.0])), [2, 0]).hi.tolist()
    [[3.0], [1.0]]
    """
    return _map(lambda a: a[..., sel][..., None], const)


def concatenate(consts):
    """Constants of several tables of the same type, one after the other along the state axis.

    Parameters
    ----------
    consts : sequence of NamedTuple
        Tables of one type (arrays with the state axis last).

    Returns
    -------
    NamedTuple
        Same type and layout, ``Σ Nᵢ`` states.

    Examples
    --------
    >>> from andoyer.free.common.cycles_numpy import frequency
    >>> concatenate([frequency(np.array([1.0])), frequency(np.array([2.0, 3.0]))]).hi.tolist()
    [1.0, 2.0, 3.0]
    """
    first = consts[0]
    if isinstance(first, tuple):
        items = (concatenate([c[i] for c in consts]) for i in range(len(first)))
        return type(first)(*items) if hasattr(first, "_fields") else tuple(items)
    return np.concatenate([np.asarray(c) for c in consts], axis=-1)
