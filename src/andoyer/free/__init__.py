"""Exact torque-free motion of a rigid body, vectorised over states and epochs.

Array-level kernels: moments ``I`` (..., 3), body angular momentum ``m0`` (..., 3),
attitude quaternions ``q0`` (..., 4, scalar last, body → reference) and times ``t``
broadcast together.  Every regime is covered: short- and long-axis modes of a triaxial
body (Jacobi elliptic functions via theta series), the separatrix, axisymmetric bodies,
spheres, steady spins and rest.  See :mod:`andoyer.free.motion`.

This package knows nothing of :class:`~andoyer.State` (the state's time-dependent charts use
:class:`FreeMotion`). :class:`~andoyer.FreeRotation`, which works on ``State`` arrays, is in
:mod:`andoyer.free_rotation`, above both; ``andoyer.free.FreeRotation`` still gives it, with a
DeprecationWarning, until the next release.

Layout.  :mod:`~andoyer.free.motion` (:class:`FreeMotion`) routes each state to its regime,
one subpackage each: :mod:`~andoyer.free.triaxial` (SAM and LAM),
:mod:`~andoyer.free.separatrix` and :mod:`~andoyer.free.uniform` (axisymmetric bodies,
spheres, steady spins, rest), on what they share, :mod:`~andoyer.free.common` (the working
frame, the scaling, the phases, the blocks of states × epochs).  One naming rule holds in
every folder, so that a step's name leads to its file on every backend
(:mod:`~andoyer.free.backends`): ``<step>.py`` holds the kernels of the step, each formula
written once (plain arithmetic that runs compiled on floats and on numpy arrays), and
``<step>_compiled.py``, ``<step>_numpy.py`` its drivers on the ``"compiled"`` and
``"numpy"`` backends (``triaxial/setup.py``, ``triaxial/setup_compiled.py``,
``triaxial/setup_numpy.py``).  The ``"scalar"`` backend, one step of one state, is
:mod:`~andoyer.free.step_scalar`.
"""

from __future__ import annotations

import warnings
from typing import Any

from andoyer.free.motion import FreeMotion, FreePeriods, attitude, momentum, periods, propagate
from andoyer.regime import Regime, classify

__all__ = [
    "FreeMotion",
    "FreePeriods",
    "Regime",
    "attitude",
    "classify",
    "momentum",
    "periods",
    "propagate",
]


def __getattr__(name: str) -> Any:
    if name == "FreeRotation":
        # The one upward import of this package, for one release (an exemption listed in
        # tests/core/test_import_graph.py): FreeRotation moved above the state package.
        warnings.warn(
            "andoyer.free.FreeRotation moved to andoyer.free_rotation (andoyer.FreeRotation); "
            "the old name works until the next release",
            DeprecationWarning,
            stacklevel=2,
        )
        from andoyer.free_rotation import FreeRotation

        return FreeRotation
    msg = f"module 'andoyer.free' has no attribute {name!r}"
    raise AttributeError(msg)
