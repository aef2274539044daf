r"""Reference integration of the heavy top on e(3): the Euler–Poisson equations in ``(m, γ)``.

With ``m`` the body angular momentum, ``γ`` the upward vertical s3 in body
components (third row of ``rot.as_matrix()``), ``ω = m/I`` and the
:class:`~andoyer.perturbations.HeavyTop` potential ``weight r_c·γ``, the
Lie–Poisson flow of ``K = ½ Σ m_i²/I_i + weight r_c·γ`` on e(3)
(``ṁ = m × ∇_m K + γ × ∇_γ K``, ``γ̇ = γ × ∇_m K``) is

.. math::

    \dot m_1 = c_1 m_2 m_3 + w (\gamma_2 z_c - \gamma_3 y_c), \quad\text{(cyclic)},\qquad
    \dot{\boldsymbol\gamma} = \boldsymbol\gamma\times\boldsymbol\omega,

with ``c_1 = (I2 − I3)/(I2 I3)`` (cyclic), ``w = m g0`` and ``r_c = (x_c, y_c, z_c)``:
the free part is written without cancellation, so for ``I1 = I2`` and ``r_c`` on
``b3`` (the Lagrange top) ``ṁ_3`` is exactly zero. The integrals are the energy
``K``, the Casimirs ``|γ|²`` and ``H = m·γ`` (:func:`euler_poisson_integrals`).

Six equations instead of seven, with a right-hand side on Python floats (about
100 times cheaper a call than the general hub equations of
:func:`~andoyer.integrate.integrate_reference`) driven by Hairer's Fortran
DOP853 (``scipy.integrate.ode``), one trajectory at a time so that each has its
own step sizes. ``method="heyoka"`` uses heyoka's Taylor integrator instead
(optional dependency).
"""

from __future__ import annotations

import functools
import importlib.util
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import ode

from andoyer._limits import check_phase, check_size, spin_rate
from andoyer._validation import as_finite, as_vectors, broadcast
from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.heavy_top import HeavyTop

__all__ = ["euler_poisson_integrals", "euler_poisson_rates", "integrate_euler_poisson"]

Array = NDArray[np.float64]

METHODS = ("dop853", "heyoka")
_MAX_STEPS = 10**9


def _check_models(body: Any, top: Any) -> None:
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    # A heavy top is any term whose torque is γ × c in a uniform field (HeavyTop's uniform_field()).
    if not isinstance(top, Perturbation) or top.uniform_field() is None:
        msg = f"expected an andoyer HeavyTop, got {type(top).__name__}"
        raise ValueError(msg)


def _points(m: ArrayLike, gamma: ArrayLike) -> tuple[Array, Array]:
    m, gamma = broadcast(("m", as_vectors(m, "m")), ("gamma", as_vectors(gamma, "gamma")))
    return m, gamma


def euler_poisson_rates(
    body: RigidBody, top: HeavyTop, m: ArrayLike, gamma: ArrayLike
) -> tuple[Array, Array]:
    r"""``(dm/dt, dγ/dt)`` of the heavy top on e(3).

    .. math:: \dot m_i = c_i m_j m_k + w(\gamma\times r_c)_i,\qquad
       \dot\gamma = \gamma\times(m/I).

    Parameters
    ----------
    body : RigidBody
        Moments about the fixed point.
    top : HeavyTop
    m : array_like, shape (..., 3)
        Body angular momentum.
    gamma : array_like, shape (..., 3)
        Upward vertical in body components (any norm: the equations are linear in γ).

    Returns
    -------
    dm, dgamma : numpy.ndarray, shape (..., 3)
        Leading axes of ``m`` and ``gamma`` broadcast.

    Examples
    --------
    >>> from andoyer.perturbations import lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> dm, dgamma = euler_poisson_rates(body, top, [0.0, 0.0, 1.0], [0.6, 0.0, 0.8])
    >>> dm.round(12).tolist(), dgamma.round(12).tolist()  # torque w γ × r_c, γ precesses at ω3 = 2
    ([0.0, -0.36, 0.0], [0.0, -1.2, 0.0])
    """
    _check_models(body, top)
    m, gamma = _points(m, gamma)
    c = body.euler_coefficients
    w = top.uniform_field()
    omega = m / body.moments
    m1, m2, m3 = np.moveaxis(m, -1, 0)
    g1, g2, g3 = np.moveaxis(gamma, -1, 0)
    o1, o2, o3 = np.moveaxis(omega, -1, 0)
    dm = np.stack(
        [
            c[0] * m2 * m3 + (g2 * w[2] - g3 * w[1]),
            c[1] * m3 * m1 + (g3 * w[0] - g1 * w[2]),
            c[2] * m1 * m2 + (g1 * w[1] - g2 * w[0]),
        ],
        axis=-1,
    )
    dgamma = np.stack([g2 * o3 - g3 * o2, g3 * o1 - g1 * o3, g1 * o2 - g2 * o1], axis=-1)
    return dm, dgamma


