"""The constants of the triaxial solution, built body by body in one compiled loop.

:func:`andoyer.free.triaxial.setup_numpy.triaxial` forms the constants of many bodies with numpy: a
few hundred passes over the arrays, most of them double-double arithmetic (the working frame and
invariants of :func:`andoyer.free.common.polhode_numpy.polhode_frame`, ``K`` and ``Π`` by the AGM,
the frequencies), 6–10 µs a body.  Here the same formulas run per body in a numba kernel, about 1 µs
a body: most of them are the very kernels the numpy set-up calls (the working frame, its invariants
and the attitude anchor of :mod:`andoyer.free.common.polhode`, the formulas of
:mod:`andoyer.free.triaxial.setup`, :func:`andoyer.special.theta.quotient_constants`), run on floats
in the double-double arithmetic of :mod:`andoyer.special.compensated` (error-free products by fused
multiply-add, one-correction division).  Written here for one body: ``K`` is taken from the AGM
sequence of ``Π`` (the same sequence), ``K'`` from the nome (the numpy set-up runs a second AGM),
the ``ψ`` offset from the series at ``τ₀`` directly (the numpy set-up evaluates its per-epoch series
at ``t = 0``), and without an attitude the quantities only the attitude needs (``Π``, the ``ϑ₁``
series) can be skipped.  The constants agree with the numpy ones to a few ulps, the frame's and the
anchor's bit for bit (``tests/free/test_free_compiled.py``); they are stored one row per body, as
:mod:`andoyer.free.triaxial.evaluate_compiled` reads them, in the columns named by
:mod:`andoyer.free.triaxial.columns`. :class:`andoyer.free.FreeMotion` uses both when numba is
installed (:data:`andoyer._jit.NUMBA`).
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import jit
from andoyer.free.common.cycles_numpy import Frequency
from andoyer.free.common.polhode import anchor, invariants, permutation_quaternion, polhode_axes, sorted_axes
from andoyer.free.triaxial.columns import (
    A3,
    C_CN,
    C_DN,
    C_SN,
    CIRCULAR,
    FLAT,
    FRAC0,
    HH,
    HI,
    HL,
    KK,
    LO,
    MU_CN,
    MU_DN,
    MU_SN,
    NCOLUMNS,
    NU,
    NU_PSI,
    NWA,
    PERIOD,
    PRECESSION_RATE,
    PSI0,
    QUAT_U,
    QUAT_V,
    SLOPE,
    V_CN,
    V_SN,
    WA,
    WB,
    G,
    Q,
    S,
)
from andoyer.free.triaxial.evaluate_compiled import _count
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
from andoyer.free.triaxial.setup_numpy import Triaxial
from andoyer.special.agm import ellipk_dd, ellippi_k_dd
from andoyer.special.compensated import dd_div, split
from andoyer.special.theta import nome, quotient_constants

__all__ = ["as_triaxial", "triaxial_table"]


@jit
def _psi_offset(circ, f0, q, wa, wb, kk, slope):
    """``ψ`` offset (cycles) that makes ``Δψ(0) = 0``: minus the series' phase at ``τ₀``."""
    f = f0 - np.rint(f0)
    if circ:
        lin = f
        q2 = q * q
        n_w = _count((1.0, q2, q2 * q2 * q2 * q2))  # as andoyer.free.triaxial.evaluate_numpy
        re = im = 0.0
        sn, cs = math.sin(2.0 * math.pi * f), math.cos(2.0 * math.pi * f)
        s2, c2 = 2.0 * sn * cs, (cs - sn) * (cs + sn)
        for n in range(n_w):  # sin, cos((2n+1)x) by turns of 2x
            re += wa[n] * sn
            im += wb[n] * cs
            sn, cs = sn * c2 + cs * s2, cs * c2 - sn * s2
    else:
        lin = f - 0.5 * np.rint(2.0 * f)
        zi = math.exp(-kk * abs(lin))
        q3 = q * q * q
        n_w = _count((1.0, q, q3, q3 * q3, q3 * q3 * q3 * q, q3 * q3 * q3 * q3 * q3))  # q*^{n² + n}
        re, im = wa[0] * (1.0 + zi), wb[0] * (1.0 - zi)
        up, down = 1.0, zi
        for n in range(1, n_w):
            up /= zi
            down *= zi
            re += wa[n] * (up + down)
            im += wb[n] * (up - down)
        if lin < 0:
            im = -im
    a = 2.0 * slope * lin + math.atan2(im, re) / math.pi  # half-turns
    return -(a - 2.0 * np.rint(0.5 * a))


