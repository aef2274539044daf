r"""The Earth–Moon–Sun numbers of the tidal model: one dataclass, its defaults from the catalogue.

Every body number the tidal evolution needs is a field of :class:`EarthMoonSystem`. The defaults
are read from the project's catalogue (:func:`andoyer.catalogue.get`, where each value carries
its source); three are cited here: the gravitational constant, the Earth's mean radius and its
fluid Love number (the catalogue does not hold them). The inertial spin rate is the catalogue's
``spin_rate``, not its ``rotation_rate`` (the IAU prime meridian's). Derived quantities (masses, the
polar moment ``C``, the lunar mean motion) are properties computed from the fields, so that
changing a field changes everything that depends on it.

Units: SI (m, kg, s, rad) unless a field's name says otherwise.

Examples
--------
>>> earth_moon = EarthMoonSystem()
>>> round(earth_moon.moment_factor, 6)  # C/(M a_E²), MHB 2002 via the catalogue
0.330698
>>> round(earth_moon.day_length_hours, 4)  # sidereal day from ω0
23.9345
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

from andoyer import catalogue
from andoyer.catalogue.units import DAY, HOUR
from andoyer.planetary.parameters import check

__all__ = ["EarthMoonSystem"]


def _catalogue(body: str, key: str):
    """A factory of the catalogue's ``key`` of ``body`` in SI."""
    return lambda: getattr(catalogue.get(body), key).si()


