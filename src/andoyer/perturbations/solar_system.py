r"""Mean orbits of the Sun and the Moon seen from the Earth and Mars, for the gravity-gradient models.

Reference frame: the mean orbital plane of the torqued planet (its ecliptic of
J2000), ``s3`` its pole, ``s1`` towards the ascending node of the Moon's orbit
at ``t = 0``. Times are seconds. Every number is the catalogue's
(:func:`andoyer.catalogue.get`, where each carries its source):

* gravitational parameters: the Sun's ``GM`` (DE440), the Moon's (Williams et al. 2014),
  the Earth's (IERS 2010) and the Mars system's (DE440);
* the Sun's orbit about the planet: the planet's eccentricity (Standish's J2000 mean elements)
  and sidereal period ``P`` (the Earth's sidereal year, IERS; Mars', the NASA Mars Fact Sheet),
  with the semi-major axis of Kepler's third law for that period,

  .. math:: a = \left(\frac{G(M_\odot + m)}{n^2}\right)^{1/3}, \qquad n = \frac{2\pi}{P},

  so that the torque ``∝ GM☉/a³`` and the mean motion belong to one ellipse (``m``: the
  Earth–Moon system's or the Mars system's mass; ``a`` = 1.00000004 au for the Earth,
  1.523692 au for Mars);
* the Moon's mean orbit (the Astronomical Almanac's): ``a``, ``e``, inclination to the
  ecliptic, sidereal month and nodal regression period;
* obliquities: the Earth's IAU 2006 ``ε₀`` = 84381.406″, Mars' 25.19° (Mars Fact Sheet).

Examples
--------
>>> [p.name for p in mean_perturbers("earth")]
['Sun', 'Moon']
>>> round(float(np.degrees(OBLIQUITY["mars"])), 2)
25.19
>>> round(mean_perturbers("mars")[0].orbit.semi_major_axis / AU, 6)
1.523692
"""

from __future__ import annotations

import numpy as np

from andoyer import catalogue
from andoyer.catalogue.units import AU, DAY, JULIAN_YEAR
from andoyer.perturbations.gravity import PointMass
from andoyer.perturbations.orbits import KeplerOrbit

__all__ = ["AU", "DAY", "GM_MOON", "GM_SUN", "JULIAN_YEAR", "OBLIQUITY", "mean_perturbers"]

_SUN, _EARTH, _MOON, _MARS = (catalogue.get(name) for name in ("sun", "earth", "moon", "mars"))

#: ``GM`` of the Sun and of the Moon, m³/s² (the catalogue's).
GM_SUN = _SUN.gm.si()
GM_MOON = _MOON.gm.si()

OBLIQUITY = {"earth": _EARTH.obliquity.si(), "mars": _MARS.obliquity.si()}


def _sun_seen_from(planet: catalogue.Body, system_gm: float) -> KeplerOrbit:
    """The Sun's mean orbit about ``planet``: its eccentricity and period, Kepler's ``a``."""
    n = 2 * np.pi / planet.require("orbital_period", "the Sun's mean orbit").si()
    a = ((GM_SUN + system_gm) / n**2) ** (1.0 / 3.0)
    return KeplerOrbit(a, planet.require("eccentricity", "the Sun's mean orbit").value, 0.0, 0.0, 0.0, 0.0, n)


def mean_perturbers(planet: str) -> list[PointMass]:
    """The Sun (and, for the Earth, the Moon) on their mean orbits around ``planet``.

    Parameters
    ----------
    planet : {"earth", "mars"}

    Returns
    -------
    list of PointMass
    """
    key = str(planet).strip().lower()
    if key == "earth":
        sun = _sun_seen_from(_EARTH, _EARTH.gm.si() + GM_MOON)
        moon = KeplerOrbit(
            _MOON.semi_major_axis.si(),
            _MOON.eccentricity.value,
            _MOON.inclination.si(),
            0.0,
            0.0,
            0.0,
            2 * np.pi / _MOON.orbital_period.si(),
            node_rate=-2 * np.pi / _MOON.node_period.si(),
        )
        return [PointMass(GM_SUN, sun, "Sun"), PointMass(GM_MOON, moon, "Moon")]
    if key == "mars":
        return [PointMass(GM_SUN, _sun_seen_from(_MARS, _MARS.gm.si()), "Sun")]
    msg = f"expected 'earth' or 'mars', got {planet!r}"
    raise ValueError(msg)
