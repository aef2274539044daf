r"""The secular method: mean states of a fast rotator under the averaged model.

``andoyer.propagate(..., method="secular")`` is :func:`integrate_secular`, which carries the
averaged model on a full :class:`~andoyer.State`; the mean angular momentum alone is
:func:`~andoyer.integrate.secular.momentum.propagate_momentum`, stepped by the exact
rotations of :mod:`andoyer.integrate.secular.rotations`.
``andoyer.integrate.secular.SecularGravityGradient`` is a deprecated alias of the model
that still has the former method ``propagate_momentum``.

:class:`~andoyer.perturbations.averaged_gravity.SecularGravityGradient` evolves the mean
reference-frame angular momentum ``M̄`` (equivalently the Andoyer node ``h``
and ``H = G cos I``; ``G`` and ``L`` are constant) after averaging over the
fast angles ``l``, ``g`` and the perturbers' mean anomalies. A precessing
frame (:class:`~andoyer.perturbations.PrecessingFrame`, ``ΔH = -μ·M``) does not
depend on the fast angles, so its average is itself and it adds
``dM̄/dt = M̄ × μ`` exactly.

The mean *state* at time ``t`` keeps the fast motion of the torque-free body
and turns it with the mean momentum: in Andoyer variables
``(l, g, L, G)`` follow the exact free flow of the initial state and
``(h, H)`` follow the averaged model,

.. math::
   \mathrm{rot}(t) = R_z(\bar h)\,R_x(\bar I - I_0)\,R_z(-h_0)\;\mathrm{rot}_\text{free}(t),
   \qquad \mathbf m(t) = \mathbf m_\text{free}(t),

since ``rot = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)``. The rotation in front carries
``M₀`` onto ``M̄(t)`` and is regular at ``sin I = 0``. No
osculating-to-mean conversion is made: the input state *is* taken as mean,
and the output lacks the short-period terms (nutations at the perturbers'
orbital harmonics, of relative size ``precession rate / orbital frequency``)
as well as the small secular drift of the fast phases ``∂⟨ΔH⟩/∂L``,
``∂⟨ΔH⟩/∂G``.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from andoyer import _quaternion as quat
from andoyer._jit import NUMBA, jit, jitable
from andoyer._limits import PhasePrecisionWarning, check_size
from andoyer._validation import as_finite
from andoyer.free.motion import FreeMotion
from andoyer.integrate.output import gather_table, output_times
from andoyer.integrate.secular.momentum import propagate_checked, propagate_momentum
from andoyer.perturbations.averaged_gravity import SecularGravityGradient as _SecularModel
from andoyer.perturbations.model import Model
from andoyer.state import State

# the one Hamilton product and Euler-angle quaternion, compiled inline into the attitude turn below
jitable(quat.product)
jitable(quat.from_zxz_one)

__all__ = ["integrate_secular", "propagate_checked", "propagate_momentum", "secular_parts"]

Array = NDArray[np.float64]

#: An averaged term: ``momentum_rate(t, M (N, 3), L (N,)) -> dM̄/dt (N, 3)``.
SecularTerm = Any


def secular_parts(model: Model) -> list[SecularTerm]:
    """The averaged terms of ``model``, in order (each term's ``secular_average()``).

    Raises ``ValueError`` for a term without an average (gravity gradients need perturbers on
    :class:`~andoyer.perturbations.KeplerOrbit`; precessing frames are their own average).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import PrecessingFrame
    >>> averages = secular_parts(Model(RigidBody(1, 1, 1.2), PrecessingFrame([0, 0, 1e-3])))
    >>> [type(a).__name__ for a in averages]
    ['FrameAverage']
    """
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    averages = []
    for item in model.parts:
        average = item.secular_average()
        if average is None:
            msg = (
                "expected gravity-gradient models on Kepler orbits or precessing frames for the secular "
                f"method, got {item!r} (use method='splitting' or 'reference')"
            )
            raise ValueError(msg)
        averages.append(average)
    return averages


#: DOP853 steps of the mean momentum per radian of the fastest perturber's mean motion at
#: rtol = 1e-12 (measured 0.008-0.011 for the Earth over 100-1000 years), and seconds per step
#: (measured 0.54 ms with the Sun and the Moon).
_STEPS_PER_ORBITAL_RADIAN = 0.007
_SECONDS_PER_STEP = 5e-4


def _check_secular_size(averages: list[Any], unique: Array, t0: float, rtol: float) -> None:
    """Refuse, before it starts, a secular run longer than :func:`andoyer._limits.check_size` allows."""
    # Frames have no perturber: only the averaged gravity gradients set the step.
    motions = [abs(p.orbit.mean_motion) for a in averages for p in getattr(a, "perturbers", ())]
    if not motions or not rtol > 0:
        return
    span = max(float(unique[-1]) - t0, 0.0) + max(t0 - float(unique[0]), 0.0)
    steps = _STEPS_PER_ORBITAL_RADIAN * (1e-12 / rtol) ** 0.125 * max(motions) * span
    check_size("a secular run", steps=steps, step_seconds=_SECONDS_PER_STEP)


@jitable
def _node_and_inclination(x, y, z):
    """Node ``h = atan2(x, −y)`` and inclination ``I = atan2(√(x² + y²), z)`` of the vector ``(x, y, z)``.

    A kernel written once: components as floats (compiled) or arrays of shape (...).
    """
    return np.arctan2(x, -y), np.arctan2(np.hypot(x, y), z)


def _turned(M0: Array, M: Array, q_free: Array) -> Array:
    """``Rz(h̄) Rx(Ī − I₀) Rz(−h₀) ⊗ q_free``: the free attitudes turned with ``M₀ → M̄``, (U, N, 4).

    ``M0`` (N, 3), ``M`` and ``q_free`` (U, N, ·). One compiled loop when numba is installed (a
    mean state of one body is otherwise a few dozen numpy calls on single numbers), else numpy.
    """
    if not NUMBA:
        h0, I0 = _node_and_inclination(M0[..., 0], M0[..., 1], M0[..., 2])
        h, inclination = _node_and_inclination(M[..., 0], M[..., 1], M[..., 2])
        return quat.multiply(quat.from_zxz(h, inclination - I0, -h0), q_free)
    out = np.empty(q_free.shape)
    _turned_compiled(M0, M, q_free, out)
    return out


@jit
def _turned_compiled(M0, M, q_free, out):
    for i in range(M0.shape[0]):
        h0, I0 = _node_and_inclination(M0[i, 0], M0[i, 1], M0[i, 2])
        for k in range(M.shape[0]):
            h, inclination = _node_and_inclination(M[k, i, 0], M[k, i, 1], M[k, i, 2])
            px, py, pz, pw = quat.from_zxz_one(h, inclination - I0, -h0)
            q = q_free[k, i]
            out[k, i, 0], out[k, i, 1], out[k, i, 2], out[k, i, 3] = quat.product(
                px, py, pz, pw, q[0], q[1], q[2], q[3]
            )


def integrate_secular(
    model: Model, state: State, t: ArrayLike, t0: float = 0.0, rtol: float = 1e-12
) -> State:
    """Propagate the mean ``state`` (at ``t0``) under the averaged ``model`` to times ``t``.

    Parameters
    ----------
    model : Model
        A body with :class:`~andoyer.perturbations.GravityGradient` terms
        (perturbers on :class:`~andoyer.perturbations.KeplerOrbit`) and/or
        :class:`~andoyer.perturbations.PrecessingFrame` terms; ``b3`` is the
        figure axis of a fast rotator.
    state : State, shape (S...)
        The mean state at ``t0``; ``L = m_body[..., 2]`` enters the averaged
        strength through ``cos J = L/G``.
    t : array_like, shape (T...)
        Output times (absolute: the perturbers' orbits are functions of ``t``).
    t0 : float
    rtol : float
        Tolerance on ``M̄``: for a gravity-gradient model alone (forwards in time), the target
        relative global error of the compiled exact-rotation composition
        (:func:`~andoyer.integrate.secular.momentum.propagate_momentum`); otherwise DOP853's tolerance.

    Returns
    -------
    State, shape broadcast(S..., T...)
        The mean state (see the module docstring).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import PrecessingFrame
    >>> body = RigidBody(1.0, 1.0, 1.2)
    >>> frame = PrecessingFrame([0.0, 0.0, 0.01])
    >>> s = State.from_andoyer(0.0, 0.0, 0.5, 0.9, 1.0, 0.8)
    >>> out = integrate_secular(Model(body, frame), s, [0.0, 10.0])
    >>> h = out.as_andoyer().h  # the node regresses at the frame's rate
    >>> round(float(h[1] - h[0]), 12)
    -0.1
    """
    averages = secular_parts(model)
    t0 = float(as_finite(t0, "t0"))
    times, unique, shape = output_times(state, t, model.body.moments, t0)
    _check_secular_size(averages, unique, t0, rtol)
    q0 = state.quaternion.reshape(-1, 4)
    m0 = state.m_body.reshape(-1, 3)
    n = m0.shape[0]
    # M₀ = R(q₀) m₀ (State.m_reference); one state on Python floats: the same IEEE operations
    # as on arrays (no fused multiply-add in either), without a dozen numpy calls on one number
    M0 = np.array([quat.apply(*q0[0].tolist(), *m0[0].tolist())]) if n == 1 else quat.rotate(q0, m0)
    L = m0[:, 2]
    if not np.all(np.sum(M0 * M0, axis=-1) > 0):  # |M₀|² > 0 ⇔ |M₀| > 0 (np.linalg.norm's arithmetic)
        msg = "expected a rotating body (|m| > 0) for the secular method, got a state at rest"
        raise ValueError(msg)

    def rhs(time: float, y: Array) -> Array:
        M = y.reshape(n, 3)
        rate = np.zeros_like(M)
        for average in averages:
            rate = rate + average.momentum_rate(time, M, L)
        return rate.ravel()

    means: dict[float, Array] = {t0: M0}
    # One averaged term whose flow is exact rotations (the gravity gradient on Kepler orbits):
    # the compiled composition, forwards; anything else (frames, several terms, backwards): DOP853.
    rotations = averages[0] if len(averages) == 1 and averages[0].exact_rotations else None
    for direction in (1.0, -1.0):
        targets = unique[(unique - t0) * direction > 0]
        if targets.size == 0:
            continue
        if rotations is not None and direction > 0:
            M = propagate_checked(rotations, M0, L, targets, rtol=rtol, t0=t0)  # inputs checked above
            means.update({float(x): M[k] for k, x in enumerate(targets)})
            continue
        scale = max(float(np.max(np.linalg.norm(M0, axis=-1), initial=0.0)), np.finfo(float).tiny)
        sol = solve_ivp(
            rhs,
            (t0, float(targets[-1] if direction > 0 else targets[0])),
            M0.ravel(),
            method="DOP853",
            t_eval=targets if direction > 0 else targets[::-1],
            rtol=rtol,
            atol=1e-15 * scale,
        )
        if not sol.success:
            msg = f"expected the secular integration to succeed, got: {sol.message}"
            raise ValueError(msg)
        means.update({float(x): y.reshape(n, 3) for x, y in zip(sol.t, sol.y.T, strict=True)})
    # the exact free motion of the initial states at every distinct time (U, N, ·); the state
    # and the times were validated above, so FreeMotion is given its arrays directly
    with warnings.catch_warnings():  # the phase of the fast angles was checked above, with the output times
        warnings.simplefilter("ignore", PhasePrecisionWarning)
        moments = model.body.moments  # in the states' shape: FreeMotion then broadcasts nothing
        moments = moments.reshape(1, 3) if n == 1 else np.broadcast_to(moments, m0.shape)
        m_free, q_free = FreeMotion(moments, m0, q0).propagate((unique - t0)[:, None])
    q = _turned(M0, np.stack([means[float(x)] for x in unique]), q_free)
    return gather_table(state, times, unique, shape, q, m_free, conserved=True)


class _DeprecatedSecularGravityGradient(_SecularModel):
    """The former ``andoyer.integrate.secular.SecularGravityGradient``, with its method."""

    def propagate_momentum(self, *args: Any, **kwargs: Any) -> Array:
        """:func:`propagate_momentum` of this model."""
        return propagate_momentum(self, *args, **kwargs)


_DeprecatedSecularGravityGradient.__name__ = "SecularGravityGradient"
_DeprecatedSecularGravityGradient.__qualname__ = "SecularGravityGradient"


def __getattr__(name: str) -> Any:
    # PEP 562: the model moved to andoyer.perturbations.averaged_gravity; the old name still works.
    if name == "SecularGravityGradient":
        warnings.warn(
            "andoyer.integrate.secular.SecularGravityGradient is deprecated: use "
            "andoyer.perturbations.averaged_gravity.SecularGravityGradient and "
            "andoyer.integrate.secular.propagate_momentum(model, ...)",
            DeprecationWarning,
            stacklevel=2,
        )
        return _DeprecatedSecularGravityGradient
    msg = f"module {__name__!r} has no attribute {name!r}"
    raise AttributeError(msg)
