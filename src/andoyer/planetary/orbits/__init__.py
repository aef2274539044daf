r"""Orbit histories: how a planet's orbit plane (and ellipse) moves over 10³–10⁷ years.

Every source answers the same small protocol, :class:`OrbitHistory`, vectorised over
the time ``t`` in Julian years TT from J2000 (negative = past):

* ``normal(t)``: the unit normal ``n`` of the orbit plane, shape ``(..., 3)``, in the
  J2000 ecliptic-and-equinox frame (``x`` to the J2000 equinox, ``z`` to the J2000
  ecliptic pole), pointing along the orbital angular momentum;
* ``eccentricity_vector(t)``: ``e`` times the unit vector towards perihelion, shape
  ``(..., 3)``, same frame, or :class:`NotImplementedError` where the source does not
  know the ellipse (``has_eccentricity`` says which);
* ``span``: the interval ``(t_min, t_max)`` of validity; ``check_times`` raises
  :class:`ValueError` outside it.

Sources: :class:`VondrakEcliptic` (the long-term ecliptic of Vondrák, Capitaine &
Wallace 2011, through pyerfa's ``ltpecl``), :class:`NBodyOrbit` (the Sun and the eight
planets integrated with REBOUND, cached), :class:`SecularOrbit` (the long secular model of
the eight planets: nonlinear, with the Jupiter–Saturn second-order terms, 10⁸–10⁹ years),
:class:`LaplaceLagrangeOrbit` (the linear Laplace–Lagrange theory), :class:`TableOrbit`
(CSV tables and the published solutions, :func:`read_solution`: La2004, La2010, ZB18a,
ZB20, ZB23); :func:`orbit_history` picks one by name or path, :func:`planet_orbits` gives every
planet's classical elements of a source (``andoyer orbit``).

Examples
--------
>>> from andoyer.planetary.orbits import VondrakEcliptic, orbit_history
>>> n = VondrakEcliptic().normal(0.0)
>>> [round(float(x), 12) for x in n]
[0.0, 0.0, 1.0]
>>> orbit_history("secular", body="earth").has_eccentricity
True
"""

from andoyer.planetary.orbits.factory import (
    SOLUTION_FORMATS,
    SOURCES,
    orbit_history,
    planet_orbits,
    read_solution,
    solution_format,
    source_span,
)
from andoyer.planetary.orbits.frequencies import fundamental_frequencies, spectral_lines
from andoyer.planetary.orbits.imcce import read_alkhqp
from andoyer.planetary.orbits.laplace_lagrange import LaplaceLagrangeOrbit
from andoyer.planetary.orbits.lyapunov import lyapunov_exponent
from andoyer.planetary.orbits.nbody import NBodyOrbit
from andoyer.planetary.orbits.planets import PLANETS
from andoyer.planetary.orbits.protocol import OrbitHistory, check_times
from andoyer.planetary.orbits.secular import SecularOrbit
from andoyer.planetary.orbits.table import TableOrbit, read_orbit_csv, write_orbit_csv
from andoyer.planetary.orbits.vondrak import VondrakEcliptic

__all__ = [
    "PLANETS",
    "SOLUTION_FORMATS",
    "SOURCES",
    "LaplaceLagrangeOrbit",
    "NBodyOrbit",
    "OrbitHistory",
    "SecularOrbit",
    "TableOrbit",
    "VondrakEcliptic",
    "check_times",
    "fundamental_frequencies",
    "lyapunov_exponent",
    "orbit_history",
    "planet_orbits",
    "read_alkhqp",
    "read_orbit_csv",
    "read_solution",
    "solution_format",
    "source_span",
    "spectral_lines",
    "write_orbit_csv",
]
