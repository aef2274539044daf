r"""Euler 3-1-3 angles ``(φ, θ, ψ)`` and their conjugate momenta ``(Φ, Θ, Ψ)``.

Convention (Gurfil et al. §2.1): the attitude that takes body vectors to the
reference frame is

.. math:: \mathcal{R} = R_z(\phi)\, R_x(\theta)\, R_z(\psi)
   = \texttt{Rotation.from\_euler("ZXZ", [φ, θ, ψ])},

with ``0 <= θ <= π`` and ``φ, ψ`` in ``[0, 2π)``; Gurfil's matrix (eq. 2),
mapping reference components to body components, is its transpose. The
momenta (eqs. 25–27, 40–42) are

.. math::
   \Phi = \mathbf{m}\cdot\hat{s}_3, \quad \Psi = m_3, \quad
   \Theta = m_1 \cos\psi - m_2 \sin\psi,

and the body angular momentum follows as
``m1 = Θ cos ψ + X sin ψ``, ``m2 = -Θ sin ψ + X cos ψ``, ``m3 = Ψ`` with
``X = (Φ - Ψ cos θ)/sin θ``.

The chart's dynamics are here too: the free-body Hamiltonian (Gurfil eq. 23,
:func:`euler_hamiltonian`) and Hamilton's equations (:func:`euler_equations`), registered with
the chart.
"""

from __future__ import annotations

import math
from types import ModuleType
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._fastmath import chunked
from andoyer._validation import (
    MAX_ANGLE,
    MAX_MOMENTUM,
    as_finite,
    broadcast,
    broadcast_finite,
    check_angle,
    check_magnitude,
)
from andoyer.body import RigidBody
from andoyer.state import _kernels
from andoyer.state.hub import State
from andoyer.state.registry import Chart, register
from andoyer.state.singular import warn_if_singular

__all__ = [
    "Euler",
    "EulerRates",
    "euler_equations",
    "euler_hamiltonian",
    "euler_matrix",
    "euler_to_hub",
    "hub_to_euler",
    "transverse_momentum",
]

Array = NDArray[np.float64]


_SINGULAR_TO_HUB = (
    "Euler chart at sin(theta) = 0: the momentum component normal to Theta's is not "
    "represented and was set to 0"
)
_SINGULAR_TO_EULER = (
    "Euler chart at sin(theta) = 0: set psi = 0; the momentum component "
    "m1 sin(psi) + m2 cos(psi) is not represented by (Phi, Theta, Psi) there"
)
_INFINITE_MOMENTUM = "expected Phi = Psi cos(theta) where sin(theta) = 0, got Phi != ±Psi (infinite momentum)"


#: Arrays of at least this many states go through the compiled loops; smaller ones through
#: numpy, as do all where numba is missing. Importing numba and loading the cached loops costs
#: ~0.7 s once per process (a command converting a few states should not pay it), and numpy's
#: ~150 µs a call stays small below this size. Both run the same kernels and agree within 2 ulp.
COMPILED_MIN = 2048


def compiled_conversions(size: int) -> ModuleType | None:
    """The numba loops of :mod:`andoyer.state._compiled` for ``size`` states, or ``None``.

    ``None`` (the numpy path) below :data:`COMPILED_MIN` states or without numba. The module
    is imported on the first large conversion, so a single state costs no numba start-up.
    """
    if size < COMPILED_MIN:
        return None
    from andoyer.state import _compiled

    return _compiled if _compiled.NUMBA else None


def scalars(values: tuple[Any, ...]) -> list[float] | None:
    """``values`` as finite Python floats when each is a real scalar (a single state), else ``None``.

    ``None`` sends the caller down its array path, whose validation names what is wrong.
    """
    out = []
    for value in values:
        kind = type(value)
        if not (kind is float or kind is int or kind is np.float64):
            return None
        try:
            number = float(value)
        except OverflowError:
            return None
        if not math.isfinite(number):
            return None
        out.append(number)
    return out


class Euler(NamedTuple):
    """Euler 3-1-3 angles and their conjugate momenta; each field has the state's shape."""

    phi: Array
    theta: Array
    psi: Array
    Phi: Array
    Theta: Array
    Psi: Array


