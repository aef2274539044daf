r"""A published solution file, read: its times, what it gives of the orbit, in the J2000 ecliptic.

Every reader of :mod:`~andoyer.planetary.orbits.imcce` (La2004, La2010) and
:mod:`~andoyer.planetary.orbits.zeebe` (ZB18a, ZB20, ZB23) returns a :class:`SolutionFile`:
the times in Julian years from J2000, increasing (the files run backwards from J2000 as often
as not), and the quantities the file gives, turned into the J2000 ecliptic and equinox where
they are angles of the orbit:

* an *orbit solution* (La2010's ``alkhqp`` files, ZB18a's full HNBody output, a CSV table) gives
  the orbit plane and the ellipse: :meth:`SolutionFile.orbit` is an
  :class:`~andoyer.planetary.orbits.protocol.OrbitHistory` (an ``andoyer obliquity --orbit``);
* an *eccentricity* or *climate solution* (La2004's ``INSOL`` files, La2010's ``ecc`` files,
  Zeebe's ``ZB18a-300``, ``ZB20x``, ``ZB23.Rxx``) gives ``e`` and, some of them, the obliquity
  and ``ϖ`` from the moving equinox of date — not the orbit plane, so not an orbit for the
  spin axis (:meth:`SolutionFile.orbit` says so), but its ``e`` is an element
  (:meth:`SolutionFile.history`).

``frame`` says how the file's frame was turned into the J2000 ecliptic (the rotation, stated).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from andoyer.planetary.orbits.numeric_text import Table
from andoyer.planetary.orbits.planet_elements import ElementsFromOrbit, ElementsHistory, TabulatedElements
from andoyer.planetary.parameters import PARAMETERS

__all__ = ["SolutionFile", "check_column", "increasing"]

Array = NDArray[np.float64]

#: Rows kept beyond a window on each side (the cubic spline's end conditions stay outside it).
WINDOW_MARGIN = 3


@dataclass(frozen=True)
class SolutionFile:
    """What a published solution file gives, on an increasing time grid, J2000 ecliptic.

    Attributes
    ----------
    path : str
    format : str
        ``"la2004"``, ``"la2010"``, ``"la2010-ecc"``, ``"zb18a"``, ``"zb-ecc"``, ``"zb23"``.
    planet : str or None
        The planet whose orbit it is, where the file's name or format says so.
    t : numpy.ndarray, shape (N,)
        Julian years from J2000, strictly increasing.
    e : numpy.ndarray, shape (N,)
        Eccentricity.
    a : numpy.ndarray, shape (N,), optional
        Semi-major axis (au).
    normal, eccentricity_vector : numpy.ndarray, shape (N, 3), optional
        The orbit plane's unit normal and ``e`` times the unit vector to perihelion (J2000
        ecliptic), where the file gives the orbit plane.
    obliquity : numpy.ndarray, shape (N,), optional
        The obliquity (radians), climate solutions.
    perihelion_of_date : numpy.ndarray, shape (N,), optional
        ``ϖ`` from the moving equinox of date (radians; La2004).
    climatic_precession : numpy.ndarray, shape (N,), optional
        ``e sin ϖ`` (ϖ of date).
    frame : str
        How the file's frame was turned into the J2000 ecliptic.
    """

    path: str
    format: str
    planet: str | None
    t: Array
    e: Array
    a: Array | None = None
    normal: Array | None = None
    eccentricity_vector: Array | None = None
    obliquity: Array | None = None
    perihelion_of_date: Array | None = None
    climatic_precession: Array | None = None
    frame: str = ""

    @property
    def span(self) -> tuple[float, float]:
        """``(t_min, t_max)``, Julian years from J2000."""
        return float(self.t[0]), float(self.t[-1])

    @property
    def has_plane(self) -> bool:
        """Whether the file gives the orbit plane (an orbit solution)."""
        return self.normal is not None

    def window(self, t0: float, t1: float) -> SolutionFile:
        """The rows about ``[t0, t1]`` (a few beyond each end), to interpolate a long file cheaply.

        Examples
        --------
        >>> sol = SolutionFile("f", "la2010-ecc", "earth", np.arange(10.0), np.full(10, 0.01))
        >>> sol.window(4.5, 5.0).t.tolist()
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]
        """
        lo = max(int(np.searchsorted(self.t, t0, side="right")) - 1 - WINDOW_MARGIN, 0)
        hi = min(int(np.searchsorted(self.t, t1, side="left")) + 1 + WINDOW_MARGIN, self.t.size)
        lo, hi = min(lo, max(self.t.size - 4, 0)), max(hi, min(lo + 4, self.t.size))
        cut = {}
        for field in dataclasses.fields(self):
            value = getattr(self, field.name)
            if isinstance(value, np.ndarray) and value.shape[:1] == self.t.shape:
                cut[field.name] = value[lo:hi]
        return dataclasses.replace(self, **cut)

    def describe(self) -> str:
        """What the file holds, in words (for messages)."""
        if self.has_plane:
            return "an orbit solution (the orbit plane and the ellipse)"
        extra = []
        if self.obliquity is not None:
            extra.append("the obliquity")
        if self.perihelion_of_date is not None:
            extra.append("the perihelion from the moving equinox")
        if self.climatic_precession is not None and self.perihelion_of_date is None:
            extra.append("the climatic precession")
        return "the eccentricity" + "".join(f", {x}" for x in extra) + ", no orbit plane"

    def orbit(self):
        """The orbit history (cubic splines of the vectors), for an orbit solution.

        Returns
        -------
        TableOrbit

        Raises
        ------
        ValueError
            For a file without the orbit plane (an eccentricity or climate solution).
        """
        from andoyer.planetary.orbits.table import TableOrbit

        if not self.has_plane:
            msg = (
                f"expected an orbit solution with the orbit plane (la2010 alkhqp, zb18a full, csv), "
                f"got the {self.format} file {self.path!r}: {self.describe()}"
            )
            raise ValueError(msg)
        name = self.path.replace("\\", "/").rsplit("/", 1)[-1]
        return TableOrbit(self.t, self.normal, self.eccentricity_vector, name=name)

    def history(self) -> ElementsHistory:
        """The elements the file gives (``a`` and ``e`` by cubic splines; the plane through :meth:`orbit`).

        Returns
        -------
        ElementsHistory
        """
        name = self.path.replace("\\", "/").rsplit("/", 1)[-1]
        if self.has_plane:
            a = None
            if self.a is not None:
                from scipy.interpolate import CubicSpline

                a = CubicSpline(self.t, self.a)
            return ElementsFromOrbit(self.orbit(), semi_major_axis=a)
        columns = {"e": self.e} if self.a is None else {"a": self.a, "e": self.e}
        return TabulatedElements(self.t, columns, name=name)


def check_column(table: Table, values: Array, parameter: str, column: str, degrees: bool = False) -> None:
    """Refuse the first value of ``values`` (one per row of ``table``) outside a parameter's range.

    Parameters
    ----------
    table : Table
        The file's rows (for the line of the message).
    values : numpy.ndarray, shape (N,)
    parameter : str
        A key of :data:`andoyer.planetary.parameters.PARAMETERS`.
    column : str
        Named in the message.
    degrees : bool
        The values are degrees (an angle's range converted).

    Raises
    ------
    ValueError
        ``expected a <name> <range> (<reason>), got <value> in column <c> on line <n> of <path>``.
    """
    p = PARAMETERS[parameter]
    x = np.radians(values) if degrees and p.unit == "rad" else values
    above = x >= p.low if p.low_closed else x > p.low
    below = x <= p.high if p.high_closed else x < p.high
    bad = np.flatnonzero(~(above & below))
    if bad.size:
        k = int(bad[0])
        try:
            p.check(float(values[k]), degrees)
        except ValueError as exc:
            msg = f"{exc} in column {column} on line {table.line(k)} of {table.path!r}"
            raise ValueError(msg) from None


def increasing(t: Array) -> NDArray[np.intp]:
    """The row order that makes strictly monotonic times ``t`` increase (reversed or as they are)."""
    order = np.arange(t.size)
    return order[::-1] if t.size > 1 and t[1] < t[0] else order
