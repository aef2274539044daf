r"""Jacobi elliptic functions on one half-period as quotients of theta series.

For ``|u| ≤ K`` the Jacobi functions are quotients of theta functions whose series converge
like ``Q^{n²}`` with a nome ``Q ≤ e^{−π} ≈ 0.043``, so four or five terms reach double
precision.  Two series cover all ``0 ≤ m ≤ 1``:

* *circular* (``m ≤ 1/2``): the nome ``q = exp(−πK'/K)`` and ``x = πu/(2K)``,

  .. math::
     \operatorname{sn} u = \frac{\vartheta_3(0)\vartheta_1(x)}{\vartheta_2(0)\vartheta_4(x)},\
     \operatorname{cn} u = \frac{\vartheta_4(0)\vartheta_2(x)}{\vartheta_2(0)\vartheta_4(x)},\
     \operatorname{dn} u = \frac{\vartheta_4(0)\vartheta_3(x)}{\vartheta_3(0)\vartheta_4(x)}
     \quad\text{(DLMF 22.2.4–6)};

* *hyperbolic* (``m > 1/2``): Jacobi's imaginary transformation (DLMF 22.6.12)
  ``sn(u|m) = −i sc(iu|m')``, ``cn(u|m) = nc(iu|m')``, ``dn(u|m) = dc(iu|m')`` with the
  complementary nome ``q' = exp(−πK/K')`` and ``y = πu/(2K')``; the theta functions of
  imaginary argument become sums of ``cosh``/``sinh`` that are evaluated here scaled by
  ``e^{−y}`` so that no term overflows even for ``1 − m`` down to 1e-300.

The nomes come from Jacobi's series ``q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷ + 20910ε²¹``
with ``ε = (1 − √k')/(2(1 + √k'))`` (A&S 17.3.21), written as
``ε = m / (2(1 + k')(1 + √k')²)`` so that it keeps full relative precision for small ``m``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import jitable, select
from andoyer.special.agm import ellipk_dd

__all__ = [
    "ThetaLattice",
    "lattice",
    "nome",
    "quotient_constants",
    "sncndn_circular",
    "sncndn_half",
    "sncndn_hyperbolic",
]


class ThetaLattice(NamedTuple):
    """Per-parameter constants of the theta-quotient evaluation (all arrays of one shape).

    Attributes
    ----------
    circular : ndarray of bool
        ``m ≤ 1/2``: the circular series applies, else the hyperbolic one.
    K_hi, K_lo : ndarray
        ``K(m)`` as a double-double (``inf`` for ``m = 1``).
    Kp : ndarray
        ``K'(m) = K(1 − m)``.
    q : ndarray
        The active nome: ``q`` (circular) or ``q'`` (hyperbolic).
    scale : ndarray
        ``π/(2K)`` (circular) or ``π/(2K')`` (hyperbolic): the theta argument per unit ``u``.
    c_sn, c_cn, c_dn : ndarray
        Normalising constants of the three quotients.
    kc : ndarray
        ``k' = √(1 − m)``.
    """

    circular: np.ndarray
    K_hi: np.ndarray
    K_lo: np.ndarray
    Kp: np.ndarray
    q: np.ndarray
    scale: np.ndarray
    c_sn: np.ndarray
    c_cn: np.ndarray
    c_dn: np.ndarray
    kc: np.ndarray


@jitable
def nome(p, pc):
    """Nome ``e^{−πK(1−p)/K(p)}`` for a parameter ``p ≤ 1/2``, from ``p`` and ``pc = 1 − p`` (A&S 17.3.21).

    One definition for floats (compiled callers, :mod:`andoyer.free.triaxial.setup_compiled`) and
    arrays (:func:`lattice`).

    Parameters
    ----------
    p, pc : float or ndarray, shape (...)
        The parameter ``0 ≤ p ≤ 1/2`` and its complement.

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> round(float(nome(0.5, 0.5)), 15)  # e^{−π}
    0.043213918263772
    """
    kc = np.sqrt(pc)
    eps = p / (2.0 * (1.0 + kc) * (1.0 + np.sqrt(kc)) ** 2)
    e4 = eps**4
    return eps * (1.0 + e4 * (2.0 + e4 * (15.0 + e4 * (150.0 + e4 * (1707.0 + e4 * 20910.0)))))


@jitable
def quotient_constants(q, circular):
    """Normalising constants ``c_sn, c_cn, c_dn`` of the theta quotients for the active nome ``q``.

    Circular (``m ≤ 1/2``, nome ``q``): ``ϑ₃/ϑ₂, ϑ₄/ϑ₂, ϑ₄/ϑ₃`` at zero (DLMF 22.2.4–6);
    hyperbolic (nome ``q'``): ``ϑ₃/ϑ₄, 2ϑ̃₂/ϑ₄, 2ϑ̃₂/ϑ₃`` with ``ϑ̃₂ = ϑ₂/(2q^{1/4})``.  Terms
    to ``q¹²`` (``q ≤ e^{−π}``).  One definition for floats (compiled callers) and arrays.

    Parameters
    ----------
    q : float or ndarray, shape (...)
        The active nome, ``0 ≤ q ≤ e^{−π}``.
    circular : bool or ndarray of bool, shape (...)
        Which series the nome belongs to.

    Returns
    -------
    c_sn, c_cn, c_dn : float or ndarray, shape (...)

    Examples
    --------
    >>> [float(c) for c in quotient_constants(0.0, True)]  # m = 0: sn = sin, cn = cos, dn = 1
    [1.0, 1.0, 1.0]
    """
    q2 = q * q
    q4 = q2 * q2
    q9 = q4 * q4 * q
    t2 = 1.0 + q2 * (1.0 + q4 * (1.0 + q2 * q4))  # 1 + q² + q⁶ + q¹²
    th3 = 1.0 + 2.0 * (q + q4 + q9)
    th4 = 1.0 - 2.0 * (q - q4 + q9)
    # choose the operands, then divide: three divisions, not six
    den = select(circular, t2, th4)
    num = select(circular, th4, 2.0 * t2)
    return th3 / den, num / den, num / th3


def lattice(m, mc, mc_lo=0.0):
    """Constants of the theta-quotient evaluation for parameters ``m`` with ``mc = 1 − m``.

    Parameters
    ----------
    m, mc : array_like
        Parameter ``0 ≤ m ≤ 1`` and its complement, supplied separately so that ``mc`` keeps
        full relative precision near ``m = 1``.  Broadcast together.
    mc_lo : array_like, optional
        Low part of ``mc`` when it is known as a double-double (sharpens ``K``).

    Returns
    -------
    ThetaLattice
        Arrays of the broadcast shape.

    Examples
    --------
    >>> lat = lattice(0.5, 0.5)
    >>> float(lat.q), float(lat.K_hi)
    (0.04321391826377226, 1.8540746773013719)
    """
    m, mc = np.broadcast_arrays(np.asarray(m, dtype=np.float64), np.asarray(mc, dtype=np.float64))
    circular = m <= 0.5
    K_hi, K_lo = ellipk_dd(mc, mc_lo)
    Kp, _ = ellipk_dd(m)
    q = np.where(
        circular,
        nome(np.minimum(m, 0.5), np.maximum(mc, 0.5)),
        nome(np.minimum(mc, 0.5), np.maximum(m, 0.5)),
    )
    with np.errstate(divide="ignore"):
        scale = np.where(circular, 0.5 * np.pi / K_hi, 0.5 * np.pi / Kp)
    c_sn, c_cn, c_dn = quotient_constants(q, circular)
    return ThetaLattice(circular, K_hi, K_lo, Kp, q, scale, c_sn, c_cn, c_dn, np.sqrt(mc))


def sncndn_circular(u, consts):
    """``sn, cn, dn`` by the circular theta series (``m ≤ 1/2``, ``|u| ≤ K``).

    Parameters
    ----------
    u : array_like
        Argument, ``|u| ≤ K`` (larger ``|u|`` converges too but loses the error bound).
    consts : tuple of array_like
        ``(q, scale, c_sn, c_cn, c_dn)`` from :class:`ThetaLattice` (``lat[4:9]``),
        broadcast against ``u``.

    Returns
    -------
    sn, cn, dn : ndarray

    Examples
    --------
    >>> lat = lattice(0.3, 0.7)
    >>> [round(float(f), 12) for f in sncndn_circular(0.8, lat[4:9])]
    [0.701566896038, 0.712603599754, 0.923223248795]
    """
    q, scale, c_sn, c_cn, c_dn = consts
    x = np.multiply(u, scale)
    s1 = np.sin(x)
    c1 = np.cos(x)
    c2 = 1.0 - 2.0 * s1 * s1
    tc2 = 2.0 * c2
    s3 = s1 * (tc2 + 1.0)
    c3 = c1 * (tc2 - 1.0)
    s5 = tc2 * s3 - s1
    c5 = tc2 * c3 - c1
    s7 = tc2 * s5 - s3
    c7 = tc2 * c5 - c3
    c4 = tc2 * c2 - 1.0
    c6 = tc2 * c4 - c2
    q2 = q * q
    q4 = q2 * q2
    q6 = q4 * q2
    q9 = q6 * q2 * q
    q12 = q6 * q6
    num1 = s1 - q2 * s3 + q6 * s5 - q12 * s7
    num2 = c1 + q2 * c3 + q6 * c5 + q12 * c7
    even = q4 * c4
    odd = q * c2 + q9 * c6
    th4 = 1.0 + 2.0 * (even - odd)
    th3 = 1.0 + 2.0 * (even + odd)
    inv = 1.0 / th4
    return c_sn * num1 * inv, c_cn * num2 * inv, c_dn * th3 * inv


def sncndn_hyperbolic(u, consts, *, relative=True):
    """``sn, cn, dn`` by the hyperbolic theta series (``m > 1/2``, ``|u| ≤ K``).

    Parameters
    ----------
    u : array_like
        Argument, ``|u| ≤ K``.
    consts : tuple of array_like
        ``(q, scale, c_sn, c_cn, c_dn)`` from :class:`ThetaLattice` (``q`` is the
        complementary nome ``q'``).
    relative : bool, optional
        Keep relative precision of ``sn`` for small ``u`` (one extra ``expm1``); without it
        the error is bounded in absolute terms only, which is what a unit vector needs.

    Returns
    -------
    sn, cn, dn : ndarray

    Examples
    --------
    >>> lat = lattice(0.9, 0.1)
    >>> [round(float(f), 12) for f in sncndn_hyperbolic(0.8, lat[4:9])]
    [0.669449139226, 0.742857893537, 0.772433858004]
    """
    q, scale, c_sn, c_cn, c_dn = consts
    u = np.asarray(u, dtype=np.float64)
    y = np.abs(u) * scale
    rho = np.exp(-2.0 * y)  # e^{−2y} ∈ [q', 1] on |u| ≤ K
    one_minus_rho = 1.0 - rho
    if relative:
        one_minus_rho = np.where(y < 0.35, -np.expm1(-2.0 * y), one_minus_rho)
    z = q / rho  # q' e^{2y} ≤ 1 on |u| ≤ K
    q2 = q * q
    q4 = q2 * q2
    q6 = q4 * q2
    q9 = q6 * q2 * q
    q12 = q6 * q6
    rho2 = rho * rho
    z2 = z * z
    z3 = z2 * z
    a1 = q * z
    b1 = q2 * rho2
    a2 = q4 * z2
    b2 = q6 * rho2 * rho
    a3 = q9 * z3
    b3 = q12 * rho2 * rho2
    sh = one_minus_rho - (a1 - b1) + (a2 - b2) - (a3 - b3)
    ch = (1.0 + rho) + (a1 + b1) + (a2 + b2) + (a3 + b3)
    t1 = z + q * rho
    t2 = q2 * z2 + q4 * rho2
    t3 = q6 * z3 + q9 * rho2 * rho
    t4 = q12 * z2 * z2
    sr = np.sqrt(rho)
    inv = 1.0 / ch
    th4 = sr * ((1.0 - t1) + (t2 - t3 + t4))
    th3 = sr * (1.0 + t1 + t2 + t3 + t4)
    return np.copysign(c_sn * sh * inv, u), c_cn * th4 * inv, c_dn * th3 * inv


def sncndn_half(u, lat: ThetaLattice):
    """``sn, cn, dn`` for ``|u| ≤ K`` and any ``0 ≤ m < 1``, choosing the series per element.

    Parameters
    ----------
    u : array_like
        Argument, broadcast against the lattice arrays, ``|u| ≤ K``.
    lat : ThetaLattice
        Constants from :func:`lattice`.

    Returns
    -------
    sn, cn, dn : ndarray
        Arrays of the broadcast shape.

    Examples
    --------
    >>> lat = lattice([0.3, 0.9], [0.7, 0.1])
    >>> sn, cn, dn = sncndn_half(0.8, lat)
    >>> [round(float(s), 12) for s in sn]
    [0.701566896038, 0.669449139226]
    """
    shape = np.broadcast_shapes(np.shape(u), lat.q.shape)
    u = np.broadcast_to(np.asarray(u, dtype=np.float64), shape)
    consts = [np.broadcast_to(f, shape) for f in lat[4:9]]
    circ = np.broadcast_to(lat.circular, shape)
    out = [np.empty(shape) for _ in range(3)]
    for mask, fn in ((circ, sncndn_circular), (~circ, sncndn_hyperbolic)):
        if mask.any():
            vals = fn(u[mask], tuple(c[mask] for c in consts))
            for o, v in zip(out, vals, strict=True):
                o[mask] = v
    return tuple(out)
