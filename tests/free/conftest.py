"""Fixtures of the free-solution tests: the backends, and the Taylor reference computed once per case.

``free_backend`` runs a test on every available backend (``compiled`` with numba, ``numpy``,
``scalar``) as a :class:`free_backends.Backend`: for tests of the flow ``(m(t), q(t))`` only,
the one thing the scalar backend computes, on states off the separatrix (which the scalar
kernel refuses), in the units where its squares neither overflow nor underflow, and near
the separatrix over short steps only (``Backend.times``); see ``free_backends.py``.

``motion_backend`` runs a test on every available backend of :class:`andoyer.free.FreeMotion`
(``compiled`` with numba, ``numpy``), as its name, for ``FreeMotion(..., backend=...)``: for
tests of what only ``FreeMotion`` offers (periods, regime, the separatrix, layouts, extreme
units, the periodic representation).

A test that applies to only some backends parametrises the fixture itself
(``indirect=["free_backend"]``, e.g. with :func:`free_backends.pairs`).
"""

from __future__ import annotations

import pytest
from free_backends import AVAILABLE, MOTION, Backend
from free_cases import cases
from free_reference import TaylorReference


@pytest.fixture(scope="session", params=AVAILABLE)
def free_backend(request) -> Backend:
    """Every available backend of the free solution (the flow only; see the module docstring)."""
    return Backend(request.param)


@pytest.fixture(scope="session", params=MOTION)
def motion_backend(request) -> str:
    """Every available backend of ``FreeMotion``, by name."""
    return request.param


class _References:
    """The Taylor reference of the cases of ``free_cases.py``, integrated once per case and time.

    ``reference(name, k)`` is ``(m, q)`` at ``k`` time units of case ``name`` (mpmath lists);
    negative ``k`` by time reversal, ``m(−t) = −n(t)``, ``q(−t) = p(t)`` where ``(n, p)``
    start from ``(−m₀, q₀)``.
    """

    def __init__(self) -> None:
        self.cases = {c[0]: c for c in cases()}
        self.runs: dict = {}
        self.done: dict = {}

    def __call__(self, name: str, k: float):
        if (name, k) not in self.done:
            _, moments, m0, q0, t_unit = self.cases[name]
            sign = -1.0 if k < 0 else 1.0
            reached, run = self.runs.get((name, sign), (None, None))
            if run is None or reached > abs(k):  # the integration only goes forward
                run = TaylorReference(moments, [sign * x for x in m0], q0)
            m, q = run.advance_to(abs(k) * t_unit)
            self.runs[name, sign] = (abs(k), run)
            self.done[name, k] = ([sign * x for x in m], q)
        return self.done[name, k]


@pytest.fixture(scope="session")
def reference() -> _References:
    """``reference(name, k)``: the 57-digit solution of case ``name`` at ``k`` of its time units."""
    return _References()
