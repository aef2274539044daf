r"""The scalar backend: the exact free flow over one step, compiled by numba when it is installed.

:class:`andoyer.free.FreeMotion` prepares per-state constants for evaluation at many
epochs (double-double phases, theta series) and costs ~10 ms to build for a single
state. A splitting integrator needs the opposite: one short step from a state that the
previous kick has just changed. This module advances ``(q, m)`` by ``h`` with the same
closed-form solution written for scalars:

* triaxial SAM/LAM, in the working frame of :mod:`andoyer.free.common.polhode` (axis 3 the
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
  ``λ = m_e (1/I_s − 1/I_t)``, ``m(h) = R_e(−λ h) m₀``: the kernels of :mod:`andoyer.free.uniform`
  (``setup``, ``evaluate``) that :class:`~andoyer.free.FreeMotion` evaluates, at ``t = h``;
* steady spin about the polhode axis: ``q(h) = q₀ ⊗ R_e(G w₃ h)``.

States on (or within ``10⁻¹²`` relative of) the separatrix are flagged and left to
:class:`~andoyer.free.FreeMotion`, which classifies them exactly in double-double.

The scalar functions are plain Python on floats; :data:`NUMBA` tells whether they are
compiled. :func:`free_step` is the array entry point.
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import NUMBA, jit, jitable
from andoyer._quaternion import product
from andoyer.free.common.cycles import phase
from andoyer.free.common.elliptic import am, carlson_rf, carlson_rj, third_minus_a_unwrapped
from andoyer.free.common.polhode import polhode_axes, sorted_axes
from andoyer.free.uniform.evaluate import attitude, momentum, turn
from andoyer.free.uniform.setup import component, decomposition, frequencies, quaternions

__all__ = ["NUMBA", "free_step", "jit"]

# the one Hamilton product, compiled inline into the kernels below
jitable(product)


_EPS = 2.220446049250313e-16
_SEPARATRIX = 1e-12
# interpreted, the kernel costs ~0.2 ms a state: FreeMotion's vectorised set-up wins beyond
_INTERPRETED_MAX = 32


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
    r = product(q[0], q[1], q[2], q[3], s * axis[0], s * axis[1], s * axis[2], c)
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]


@jit
def _uniform(q, m, h, k, I_s, I_t):
    """Two equal moments ``I_t`` (symmetry axis ``k``, moment ``I_s``) or a sphere (any ``k``, ``I_s = I_t``).

    The kernels of :mod:`andoyer.free.uniform.setup` at ``t = h``.
    """
    m_s = component(m, k)
    G, sh, sl, lh, ll, _, _ = frequencies(m, m_s, I_s, I_t)
    m_par, m_perp, m_cross = decomposition(m, k, m_s)
    q1 = (q[0], q[1], q[2], q[3])
    q2, q3, q4 = quaternions(q1, m, k, G)
    cb, sb = turn(phase(lh, ll, h))
    ca, sa = turn(phase(sh, sl, h))
    m[0], m[1], m[2] = momentum(cb, sb, m_par, m_perp, m_cross)
    q[0], q[1], q[2], q[3] = attitude(cb, sb, ca, sa, q1, q2, q3, q4)


@jit
def _step_one(moments, q, m, h):
    """Advance one state in place; return ``False`` when it is left to ``FreeMotion``."""
    I = moments
    # (Python floats and bools for the frame kernels: without numba their select then takes its
    # conditional fast path instead of numpy.where on numpy scalars)
    ia, ib, ic = sorted_axes(float(I[0]), float(I[1]), float(I[2]))
    A, B, C = I[ia], I[ib], I[ic]
    if A == C:
        _uniform(q, m, h, 0, A, A)
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
    # the working frame of andoyer.free.common.polhode: working axis j is sigma_j times body axis
    iu, ib, ip, s2, s3 = polhode_axes(ia, ib, ic, bool(lam), float(m[0]), float(m[1]), float(m[2]))
    s = -1.0 if lam else 1.0
    I1, I2, I3 = I[iu], I[ib], I[ip]
    m1, m2, m3 = m[iu], s2 * m[ib], s3 * m[ip]
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
    bracket = third_minus_a_unwrapped(phi1, mm, mc, kap2, c3, pi_full, a_full) - third_minus_a_unwrapped(
        phi0, mm, mc, kap2, c3, pi_full, a_full
    )
    dpsi = G / I3 * h + s * G * e13 / om * bracket
    s1, c1 = math.sin(phi1), math.cos(phi1)
    n1, n2, n3 = a1 * c1, s * a2 * s1, a3 * math.sqrt(mc + mm * c1 * c1)
    new = np.empty(3)
    new[iu], new[ib], new[ip] = n1, s2 * n2, s3 * n3
    # q ⊗ S(m₀)* ⊗ R_e(Δψ) ⊗ S(m₁)
    a = _arc(m, e, G)
    r = product(q[0], q[1], q[2], q[3], -a[0], -a[1], -a[2], a[3])
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]
    _turn(q, e, dpsi)
    g1 = math.sqrt(n1 * n1 + n2 * n2 + n3 * n3)
    b = _arc(new, e, g1)
    r = product(q[0], q[1], q[2], q[3], b[0], b[1], b[2], b[3])
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
