r"""Laplace coefficients ``b_s^{(j)}(α)`` of celestial mechanics.

.. math:: b_s^{(j)}(\alpha) = \frac{1}{\pi}\int_0^{2\pi}
   \frac{\cos j\psi\, d\psi}{(1 - 2\alpha\cos\psi + \alpha^2)^{s}}

(Murray & Dermott 1999, eq. 6.67), computed by the trapezoidal rule, which converges
geometrically for a periodic analytic integrand (error ``~α^K`` with ``K`` nodes).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["laplace_coefficient"]


def laplace_coefficient(s: float, j: int, alpha: ArrayLike, nodes: int = 1024) -> NDArray[np.float64]:
    """Laplace coefficient ``b_s^{(j)}(α)`` for ``0 ≤ α < 1``.

    Parameters
    ----------
    s : float
        Half-integer exponent (``3/2`` for the secular theory).
    j : int
        Harmonic, ``j ≥ 0``.
    alpha : array_like, shape (...)
        Ratio of the semi-major axes, ``0 ≤ α < 1``.
    nodes : int
        Trapezoid nodes (``α^nodes`` must be negligible).

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> round(float(laplace_coefficient(1.5, 1, 0.5)), 8)  # 2·(3/2)·0.5·F(3/2, 5/2; 2; 1/4)
    2.58050003
    """
    alpha = np.asarray(alpha, dtype=float)
    if np.any((alpha < 0) | (alpha >= 1)) or not np.all(np.isfinite(alpha)):
        msg = f"expected semi-major-axis ratios 0 <= alpha < 1, got {alpha.tolist()}"
        raise ValueError(msg)
    psi = 2.0 * np.pi * np.arange(nodes) / nodes
    a = alpha[..., None]
    return 2.0 * np.mean(np.cos(j * psi) / (1.0 - 2.0 * a * np.cos(psi) + a * a) ** s, axis=-1)
