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

__all__ = ["NUMBA", "jit", "jitable"]


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
