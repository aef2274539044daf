r"""Jacobi elliptic functions ``sn, cn, dn`` and the amplitude ``am`` for any real argument.

Conventions (DLMF §22.2, parameter ``m = k²``): ``φ = am(u|m)`` inverts ``u = F(φ|m)``,
``sn u = sin φ``, ``cn u = cos φ``, ``dn u = √(1 − m sn²u)``; ``am(u + 2K) = am(u) + π``.

scipy's ``ellipj`` (Cephes' descending Landen / AGM) loses accuracy for large ``|u|`` and
for ``m`` near 1, where it only sees the rounded ``m`` (measured in
``tests/special/test_special_jacobi.py`` and ``docs/errata-free.md``).  Here:

1. ``u`` is reduced exactly modulo ``2K`` with ``K`` in double-double,
   ``u = 2jK + r``, ``|r| ≤ K``, using ``sn(u) = (−1)^j sn(r)``, ``cn(u) = (−1)^j cn(r)``,
   ``dn(u) = dn(r)``;
2. for ``K/2 < |r| ≤ K`` the quarter-period reflection (DLMF 22.4.3)
   ``sn(K − v) = cd v``, ``cn(K − v) = k' sd v``, ``dn(K − v) = k' nd v`` keeps relative
   accuracy where ``cn`` vanishes;
3. the functions on ``|v| ≤ K/2`` are theta quotients (:mod:`andoyer.special.theta`) with
   nome at most ``e^{−π}``.

``m = 1`` gives the limits ``sn = tanh u``, ``cn = dn = sech u``, ``am = gd u``.
"""

from __future__ import annotations

import numpy as np

from andoyer.special.compensated import two_prod
from andoyer.special.parameter import parameter_pair
from andoyer.special.theta import ThetaLattice, lattice, sncndn_half

__all__ = ["am", "ellipj"]


def ellipj(u, m, mc=None):
    """Jacobi elliptic functions and amplitude, accurate for large ``u`` and ``m → 1``.

    Parameters
    ----------
    u : array_like
        Argument (any finite real).
    m : array_like
        Parameter ``0 ≤ m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately (needed for full accuracy when ``1 − m`` is small).

    Returns
    -------
    sn, cn, dn, am : ndarray
        Arrays of the broadcast shape of ``u`` and ``m``; ``am`` is continuous in ``u``.

    Raises
    ------
    ValueError
        If ``m`` is outside ``[0, 1]`` or ``u`` is not finite.

    Examples
    --------
    >>> sn, cn, dn, ph = ellipj(0.8, 0.3)
    >>> [round(float(f), 12) for f in (sn, cn, dn, ph)]
    [0.701566896038, 0.712603599754, 0.923223248795, 0.777593956138]
    >>> sn, cn, dn, ph = ellipj(1e6, 1 - 1e-14, mc=1e-14)
    >>> round(float(sn), 12)
    0.999999979882
    """
    m, mc = parameter_pair(m, mc, lower=0.0)
    u = np.asarray(u, dtype=np.float64)
    if not np.all(np.isfinite(u)):
        raise ValueError(f"expected a finite argument u, got {u[~np.isfinite(u)].ravel()[:3]}")
    u, m, mc = np.broadcast_arrays(u, m, mc)
    shape = u.shape
    u, m, mc = (np.ravel(a) for a in (u, m, mc))
    lat = lattice(m, mc)
    sn, cn, dn, ph = (np.empty(u.shape) for _ in range(4))

    lim = mc == 0  # m = 1: the period is infinite, the functions are hyperbolic
    if lim.any():
        ul = u[lim]
        sn[lim] = np.tanh(ul)
        cn[lim] = dn[lim] = 1.0 / np.cosh(ul)
        ph[lim] = np.arctan(np.sinh(ul))

    per = ~lim
    if per.any():
        uu = u[per]
        kh, kl = lat.K_hi[per], lat.K_lo[per]
        j = np.round(uu / (2.0 * kh))
        p, e = two_prod(j, 2.0 * kh)
        r = ((uu - p) - e) - j * (2.0 * kl)
        a = np.abs(r)
        far = a > 0.5 * kh
        v = np.where(far, (kh - a) + kl, a)
        s, c, d = sncndn_half(v, ThetaLattice(*(np.asarray(f)[per] for f in lat)))
        kc = lat.kc[per]
        s, c, d = (np.where(far, c / d, s), np.where(far, kc * s / d, c), np.where(far, kc / d, d))
        s = np.copysign(s, r)
        sign = 1.0 - 2.0 * (np.abs(j) % 2)
        sn[per] = sign * s
        cn[per] = sign * c
        dn[per] = d
        ph[per] = np.arctan2(s, c) + j * np.pi
    return tuple(a.reshape(shape) for a in (sn, cn, dn, ph))


def am(u, m, mc=None):
    """Jacobi amplitude ``am(u|m)``, the inverse of ``u = F(φ|m)``.

    Parameters
    ----------
    u : array_like
        Argument (any finite real).
    m : array_like
        Parameter ``0 ≤ m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``am(u|m)``, continuous and increasing in ``u``, ``am(u + 2K) = am(u) + π``.

    Examples
    --------
    >>> float(am(1.0832167728451687, 0.5))
    1.0
    """
    return ellipj(u, m, mc)[3]
