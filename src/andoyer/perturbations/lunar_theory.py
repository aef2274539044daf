r"""The Moon's and the Sun's geocentric positions from the Delaunay arguments (a truncated lunar theory).

:func:`~andoyer.perturbations.solar_system.mean_perturbers` puts the Moon on
a Kepler ellipse whose argument of latitude advances at the sidereal rate, so
its month is 27.43 days instead of the draconic 27.2122 days: good for the
precession, 0.4 % off for the nutation. This module gives the positions the
nutation needs, referred to the **mean ecliptic and mean equinox of date**:

* the **Delaunay arguments** ``(l, l′, F, D, Ω)`` of the IERS Conventions 2010,
  eq. 5.43 (Simon et al. 1994, A&A 282, 663): polynomials in Julian
  centuries TT from J2000, :func:`delaunay_arguments`, with their rates
  :func:`delaunay_rates`;
* the **Moon**: ecliptic longitude ``λ = L + Σ A_k sin θ_k``, latitude
  ``β = Σ B_k sin θ_k`` and distance ``r = r₀ + Σ R_k cos θ_k`` with
  ``L = F + Ω`` the mean longitude and ``θ_k = d D + m l′ + m′ l + f F``:
  the 60 + 60 largest terms of ELP-2000/82 (Chapront-Touzé & Chapront 1983)
  as tabulated by Meeus (1998, *Astronomical Algorithms*, 2nd ed.,
  Tables 47.A and 47.B, with ``r₀ = 385000.56 km``, the factor
  ``E = 1 − 0.002516 T − 0.0000074 T²`` on terms in ``l′`` and Meeus'
  additive terms from Venus, Jupiter and the Earth's flattening). Left out:
  every ELP term below 0.0003° in longitude, 0.0001° in latitude and 1 km in
  distance; the truncation is worth 2.9″ RMS (18″ at worst) in direction and
  6 km in distance against ELP/MPP02 (SOFA's notes on ``iauMoon98``, which
  implements the same tables), i.e. ``≲ 10⁻⁵`` of the Moon's torque;
* the **Sun**: a Kepler ellipse with the mean anomaly ``l′``, mean longitude
  ``L☉ = F − D + Ω``, eccentricity ``e = 0.016708634 − 0.000042037 T``
  (Meeus eq. 25.4, from VSOP87) and semi-major axis ``1.000001018 au``
  (Simon et al. 1994). Left out: the planetary perturbations of the Earth's
  orbit (≤ 0.005° in longitude, ≤ 3·10⁻⁵ in distance) and the Earth's 4700 km
  offset from the Earth–Moon barycentre (6.4″ in the Sun's longitude).

:func:`precise_perturbers` wraps both as
:class:`~andoyer.perturbations.PointMass` perturbers for the torque models,
in a frame fixed in space (see there).

Examples
--------
>>> lon, lat, r = moon_ecliptic(0.0)  # J2000.0
>>> round(float(np.degrees(lon)), 3), round(float(np.degrees(lat)), 3), round(float(r / 1e3))
(223.319, 5.171, 402445)
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.catalogue.units import ARCSEC, AU, DEGREE, JULIAN_YEAR
from andoyer.perturbations.gravity import PointMass
from andoyer.perturbations.orbits import TabulatedOrbit, solve_kepler
from andoyer.perturbations.solar_system import GM_MOON, GM_SUN

__all__ = [
    "GENERAL_PRECESSION",
    "LUNAR_THEORY_SPAN",
    "check_span",
    "delaunay_arguments",
    "delaunay_rates",
    "ecliptic_vector",
    "moon_ecliptic",
    "precise_perturbers",
    "sun_ecliptic",
]

Array = NDArray[np.float64]

#: IERS Conventions 2010, eq. 5.43: ``(l, l′, F, D, Ω)`` in arcseconds, powers 0..4 of Julian centuries TT.
_DELAUNAY = np.array(
    [
        [485868.249036, 1717915923.2178, 31.8792, 0.051635, -0.00024470],
        [1287104.793048, 129596581.0481, -0.5532, 0.000136, -0.00001149],
        [335779.526232, 1739527262.8478, -12.7512, -0.001037, 0.00000417],
        [1072260.703692, 1602961601.2090, -6.3706, 0.006593, -0.00003169],
        [450160.398036, -6962890.5431, 7.4722, 0.007702, -0.00005939],
    ]
)

#: IAU 2006 general precession in longitude at J2000, 5028.796195″ per Julian century (Capitaine et al. 2003).
GENERAL_PRECESSION = 5028.796195 * ARCSEC / 100.0

# Meeus (1998) Table 47.A: multipliers of (D, l′, l, F); Σl in 1e-6 degree, Σr in metres.
_LR = np.array(
    [
        (0, 0, 1, 0, 6288774, -20905355), (2, 0, -1, 0, 1274027, -3699111),
        (2, 0, 0, 0, 658314, -2955968), (0, 0, 2, 0, 213618, -569925),
        (0, 1, 0, 0, -185116, 48888), (0, 0, 0, 2, -114332, -3149),
        (2, 0, -2, 0, 58793, 246158), (2, -1, -1, 0, 57066, -152138),
        (2, 0, 1, 0, 53322, -170733), (2, -1, 0, 0, 45758, -204586),
        (0, 1, -1, 0, -40923, -129620), (1, 0, 0, 0, -34720, 108743),
        (0, 1, 1, 0, -30383, 104755), (2, 0, 0, -2, 15327, 10321),
        (0, 0, 1, 2, -12528, 0), (0, 0, 1, -2, 10980, 79661),
        (4, 0, -1, 0, 10675, -34782), (0, 0, 3, 0, 10034, -23210),
        (4, 0, -2, 0, 8548, -21636), (2, 1, -1, 0, -7888, 24208),
        (2, 1, 0, 0, -6766, 30824), (1, 0, -1, 0, -5163, -8379),
        (1, 1, 0, 0, 4987, -16675), (2, -1, 1, 0, 4036, -12831),
        (2, 0, 2, 0, 3994, -10445), (4, 0, 0, 0, 3861, -11650),
        (2, 0, -3, 0, 3665, 14403), (0, 1, -2, 0, -2689, -7003),
        (2, 0, -1, 2, -2602, 0), (2, -1, -2, 0, 2390, 10056),
        (1, 0, 1, 0, -2348, 6322), (2, -2, 0, 0, 2236, -9884),
        (0, 1, 2, 0, -2120, 5751), (0, 2, 0, 0, -2069, 0),
        (2, -2, -1, 0, 2048, -4950), (2, 0, 1, -2, -1773, 4130),
        (2, 0, 0, 2, -1595, 0), (4, -1, -1, 0, 1215, -3958),
        (0, 0, 2, 2, -1110, 0), (3, 0, -1, 0, -892, 3258),
        (2, 1, 1, 0, -810, 2616), (4, -1, -2, 0, 759, -1897),
        (0, 2, -1, 0, -713, -2117), (2, 2, -1, 0, -700, 2354),
        (2, 1, -2, 0, 691, 0), (2, -1, 0, -2, 596, 0),
        (4, 0, 1, 0, 549, -1423), (0, 0, 4, 0, 537, -1117),
        (4, -1, 0, 0, 520, -1571), (1, 0, -2, 0, -487, -1739),
        (2, 1, 0, -2, -399, 0), (0, 0, 2, -2, -381, -4421),
        (1, 1, 1, 0, 351, 0), (3, 0, -2, 0, -340, 0),
        (4, 0, -3, 0, 330, 0), (2, -1, 2, 0, 327, 0),
        (0, 2, 1, 0, -323, 1165), (1, 1, -1, 0, 299, 0),
        (2, 0, 3, 0, 294, 0), (2, 0, -1, -2, 0, 8752),
    ],
    dtype=float,
)  # fmt: skip

# Meeus (1998) Table 47.B: multipliers of (D, l′, l, F); Σb in 1e-6 degree.
_B = np.array(
    [
        (0, 0, 0, 1, 5128122), (0, 0, 1, 1, 280602), (0, 0, 1, -1, 277693), (2, 0, 0, -1, 173237),
        (2, 0, -1, 1, 55413), (2, 0, -1, -1, 46271), (2, 0, 0, 1, 32573), (0, 0, 2, 1, 17198),
        (2, 0, 1, -1, 9266), (0, 0, 2, -1, 8822), (2, -1, 0, -1, 8216), (2, 0, -2, -1, 4324),
        (2, 0, 1, 1, 4200), (2, 1, 0, -1, -3359), (2, -1, -1, 1, 2463), (2, -1, 0, 1, 2211),
        (2, -1, -1, -1, 2065), (0, 1, -1, -1, -1870), (4, 0, -1, -1, 1828), (0, 1, 0, 1, -1794),
        (0, 0, 0, 3, -1749), (0, 1, -1, 1, -1565), (1, 0, 0, 1, -1491), (0, 1, 1, 1, -1475),
        (0, 1, 1, -1, -1410), (0, 1, 0, -1, -1344), (1, 0, 0, -1, -1335), (0, 0, 3, 1, 1107),
        (4, 0, 0, -1, 1021), (4, 0, -1, 1, 833), (0, 0, 1, -3, 777), (4, 0, -2, 1, 671),
        (2, 0, 0, -3, 607), (2, 0, 2, -1, 596), (2, -1, 1, -1, 491), (2, 0, -2, 1, -451),
        (0, 0, 3, -1, 439), (2, 0, 2, 1, 422), (2, 0, -3, -1, 421), (2, 1, -1, 1, -366),
        (2, 1, 0, 1, -351), (4, 0, 0, 1, 331), (2, -1, 1, 1, 315), (2, -2, 0, -1, 302),
        (0, 0, 1, 3, -283), (2, 1, 1, -1, -229), (1, 1, 0, -1, 223), (1, 1, 0, 1, 223),
        (0, 1, -2, -1, -220), (2, 1, -1, -1, -220), (1, 0, 1, 1, -185), (2, -1, -2, -1, 181),
        (0, 1, 2, 1, -177), (4, 0, -2, -1, 176), (4, -1, -1, -1, 166), (1, 0, 1, -1, -164),
        (4, 0, 1, -1, 132), (1, 0, -1, -1, -119), (4, -1, 0, -1, 115), (2, -2, 0, 1, 107),
    ],
    dtype=float,
)  # fmt: skip

_R0 = 385000.56e3  # Meeus (1998) ch. 47: the constant of the distance series, metres


#: The Delaunay polynomials (Simon et al. 1994) hold over a few millennia; far outside, their
#: powers of T only lose meaning (and overflow near 1e77 years).
DELAUNAY_SPAN_YEARS = 1e5
#: The Sun's eccentricity ``e = e₀ + e₁ T`` (T in Julian centuries; Meeus 1998, eq. 25.4, from VSOP87).
SUN_ECCENTRICITY = (0.016708634, -0.000042037)
#: Span of validity of the lunar and solar arguments, Julian years from J2000: the Delaunay
#: polynomials' ±100 000 years, cut where the Sun's eccentricity polynomial turns negative
#: (``T = −e₀/e₁``, 39 747 years after J2000).
LUNAR_THEORY_SPAN = (
    -DELAUNAY_SPAN_YEARS,
    min(DELAUNAY_SPAN_YEARS, -100.0 * SUN_ECCENTRICITY[0] / SUN_ECCENTRICITY[1]),
)


def check_span(t0: float, t1: float, name: str = "times") -> None:
    """Refuse a span ``[t0, t1]`` (Julian years from J2000) outside :data:`LUNAR_THEORY_SPAN`.

    Parameters
    ----------
    t0, t1 : float
    name : str
        What the span is, for the message (a command line names its option).

    Examples
    --------
    >>> check_span(0.0, 100.0)
    >>> check_span(0.0, 250000.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected times within the lunar theory's span of validity -100000 to ..., got 0 to 250000
    """
    lo, hi = LUNAR_THEORY_SPAN
    if not (lo <= t0 and t1 <= hi):  # NaN fails too
        msg = (
            f"expected {name} within the lunar theory's span of validity {lo:.0f} to {hi:.0f} years from "
            f"J2000 (the Delaunay polynomials; after {hi:.0f} the Sun's eccentricity polynomial turns "
            f"negative), got {t0:g} to {t1:g}"
        )
        raise ValueError(msg)


def _centuries(t: ArrayLike) -> Array:
    years = as_finite(t, "t")
    if years.size:
        check_span(float(np.min(years)), float(np.max(years)))
    return years / 100.0


def delaunay_arguments(t: ArrayLike) -> Array:
    """The Delaunay arguments ``(l, l′, F, D, Ω)`` (radians, not reduced), IERS Conventions 2010 eq. 5.43.

    ``l`` and ``l′`` are the mean anomalies of the Moon and the Sun, ``F = L − Ω``
    the Moon's mean argument of latitude, ``D`` the mean elongation of the Moon
    from the Sun, ``Ω`` the mean longitude of the Moon's ascending node on the
    ecliptic of date, from the mean equinox of date.

    Parameters
    ----------
    t : array_like, shape (...)
        Julian years TT from J2000.0.

    Returns
    -------
    numpy.ndarray, shape (..., 5)

    Examples
    --------
    >>> np.degrees(delaunay_arguments(0.0)).round(6).tolist()
    [134.963403, 357.529109, 93.272091, 297.850195, 125.044555]
    """
    T = _centuries(t)[..., None]
    powers = T ** np.arange(5)
    return np.sum(_DELAUNAY * powers[..., None, :], axis=-1) * ARCSEC


def delaunay_rates(t: ArrayLike = 0.0) -> Array:
    """Rates of the Delaunay arguments, radians per Julian year, shape (..., 5).

    Examples
    --------
    >>> periods = 2 * np.pi / np.abs(delaunay_rates()) * 365.25  # days
    >>> periods.round(3).tolist()  # anomalistic month, year, draconic month, synodic month, node
    [27.555, 365.26, 27.212, 29.531, 6798.383]
    """
    T = _centuries(t)[..., None]
    powers = np.arange(1, 5) * T ** np.arange(4)
    return np.sum(_DELAUNAY[:, 1:] * powers[..., None, :], axis=-1) * ARCSEC / 100.0


def _series_angles(args: Array, table: Array) -> Array:
    # Columns of the tables multiply (D, l′, l, F); args holds (l, l′, F, D, Ω).
    basis = np.stack([args[..., 3], args[..., 1], args[..., 0], args[..., 2]], axis=-1)
    return basis @ table[:, :4].T


def moon_ecliptic(
    t: ArrayLike, args: ArrayLike | None = None, planetary: bool = True
) -> tuple[Array, Array, Array]:
    """The Moon's geocentric longitude, latitude (radians) and distance (m), mean ecliptic/equinox of date.

    Parameters
    ----------
    t : array_like, shape (...)
        Julian years TT from J2000.0 (they set the slow factor ``E`` and, unless
        ``args`` is given, the arguments).
    args : array_like, shape (..., 5), optional
        Delaunay arguments to use instead of :func:`delaunay_arguments` ``(t)``
        (a point of the torus, for Fourier analysis).
    planetary : bool
        Include Meeus' additive terms in Venus' and Jupiter's arguments
        (``A₁, A₂, A₃``, not functions of the Delaunay arguments; at most 14″);
        the terms in ``L`` (the Earth's flattening, ``−8.0″ sin L``) stay.

    Returns
    -------
    lon, lat, distance : numpy.ndarray, shape (...)

    Examples
    --------
    >>> lon, lat, r = moon_ecliptic(np.array([0.0, 10.0]))
    >>> (r / 1e3).round(0).tolist()
    [402445.0, 359367.0]
    """
    T = _centuries(t)
    a = delaunay_arguments(t) if args is None else np.asarray(args, dtype=float)
    E = 1 - 0.002516 * T - 0.0000074 * T**2  # Meeus eq. 47.6: the Earth's orbital eccentricity drift
    E = E[..., None]
    lr = _series_angles(a, _LR)
    eccentric = E ** np.abs(_LR[:, 1])
    L = a[..., 2] + a[..., 4]
    # Meeus' additive terms: Venus (A1), Jupiter (A2), the Earth's flattening (in latitude, sin L).
    A1 = (119.75 + 131.849 * T) * DEGREE
    A2 = (53.09 + 479264.290 * T) * DEGREE
    A3 = (313.45 + 481266.484 * T) * DEGREE
    extra_lon = 1962 * np.sin(L - a[..., 2])
    extra_lat = -2235 * np.sin(L) + 127 * np.sin(L - a[..., 0]) - 115 * np.sin(L + a[..., 0])
    if planetary:
        extra_lon = extra_lon + 3958 * np.sin(A1) + 318 * np.sin(A2)
        extra_lat = extra_lat + 382 * np.sin(A3) + 175 * np.sin(A1 - a[..., 2]) + 175 * np.sin(A1 + a[..., 2])
    lon = L + (np.sum(_LR[:, 4] * eccentric * np.sin(lr), axis=-1) + extra_lon) * 1e-6 * DEGREE
    distance = _R0 + np.sum(_LR[:, 5] * eccentric * np.cos(lr), axis=-1)
    b = _series_angles(a, _B)
    lat = (np.sum(_B[:, 4] * E ** np.abs(_B[:, 1]) * np.sin(b), axis=-1) + extra_lat) * 1e-6 * DEGREE
    return lon, lat, distance


def sun_ecliptic(t: ArrayLike, args: ArrayLike | None = None) -> tuple[Array, Array, Array]:
    """The Sun's geocentric longitude, latitude (zero) in radians and distance (m), mean ecliptic of date.

    A Kepler ellipse: mean anomaly ``l′``, perihelion longitude ``L☉ − l′`` with
    ``L☉ = F − D + Ω``, ``e = 0.016708634 − 0.000042037 T``, ``a = 1.000001018 au``.

    Parameters
    ----------
    t : array_like, shape (...)
        Julian years TT from J2000.0.
    args : array_like, shape (..., 5), optional
        Delaunay arguments to use instead of :func:`delaunay_arguments` ``(t)``.

    Returns
    -------
    lon, lat, distance : numpy.ndarray, shape (...)

    Examples
    --------
    >>> lon, lat, r = sun_ecliptic(0.0)
    >>> round(float(np.degrees(lon % (2 * np.pi))), 3), round(float(r / 1.495978707e11), 5)
    (280.382, 0.98331)
    """
    T = _centuries(t)
    a = delaunay_arguments(t) if args is None else np.asarray(args, dtype=float)
    e = SUN_ECCENTRICITY[0] + SUN_ECCENTRICITY[1] * T
    M = a[..., 1]
    E = solve_kepler(M, e)
    nu = 2 * np.arctan2(np.sqrt(1 + e) * np.sin(E / 2), np.sqrt(1 - e) * np.cos(E / 2))
    mean_longitude = a[..., 2] - a[..., 3] + a[..., 4]
    lon = mean_longitude + nu - M
    distance = 1.000001018 * AU * (1 - e * np.cos(E))
    return lon, np.zeros_like(lon), distance


def ecliptic_vector(lon: ArrayLike, lat: ArrayLike, distance: ArrayLike) -> Array:
    """Cartesian ``r (cos β cos λ, cos β sin λ, sin β)``, shape (..., 3).

    Examples
    --------
    >>> ecliptic_vector(np.pi / 2, 0.0, 2.0).round(12).tolist()
    [0.0, 2.0, 0.0]
    """
    lon, lat, distance = (np.asarray(v, dtype=float) for v in (lon, lat, distance))
    cb = np.cos(lat)
    return distance[..., None] * np.stack([cb * np.cos(lon), cb * np.sin(lon), np.sin(lat) + 0 * lon], -1)


def precise_perturbers(
    planet: str = "earth", precession_rate: float = GENERAL_PRECESSION, planetary: bool = True
) -> list[PointMass]:
    """The Sun and the Moon from :func:`sun_ecliptic` and :func:`moon_ecliptic`, for the torque models.

    Times are seconds TT from J2000.0 (the torque models' unit). The frame is
    fixed in space: the mean ecliptic (its own slow motion, 47″ per century,
    left out) with the mean equinox of J2000, reached from the equinox of date
    by ``λ_fixed = λ_date − p t``, ``p = precession_rate`` (radians per Julian
    year; default the IAU 2006 general precession in longitude).

    Parameters
    ----------
    planet : {"earth"}
    precession_rate : float
    planetary : bool
        Keep the Moon's additive planetary terms (see :func:`moon_ecliptic`).

    Returns
    -------
    list of PointMass

    Examples
    --------
    >>> sun, moon = precise_perturbers()
    >>> (np.linalg.norm(moon.orbit.position(0.0)) / 1e3).round(0)
    np.float64(402445.0)
    """
    if str(planet).strip().lower() != "earth":
        msg = f"expected 'earth' (the lunar theory is the Earth's Moon), got {planet!r}"
        raise ValueError(msg)
    rate = float(as_finite(precession_rate, "precession_rate"))

    def place(body: str):  # type: ignore[no-untyped-def]
        def position(seconds: Array) -> Array:
            years = np.asarray(seconds, dtype=float) / JULIAN_YEAR
            if body == "moon":
                lon, lat, r = moon_ecliptic(years, planetary=planetary)
            else:
                lon, lat, r = sun_ecliptic(years)
            return ecliptic_vector(lon - rate * years, lat, r)

        return position

    return [
        PointMass(GM_SUN, TabulatedOrbit(place("sun")), "Sun"),
        PointMass(GM_MOON, TabulatedOrbit(place("moon")), "Moon"),
    ]
