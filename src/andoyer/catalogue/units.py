r"""Unit constants, defined once: angles, time, length and the units a catalogue value may carry.

Every constant is exact by definition (the SI second, the Julian year of 365.25 days, the IAU 2012
astronomical unit) or a defining constant of an IAU system; body numbers (``GM``, radii, orbits)
are not here but in the catalogue (:func:`andoyer.catalogue.get`).

* ``ARCSEC = π/648000`` rad, ``DEGREE = π/180`` rad, ``MAS`` one milliarcsecond.
* ``DAY = 86400`` s; ``JULIAN_YEAR = 365.25 DAY``; ``JULIAN_CENTURY = 36525 DAY``.
* ``AU = 149 597 870 700`` m exactly (IAU 2012 Resolution B2).
* ``SPEED_OF_LIGHT = 299 792 458`` m/s (SI).
* ``GAUSSIAN_GRAVITATIONAL_CONSTANT = 0.01720209895`` (IAU 1976 system; ``k²`` is the Sun's
  ``GM`` in au³/d² of the old system, kept for conversions of historical tables).
* ``J2000_JD = 2451545.0``, the epoch J2000.0 (TT).

:data:`UNITS` maps each unit a catalogue value may be written in to its dimension and its factor
to SI (metres, seconds, radians): ``value_SI = value × factor``.

Examples
--------
>>> from andoyer.catalogue import units
>>> round(units.ARCSEC * 648000 / units.DEGREE / 180, 15)
1.0
>>> units.convert(1.0, "au", "km")
149597870.7
>>> units.convert(360.0, "deg/d", "rad/s") == 2 * units.math.pi / units.DAY
True
"""

from __future__ import annotations

import math

__all__ = [
    "ARCMIN",
    "ARCSEC",
    "AU",
    "AU_KM",
    "DAY",
    "DEGREE",
    "GAUSSIAN_GRAVITATIONAL_CONSTANT",
    "HOUR",
    "J2000_JD",
    "JULIAN_CENTURY",
    "JULIAN_YEAR",
    "MAS",
    "SPEED_OF_LIGHT",
    "UNITS",
    "convert",
    "dimension",
]

#: One degree in radians.
DEGREE = math.pi / 180.0
#: One arcminute in radians.
ARCMIN = math.pi / 10800.0
#: One arcsecond in radians.
ARCSEC = math.pi / 648000.0
#: One milliarcsecond in radians.
MAS = ARCSEC / 1000.0
#: One hour in seconds.
HOUR = 3600.0
#: One day in seconds (86400 SI seconds).
DAY = 86400.0
#: One Julian year (365.25 days) in seconds.
JULIAN_YEAR = 365.25 * DAY
#: One Julian century (36525 days) in seconds.
JULIAN_CENTURY = 36525.0 * DAY
#: The astronomical unit in metres, exact (IAU 2012 Resolution B2).
AU = 149_597_870_700.0
#: The astronomical unit in kilometres.
AU_KM = AU / 1000.0
#: The speed of light in vacuum, m/s (exact, SI).
SPEED_OF_LIGHT = 299_792_458.0
#: Gauss's gravitational constant ``k`` (IAU 1976 system of astronomical constants).
GAUSSIAN_GRAVITATIONAL_CONSTANT = 0.01720209895
#: Julian date of the epoch J2000.0 (2000 January 1, 12h TT).
J2000_JD = 2451545.0

#: Unit -> (dimension, factor to SI). Dimensions: "1" (a pure number), "length", "time",
#: "angle", "angular rate", "angular acceleration", "gm" (m³/s²), "speed".
UNITS: dict[str, tuple[str, float]] = {
    "1": ("1", 1.0),
    "m": ("length", 1.0),
    "km": ("length", 1000.0),
    "au": ("length", AU),
    "s": ("time", 1.0),
    "h": ("time", HOUR),
    "d": ("time", DAY),
    "yr": ("time", JULIAN_YEAR),
    "rad": ("angle", 1.0),
    "deg": ("angle", DEGREE),
    "arcmin": ("angle", ARCMIN),
    "arcsec": ("angle", ARCSEC),
    "mas": ("angle", MAS),
    "rad/s": ("angular rate", 1.0),
    "deg/d": ("angular rate", DEGREE / DAY),
    "deg/yr": ("angular rate", DEGREE / JULIAN_YEAR),
    "deg/cy": ("angular rate", DEGREE / JULIAN_CENTURY),
    "arcsec/yr": ("angular rate", ARCSEC / JULIAN_YEAR),
    "arcsec/cy": ("angular rate", ARCSEC / JULIAN_CENTURY),
    "mas/yr": ("angular rate", MAS / JULIAN_YEAR),
    "deg/d2": ("angular acceleration", DEGREE / DAY**2),
    "m3/s2": ("gm", 1.0),
    "km3/s2": ("gm", 1e9),
    "au3/d2": ("gm", AU**3 / DAY**2),
    "au3/yr2": ("gm", AU**3 / JULIAN_YEAR**2),
    "m/s": ("speed", 1.0),
    "cm/yr": ("speed", 0.01 / JULIAN_YEAR),
    "Gyr": ("time", 1e9 * JULIAN_YEAR),
}


def dimension(unit: str) -> str:
    """The dimension of ``unit`` (a key of :data:`UNITS`), or ``ValueError``.

    Examples
    --------
    >>> dimension("arcsec/yr")
    'angular rate'
    """
    try:
        return UNITS[unit][0]
    except (KeyError, TypeError):
        msg = f"expected a unit among {', '.join(UNITS)}, got {unit!r}"
        raise ValueError(msg) from None


def convert(value: float, unit: str, to: str) -> float:
    """``value`` in ``unit`` expressed in ``to`` (both keys of :data:`UNITS`, one dimension).

    Parameters
    ----------
    value : float
    unit, to : str

    Returns
    -------
    float

    Examples
    --------
    >>> round(convert(1.0, "d", "h"), 12)
    24.0
    >>> convert(1.0, "km", "deg")
    Traceback (most recent call last):
    ...
    ValueError: expected a unit of dimension length, got 'deg' (angle)
    """
    if dimension(unit) != dimension(to):
        msg = f"expected a unit of dimension {dimension(unit)}, got {to!r} ({dimension(to)})"
        raise ValueError(msg)
    if unit == to:
        return float(value)
    return float(value) * UNITS[unit][1] / UNITS[to][1]