def euler_matrix(phi: ArrayLike, theta: ArrayLike, psi: ArrayLike) -> Array:
    """Gurfil's rotation matrix ``R(φ, θ, ψ)`` (eq. 2), reference → body components.

    Parameters
    ----------
    phi, theta, psi : array_like, shape (...)
        Euler 3-1-3 angles in radians; they broadcast together.

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``R`` with ``v_body = R @ v_ref``; it equals
        ``Rotation.from_euler("ZXZ", [φ, θ, ψ]).as_matrix().T``.

    Examples
    --------
    >>> import numpy as np
    >>> R = euler_matrix(0.3, 0.2, 0.1)
    >>> np.allclose(R @ R.T, np.eye(3))
    True
    """
    phi, theta, psi = broadcast(
        ("phi", as_finite(phi, "phi")), ("theta", as_finite(theta, "theta")), ("psi", as_finite(psi, "psi"))
    )
    cf, sf = np.cos(phi), np.sin(phi)
    ct, st = np.cos(theta), np.sin(theta)
    cp, sp = np.cos(psi), np.sin(psi)
    rows = [
        [cp * cf - sp * ct * sf, cp * sf + sp * ct * cf, sp * st],
        [-sp * cf - cp * ct * sf, -sp * sf + cp * ct * cf, cp * st],
        [st * sf, -st * cf, ct],
    ]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def transverse_momentum(big: Array, small: Array, theta: Array) -> tuple[Array, Array]:
    """``(big - small cos θ)`` and ``sin θ`` without cancellation near ``sin θ = 0``, on arrays.

    Near ``θ = 0`` the physical state has ``big ≈ small`` and the difference is
    ``(big - small) + 2 small sin²(θ/2)``; near ``θ = π`` it is
    ``(big + small) - 2 small cos²(θ/2)``. Both forms are exact rearrangements
    (the kernel :func:`andoyer.state._kernels.transverse_momentum_one`, on arrays).

    Parameters
    ----------
    big, small, theta : ndarray, shape (...)
        The two momenta (``Φ, Ψ`` for ``X``; ``Ψ, Φ`` for its reference twin) and ``θ``;
        they broadcast together.

    Returns
    -------
    numerator, sin_theta : ndarray, shape (...)

    Examples
    --------
    >>> numerator, st = transverse_momentum(np.array(1.0), np.array(1.0), np.array(1e-9))
    >>> float(numerator), float(st)  # Φ - Ψ cos θ with Φ = Ψ: Ψ θ²/2, no cancellation
    (5.000000000000001e-19, 1e-09)
    """
    return _kernels.transverse_momentum_arrays(big, small, theta)


def euler_to_hub(
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
    stacklevel: int = 2,
    *,
    unit: bool = False,
) -> tuple[Array, Array]:
    """Attitude quaternions (..., 4) and body angular momenta (..., 3) of Euler states.

    At ``sin θ = 0`` the component ``X`` of the momentum is not represented by
    the chart; it is set to 0 with a :class:`SingularChartWarning`, and states
    with ``Φ ≠ ±Ψ`` there (infinite momentum) are rejected. The quaternions come
    divided by their norm as :class:`~andoyer.State` stores them (``unit``, kept for
    the callers that ask for it, changes nothing), from the kernel
    :func:`andoyer.state._kernels.euler_to_hub_one`: as Python for one state,
    compiled for arrays (numba), or on whole arrays (numpy).
    """
    del unit  # every path normalises
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    values = (phi, theta, psi, Phi, Theta, Psi)
    one = scalars(values)
    # Out-of-range angles or momenta take the array path, which names them.
    if (
        one is not None
        and 0 <= one[1] <= np.pi
        and max(abs(one[0]), abs(one[2])) <= MAX_ANGLE
        and max(map(abs, one[3:])) <= MAX_MOMENTUM
    ):
        *r, status = _kernels.euler_to_hub_floats(*one)
        if status == _kernels.INFINITE_MOMENTUM:
            raise ValueError(_INFINITE_MOMENTUM)
        if status == _kernels.SINGULAR:
            warn_if_singular(True, _SINGULAR_TO_HUB, stacklevel + 1)
        return np.array(r[:4]), np.array(r[4:])
    phi, theta, psi, Phi, Theta, Psi = broadcast_finite(names, values)
    for name, momentum in (("Phi", Phi), ("Theta", Theta), ("Psi", Psi)):
        check_magnitude(momentum, name)
    check_angle(phi, "phi")
    check_angle(psi, "psi")
    if np.any((theta < 0) | (theta > np.pi)):
        bad = float(theta[(theta < 0) | (theta > np.pi)].flat[0])
        msg = f"expected 0 <= theta <= pi, got theta = {bad!r}"
        raise ValueError(msg)
    compiled = compiled_conversions(phi.size)
    if compiled is not None:
        q, m, status = compiled.euler_to_hub((phi, theta, psi, Phi, Theta, Psi))
    else:
        flat = [np.ascontiguousarray(v).reshape(-1) for v in (phi, theta, psi, Phi, Theta, Psi)]
        *columns, status = chunked(_kernels.euler_to_hub_arrays, flat, 8)
        q, m = np.stack(columns[:4], axis=-1), np.stack(columns[4:], axis=-1)
    if np.any(status == _kernels.INFINITE_MOMENTUM):
        raise ValueError(_INFINITE_MOMENTUM)
    warn_if_singular(status == _kernels.SINGULAR, _SINGULAR_TO_HUB, stacklevel + 1)
    return q.reshape(*phi.shape, 4), m.reshape(*phi.shape, 3)