@jit
def _body(Ib, mb, lam, q0, out, i, full):
    """Constants of body ``i`` into row ``i`` of ``out`` (columns: :mod:`andoyer.free.triaxial.columns`)."""
    # working frame: axis 3 the polhode axis (C for SAM, A for LAM), axis 2 the middle one
    # (the kernels of andoyer.free.common.polhode, as andoyer.free.common.polhode_numpy.polhode_frame)
    p1, p2, p3, sigma2, sigma3 = polhode_axes(*sorted_axes(Ib[0], Ib[1], Ib[2]), lam, mb[0], mb[1], mb[2])
    mw = (mb[p1], mb[p2] * sigma2, mb[p3] * sigma3)
    s = -1.0 if lam else 1.0
    e12, e13, e23, P1, P2, P3, g_dd, w3 = invariants(s, Ib[p1], Ib[p2], Ib[p3], mw[0], mw[1], mw[2])
    out[i, FLAT] = 1.0 if P1[0] == 0.0 else 0.0
    if P1[0] == 0.0:  # a steady spin: FreeMotion routes it elsewhere
        return
    e12h, e13h, e23h, P1h, P3h, Gh = e12[0], e13[0], e23[0], P1[0], P3[0], g_dd[0]
    # amplitudes, modulus, K, Π (the kernels of andoyer.free.triaxial.setup)
    a1, a2, a3 = amplitudes(e13h, e23h, P1h, P3h)
    m, (mch, mcl), omega2 = modulus(e12, e13, e23, P1, P2, P3)
    if full:  # Π(−κ²|m) for the secular rate of ψ, and K from the same AGM
        k2h, k2l = dd_div(*e12, *e23)
        p3h, p3l, Kh, Kl = ellippi_k_dd(-k2h, -k2l, mch, mcl)
    else:  # the momentum needs K only
        p3h = p3l = 0.0
        Kh, Kl = ellipk_dd(mch, mcl)
    circ = m <= 0.5
    q = nome(min(m, 0.5), max(mch, 0.5)) if circ else nome(min(mch, 0.5), max(m, 0.5))
    # K' from the nome q = exp(−πK'/K) (circular) or q' = exp(−πK/K') (hyperbolic), no
    # second AGM: K' enters only reduced phases
    if circ:
        Kp = -Kh * math.log(q) / math.pi
    else:  # (K' = K(m') → π/2 (1 + m'/4) where q' would underflow)
        Kp = -math.pi * Kh / math.log(q) if q > 1e-300 else 0.5 * math.pi * (1.0 + 0.25 * mch)
    c_sn, c_cn, c_dn = quotient_constants(q, circ)
    nuh, nul = polhode_frequency(omega2, (Kh, Kl))
    frac0 = initial_phase(mw[0], mw[1], mw[2], (a1, a2, a3), s, Kh)
    period, kk = polhode_scales(nuh, Kh, Kp)
    nhh, nhl = split(nuh)
    out[i, CIRCULAR] = 1.0 if circ else 0.0
    out[i, NU + HI] = nuh
    out[i, NU + LO] = nul
    out[i, NU + HH] = nhh
    out[i, NU + HL] = nhl
    out[i, FRAC0] = frac0
    out[i, Q] = q
    out[i, C_SN] = c_sn
    out[i, C_CN] = c_cn
    out[i, C_DN] = c_dn
    out[i, KK] = kk
    # working axis j is sigma_j times body axis p_j
    mu_cn, mu_sn, mu_dn, v_sn, v_cn = momentum_coefficients((a1, a2, a3), s, c_sn, c_cn, c_dn)
    out[i, MU_CN + p1] = mu_cn
    out[i, MU_SN + p2] = mu_sn * sigma2
    out[i, MU_DN + p3] = mu_dn * sigma3
    out[i, V_SN + p1] = v_sn
    out[i, V_CN + p2] = v_cn * sigma2
    out[i, G] = Gh
    out[i, A3] = a3
    out[i, PERIOD] = period
    out[i, S] = s
    if not full:
        out[i, PRECESSION_RATE] = math.nan  # the precession rate needs Π
        return
    v1 = pole_offset(e12h / e23h, m)
    wa = out[i, WA : WA + NWA]  # views into the table: no allocation per body
    wb = out[i, WB : WB + NWA]
    if circ:
        theta_circular(q, v1, Kh, s, wa, wb)
    else:
        theta_hyperbolic(q, v1, Kp, s, wa, wb)
    rate, (psh, psl) = secular_rate(e13, e23, P3, g_dd, w3, s, (p3h, p3l), (Kh, Kl))
    slope, precession_rate = psi_constants(circ, s, Kp, v1, rate[0], period)
    phh, phl = split(psh)
    out[i, NU_PSI + HI] = psh
    out[i, NU_PSI + LO] = psl
    out[i, NU_PSI + HH] = phh
    out[i, NU_PSI + HL] = phl
    out[i, SLOPE] = slope
    out[i, PRECESSION_RATE] = precession_rate
    if q0.shape[0] == 0:
        return
    out[i, PSI0] = _psi_offset(circ, frac0, q, wa, wb, kk, slope)
    # U = Q₀ ⊗ P, V = Q₀ ⊗ e_z ⊗ P (andoyer.free.common.polhode_numpy.attitude_anchor)
    pq = permutation_quaternion(p1, p2, p3, sigma2, sigma3)
    U, V = anchor(q0[i, 0], q0[i, 1], q0[i, 2], q0[i, 3], pq, mw[0], mw[1], mw[2], Gh)
    for k in range(4):
        out[i, QUAT_U + k] = U[k]
        out[i, QUAT_V + k] = V[k]


