r"""Compiled splitting loop for tabulated kicks (gravity gradient, heavy top, precessing frame).

The kicks of :class:`~andoyer.perturbations.GravityGradient` and
:class:`~andoyer.perturbations.HeavyTop` depend on the attitude through a few
reference-frame vectors whose time dependence does not involve the state: the
perturbers' positions ``r_p(t)`` and the vertical. The driver tabulates them at every
kick time of a chunk of steps (one vectorised orbit evaluation), and this loop then runs
every state through every step with no Python in between:

.. math::
   \mathbf m \mathrel{+}= \tfrac{h}{2}(w_{k-1} + w_k)\,\boldsymbol\tau(t_k, q),\qquad
   \boldsymbol\tau = \sum_p \frac{3\mu_p}{\rho_p^5}\,\boldsymbol\rho_p\times I\boldsymbol\rho_p
      + \boldsymbol\gamma\times\mathbf c,

``ρ_p = Rᵀ r_p``, ``γ = Rᵀ s₃``, ``c = m g₀ r_c`` (summed over heavy tops), between
the exact free flows of the substeps ``w_k h`` (:mod:`andoyer.free.step_scalar`) and the frame
rotations ``q → exp(−μ w_k h/2) ⊗ q`` with ``μ`` at the substep's midpoint. The two
half kicks that meet between substeps are one kick (the attitude does not change in a
kick), so a step of ``K`` substeps evaluates the torque ``K + 1`` times.

Without numba the same source runs interpreted; the driver then prefers its generic
loop (:func:`andoyer.integrate.splitting.split_step`).
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import jit, jitable
from andoyer._quaternion import apply, product
from andoyer.free.step_scalar import _step_one

__all__ = ["run_tabulated"]

# the one Hamilton product and rotation, compiled inline into the kernels below
jitable(product)
jitable(apply)


@jit
def _body_vector(q, v):
    """``Rᵀ v``: reference vector ``v`` in body components for attitude ``q``."""
    return apply(-q[0], -q[1], -q[2], q[3], v[0], v[1], v[2])


@jit
def _kick(q, m, coef, positions, gm, inertia, heavy):
    """``m += coef · τ(q)`` for perturbers at ``positions`` (P, 3) and the heavy-top vector."""
    t0 = 0.0
    t1 = 0.0
    t2 = 0.0
    for p in range(positions.shape[0]):
        x, y, z = _body_vector(q, positions[p])
        r2 = x * x + y * y + z * z
        scale = 3.0 * gm[p] / (r2 * r2 * math.sqrt(r2))
        I1, I2, I3 = inertia[p, 0], inertia[p, 1], inertia[p, 2]
        t0 += scale * (I3 - I2) * y * z
        t1 += scale * (I1 - I3) * z * x
        t2 += scale * (I2 - I1) * x * y
    if heavy[0] != 0.0 or heavy[1] != 0.0 or heavy[2] != 0.0:
        up = np.zeros(3)
        up[2] = 1.0
        gx, gy, gz = _body_vector(q, up)
        t0 += gy * heavy[2] - gz * heavy[1]
        t1 += gz * heavy[0] - gx * heavy[2]
        t2 += gx * heavy[1] - gy * heavy[0]
    m[0] += coef * t0
    m[1] += coef * t1
    m[2] += coef * t2


@jit
def _frame_turn(q, rate, dt):
    """``q → exp(−μ dt/2) ⊗ q`` (rotation of the attitude about the frame's axis)."""
    norm = math.sqrt(rate[0] * rate[0] + rate[1] * rate[1] + rate[2] * rate[2])
    if norm == 0.0:
        return
    half = -0.5 * norm * dt
    s = math.sin(half) / norm
    r = product(s * rate[0], s * rate[1], s * rate[2], math.cos(half), q[0], q[1], q[2], q[3])
    q[0], q[1], q[2], q[3] = r[0], r[1], r[2], r[3]


@jit
def run_tabulated(moments, q, m, hs, weights, positions, gm, inertia, heavy, rates, start, status):
    """Advance every state in place from kick ``start[i]`` to the end of steps ``hs``.

    Kick ``j = n (K+1) + k`` is the ``k``-th kick of step ``n``; ``positions``
    (S, K+1, P, 3) hold the perturbers there, ``rates`` (S, K, 3) the frame's rate at
    the substep midpoints (zeros without frame). ``status[i]`` is ``-1`` when state
    ``i`` finished, else the kick index ``j`` whose following free substep it left
    undone (a separatrix state, for :class:`~andoyer.free.FreeMotion`).
    """
    n_stage = weights.shape[0]
    for i in range(q.shape[0]):
        status[i] = -1
        begin = start[i]
        for n in range(begin // (n_stage + 1), hs.shape[0]):
            h = hs[n]
            k0 = begin % (n_stage + 1) if n == begin // (n_stage + 1) else 0
            for k in range(k0, n_stage + 1):
                coef = 0.0
                if k > 0:
                    coef += 0.5 * weights[k - 1] * h
                if k < n_stage:
                    coef += 0.5 * weights[k] * h
                _kick(q[i], m[i], coef, positions[n, k], gm, inertia, heavy)
                if k == n_stage:
                    break
                sub = weights[k] * h
                if not _step_one(moments, q[i], m[i], sub):
                    status[i] = n * (n_stage + 1) + k
                    break
                _frame_turn(q[i], rates[n, k], sub)
            if status[i] >= 0:
                break
