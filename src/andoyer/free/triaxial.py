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
integral of the third kind of the classical solution,
``∫f dτ = [Π(−κ²; am τ | m) − c A(am τ)]/(1 − c²)`` with ``A(φ) = ∫dθ/(1 + κ² sin²θ)``
(the characteristic of Sadov's ``Π(κ², λ)``, Gurfil eq. 143, in the other sign
convention), by a few series terms per epoch, and avoids its cancellation near pure spin.
The secular rate needs the complete ``Π(−κ²|m)``: it is taken from the AGM in
double-double arithmetic (:func:`andoyer.free.kernels.triaxial.secular_rate`), because
``Ω_ψ t`` reaches 10⁶ rad at 100 periods of a fast spinner.

Numbers are carried so that the phase stays exact over long times: the polhode frequency
``ω/4K`` and ``Ω_ψ/2π`` are double-doubles (``K`` from the AGM on ``1 − k²`` formed without
cancellation), multiplied by the time error-free (:mod:`andoyer.free.phase`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free import series
from andoyer.free.constants import rows
from andoyer.free.kernels.triaxial import (
    amplitudes,
    initial_phase,
    modulus,
    momentum_coefficients,
    pole_offset,
    polhode_frequency,
    polhode_scales,
    psi_constants,
    secular_rate,
    theta_circular,
    theta_hyperbolic,
)
from andoyer.free.phase import Frequency, frequency
from andoyer.free.regime import PolhodeFrame, attitude_anchor, working_axes
from andoyer.special.agm import ellippi_dd
from andoyer.special.compensated import dd_div, split
from andoyer.special.theta import lattice

__all__ = ["Triaxial", "triaxial"]

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
    mu_cn, mu_sn, mu_dn : ndarray, shape (3, N)
        Body-frame vectors with ``m = (mu_cn ϑ_cn + mu_sn ϑ_sn + mu_dn ϑ_dn)/ϑ₄``: the
        amplitudes ``a₁, s a₂, a₃`` along the working axes times the theta-quotient
        constants ``c_cn, c_sn, c_dn``, so that ``m`` needs no separate ``sn, cn, dn``.
    s : ndarray
        ``+1`` SAM, ``−1`` LAM.
    nu_psi : Frequency
        Secular rate of ``ψ`` in cycles per unit time.
    wa, wb : ndarray, shape (6, N)
        Coefficients of the ``ϑ₁`` series of ``Φ`` (``wb`` carries the factor ``s``).
    slope : ndarray
        The part of ``sΦ/2`` linear in the polhode phase that is not in the series, in
        cycles per polhode cycle: ``s`` (circular, per unreduced cycle) or ``s v₁/(2K')``
        (hyperbolic, per reduced cycle).
    psi0 : ndarray
        Offset of the ``ψ`` phase (cycles) that makes ``Δψ(0) = 0``.
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
    mu_cn: np.ndarray
    mu_sn: np.ndarray
    mu_dn: np.ndarray
    s: np.ndarray
    nu_psi: Frequency
    wa: np.ndarray
    wb: np.ndarray
    slope: np.ndarray
    psi0: np.ndarray
    quat_u: np.ndarray
    quat_v: np.ndarray
    v_sn: np.ndarray
    v_cn: np.ndarray
    G: np.ndarray
    a3: np.ndarray
    period: np.ndarray
    precession_rate: np.ndarray


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
    e12, e13, e23, P1, P3, G = (hi(x) for x in (frame.e12, frame.e13, frame.e23, frame.P1, frame.P3, frame.G))
    s = frame.s
    a1, a2, a3 = amplitudes(e13, e23, P1, P3)
    m, (mc_hi, mc_lo), omega2 = modulus(frame.e12, frame.e13, frame.e23, frame.P1, frame.P2, frame.P3)
    lat = lattice(m, mc_hi, mc_lo)
    K, Kp = lat.K_hi, lat.Kp
    nu = polhode_frequency(omega2, (lat.K_hi, lat.K_lo))  # ν = ω/(4K)
    frac0 = initial_phase(frame.mw[:, 0], frame.mw[:, 1], frame.mw[:, 2], (a1, a2, a3), s, K)

    v1 = pole_offset(e12 / e23, m)
    circ = lat.circular
    wa, wb, wa_h, wb_h = np.zeros((4, 6, s.size))
    theta_circular(lat.q, v1, K, s, wa, wb)
    theta_hyperbolic(lat.q, v1, Kp, s, wa_h, wb_h)
    wa = np.where(circ, wa, wa_h)
    wb = np.where(circ, wb, wb_h)
    # Π(−κ²|k²) for the secular rate of ψ from the AGM in double-double (DLMF 19.8.6)
    kap2 = dd_div(*frame.e12, *frame.e23)
    pi3 = ellippi_dd(-kap2[0], -kap2[1], mc_hi, mc_lo)
    K_dd = (lat.K_hi, lat.K_lo)
    rate, nu_psi = secular_rate(frame.e13, frame.e23, frame.P3, frame.G, frame.w3, s, pi3, K_dd)
    period, kk = polhode_scales(nu[0], K, Kp)
    slope, precession_rate = psi_constants(circ, s, Kp, v1, rate[0], period)

    cols = working_axes(frame)
    mu_cn, mu_sn, mu_dn, v_sn, v_cn = momentum_coefficients((a1, a2, a3), s, lat.c_sn, lat.c_cn, lat.c_dn)
    const = Triaxial(
        circular=circ,
        nu=frequency(*nu),
        frac0=frac0,
        q=lat.q,
        c_sn=lat.c_sn,
        c_cn=lat.c_cn,
        c_dn=lat.c_dn,
        kk=kk,
        mu_cn=mu_cn * cols[0],
        mu_sn=mu_sn * cols[1],
        mu_dn=mu_dn * cols[2],
        s=s,
        nu_psi=frequency(*nu_psi),
        wa=wa,
        wb=wb,
        slope=slope,
        psi0=np.zeros_like(s),
        quat_u=np.zeros((4, s.size)),
        quat_v=np.zeros((4, s.size)),
        v_sn=v_sn * cols[0],
        v_cn=v_cn * cols[1],
        G=G,
        a3=a3,
        period=period,
        precession_rate=precession_rate,
    )
    if q0 is None:
        return const
    # the ψ phase that makes Δψ(0) = 0, from the kernels themselves (to round-off)
    psi0 = np.empty_like(s)
    zero = np.zeros(1)
    for kind, kernel in ((True, series.circular), (False, series.hyperbolic)):
        sel = np.nonzero(circ == kind)[0]
        if sel.size:
            sub = rows(const, sel)
            _, _, phase = kernel(sub, zero, split(zero), True)
            cz, sz = series.half_angle(sub, zero, split(zero), phase)
            psi0[sel] = -np.arctan2(sz, cz)[:, 0] / np.pi
    const = const._replace(psi0=psi0)
    quat_u, quat_v = attitude_anchor(frame, q0)
    return const._replace(quat_u=quat_u, quat_v=quat_v)
