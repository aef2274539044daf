"""The planets at J2000 shipped with the package: names, GM, elements, heliocentric states.

The data file ``data/planets_j2000.json`` is written by
``scripts/make_nbody_initial_conditions.py`` from the JPL DE421 ephemeris (the states),
Standish's JPL Table 1 elements (mean elements, a fit to DE405, J2000 ecliptic and equinox) and
the DE440 gravitational parameters (the DE440 header constants; Park et al. 2021);
see that script for the sources. Units: au, Julian years, au³/yr². ``"earth"`` is the
Earth–Moon barycentre.

The file is the N-body solution's data, kept whole because ``data/secular_model.json`` is bound
to its digest: its GMs and Standish elements are the catalogue's (:func:`andoyer.catalogue.get`;
``tests/catalogue/test_catalogue_single_source.py`` checks that they agree, the Earth's row being
the Earth–Moon barycentre's).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from importlib import resources

import numpy as np
from numpy.typing import NDArray

__all__ = ["PLANETS", "PlanetData", "check_planet", "planet_data"]

#: The eight planets, Sun outwards (``"earth"`` = Earth–Moon barycentre).
PLANETS = ("mercury", "venus", "earth", "mars", "jupiter", "saturn", "uranus", "neptune")


@dataclass(frozen=True)
class PlanetData:
    """The shipped J2000 data of the Sun and the planets (arrays in :data:`PLANETS` order).

    Attributes
    ----------
    sun_gm : float
        GM of the Sun, au³/yr².
    gm : numpy.ndarray, shape (8,)
        GM of each planet's system, au³/yr².
    a, e, inclination, node, varpi, mean_longitude : numpy.ndarray, shape (8,)
        Standish's J2000 elements (au; radians).
    position, velocity : numpy.ndarray, shape (8, 3)
        Heliocentric states (au, au/yr), J2000 ecliptic frame.
    digest : str
        The data file's SHA-256 (keys caches of results computed from it).
    """

    sun_gm: float
    gm: NDArray[np.float64]
    a: NDArray[np.float64]
    e: NDArray[np.float64]
    inclination: NDArray[np.float64]
    node: NDArray[np.float64]
    varpi: NDArray[np.float64]
    mean_longitude: NDArray[np.float64]
    position: NDArray[np.float64]
    velocity: NDArray[np.float64]
    digest: str


@cache
def planet_data() -> PlanetData:
    """Read the shipped data file once.

    Returns
    -------
    PlanetData

    Examples
    --------
    >>> data = planet_data()
    >>> data.position.shape, round(float(data.a[2]), 6)
    ((8, 3), 1.000003)
    """
    import hashlib

    data_file = resources.files("andoyer.planetary.orbits").joinpath("data/planets_j2000.json")
    text = data_file.read_text(encoding="utf-8")
    raw = json.loads(text)
    rows = [raw["planets"][name] for name in PLANETS]

    def column(key: str) -> NDArray[np.float64]:
        return np.array([row["elements"][key] for row in rows], dtype=float)

    return PlanetData(
        sun_gm=float(raw["sun_gm"]),
        gm=np.array([row["gm"] for row in rows], dtype=float),
        a=column("a"),
        e=column("e"),
        inclination=np.radians(column("inclination_deg")),
        node=np.radians(column("node_deg")),
        varpi=np.radians(column("varpi_deg")),
        mean_longitude=np.radians(column("mean_longitude_deg")),
        position=np.array([row["position"] for row in rows], dtype=float),
        velocity=np.array([row["velocity"] for row in rows], dtype=float),
        digest=hashlib.sha256(text.encode()).hexdigest(),
    )


def check_planet(body: str) -> int:
    """Index of a planet in :data:`PLANETS`, or a clear error.

    Parameters
    ----------
    body : str
        A planet's name (case-insensitive).

    Returns
    -------
    int

    Examples
    --------
    >>> check_planet("Mars")
    3
    >>> check_planet("pluto")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a planet among mercury, venus, ..., neptune, got 'pluto'
    """
    name = str(body).lower()
    if name not in PLANETS:
        msg = f"expected a planet among {', '.join(PLANETS)}, got {body!r}"
        raise ValueError(msg)
    return PLANETS.index(name)