def hub_to_euler(q: Array, m: Array, stacklevel: int = 2) -> Euler:
    """Euler angles and momenta of attitude quaternions (..., 4) and body momenta (..., 3).

    At ``sin θ = 0`` the convention is ``ψ = 0`` (``φ`` carries ``φ ± ψ``), with a
    :class:`SingularChartWarning`. Attitudes within ``2ε`` of the singularity
    (``sin(θ/2)`` or ``cos(θ/2)`` below ``2ε``) are snapped onto it, and there
    ``Φ = Ψ cos θ`` exactly, so the rotation round trip stays exact to ``4ε``.
    One state goes through the kernel :func:`andoyer.state._kernels.hub_to_euler_one`
    as Python (fields are numpy scalars), arrays through it compiled when numba is
    there, else through it on whole arrays (numpy).
    """
    if q.shape == (4,) and m.shape == (3,):
        *r, singular = _kernels.hub_to_euler_floats(*q.tolist(), *m.tolist())
        if singular:
            warn_if_singular(True, _SINGULAR_TO_EULER, stacklevel + 1)
        return Euler(*map(np.float64, r))
    shape = np.broadcast_shapes(q.shape[:-1], m.shape[:-1])
    q, m = np.broadcast_to(q, (*shape, 4)).reshape(-1, 4), np.broadcast_to(m, (*shape, 3)).reshape(-1, 3)
    compiled = compiled_conversions(m.shape[0])
    if compiled is not None:
        out, singular = compiled.hub_to_euler(q, m)
    else:
        *out, singular = chunked(_kernels.hub_to_euler_arrays, [*q.T, *m.T], 7)
    warn_if_singular(singular != 0, _SINGULAR_TO_EULER, stacklevel + 1)
    return Euler(*(v.reshape(shape) for v in out))


# The chart's methods of State (installed when the chart registers, below): their signatures
# are the chart's, written once here. ``cls`` and ``self`` are the State class and a state.