def euler_poisson_integrals(
    body: RigidBody, top: HeavyTop, m: ArrayLike, gamma: ArrayLike
) -> dict[str, Array]:
    """Energy and Casimirs of the heavy top at points ``(m, γ)``.

    Parameters
    ----------
    body : RigidBody
    top : HeavyTop
    m, gamma : array_like, shape (..., 3)

    Returns
    -------
    dict of str to numpy.ndarray, shape (...)
        ``"energy"`` ``½ Σ m_i²/I_i + w r_c·γ``, ``"H"`` ``m·γ`` and ``"gamma2"`` ``|γ|²``.

    Examples
    --------
    >>> from andoyer.perturbations import lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> {k: float(v) for k, v in euler_poisson_integrals(body, top, [0, 0, 1.0], [0.6, 0, 0.8]).items()}
    {'energy': 1.48, 'H': 0.8, 'gamma2': 1.0}
    """
    _check_models(body, top)
    m, gamma = _points(m, gamma)
    energy = 0.5 * np.sum(m * m / body.moments, axis=-1) + top.weight * (gamma @ top.center_of_mass)
    return {
        "energy": energy[()],
        "H": np.sum(m * gamma, axis=-1)[()],
        "gamma2": np.sum(gamma * gamma, axis=-1)[()],
    }


def _scalar_rhs(body: RigidBody, top: HeavyTop) -> Callable[[float, Array], list[float]]:
    """The right-hand side on Python floats: a numpy call per operation would cost 20× more."""
    c1, c2, c3 = body.euler_coefficients.tolist()
    i1, i2, i3 = body.inverse_moments.tolist()
    x, y, z = top.uniform_field().tolist()

    def rhs(_t: float, state: Array) -> list[float]:
        m1, m2, m3, g1, g2, g3 = state.tolist()
        o1, o2, o3 = m1 * i1, m2 * i2, m3 * i3
        return [
            c1 * m2 * m3 + (g2 * z - g3 * y),
            c2 * m3 * m1 + (g3 * x - g1 * z),
            c3 * m1 * m2 + (g1 * y - g2 * x),
            g2 * o3 - g3 * o2,
            g3 * o1 - g1 * o3,
            g1 * o2 - g2 * o1,
        ]

    return rhs


def _dop853_runner(body: RigidBody, top: HeavyTop, rtol: float, atol: float) -> Callable[..., Array]:
    rhs = _scalar_rhs(body, top)

    def run(y0: Array, t0: float, targets: Array) -> Array:
        solver = ode(rhs).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=_MAX_STEPS)
        solver.set_initial_value(y0, t0)
        out = np.empty((targets.size, 6))
        for k, time in enumerate(targets):
            out[k] = solver.integrate(time)
            if not solver.successful():
                code = solver.get_return_code()
                msg = f"expected the DOP853 integration to succeed, got return code {code}"
                raise ValueError(msg)
        return out

    return run


@functools.cache
def _heyoka_integrator() -> Any:  # pragma: no cover - optional dependency
    import heyoka as hy

    m1, m2, m3, g1, g2, g3 = hy.make_vars("m1", "m2", "m3", "g1", "g2", "g3")
    c1, c2, c3, i1, i2, i3, x, y, z = (hy.par[k] for k in range(9))
    o1, o2, o3 = m1 * i1, m2 * i2, m3 * i3
    system = [
        (m1, c1 * m2 * m3 + (g2 * z - g3 * y)),
        (m2, c2 * m3 * m1 + (g3 * x - g1 * z)),
        (m3, c3 * m1 * m2 + (g1 * y - g2 * x)),
        (g1, g2 * o3 - g3 * o2),
        (g2, g3 * o1 - g1 * o3),
        (g3, g1 * o2 - g2 * o1),
    ]
    return hy.taylor_adaptive(system, [0.0] * 6, pars=[0.0] * 9, compact_mode=True)


def _heyoka_runner(body: RigidBody, top: HeavyTop, rtol: float | None) -> Callable[..., Array]:
    if importlib.util.find_spec("heyoka") is None:
        msg = "expected heyoka to be installed for method='heyoka', got no module named 'heyoka'"
        raise ValueError(msg)
    if rtol is not None:
        msg = f"expected rtol=None with method='heyoka' (its tolerance is the machine epsilon), got {rtol!r}"
        raise ValueError(msg)
    pars = [
        *body.euler_coefficients.tolist(),
        *body.inverse_moments.tolist(),
        *top.uniform_field().tolist(),
    ]

    def run(y0: Array, t0: float, targets: Array) -> Array:  # pragma: no cover - optional dependency
        ta = _heyoka_integrator()
        ta.state[:] = y0
        ta.pars[:] = pars
        ta.time = t0
        result = ta.propagate_grid(np.concatenate([[t0], targets]))
        if result[5].shape[0] != targets.size + 1:
            msg = f"expected the heyoka integration to reach every output time, got outcome {result[0]}"
            raise ValueError(msg)
        return result[5][1:]

    return run


