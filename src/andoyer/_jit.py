"""Compilation of the scalar kernels with numba (a base dependency), with a pure-Python fallback.

``NUMBA`` tells whether numba is importable and not switched off (the fallback serves
``ANDOYER_NUMBA=0`` and an environment where numba could not be installed); :func:`jit` compiles a
function with ``numba.njit(cache=True)`` when it is, and returns it unchanged otherwise, so
every kernel also runs (slowly, but identically) as plain Python. ``ANDOYER_NUMBA=0`` in the
environment, read at import, forces the interpreted path, which the tests also run.
"""

from __future__ import annotations

import os

try:
    import numba as _numba
except ImportError:  # pragma: no cover - depends on the environment
    _numba = None
if os.environ.get("ANDOYER_NUMBA", "1") == "0":  # pragma: no cover - depends on the environment
    _numba = None

#: Whether the kernels decorated with :func:`jit` are compiled.
NUMBA = _numba is not None

__all__ = ["NUMBA", "every", "jit", "jitable", "select"]


def jit(function=None, *, inline=False):
    """``numba.njit(cache=True)`` when numba is installed, else the function itself.

    Parameters
    ----------
    function : callable, optional
        The kernel (``@jit``); omitted when options are given (``@jit(inline=True)``).
    inline : bool, optional
        Inline the kernel into its compiled callers (numba's ``inline="always"``): for
        small kernels in hot loops, where the call boundary keeps LLVM from interleaving
        the caller's work with the kernel's.

    Examples
    --------
    A kernel compiled (or not) this way is called like any function; Carlson's
    ``R_F(0, 1, 2)`` (DLMF 19.20.1: the lemniscate constant ``Γ(1/4)²/(4√(2π))``):

    >>> from andoyer.free.kernels.elliptic import carlson_rf
    >>> round(float(carlson_rf(0.0, 1.0, 2.0)), 13)
    1.3110287771461
    """
    if function is None:
        return lambda f: jit(f, inline=inline)
    if _numba is None:  # pragma: no cover - depends on the environment
        return function
    options = {"inline": "always"} if inline else {}
    return _numba.njit(cache=True, error_model="numpy", **options)(function)


def jitable(function):
    """Let compiled kernels call the plain Python ``function`` (``numba.extending.register_jitable``).

    The function itself is returned unchanged, so Python callers keep calling it as
    Python; kernels compiled with :func:`jit` that name it compile it inline.

    Examples
    --------
    >>> def twice(x):
    ...     return 2.0 * x
    >>> jitable(twice) is twice
    True
    """
    if _numba is None:  # pragma: no cover - depends on the environment
        return function
    from numba.extending import register_jitable

    return register_jitable(function)


def select(condition, if_true, if_false):
    """``if_true`` where ``condition`` holds, else ``if_false``: the one branch of a kernel written once.

    A scalar kernel that must also run on whole arrays (the numpy path) chooses with this
    function instead of ``if``: called from Python it is :func:`numpy.where` (element-wise
    on arrays, a numpy scalar on scalars); inside a kernel compiled by :func:`jit` numba
    replaces it by the conditional expression ``if_true if condition else if_false``.
    Both operands are evaluated, so each must be finite-safe on its own (guard a division
    by selecting a safe denominator first).

    Parameters
    ----------
    condition : bool or ndarray of bool, shape (...)
        Where to take ``if_true``.
    if_true, if_false : float or ndarray, shape (...)
        The two candidates, broadcast with ``condition``.

    Returns
    -------
    float or ndarray, shape (...)
        The chosen values.

    Examples
    --------
    >>> import numpy as np
    >>> select(np.array([True, False]), 1.0, np.array([2.0, 3.0])).tolist()
    [1.0, 3.0]
    >>> float(select(0.0 > 1.0, 1.0, 2.0))
    2.0
    """
    import numpy as np

    return np.where(condition, if_true, if_false)


def every(condition):
    """Whether ``condition`` holds everywhere: the stopping test of a kernel's loop written once.

    Called from Python it is :func:`numpy.all` (a loop over a whole array stops when every
    element has converged); inside a kernel compiled by :func:`jit` it is the condition
    itself.

    Parameters
    ----------
    condition : bool or ndarray of bool, shape (...)
        The per-element test.

    Returns
    -------
    bool
        True where every element holds.

    Examples
    --------
    >>> import numpy as np
    >>> every(np.array([True, False])), every(True)
    (False, True)
    """
    import numpy as np

    return bool(np.all(condition))


if _numba is not None:
    from numba.extending import overload

    # not inline="always": numba's IR inlining of a conditional expression, twice in one
    # kernel, trips its NumbaIRAssumptionWarning (numba 0.6x); LLVM inlines the call anyway
    @overload(select)
    def _select_compiled(condition, if_true, if_false):  # noqa: ARG001 - numba's overload signature
        def conditional(condition, if_true, if_false):
            return if_true if condition else if_false

        return conditional

    @overload(every, inline="always")
    def _every_compiled(condition):  # noqa: ARG001 - numba's overload signature
        return lambda condition: condition