@jit
def _all(moments, m0, lam, q0, out, full):
    for i in range(moments.shape[0]):
        _body(moments[i], m0[i], lam[i], q0, out, i, full)


def triaxial_table(moments, m0, lam, q0=None, rate=True):
    """Constants of the triaxial solution as one table, rows in the order of :class:`Triaxial`.

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Strictly triaxial moments and body angular momenta, off the separatrix, scaled
        by :func:`andoyer.free.common.scaling_numpy.normalise`.
    lam : ndarray of bool, shape (N,)
        True for LAM states.
    q0 : ndarray, shape (N, 4), optional
        Initial attitude quaternions (unit, scalar last, body → reference).
    rate : bool, optional
        Compute the secular rate of ``ψ`` (the precession rate) even without ``q0``.
        ``False`` without ``q0`` skips the quantities only the attitude needs (``Π``,
        the ``ϑ₁`` series; about half the cost): the table is good for the momentum, its
        precession rate is ``nan``.

    Returns
    -------
    table : ndarray, shape (M, NCOLUMNS)
        One row per state that is not a steady spin (the constants of a state lie
        together in memory, as the compiled evaluation reads them); the columns are named
        in :mod:`andoyer.free.triaxial.columns` (``FLAT`` is zero in every row kept).
    flat : ndarray of bool, shape (N,)
        States whose wobble ``P₁`` underflows to zero: steady spins about the polhode
        axis, which have no column.

    Examples
    --------
    >>> table, flat = triaxial_table(np.array([[0.25, 0.5, 0.75]]), np.array([[0.3, 0.2, 1.0]]),
    ...                              np.array([False]))
    >>> table.shape, round(float(table[0, PERIOD]) * 4, 10), flat.tolist()  # time scales as I
    ((1, 58), 20.2049347381, [False])
    """
    n = moments.shape[0]
    out = np.zeros((n, NCOLUMNS))
    q = np.zeros((0, 4)) if q0 is None else np.ascontiguousarray(q0, dtype=np.float64)
    _all(
        np.ascontiguousarray(moments, dtype=np.float64),
        np.ascontiguousarray(m0, dtype=np.float64),
        np.ascontiguousarray(lam, dtype=np.bool_),
        q,
        out,
        bool(rate or q0 is not None),
    )
    flat = out[:, FLAT] > 0
    if np.any(flat):
        out = out[~flat]
    return out, flat


def as_triaxial(table):
    """The :class:`Triaxial` constants of a table from :func:`triaxial_table` (views).

    Parameters
    ----------
    table : ndarray, shape (N, NCOLUMNS)
        A table of :func:`triaxial_table` (columns: :mod:`andoyer.free.triaxial.columns`).

    Returns
    -------
    Triaxial

    Examples
    --------
    >>> table, _ = triaxial_table(np.array([[0.25, 0.5, 0.75]]), np.array([[0.3, 0.2, 1.0]]),
    ...                           np.array([False]))
    >>> as_triaxial(table).mu_cn.shape
    (3, 1)
    """
    out = table.T
    freq = lambda r: Frequency(out[r + HI], out[r + LO], out[r + HH], out[r + HL])  # noqa: E731
    vec = lambda r, n=3: out[r : r + n]  # noqa: E731
    return Triaxial(
        circular=out[CIRCULAR] > 0,
        nu=freq(NU),
        frac0=out[FRAC0],
        q=out[Q],
        c_sn=out[C_SN],
        c_cn=out[C_CN],
        c_dn=out[C_DN],
        kk=out[KK],
        mu_cn=vec(MU_CN),
        mu_sn=vec(MU_SN),
        mu_dn=vec(MU_DN),
        s=out[S],
        nu_psi=freq(NU_PSI),
        wa=vec(WA, NWA),
        wb=vec(WB, NWA),
        slope=out[SLOPE],
        psi0=out[PSI0],
        quat_u=vec(QUAT_U, 4),
        quat_v=vec(QUAT_V, 4),
        v_sn=vec(V_SN),
        v_cn=vec(V_CN),
        G=out[G],
        a3=out[A3],
        period=out[PERIOD],
        precession_rate=out[PRECESSION_RATE],
    )
