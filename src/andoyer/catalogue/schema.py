r"""The keys of a catalogue entry: what each value means, its dimension, its unit and its bounds.

One table, :data:`FIELDS`, serves the shipped catalogue and the user's body files alike: a value
is accepted when it is a finite number in a unit of the field's dimension and within the field's
bounds; a body is accepted when its moments are ordered (``A ≤ B ≤ C``, ``A + B ≥ C``).

Conventions (radians inside the code, the units below in the files):

* ``j2 = −C20 = (C − (A+B)/2)/MR²`` and ``c22 = (B − A)/4MR²`` are unnormalised and referred to
  ``radius``; ``moment_of_inertia = C/MR²`` to the same ``radius``.
* ``dynamical_ellipticity`` ``H = (C − (A+B)/2)/C``; ``a_over_c``, ``b_over_c`` the principal
  moments over the largest, ``A ≤ B ≤ C``.
* ``pole_ra``, ``pole_dec``, ``prime_meridian``, ``rotation_rate``: the IAU WGCCRE model
  ``α = α₀ + α̇ T``, ``δ = δ₀ + δ̇ T``, ``W = W₀ + Ẇ d`` (``T`` Julian centuries and ``d`` days
  from J2000 TDB), ICRF; a negative ``Ẇ`` is a retrograde rotation. Where the model has periodic
  terms (``Σ a_k sin M_k`` in ``α``, ``Σ b_k cos M_k`` in ``δ``), ``pole_ra_periodic`` and
  ``pole_dec_periodic`` are their sums at J2000 (each entry's note lists the terms): the pole at
  J2000 is ``(pole_ra + pole_ra_periodic, pole_dec + pole_dec_periodic)``.
* ``precession_rate`` ``ψ̇``: the measured rate of the spin axis about the orbit normal
  (luni-solar precession of the equator for the Earth), positive westward.
* orbit: about ``primary``, in ``orbit_frame`` at ``orbit_epoch``; ``node_period`` and
  ``apsis_period`` are the periods of the node's regression and the apsis's advance.

Examples
--------
>>> FIELDS["moment_of_inertia"].describe_bounds()
'in (0, 2/3]'
>>> sorted(FIELDS)[:3]
['a_over_c', 'age', 'apsis_period']
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from andoyer.catalogue.units import UNITS

__all__ = ["FIELDS", "KINDS", "MOMENT_SET_FIELDS", "TEXT_FIELDS", "Field"]


@dataclass(frozen=True)
class Field:
    """One numeric key of an entry.

    Attributes
    ----------
    name : str
    dimension : str
        A dimension of :data:`andoyer.catalogue.units.UNITS`.
    unit : str
        The unit the catalogue prints it in (a value may be written in any unit of the dimension).
    low, high : float
        Bounds (``±inf`` for none).
    low_open, high_open : bool
        Whether the bound itself is excluded.
    group : str
        ``"physical"``, ``"spin"`` or ``"orbit"``.
    description : str
    """

    name: str
    dimension: str
    unit: str
    low: float
    high: float
    low_open: bool
    high_open: bool
    group: str
    description: str

    def contains(self, value: float) -> bool:
        """Whether ``value`` (in :attr:`unit`) lies within the bounds."""
        above = value > self.low if self.low_open else value >= self.low
        below = value < self.high if self.high_open else value <= self.high
        return math.isfinite(value) and above and below

    def describe_bounds(self) -> str:
        """The bounds as words for error messages."""
        if self.name == "moment_of_inertia":
            return "in (0, 2/3]"
        if math.isinf(self.low) and math.isinf(self.high):
            return "finite"
        if math.isinf(self.high):
            return f"{'>' if self.low_open else '>='} {self.low:g}"
        left = "(" if self.low_open else "["
        right = ")" if self.high_open else "]"
        return f"in {left}{self.low:g}, {self.high:g}{right}"


INF = math.inf


def _f(name, dim, unit, low, high, low_open, high_open, group, description) -> Field:
    if UNITS[unit][0] != dim:  # a wrong table is a programming error, caught at import
        raise AssertionError(name)
    return Field(name, dim, unit, low, high, low_open, high_open, group, description)


_TABLE = (
    _f("gm", "gm", "km3/s2", 0, INF, True, True, "physical", "gravitational parameter GM"),
    _f("radius", "length", "km", 0, INF, True, True, "physical", "reference radius R of j2, c22, C/MR²"),
    _f("j2", "1", "1", 0, INF, False, True, "physical", "J2 = -C20, unnormalised, at radius"),
    _f("c22", "1", "1", 0, INF, False, True, "physical", "C22 = (B - A)/4MR², unnormalised"),
    _f("moment_of_inertia", "1", "1", 0, 2 / 3, True, False, "physical", "C/MR², polar moment at radius"),
    _f("dynamical_ellipticity", "1", "1", 0, 0.5, False, True, "physical", "H = (C - (A+B)/2)/C"),
    _f("a_over_c", "1", "1", 0, 1, True, False, "physical", "A/C, smallest principal moment over C"),
    _f("b_over_c", "1", "1", 0, 1, True, False, "physical", "B/C, middle principal moment over C"),
    _f(
        "j0",
        "angle",
        "arcsec",
        0,
        180 * 3600,
        False,
        False,
        "spin",
        "angle J between momentum and figure axis",
    ),
    _f("rotation_period", "time", "d", 0, INF, True, True, "spin", "sidereal rotation period"),
    _f(
        "rotation_rate",
        "angular rate",
        "deg/d",
        -INF,
        INF,
        True,
        True,
        "spin",
        "IAU W-dot (negative: retrograde)",
    ),
    _f(
        "spin_rate",
        "angular rate",
        "rad/s",
        0,
        INF,
        True,
        True,
        "spin",
        "inertial angular velocity omega of the spin (not the IAU W-dot)",
    ),
    _f("prime_meridian", "angle", "deg", -INF, INF, True, True, "spin", "IAU W0 at J2000"),
    _f("pole_ra", "angle", "deg", -INF, INF, True, True, "spin", "IAU pole right ascension alpha0, ICRF"),
    _f("pole_ra_rate", "angular rate", "deg/cy", -INF, INF, True, True, "spin", "IAU alpha0 rate"),
    _f("pole_dec", "angle", "deg", -90, 90, False, False, "spin", "IAU pole declination delta0, ICRF"),
    _f("pole_dec_rate", "angular rate", "deg/cy", -INF, INF, True, True, "spin", "IAU delta0 rate"),
    _f(
        "pole_ra_periodic",
        "angle",
        "deg",
        -INF,
        INF,
        True,
        True,
        "spin",
        "IAU periodic terms of alpha0 summed at J2000 (the J2000 pole is pole_ra + this)",
    ),
    _f(
        "pole_dec_periodic",
        "angle",
        "deg",
        -INF,
        INF,
        True,
        True,
        "spin",
        "IAU periodic terms of delta0 summed at J2000 (the J2000 pole is pole_dec + this)",
    ),
    _f("age", "time", "Gyr", 0, INF, True, True, "physical", "age at J2000 (the Sun: the solar system's)"),
    _f("obliquity", "angle", "deg", 0, 180, False, False, "spin", "obliquity: spin axis to orbit normal"),
    _f(
        "precession_rate",
        "angular rate",
        "arcsec/yr",
        -INF,
        INF,
        True,
        True,
        "spin",
        "measured precession rate of the spin axis",
    ),
    _f("resonance", "1", "1", 0, INF, True, True, "spin", "spin-orbit ratio p = omega/n (1 synchronous)"),
    _f("semi_major_axis", "length", "km", 0, INF, True, True, "orbit", "semi-major axis"),
    _f("eccentricity", "1", "1", 0, 1, False, True, "orbit", "eccentricity"),
    _f(
        "inclination", "angle", "deg", 0, 180, False, False, "orbit", "inclination to the orbit_frame's plane"
    ),
    _f("node", "angle", "deg", -INF, INF, True, True, "orbit", "longitude of the ascending node"),
    _f("periapsis_longitude", "angle", "deg", -INF, INF, True, True, "orbit", "longitude of periapsis"),
    _f("argument_of_periapsis", "angle", "deg", -INF, INF, True, True, "orbit", "argument of periapsis"),
    _f("mean_longitude", "angle", "deg", -INF, INF, True, True, "orbit", "mean longitude at the epoch"),
    _f("mean_anomaly", "angle", "deg", -INF, INF, True, True, "orbit", "mean anomaly at the epoch"),
    _f("orbital_period", "time", "d", 0, INF, True, True, "orbit", "sidereal orbital period"),
    _f("node_period", "time", "yr", 0, INF, True, True, "orbit", "period of the node's regression"),
    _f("apsis_period", "time", "yr", 0, INF, True, True, "orbit", "period of the apsis's advance"),
    _f(
        "migration_rate",
        "speed",
        "cm/yr",
        -INF,
        INF,
        True,
        True,
        "orbit",
        "measured present rate da/dt of the semi-major axis (tidal migration)",
    ),
    _f(
        "laplace_inclination",
        "angle",
        "deg",
        0,
        180,
        False,
        False,
        "orbit",
        "inclination to the Laplace plane (when orbit_frame is another plane)",
    ),
    _f(
        "laplace_pole_ra",
        "angle",
        "deg",
        -INF,
        INF,
        True,
        True,
        "orbit",
        "right ascension of the Laplace-plane pole, ICRF",
    ),
    _f(
        "laplace_pole_dec",
        "angle",
        "deg",
        -90,
        90,
        False,
        False,
        "orbit",
        "declination of the Laplace-plane pole, ICRF",
    ),
    _f(
        "laplace_tilt",
        "angle",
        "deg",
        0,
        180,
        False,
        False,
        "orbit",
        "angle between the primary's equator and the Laplace plane",
    ),
)

#: Every numeric key, in the order the catalogue prints them.
FIELDS: dict[str, Field] = {f.name: f for f in _TABLE}

#: The keys a named moment set (``moment_sets``) may hold.
MOMENT_SET_FIELDS = ("a_over_c", "b_over_c", "j0", "rotation_period")

#: Text keys of an entry (``name`` is required; the others are optional).
TEXT_FIELDS = ("name", "kind", "primary", "orbit_frame", "orbit_epoch", "note")

#: The kinds of body.
KINDS = ("star", "planet", "dwarf planet", "satellite", "asteroid", "user")
