"""Exact torque-free motion of a rigid body, vectorised over states and epochs.

Array-level kernels: moments ``I`` (..., 3), body angular momentum ``m0`` (..., 3),
attitude quaternions ``q0`` (..., 4, scalar last, body → reference) and times ``t``
broadcast together.  Every regime is covered: short- and long-axis modes of a triaxial
body (Jacobi elliptic functions via theta series), the separatrix, axisymmetric bodies,
spheres, steady spins and rest.  See :mod:`andoyer.free.motion`.
"""

from andoyer.free.motion import FreeMotion, FreePeriods, attitude, momentum, periods, propagate
from andoyer.free.regime import Regime, classify
from andoyer.free.rotation import FreeRotation

__all__ = [
    "FreeMotion",
    "FreePeriods",
    "FreeRotation",
    "Regime",
    "attitude",
    "classify",
    "momentum",
    "periods",
    "propagate",
]
