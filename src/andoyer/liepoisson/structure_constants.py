"""Structure constants of so(3), e(3) and l(7) (Pavlov eqs. 1.1 and 2.9).

``C[a, b, c]`` with ``{x_a, x_b} = Σ_c C[a, b, c] x_c``; generators ordered
``(m1, m2, m3, γ1, γ2, γ3)`` or ``(m1, m2, m3, λ0, λ1, λ2, λ3)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["e3_structure", "l7_structure", "levi_civita", "so3_structure"]


def levi_civita() -> np.ndarray:
    """The Levi-Civita symbol ε_ijk as a (3, 3, 3) array.

    Examples
    --------
    >>> float(levi_civita()[0, 1, 2]), float(levi_civita()[1, 0, 2])
    (1.0, -1.0)
    """
    eps = np.zeros((3, 3, 3))
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        eps[i, j, k] = 1.0
        eps[j, i, k] = -1.0
    return eps


def so3_structure() -> np.ndarray:
    """``{m_i, m_j} = -ε_ijk m_k``.

    Examples
    --------
    >>> float(so3_structure()[0, 1, 2])  # {m1, m2} = -m3
    -1.0
    """
    return -levi_civita()


def e3_structure() -> np.ndarray:
    """so(3) plus ``{m_i, γ_j} = -ε_ijk γ_k``, ``{γ_i, γ_j} = 0``.

    Examples
    --------
    >>> c = e3_structure()
    >>> float(c[2, 3, 4]), float(c[3, 2, 4])  # {m3, γ1} = -γ2, {γ1, m3} = γ2
    (-1.0, 1.0)
    """
    eps = levi_civita()
    c = np.zeros((6, 6, 6))
    c[:3, :3, :3] = -eps
    c[:3, 3:, 3:] = -eps  # {m_i, γ_j} = -ε_ijk γ_k
    c[3:, :3, 3:] = np.transpose(eps, (1, 0, 2))  # {γ_j, m_i} = +ε_ijk γ_k
    return c


def l7_structure() -> np.ndarray:
    """so(3) plus ``{m_i, λ0} = ½λ_i``, ``{m_i, λ_j} = -½(ε_ijk λ_k + δ_ij λ0)``.

    Examples
    --------
    >>> c = l7_structure()
    >>> float(c[0, 3, 4]), float(c[0, 4, 3]), float(c[2, 4, 5])  # {m1,λ0}, {m1,λ1}, {m3,λ1}
    (0.5, -0.5, -0.5)
    """
    eps = levi_civita()
    # a[i, mu, nu]: {m_i, λ_mu} = Σ_nu a[i, mu, nu] λ_nu  (Pavlov eq. 2.9)
    a = np.zeros((3, 4, 4))
    for i in range(3):
        a[i, 0, 1 + i] = 0.5
        a[i, 1 + i, 0] = -0.5
        a[i, 1:, 1:] = -0.5 * eps[i]
    c = np.zeros((7, 7, 7))
    c[:3, :3, :3] = -eps
    c[:3, 3:, 3:] = a
    c[3:, :3, 3:] = -np.transpose(a, (1, 0, 2))
    return c
