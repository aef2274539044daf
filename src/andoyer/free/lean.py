r"""A lean exact free flow for one step: scalar kernel, compiled by numba when it is installed.

:class:`andoyer.free.FreeMotion` prepares per-state constants for evaluation at many
epochs (double-double phases, theta series) and costs ~10 ms to build for a single
state. A splitting integrator needs the opposite: one short step from a state that the
previous kick has just changed. This module advances ``(q, m)`` by ``h`` with the same
closed-form solution written for scalars:

* triaxial SAM/LAM, in the working frame of :mod:`andoyer.free.regime` (axis 3 the
  polhode axis, ``m₃ > 0``, ``s = +1`` SAM, ``−1`` LAM):
  ``m = (a₁ cn τ, s a₂ sn τ, a₃ dn τ)``, ``τ = τ₀ + ω h``, ``am τ`` by the AGM;
* the attitude ``q(h) = q₀ ⊗ S(m₀)* ⊗ R_e(Δψ) ⊗ S(m(h))`` with ``S(m)`` the shortest
  arc taking ``m`` to the signed polhode axis ``e`` (body components) and

  .. math::
     \Delta\psi = G w_3 h + \frac{s G e_{13}}{\omega}\big[\Pi(-\kappa^2; \varphi)
        - c\,A(\varphi)\big]_{\varphi_0}^{\varphi_1},\qquad
     A(\varphi) = \int_0^\varphi \frac{d\theta}{1 + \kappa^2\sin^2\theta},

  ``c = a₃/G``, ``κ² = e₁₂/e₂₃`` (the incomplete integral of the third kind that
  :mod:`andoyer.free.triaxial` replaces by theta series for long times; over one step
  the cancellation near pure spin costs only ``eps·|Δφ|`` in absolute angle), with
  Carlson's ``R_F``, ``R_J`` (DLMF 19.25.14–15, 19.36);
* two equal moments (and the sphere): ``q(h) = q₀ ⊗ R_{m̂₀}(G h/I_t) ⊗ R_e(λ h)``,
  ``λ = m_e (1/I_s − 1/I_t)``, ``m(h) = R_e(−λ h) m₀``;
* steady spin about the polhode axis: ``q(h) = q₀ ⊗ R_e(G w₃ h)``.

States on (or within ``10⁻¹²`` relative of) the separatrix are flagged and left to
:class:`~andoyer.free.FreeMotion`, which classifies them exactly in double-double.

The scalar functions are plain Python on floats; :data:`NUMBA` tells whether they are
compiled. :func:`free_step` is the array entry point.
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import NUMBA, jit

__all__ = ["NUMBA", "am", "carlson_rf", "carlson_rj", "free_step", "jit"]


_EPS = 2.220446049250313e-16
_SEPARATRIX = 1e-12
# interpreted, the kernel costs ~0.2 ms a state: FreeMotion's vectorised set-up wins beyond
_INTERPRETED_MAX = 32


@jit
def carlson_rf(x, y, z):
    """Carlson's ``R_F(x, y, z)`` for ``x, y, z ≥ 0``, at most one zero (DLMF 19.36.1).

    Examples
    --------
    >>> from scipy.special import ellipk
    >>> bool(abs(carlson_rf(0.0, 0.5, 1.0) / ellipk(0.5) - 1.0) < 1e-15)
    True
    """
    a0 = (x + y + z) / 3.0
    x0, y0 = x, y
    q = max(abs(a0 - x), abs(a0 - y), abs(a0 - z)) * 424.0  # (3 r)^(-1/6), r = eps/4 (Carlson 1995)
    a = a0
    f = 1.0
    while f * q >= abs(a):
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * sy + sy * sz + sz * sx
        x, y, z, a = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (a + lam)
        f *= 0.25
    X = (a0 - x0) / a * f
    Y = (a0 - y0) / a * f
    Z = -(X + Y)
    e2 = X * Y - Z * Z
    e3 = X * Y * Z
    return (
        1.0
        - e2 / 10.0
        + e3 / 14.0
        + e2 * e2 / 24.0
        - 3.0 * e2 * e3 / 44.0
        - 5.0 * e2 * e2 * e2 / 208.0
        + 3.0 * e3 * e3 / 104.0
        + e2 * e2 * e3 / 16.0
    ) / math.sqrt(a)


@jit
def _rc_one(e):
    """``R_C(1, 1 + e)`` for ``e > −1``: ``atan(√e)/√e`` (``atanh`` for ``e < 0``)."""
    if e > 0.0:
        r = math.sqrt(e)
        return math.atan(r) / r
    if e < 0.0:
        r = math.sqrt(-e)
        return math.atanh(r) / r
    return 1.0


@jit
def carlson_rj(x, y, z, p):
    """Carlson's ``R_J(x, y, z, p)`` for ``x, y, z ≥ 0`` (one zero at most), ``p > 0`` (DLMF 19.36.2).

    Examples
    --------
    >>> from scipy.special import elliprj
    >>> bool(abs(carlson_rj(1.0, 2.0, 3.0, 4.0) / elliprj(1.0, 2.0, 3.0, 4.0) - 1.0) < 1e-15)
    True
    """
    a0 = (x + y + z + 2.0 * p) / 5.0
    delta = (p - x) * (p - y) * (p - z)
    x0, y0, z0 = x, y, z
    q = max(abs(a0 - x), abs(a0 - y), abs(a0 - z), abs(a0 - p)) * 644.0  # (r/4)^(-1/6)
    a = a0
    f = 1.0
    f3 = 1.0
    total = 0.0
    while f * q >= abs(a):
        sx, sy, sz, sp = math.sqrt(x), math.sqrt(y), math.sqrt(z), math.sqrt(p)
        lam = sx * sy + sy * sz + sz * sx
        d = (sp + sx) * (sp + sy) * (sp + sz)
        total += f * _rc_one(f3 * delta / (d * d)) / d
        x, y, z, p = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (p + lam)
        a = 0.25 * (a + lam)
        f *= 0.25
        f3 *= 1.0 / 64.0
    X = (a0 - x0) / a * f
    Y = (a0 - y0) / a * f
    Z = (a0 - z0) / a * f
    P = -0.5 * (X + Y + Z)
    e2 = X * Y + X * Z + Y * Z - 3.0 * P * P
    e3 = X * Y * Z + 2.0 * e2 * P + 4.0 * P * P * P
    e4 = (2.0 * X * Y * Z + e2 * P + 3.0 * P * P * P) * P
    e5 = X * Y * Z * P * P
    series = (
        1.0
        - 3.0 * e2 / 14.0
        + e3 / 6.0
        + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
    )
    return f * series / (a * math.sqrt(a)) + 6.0 * total


@jit
def am(u, m, mc):
    """Jacobi amplitude ``am(u | m)`` for ``0 ≤ m < 1`` given also ``mc = 1 − m`` (AGM, DLMF 22.20).

    ``mc`` is passed separately so that it carries its digits near ``m = 1``. The
    result is unwrapped (continuous in ``u``).

    Examples
    --------
    >>> round(am(0.7, 0.0, 1.0), 15)
    0.7
    """
    a = 1.0
    b = math.sqrt(mc)
    c = math.sqrt(m)
    ratios = np.empty(32)
    n = 0
    while abs(c) > _EPS * a and n < 32:
        an = 0.5 * (a + b)
        c = 0.5 * (a - b)
        b = math.sqrt(a * b)
        a = an
        ratios[n] = c / a
        n += 1
    phi = a * u * 2.0**n
    for i in range(n - 1, -1, -1):
        phi = 0.5 * (phi + math.asin(ratios[i] * math.sin(phi)))
    return phi


@jit
def _ellip_f(phi, m, mc, K):
    """Unwrapped ``F(φ | m)`` (``K`` the complete integral)."""
    j = math.floor(phi / math.pi + 0.5)
    r = phi - j * math.pi
    s, c = math.sin(r), math.cos(r)
    return 2.0 * j * K + s * carlson_rf(c * c, mc + m * c * c, 1.0)


@jit
def _third_minus_a(phi, m, mc, kap2, c3, pi_full, a_full):
    """Unwrapped ``Π(−κ²; φ | m) − c A(φ)`` (``pi_full``, ``a_full``: their values at ``π/2``)."""
    j = math.floor(phi / math.pi + 0.5)
    r = phi - j * math.pi
    s, c = math.sin(r), math.cos(r)
    dn2 = mc + m * c * c
    s3 = s * s * s
    pi_r = s * carlson_rf(c * c, dn2, 1.0) - kap2 / 3.0 * s3 * carlson_rj(c * c, dn2, 1.0, 1.0 + kap2 * s * s)
    root = math.sqrt(1.0 + kap2)
    a_r = math.atan2(root * s, c) / root
    return 2.0 * j * (pi_full - c3 * a_full) + pi_r - c3 * a_r


@jit
def _qmul(p0, p1, p2, p3, q0, q1, q2, q3):
    return (
        p3 * q0 + p0 * q3 + p1 * q2 - p2 * q1,
        p3 * q1 - p0 * q2 + p1 * q3 + p2 * q0,
        p3 * q2 + p0 * q1 - p1 * q0 + p2 * q3,
        p3 * q3 - p0 * q0 - p1 * q1 - p2 * q2,
    )


@jit
def _arc(m, e, g):
    """Shortest arc taking body vector ``m`` (norm ``g``) to the unit axis ``e``, as (x, y, z, w)."""
    x = m[1] * e[2] - m[2] * e[1]
    y = m[2] * e[0] - m[0] * e[2]
    z = m[0] * e[1] - m[1] * e[0]
    w = g + m[0] * e[0] + m[1] * e[1] + m[2] * e[2]
    n = math.sqrt(x * x + y * y + z * z + w * w)
    return x / n, y / n, z / n, w / n


@jit
def _turn(q, axis, angle):
    """``q ⊗ R_axis(angle)`` in place (``axis`` a unit body vector)."""
    s, c = math.sin(0.5 * angle), math.cos(0.5 * angle)
    r = _qmul(q[0], q[1], q[2], q[3], s * axis[0], s * axis[1], s * axis[2], c)
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]


@jit
def _uniform(q, m, h, k, I_s, I_t):
    """Two equal moments ``I_t`` (symmetry axis ``k``, moment ``I_s``) or a sphere (``k < 0``)."""
    g = math.sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2])
    if g == 0.0:
        return
    axis = np.empty(3)
    axis[0], axis[1], axis[2] = m[0] / g, m[1] / g, m[2] / g
    _turn(q, axis, g * h / I_t)
    if k < 0:
        return
    lam = m[k] * (I_t - I_s) / (I_s * I_t)
    e = np.zeros(3)
    e[k] = 1.0
    _turn(q, e, lam * h)
    i, j = (k + 1) % 3, (k + 2) % 3
    s, c = math.sin(lam * h), math.cos(lam * h)
    mi, mj = m[i], m[j]
    m[i] = c * mi + s * mj
    m[j] = -s * mi + c * mj


@jit
def _step_one(moments, q, m, h):
    """Advance one state in place; return ``False`` when it is left to ``FreeMotion``."""
    I = moments
    ia, ib, ic = 0, 1, 2
    if I[ia] > I[ib]:
        ia, ib = ib, ia
    if I[ib] > I[ic]:
        ib, ic = ic, ib
    if I[ia] > I[ib]:
        ia, ib = ib, ia
    A, B, C = I[ia], I[ib], I[ic]
    if A == C:
        _uniform(q, m, h, -1, A, A)
        return True
    if A == B:
        _uniform(q, m, h, ic, C, A)
        return True
    if B == C:
        _uniform(q, m, h, ia, A, C)
        return True
    # P₂ A B C = m_C²(C − B)A − m_A²(B − A)C: its sign picks SAM or LAM
    t1 = m[ic] * m[ic] * (C - B) * A
    t2 = m[ia] * m[ia] * (B - A) * C
    if abs(t1 - t2) <= _SEPARATRIX * (t1 + t2):
        return False
    lam = t1 < t2
    iu, ip = (ic, ia) if lam else (ia, ic)
    s = -1.0 if lam else 1.0
    parity = 1.0 if (ib - iu) % 3 == 1 else -1.0  # (iu, ib, ip) a cyclic shift of (0, 1, 2)
    s3 = -1.0 if m[ip] < 0.0 else 1.0
    I1, I2, I3 = I[iu], I[ib], I[ip]
    m1, m2, m3 = m[iu], parity * s3 * m[ib], s3 * m[ip]
    e12 = s * (I2 - I1) / (I1 * I2)
    e13 = s * (I3 - I1) / (I1 * I3)
    e23 = s * (I3 - I2) / (I2 * I3)
    P1 = m1 * m1 * e13 + m2 * m2 * e23
    P3 = m2 * m2 * e12 + m3 * m3 * e13
    P2 = m3 * m3 * e23 - m1 * m1 * e12
    G = math.sqrt(m1 * m1 + m2 * m2 + m3 * m3)
    e = np.zeros(3)
    e[ip] = s3
    if P1 == 0.0:  # steady spin about the polhode axis
        _turn(q, e, G / I3 * h)
        return True
    a1 = math.sqrt(P1 / e13)
    a2 = math.sqrt(P1 / e23)
    a3 = math.sqrt(P3 / e13)
    den = e23 * P3
    mm = e12 * P1 / den
    mc = e13 * P2 / den
    om = math.sqrt(den)
    K = carlson_rf(0.0, mc, 1.0)  # complete K(m)
    cn0, sn0, dn0 = m1 / a1, m2 / (s * a2), m3 / a3
    rf = carlson_rf(cn0 * cn0, dn0 * dn0, 1.0)
    tau0 = sn0 * rf if cn0 >= 0.0 else math.copysign(2.0 * K, sn0) - sn0 * rf
    phi0 = math.atan2(sn0, cn0)
    phi1 = am(tau0 + om * h - 2.0 * K * math.floor((tau0 + om * h) / (2.0 * K) + 0.5), mm, mc)
    phi1 += math.pi * math.floor((tau0 + om * h) / (2.0 * K) + 0.5)
    # the phase of ψ: Π(−κ²; φ) − c A(φ) between φ₀ and φ₁
    kap2 = e12 / e23
    c3 = a3 / G
    root = math.sqrt(1.0 + kap2)
    pi_full = K - kap2 / 3.0 * carlson_rj(0.0, mc, 1.0, 1.0 + kap2)
    a_full = 0.5 * math.pi / root
    bracket = _third_minus_a(phi1, mm, mc, kap2, c3, pi_full, a_full) - _third_minus_a(
        phi0, mm, mc, kap2, c3, pi_full, a_full
    )
    dpsi = G / I3 * h + s * G * e13 / om * bracket
    s1, c1 = math.sin(phi1), math.cos(phi1)
    n1, n2, n3 = a1 * c1, s * a2 * s1, a3 * math.sqrt(mc + mm * c1 * c1)
    new = np.empty(3)
    new[iu], new[ib], new[ip] = n1, parity * s3 * n2, s3 * n3
    # q ⊗ S(m₀)* ⊗ R_e(Δψ) ⊗ S(m₁)
    a = _arc(m, e, G)
    r = _qmul(q[0], q[1], q[2], q[3], -a[0], -a[1], -a[2], a[3])
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]
    _turn(q, e, dpsi)
    g1 = math.sqrt(n1 * n1 + n2 * n2 + n3 * n3)
    b = _arc(new, e, g1)
    r = _qmul(q[0], q[1], q[2], q[3], b[0], b[1], b[2], b[3])
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]
    m[0], m[1], m[2] = new[0], new[1], new[2]
    return True


@jit
def _step_many(moments, q, m, h, done):
    """Advance states ``q`` (N, 4), ``m`` (N, 3) with moments (N, 3) in place."""
    for i in range(q.shape[0]):
        done[i] = _step_one(moments[i], q[i], m[i], h)


def free_step(moments, q, m, h):
    """Exact torque-free flow over one step ``h`` of attitudes and body momenta.

    Parameters
    ----------
    moments : array_like, shape (3,) or (N, 3)
        Principal moments along b1, b2, b3 (any order).
    q : array_like, shape (N, 4)
        Unit attitude quaternions (scalar last, body → reference).
    m : array_like, shape (N, 3)
        Body angular momenta.
    h : float
        Step (either sign).

    Returns
    -------
    q, m : ndarray, shapes (N, 4) and (N, 3)
        New arrays; states within ``10⁻¹²`` of the separatrix (and, without numba,
        batches of more than 32 states) come from :class:`~andoyer.free.FreeMotion`.

    Examples
    --------
    >>> q, m = free_step([1.0, 2.0, 3.0], [[0.0, 0.0, 0.0, 1.0]], [[0.3, 0.2, 1.0]], 0.5)
    >>> from andoyer.free import FreeMotion
    >>> m_ref, q_ref = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0]).propagate(0.5)
    >>> bool(abs(m - m_ref).max() < 1e-14 and abs(q - q_ref).max() < 1e-14)
    True
    """
    q = np.array(q, dtype=np.float64, copy=True).reshape(-1, 4)
    m = np.array(m, dtype=np.float64, copy=True).reshape(-1, 3)
    if q.shape[0] != m.shape[0]:
        msg = f"expected as many attitudes as momenta, got {q.shape[0]} and {m.shape[0]}"
        raise ValueError(msg)
    moments = np.ascontiguousarray(np.broadcast_to(np.asarray(moments, dtype=np.float64), m.shape))
    q0, m0 = q.copy(), m.copy()
    done = np.zeros(q.shape[0], dtype=np.bool_)
    if NUMBA or q.shape[0] <= _INTERPRETED_MAX:
        _step_many(moments, q, m, float(h), done)
    if not np.all(done):
        from andoyer.free.motion import FreeMotion

        rest = ~done
        m_new, q_new = FreeMotion(moments[rest], m0[rest], q0[rest]).propagate(float(h))
        q[rest], m[rest] = q_new, m_new
    return q, m
