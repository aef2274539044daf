"""The physical rotation state: attitude plus angular momentum, the hub of every chart."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from andoyer import _quaternion as quat
from andoyer._validation import as_vectors, check_magnitude, describe
from andoyer.body import RigidBody
from andoyer.charts.andoyer import Andoyer, andoyer_to_hub, hub_to_andoyer
from andoyer.charts.euler import Euler, euler_to_hub, hub_to_euler
from andoyer.state_charts import check_body, free_flow

__all__ = ["State"]

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
    ``as_*`` methods.

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
    def _of_unit(cls, q: Array, m: Array) -> State:
        """State from unit quaternions (..., 4) and momenta (..., 3) of one leading shape, as built.

        The chart converters normalise the quaternions as ``__init__`` does, so only the
        momenta's finiteness is left to check (``__init__`` names what overflowed).
        """
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

    @classmethod
    def from_euler(
        cls,
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

        Examples
        --------
        >>> s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
        >>> [round(float(x), 12) for x in s.as_euler()]
        [0.1, 0.5, 0.2, 1.0, 0.3, 0.8]
        """
        return cls._of_unit(*euler_to_hub(phi, theta, psi, Phi, Theta, Psi, stacklevel=2, unit=True))

    @classmethod
    def from_andoyer(
        cls,
        l: ArrayLike,
        g: ArrayLike,
        h: ArrayLike,
        L: ArrayLike,
        G: ArrayLike,
        H: ArrayLike,
    ) -> State:
        r"""State from Andoyer variables (Gurfil §3.2).

        The attitude is ``Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)`` with ``cos I = H/G``,
        ``cos J = L/G``, and ``m_body = (√(G²-L²) sin l, √(G²-L²) cos l, L)``.

        Parameters
        ----------
        l, g, h : array_like, shape (...)
            Andoyer angles in radians.
        L, G, H : array_like, shape (...)
            Momenta with ``G > 0``, ``|L| <= G``, ``|H| <= G``. All six broadcast.

        Examples
        --------
        >>> s = State.from_andoyer(0.0, 0.0, 0.0, [0.5, 1.0], 1.0, 1.0)
        >>> s.shape
        (2,)
        """
        return cls._of_unit(*andoyer_to_hub(l, g, h, L, G, H, unit=True))

    # -------------------------------------------------------------- converters
    def as_euler(self) -> Euler:
        """Euler 3-1-3 angles and conjugate momenta ``(phi, theta, psi, Phi, Theta, Psi)``.

        At ``sin θ = 0`` the convention is ``ψ = 0`` with a
        :class:`~andoyer.charts.SingularChartWarning`.

        Examples
        --------
        >>> s = State.from_euler(1.0, 2.0, 3.0, 0.1, 0.2, 0.3)
        >>> round(float(s.as_euler().Theta), 12)
        0.2
        """
        return hub_to_euler(self._q, self._m, stacklevel=2)

    def as_andoyer(self) -> Andoyer:
        """Andoyer variables ``(l, g, h, L, G, H)``; angles in ``[0, 2π)``.

        At ``sin J = 0`` (``l = 0``) and ``sin I = 0`` (``h = 0``) a
        :class:`~andoyer.charts.SingularChartWarning` is issued. A state with
        zero angular momentum has no Andoyer chart and raises ``ValueError``.

        Examples
        --------
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.6, 1.0, -0.2)
        >>> round(float(s.as_andoyer().g), 12)
        0.4
        """
        return hub_to_andoyer(self._q, self._m, stacklevel=2)

    # ------------------------------------------ the charts that need the body

    @classmethod
    def from_sadov(
        cls,
        body: RigidBody,
        phi_l: ArrayLike,
        phi_g: ArrayLike,
        phi_h: ArrayLike,
        I_l: ArrayLike,
        I_g: ArrayLike,
        I_h: ArrayLike,
    ) -> State:
        """State from Sadov's action–angle variables (Gurfil §5); see :mod:`andoyer.charts.sadov`.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
        >>> back = State.from_sadov(body, *s.as_sadov(body))
        >>> bool(abs(back.m_body - s.m_body).max() < 1e-13)
        True
        """
        from andoyer.charts.sadov import sadov_to_andoyer

        return cls.from_andoyer(*sadov_to_andoyer(check_body(body), phi_l, phi_g, phi_h, I_l, I_g, I_h))

    def as_sadov(self, body: RigidBody):
        """Sadov's action–angle variables ``(phi_l, phi_g, phi_h, I_l, I_g, I_h)`` of the free body.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
        >>> round(float(s.as_sadov(RigidBody(1.0, 2.0, 3.0)).I_g), 12)
        1.0
        """
        from andoyer.charts.sadov import andoyer_to_sadov

        return andoyer_to_sadov(check_body(body), *self.as_andoyer())

    def as_initial_andoyer(self, body: RigidBody, epoch: ArrayLike, t: ArrayLike = 0.0) -> Andoyer:
        """The modified Andoyer set (Gurfil §4.1): Andoyer variables at ``epoch`` of the free motion.

        The state is taken at time ``t``; the free flow carries it to ``epoch``.
        ``(l0, g0, h, L0, G, H)`` are constants of the free motion.

        Examples
        --------
        >>> from andoyer import FreeRotation, RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
        >>> later = FreeRotation(body).propagate(s, 2.5)
        >>> a, b = s.as_initial_andoyer(body, 0.0), later.as_initial_andoyer(body, 0.0, t=2.5)
        >>> bool(max(abs(x - y) for x, y in zip(a, b)) < 1e-12)
        True
        """
        dt = np.asarray(epoch, dtype=float) - np.asarray(t, dtype=float)
        return free_flow(check_body(body), self, dt).as_andoyer()

    @classmethod
    def from_initial_andoyer(
        cls,
        body: RigidBody,
        l0: ArrayLike,
        g0: ArrayLike,
        h: ArrayLike,
        L0: ArrayLike,
        G: ArrayLike,
        H: ArrayLike,
        epoch: ArrayLike,
        t: ArrayLike = 0.0,
    ) -> State:
        """State at time ``t`` of the free motion whose Andoyer variables at ``epoch`` are given.

        The inverse of :meth:`as_initial_andoyer` (Gurfil §4.1's modified Andoyer set
        ``(l0, g0, h, L0, G, H)``): the free flow carries ``from_andoyer(l0, …, H)`` from
        ``epoch`` to ``t``. All arguments broadcast.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_initial_andoyer(body, 0.3, 0.4, 0.5, 0.9, 1.0, 0.2, epoch=1.0, t=2.5)
        >>> a = s.as_initial_andoyer(body, 1.0, t=2.5)
        >>> [round(float(x), 12) for x in a]
        [0.3, 0.4, 0.5, 0.9, 1.0, 0.2]
        """
        dt = np.asarray(t, dtype=float) - np.asarray(epoch, dtype=float)
        return free_flow(check_body(body), cls.from_andoyer(l0, g0, h, L0, G, H), dt)

    def as_serret(self, body: RigidBody, t: ArrayLike = 0.0, *, epoch: ArrayLike | None = None):
        r"""Serret's elements ``(g0, h, t0, G, H, T, sign)`` of the state taken at time ``t``.

        ``(g0, h, -t0)`` are conjugate to ``(G, H, T)``, ``T`` the kinetic energy; ``t0`` is
        the last passage at or before ``epoch`` (default ``t``) of the body momentum through the
        reference point ``φ_ℓ = 0`` of its polhode, ``t - t0 ≡ φ_ℓ/ω_ℓ (mod P_ℓ)``, and ``g0``
        is ``g`` at ``t0``. See :mod:`andoyer.charts.serret` for the definitions and the
        states where the chart is undefined (``ValueError``).

        Examples
        --------
        >>> from andoyer import FreeRotation, RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
        >>> later = FreeRotation(body).propagate(s, 7.0)
        >>> a, b = s.as_serret(body), later.as_serret(body, t=7.0, epoch=0.0)
        >>> bool(max(abs(x - y) for x, y in zip(a, b)) < 1e-12)
        True
        """
        from andoyer.charts.andoyer import hub_to_andoyer
        from andoyer.charts.serret import andoyer_to_serret

        a = hub_to_andoyer(self._q, self._m, stacklevel=2)
        return andoyer_to_serret(check_body(body), *a, t=t, epoch=epoch, stacklevel=3)

    @classmethod
    def from_serret(
        cls,
        body: RigidBody,
        g0: ArrayLike,
        h: ArrayLike,
        t0: ArrayLike,
        G: ArrayLike,
        H: ArrayLike,
        T: ArrayLike,
        sign: ArrayLike = 1.0,
        *,
        t: ArrayLike = 0.0,
    ) -> State:
        """State at time ``t`` from Serret's elements; inverse of :meth:`as_serret`.

        ``sign`` (``±1``) picks the orbit among the two with the same ``(G, T)``: the sign
        of ``L`` in circulation, the lobe ``±b_e`` in libration.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
        >>> back = State.from_serret(body, *s.as_serret(body, t=2.0), t=2.0)
        >>> bool(abs(back.m_body - s.m_body).max() < 1e-13)
        True
        """
        from andoyer.charts.serret import serret_to_andoyer

        return cls.from_andoyer(*serret_to_andoyer(check_body(body), g0, h, t0, G, H, T, sign, t))

    def as_sam(self, body: RigidBody, mode: str = "SAM"):
        """Lara's SAM (or LAM) action–angle chart ``(sam_l, sam_g, h, sam_L, sam_G, H, sign)``.

        See :mod:`andoyer.charts.sam` (Lara eqs. 18–25, any axis labelling).

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(1.0, 2.0, 3.0)
        >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.99, 1.0, 0.2)
        >>> back = State.from_sam(*s.as_sam(body), body=body)
        >>> bool(abs(back.m_body - s.m_body).max() < 1e-13)
        True
        """
        from andoyer.charts.sam import hub_to_sam

        return hub_to_sam(self._q, self._m, check_body(body), mode, stacklevel=2)

    @classmethod
    def from_sam(
        cls,
        sam_l: ArrayLike,
        sam_g: ArrayLike,
        h: ArrayLike,
        sam_L: ArrayLike,
        sam_G: ArrayLike,
        H: ArrayLike,
        sign: ArrayLike = 1.0,
        *,
        body: RigidBody,
        mode: str = "SAM",
    ) -> State:
        """State from Lara's SAM (or LAM) action–angle chart; inverse of :meth:`as_sam`."""
        from andoyer.charts.sam import sam_to_hub

        return cls(*sam_to_hub(sam_l, sam_g, h, sam_L, sam_G, H, sign, body=check_body(body), mode=mode))

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
        return State._of_unit(np.array(self._q[items]), np.array(self._m[items]))

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
