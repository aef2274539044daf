"""The free-body action–angle and element charts of :class:`~andoyer.State`.

Sadov's action–angle variables, the modified Andoyer set, Serret's elements and Lara's
SAM/LAM variables all need the body's moments; :class:`FreeBodyCharts` gathers their paired
``from_*``/``as_*`` converters, which :class:`~andoyer.State` inherits.  Each converter is a
thin wrapper over its chart module in :mod:`andoyer.charts`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from andoyer.body import RigidBody
from andoyer.charts.andoyer import Andoyer

if TYPE_CHECKING:
    from andoyer.state import State

__all__ = ["FreeBodyCharts", "check_body"]


def check_body(body: Any) -> RigidBody:
    """Return ``body`` if it is a :class:`~andoyer.RigidBody`, else raise ``ValueError``."""
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    return body


def _free_flow(body: RigidBody, state: State, dt: ArrayLike) -> State:
    """The states reached by the free flow after ``dt`` (``FreeRotation.propagate`` without the wrapper)."""
    # Imported here so that a State costs no numba/theta-series start-up until a time chart is used.
    from andoyer.free.motion import FreeMotion

    m, q = FreeMotion(body.moments, state.m_body, state.quaternion).propagate(dt)
    return type(state).from_quaternion(q, m)


class FreeBodyCharts:
    """Mixin: the body-dependent charts of the state (Sadov, modified Andoyer, Serret, SAM)."""

    # Provided by State.
    from_andoyer: Any
    as_andoyer: Any

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
        return _free_flow(check_body(body), self, dt).as_andoyer()

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
        return _free_flow(check_body(body), cls.from_andoyer(l0, g0, h, L0, G, H), dt)

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
