r"""The set-up formulas of the triaxial solution, one kernel each, for compiled floats and numpy arrays.

Notation of :mod:`andoyer.free.triaxial` (working frame of :mod:`andoyer.free.common.polhode_numpy`,
axis 3 the polhode axis, ``s = +1`` SAM, ``−1`` LAM): ``e_{ij} = s(1/I_i − 1/I_j)``, ``P₁, P₂, P₃``
the invariants, ``G = |m|``, ``w₃ = 1/I₃``; double-doubles are ``(hi, lo)`` tuples.

Each kernel is plain arithmetic with :func:`andoyer._jit.select` for its branches, registered
with :func:`andoyer._jit.jitable`: the compiled set-up (:mod:`andoyer.free.triaxial.setup_compiled`)
inlines it on floats, the numpy set-up (:func:`andoyer.free.triaxial.setup_numpy.triaxial`) calls it on
arrays; the double-double operations are :mod:`andoyer.special.compensated` (one text for both
paths) and ``R_F`` is :func:`andoyer.free.common.elliptic.elliprf` (Carlson's kernel compiled,
scipy's on arrays).
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable, select
from andoyer.free.common.elliptic import elliprf
from andoyer.special.compensated import dd_add, dd_div, dd_mul, dd_sqrt

__all__ = [
    "amplitudes",
    "initial_phase",
    "modulus",
    "momentum_coefficients",
    "pole_offset",
    "polhode_frequency",
    "polhode_scales",
    "psi_constants",
    "secular_rate",
    "theta_circular",
    "theta_hyperbolic",
]

_PI_HI, _PI_LO = 3.141592653589793, 1.2246467991473532e-16


@jitable
def modulus(e12, e13, e23, P1, P2, P3):
    r"""The parameter ``k² = e₁₂P₁/(e₂₃P₃)``, its complement and ``ω² = e₂₃P₃``.

    ``1 − k² = e₁₃P₂/(e₂₃P₃)`` is formed from ``P₂`` directly, without the cancellation of
    ``1 − k²`` near the separatrix.

    Parameters
    ----------
    e12, e13, e23, P1, P2, P3 : tuple of (float or ndarray, shape (...))
        Double-doubles ``(hi, lo)``.

    Returns
    -------
    m : float or ndarray, shape (...)
        ``k²`` (high word).
    mc, omega2 : tuple
        Double-doubles ``1 − k²`` and ``ω² = e₂₃P₃``.

    Examples
    --------
    >>> m, mc, omega2 = modulus((1.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 0.0), (1.0, 0.0), (3.0, 0.0))
    >>> float(m), float(mc[0]), float(omega2[0])
    (0.3333333333333333, 0.6666666666666666, 3.0)
    """
    den = dd_mul(e23[0], e23[1], P3[0], P3[1])
    m = dd_div(*dd_mul(e12[0], e12[1], P1[0], P1[1]), den[0], den[1])[0]
    mc = dd_div(*dd_mul(e13[0], e13[1], P2[0], P2[1]), den[0], den[1])
    return m, mc, den


@jitable
def amplitudes(e13, e23, P1, P3):
    """Amplitudes ``a₁ = √(P₁/e₁₃)``, ``a₂ = √(P₁/e₂₃)``, ``a₃ = √(P₃/e₁₃)`` of ``m₁ cn, m₂ sn, m₃ dn``.

    Parameters
    ----------
    e13, e23, P1, P3 : float or ndarray, shape (...)
        High words.

    Returns
    -------
    a1, a2, a3 : float or ndarray, shape (...)

    Examples
    --------
    >>> [float(a) for a in amplitudes(1.0, 4.0, 4.0, 9.0)]
    [2.0, 1.0, 3.0]
    """
    return np.sqrt(P1 / e13), np.sqrt(P1 / e23), np.sqrt(P3 / e13)


@jitable
def momentum_coefficients(amp, s, c_sn, c_cn, c_dn):
    """Working-frame coefficients of ``m`` in theta quotients and of the shortest-arc factor.

    ``m = (μ_cn ϑ_cn + μ_sn ϑ_sn + μ_dn ϑ_dn)/ϑ₄`` with ``μ_cn = a₁c_cn e₁``, ``μ_sn =
    s a₂ c_sn e₂``, ``μ_dn = a₃ c_dn e₃``, and the vector part of the shortest arc is
    ``v_sn sn τ + v_cn cn τ`` with ``v_sn = s a₂ e₁``, ``v_cn = −a₁ e₂`` (``e_j`` the working
    axes; each path places these magnitudes along its axes).

    Parameters
    ----------
    amp : tuple
        ``(a₁, a₂, a₃)`` of :func:`amplitudes`.
    s, c_sn, c_cn, c_dn : float or ndarray, shape (...)
        ``±1`` and :func:`andoyer.special.theta.quotient_constants`.

    Returns
    -------
    mu_cn, mu_sn, mu_dn, v_sn, v_cn : float or ndarray, shape (...)

    Examples
    --------
    >>> momentum_coefficients((1.0, 2.0, 3.0), -1.0, 1.0, 1.0, 1.0)
    (1.0, -2.0, 3.0, -2.0, -1.0)
    """
    return amp[0] * c_cn, s * amp[1] * c_sn, amp[2] * c_dn, s * amp[1], -amp[0]


@jitable
def polhode_frequency(omega2, K):
    """Polhode frequency ``ν = ω/(4K)`` in cycles per unit time, a double-double.

    Parameters
    ----------
    omega2, K : tuple of (float or ndarray, shape (...))
        Double-doubles ``ω²`` and ``K(k²)``.

    Returns
    -------
    tuple
        ``(hi, lo)``.

    Examples
    --------
    >>> [float(x) for x in polhode_frequency((4.0, 0.0), (0.5, 0.0))]
    [1.0, 0.0]
    """
    om = dd_sqrt(omega2[0], omega2[1])
    return dd_div(om[0], om[1], 4.0 * K[0], 4.0 * K[1])


@jitable
def initial_phase(mw0, mw1, mw2, amp, s, K):
    """Initial polhode phase ``τ₀/(4K)`` in cycles, ``τ₀ = F(am τ₀ | k²)``, from the measured ``cn, sn, dn``.

    ``τ₀ = sn₀ R_F(cn₀², dn₀², 1)`` on the half-period where ``cn₀ ≥ 0`` and ``2K − sn₀R_F``
    (with the sign of ``sn₀``) beyond: Carlson's form, without the cancellation of an
    inverse sine near the turning points.

    Parameters
    ----------
    mw0, mw1, mw2 : float or ndarray, shape (...)
        Working-frame angular momentum.
    amp : tuple
        The amplitudes ``(a₁, a₂, a₃)`` of :func:`amplitudes`.
    s, K : float or ndarray, shape (...)
        ``±1`` and ``K(k²)`` (high word).

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> float(initial_phase(1.0, 0.0, 1.0, (1.0, 1.0, 1.0), 1.0, 1.5))  # cn = 1: τ₀ = 0
    0.0
    """
    cn0, sn0, dn0 = mw0 / amp[0], mw1 / (s * amp[1]), mw2 / amp[2]
    rf = elliprf(cn0 * cn0, dn0 * dn0, 1.0)
    tau0 = select(cn0 >= 0, sn0 * rf, np.copysign(2.0 * K, sn0) - sn0 * rf)
    return tau0 / (4.0 * K)


@jitable
def pole_offset(kappa2, m):
    """``v₁ = F(arccot κ | k'²) = R_F(κ², κ² + k², 1 + κ²)``: the pole of ``dψ/dτ`` off the real axis.

    Parameters
    ----------
    kappa2, m : float or ndarray, shape (...)
        ``κ² = e₁₂/e₂₃`` and ``k²``.

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> round(float(pole_offset(0.0, 1.0)), 14)  # κ = 0, k² = 1: R_F(0, 1, 1) = π/2
    1.57079632679490
    """
    return elliprf(kappa2, kappa2 + m, 1.0 + kappa2)


@jitable
def secular_rate(e13, e23, P3, G, w3, s, pi3, K):
    """``Ω_ψ = G w₃ + s G e₁₃ [Π(−κ²|k²) − c π/(2√(1 + κ²))]/K`` and ``Ω_ψ/2π``, double-doubles.

    ``c = a₃/G = √(P₃/e₁₃)/G`` and ``1/√(1 + κ²) = √(e₂₃/e₁₃)``.  Both terms can be large
    and of opposite signs (a LAM body turns about its polhode axis far more slowly than
    ``G/I₃``), so the mean is needed beyond double precision (see
    :mod:`andoyer.free.triaxial`).

    Parameters
    ----------
    e13, e23, P3, G, w3 : tuple of (float or ndarray, shape (...))
        Double-doubles.
    s : float or ndarray, shape (...)
        ``±1``.
    pi3, K : tuple of (float or ndarray, shape (...))
        Double-doubles ``Π(−κ²|k²)`` and ``K(k²)``.

    Returns
    -------
    rate, cycles : tuple
        ``Ω_ψ`` (rad per unit time) and ``Ω_ψ/2π`` as ``(hi, lo)``.

    Examples
    --------
    A sphere-like limit: ``P₃ = 0`` leaves ``Ω_ψ = G w₃ + s G e₁₃ Π/K``.

    >>> rate, cyc = secular_rate((1.0, 0.0), (1.0, 0.0), (0.0, 0.0), (2.0, 0.0), (0.5, 0.0), 1.0,
    ...                          (1.0, 0.0), (2.0, 0.0))
    >>> [float(x) for x in rate]
    [2.0, 0.0]
    """
    c = dd_div(*dd_sqrt(*dd_div(P3[0], P3[1], e13[0], e13[1])), G[0], G[1])
    root = dd_sqrt(*dd_div(e23[0], e23[1], e13[0], e13[1]))  # 1/√(1 + κ²)
    t = dd_mul(*dd_mul(c[0], c[1], root[0], root[1]), 0.5 * _PI_HI, 0.5 * _PI_LO)
    bracket = dd_add(pi3[0], pi3[1], -t[0], -t[1])
    corr = dd_div(*dd_mul(*dd_mul(G[0], G[1], e13[0], e13[1]), bracket[0], bracket[1]), K[0], K[1])
    rate = dd_add(*dd_mul(G[0], G[1], w3[0], w3[1]), s * corr[0], s * corr[1])
    return rate, dd_div(rate[0], rate[1], 2.0 * _PI_HI, 2.0 * _PI_LO)


@jitable
def polhode_scales(nu, K, Kp):
    """The polhode period ``4K/ω = 1/ν`` and ``kk = 2πK/K'``, the hyperbolic variable per cycle.

    Parameters
    ----------
    nu, K, Kp : float or ndarray, shape (...)
        High words of :func:`polhode_frequency` and of ``K``, and ``K'``.

    Returns
    -------
    period, kk : float or ndarray, shape (...)

    Examples
    --------
    >>> polhode_scales(0.25, 2.0, 4.0)
    (4.0, 3.141592653589793)
    """
    return 1.0 / nu, 2.0 * np.pi * K / Kp


@jitable
def psi_constants(circular, s, Kp, v1, rate, period):
    """The ``ψ`` slope and the mean precession rate of Andoyer's ``g``.

    The slope is the part of ``sΦ/2`` linear in the polhode phase (cycles per polhode cycle):
    ``s`` (circular series, per unreduced cycle) or ``s v₁/(2K')`` (hyperbolic, per reduced
    cycle); the precession rate is ``Ω_ψ + 2πs/period``.

    Parameters
    ----------
    circular : bool or ndarray of bool, shape (...)
        ``k² ≤ 1/2``.
    s, Kp, v1 : float or ndarray, shape (...)
        ``±1``, ``K'`` and :func:`pole_offset`.
    rate, period : float or ndarray, shape (...)
        High word of ``Ω_ψ`` (:func:`secular_rate`) and the polhode period.

    Returns
    -------
    slope, precession_rate : float or ndarray, shape (...)

    Examples
    --------
    >>> [float(x) for x in psi_constants(False, -1.0, 2.0, 1.0, 0.5, 4.0 * 3.141592653589793)]
    [-0.25, 0.0]
    """
    return s * select(circular, 1.0, 0.5 * v1 / Kp), rate + 2.0 * np.pi * s / period


@jitable
def theta_circular(q, v1, K, s, wa, wb):
    """Coefficients of the ``ϑ₁`` series of ``Φ``, circular case (``k² ≤ 1/2``), into ``wa, wb``.

    ``ϑ₁(x + iy₀ | q²)`` scaled by ``e^{−y₀} q^{−1/2}/2``, with ``e^{2y₀} = η/q²`` and
    ``η = e^{−πv₁/K}``: the ``n``-th terms are ``(−1)ⁿ(q^{2n²}ηⁿ ± q^{2(n+1)²}η^{−n−1})``
    (``wb`` times ``s``), formed by their ratios; three of them reach ``q¹⁸ < 10⁻²⁴``.

    Parameters
    ----------
    q, v1, K, s : float or ndarray, shape (...)
        The nome, :func:`pole_offset`, ``K`` and ``±1``.
    wa, wb : ndarray, shape (6, ...)
        Filled in rows 0–2 (the rest untouched).

    Examples
    --------
    >>> wa, wb = np.zeros(6), np.zeros(6)
    >>> theta_circular(0.0, 1.0, 1.0, 1.0, wa, wb)  # q = 0: ϑ₁ is its first term
    >>> wa.tolist()[:3], wb.tolist()[:3]
    ([1.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    """
    q2 = q * q
    eta = np.exp(-np.pi * v1 / K)
    head, tail = 1.0, q2 / eta  # q^{2n²} ηⁿ and q^{2(n+1)²} η^{−n−1}
    up, down = q2, q2 * q2 * q2  # their ratios q^{2(2n+1)}, q^{2(2n+3)} (but η)
    for n in range(3):
        sgn = 1.0 - 2.0 * (n % 2)
        wa[n] = sgn * (head + tail)
        wb[n] = sgn * (head - tail) * s
        head = head * (up * eta)
        tail = tail * (down / eta)
        up = up * (q2 * q2)
        down = down * (q2 * q2)


@jitable
def theta_hyperbolic(q, v1, Kp, s, wa, wb):
    """Coefficients of the ``ϑ₁`` series of ``Φ``, hyperbolic case (``k² > 1/2``), into ``wa, wb``.

    ``ϑ₁(a + ib | q*)`` with ``q* = √q'`` and ``a = −πv₀/(4K')``: ``(−1)ⁿ q*^{n²+n}`` times
    ``sin, cos((2n+1)a)`` (``wb`` times ``s``), the multiples of ``a`` by turns of ``2a``; six
    terms reach ``q*^{25} < 10⁻¹⁷`` at the worst nome ``q* = e^{−π/2}`` (``k² = 1/2``).

    Parameters
    ----------
    q, v1, Kp, s : float or ndarray, shape (...)
        The complementary nome ``q'``, :func:`pole_offset`, ``K'`` and ``±1``.
    wa, wb : ndarray, shape (6, ...)
        Filled.

    Examples
    --------
    >>> wa, wb = np.zeros(6), np.zeros(6)
    >>> theta_hyperbolic(0.0, 0.0, 1.0, 1.0, wa, wb)  # q' = 0, a = −π/2: sin a = −1
    >>> float(wa[0]), float(abs(wa[1])), bool(abs(wb[0]) < 1e-16)
    (-1.0, 0.0, True)
    """
    ang = -0.5 * np.pi + 0.25 * np.pi * v1 / Kp
    sn, cs = np.sin(ang), np.cos(ang)
    s2, c2 = 2.0 * sn * cs, (cs - sn) * (cs + sn)
    amp, step = 1.0, 1.0  # (−1)ⁿ q*^{n² + n}; ratio q*^{2n+2} = q^{n+1}
    for n in range(6):
        wa[n] = amp * sn
        wb[n] = amp * cs * s
        sn, cs = sn * c2 + cs * s2, cs * c2 - sn * s2
        step = step * q
        amp = -amp * step
