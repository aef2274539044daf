"""One entry point for every orbit source: a name or a table file."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from andoyer.planetary.orbits.planets import PLANETS, check_planet
from andoyer.planetary.orbits.protocol import OrbitHistory

__all__ = ["SOURCES", "orbit_history", "source_span"]

#: The named orbit sources.
SOURCES = ("vondrak", "nbody", "secular", "laplace-lagrange")


def orbit_history(source: str | os.PathLike[str], body: str = "earth", **options: Any) -> OrbitHistory:
    """The orbit history of ``body`` from a named source or a table file.

    Parameters
    ----------
    source : str or path-like
        ``"vondrak"`` (the Earth only), ``"nbody"``, ``"secular"`` (the long secular model),
        ``"laplace-lagrange"`` (the linear theory), or the path of a CSV
        table (:func:`~andoyer.planetary.orbits.table.read_orbit_csv`; a table holds one orbit, so
        ``body`` is not used).
    body : str
        A planet of :data:`~andoyer.planetary.orbits.planets.PLANETS`.
    **options
        Passed to :class:`~andoyer.planetary.orbits.nbody.NBodyOrbit`,
        :class:`~andoyer.planetary.orbits.secular.SecularOrbit` or
        :class:`~andoyer.planetary.orbits.laplace_lagrange.LaplaceLagrangeOrbit`.

    Returns
    -------
    OrbitHistory

    Examples
    --------
    >>> orbit_history("secular", "mars").name
    'secular'
    >>> orbit_history("vondrak", "mars")
    Traceback (most recent call last):
    ...
    ValueError: expected body 'earth' for the vondrak orbit (the ecliptic), got 'mars'
    """
    name = str(source)
    if name in SOURCES:
        planet = PLANETS[check_planet(body)]
        if name == "vondrak":
            from andoyer.planetary.orbits.vondrak import VondrakEcliptic

            if planet != "earth":
                msg = f"expected body 'earth' for the vondrak orbit (the ecliptic), got {body!r}"
                raise ValueError(msg)
            if options:
                msg = f"expected no options for the vondrak orbit, got {', '.join(sorted(options))}"
                raise ValueError(msg)
            return VondrakEcliptic()
        if name == "nbody":
            from andoyer.planetary.orbits.nbody import NBodyOrbit

            return NBodyOrbit(planet, **options)
        if name == "laplace-lagrange":
            from andoyer.planetary.orbits.laplace_lagrange import LaplaceLagrangeOrbit

            return LaplaceLagrangeOrbit(planet, **options)
        from andoyer.planetary.orbits.secular import SecularOrbit

        return SecularOrbit(planet, **options)
    path = Path(name)
    if not path.is_file():
        msg = f"expected an orbit source among {', '.join(SOURCES)} or an existing table file, got {name!r}"
        raise ValueError(msg)
    if path.suffix.lower() != ".csv":
        msg = (
            f"expected a .csv orbit table (La2010-style alkhqp files: "
            f"andoyer.planetary.orbits.read_alkhqp with the "
            f"frame's rotation), got {name!r}"
        )
        raise ValueError(msg)
    if options:
        msg = f"expected no options for an orbit table, got {', '.join(sorted(options))}"
        raise ValueError(msg)
    from andoyer.planetary.orbits.table import read_orbit_csv

    return read_orbit_csv(path)


def source_span(source: str, body: str = "earth") -> tuple[float, float]:
    """The span of validity ``(t_min, t_max)`` (Julian years from J2000) of a named orbit source.

    Read without building the source (an N-body orbit is integrated only when first asked).

    Parameters
    ----------
    source : {"vondrak", "nbody", "secular", "laplace-lagrange"}
    body : str
        A planet of :data:`~andoyer.planetary.orbits.planets.PLANETS` (``vondrak``: the Earth only).

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> source_span("vondrak"), source_span("nbody", "mars")
    ((-200000.0, 200000.0), (-50000000.0, 50000000.0))
    """
    planet = PLANETS[check_planet(body)]
    name = str(source)
    if name == "vondrak":
        from andoyer.planetary.orbits.vondrak import VondrakEcliptic

        if planet != "earth":
            msg = f"expected body 'earth' for the vondrak orbit (the ecliptic), got {body!r}"
            raise ValueError(msg)
        return tuple(map(float, VondrakEcliptic.span))  # type: ignore[return-value]
    if name == "nbody":
        import inspect

        from andoyer.planetary.orbits.nbody import NBodyOrbit

        most = float(inspect.signature(NBodyOrbit).parameters["max_span"].default)
        return (-most, most)
    if name == "secular":
        from andoyer.planetary.orbits.secular import SecularOrbit

        return tuple(map(float, SecularOrbit.span))  # type: ignore[return-value]
    if name == "laplace-lagrange":
        from andoyer.planetary.orbits.laplace_lagrange import LaplaceLagrangeOrbit

        return tuple(map(float, LaplaceLagrangeOrbit.span))  # type: ignore[return-value]
    msg = f"expected a named orbit source among {', '.join(SOURCES)}, got {source!r}"
    raise ValueError(msg)
