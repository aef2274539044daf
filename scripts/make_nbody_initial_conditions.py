"""Write ``src/andoyer/planetary/orbits/data/planets_j2000.json``: the planets at J2000.

Sources:

* States: the JPL DE421 ephemeris (Folkner, Williams & Boggs 2009, IPN Progress Report 42-178),
  read with ``jplephem`` from the ``de421`` package of PyPI (``pip install jplephem de421``;
  needed only to run this script): barycentric positions and velocities of the Sun, the
  Earth-Moon barycentre and the other planets' system barycentres at JD 2451545.0 TDB, ICRF
  (equatorial) axes. The script turns them into heliocentric states and rotates them by
  ``ε₀ = 84381.406″`` about ``x`` into the J2000 ecliptic frame (the ICRF-to-J2000 frame bias,
  ~23 mas, is neglected). These are osculating states of the ephemeris, so the integration
  starts on the real orbits (mean motions and the Jupiter-Saturn great inequality included).

* Mean elements, shipped beside the states for the secular theory (which needs mean, not
  osculating, elements): E. M. Standish, "Keplerian Elements for Approximate Positions of the Major
  Planets", JPL Solar System Dynamics, Table 1 (``p_elem_t1.txt``, valid 1800 AD–2050 AD,
  a fit to the JPL DE405 ephemeris), mean ecliptic and equinox of J2000: ``a`` (au), ``e``,
  ``I``, ``L``, ``ϖ``, ``Ω`` (degrees) at J2000 (TDB = JD 2451545.0). The Earth row is the
  Earth–Moon barycentre. These are best-fit elements over 250 years, not osculating ones:
  the states derived from them differ from DE405's osculating states by the planets'
  short-period perturbations (Standish's stated position errors over 1800–2050: 15–600″,
  the largest for Jupiter and Saturn, whose great inequality the fit absorbs).
  Until 2026-11-25 the N-body source started from the Keplerian conversion of these mean
  elements, which made Saturn's mean motion 0.7 % fast and the great inequality's period
  431 yr instead of ~900 yr (measured in the review of that date).
* Gravitational parameters: the constants of the JPL DE440 ephemeris (Park, Folkner, Williams &
  Boggs 2021, AJ 161, 105), km³/s², as its header lists them (GM1…GM9, GMS, GMB in NAIF's
  ``de440_tech-comments.txt``, https://naif.jpl.nasa.gov/pub/naif/generic_kernels/spk/planets/);
  checked digit by digit against that list (2026 review); the table of the paper that prints
  them was not checked. The planets' values are those of their systems (planet + moons), the
  Earth's that of the Earth–Moon system (GMB = GM3 + GMM = 403503.235625; the earlier value
  403503.235502 of this script was DE430's, corrected in the review).
* Astronomical unit: 149 597 870.700 km (IAU 2012 Resolution B2); the Julian year of
  365.25 days of 86 400 s.

Run from the repository root: ``python3 scripts/make_nbody_initial_conditions.py``.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "src" / "andoyer" / "orbits" / "data" / "planets_j2000.json"

AU_KM = 149597870.700  # IAU 2012 Resolution B2
YEAR_S = 365.25 * 86400.0  # Julian year

# DE440 GM values (km^3/s^2): the DE440 header constants (de440_tech-comments.txt), see above.
GM_KM3_S2 = {
    "sun": 132712440041.279419,
    "mercury": 22031.868551,
    "venus": 324858.592000,
    "earth": 403503.235625,  # Earth-Moon system (DE440 GMB)
    "mars": 42828.375816,
    "jupiter": 126712764.100000,
    "saturn": 37940584.841800,
    "uranus": 5794556.400000,
    "neptune": 6836527.100580,
}

# Standish, JPL "Keplerian Elements for Approximate Positions of the Major Planets", Table 1:
# a (au), e, I (deg), L (deg), varpi (deg), Omega (deg) at J2000, J2000 ecliptic and equinox.
# All 48 numbers checked digit by digit (2026 review) against two independent public copies of
# ssd.jpl.nasa.gov/txt/p_elem_t1.txt (one quoting that URL); they agree with the JPL file.
STANDISH_TABLE_1 = {
    "mercury": (0.38709927, 0.20563593, 7.00497902, 252.25032350, 77.45779628, 48.33076593),
    "venus": (0.72333566, 0.00677672, 3.39467605, 181.97909950, 131.60246718, 76.67984255),
    "earth": (1.00000261, 0.01671123, -0.00001531, 100.46457166, 102.93768193, 0.0),
    "mars": (1.52371034, 0.09339410, 1.84969142, -4.55343205, -23.94362959, 49.55953891),
    "jupiter": (5.20288700, 0.04838624, 1.30439695, 34.39644051, 14.72847983, 100.47390909),
    "saturn": (9.53667594, 0.05386179, 2.48599187, 49.95424423, 92.59887831, 113.66242448),
    "uranus": (19.18916464, 0.04725744, 0.77263783, 313.23810451, 170.95427630, 74.01692503),
    "neptune": (30.06992276, 0.00859048, 1.77004347, -55.12002969, 44.96476227, 131.78422574),
}


JD_J2000 = 2451545.0
EPSILON_0 = np.radians(84381.406 / 3600.0)  # IAU 2006 obliquity at J2000
DE421_NAMES = {"earth": "earthmoon"}


def de421_heliocentric_states() -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Heliocentric (au, au/yr) states at J2000 in the J2000 ecliptic frame, from DE421."""
    import de421  # the ephemeris data (PyPI package), only for this script
    from jplephem.ephem import Ephemeris

    ephemeris = Ephemeris(de421)
    c, s = np.cos(EPSILON_0), np.sin(EPSILON_0)
    to_ecliptic = np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])

    def state(name: str) -> tuple[np.ndarray, np.ndarray]:
        r_km, v_km_day = ephemeris.position_and_velocity(name, JD_J2000)
        return r_km[:, 0], v_km_day[:, 0]

    r_sun, v_sun = state("sun")
    out = {}
    for name in STANDISH_TABLE_1:
        r, v = state(DE421_NAMES.get(name, name))
        out[name] = (
            to_ecliptic @ (r - r_sun) / AU_KM,
            to_ecliptic @ (v - v_sun) * 365.25 / AU_KM,
        )
    return out


