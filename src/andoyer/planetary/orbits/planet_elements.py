r"""The planets' classical elements over time: a sibling of the :class:`OrbitHistory` protocol.

:class:`~andoyer.planetary.orbits.protocol.OrbitHistory` gives one body's orbit normal and
eccentricity vector, what the spin axis needs. This module gives what a user asks of an orbit
source (``andoyer orbit``): the elements of several planets,

* ``a``, the semi-major axis (au);
* ``e``, the eccentricity;
* ``inclination`` ``i``, ``node`` ``Ω`` and ``perihelion`` ``ϖ = Ω + ω`` (radians here,
  degrees at the command line), J2000 ecliptic and equinox,

each where the source knows it (``known``). An :class:`ElementsHistory` is one planet's; the
adapters are :class:`ElementsFromOrbit` (any ``OrbitHistory``, its ``i, Ω`` from the normal,
``e, ϖ`` from the eccentricity vector, :func:`~andoyer.planetary.orbits.elements.elements_from_vectors`,
and ``a`` where given) and :class:`TabulatedElements` (scalar columns of a file, cubic
splines). :class:`PlanetOrbits` gathers the planets of one source and answers
:meth:`PlanetOrbits.elements` with an :class:`OrbitElements` record.

Examples
--------
>>> from andoyer.planetary.orbits import VondrakEcliptic
>>> earth = ElementsFromOrbit(VondrakEcliptic())
>>> sorted(earth.known)
['inclination', 'node']
>>> system = PlanetOrbits({"earth": earth}, name="vondrak")
>>> record = system.elements([0.0, 1000.0])
>>> record.values["earth"]["e"] is None, round(float(np.degrees(record.values["earth"]["inclination"][1])), 4)
(True, 0.1296)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.planetary.orbits.elements import elements_from_vectors
from andoyer.planetary.orbits.planets import PLANETS, check_planet
from andoyer.planetary.orbits.protocol import OrbitHistory, check_times

__all__ = [
    "ELEMENTS",
    "ElementsFromOrbit",
    "ElementsHistory",
    "OrbitElements",
    "PlanetOrbits",
    "TabulatedElements",
]

Array = NDArray[np.float64]

#: The elements, in the order of every output: ``a`` (au), ``e``, then angles (radians).
ELEMENTS = ("a", "e", "inclination", "perihelion", "node")
#: Their units at the command line and in files.
UNITS = {"a": "au", "e": "1", "inclination": "deg", "perihelion": "deg", "node": "deg"}
_ANGLES = ("inclination", "perihelion", "node")


@runtime_checkable
class ElementsHistory(Protocol):
    """One planet's classical elements over time, those the source knows.

    Attributes
    ----------
    name : str
        The source.
    span : tuple of float
        ``(t_min, t_max)``, Julian years from J2000.
    known : frozenset of str
        The elements of :data:`ELEMENTS` that :meth:`elements` returns.
    """

    name: str
    span: tuple[float, float]
    known: frozenset[str]

    def elements(self, t: ArrayLike) -> dict[str, Array]:
        """The known elements at ``t`` (shape ``t.shape`` each; au and radians)."""
        ...


class ElementsFromOrbit:
    """The elements of an :class:`OrbitHistory`: ``i, Ω`` from its normal, ``e, ϖ`` from its ellipse.

    Parameters
    ----------
    orbit : OrbitHistory
    semi_major_axis : float or callable, optional
        ``a`` in au, constant or a function of ``t`` (years); ``None``: not known.

    Examples
    --------
    >>> from andoyer.planetary.orbits import SecularOrbit
    >>> mars = ElementsFromOrbit(SecularOrbit("mars"), semi_major_axis=1.5237)
    >>> values = mars.elements(0.0)
    >>> round(float(values["e"]), 3), round(float(np.degrees(values["perihelion"])), 1)
    (0.093, 336.1)
    """

    def __init__(self, orbit: OrbitHistory, semi_major_axis: float | Callable[[Array], Array] | None = None):
        if not isinstance(orbit, OrbitHistory):
            msg = f"expected an OrbitHistory (normal, eccentricity_vector, span), got {type(orbit).__name__}"
            raise ValueError(msg)
        if semi_major_axis is not None and not callable(semi_major_axis):
            a = float(semi_major_axis)
            if not (np.isfinite(a) and a > 0):
                msg = f"expected a positive semi-major axis (au), got {semi_major_axis!r}"
                raise ValueError(msg)
        self.orbit = orbit
        self.name = orbit.name
        self.span = tuple(map(float, orbit.span))
        self._a = semi_major_axis
        known = {"inclination", "node"}
        if orbit.has_eccentricity:
            known |= {"e", "perihelion"}
        if semi_major_axis is not None:
            known.add("a")
        self.known = frozenset(known)

    def elements(self, t: ArrayLike) -> dict[str, Array]:
        """The known elements at ``t``.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, within ``span``.

        Returns
        -------
        dict of str to numpy.ndarray, each of shape (...)
        """
        times = check_times(t, self.span, self.name)
        n = self.orbit.normal(times)
        if self.orbit.has_eccentricity:
            e, inc, node, varpi = elements_from_vectors(n, self.orbit.eccentricity_vector(times))
            out = {"e": e, "inclination": inc, "perihelion": varpi, "node": node}
        else:
            _, inc, node, _ = elements_from_vectors(n, np.zeros_like(n))
            out = {"inclination": inc, "node": node}
        if self._a is not None:
            a = self._a(times) if callable(self._a) else np.full(times.shape, float(self._a))
            out["a"] = np.asarray(a, dtype=float)
        return out

    def __repr__(self) -> str:
        return f"ElementsFromOrbit({self.orbit!r})"


class TabulatedElements:
    """Scalar elements tabulated in time (``e`` alone, or ``a`` and ``e``), cubic splines.

    For a file that gives no orbit plane (an eccentricity solution): what it gives, as elements.

    Parameters
    ----------
    t : array_like, shape (N,)
        Julian years from J2000, strictly increasing, ``N ≥ 4``.
    columns : mapping of str to array_like, shape (N,)
        Elements among ``a`` and ``e``.
    name : str

    Examples
    --------
    >>> table = TabulatedElements([0.0, 1.0, 2.0, 3.0], {"e": [0.1, 0.2, 0.3, 0.4]}, name="ecc")
    >>> round(float(table.elements(1.5)["e"]), 12), sorted(table.known)
    (0.25, ['e'])
    """

    def __init__(self, t: ArrayLike, columns: Mapping[str, ArrayLike], name: str) -> None:
        from scipy.interpolate import CubicSpline

        times = np.asarray(t, dtype=float)
        if times.ndim != 1 or times.size < 4 or not np.all(np.diff(times) > 0):
            msg = f"expected at least 4 strictly increasing times, got {times.size} times"
            raise ValueError(msg)
        unknown = sorted(set(columns) - {"a", "e"})
        if unknown:
            msg = f"expected tabulated elements among a, e, got {', '.join(unknown)}"
            raise ValueError(msg)
        self.name = name
        self.span = (float(times[0]), float(times[-1]))
        self.known = frozenset(columns)
        self._splines = {k: CubicSpline(times, np.asarray(v, dtype=float)) for k, v in columns.items()}

    def elements(self, t: ArrayLike) -> dict[str, Array]:
        """The tabulated elements at ``t``.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, within ``span``.

        Returns
        -------
        dict of str to numpy.ndarray, each of shape (...)
        """
        times = check_times(t, self.span, self.name)
        return {k: np.asarray(s(times), dtype=float) for k, s in self._splines.items()}

    def __repr__(self) -> str:
        return f"TabulatedElements(name={self.name!r}, known={sorted(self.known)})"


@dataclass(frozen=True)
class OrbitElements:
    """The elements of several planets at the times ``t`` (au and radians; ``None``: not known).

    Attributes
    ----------
    source : str
    t : numpy.ndarray, shape (T,)
        Julian years from J2000.
    planets : tuple of str
    values : mapping
        ``values[planet][element]``: an array of shape (T,), or ``None`` where the source does
        not know that element.
    """

    source: str
    t: Array
    planets: tuple[str, ...]
    values: Mapping[str, Mapping[str, Array | None]]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: ``source``, ``t`` (years), ``planets``, ``elements`` (au, degrees; ``None`` unknown).

        Examples
        --------
        >>> record = OrbitElements("demo", np.array([0.0]), ("mars",),
        ...                        {"mars": dict.fromkeys(ELEMENTS) | {"e": np.array([0.09])}})
        >>> record.as_dict()["elements"]["mars"]["e"], record.as_dict()["elements"]["mars"]["node"]
        ([0.09], None)
        """

        def show(name: str, value: Array | None) -> list[float] | None:
            if value is None:
                return None
            return (np.degrees(value) if name in _ANGLES else value).tolist()

        return {
            "source": self.source,
            "t": self.t.tolist(),
            "planets": list(self.planets),
            "elements": {p: {k: show(k, self.values[p].get(k)) for k in ELEMENTS} for p in self.planets},
        }

    def columns(self) -> dict[str, Array]:
        """Each element as an array (T, P) in au and degrees, NaN where not known."""
        out = {}
        for k in ELEMENTS:
            table = np.full((self.t.size, len(self.planets)), np.nan)
            for j, p in enumerate(self.planets):
                value = self.values[p].get(k)
                if value is not None:
                    table[:, j] = np.degrees(value) if k in _ANGLES else value
            out[k] = table
        return out

    def to_dataset(self):
        """An :class:`xarray.Dataset`: dims ``time``, ``planet``; au and degrees, NaN where not known.

        Requires xarray (the ``ensemble`` extra).
        """
        import xarray as xr

        data = {
            k: (("time", "planet"), v, {"units": UNITS[k], "frame": "J2000 ecliptic and equinox"})
            for k, v in self.columns().items()
        }
        coords = {
            "time": ("time", self.t, {"units": "Julian years TT from J2000"}),
            "planet": list(self.planets),
        }
        return xr.Dataset(data, coords=coords, attrs={"source": self.source})


