r"""The reference method's heyoka path: the hub equations as a Taylor integrator (optional dependency).

The same hub equations as the DOP853 path (:mod:`andoyer.integrate.reference.dop853`) of
:func:`~andoyer.integrate.reference.integrate_reference`, written as heyoka expressions:

.. math::
   \dot q = \tfrac12\, q\otimes(\boldsymbol\omega - \boldsymbol\mu_b,\ 0), \qquad
   \dot m_1 = c_1 m_2 m_3 + \tau_1 \ \text{(cyclic)},

with ``q`` scalar last, ``ω = m/I``, ``c_1 = (I2 − I3)/(I2 I3)`` (the free part
without cancellation), ``μ_b = Rᵀμ`` for a precessing frame (whose gradient and
torque cancel exactly in ``ṁ``, so neither is formed) and ``τ`` the sum of the
torques: gravity gradient ``3μ_p/ρ⁵ ((I3−I2) ρ2 ρ3, …)`` of perturbers on
Kepler orbits (``kepE`` for the eccentric anomaly, linear node and periapsis
drift as in :mod:`andoyer.perturbations.orbits`), heavy top ``w γ × r_c`` and
linear damping ``−c ω``. The momenta are integrated as ``m/s`` with ``s`` the
largest initial ``|m|``, so that heyoka's single tolerance (relative to the
largest component) applies to quaternion and momentum alike.

Each term writes its own share (:meth:`~andoyer.perturbations.Perturbation.heyoka_rates`).
Every number of the model is a runtime parameter: the integrator is compiled
once per model *structure* (which terms, which orbits are eccentric, which
angles drift) and tolerance, and cached.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
from numpy.typing import NDArray

from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.expressions import HeyokaContext, Parameters, kepler_position
from andoyer.perturbations.model import Model

__all__ = ["heyoka_system", "heyoka_values", "kepler_position"]

Array = NDArray[np.float64]

_CACHE: dict[tuple[Any, ...], Any] = {}
_CACHE_SIZE = 16


def _heyoka_module() -> Any:
    """Import heyoka, or raise ``ValueError`` naming the extra that installs it."""
    try:
        import heyoka
    except ImportError as exc:
        msg = f"expected heyoka installed (pip install andoyer[heyoka]), got {type(exc).__name__}: {exc}"
        raise ValueError(msg) from exc
    return heyoka


def _check_supported(part: Perturbation) -> None:
    if not part.heyoka_supported:
        msg = (
            "expected gravity gradients of Kepler/circular orbits, constant-rate precessing frames, "
            f"heavy tops or linear damping for the heyoka integrator, got {part!r} (use method='dop853')"
        )
        raise ValueError(msg)


def heyoka_system(
    model: Model, scale: float = 1.0, time_unit: float = 1.0
) -> tuple[list[tuple[Any, Any]], list[float]]:
    """The hub equations of ``model`` as a heyoka system and its parameter values.

    Parameters
    ----------
    model : Model
    scale : float
        ``s``: the state holds ``m/s`` (its equations are divided by ``s``).
    time_unit : float
        ``T``: the independent variable is ``t/T`` (the rates are multiplied by ``T``).

    Returns
    -------
    system : list of (variable, expression)
        State ``(qx, qy, qz, qw, m1/s, m2/s, m3/s)``.
    parameters : list of float
        Values of ``par[0], par[1], …``.

    Raises
    ------
    ValueError
        Without heyoka, or for a model the heyoka integrator cannot express.

    Examples
    --------
    Models outside the four families are refused (before heyoka is imported):

    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import UserTorque
    >>> body = RigidBody(1, 2, 3)
    >>> heyoka_system(Model(body, UserTorque(lambda t, rot, w: -w)))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected gravity gradients of Kepler/circular orbits, ...UserTorque... (use method='dop853')
    """
    parts = list(model.parts)
    for part in parts:
        _check_supported(part)
    hy = _heyoka_module()
    par = Parameters(hy)
    q = hy.make_vars("qx", "qy", "qz", "qw")
    m = hy.make_vars("m1", "m2", "m3")
    body, T = model.body, float(time_unit)
    time = hy.time if T == 1.0 else T * hy.time
    velocity = [par(T * scale * w) * m[i] for i, w in enumerate(body.inverse_moments.tolist())]
    c = (T * scale * body.euler_coefficients).tolist()
    rate = [par(c[0]) * m[1] * m[2], par(c[1]) * m[2] * m[0], par(c[2]) * m[0] * m[1]]
    torques: list[list[Any]] = []
    ctx = HeyokaContext(hy, par, q, m, time, T, scale)
    for part in parts:
        shift, part_torques = part.heyoka_rates(ctx)
        if shift is not None:
            velocity = [velocity[i] + shift[i] for i in range(3)]
        torques.extend(part_torques)
    rate = [rate[i] + hy.sum([tau[i] for tau in torques]) if torques else rate[i] for i in range(3)]
    w = velocity
    qx, qy, qz, qw = q
    dq = [
        0.5 * (qw * w[0] + qy * w[2] - qz * w[1]),
        0.5 * (qw * w[1] + qz * w[0] - qx * w[2]),
        0.5 * (qw * w[2] + qx * w[1] - qy * w[0]),
        -0.5 * (qx * w[0] + qy * w[1] + qz * w[2]),
    ]
    return list(zip([*q, *m], [*dq, *rate], strict=True)), par.values


def _integrator(system: list[tuple[Any, Any]], npars: int, tol: float | None, batch: int) -> Any:
    """A compiled integrator for this system structure, from the cache (a private copy)."""
    hy = _heyoka_module()
    key = (tuple(str(rhs) for _, rhs in system), tol, batch)
    if key not in _CACHE:
        if len(_CACHE) >= _CACHE_SIZE:
            _CACHE.pop(next(iter(_CACHE)))
        extra = {} if tol is None else {"tol": tol}
        if batch == 1:
            _CACHE[key] = hy.taylor_adaptive(
                system, [0.0] * 7, pars=[0.0] * npars, compact_mode=True, **extra
            )
        else:
            _CACHE[key] = hy.taylor_adaptive_batch(
                system, np.zeros((7, batch)), pars=np.zeros((npars, batch)), compact_mode=True, **extra
            )
    # A copy: the cached object keeps no state of this call (threads may share the cache).
    return copy.copy(_CACHE[key])


def _propagate_heyoka(
    model: Model, q0: Array, m0: Array, t0: float, targets: Array, tol: float | None
) -> tuple[Array, Array]:
    """States ``(q, m)`` of ``N`` bodies at sorted ``targets`` (all after, or all before, ``t0``).

    Parameters
    ----------
    model : Model
    q0 : numpy.ndarray, shape (N, 4)
    m0 : numpy.ndarray, shape (N, 3)
    t0 : float
    targets : numpy.ndarray, shape (T,)
        Monotonic away from ``t0``.
    tol : float or None
        heyoka's tolerance (``None``: machine epsilon).

    Returns
    -------
    q, m : numpy.ndarray, shapes (T, N, 4) and (T, N, 3)
    """
    n = q0.shape[0]
    scale = max(float(np.max(np.linalg.norm(m0, axis=-1), initial=0.0)), np.finfo(float).tiny)
    system, pars = heyoka_system(model, scale)  # refuses unsupported models before needing heyoka
    hy = _heyoka_module()
    y0 = np.concatenate([q0, m0 / scale], axis=-1)
    grid = np.concatenate([[t0], targets])
    batch = hy.recommended_simd_size() if n > 1 else 1
    ta = _integrator(system, len(pars), tol, batch)
    out = np.empty((targets.size, n, 7))
    for start in range(0, n, batch):
        chunk = y0[start : start + batch]
        k = chunk.shape[0]
        if batch == 1:
            ta.time, ta.state[:], ta.pars[:] = t0, chunk[0], pars
            result = ta.propagate_grid(grid)
            outcomes = [result[0]]
            values = result[5][1:, :, None]
        else:
            ta.set_time(np.full(batch, t0))
            ta.state[:] = np.concatenate([chunk, np.repeat(chunk[-1:], batch - k, axis=0)]).T
            ta.pars[:] = np.asarray(pars)[:, None]
            values = ta.propagate_grid(np.repeat(grid[:, None], batch, axis=1))[1][1:]
            outcomes = [res[0] for res in ta.propagate_res]
        if any(o != hy.taylor_outcome.time_limit for o in outcomes) or values.shape[0] != targets.size:
            msg = f"expected the heyoka integration to reach every output time, got outcomes {outcomes}"
            raise ValueError(msg)
        out[:, start : start + k] = np.moveaxis(values[..., :k], 1, 2)
    return out[..., :4], out[..., 4:] * scale


def heyoka_values(
    model: Model, q0: Array, m0: Array, t0: float, unique: Array, rtol: float | None
) -> dict[float, tuple[Array, Array]]:
    """States ``(q, m)`` at each of the sorted times ``unique`` (but ``t0``), by time: both directions.

    Parameters
    ----------
    model : Model
    q0 : numpy.ndarray, shape (N, 4)
    m0 : numpy.ndarray, shape (N, 3)
    t0 : float
    unique : numpy.ndarray, shape (U,)
        Sorted output times, on either side of ``t0``.
    rtol : float or None
        heyoka's tolerance (``None``: machine epsilon).

    Returns
    -------
    dict
        ``{time: (q (N, 4), m (N, 3))}`` for every time of ``unique`` but ``t0``.
    """
    values: dict[float, tuple[Array, Array]] = {}
    for targets in (unique[unique > t0], unique[unique < t0][::-1]):
        if targets.size:
            q, m = _propagate_heyoka(model, q0, m0, t0, targets, rtol)
            values.update((float(time), (q[k], m[k])) for k, time in enumerate(targets))
    return values
