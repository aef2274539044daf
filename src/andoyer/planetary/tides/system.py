r"""The Earth–Moon–Sun numbers of the tidal model: one cited dataclass of defaults.

Every body number the tidal evolution needs is a field of :class:`EarthMoonSystem`, with its
source. Derived quantities (masses, the polar moment ``C``, the lunar mean motion) are
properties computed from the fields, so that changing a field changes everything that depends
on it. Until the project's catalogue (``andoyer.catalogue``) holds these numbers, this class is
their one place in the tidal package.

Units: SI (m, kg, s, rad) unless a field's name says otherwise.

Examples
--------
>>> earth_moon = EarthMoonSystem()
>>> round(earth_moon.moment_factor, 4)  # C/(M a_E²) = J2/H
0.3307
>>> round(earth_moon.day_length_hours, 4)  # sidereal day from ω0
23.9345
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from andoyer.bodies import ARCSEC
from andoyer.perturbations.solar_system import DAY

__all__ = ["EarthMoonSystem"]


@dataclass(frozen=True)
class EarthMoonSystem:
    """The Earth, the Moon and the Sun as the tidal model sees them (present-day values).

    Attributes
    ----------
    gravitational_constant : float
        ``G`` = 6.67430e-11 m³ kg⁻¹ s⁻² (CODATA 2018).
    gm_earth : float
        3.986004418e14 m³ s⁻² (IERS Conventions 2010, Table 1.1).
    gm_moon : float
        4.9028e12 m³ s⁻² (JPL DE440, Park et al. 2021; as in
        :mod:`andoyer.perturbations.solar_system`).
    gm_sun : float
        1.3271244e20 m³ s⁻² (IAU 2015 Resolution B3, nominal).
    equatorial_radius : float
        ``a_E`` = 6378136.6 m (IERS Conventions 2010, Table 1.1): the radius of the tidal
        torques and of ``C = (C/M a_E²) M a_E²``.
    mean_radius : float
        6371000 m (IUGG mean radius, Moritz 2000): the radius of the ocean model's sphere.
    j2 : float
        1.0826359e-3, the dynamical form factor (IERS Conventions 2010, Table 1.1).
    dynamical_ellipticity : float
        ``H = (C − (A+B)/2)/C`` = 3.2737949e-3 (IERS Conventions 2010, Table 1.1; Mathews et al.
        2002). With ``j2``: ``C/(M a_E²) = J2/H`` = 0.33070.
    spin_rate : float
        ``ω0`` = 7.292115e-5 rad s⁻¹ (IERS Conventions 2010, Table 1.1).
    obliquity : float
        ``ε0`` = 84381.406″ in radians (IAU 2006, Capitaine et al. 2003).
    fluid_love_number : float
        ``k_f`` = 0.93, the Earth's fluid (secular) Love number in the centrifugal change of the
        polar moment ``C(ω) = C0 + (2/9) k_f a_E⁵ (ω² − ω0²)/G`` (the form and value of Farhat
        et al. 2022, A&A 665, L1, App. A; also in Eulenfeld & Heubeck 2023's code).
    lunar_semi_major_axis : float
        ``a_M`` = 384399e3 m, the Moon's mean distance (as in
        :mod:`andoyer.perturbations.solar_system`).
    lunar_eccentricity, lunar_inclination : float
        0.0549 and 5.145° (in radians) to the ecliptic: the mean lunar orbit (same source),
        used by the precession constant only.
    solar_semi_major_axis : float
        1 au = 1.495978707e11 m (IAU 2012 Resolution B2).
    solar_eccentricity : float
        0.0167086, the Earth's orbit at J2000 (as in :mod:`andoyer.perturbations.solar_system`).
    sidereal_year_days : float
        365.256363004 d (same source): the Sun's mean motion seen from the Earth.

    Examples
    --------
    >>> EarthMoonSystem(spin_rate=0.0)
    Traceback (most recent call last):
    ...
    ValueError: expected a positive finite spin_rate, got 0.0
    """

    gravitational_constant: float = 6.67430e-11
    gm_earth: float = 3.986004418e14
    gm_moon: float = 4.9028e12
    gm_sun: float = 1.3271244e20
    equatorial_radius: float = 6378136.6
    mean_radius: float = 6371000.0
    j2: float = 1.0826359e-3
    dynamical_ellipticity: float = 3.2737949e-3
    spin_rate: float = 7.292115e-5
    obliquity: float = 84381.406 * ARCSEC
    fluid_love_number: float = 0.93
    lunar_semi_major_axis: float = 384399e3
    lunar_eccentricity: float = 0.0549
    lunar_inclination: float = math.radians(5.145)
    solar_semi_major_axis: float = 1.495978707e11
    solar_eccentricity: float = 0.0167086
    sidereal_year_days: float = 365.256363004

    def __post_init__(self) -> None:
        for item in fields(self):
            value = getattr(self, item.name)
            if not (isinstance(value, int | float) and math.isfinite(value)):
                msg = f"expected a finite real {item.name}, got {value!r}"
                raise ValueError(msg)
            allowed_zero = item.name in ("fluid_love_number", "lunar_eccentricity", "lunar_inclination",
                                         "solar_eccentricity")
            if value < 0 or (value == 0 and not allowed_zero):
                msg = f"expected a positive finite {item.name}, got {value!r}"
                raise ValueError(msg)
        if not 0 < self.obliquity < math.pi / 2:
            msg = f"expected an obliquity in (0, π/2) radians, got {self.obliquity!r}"
            raise ValueError(msg)
        if not (self.lunar_eccentricity < 1 and self.solar_eccentricity < 1 and self.lunar_inclination < 0.6):
            msg = (
                "expected eccentricities below 1 and a lunar inclination below 0.6 rad, got "
                f"{self.lunar_eccentricity!r}, {self.solar_eccentricity!r}, {self.lunar_inclination!r}"
            )
            raise ValueError(msg)
        if not self.dynamical_ellipticity < 0.5 or not self.j2 < self.dynamical_ellipticity:
            msg = (
                "expected 0 < J2 < H < 1/2 (C/(M a²) = J2/H below 1), got "
                f"J2 = {self.j2!r}, H = {self.dynamical_ellipticity!r}"
            )
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
    def moment_factor(self) -> float:
        """``C/(M_E a_E²) = J2/H``."""
        return self.j2 / self.dynamical_ellipticity

    @property
    def polar_moment(self) -> float:
        """``C0 = (J2/H) M_E a_E²``, kg m²: the polar moment of inertia today."""
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
        return 2.0 * math.pi / self.spin_rate / 3600.0

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
