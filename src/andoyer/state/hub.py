"""The hub of the state package: the rotation state, attitude plus angular momentum.

:class:`State` holds the attitude quaternion ``q`` and the body angular momentum ``m``; every
chart converts to and from them. The hub knows none of its charts: each chart module of
:mod:`andoyer.state` imports this one, registers its :class:`~andoyer.state.registry.Chart`
and installs its methods ``State.from_<chart>``/``State.as_<chart>`` (so ``State.from_sadov``
is written in :mod:`andoyer.state.sadov`); the package's ``__init__`` imports the charts. The
hub's own chart (``state``: the columns ``qx, qy, qz, qw, m1, m2, m3``) and its dynamics are
here: the free-body Hamiltonian ``½ m·I⁻¹m`` (:func:`state_hamiltonian`) and the equations of
motion of ``m`` and ``q`` (:func:`euler_poinsot`, :func:`euler_poinsot_omega`,
:func:`lie_poisson`, :func:`attitude_rate`), with the checks every chart shares
(:func:`check_body`) and the free flow of the time-dependent charts (:func:`free_flow`).

Right-hand sides are written without cancellation: the free Euler–Poinsot equations as
``dm_i/dt = c_i m_j m_k`` with ``c_i = (I_j - I_k)/(I_j I_k)`` (cyclic ``i, j, k``), never as
the literal cross product ``m × I⁻¹m``, which on a near-axisymmetric body (Earth:
``(B - A)/A ≈ 2e-6``) subtracts two nearly equal products and loses about three digits.

Signs: the body angular momentum obeys the so(3) Lie–Poisson bracket
``{F, K}(m) = -m·(∇F × ∇K)``, so ``{m1, m2} = -m3`` (Gurfil eq. 28) and
``dm/dt = {m, K} = m × ∇K``. The attitude ``q`` (body → reference) obeys
``dq/dt = ½ q ⊗ (ω, 0)`` with ``ω = I⁻¹ m`` in body components.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from andoyer import _quaternion as quat
from andoyer._validation import as_vectors, check_magnitude, describe
from andoyer.body import RigidBody
from andoyer.state.registry import Chart, Hub, register

__all__ = [
    "State",
    "attitude_rate",
    "check_body",
    "euler_poinsot",
    "euler_poinsot_omega",
    "free_flow",
    "lie_poisson",
    "state_hamiltonian",
]

Array = NDArray[np.float64]


def _check_rotation(rotation: Any) -> Array:
    if not isinstance(rotation, Rotation):
        msg = f"expected a scipy.spatial.transform.Rotation, got {type(rotation).__name__}"
        raise ValueError(msg)
    return np.asarray(rotation.as_quat(), dtype=np.float64)


class State:
    r"""Rotation state of a rigid body: attitude and angular momentum, vectorised.

    The attitude is a rotation :math:`\mathcal{R}` taking body components to
    reference components, ``v_ref = rotation.apply(v_body)``; Gurfil's matrix
    ``R`` (reference → body) is ``rotation.as_matrix().T``. The angular
    momentum is kept in body components ``m_body``; ``m_reference = R m_body``.
    A state array has a shape (``state.shape``); every field carries it as
    leading axes.

    Build states with the ``from_*`` class methods and read charts with the
    ``as_*`` methods. Those of the charts (``from_euler``/``as_euler``, ``andoyer``,
    ``initial_andoyer``, ``sadov``, ``serret``, ``sam``) are written in the chart
    modules, ``State.from_<chart>`` in :mod:`andoyer.state.<chart>`, and installed
    on this class when the chart registers (:func:`andoyer.state.registry.register`).

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Attitude as unit quaternions, scalar last ``(x, y, z, w)`` (scipy's convention).
    m_body : array_like, shape (..., 3)
        Angular momentum in body components. Shapes broadcast.

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import State
    >>> s = State.from_andoyer(l=0.3, g=1.0, h=2.0, L=0.9, G=1.0, H=0.5)
    >>> s.shape
    ()
    >>> a = s.as_andoyer()
    >>> [round(float(x), 12) for x in a]
    [0.3, 1.0, 2.0, 0.9, 1.0, 0.5]
    >>> round(float(s.m_reference[2]), 12)  # H is the reference-axis projection
    0.5
    """

    __slots__ = ("_m", "_q")

    def __init__(self, quaternion: ArrayLike, m_body: ArrayLike) -> None:
        q = as_vectors(quaternion, "quaternion", 4)
        m = as_vectors(m_body, "m_body", 3)
        check_magnitude(m, "m_body")
        norm = np.linalg.norm(q, axis=-1)
        if np.any(np.abs(norm - 1.0) > 1e-6):
            bad = float(norm.flat[np.argmax(np.abs(norm - 1.0))])
            msg = f"expected unit quaternions (|q| = 1 within 1e-6), got |q| = {bad!r}"
            raise ValueError(msg)
        try:
            shape = np.broadcast_shapes(q.shape[:-1], m.shape[:-1])
        except ValueError as exc:
            msg = (
                "expected attitude and angular momentum with broadcastable shapes, "
                f"got {q.shape[:-1]} and {m.shape[:-1]}"
            )
            raise ValueError(msg) from exc
        self._q = np.broadcast_to(q / norm[..., None], (*shape, 4)).copy()
        self._m = np.broadcast_to(m, (*shape, 3)).copy()

    @classmethod
    def from_unit_quaternion(cls, q: Array, m: Array) -> State:
        """State from arrays already normalised, without a copy (for converters and integrators).

        Unlike :meth:`from_quaternion`, the quaternions are taken as they are (the caller has
        normalised them, as the chart converters and the integrators' outputs do) and the
        arrays are neither broadcast nor copied. What is checked is what costs one pass: the
        shapes, the unit norms (to ``10⁻¹²``; a NaN fails it) and the momenta's finiteness (a
        non-finite one goes through the checking constructor, which names it).

        Parameters
        ----------
        q : ndarray, shape (..., 4)
            Unit quaternions, scalar last (body → reference).
        m : ndarray, shape (..., 3)
            Body angular momenta, of the same leading shape.

        Returns
        -------
        State
            The state of shape ``q.shape[:-1]``.

        Examples
        --------
        >>> import numpy as np
        >>> State.from_unit_quaternion(np.array([[0.0, 0.0, 0.0, 1.0]]), np.array([[0.0, 0.0, 2.0]])).shape
        (1,)
        >>> State.from_unit_quaternion(np.array([0.0, 0.0, 0.0, 2.0]), np.array([0.0, 0.0, 2.0]))
        Traceback (most recent call last):
        ...
        ValueError: expected unit quaternions (norm 1 to 1e-12), got norms [2.]
        """
        if not (isinstance(q, np.ndarray) and isinstance(m, np.ndarray) and q.dtype == m.dtype == np.float64):
            q, m = np.asarray(q, dtype=np.float64), np.asarray(m, dtype=np.float64)
        if q.shape[-1:] != (4,) or m.shape[-1:] != (3,) or q.shape[:-1] != m.shape[:-1]:
            msg = f"expected q (..., 4) and m (..., 3) of one leading shape, got {q.shape} and {m.shape}"
            raise ValueError(msg)
        squared = np.einsum("...i,...i->...", q, q)
        if not (abs(squared - 1.0) <= 2e-12).all():
            norms = np.sqrt(squared[~(abs(squared - 1.0) <= 2e-12)]).ravel()[:3]
            msg = f"expected unit quaternions (norm 1 to 1e-12), got norms {norms}"
            raise ValueError(msg)
        if not np.isfinite(m).all():
            return cls(q, m)
        state = object.__new__(cls)
        state._q, state._m = q, m
        return state

    # ----------------------------------------------------------- constructors
    @classmethod
    def from_quaternion(cls, quaternion: ArrayLike, m_body: ArrayLike) -> State:
        """State from attitude quaternions (..., 4), scalar last, and body momenta (..., 3).

        Examples
        --------
        >>> State.from_quaternion([0, 0, 0, 1], [[0, 0, 1], [0, 1, 0]]).shape
        (2,)
        """
        return cls(quaternion, m_body)

    @classmethod
    def from_attitude(cls, rotation: Rotation, m_body: ArrayLike) -> State:
        """State from an attitude (body → reference) and the body angular momentum.

        Parameters
        ----------
        rotation : scipy.spatial.transform.Rotation, shape (...)
            Attitude taking body vectors to the reference frame.
        m_body : array_like, shape (..., 3)
            Angular momentum in body components; broadcasts with ``rotation``.

        Examples
        --------
        >>> from scipy.spatial.transform import Rotation
        >>> s = State.from_attitude(Rotation.from_euler("z", 90, degrees=True), [1.0, 0.0, 0.0])
        >>> [round(float(x), 12) for x in s.m_reference]
        [0.0, 1.0, 0.0]
        """
        return cls(_check_rotation(rotation), m_body)

    @classmethod
    def from_angular_velocity(cls, rotation: Rotation, omega_body: ArrayLike, body: RigidBody) -> State:
        """State from an attitude and the body angular velocity ``ω``: ``m = I ω``.

        Parameters
        ----------
        rotation : scipy.spatial.transform.Rotation, shape (...)
            Attitude taking body vectors to the reference frame.
        omega_body : array_like, shape (..., 3)
            Angular velocity in body components (radians per unit time).
        body : RigidBody

        Examples
        --------
        >>> from scipy.spatial.transform import Rotation
        >>> from andoyer import RigidBody
        >>> s = State.from_angular_velocity(Rotation.identity(), [0, 0, 2.0], RigidBody(1, 1, 2))
        >>> s.m_body.tolist()
        [0.0, 0.0, 4.0]
        """
        body = check_body(body)
        omega = as_vectors(omega_body, "omega_body")
        return cls(_check_rotation(rotation), omega * body.moments)

    # The chart methods, from_<chart> (class methods) and as_<chart>, are written once in each
    # chart's module (andoyer.state.<chart>), which installs them when it registers.

    # -------------------------------------------------------------- properties

    @property
    def quaternion(self) -> Array:
        """Attitude quaternions, scalar last, shape (..., 4) (a copy)."""
        return self._q.copy()

    @property
    def rotation(self) -> Rotation:
        """The attitude as a :class:`scipy.spatial.transform.Rotation` of shape ``self.shape``."""
        return Rotation.from_quat(self._q)

    @property
    def m_body(self) -> Array:
        """Angular momentum in body components, shape (..., 3) (a copy)."""
        return self._m.copy()

    @property
    def m_reference(self) -> Array:
        """Angular momentum in reference components, shape (..., 3)."""
        return quat.rotate(self._q, self._m)

    @property
    def gamma(self) -> Array:
        """The reference axis ``s3`` in body components, ``γ = 𝓡ᵀ s3`` (Pavlov's γ), shape (..., 3).

        It is the third row of ``rotation.as_matrix()`` and the third column of
        Gurfil's ``R`` (eq. 74); ``m_body · γ = H``.

        Examples
        --------
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.6, 1.0, -0.2)
        >>> round(float(s.m_body @ s.gamma), 12)
        -0.2
        """
        return quat.rotate(quat.conjugate(self._q), np.array([0.0, 0.0, 1.0]))

    @property
    def shape(self) -> tuple[int, ...]:
        """Leading shape of the state array."""
        return self._m.shape[:-1]

    @property
    def ndim(self) -> int:
        """Number of leading axes."""
        return len(self.shape)

    @property
    def size(self) -> int:
        """Number of states."""
        return int(np.prod(self.shape, dtype=int))

    def omega(self, body: RigidBody) -> Array:
        """Body angular velocity ``ω = I⁻¹ m``, shape (..., 3).

        Examples
        --------
        >>> from andoyer import RigidBody
        >>> State.from_quaternion([0, 0, 0, 1], [1.0, 2.0, 3.0]).omega(RigidBody(1, 2, 3)).tolist()
        [1.0, 1.0, 1.0]
        """
        return self._m / check_body(body).moments

    def energy(self, body: RigidBody) -> Array:
        """Kinetic energy ``½ m·I⁻¹m``, shape (...).

        Examples
        --------
        >>> from andoyer import RigidBody
        >>> float(State.from_quaternion([0, 0, 0, 1], [1.0, 2.0, 3.0]).energy(RigidBody(1, 2, 3)))
        3.0
        """
        return check_body(body).energy(self._m)

    # --------------------------------------------------------- array protocol
    def __len__(self) -> int:
        if not self.shape:
            msg = "expected a state array with at least one axis for len(), got a single state"
            raise TypeError(msg)
        return self.shape[0]

    def __getitem__(self, index: Any) -> State:
        """Index or slice the leading axes, like a numpy array."""
        q = self._q[..., 0][index]  # validates the index against the leading shape
        del q
        # The quaternions are unit already: normalising them again could move their last bit.
        items = (*np.index_exp[index], slice(None))
        return State.from_unit_quaternion(np.array(self._q[items]), np.array(self._m[items]))

    def reshape(self, *shape: int) -> State:
        """The same states with a new leading shape.

        Examples
        --------
        >>> State.from_quaternion([0, 0, 0, 1], [[0, 0, 1]] * 6).reshape(2, 3).shape
        (2, 3)
        """
        new = shape[0] if len(shape) == 1 and isinstance(shape[0], tuple) else shape
        try:
            return State(self._q.reshape(*new, 4), self._m.reshape(*new, 3))
        except (TypeError, ValueError) as exc:
            msg = f"expected a shape with {self.size} states in all, got {new!r}"
            raise ValueError(msg) from exc

    def __repr__(self) -> str:
        if self.shape:
            return f"State(shape={self.shape})"
        return f"State(quaternion={self._q.tolist()}, m_body={self._m.tolist()})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (State, (self._q, self._m))

    @staticmethod
    def _describe(value: Any) -> str:
        return describe(value)



def check_body(body: Any) -> RigidBody:
    """Return ``body`` if it is a :class:`~andoyer.RigidBody`, else raise ``ValueError``.

    Examples
    --------
    >>> check_body(None)
    Traceback (most recent call last):
    ...
    ValueError: expected an andoyer.RigidBody, got NoneType
    """
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    return body


def free_flow(body: RigidBody, state: State, dt: ArrayLike) -> State:
    """The states reached by the free flow after ``dt`` (``FreeRotation.propagate`` without the wrapper).

    The time-dependent charts (the modified Andoyer set) carry a state along the free motion.

    Parameters
    ----------
    body : RigidBody
        The body.
    state : State, shape (...)
        The states at the start.
    dt : array_like, shape (...)
        The times of flight; broadcast with the state's shape.

    Returns
    -------
    State
        The states after ``dt``.

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> from andoyer.state.hub import free_flow
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    >>> round(float(free_flow(RigidBody(1.0, 2.0, 3.0), s, 1.5).as_andoyer().G), 12)
    1.0
    """
    # A downward import, made on first use so that a State costs no numba/theta-series start-up
    # until a time-dependent chart is read (andoyer.free.motion loads numba).
    from andoyer.free.motion import FreeMotion

    m, q = FreeMotion(body.moments, state.m_body, state.quaternion).propagate(dt)
    return type(state).from_quaternion(q, m)


# ------------------------------------------------------------------ the hub's dynamics


def state_hamiltonian(body: RigidBody, m_body: ArrayLike) -> Array:
    """``½ m·I⁻¹m`` for body angular momenta (..., 3); shape (...) (Gurfil eq. 38).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> float(state_hamiltonian(RigidBody(1.0, 2.0, 2.5), [1.0, 2.0, 5.0]))
    6.5
    """
    return body.energy(m_body)


def euler_poinsot(body: RigidBody, m_body: ArrayLike, torque: ArrayLike | None = None) -> Array:
    """``dm/dt`` of the body angular momentum (Gurfil eqs. 12, 14 in momentum form).

    ``dm_i/dt = c_i m_j m_k + u_i`` with ``c = body.euler_coefficients``.

    Parameters
    ----------
    body : RigidBody
    m_body : array_like, shape (..., 3)
        Body angular momentum.
    torque : array_like, shape (..., 3), optional
        External torque ``u`` in body components (the forced eq. 14).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> euler_poinsot(RigidBody(1.0, 2.0, 2.5), [1.0, 1.0, 1.0]).tolist()
    [-0.1, 0.6, -0.5]
    """
    m = as_vectors(m_body, "m_body")
    c = body.euler_coefficients
    rate = np.stack(
        [c[0] * m[..., 1] * m[..., 2], c[1] * m[..., 2] * m[..., 0], c[2] * m[..., 0] * m[..., 1]], axis=-1
    )
    if torque is not None:
        rate = rate + as_vectors(torque, "torque")
    return rate


def euler_poinsot_omega(body: RigidBody, omega: ArrayLike, torque: ArrayLike | None = None) -> Array:
    """``dω/dt`` from ``I dω/dt + ω × Iω = u`` (Gurfil eqs. 12, 14).

    ``dω_1/dt = ((I2 - I3) ω2 ω3 + u1)/I1`` and cyclic.

    Parameters
    ----------
    body : RigidBody
    omega : array_like, shape (..., 3)
        Body angular velocity.
    torque : array_like, shape (..., 3), optional
        External torque in body components.

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> euler_poinsot_omega(RigidBody(1.0, 2.0, 2.5), [1.0, 1.0, 1.0]).tolist()
    [-0.5, 0.75, -0.4]
    """
    w = as_vectors(omega, "omega")
    I1, I2, I3 = body.moments
    rate = np.stack(
        [
            (I2 - I3) * w[..., 1] * w[..., 2] / I1,
            (I3 - I1) * w[..., 2] * w[..., 0] / I2,
            (I1 - I2) * w[..., 0] * w[..., 1] / I3,
        ],
        axis=-1,
    )
    if torque is not None:
        rate = rate + as_vectors(torque, "torque") / body.moments
    return rate


def lie_poisson(m_body: ArrayLike, grad_hamiltonian: ArrayLike) -> Array:
    """Lie–Poisson equations ``dm/dt = {m, K} = m × ∇K`` for any Hamiltonian ``K(m)`` (eqs. 34–36).

    Parameters
    ----------
    m_body : array_like, shape (..., 3)
    grad_hamiltonian : array_like, shape (..., 3)
        ``∂K/∂m`` at ``m_body`` (for the free body, the angular velocity).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> lie_poisson([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).tolist()
    [0.0, 1.0, 0.0]
    """
    m = as_vectors(m_body, "m_body")
    grad = as_vectors(grad_hamiltonian, "grad_hamiltonian")
    return quat.cross(m, grad)


def attitude_rate(quaternion: ArrayLike, omega_body: ArrayLike) -> Array:
    """``dq/dt = ½ q ⊗ (ω, 0)`` for attitude quaternions (body → reference), scalar last.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
    omega_body : array_like, shape (..., 3)
        Angular velocity in body components.

    Returns
    -------
    numpy.ndarray, shape (..., 4)

    Examples
    --------
    >>> attitude_rate([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 2.0]).tolist()
    [0.0, 0.0, 1.0, 0.0]
    """
    q = as_vectors(quaternion, "quaternion", 4)
    w = as_vectors(omega_body, "omega_body")
    w4 = np.concatenate([w, np.zeros((*w.shape[:-1], 1))], axis=-1)
    return 0.5 * quat.multiply(*np.broadcast_arrays(q, w4))


# ------------------------------------------------------------------ the hub's chart


def _hub_arrays(columns: tuple[Any, ...]) -> tuple[Array, Array]:
    """The quaternions (..., 4) and momenta (..., 3) of the seven hub columns, broadcast."""
    values = np.broadcast_arrays(*(np.asarray(c, dtype=np.float64) for c in columns))
    return np.stack(values[:4], -1), np.stack(values[4:], -1)


def _hub_from(cls: type[State], qx: Any, qy: Any, qz: Any, qw: Any, m1: Any, m2: Any, m3: Any) -> State:
    return cls.from_quaternion(np.stack([qx, qy, qz, qw], -1), np.stack([m1, m2, m3], -1))


def _hub_as(self: State) -> Hub:
    return Hub(*np.moveaxis(self.quaternion, -1, 0), *np.moveaxis(self.m_body, -1, 0))


def _hub_hamiltonian(body: RigidBody, qx: Any, qy: Any, qz: Any, qw: Any, m1: Any, m2: Any, m3: Any) -> Array:
    """``½ m·I⁻¹m`` of the hub's columns (the attitude does not enter)."""
    return state_hamiltonian(check_body(body), _hub_arrays((qx, qy, qz, qw, m1, m2, m3))[1])


def _hub_equations(body: RigidBody, qx: Any, qy: Any, qz: Any, qw: Any, m1: Any, m2: Any, m3: Any) -> Hub:
    """``dq/dt = ½ q ⊗ (I⁻¹m, 0)`` and ``dm/dt`` (Euler–Poinsot) of the hub's columns."""
    body = check_body(body)
    q, m = _hub_arrays((qx, qy, qz, qw, m1, m2, m3))
    rates = np.concatenate([attitude_rate(q, m / body.moments), euler_poinsot(body, m)], axis=-1)
    return Hub(*np.moveaxis(rates, -1, 0))


register(
    Chart(
        "state",
        Hub._fields,
        (),
        "the hub: attitude quaternion (scalar last) and body angular momentum",
        _hub_from,
        _hub_as,
        method=False,
        source="andoyer.state.hub",
        hamiltonian=_hub_hamiltonian,
        equations=_hub_equations,
    )
)
