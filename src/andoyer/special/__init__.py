"""Elliptic integrals and Jacobi elliptic functions, accurate near ``m = 1`` and for large ``u``.

Conventions: parameter ``m = k²`` throughout (never the modulus), with the complement
``1 − m`` accepted separately as ``mc``; the characteristic ``n`` of the third kind enters
as ``1 − n sin²θ``.  See :mod:`andoyer.special.integrals` and :mod:`andoyer.special.jacobi`.
"""

from andoyer.special.integrals import ellipe, ellipeinc, ellipf, ellipk, ellippi, ellippiinc
from andoyer.special.jacobi import am, ellipj

__all__ = ["am", "ellipe", "ellipeinc", "ellipf", "ellipj", "ellipk", "ellippi", "ellippiinc"]
