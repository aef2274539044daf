"""The exact torque-free rotation of a body, on :class:`~andoyer.State` arrays.

:class:`FreeRotation` joins two layers below it: the state package (:mod:`andoyer.state`)
and the exact solution on arrays (:mod:`andoyer.free`: moments, momenta and quaternions in,
arrays out), which knows nothing of ``State``. ``andoyer.FreeRotation`` is this class.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.body import RigidBody
from andoyer.free.backends import resolve
from andoyer.free.motion import FreeMotion, FreePeriods
from andoyer.regime import regime_names
from andoyer.state import State
from andoyer.state.hub import check_body

__all__ = ["FreeRotation"]


class FreeRotation:
    """Closed-form torque-free motion of ``body``: every regime, vectorised, exact.

    SAM and LAM rotation of a triaxial body (Jacobi elliptic functions through
    theta series, the attitude about the fixed angular momentum through the
    incomplete integral of the third kind), the separatrix (hyperbolic limit),
    axisymmetric bodies (regular precession), the sphere and rest; see
    :mod:`andoyer.free.motion`. The phase is reduced modulo the period and
    carried in double-double arithmetic, so the accuracy does not degrade with
    the number of periods.

    Parameters
    ----------
    body : RigidBody
    backend : {"compiled", "numpy"}, optional
        The implementation (:mod:`andoyer.free.backends`); default the fastest available.

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import RigidBody, State
    >>> free = FreeRotation(RigidBody(1.0, 2.0, 3.0))
    >>> s = State.from_quaternion([0, 0, 0, 1.0], [0.3, 0.2, 1.0])
    >>> T = float(free.periods(s).period)
    >>> free.propagate(s, [0.0, T]).m_body.round(12).tolist()
    [[0.3, 0.2, 1.0], [0.3, 0.2, 1.0]]
    >>> str(free.regime(s))
    'SAM'
    """

    def __init__(self, body: RigidBody, backend: str | None = None) -> None:
        self.body = check_body(body)
        self.backend = resolve(backend)

    def _motion(self, state: State) -> FreeMotion:
        if not isinstance(state, State):
            msg = f"expected an andoyer State, got {type(state).__name__}"
            raise ValueError(msg)
        return FreeMotion(self.body.moments, state.m_body, state.quaternion, backend=self.backend)

    def propagate(self, state: State, t: ArrayLike) -> State:
        """The states reached after times ``t`` (shape (T...)), broadcast with ``state`` (S...).

        Parameters
        ----------
        state : State, shape (S...)
        t : array_like, shape (T...)
            Times since ``state``, positive or negative.

        Returns
        -------
        State, shape broadcast(S..., T...)

        Raises
        ------
        ValueError
            For times that do not broadcast with the states, or whose phase ``|ω t|``
            (``ω = |m|/min(I)``) reaches ``2⁵²`` rad: no digit of it is left.

        Warns
        -----
        PhasePrecisionWarning
            Once fewer than six digits of the phase are left (``|ω t| > 4.5·10⁹`` rad).
        """
        m, q = self._motion(state).propagate(t)
        return State.from_quaternion(q, m)

    def momentum(self, state: State, t: ArrayLike) -> NDArray[np.float64]:
        """Body angular momentum only (cheaper than :meth:`propagate`), shape broadcast(S..., T...) + (3,)."""
        return FreeMotion(self.body.moments, state.m_body, backend=self.backend).momentum(t)

    def regime(self, state: State) -> NDArray[np.str_]:
        """Regime names, shape (S...): SAM, LAM, SEPARATRIX, AXISYMMETRIC, SPHERE or REST."""
        return regime_names(self._motion(state).regime)

    def periods(self, state: State) -> FreePeriods:
        """Period of ``m(t)``, precession of the attitude per period and its mean rate, shape (S...)."""
        return self._motion(state).periods
