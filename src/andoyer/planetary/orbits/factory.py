"""One entry point for every orbit source: a name, a table file or a published solution file.

A file's format is recognised from its name (``INSOLN.LA2004.BTL.ASC``, ``La2010a_alkhqp3L.dat``,
``ems-plan3.dat``, ``ZB20a.dat``, ``ZB23.R01.eiop.dat``, ``*.csv``), else from its first data row
(a comma: CSV; else the number of columns: 2 ``la2010-ecc``, 3 ``zb-ecc``, 4 ``la2004``,
5 ``zb23``, 7 ``la2010``, 8 ``zb18a``), or named (``orbit_format=``). docs/orbits.md describes
each format, its frame and its units.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from andoyer.planetary.orbits.planets import PLANETS, check_planet
from andoyer.planetary.orbits.protocol import OrbitHistory

if TYPE_CHECKING:
    from andoyer.planetary.orbits.planet_elements import PlanetOrbits
    from andoyer.planetary.orbits.solutions import SolutionFile

__all__ = [
    "SOLUTION_FORMATS",
    "SOURCES",
    "orbit_history",
    "planet_orbits",
    "read_solution",
    "solution_format",
    "source_span",
]

#: The named orbit sources.
SOURCES = ("vondrak", "nbody", "secular", "laplace-lagrange")
#: The file formats read (docs/orbits.md): the IMCCE's, Zeebe's and the project's CSV table.
SOLUTION_FORMATS = ("la2004", "la2010", "la2010-ecc", "zb18a", "zb-ecc", "zb23", "csv")
#: A format by the number of columns of its first data row.
_BY_COLUMNS = {2: "la2010-ecc", 3: "zb-ecc", 4: "la2004", 5: "zb23", 7: "la2010", 8: "zb18a"}


def solution_format(path: str | os.PathLike[str]) -> str:
    r"""The format of an orbit or solution file, from its name or else its first data row.

    Parameters
    ----------
    path : str or path-like
        An existing file.

    Returns
    -------
    str
        One of :data:`SOLUTION_FORMATS`.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "earth.dat"
    >>> _ = path.write_text("0 1.0 0.1 0.0167 0.0 0.0 0.0\n")
    >>> solution_format(path), solution_format("INSOLN.LA2004.BTL.ASC")
    ('la2010', 'la2004')
    """
    from andoyer.planetary.orbits import imcce, zeebe
    from andoyer.planetary.orbits.numeric_text import first_row

    name = Path(path).name
    if name.lower().endswith(".csv"):
        return "csv"
    by_name = imcce.format_from_name(name) or zeebe.format_from_name(name)
    if by_name is not None:
        return by_name
    if "," in first_row(path, header_lines=0)[1]:  # a CSV table's header row
        return "csv"
    line, text = first_row(path)
    fields = text.replace("D", "E").replace("d", "e").split()  # Fortran exponents (La2004)
    try:
        [float(x) for x in fields]
    except ValueError:
        fields = []
    columns = len(fields)
    if columns not in _BY_COLUMNS:
        where = f"{columns} columns on line {line}" if columns else f"a line not of numbers (line {line})"
        if not line:
            where = "no rows (an empty file)"
        msg = (
            f"expected an orbit or solution file of a known format ({', '.join(SOLUTION_FORMATS)}; "
            f"name it with --orbit-format), got {where} of {str(path)!r}"
        )
        raise ValueError(msg)
    return _BY_COLUMNS[columns]


def _existing_file(path: str | os.PathLike[str]) -> Path:
    file = Path(path)
    if not file.is_file():
        msg = f"expected an existing orbit or solution file, got {str(path)!r}"
        raise ValueError(msg)
    return file


def read_solution(path: str | os.PathLike[str], orbit_format: str | None = None) -> SolutionFile:
    r"""Read a published solution file (La2004, La2010, ZB18a, ZB20, ZB23), J2000 ecliptic.

    Parameters
    ----------
    path : str or path-like
    orbit_format : str, optional
        One of :data:`SOLUTION_FORMATS` but ``"csv"``; default: :func:`solution_format`.

    Returns
    -------
    SolutionFile

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ZB20a.dat"
    >>> _ = path.write_text("".join(f"{k} 0.0{k + 1} 1.5\n" for k in range(4)))
    >>> sol = read_solution(path)
    >>> sol.format, sol.span
    ('zb-ecc', (-3000.0, 0.0))
    """
    from andoyer.planetary.orbits import imcce, zeebe

    file = _existing_file(path)
    fmt = solution_format(file) if orbit_format is None else str(orbit_format).lower()
    readers = {
        "la2004": imcce.read_la2004,
        "la2010": imcce.read_la2010,
        "la2010-ecc": imcce.read_la2010_ecc,
        "zb18a": zeebe.read_zb18a,
        "zb-ecc": zeebe.read_zb_ecc,
        "zb23": zeebe.read_zb23,
    }
    if fmt not in readers:
        shown = "a CSV table (read_orbit_csv)" if fmt == "csv" else repr(orbit_format)
        msg = f"expected a solution format among {', '.join(readers)}, got {shown} for {str(path)!r}"
        raise ValueError(msg)
    return readers[fmt](file)


def orbit_history(
    source: str | os.PathLike[str], body: str = "earth", orbit_format: str | None = None, **options: Any
) -> OrbitHistory:
    """The orbit history of ``body`` from a named source, a table file or a solution file.

    Parameters
    ----------
    source : str or path-like
        ``"vondrak"`` (the Earth only), ``"nbody"``, ``"secular"`` (the long secular model),
        ``"laplace-lagrange"`` (the linear theory), or the path of a CSV
        table (:func:`~andoyer.planetary.orbits.table.read_orbit_csv`; a table holds one orbit, so
        ``body`` is not used) or of an orbit solution (La2010 ``alkhqp``, ZB18a full;
        :func:`read_solution`: it must be ``body``'s orbit).
    body : str
        A planet of :data:`~andoyer.planetary.orbits.planets.PLANETS`.
    orbit_format : str, optional
        A file's format (:data:`SOLUTION_FORMATS`); default: recognised (:func:`solution_format`).
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
        if orbit_format is not None:
            msg = f"expected orbit_format only with a file, got {orbit_format!r} for the {name} orbit"
            raise ValueError(msg)
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
    if not Path(name).is_file():
        msg = f"expected an orbit source among {', '.join(SOURCES)} or an existing table file, got {name!r}"
        raise ValueError(msg)
    if options:
        msg = f"expected no options for an orbit file, got {', '.join(sorted(options))}"
        raise ValueError(msg)
    fmt = solution_format(name) if orbit_format is None else str(orbit_format).lower()
    if fmt == "csv":
        from andoyer.planetary.orbits.table import read_orbit_csv

        return read_orbit_csv(name)
    solution = read_solution(name, fmt)
    planet = PLANETS[check_planet(body)]
    if solution.planet is not None and solution.planet != planet:
        msg = f"expected an orbit of {planet}, got the {solution.planet}'s orbit in {name!r}"
        raise ValueError(msg)
    return solution.orbit()


def planet_orbits(
    source: str | os.PathLike[str],
    planets: list[str] | tuple[str, ...] | None = None,
    orbit_format: str | None = None,
    **options: Any,
) -> PlanetOrbits:
    """The classical elements of the planets of a named source or a file (``andoyer orbit``).

    What each source knows: ``nbody``, ``secular`` and ``laplace-lagrange`` every planet's
    ``e, i, ϖ, Ω`` (``a``: the secular models' constant mean semi-major axes, Standish's for
    the linear theory; not kept by the N-body cache, so unknown there); ``vondrak`` the
    Earth's ``i, Ω`` (the ecliptic, no ellipse); a file its planet's (a CSV table: the Earth's
    unless ``planets`` names another), an eccentricity or climate solution ``e`` (and ``a``).

    Parameters
    ----------
    source : str or path-like
        A name of :data:`SOURCES` or a file (:func:`orbit_history`).
    planets : sequence of str, optional
        The planets built (default: all the source knows); for a CSV table, one planet.
    orbit_format : str, optional
        A file's format (:data:`SOLUTION_FORMATS`).
    **options
        Passed to each planet's orbit (:func:`orbit_history`).

    Returns
    -------
    PlanetOrbits

    Examples
    --------
    >>> system = planet_orbits("laplace-lagrange", ["mars", "earth"])
    >>> system.planets, sorted(system.members["mars"].known)
    (('earth', 'mars'), ['a', 'e', 'inclination', 'node', 'perihelion'])
    """
    from andoyer.planetary.orbits.planet_elements import ElementsFromOrbit, PlanetOrbits

    name = str(source)
    chosen = None if planets is None else [PLANETS[check_planet(p)] for p in planets]
    if name in SOURCES:
        if name == "vondrak":
            if chosen is not None and set(chosen) != {"earth"}:
                msg = f"expected planets earth for the vondrak orbit (the ecliptic), got {', '.join(chosen)}"
                raise ValueError(msg)
            chosen = ["earth"]
        chosen = list(PLANETS) if chosen is None else chosen
        if name == "secular":
            from andoyer.planetary.orbits.secular import secular_model

            a = secular_model().a
        elif name == "laplace-lagrange":
            from andoyer.planetary.orbits.planets import planet_data

            a = planet_data().a
        else:
            a = None
        if name == "secular":  # one integration for all the planets asked for
            from andoyer.planetary.orbits.secular import SecularOrbit

            orbits = SecularOrbit.system(chosen, **options)
        else:
            orbits = {p: orbit_history(name, p, **options) for p in chosen}
        members = {
            p: ElementsFromOrbit(orbit, None if a is None else float(a[PLANETS.index(p)]))
            for p, orbit in orbits.items()
        }
        return PlanetOrbits(members, name)
    file = _existing_file(name)
    if options:
        msg = f"expected no options for an orbit file, got {', '.join(sorted(options))}"
        raise ValueError(msg)
    fmt = solution_format(file) if orbit_format is None else str(orbit_format).lower()
    if fmt == "csv":
        from andoyer.planetary.orbits.table import read_orbit_csv

        if chosen is not None and len(set(chosen)) != 1:
            msg = f"expected one planet for a CSV orbit table (it holds one orbit), got {', '.join(chosen)}"
            raise ValueError(msg)
        planet = "earth" if chosen is None else chosen[0]
        return PlanetOrbits({planet: ElementsFromOrbit(read_orbit_csv(file))}, file.name)
    solution = read_solution(file, fmt)
    planet = solution.planet or "earth"
    if chosen is not None and set(chosen) != {planet}:
        msg = f"expected planets {planet} for {file.name} (the {planet}'s orbit), got {', '.join(chosen)}"
        raise ValueError(msg)
    return PlanetOrbits({planet: solution.history()}, file.name)


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
