r"""The reference equations as a heyoka Taylor integrator (optional dependency).

The same hub equations as the DOP853 path of
:func:`~andoyer.integrate.integrate_reference`, written as heyoka expressions:

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

Every number of the model is a runtime parameter: the integrator is compiled
once per model *structure* (which terms, which orbits are eccentric, which
angles drift) and tolerance, and cached.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.frame import PrecessingFrame
from andoyer.perturbations.gravity import GravityGradient
from andoyer.perturbations.heavy_top import HeavyTop
from andoyer.perturbations.model import Model
from andoyer.perturbations.orbits import CircularOrbit, KeplerOrbit, Orbit
from andoyer.perturbations.user import LinearDamping

__all__ = ["heyoka_system", "kepler_position"]

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


class _Parameters:
    """Runtime parameters of a heyoka system: each number becomes ``par[k]`` with its value recorded."""

    def __init__(self, hy: Any) -> None:
        self.hy = hy
        self.values: list[float] = []

    def __call__(self, value: float) -> Any:
        self.values.append(float(value))
        return self.hy.par[len(self.values) - 1]


def _cos_sin(hy: Any, par: _Parameters, angle: float, rate: float, dt: Any) -> tuple[Any, Any]:
    """``cos``, ``sin`` of ``angle + rate dt``: parameters when the angle does not drift."""
    if rate == 0.0:
        return par(math.cos(angle)), par(math.sin(angle))
    value = par(angle) + par(rate) * dt
    return hy.cos(value), hy.sin(value)


def kepler_position(hy: Any, par: _Parameters | None, orbit: Orbit, time: Any = None) -> list[Any]:
    r"""Reference-frame position of a Kepler orbit as heyoka expressions of ``heyoka.time``.

    .. math:: \mathbf r = R_z(\Omega)R_x(i)R_z(\omega)\,a(\cos E - e, \sqrt{1-e^2}\sin E, 0),
       \quad E = \mathrm{kepE}(e, M_0 + n(t - t_0)),

    ``E = M`` for circular orbits; ``Ω``, ``ω`` drift linearly when their rates are nonzero.

    Parameters
    ----------
    hy : module
        heyoka.
    par : callable or None
        Maps each number to a runtime parameter; ``None`` embeds the numbers as constants.
    orbit : KeplerOrbit or CircularOrbit
    time : heyoka expression, optional
        The time ``t`` of the orbit's elements; default ``heyoka.time``.

    Returns
    -------
    list of 3 heyoka expressions

    Raises
    ------
    ValueError
        For other orbits (tabulated ones: no closed form).

    Examples
    --------
    >>> from andoyer.perturbations import TabulatedOrbit
    >>> kepler_position(None, None, TabulatedOrbit(lambda t: np.stack([t, t, t], -1)))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a KeplerOrbit or CircularOrbit for heyoka, got <...TabulatedOrbit object at ...>
    """
    if type(orbit) not in (KeplerOrbit, CircularOrbit):
        msg = f"expected a KeplerOrbit or CircularOrbit for heyoka, got {orbit!r}"
        raise ValueError(msg)
    if par is None:
        par = float  # type: ignore[assignment]
    dt = (hy.time if time is None else time) - par(orbit.epoch)
    mean = par(orbit.mean_anomaly) + par(orbit.mean_motion) * dt
    a, e = orbit.semi_major_axis, orbit.eccentricity
    if e == 0.0:
        x, y = par(a) * hy.cos(mean), par(a) * hy.sin(mean)
    else:
        anomaly = hy.kepE(par(e), mean)
        x = par(a) * (hy.cos(anomaly) - par(e))
        y = par(a * math.sqrt((1 - e) * (1 + e))) * hy.sin(anomaly)
    cO, sO = _cos_sin(hy, par, orbit.node, orbit.node_rate, dt)
    cw, sw = _cos_sin(hy, par, orbit.periapsis, orbit.periapsis_rate, dt)
    ci, si = par(math.cos(orbit.inclination)), par(math.sin(orbit.inclination))
    return [
        (cO * cw - sO * ci * sw) * x + (-cO * sw - sO * ci * cw) * y,
        (sO * cw + cO * ci * sw) * x + (-sO * sw + cO * ci * cw) * y,
        si * sw * x + si * cw * y,
    ]


def _cross(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _to_body(q: Sequence[Any], v: Sequence[Any]) -> list[Any]:
    """``Rᵀ v``: the rotation of ``conj(q)``, as :func:`andoyer._quaternion.rotate`."""
    u = [-q[0], -q[1], -q[2]]
    t = [2 * c for c in _cross(u, v)]
    ut = _cross(u, t)
    return [v[i] + q[3] * t[i] + ut[i] for i in range(3)]


def _check_supported(part: Perturbation) -> None:
    ok = (
        (
            type(part) is GravityGradient
            and all(type(p.orbit) in (KeplerOrbit, CircularOrbit) for p in part.perturbers)
        )
        or (type(part) is PrecessingFrame and part._function is None)
        or type(part) in (HeavyTop, LinearDamping)
    )
    if not ok:
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
    >>> heyoka_system(Model(body, UserTorque(body, lambda t, rot, w: -w)))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected gravity gradients of Kepler/circular orbits, ...UserTorque... (use method='dop853')
    """
    parts = list(model.parts)
    for part in parts:
        _check_supported(part)
    hy = _heyoka_module()
    par = _Parameters(hy)
    q = hy.make_vars("qx", "qy", "qz", "qw")
    m = hy.make_vars("m1", "m2", "m3")
    body, T = model.body, float(time_unit)
    time = hy.time if T == 1.0 else T * hy.time
    velocity = [par(T * scale * w) * m[i] for i, w in enumerate(body.inverse_moments.tolist())]
    c = (T * scale * body.euler_coefficients).tolist()
    rate = [par(c[0]) * m[1] * m[2], par(c[1]) * m[2] * m[0], par(c[2]) * m[0] * m[1]]
    torques: list[list[Any]] = []
    for part in parts:
        if isinstance(part, PrecessingFrame):
            mu = _to_body(q, [par(T * v) for v in part._constant.tolist()])
            velocity = [velocity[i] - mu[i] for i in range(3)]
        elif isinstance(part, HeavyTop):
            x, y, z = (T * part.weight * part.center_of_mass / scale).tolist()
            qx, qy, qz, qw = q
            g = [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]
            torques.append(
                [g[1] * par(z) - g[2] * par(y), g[2] * par(x) - g[0] * par(z), g[0] * par(y) - g[1] * par(x)]
            )
        elif isinstance(part, LinearDamping):
            damping = np.broadcast_to(T * part.coefficient * part.body.inverse_moments, 3).tolist()
            torques.append([-par(damping[i]) * m[i] for i in range(3)])
        else:
            torques.extend(_gravity_torques(hy, par, part, q, T / scale, time))
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


def _gravity_torques(
    hy: Any, par: _Parameters, part: GravityGradient, q: Sequence[Any], factor: float, time: Any
) -> list[Any]:
    I1, I2, I3 = part.body.moments.tolist()
    out = []
    for p in part.perturbers:
        rho = _to_body(q, kepler_position(hy, par, p.orbit, time))
        r5 = (rho[0] * rho[0] + rho[1] * rho[1] + rho[2] * rho[2]) ** -2.5
        k = 3 * p.gm * factor
        out.append(
            [
                par(k * (I3 - I2)) * r5 * rho[1] * rho[2],
                par(k * (I1 - I3)) * r5 * rho[2] * rho[0],
                par(k * (I2 - I1)) * r5 * rho[0] * rho[1],
            ]
        )
    return out


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
