r"""The reference method's DOP853 path: the hub equations of ``N`` bodies as one system.

The hub equations (:func:`andoyer.perturbations.perturbed_rates`, free part
``ṁ_1 = c_1 m_2 m_3`` written without cancellation, ``q̇ = ½ q ⊗ (ω, 0)``
scalar last) of ``N`` bodies are integrated by scipy's DOP853 as one system of ``7N``
equations, with dense output to reach every requested time
(:func:`~andoyer.integrate.reference.integrate_reference` with ``method="dop853"``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp

from andoyer._limits import check_size, progress, spin_rate
from andoyer._quaternion import product
from andoyer.perturbations.model import Model

__all__ = ["dop853_values"]

Array = NDArray[np.float64]


#: DOP853 steps per radian turned at ``rtol = 1e-12`` (measured on heavy tops, 2.7-2.9); the
#: count of an 8th-order method scales as ``rtol^(-1/8)``.
_DOP853_STEPS_PER_RADIAN = 2.5
#: Seconds per DOP853 step of one body (measured, 70 µs: 12 Python right-hand sides).
_DOP853_STEP_SECONDS = 7e-5


def _check_dop853_size(model: Model, m0: Array, t0: float, unique: Array, rtol: float) -> None:
    """Refuse a DOP853 run whose dense output or duration cannot fit, before it starts.

    Steps: at least ``2.5 (1e-12/rtol)^(1/8)`` per radian turned at the spin rate over the
    longer of the two spans. Each step keeps its interpolant (about ``600 + 450 n`` bytes
    for ``n`` bodies: 950 measured for one) and costs ``n`` times 70 µs.
    """
    n = m0.shape[0]
    span = max(float(unique[-1]) - t0, t0 - float(unique[0]), 0.0)
    per_radian = _DOP853_STEPS_PER_RADIAN * (1e-12 / rtol) ** 0.125 if rtol > 0 else 0.0
    steps = per_radian * spin_rate(model.body.moments, m0) * span
    check_size(
        "a DOP853 run",
        steps=steps * n,
        nbytes=steps * (600 + 450 * n),
        step_seconds=_DOP853_STEP_SECONDS,
    )


def dop853_values(
    model: Model, q0: Array, m0: Array, t0: float, unique: Array, rtol: float, atol: float
) -> dict[float, tuple[Array, Array]]:
    """States ``(q, m)`` at each of the sorted times ``unique`` (but ``t0``), by time.

    Parameters
    ----------
    model : Model
    q0 : numpy.ndarray, shape (N, 4)
    m0 : numpy.ndarray, shape (N, 3)
    t0 : float
    unique : numpy.ndarray, shape (U,)
        Sorted output times, on either side of ``t0``.
    rtol, atol : float
        DOP853's tolerances (``atol`` scaled by the largest ``|m|`` for the momenta).

    Returns
    -------
    dict
        ``{time: (q (N, 4), m (N, 3))}`` for every time of ``unique`` but ``t0``.
    """
    n = q0.shape[0]
    _check_dop853_size(model, m0, t0, unique, rtol)
    scale = max(float(np.max(np.linalg.norm(m0, axis=-1), initial=0.0)), np.finfo(float).tiny)
    atol_vec = np.concatenate([np.full(4 * n, atol), np.full(3 * n, atol * scale)])
    rhs = _rhs(model, n)
    y0 = np.concatenate([q0.ravel(), m0.ravel()])
    values: dict[float, tuple[Array, Array]] = {}
    span = max(float(unique[-1]) - t0, 0.0) + max(t0 - float(unique[0]), 0.0)
    with progress(span, "DOP853", unit="time") as bar:
        for direction in (1.0, -1.0):
            targets = unique[(unique - t0) * direction > 0]
            if targets.size == 0:
                continue
            end = targets.max() if direction > 0 else targets.min()
            sol = solve_ivp(
                _reporting(rhs, t0, span, bar),
                (t0, end),
                y0,
                method="DOP853",
                rtol=rtol,
                atol=atol_vec,
                dense_output=True,
            )
            if not sol.success:
                msg = f"expected the reference integration to succeed, got: {sol.message}"
                raise ValueError(msg)
            for time in targets:
                y = sol.sol(time) if time != end else sol.y[:, -1]
                values[float(time)] = (y[: 4 * n].reshape(n, 4), y[4 * n :].reshape(n, 3))
    return values


def _reporting(
    rhs: Callable[[float, Array], Array], t0: float, span: float, bar: Any
) -> Callable[[float, Array], Array]:
    """``rhs`` that tells ``bar`` how far from ``t0`` the integration has gone (every 1/1000 of ``span``)."""
    if bar is None:
        return rhs
    reported = [0.0]

    def wrapped(t: float, y: Array) -> Array:
        done = abs(t - t0)
        if done - reported[0] > 1e-3 * span:
            bar.update(done - reported[0])
            reported[0] = done
        return rhs(t, y)

    return wrapped


# The right-hand side of the DOP853 path. The generic hub equations
# (:func:`andoyer.perturbations.perturbed_rates`) cost 0.1-1 ms a call, most of
# it numpy's per-call overhead on small arrays (stack, broadcast, a vectorised
# Kepler solve for one time); here each term gives its share of the equations on
# the components of the state (``Perturbation.hub_rates``: Python floats for one
# body, arrays (N,) for many), with the orbit positions solved on Python floats.


def _rhs(model: Model, n: int) -> Callable[[float, Array], Array]:
    """The hub equations of ``n`` bodies on the flat state ``(q (n, 4), m (n, 3))``."""
    terms = [part.hub_rates() for part in model.parts]
    c1, c2, c3 = model.body.euler_coefficients.tolist()
    I1, I2, I3 = model.body.moments.tolist()

    def rhs(t: float, y: Array) -> Array:
        if n == 1:
            qx, qy, qz, qw, m1, m2, m3 = y.tolist()
        else:
            qx, qy, qz, qw = (y[k : 4 * n : 4] for k in range(4))
            m1, m2, m3 = (y[4 * n + k :: 3] for k in range(3))
        q, m = (qx, qy, qz, qw), (m1, m2, m3)
        w1, w2, w3 = m1 / I1, m2 / I2, m3 / I3
        d1, d2, d3 = c1 * m2 * m3, c2 * m3 * m1, c3 * m1 * m2
        for term in terms:
            dv, dm = term(t, q, m)
            if dv is not None:
                w1, w2, w3 = w1 + dv[0], w2 + dv[1], w3 + dv[2]
            if dm is not None:
                d1, d2, d3 = d1 + dm[0], d2 + dm[1], d3 + dm[2]
        # dq/dt = q ⊗ (ω, 0) / 2
        dq = product(qx, qy, qz, qw, w1, w2, w3, 0.0)
        rates = (0.5 * dq[0], 0.5 * dq[1], 0.5 * dq[2], 0.5 * dq[3], d1, d2, d3)
        if n == 1:
            return np.array([float(v) for v in rates])
        out = np.empty(7 * n)
        for k in range(4):
            out[k : 4 * n : 4] = rates[k]
        for k in range(3):
            out[4 * n + k :: 3] = rates[4 + k]
        return out

    return rhs