class PlanetOrbits:
    """The planets of one orbit source: their :class:`ElementsHistory`, and their elements at any times.

    Parameters
    ----------
    members : mapping of str to ElementsHistory
        Planet name (of :data:`~andoyer.planetary.orbits.planets.PLANETS`) to its history.
    name : str
        The source.

    Attributes
    ----------
    planets : tuple of str
        In :data:`PLANETS` order.
    span : tuple of float
        Where every member is valid.

    Examples
    --------
    >>> from andoyer.planetary.orbits import SecularOrbit
    >>> system = PlanetOrbits({p: ElementsFromOrbit(SecularOrbit(p)) for p in ("mars", "earth")}, "secular")
    >>> system.planets
    ('earth', 'mars')
    >>> record = system.elements(np.linspace(0.0, 1e4, 3), planets=["mars"])
    >>> record.planets, record.values["mars"]["e"].shape
    (('mars',), (3,))
    """

    def __init__(self, members: Mapping[str, ElementsHistory], name: str) -> None:
        if not members:
            msg = "expected at least one planet's elements, got none"
            raise ValueError(msg)
        for planet, member in members.items():
            check_planet(planet)
            if not isinstance(member, ElementsHistory):
                msg = f"expected an ElementsHistory for {planet!r}, got {type(member).__name__}"
                raise ValueError(msg)
        order = sorted(members, key=lambda p: PLANETS.index(p.lower()))
        self.members = {p.lower(): members[p] for p in order}
        self.planets = tuple(self.members)
        self.name = name
        self.span = (
            max(float(m.span[0]) for m in self.members.values()),
            min(float(m.span[1]) for m in self.members.values()),
        )

    def select(self, planets: Sequence[str] | None) -> tuple[str, ...]:
        """The planets asked for, in :data:`PLANETS` order; ``None``: all of this source's."""
        if planets is None:
            return self.planets
        chosen = []
        for p in planets:
            name = PLANETS[check_planet(p)]
            if name not in self.members:
                msg = f"expected planets of the {self.name} orbit ({', '.join(self.planets)}), got {p!r}"
                raise ValueError(msg)
            if name not in chosen:
                chosen.append(name)
        return tuple(sorted(chosen, key=PLANETS.index))

    def elements(self, t: ArrayLike, planets: Sequence[str] | None = None) -> OrbitElements:
        """The elements of ``planets`` (default: all) at the times ``t``.

        Parameters
        ----------
        t : array_like, shape (T,)
            Julian years from J2000, within ``span``.
        planets : sequence of str, optional

        Returns
        -------
        OrbitElements
        """
        times = check_times(np.atleast_1d(np.asarray(t, dtype=float)), self.span, self.name)
        if times.ndim != 1:
            msg = f"expected a one-dimensional array of times, got shape {times.shape}"
            raise ValueError(msg)
        chosen = self.select(planets)
        values = {}
        for p in chosen:
            got = self.members[p].elements(times)
            values[p] = {k: got.get(k) for k in ELEMENTS}
        return OrbitElements(self.name, times, chosen, values)

    def __repr__(self) -> str:
        return f"PlanetOrbits(name={self.name!r}, planets={self.planets})"
