"""The backends of the free solution driven alike by the tests (fixtures in ``tests/conftest.py``).

Three implementations of the torque-free solution (:mod:`andoyer.free.backends`):

* ``"compiled"`` and ``"numpy"``: :class:`andoyer.free.FreeMotion` with that ``backend``;
  every operation (momentum, attitude, periods, regime) in every regime.
* ``"scalar"``: the one-step kernel of :mod:`andoyer.free.step_scalar` (``_step_one``, compiled when
  numba is available), driven here from the initial state to each time ``t`` in one step of
  length ``t``.  It has no set-up, hence no periods and no regime: only the flow ``(m(t),
  q(t))``.  It refuses states within ``10⁻¹²`` of the separatrix (``free_step`` would hand
  them to ``FreeMotion``; this driver raises instead, so that no test of the scalar backend
  passes on ``FreeMotion``'s answer).  It works in the units it is given (no exact scaling by
  powers of two, so momenta whose squares underflow, ``|m| < 1e-154``, are out of its reach).
  Its phases are float64 where ``FreeMotion`` carries them in double-double, so its error
  grows with the step: about ``eps`` per radian of the fastest phase ``ω t``, ``ω = |m|/min I``
  (measured against the Taylor reference over 100 periods of seven SAM and LAM cases and
  ~10 of the Earth: at most ``1.0 eps ω t``; 2.8e-12 rad after 100 periods of ``sam-1``,
  2.7e-12 after 9.7 of ``earth-wobble-0.3``).  So it is checked against the documented
  accuracy only over steps where its bound :meth:`Backend.step_error`, ``4 eps ω t``, stays
  within :data:`PHASE_ERROR_MAX`, and a test that bounds the evaluation error itself adds
  that bound.  Near the separatrix it keeps the accuracy of the others only over
  short steps (at ``1 − k² = 10⁻¹⁰``: 3e-16 over a hundredth of a period, 3.5e-10 over 0.37
  of one): on those cases (:data:`NEAR_SEPARATRIX`) it is checked over :data:`SHORT_STEPS`.
"""

from __future__ import annotations

import numpy as np
import pytest
from free_cases import cases

from andoyer.free import FreeMotion, backends
from andoyer.free import step_scalar as lean

#: The backends that run here, and those of them that FreeMotion offers.
AVAILABLE = backends.available()
MOTION = tuple(name for name in AVAILABLE if name in backends.MOTION_BACKENDS)

#: Cases (``free_cases.py``) close enough to the separatrix that the scalar kernel's float64
#: phase loses digits over long steps, and the steps (in periods) over which it is checked there.
NEAR_SEPARATRIX = frozenset(
    {"near-separatrix-sam-1e-10", "near-separatrix-lam-1e-10", "near-separatrix-sam-1e-6"}
)
SHORT_STEPS = (1e-3, 1e-2)
#: The largest bound of the scalar kernel's phase error (rad) over the steps where it is checked
#: against the documented accuracy (1e-12 rad for the attitude).
PHASE_ERROR_MAX = 1e-12
_EPS = np.finfo(float).eps
_CASES = {c[0]: c for c in cases()}
#: Cases the scalar kernel refuses (on the separatrix): FreeMotion's backends only.
SEPARATRIX = frozenset({"separatrix"})


class Backend:
    """One backend of the free solution: the flow ``(m(t), q(t))`` from initial states.

    Parameters
    ----------
    name : str
        One of :data:`AVAILABLE`.
    """

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return f"Backend({self.name!r})"

    def propagate(self, moments, m0, q0, t):
        """Body angular momentum and attitude at times ``t``, broadcast as :meth:`FreeMotion.propagate`."""
        if self.name != "scalar":
            return FreeMotion(moments, m0, q0, backend=self.name).propagate(t)
        return _scalar(moments, m0, q0, t)

    def momentum(self, moments, m0, t):
        """Body angular momentum only, as :meth:`FreeMotion.momentum`."""
        if self.name != "scalar":
            return FreeMotion(moments, m0, backend=self.name).momentum(t)
        return _scalar(moments, m0, [0.0, 0.0, 0.0, 1.0], t)[0]

    def times(self, name, multiples):
        """The multiples of the time unit at which this backend is checked on case ``name`` (free_cases).

        All of ``multiples``, but for the scalar kernel :data:`SHORT_STEPS` near the separatrix,
        and elsewhere those within its phase-error bound :data:`PHASE_ERROR_MAX`.
        """
        if self.name != "scalar":
            return multiples
        if name in NEAR_SEPARATRIX:
            return SHORT_STEPS
        _, moments, m0, _, t_unit = _CASES[name]
        return tuple(k for k in multiples if self.step_error(moments, m0, k * t_unit) <= PHASE_ERROR_MAX)

    def step_error(self, moments, m0, t):
        """Error (rad, and relative in ``m``) this backend adds over a step ``t`` to ``FreeMotion``'s.

        ``0`` for FreeMotion's backends; ``4 eps ω |t|`` with ``ω = |m₀|/min I`` for the
        scalar kernel (four times the largest measured; see the module docstring).
        """
        if self.name != "scalar":
            return 0.0
        return 4.0 * _EPS * float(np.linalg.norm(m0) / np.min(moments)) * abs(float(t))


def _scalar(moments, m0, q0, t):
    """The scalar kernel from each initial state to its time, in one step."""
    moments, m0 = np.asarray(moments, dtype=float), np.asarray(m0, dtype=float)
    q0, t = np.asarray(q0, dtype=float), np.asarray(t, dtype=float)
    shape = np.broadcast_shapes(moments.shape[:-1], m0.shape[:-1], q0.shape[:-1], t.shape)
    inertia = np.broadcast_to(moments, (*shape, 3)).reshape(-1, 3)
    m_out = np.array(np.broadcast_to(m0, (*shape, 3)).reshape(-1, 3))
    q_out = np.array(np.broadcast_to(q0, (*shape, 4)).reshape(-1, 4))
    q_out /= np.linalg.norm(q_out, axis=-1, keepdims=True)
    steps = np.broadcast_to(t, shape).ravel()
    for k in range(steps.size):
        m, q = m_out[k].copy(), q_out[k].copy()
        if not lean._step_one(inertia[k].copy(), q, m, float(steps[k])):
            msg = f"the scalar kernel refuses the state {m_out[k]} with moments {inertia[k]} (separatrix)"
            raise AssertionError(msg)
        m_out[k], q_out[k] = m, q
    return m_out.reshape(*shape, 3), q_out.reshape(*shape, 4)


def pairs(names):
    """``(case name, backend)`` parameters over every available backend that applies to each case.

    For ``pytest.mark.parametrize(("name", "free_backend"), pairs(...), indirect=["free_backend"])``:
    the scalar backend is left out only on the separatrix, which it refuses.
    """
    return [
        pytest.param(name, backend, id=f"{name}-{backend}")
        for name in names
        for backend in AVAILABLE
        if not (backend == "scalar" and name in SEPARATRIX)
    ]
