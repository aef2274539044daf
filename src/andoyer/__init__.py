"""andoyer: rigid-body rotation in canonical variables.

The Serret–Andoyer formalism as working software: a rigid body
(:class:`RigidBody`), one physical rotation state (:class:`State`) with
converters to every canonical chart (Euler angles and momenta, Andoyer
variables, ...), the free-body Hamiltonians and equations of motion.

The subpackages and names below load when first used (PEP 562 module
``__getattr__``), so ``import andoyer`` costs little more than Python itself
and a command pays only for what it uses.

Examples
--------
>>> import andoyer
>>> earth = andoyer.bodies.get("earth")
>>> state = andoyer.State.from_andoyer(l=0.1, g=0.2, h=0.3, L=0.99, G=1.0, H=0.9)
>>> round(float(state.energy(earth)), 12)
0.500032721584
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from andoyer import _moved

# Old module paths (``andoyer.orbits`` -> ``andoyer.planetary.orbits``, ...) import the moved
# modules with a DeprecationWarning for one release.
_moved.install()

if TYPE_CHECKING:  # the eager names, for type checkers and IDEs
    from andoyer import (
        bodies,
        catalogue,
        free,
        integrate,
        liepoisson,
        perturbations,
        planetary,
        series,
        special,
        state,
        theories,
    )
    from andoyer._limits import PhasePrecisionWarning
    from andoyer.body import NonPhysicalInertiaWarning, RigidBody, Symmetry
    from andoyer.free_rotation import FreeRotation
    from andoyer.integrate.propagation import propagate
    from andoyer.regime import Regime
    from andoyer.state import SingularChartWarning, State

#: Public name -> the module that defines it (a subpackage maps to itself).
_LAZY = {
    "FreeRotation": "andoyer.free_rotation",
    "NonPhysicalInertiaWarning": "andoyer.body",
    "PhasePrecisionWarning": "andoyer._limits",
    "Regime": "andoyer.regime",
    "RigidBody": "andoyer.body",
    "SingularChartWarning": "andoyer.state",
    "State": "andoyer.state",
    "Symmetry": "andoyer.body",
    "propagate": "andoyer.integrate.propagation",
    **{
        name: f"andoyer.{name}"
        for name in (
            "bodies",
            "catalogue",
            "free",
            "integrate",
            "liepoisson",
            "perturbations",
            "planetary",
            "series",
            "special",
            "state",
            "theories",
        )
    },
}

__all__ = [
    "FreeRotation",
    "NonPhysicalInertiaWarning",
    "PhasePrecisionWarning",
    "Regime",
    "RigidBody",
    "SingularChartWarning",
    "State",
    "Symmetry",
    "bodies",
    "catalogue",
    "free",
    "integrate",
    "liepoisson",
    "perturbations",
    "planetary",
    "propagate",
    "series",
    "special",
    "state",
    "theories",
]

__version__ = "0.1.0.dev0"


#: Deprecated public names -> the module that serves them (with a DeprecationWarning, each time).
_DEPRECATED = {"RotationMode": "andoyer.body"}


def __getattr__(name: str) -> Any:
    if _moved.new_name(f"andoyer.{name}") is not None:  # a moved subpackage, by its old name
        return importlib.import_module(f"andoyer.{name}")
    if name in _DEPRECATED:
        return getattr(importlib.import_module(_DEPRECATED[name]), name)
    module_name = _LAZY.get(name)
    if module_name is None:
        msg = f"module 'andoyer' has no attribute {name!r}"
        raise AttributeError(msg)
    module = importlib.import_module(module_name)
    value = module if module_name == f"andoyer.{name}" else getattr(module, name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
