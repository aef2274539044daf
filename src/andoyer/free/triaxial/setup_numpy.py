"""The constants of the triaxial solution on arrays (the numpy driver of ``setup``).

The formulas (derived in :mod:`andoyer.free.triaxial`) are the kernels of
:mod:`andoyer.free.triaxial.setup` and of the working frame
(:mod:`andoyer.free.common.polhode_numpy`), applied to whole arrays; the compiled driver
(:mod:`andoyer.free.triaxial.setup_compiled`) runs the same kernels per state.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.common.constants import rows
from andoyer.free.common.cycles_numpy import Frequency, frequency
from andoyer.free.common.polhode_numpy import PolhodeFrame, attitude_anchor, working_axes
from andoyer.free.triaxial import evaluate_numpy as series
from andoyer.free.triaxial.setup import (
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
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
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