@dataclass(frozen=True)
class EarthMoonSystem:
    """The Earth, the Moon and the Sun as the tidal model sees them (present-day values).

    Every default but three is the catalogue's (``andoyer bodies earth``, ``moon``, ``sun``
    print each value with its source): the Earth's ``GM``, equatorial radius ``a_E``, ``J2``,
    ``C/(M a_E²)``, ``H``, obliquity, orbit (``a``, ``e``, sidereal year); the Moon's ``GM``
    and mean orbit (``a``, ``e``, ``i``); the Sun's ``GM``.

    Attributes
    ----------
    gravitational_constant : float
        ``G`` = 6.67430e-11 m³ kg⁻¹ s⁻² (CODATA 2018): masses from ``GM``.
    gm_earth, gm_moon, gm_sun : float
        m³ s⁻² (catalogue).
    equatorial_radius : float
        ``a_E``, m (catalogue): the radius of the tidal torques and of ``C``.
    mean_radius : float
        6371000 m (IUGG mean radius, Moritz 2000): the radius of the ocean model's sphere.
    j2 : float
        The dynamical form factor (catalogue): the Laplace radius.
    moment_factor : float
        ``C/(M_E a_E²)`` (catalogue).
    dynamical_ellipticity : float
        ``H = (C − (A+B)/2)/C`` (catalogue).
    spin_rate : float
        ``ω0`` = 7.292115e-5 rad s⁻¹, the Earth's inertial spin (catalogue ``spin_rate``: GRS80,
        IERS Conventions 2010, Table 1.2). Not the catalogue's ``rotation_rate``: that is the rate
        of the IAU prime meridian, 360.9856235°/d (5.1e-8 more).
    obliquity : float
        ``ε0``, radians (catalogue, IAU 2006).
    fluid_love_number : float
        ``k_f`` = 0.93, the Earth's fluid (secular) Love number in the centrifugal change of the
        polar moment ``C(ω) = C0 + (2/9) k_f a_E⁵ (ω² − ω0²)/G`` (the form and value of Farhat
        et al. 2022, A&A 665, L1, App. A; also in Eulenfeld & Heubeck 2023's code).
    lunar_semi_major_axis : float
        ``a_M``, m (catalogue: the mean lunar orbit).
    lunar_eccentricity, lunar_inclination : float
        The mean lunar orbit (catalogue), used by the precession constant only.
    solar_semi_major_axis, solar_eccentricity : float
        The Earth's orbit (catalogue, J2000).
    sidereal_year_days : float
        The sidereal year (catalogue): the Sun's mean motion seen from the Earth.

    Examples
    --------
    >>> EarthMoonSystem(spin_rate=0.0)
    Traceback (most recent call last):
    ...
    ValueError: expected a positive finite spin_rate, got 0.0
    """

    gravitational_constant: float = 6.67430e-11
    gm_earth: float = field(default_factory=_catalogue("earth", "gm"))
    gm_moon: float = field(default_factory=_catalogue("moon", "gm"))
    gm_sun: float = field(default_factory=_catalogue("sun", "gm"))
    equatorial_radius: float = field(default_factory=_catalogue("earth", "radius"))
    mean_radius: float = 6371000.0
    j2: float = field(default_factory=_catalogue("earth", "j2"))
    moment_factor: float = field(default_factory=_catalogue("earth", "moment_of_inertia"))
    dynamical_ellipticity: float = field(default_factory=_catalogue("earth", "dynamical_ellipticity"))
    spin_rate: float = field(default_factory=_catalogue("earth", "spin_rate"))
    obliquity: float = field(default_factory=_catalogue("earth", "obliquity"))
    fluid_love_number: float = 0.93
    lunar_semi_major_axis: float = field(default_factory=_catalogue("moon", "semi_major_axis"))
    lunar_eccentricity: float = field(default_factory=_catalogue("moon", "eccentricity"))
    lunar_inclination: float = field(default_factory=_catalogue("moon", "inclination"))
    solar_semi_major_axis: float = field(default_factory=_catalogue("earth", "semi_major_axis"))
    solar_eccentricity: float = field(default_factory=_catalogue("earth", "eccentricity"))
    sidereal_year_days: float = field(default_factory=lambda: catalogue.get("earth").orbital_period.to("d"))

    def __post_init__(self) -> None:
        ranged = {
            "obliquity": "obliquity",
            "dynamical_ellipticity": "dynamical_ellipticity",
            "j2": "j2",
            "moment_factor": "moment_of_inertia",
            "lunar_eccentricity": "eccentricity",
            "solar_eccentricity": "eccentricity",
            "lunar_inclination": "inclination",
        }
        for item in fields(self):
            value = getattr(self, item.name)
            if not (isinstance(value, int | float) and math.isfinite(value)):
                msg = f"expected a finite real {item.name}, got {value!r}"
                raise ValueError(msg)
            if item.name in ranged:
                check(ranged[item.name], value)
            elif value <= 0 and not (item.name == "fluid_love_number" and value == 0):
                msg = f"expected a positive finite {item.name}, got {value!r}"
                raise ValueError(msg)

    @property
    def mass_earth(self) -> float:
        """``M_E = GM_E / G``, kg."""
        return self.gm_earth / self.gravitational_constant

    @property
    def mass_moon(self) -> float:
        """``M_M = GM_M / G``, kg."""
        return self.gm_moon / self.gravitational_constant

    @property
    def reduced_mass(self) -> float:
        """``M_E M_M / (M_E + M_M)``, kg: the mass of the Earth–Moon relative orbit."""
        return self.mass_earth * self.mass_moon / (self.mass_earth + self.mass_moon)

    @property
    def polar_moment(self) -> float:
        """``C0 = (C/M a²) M_E a_E²``, kg m²: the polar moment of inertia today."""
        return self.moment_factor * self.mass_earth * self.equatorial_radius**2

    @property
    def centrifugal_moment(self) -> float:
        """``(2/9) k_f a_E⁵ / G``, kg m² s²: ``C(ω) = C0 + this · (ω² − ω0²)``."""
        return 2.0 / 9.0 * self.fluid_love_number * self.equatorial_radius**5 / self.gravitational_constant

    @property
    def solar_mean_motion(self) -> float:
        """``n_⊙ = 2π / sidereal year``, rad s⁻¹."""
        return 2.0 * math.pi / (self.sidereal_year_days * DAY)

    @property
    def day_length_hours(self) -> float:
        """``2π/ω0`` in hours (the sidereal day)."""
        return 2.0 * math.pi / self.spin_rate / HOUR

    def lunar_mean_motion(self, semi_major_axis: float) -> float:
        """``n = √(G(M_E + M_M)/a³)``, rad s⁻¹, the Kepler mean motion of the relative orbit.

        Parameters
        ----------
        semi_major_axis : float
            Metres.

        Returns
        -------
        float
        """
        return math.sqrt((self.gm_earth + self.gm_moon) / semi_major_axis**3)
