"""The planetary layer: spin axes, orbits, precession, nutation and Cassini states of real bodies.

One package over the core (:class:`~andoyer.RigidBody`, :class:`~andoyer.State`, the
disturbing terms of :mod:`andoyer.perturbations` and the propagators of
:mod:`andoyer.integrate`), which never imports it:

* :mod:`andoyer.planetary.orbits` -- orbit histories (VCW 2011 ecliptic, N-body, secular,
  tables), the protocol :class:`~andoyer.planetary.orbits.OrbitHistory`;
* :mod:`andoyer.planetary.precession` -- the luni-solar precession rate of a planet;
* :mod:`andoyer.planetary.precession_constant` -- the precession constant of any body, its
  satellites' share included;
* :mod:`andoyer.planetary.spin_axis` -- the spin axis along a moving orbit: obliquity,
  general and climatic precession, insolation;
* :mod:`andoyer.planetary.migration` -- a satellite's power-law migration driving its planet's
  precession constant (resonance capture or crossing);
* :mod:`andoyer.planetary.nutation` -- the rigid-Earth luni-solar nutation;
* :mod:`andoyer.planetary.cassini` -- Cassini states (Colombo's top);
* :mod:`andoyer.planetary.parameters` -- the range of every physical parameter, checked alike by
  the API and the command line;
* :mod:`andoyer.planetary.tides` -- the Earth–Moon tidal evolution (lunar distance, day length,
  precession constant, obliquity) back to the Archean.

The subpackages load when first used. Their old places (``andoyer.orbits``, ``andoyer.cassini``,
...) keep working for one release, with a :class:`DeprecationWarning`.

Examples
--------
>>> from andoyer import planetary
>>> planetary.orbits.orbit_history("secular", body="earth").has_eccentricity
True
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = [
    "cassini",
    "migration",
    "nutation",
    "orbits",
    "parameters",
    "precession",
    "precession_constant",
    "spin_axis",
    "tides",
]


def __getattr__(name: str) -> Any:
    if name not in __all__:
        msg = f"module 'andoyer.planetary' has no attribute {name!r}"
        raise AttributeError(msg)
    module = importlib.import_module(f"andoyer.planetary.{name}")
    globals()[name] = module
    return module


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
