"""andoyer: rigid-body rotation in canonical variables.

The Serret–Andoyer formalism as working software: a rigid body
(:class:`RigidBody`), one physical rotation state (:class:`State`) with
converters to every canonical chart (Euler angles and momenta, Andoyer
variables, ...), the free-body Hamiltonians and equations of motion.

Examples
--------
>>> import andoyer
>>> earth = andoyer.bodies.get("earth")
>>> state = andoyer.State.from_andoyer(l=0.1, g=0.2, h=0.3, L=0.99, G=1.0, H=0.9)
>>> round(float(state.energy(earth)), 12)
0.500032721584
"""

from andoyer import bodies, charts, free, integrate, liepoisson, perturbations, series, special, theories
from andoyer._limits import PhasePrecisionWarning
from andoyer.body import RigidBody, RotationMode, Symmetry
from andoyer.charts import SingularChartWarning
from andoyer.free import FreeRotation
from andoyer.propagation import propagate
from andoyer.state import State

__all__ = [
    "FreeRotation",
    "PhasePrecisionWarning",
    "RigidBody",
    "RotationMode",
    "SingularChartWarning",
    "State",
    "Symmetry",
    "bodies",
    "charts",
    "free",
    "integrate",
    "liepoisson",
    "perturbations",
    "propagate",
    "series",
    "special",
    "theories",
]

__version__ = "0.1.0.dev0"
