r"""Lara's SAM theory evaluated on physical states: the analytic free rotation of a rigid body.

A state is taken through the chain

    state → SAM chart (:mod:`andoyer.state.sam`) → inverse Lie transformation (mean elements
    ``ℓ', g', L', G'``) → ``ℓ' + n_ℓ t``, ``g' + n_g t`` → direct transformation → SAM chart
    → state,

with ``h`` and ``H`` constant.  Truncated at Deprit order ``N`` the result differs from the
exact free motion by ``O(δ^(N+1))`` in the SAM variables over times of order ``1/n_ℓ``, where
``δ = L'/(G'√(1 − β²))`` (``2 sin²(J/2)`` to first order).  ``mode="LAM"`` runs the same theory
about the axis of minimum inertia (Lara §6: ``α* < 0``, ``β → −β*``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.body import RigidBody
from andoyer.regime import Regime
from andoyer.state import State
from andoyer.state.sam import SAM, SAMAxes, _sam_of_hub, sam_axes, sam_to_hub
from andoyer.theories.sam import SAMTheory, sam_theory

__all__ = ["SAMFrequencies", "SAMRotation"]

Array = NDArray[np.float64]


class SAMFrequencies(NamedTuple):
    """Secular frequencies ``n_ℓ = ∂T/∂L'`` and ``n_g = ∂T/∂G'`` (``h`` does not move).

    In the chart's relabelled frame the Andoyer angles then advance on average at
    ``⟨dl/dt⟩ = −n_ℓ`` and ``⟨dg/dt⟩ = n_g + n_ℓ`` (``ν`` turns opposite to ``ℓ``, eq. 18).
    """

    n_l: Array
    n_g: Array


class SAMRotation:
    """Torque-free rotation by Lara's SAM (or LAM) theory of Deprit order ``order``.

    Parameters
    ----------
    body : RigidBody
    order : int
        Deprit order ``N ≥ 1`` (error ``O(δ^(N+1))``).
    mode : {"SAM", "LAM"}
        Rotation about the axis of maximum (SAM) or minimum (LAM) inertia.  States must be in
        that :class:`~andoyer.Regime` (:meth:`~andoyer.RigidBody.regime`; any state of an
        axisymmetric body whose chart exists).

    Attributes
    ----------
    axes : SAMAxes
        The relabelled axes, ``alpha``, ``beta`` and the moment ``I3'`` used by the theory.
    theory : SAMTheory

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(0.5, 0.75, 1.0)
    >>> rotation = SAMRotation(body, order=6)
    >>> state = State.from_andoyer(0.3, 0.2, 0.1, 0.99, 1.0, 0.5)
    >>> later = rotation.propagate(state, [0.0, 10.0])
    >>> later.shape
    (2,)
    >>> bool(np.allclose(later[0].m_body, state.m_body, atol=1e-12))   # direct ∘ inverse
    True
    >>> round(float(later[1].energy(body) - state.energy(body)), 12)
    0.0
    """

    def __init__(self, body: RigidBody, order: int = 6, mode: str = "SAM") -> None:
        self.axes: SAMAxes = sam_axes(body, mode)
        self.body = body
        self.mode = mode
        self.theory: SAMTheory = sam_theory(order)
        self.order = order

    def __repr__(self) -> str:
        return f"SAMRotation({self.body!r}, order={self.order}, mode={self.mode!r})"

    @property
    def _params(self) -> dict[str, float]:
        return {"alpha": self.axes.alpha, "beta": self.axes.beta, "C": self.axes.moments[2]}

    def _sam(self, state: State) -> SAM:
        if not isinstance(state, State):
            msg = f"expected an andoyer State, got {type(state).__name__}"
            raise ValueError(msg)
        m = state.m_body
        regime = self.body.regime(m)
        # the triaxial regimes other than the theory's; the chart refuses a zero momentum itself
        wrong = (regime <= Regime.SEPARATRIX) & (regime != Regime[self.mode])
        if np.any(wrong):
            other = Regime(int(regime[wrong].flat[0])).name
            msg = (
                f"expected states in {self.mode} rotation for mode={self.mode!r}, "
                f"got {int(np.count_nonzero(wrong))} state(s) in {other} rotation"
            )
            raise ValueError(msg)
        sam, _, _ = _sam_of_hub(state.quaternion, m, self.axes)  # conventions at poles: exact
        return sam

    def osculating_elements(self, state: State) -> SAM:
        """The SAM (or LAM) chart of ``state`` in this theory's frame, shape ``state.shape``.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> rotation = SAMRotation(RigidBody(0.5, 0.75, 1.0), order=2)
        >>> round(float(rotation.osculating_elements(State.from_andoyer(0, 0, 0, 1.0, 1.0, 1.0)).sam_L), 12)
        0.0
        """
        return self._sam(state)

    def mean_elements(self, state: State) -> SAM:
        """Mean elements ``(ℓ', g', h, L', G', H, sign)`` by the inverse Lie transformation.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> rotation = SAMRotation(RigidBody(0.5, 0.75, 1.0), order=4)
        >>> mean = rotation.mean_elements(State.from_andoyer(0.3, 0.2, 0.1, 0.99, 1.0, 0.5))
        >>> round(float(mean.sam_L), 6), float(mean.sam_G)
        (0.006775, 1.0)
        """
        sam = self._sam(state)
        new = self.theory.inverse(sam.sam_l, sam.sam_g, sam.sam_L, sam.sam_G, **self._params)
        return SAM(new[0], new[1], sam.h, new[2], new[3], sam.H, sam.sign)

    def delta(self, state: State) -> Array:
        """The small parameter ``δ' = L'/(G'√(1 − β²))`` of ``state`` (mean elements).

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> rotation = SAMRotation(RigidBody(0.5, 0.75, 1.0), order=4)
        >>> round(float(rotation.delta(State.from_andoyer(0.3, 0.2, 0.1, 0.99, 1.0, 0.5))), 6)
        0.007823
        """
        mean = self.mean_elements(state)
        beta = self.axes.beta
        return mean.sam_L / (mean.sam_G * np.sqrt((1 - beta) * (1 + beta)))

    def secular_hamiltonian(self, state: State) -> Array:
        """The averaged Hamiltonian ``T(L', G')`` (eq. 30) at ``state``: the energy to ``O(δ^(N+2))``.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(0.5, 0.75, 1.0)
        >>> state = State.from_andoyer(0.3, 0.2, 0.1, 0.99, 1.0, 0.5)
        >>> T = SAMRotation(body, order=6).secular_hamiltonian(state)
        >>> bool(abs(T - state.energy(body)) < 1e-15)
        True
        """
        mean = self.mean_elements(state)
        return self.theory.secular_hamiltonian(mean.sam_L, mean.sam_G, **self._params)

    def frequencies(self, state: State) -> SAMFrequencies:
        """Secular frequencies ``(n_ℓ, n_g)`` at ``state``.

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(0.5, 0.75, 1.0)
        >>> n = SAMRotation(body, order=4).frequencies(State.from_andoyer(0, 0, 0, 2.0, 2.0, 2.0))
        >>> round(float(n.n_l), 12), float(n.n_g)    # α √(1 − β²) G/C and G/C on the axis
        (1.154700538379, 2.0)
        """
        mean = self.mean_elements(state)
        return SAMFrequencies(*self.theory.frequencies(mean.sam_L, mean.sam_G, **self._params))

    def propagate(self, state: State, t: ArrayLike, t0: float = 0.0) -> State:
        """States at times ``t`` of the free rotation starting from ``state`` at ``t0``.

        Parameters
        ----------
        state : State, shape (S...)
        t : array_like, shape (T...)
            Times; they broadcast with the state's shape.
        t0 : float
            Time of ``state``.

        Returns
        -------
        State, shape broadcast(S..., T...)

        Examples
        --------
        >>> from andoyer import RigidBody, State
        >>> body = RigidBody(0.5, 0.75, 1.0)
        >>> states = State.from_andoyer(0.3, 0.2, 0.1, [0.99, 0.995], 1.0, 0.5)
        >>> SAMRotation(body, order=3).propagate(states[:, None], np.linspace(0, 5, 4)).shape
        (2, 4)
        """
        times = as_finite(t, "t") - float(t0)
        mean = self.mean_elements(state)
        p = self._params
        n_l, n_g = self.theory.frequencies(mean.sam_L, mean.sam_G, **p)
        try:
            shape = np.broadcast_shapes(np.shape(mean.sam_L), times.shape)
        except ValueError as exc:
            msg = (
                f"expected times broadcastable with the state's shape {state.shape}, got shape {times.shape}"
            )
            raise ValueError(msg) from exc
        ell, g, L, G = self.theory.direct(
            mean.sam_l + n_l * times, mean.sam_g + n_g * times, mean.sam_L, mean.sam_G, **p
        )
        h, H, sign = (np.broadcast_to(v, shape) for v in (mean.h, mean.H, mean.sign))
        q, m = sam_to_hub(ell, g, h, L, G, H, sign, body=self.body, mode=self.mode)
        return State(q, m)
