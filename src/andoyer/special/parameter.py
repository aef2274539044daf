"""The parameter ``m = k²`` of elliptic functions and its complement ``m' = 1 − m``.

Every function in :mod:`andoyer.special` uses the *parameter* ``m`` (not the modulus
``k = √m``; ``m = k² = sin²α`` in the notation of DLMF §19.2 and Abramowitz–Stegun
§17.2).  Near ``m = 1`` the complement ``m' = 1 − m`` cannot be recovered from a rounded
``m`` (``1 − m`` has only ``−log₁₀ m'`` correct digits less than ``m``), and the functions
depend on ``m'`` logarithmically, so each function accepts ``mc = m'`` as an optional
keyword that is used wherever ``1 − m`` would appear.
"""

from __future__ import annotations

import numpy as np

__all__ = ["parameter_pair"]

_TOL = 8.0 * np.finfo(np.float64).eps


def parameter_pair(m, mc=None, *, lower=-np.inf, upper=1.0):
    """Validate ``m`` and return ``(m, mc)`` as float64 arrays with ``mc = 1 − m``.

    Parameters
    ----------
    m : array_like
        Parameter ``m = k²``.
    mc : array_like, optional
        Complementary parameter ``1 − m``; when given it must agree with ``m`` to
        ``8 eps · max(1, |m|)`` and it is returned unchanged (its extra digits are kept).
    lower, upper : float, optional
        Closed range allowed for ``m``.

    Returns
    -------
    m, mc : ndarray
        Broadcast arrays.

    Raises
    ------
    ValueError
        If ``m`` is outside ``[lower, upper]`` or not finite, or ``mc`` disagrees with ``m``.

    Examples
    --------
    >>> m, mc = parameter_pair(1 - 1e-12, mc=1e-12)
    >>> float(mc)
    1e-12
    """
    m = np.asarray(m, dtype=np.float64)
    if not np.all(np.isfinite(m)):
        bad = m[~np.isfinite(m)].ravel()[:3]
        raise ValueError(f"expected a finite parameter m, got {bad}")
    if np.any((m < lower) | (m > upper)):
        bad = m[(m < lower) | (m > upper)].ravel()[:3]
        raise ValueError(f"expected the parameter m in [{lower}, {upper}], got {bad}")
    if mc is None:
        return m, 1.0 - m
    mc = np.asarray(mc, dtype=np.float64)
    m, mc = np.broadcast_arrays(m, mc)
    off = np.abs((m - 1.0) + mc) > _TOL * np.maximum(1.0, np.abs(m))
    if np.any(off | (mc < 1.0 - upper)):
        raise ValueError(
            f"expected mc = 1 - m (to 8 eps), got m = {m[off].ravel()[:3]}, mc = {mc[off].ravel()[:3]}"
        )
    return m, mc