def _from_euler(
    cls: type[State],
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> State:
    r"""State from Euler 3-1-3 angles and their conjugate momenta (Gurfil §2).

    The attitude is ``Rotation.from_euler("ZXZ", [φ, θ, ψ])``; the momenta
    give ``m_body`` through Gurfil eqs. 25–27,
    ``m = (Θ cos ψ + X sin ψ, -Θ sin ψ + X cos ψ, Ψ)``, ``X = (Φ - Ψ cos θ)/sin θ``.

    Parameters
    ----------
    phi, theta, psi : array_like, shape (...)
        Euler angles in radians, ``0 <= θ <= π``.
    Phi, Theta, Psi : array_like, shape (...)
        Conjugate momenta. All six broadcast together.

    Returns
    -------
    State, shape (...)
        The states (the broadcast shape of the six).

    Examples
    --------
    >>> from andoyer import State
    >>> s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    >>> [round(float(x), 12) for x in s.as_euler()]
    [0.1, 0.5, 0.2, 1.0, 0.3, 0.8]
    """
    return cls.from_unit_quaternion(*euler_to_hub(phi, theta, psi, Phi, Theta, Psi, stacklevel=2, unit=True))


def _as_euler(self) -> Euler:
    """Euler 3-1-3 angles and conjugate momenta ``(phi, theta, psi, Phi, Theta, Psi)``.

    At ``sin θ = 0`` the convention is ``ψ = 0`` with a
    :class:`~andoyer.state.SingularChartWarning`.

    Returns
    -------
    Euler of arrays, each of shape (...)
        The six coordinates, of the state's shape (numpy floats for a single state).

    Examples
    --------
    >>> from andoyer import State
    >>> s = State.from_euler(1.0, 2.0, 3.0, 0.1, 0.2, 0.3)
    >>> round(float(s.as_euler().Theta), 12)
    0.2
    """
    return hub_to_euler(self._q, self._m, stacklevel=2)


# ---------------------------------------------------------------- the chart's dynamics


class EulerRates(NamedTuple):
    """Time derivatives of the Euler chart's variables."""

    phi: Array
    theta: Array
    psi: Array
    Phi: Array
    Theta: Array
    Psi: Array


def euler_hamiltonian(
    body: RigidBody,
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> Array:
    """Gurfil eq. 23: the free Hamiltonian in Euler angles and momenta.

    ``½ (s_ψ²/I1 + c_ψ²/I2) X² + Ψ²/(2 I3) + ½ (c_ψ²/I1 + s_ψ²/I2) Θ² + (1/I1 - 1/I2) X Θ s_ψ c_ψ``
    with ``X = (Φ - Ψ c_θ)/s_θ``: the kinetic energy ``½ m·I⁻¹m``. ``φ`` is cyclic and does
    not enter. ``(Φ - Ψ cos θ)`` is formed without cancellation near ``sin θ = 0``, where the
    chart is singular (``sin θ = 0`` raises unless ``Φ = ±Ψ`` there).

    Parameters
    ----------
    body : RigidBody
    phi, theta, psi, Phi, Theta, Psi : array_like, shape (...)
        Euler 3-1-3 angles and conjugate momenta; they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> e = (0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    >>> bool(abs(euler_hamiltonian(body, *e) - State.from_euler(*e).energy(body)) < 1e-15)
    True
    """
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    _, theta, psi, Phi, Theta, Psi = broadcast_finite(names, (phi, theta, psi, Phi, Theta, Psi))
    numerator, st = transverse_momentum(Phi, Psi, theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 in the Euler-chart Hamiltonian, got sin(theta) = 0"
        raise ValueError(msg)
    X = numerator / st
    I1, I2, I3 = body.moments
    s2, c2 = np.sin(psi) ** 2, np.cos(psi) ** 2
    return (
        0.5 * (s2 / I1 + c2 / I2) * X * X
        + Psi * Psi / (2 * I3)
        + 0.5 * (c2 / I1 + s2 / I2) * Theta * Theta
        + (I2 - I1) / (I1 * I2) * X * Theta * np.sin(psi) * np.cos(psi)
    )


def euler_equations(
    body: RigidBody,
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> EulerRates:
    r"""Hamilton's equations of the Euler-chart Hamiltonian (eq. 23).

    With ``ω = I⁻¹ m`` and ``S = ω1 sin ψ + ω2 cos ψ``, the chain rule through
    eqs. 25–27 gives ``dφ/dt = S / sin θ``, ``dθ/dt = ω1 cos ψ - ω2 sin ψ``,
    ``dψ/dt = ω3 - S cot θ``, ``dΦ/dt = 0``, ``dΘ/dt = -S (Ψ - X cot θ)``,
    ``dΨ/dt = c3 m1 m2``, which reproduce the kinematic eqs. 5–7.

    Parameters
    ----------
    body : RigidBody
    phi, theta, psi, Phi, Theta, Psi : array_like, shape (...)
        They broadcast; ``sin θ ≠ 0``.

    Returns
    -------
    EulerRates

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> rates = euler_equations(RigidBody(1.0, 2.0, 2.5), 0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    >>> float(rates.Phi)
    0.0
    """
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    _, theta, psi, Phi, Theta, Psi = broadcast_finite(names, (phi, theta, psi, Phi, Theta, Psi))
    numerator, st = transverse_momentum(Phi, Psi, theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 in the Euler-chart equations, got sin(theta) = 0"
        raise ValueError(msg)
    X = numerator / st
    cot = np.cos(theta) / st
    cp, sp = np.cos(psi), np.sin(psi)
    m1, m2 = Theta * cp + X * sp, -Theta * sp + X * cp
    I1, I2, I3 = body.moments
    w1, w2, w3 = m1 / I1, m2 / I2, Psi / I3
    S = w1 * sp + w2 * cp
    return EulerRates(
        S / st,
        w1 * cp - w2 * sp,
        w3 - S * cot,
        np.zeros_like(Phi),
        -S * (Psi - X * cot),
        body.euler_coefficients[2] * m1 * m2,
    )


register(
    Chart(
        "euler",
        Euler._fields,
        ("phi", "theta", "psi"),
        "Euler 3-1-3 angles and their conjugate momenta (Gurfil §2)",
        _from_euler,
        _as_euler,
        source="andoyer.state.euler",
        hamiltonian=euler_hamiltonian,
        equations=euler_equations,
    ),
    State,
)
