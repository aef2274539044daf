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

The amplitude has one source, :func:`amplitude`: the arithmetic-geometric mean (DLMF
22.20(ii)) written once for floats, numpy arrays (branches by :func:`andoyer._jit.select`,
the loop stopped by :func:`andoyer._jit.every`) and numba kernels, which call it compiled
(:mod:`andoyer.free.common.elliptic` registers it); :func:`am` and :func:`ellipj` apply it
to arrays.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import every, select
from andoyer.special.agm import ellipk_dd
from andoyer.special.compensated import two_prod
from andoyer.special.parameter import parameter_pair
from andoyer.special.theta import ThetaLattice, lattice, sncndn_half

__all__ = ["am", "amplitude", "ellipj"]

_EPS = 2.220446049250313e-16
# more than the AGM needs for any 1 − m ≥ 1e-308 (about 14 steps): a guard against NaN
_MAX_STEPS = 64


def amplitude(u, m, mc):
    r"""Jacobi amplitude ``am(u|m)`` by the AGM: the one kernel for floats, arrays and numba.

    The AGM ``a₀ = 1``, ``b₀ = √(1 − m)``, ``c₀ = √m``, ``a_n = (a_{n−1} + b_{n−1})/2``,
    ``c_n = (a_{n−1} − b_{n−1})/2``, ``b_n = √(a_{n−1} b_{n−1})`` runs until
    ``c_N ≤ ε a_N``; then ``φ_N = 2^N a_N u`` and (DLMF 22.20.5)

    .. math::
        \varphi_{n-1} = \tfrac12\bigl(\varphi_n + \arcsin(r_n \sin\varphi_n)\bigr),
        \qquad r_n = c_n/a_n,

    gives ``am(u|m) = φ₀``. Near ``r_n \sin φ_n = 1`` (``m → 1``) ``arcsin`` loses half
    the digits of its argument, so it is taken as ``atan2(x, √((1 − x)(1 + x)))`` with
    ``1 − x = (1 − r_n) + r_n \cos²φ_n/(1 + |\sin φ_n|)`` for ``x = r_n|\sin φ_n|``, and
    ``1 − r_n = b_{n−1}/a_n`` exactly: no cancellation. ``m = 1`` (``mc = 0``) gives
    ``gd u = 2 atan(tanh(u/2))``. On arrays, elements that converge early keep their
    ``a_N`` and take ``r_n = 0`` afterwards (exact halvings of ``φ``), so each element
    gets the bits it gets alone.

    Parameters
    ----------
    u : float or ndarray, shape (...)
        Argument (finite).
    m, mc : float or ndarray, shape (...)
        Parameter ``0 ≤ m ≤ 1`` and ``mc = 1 − m``, given separately so that ``mc`` carries
        its digits near ``m = 1``; broadcast with ``u``. Not checked (see :func:`am`).

    Returns
    -------
    float or ndarray, shape (...)
        ``am(u|m)``, continuous and increasing in ``u``.

    Examples
    --------
    ``am(F(1|1/2) | 1/2) = 1``, and ``m = 0`` gives ``u`` itself:

    >>> float(amplitude(1.0832167728451687, 0.5, 0.5))
    1.0
    >>> float(amplitude(0.7, 0.0, 1.0))
    0.7
    """
    limit = mc == 0.0
    a = 1.0
    b = np.sqrt(select(limit, 1.0, mc))  # m = 1 runs as m = 0, then is replaced
    c = np.sqrt(select(limit, 0.0, m))
    levels = []  # (r_n, 1 − r_n) of each step
    done = c <= _EPS * a
    while not every(done) and len(levels) < _MAX_STEPS:
        a_next = 0.5 * (a + b)
        c = 0.5 * (a - b)
        levels.append((select(done, 0.0, c / a_next), select(done, 1.0, b / a_next)))
        b = select(done, b, np.sqrt(a * b))
        a = select(done, a, a_next)
        done = done | (c <= _EPS * a)
    phi = a * u * 2.0 ** len(levels)
    for n in range(len(levels) - 1, -1, -1):
        r, d = levels[n]
        s = np.sin(phi)
        x = r * np.abs(s)
        small = x <= 0.5  # arcsin is well conditioned there; the costlier form only where needed
        if every(small):
            psi = np.arcsin(r * s)
        else:
            co = np.cos(phi)
            rest = d + r * co * co / (1.0 + np.abs(s))  # 1 − x without cancellation
            psi = select(small, np.arcsin(r * s), np.arctan2(r * s, np.sqrt(rest * (1.0 + x))))
        phi = 0.5 * (phi + psi)
    if every(mc != 0.0):
        return phi
    return select(limit, 2.0 * np.arctan(np.tanh(0.5 * u)), phi)



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
    sn, cn, dn = (np.empty(u.shape) for _ in range(3))

    lim = mc == 0  # m = 1: the period is infinite, the functions are hyperbolic
    if lim.any():
        ul = u[lim]
        sn[lim] = np.tanh(ul)
        cn[lim] = dn[lim] = 1.0 / np.cosh(ul)

    per = ~lim
    if per.any():
        uu = u[per]
        kh, kl = lat.K_hi[per], lat.K_lo[per]
        j, r = _periods(uu, kh, kl)
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
    ph = _unwrapped(u, m, mc, lat.K_hi, lat.K_lo)
    return tuple(a.reshape(shape) for a in (sn, cn, dn, ph))


def am(u, m, mc=None):
    """Jacobi amplitude ``am(u|m)``, the inverse of ``u = F(φ|m)`` (:func:`amplitude`, checked).

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

    Raises
    ------
    ValueError
        If ``m`` is outside ``[0, 1]`` or ``u`` is not finite.

    Examples
    --------
    >>> float(am(1.0832167728451687, 0.5))
    1.0
    """
    m, mc = parameter_pair(m, mc, lower=0.0)
    u = np.asarray(u, dtype=np.float64)
    if not np.all(np.isfinite(u)):
        raise ValueError(f"expected a finite argument u, got {u[~np.isfinite(u)].ravel()[:3]}")
    u, m, mc = np.broadcast_arrays(u, m, mc)
    return _unwrapped(u, m, mc, *ellipk_dd(mc))


def _periods(u, K_hi, K_lo):
    """``u = 2jK + r`` with ``|r| ≤ K``, ``K`` a double-double: the exact reduction ``(j, r)``."""
    j = np.round(u / (2.0 * K_hi))
    p, e = two_prod(j, 2.0 * K_hi)
    return j, ((u - p) - e) - j * (2.0 * K_lo)


def _unwrapped(u, m, mc, K_hi, K_lo):
    """``am(u|m) = am(r|m) + jπ`` (:func:`amplitude` on the exactly reduced ``r``), arrays."""
    per = mc > 0.0  # m = 1: no period, amplitude gives gd u
    j, r = _periods(u, np.where(per, K_hi, 1.0), np.where(per, K_lo, 0.0))
    j = np.where(per, j, 0.0)
    r = np.where(per, r, u)
    return np.asarray(amplitude(r, m, mc) + j * np.pi, dtype=np.float64)
