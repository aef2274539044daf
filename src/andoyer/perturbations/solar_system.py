"""Mean orbits of the Sun and the Moon seen from the Earth and Mars, for the gravity-gradient models.

Reference frame: the mean orbital plane of the torqued planet (its ecliptic of
J2000), ``s3`` its pole, ``s1`` towards the ascending node of the Moon's orbit
at ``t = 0``. Times are seconds. Sources:

* gravitational parameters: IAU 2015 Resolution B3 nominal ``GM_sun``
  (1.3271244e20 m³ s⁻²); DE440 ``GM_moon`` = 4.9028e12 m³ s⁻².
* Earth's orbit: a = 1 au = 1.495978707e11 m (IAU 2012), e = 0.0167086, sidereal year 365.256363004 d.
* Mars' orbit: a = 1.52368 au, e = 0.0934, sidereal period 686.980 d (JPL mean elements, J2000).
* the Moon's mean orbit: a = 384399 km, e = 0.0549, inclination 5.145° to the ecliptic,
  sidereal month 27.321661 d, nodal regression period 6798.38 d (18.61 yr).
* obliquities: Earth 23.44° (IAU 2006, 84381.406″), Mars 25.19° (Mars Fact Sheet, NASA GSFC).

Examples
--------
>>> [p.name for p in mean_perturbers("earth")]
['Sun', 'Moon']
>>> round(float(np.degrees(OBLIQUITY["mars"])), 2)
25.19
"""

from __future__ import annotations

import numpy as np

from andoyer.perturbations.gravity import PointMass
from andoyer.perturbations.orbits import KeplerOrbit

__all__ = ["DAY", "JULIAN_YEAR", "OBLIQUITY", "mean_perturbers"]

DAY = 86400.0
JULIAN_YEAR = 365.25 * DAY
AU = 1.495978707e11
GM_SUN = 1.3271244e20
GM_MOON = 4.9028e12

OBLIQUITY = {"earth": np.radians(84381.406 / 3600.0), "mars": np.radians(25.19)}


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
        sun = KeplerOrbit(AU, 0.0167086, 0.0, 0.0, 0.0, 0.0, 2 * np.pi / (365.256363004 * DAY))
        moon = KeplerOrbit(
            384399e3,
            0.0549,
            np.radians(5.145),
            0.0,
            0.0,
            0.0,
            2 * np.pi / (27.321661 * DAY),
            node_rate=-2 * np.pi / (6798.38 * DAY),
        )
        return [PointMass(GM_SUN, sun, "Sun"), PointMass(GM_MOON, moon, "Moon")]
    if key == "mars":
        sun = KeplerOrbit(1.52368 * AU, 0.0934, 0.0, 0.0, 0.0, 0.0, 2 * np.pi / (686.980 * DAY))
        return [PointMass(GM_SUN, sun, "Sun")]
    msg = f"expected 'earth' or 'mars', got {planet!r}"
    raise ValueError(msg)