def main() -> None:
    """Write the DE421 states, the mean elements and the GM values to the JSON file."""
    to_au3_yr2 = YEAR_S**2 / AU_KM**3
    gm = {name: value * to_au3_yr2 for name, value in GM_KM3_S2.items()}
    states = de421_heliocentric_states()
    planets = {}
    for name, (a, e, inc, L, varpi, node) in STANDISH_TABLE_1.items():
        r, v = states[name]
        planets[name] = {
            "gm": gm[name],
            "elements": {"a": a, "e": e, "inclination_deg": inc, "node_deg": node, "varpi_deg": varpi,
                         "mean_longitude_deg": L},
            "position": r.tolist(),
            "velocity": v.tolist(),
        }
    data = {
        "description": (
            "The Sun and the eight planets (earth = Earth-Moon barycentre) at J2000 (JD 2451545.0 TDB): "
            "heliocentric positions (au) and velocities (au per Julian year) in the J2000 ecliptic and "
            "equinox frame, and GM (au^3/yr^2). Written by scripts/make_nbody_initial_conditions.py."
        ),
        "sources": {
            "states": (
                "JPL DE421 (Folkner, Williams & Boggs 2009) via jplephem and the de421 package: "
                "barycentric states at JD 2451545.0 TDB made heliocentric and rotated by eps0 = "
                "84381.406 arcsec from ICRF to the J2000 ecliptic (frame bias neglected)."
            ),
            "elements": (
                "E. M. Standish, Keplerian Elements for Approximate Positions of the Major Planets, "
                "JPL Solar System Dynamics, Table 1 (1800 AD-2050 AD, fit to DE405): mean elements, "
                "for the secular theory; not the source of the states."
            ),
            "gm": (
                "JPL DE440 header constants GM1-GM9, GMS, GMB (system values; NAIF de440_tech-comments.txt); "
                "Park, Folkner, Williams & Boggs (2021), AJ 161, 105."
            ),
            "au_km": "149597870.700 km, IAU 2012 Resolution B2.",
        },
        "units": {"length": "au", "time": "Julian year (365.25 d)", "gm": "au^3/yr^2", "angles": "deg"},
        "au_km": AU_KM,
        "sun_gm": gm["sun"],
        "planets": planets,
    }
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