#: DOP853 steps per radian turned at rtol = 1e-12 (:mod:`andoyer.integrate.reference`).
_STEPS_PER_RADIAN = 2.5


def integrate_euler_poisson(
    body: RigidBody,
    top: HeavyTop,
    m: ArrayLike,
    gamma: ArrayLike,
    t: ArrayLike,
    t0: float = 0.0,
    *,
    method: str = "dop853",
    rtol: float | None = None,
    atol: float | None = None,
) -> tuple[Array, Array]:
    """Propagate heavy-top states ``(m, γ)`` (at ``t0``) to times ``t``.

    Parameters
    ----------
    body : RigidBody
        Moments about the fixed point.
    top : HeavyTop
    m, gamma : array_like, shape (S..., 3)
        Initial body momenta and verticals; leading axes broadcast.
    t : array_like, shape (T...)
        Output times; they broadcast with ``S``.
    t0 : float
        Time of the initial states.
    method : {"dop853", "heyoka"}
        Hairer's DOP853 (``scipy.integrate.ode``), or heyoka's Taylor integrator at
        machine-epsilon tolerance (optional dependency).
    rtol, atol : float, optional
        DOP853 tolerances on every component, default ``1e-14`` and ``1e-16``
        (``rtol`` dominates for momenta of order one). Must be ``None`` for heyoka.

    Returns
    -------
    m, gamma : numpy.ndarray, shape broadcast(S..., T...) + (3,)

    Raises
    ------
    ValueError
        For bad input, an unknown method, heyoka missing, or a failed integration.

    Examples
    --------
    A sleeping Lagrange top (spinning upright) stays upright.

    >>> from andoyer.perturbations import lagrange_top
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> m, gamma = integrate_euler_poisson(body, top, [0, 0, 3.0], [0, 0, 1.0], [0.0, 5.0])
    >>> m.round(12).tolist(), gamma.round(12).tolist()
    ([[0.0, 0.0, 3.0], [0.0, 0.0, 3.0]], [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    """
    _check_models(body, top)
    if method not in METHODS:
        msg = f"expected method in {METHODS}, got {method!r}"
        raise ValueError(msg)
    m, gamma = _points(m, gamma)
    times = as_finite(t, "t")
    t0 = float(as_finite(t0, "t0"))
    state_shape = m.shape[:-1]
    try:
        shape = np.broadcast_shapes(state_shape, times.shape)
    except ValueError as exc:
        msg = f"expected times broadcastable with the states' shape {state_shape}, got shape {times.shape}"
        raise ValueError(msg) from exc
    if times.size == 0:
        msg = f"expected at least one output time t, got an empty array of shape {times.shape}"
        raise ValueError(msg)
    y0 = np.concatenate([m, gamma], axis=-1).reshape(-1, 6)
    with np.errstate(over="ignore"):  # an overflow is an infinite phase: refused
        span = float(np.max(np.abs(times - t0)))
    rate = spin_rate(body.moments, m)
    check_phase(rate, span, "the heavy top")
    tolerance = 1e-14 if rtol is None else float(rtol)
    if method != "heyoka" and tolerance > 0:
        # DOP853 (Fortran, scipy.integrate.ode): 2.5 (1e-12/rtol)^(1/8) steps per radian, as
        # andoyer.integrate.reference measures, of about 10 µs each (measured 23 µs a step at rtol 1e-14)
        per_radian = _STEPS_PER_RADIAN * (1e-12 / tolerance) ** 0.125
        check_size("a DOP853 run", steps=per_radian * rate * span * y0.shape[0], step_seconds=1e-5)
    check_size("an output", nbytes=np.unique(times).size * y0.shape[0] * 6 * 8 * 3)
    if method == "heyoka":
        if atol is not None:
            msg = f"expected atol=None with method='heyoka', got {atol!r}"
            raise ValueError(msg)
        run = _heyoka_runner(body, top, rtol)
    else:
        rtol = 1e-14 if rtol is None else float(rtol)
        atol = 1e-16 if atol is None else float(atol)
        run = _dop853_runner(body, top, rtol, atol)
    unique = np.unique(times)
    table = np.empty((unique.size, y0.shape[0], 6))
    table[unique == t0] = y0
    forward, backward = unique > t0, unique < t0
    for i, start in enumerate(y0):
        if forward.any():
            table[forward, i] = run(start, t0, unique[forward])
        if backward.any():
            table[backward, i] = run(start, t0, unique[backward][::-1])[::-1]
    which = np.searchsorted(unique, np.broadcast_to(times, shape))
    index = np.broadcast_to(np.arange(y0.shape[0]).reshape(state_shape), shape)
    out = table[which, index]
    return out[..., :3], out[..., 3:]
