r"""Exact torque-free motion of a triaxial body in SAM or LAM (off the separatrix).

In the working frame of :mod:`andoyer.free.regime` (axis 3 the polhode axis, ``m₃ > 0``)
the body angular momentum is (Jacobi; Gurfil et al. A.2 for SAM, with ``s`` for LAM)

.. math::
   m_1 = a_1 \operatorname{cn}\tau,\quad m_2 = s\,a_2 \operatorname{sn}\tau,\quad
   m_3 = a_3 \operatorname{dn}\tau,\qquad \tau = \omega t + \tau_0,\quad
   a_1^2 = \frac{P_1}{e_{13}},\ a_2^2 = \frac{P_1}{e_{23}},\ a_3^2 = \frac{P_3}{e_{13}},\
   k^2 = \frac{e_{12} P_1}{e_{23} P_3},\ \omega^2 = e_{23} P_3 .

Attitude.  With ``S(m)`` the shortest-arc rotation taking ``m`` to ``+z``
(:func:`andoyer.free.quaternion.shortest_arc`), ``rot_w(t) = Q₀ R_z(Δψ(t)) S(m(t))``,
where ``Q₀`` is fixed by the initial attitude and ``ψ = g + l`` (Andoyer's node plus
proper-rotation angles, regular at ``J = 0``) obeys

.. math:: \dot\psi = G w_3 + \frac{D - G^2 w_3}{G + m_3}.

With ``c = a₃/G`` and ``f(τ) = 1/(1 + c dn τ)``, ``Δψ = G w₃ Δt + (sP₁/(Gω)) ∫f dτ``.
``f`` is elliptic with periods ``2K, 4iK'`` and simple poles at ``±i v₀``, ``v₀ = 2K' − v₁``,
``v₁ = F(arccot κ | m') = R_F(κ², κ² + m, 1 + κ²)``, ``κ² = e₁₂/e₂₃``, residues ``±iρ``,
``ρ = G a₃ / (a₁² √(1 + κ²))``.  The partial-fraction expansion in ``ϑ₁(·|q²)`` then gives
(``sP₁ρ/(Gω) = s`` exactly)

.. math::
   \Delta\psi = \Omega_\psi \Delta t + s\,[\Phi(\tau) - \Phi(\tau_0)],\qquad
   \Phi(\tau) = \frac{\pi\tau}{K}
      + 2\arg\vartheta_1\Big(\frac{\pi(\tau + i v_0)}{2K}\Big|q^2\Big),
   \qquad \Omega_\psi = G w_3 + \frac{s P_1}{G}\langle f\rangle .

``Φ`` is ``2K``-periodic modulo ``2π`` and only ``e^{iΦ/2}`` (up to sign) is needed, so
no branch of ``arg`` has to be tracked.  For ``m ≤ 1/2`` the series in ``q² ≤ e^{−2π}`` is
used directly ("circular"); for ``m > 1/2`` it is rewritten by Jacobi's imaginary
transformation (DLMF 20.7.30) as a series in ``q* = √q' ≤ e^{−π/2}`` of hyperbolic
functions plus a term linear in ``τ`` ("hyperbolic").  This replaces the incomplete
integral of the third kind ``Π(−κ²; am τ | m)`` of the classical solution (same
characteristic as Sadov's ``Π(κ², λ)`` up to the sign convention) by a few terms per
epoch, and avoids its cancellation near pure spin.  The mean ``⟨f⟩`` is obtained from
the same theta constants; tests compare it with ``[Π(−κ²|m) − cπ/(2√(1+κ²))]/(K(1 − c²))``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy import special as sc

from andoyer.free.phase import Frequency, cycles, frequency
from andoyer.free.quaternion import qmul
from andoyer.free.regime import PolhodeFrame, attitude_anchor, working_axes
from andoyer.special.agm import ellippi_dd
from andoyer.special.compensated import PI_DD, dd_add, dd_div, dd_mul, dd_sqrt, split
from andoyer.special.theta import lattice

__all__ = ["Triaxial", "evaluate", "triaxial"]

_TWO_PI = (2.0 * PI_DD[0], 2.0 * PI_DD[1])


class Triaxial(NamedTuple):
    """Per-state constants of the triaxial solution (arrays; vectors are ``(3, N)``).

    Attributes
    ----------
    circular : ndarray of bool
        ``k² ≤ 1/2`` (circular theta series) or not (hyperbolic).
    nu : Frequency
        Polhode frequency ``ω/(4K)`` in cycles per unit time (double-double).
    frac0 : ndarray
        Initial polhode phase ``τ₀/(4K)``.
    q, c_sn, c_cn, c_dn : ndarray
        Theta-quotient constants (:class:`andoyer.special.theta.ThetaLattice`).
    kk : ndarray
        ``2πK/K'``: hyperbolic variable per cycle.
    u_cn, u_sn, u_dn : ndarray, shape (3, N)
        Body-frame vectors with ``m = u_cn cn τ + u_sn sn τ + u_dn dn τ``.
    s : ndarray
        ``+1`` SAM, ``−1`` LAM.
    nu_psi : Frequency
        Secular rate of ``ψ`` in cycles per unit time.
    wa, wb : ndarray, shape (6, N)
        Coefficients of the ``ϑ₁`` series of ``Φ`` (``wb`` carries the factor ``s``).
    slope : ndarray
        ``s π v₁/K'`` (hyperbolic) or ``2πs`` (circular): the angle ``Φ/2`` per cycle that
        is not in the series.
    k0 : tuple of ndarray
        ``e^{−isΦ(τ₀)/2}`` as ``(cos, sin)``.
    quat_u, quat_v : ndarray, shape (4, N)
        ``Q₀ ⊗ P`` and ``Q₀ ⊗ e_z ⊗ P`` (zero when no attitude was given).
    v_sn, v_cn : ndarray, shape (3, N)
        Body-frame vector part of the shortest-arc factor: ``v_sn sn τ + v_cn cn τ``.
    G, a3 : ndarray
        ``|m|`` and the amplitude of ``m₃``.
    period, precession_rate : ndarray
        ``4K/ω`` and the mean rate of Andoyer's ``g`` about the polhode axis.
    """

    circular: np.ndarray
    nu: Frequency
    frac0: np.ndarray
    q: np.ndarray
    c_sn: np.ndarray
    c_cn: np.ndarray
    c_dn: np.ndarray
    kk: np.ndarray
    u_cn: np.ndarray
    u_sn: np.ndarray
    u_dn: np.ndarray
    s: np.ndarray
    nu_psi: Frequency
    wa: np.ndarray
    wb: np.ndarray
    slope: np.ndarray
    k0: tuple
    quat_u: np.ndarray
    quat_v: np.ndarray
    v_sn: np.ndarray
    v_cn: np.ndarray
    G: np.ndarray
    a3: np.ndarray
    period: np.ndarray
    precession_rate: np.ndarray


def _initial_tau(mw, amplitudes, s, K):
    """``τ₀ = F(am τ₀ | m)`` from the measured ``cn, sn, dn`` (Carlson, no cancellation)."""
    a1, a2, a3 = amplitudes
    cn0 = mw[:, 0] / a1
    sn0 = mw[:, 1] / (s * a2)
    dn0 = mw[:, 2] / a3
    rf = sc.elliprf(cn0 * cn0, dn0 * dn0, 1.0)
    return np.where(cn0 >= 0, sn0 * rf, np.copysign(2.0 * K, sn0) - sn0 * rf)


def _theta_circular(q, v1, K):
    """Coefficients of ``ϑ₁(x + iy₀ | q²)`` scaled by ``e^{−y₀} q^{−1/2}/2`` (circular case).

    ``e^{2y₀} = η/q²`` with ``η = e^{−πv₁/K}``; the ``n``-th terms are
    ``(−1)ⁿ(q^{2n²}ηⁿ ± q^{2(n+1)²}η^{−n−1})``, three of them reach ``q^{18} < 10⁻²⁴``.
    """
    qt = q * q
    eta = np.exp(-np.pi * v1 / K)
    wa = np.zeros((6, q.size))
    wb = np.zeros((6, q.size))
    for n in range(3):
        head = qt ** (n * n) * eta**n
        tail = qt ** ((n + 1) ** 2) * eta ** (-(n + 1))
        sgn = (-1.0) ** n
        wa[n] = sgn * (head + tail)
        wb[n] = sgn * (head - tail)
    return wa, wb


def _theta_hyperbolic(q, v1, Kp):
    """Coefficients of ``ϑ₁(a + ib | q*)``, ``q* = √q'``, ``a = −πv₀/(4K')`` (hyperbolic case).

    Six terms reach ``q*^{25} < 10⁻¹⁷`` at the worst nome ``q* = e^{−π/2}`` (``m = 1/2``).
    """
    qs = np.sqrt(q)
    a = -0.5 * np.pi + 0.25 * np.pi * v1 / Kp
    wa = np.zeros((6, q.size))
    wb = np.zeros((6, q.size))
    for n in range(6):
        amp = (-1.0) ** n * qs ** (n * n + n)
        wa[n] = amp * np.sin((2 * n + 1) * a)
        wb[n] = amp * np.cos((2 * n + 1) * a)
    return wa, wb


def _secular_rate(frame: PolhodeFrame, mc_dd, K_dd):
    """``Ω_ψ = G w₃ + s G e₁₃ [Π(−κ²|m) − cπ/(2√(1+κ²))]/K`` in double-double.

    This is ``G w₃ + (sP₁/G)⟨1/(1 + c dn)⟩`` with ``⟨·⟩`` written through the complete
    integral of the third kind (``(sP₁/G)/(K(1 − c²)) = sGe₁₃/K``).  Both terms can be
    large and of opposite signs (a LAM body turns about its polhode axis far more
    slowly than ``G/I₃``), so the mean is needed beyond double precision: at 100 periods
    ``Ω_ψ t`` may be 10⁶ rad.  Π comes from the AGM (DLMF 19.8.6) in double-double.
    """
    kap2 = dd_div(*frame.e12, *frame.e23)
    pi3 = ellippi_dd(-kap2[0], -kap2[1], *mc_dd)
    c = dd_div(*dd_sqrt(*dd_div(*frame.P3, *frame.e13)), *frame.G)
    root = dd_sqrt(*dd_div(*frame.e23, *frame.e13))  # 1/√(1 + κ²)
    t = dd_mul(*dd_mul(*c, *root), 0.5 * PI_DD[0], 0.5 * PI_DD[1])
    bracket = dd_add(*pi3, -t[0], -t[1])
    corr = dd_div(*dd_mul(*dd_mul(*frame.G, *frame.e13), *bracket), *K_dd)
    return dd_add(*dd_mul(*frame.G, *frame.w3), frame.s * corr[0], frame.s * corr[1])


def triaxial(frame: PolhodeFrame, q0=None):
    """Constants of the triaxial solution for states off the separatrix and off pure spin.

    Parameters
    ----------
    frame : PolhodeFrame
        Working frame and invariants (``P₁ > 0``, ``P₂ ≠ 0``).
    q0 : ndarray, shape (N, 4), optional
        Initial attitude quaternions (scalar last, body → reference, unit norm).

    Returns
    -------
    Triaxial

    Examples
    --------
    >>> from andoyer.free.regime import polhode_frame
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.3, 0.2, 1.0]]),
    ...                    np.array([False]))
    >>> round(float(triaxial(fr).period[0]), 10)
    20.2049347381
    """
    hi = lambda p: p[0]  # noqa: E731
    e12, e13, e23, P1, P3, G = (
        hi(x) for x in (frame.e12, frame.e13, frame.e23, frame.P1, frame.P3, frame.G)
    )
    s = frame.s
    a1 = np.sqrt(P1 / e13)
    a2 = np.sqrt(P1 / e23)
    a3 = np.sqrt(P3 / e13)
    den = dd_mul(*frame.e23, *frame.P3)
    m = dd_div(*dd_mul(*frame.e12, *frame.P1), *den)[0]
    mc_hi, mc_lo = dd_div(*dd_mul(*frame.e13, *frame.P2), *den)
    lat = lattice(m, mc_hi, mc_lo)
    K, Kp = lat.K_hi, lat.Kp
    om = dd_sqrt(*den)
    nu = dd_div(*om, 4.0 * lat.K_hi, 4.0 * lat.K_lo)
    frac0 = _initial_tau(frame.mw, (a1, a2, a3), s, K) / (4.0 * K)

    kappa2 = e12 / e23
    v1 = sc.elliprf(kappa2, kappa2 + m, 1.0 + kappa2)
    circ = lat.circular
    wa, wb = _theta_circular(lat.q, v1, K)
    wa_h, wb_h = _theta_hyperbolic(lat.q, v1, Kp)
    wa = np.where(circ, wa, wa_h)
    wb = np.where(circ, wb, wb_h) * s
    rate = _secular_rate(frame, (mc_hi, mc_lo), (lat.K_hi, lat.K_lo))
    nu_psi = dd_div(*rate, *_TWO_PI)
    slope = s * np.where(circ, 2.0 * np.pi, np.pi * v1 / Kp)

    cols = working_axes(frame)
    period = 1.0 / nu[0]
    const = Triaxial(
        circular=circ, nu=frequency(*nu), frac0=frac0, q=lat.q, c_sn=lat.c_sn, c_cn=lat.c_cn,
        c_dn=lat.c_dn, kk=2.0 * np.pi * K / Kp,
        u_cn=a1 * cols[0], u_sn=s * a2 * cols[1], u_dn=a3 * cols[2],
        s=s, nu_psi=frequency(*nu_psi), wa=wa, wb=wb, slope=slope,
        k0=(np.ones_like(s), np.zeros_like(s)),
        quat_u=np.zeros((4, s.size)), quat_v=np.zeros((4, s.size)),
        v_sn=s * a2 * cols[0], v_cn=-a1 * cols[1], G=G, a3=a3,
        period=period, precession_rate=rate[0] + 2.0 * np.pi * s / period,
    )
    if q0 is None:
        return const
    # e^{−isΦ(τ₀)/2} from the kernel itself at t = 0, so that Δψ(0) = 0 to round-off.
    _, (wr, wi) = _phase_factor(const, np.zeros_like(s))
    const = const._replace(k0=(wr, -wi))
    quat_u, quat_v = attitude_anchor(frame, cols, q0)
    return const._replace(quat_u=quat_u, quat_v=quat_v)


def _polhode(c: Triaxial, t, tt):
    """Reduced polhode phase ``f_w ∈ [−1/4, 1/4]`` and the sign ``(−1)^j`` of ``sn, cn``."""
    f = cycles(c.nu, t, tt, c.frac0)
    j = np.round(2.0 * f)
    return f - 0.5 * j, 1.0 - 2.0 * np.abs(j)


def _sncndn_circular(c: Triaxial, fw):
    x = (2.0 * np.pi) * fw
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
    q = c.q
    q2 = q * q
    q4 = q2 * q2
    q6 = q4 * q2
    q12 = q6 * q6
    even = q4 * c4
    odd = q * c2 + (q6 * q2 * q) * c6
    inv = 1.0 / (1.0 + 2.0 * (even - odd))
    sn = c.c_sn * inv * (s1 - q2 * s3 + q6 * s5 - q12 * s7)
    cn = c.c_cn * inv * (c1 + q2 * c3 + q6 * c5 + q12 * c7)
    dn = c.c_dn * inv * (1.0 + 2.0 * (even + odd))
    x = c.wa[0] * s1 + c.wa[1] * s3 + c.wa[2] * s5
    y = c.wb[0] * c1 + c.wb[1] * c3 + c.wb[2] * c5
    return sn, cn, dn, (x, y)


def _sncndn_hyperbolic(c: Triaxial, fw):
    y = c.kk * np.abs(fw)
    zi = np.exp(-y)
    rho = zi * zi
    q = c.q
    z = q / rho
    q2 = q * q
    q4 = q2 * q2
    q6 = q4 * q2
    q9 = q6 * q2 * q
    rho2 = rho * rho
    z2 = z * z
    a1, b1 = q * z, q2 * rho2
    a2, b2 = q4 * z2, q6 * rho2 * rho
    a3, b3 = q9 * z2 * z, (q6 * q6) * rho2 * rho2
    inv = 1.0 / ((1.0 + rho) + (a1 + b1) + (a2 + b2) + (a3 + b3))
    t1 = z + q * rho
    t2 = q2 * z2 + q4 * rho2
    t3 = q6 * z2 * z + q9 * rho2 * rho
    sn = np.copysign(c.c_sn * inv * ((1.0 - rho) - (a1 - b1) + (a2 - b2) - (a3 - b3)), fw)
    cn = c.c_cn * inv * zi * ((1.0 - t1) + (t2 - t3))
    dn = c.c_dn * inv * zi * (1.0 + t1 + t2 + t3)
    # ϑ₁(a + ib | q*) scaled by e^{−|b|}, with ζ = e^{2|b|} = 1/zi.
    zeta = 1.0 / zi
    up, down = np.ones_like(zi), zi
    re = c.wa[0] * (up + down)
    im = c.wb[0] * (up - down)
    for n in range(1, 6):
        up = up * zeta
        down = down * zi
        re = re + c.wa[n] * (up + down)
        im = im + c.wb[n] * (up - down)
    return sn, cn, dn, (re, np.where(fw < 0, -im, im))


def _sncndn(c: Triaxial, fw):
    """The series kind of the constants, or both merged when they are mixed (set-up only)."""
    if np.all(c.circular):
        return _sncndn_circular(c, fw)
    if not np.any(c.circular):
        return _sncndn_hyperbolic(c, fw)
    a, b = _sncndn_circular(c, fw), _sncndn_hyperbolic(c, fw)
    pick = lambda u, v: np.where(c.circular, u, v)  # noqa: E731
    return (*(pick(u, v) for u, v in zip(a[:3], b[:3], strict=True)),
            (pick(a[3][0], b[3][0]), pick(a[3][1], b[3][1])))


def _phase_factor(c: Triaxial, t, tt=None):
    """Polhode quantities and ``e^{i(Δψ/2 − 2π f_ψ... )}`` before the initial correction."""
    fw, sgn = _polhode(c, t, tt)
    sn, cn, dn, (x, y) = _sncndn(c, fw)
    beta = np.pi * cycles(c.nu_psi, t, tt) + c.slope * fw
    cb, sb = np.cos(beta), np.sin(beta)
    inv = 1.0 / np.sqrt(x * x + y * y)
    x, y = x * inv, y * inv
    return (sgn * sn, sgn * cn, dn), (cb * x - sb * y, cb * y + sb * x)


def evaluate(c: Triaxial, t, attitude=True):
    """Body angular momentum and attitude of triaxial states at times ``t``.

    Parameters
    ----------
    c : Triaxial
        Constants, all of one series kind (all circular or all hyperbolic), with fields
        shaped to broadcast against ``t`` (vectors with a leading axis of 3 or 4).
    t : ndarray
        Times since the initial state.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray
        Body-frame angular momentum components.
    q : tuple of 4 ndarray or None
        Attitude quaternion components ``(x, y, z, w)``.

    Examples
    --------
    >>> from andoyer.free.regime import polhode_frame
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.3, 0.2, 1.0]]),
    ...                    np.array([False]))
    >>> m, _ = evaluate(triaxial(fr), np.zeros(1), attitude=False)
    >>> [round(float(v[0]), 14) for v in m]
    [0.3, 0.2, 1.0]
    """
    tt = split(t)
    if not attitude:
        fw, sgn = _polhode(c, t, tt)
        sn, cn, dn, _ = _sncndn(c, fw)
        sn, cn = sgn * sn, sgn * cn
        return tuple(c.u_cn[k] * cn + c.u_sn[k] * sn + c.u_dn[k] * dn for k in range(3)), None
    (sn, cn, dn), (wr, wi) = _phase_factor(c, t, tt)
    m = tuple(c.u_cn[k] * cn + c.u_sn[k] * sn + c.u_dn[k] * dn for k in range(3))
    cz = wr * c.k0[0] - wi * c.k0[1]
    sz = wr * c.k0[1] + wi * c.k0[0]
    au = tuple(cz * c.quat_u[k] + sz * c.quat_v[k] for k in range(4))
    w = c.G + c.a3 * dn
    inv = 1.0 / np.sqrt(2.0 * c.G * w)
    arc = (*((c.v_sn[k] * sn + c.v_cn[k] * cn) * inv for k in range(3)), w * inv)
    return m, qmul(au, arc)
