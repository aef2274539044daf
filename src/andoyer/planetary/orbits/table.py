r"""Orbit histories read from tables: CSV files and La2010-style ``alkhqp`` files.

**CSV** (comma-separated, one header row, ``#`` comment lines allowed anywhere), in one of
two column sets (extra columns are ignored):

* vectors: ``t_years, nx, ny, nz`` and optionally ``ex, ey, ez``: the orbit normal and the
  eccentricity vector in the J2000 ecliptic frame (as :class:`~andoyer.planetary.orbits.protocol.OrbitHistory`
  returns them);
* elements: ``t_years, e, inclination_deg, node_deg, varpi_deg``: eccentricity, inclination,
  longitude of the node and of perihelion (``ϖ = Ω + ω``) in degrees, J2000 ecliptic.

``t_kyr`` (thousands of Julian years from J2000) may replace ``t_years``.

**alkhqp** (whitespace-separated, no header, 7 columns, the layout of La2010's
``La2010X_alkhqp3L.dat`` files): ``t`` (kyr), ``a``, ``λ``, ``k = e cos ϖ``,
``h = e sin ϖ``, ``q = sin(i/2) cos Ω``, ``p = sin(i/2) sin Ω``. La2010 refers these to the
*invariable plane* of the Solar System, not to the J2000 ecliptic: the reader
(:func:`~andoyer.planetary.orbits.imcce.read_la2010`, the one reader of the format, and
:func:`~andoyer.planetary.orbits.imcce.read_alkhqp` for its orbit) takes a
``rotation`` (3×3, file frame → J2000 ecliptic) or fixes it from the file's J2000 row, and says
which. (La2004's ``INSOLN``/``INSOLP`` files tabulate e, the obliquity and ϖ of date: spin
quantities, not an orbit plane; they are not an orbit source.)

Interpolation: the vectors (elements are turned into vectors first, which avoids angle
wrap-around) are interpolated by a not-a-knot cubic spline in ``t``; the normal is
renormalised. Validity: the table's span. Times must increase strictly; at least 4 rows.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._files import atomic_write_bytes
from andoyer._validation import as_vectors
from andoyer.planetary.orbits.elements import eccentricity_from_elements, normal_from_elements
from andoyer.planetary.orbits.protocol import OrbitHistory, check_times
from andoyer.planetary.parameters import PARAMETERS

__all__ = ["TableOrbit", "read_orbit_csv", "write_orbit_csv"]

Array = NDArray[np.float64]
VECTOR_COLUMNS = ("nx", "ny", "nz")
ECC_COLUMNS = ("ex", "ey", "ez")
ELEMENT_COLUMNS = ("e", "inclination_deg", "node_deg", "varpi_deg")
MIN_ROWS = 4


class TableOrbit:
    """An orbit history interpolated (cubic spline) from tabulated vectors.

    Parameters
    ----------
    t : array_like, shape (N,)
        Julian years from J2000, strictly increasing, ``N ≥ 4``.
    normal : array_like, shape (N, 3)
        Orbit normals, J2000 ecliptic (unit to 1e-3; renormalised).
    eccentricity_vector : array_like, shape (N, 3), optional
        ``e`` times the unit vector to perihelion.
    name : str
        Named in errors and ``repr``.

    Examples
    --------
    >>> t = np.linspace(-1e4, 1e4, 5)
    >>> n = np.stack([np.zeros(5), 1e-3 * t / 1e4, np.ones(5)], axis=-1)
    >>> orbit = TableOrbit(t, n / np.linalg.norm(n, axis=-1, keepdims=True))
    >>> orbit.span, orbit.has_eccentricity
    ((-10000.0, 10000.0), False)
    >>> orbit.normal(5000.0).round(6).tolist()
    [0.0, 0.0005, 1.0]
    """

    def __init__(
        self,
        t: ArrayLike,
        normal: ArrayLike,
        eccentricity_vector: ArrayLike | None = None,
        name: str = "table",
    ) -> None:
        from scipy.interpolate import CubicSpline

        times = np.asarray(t, dtype=float)
        if times.ndim != 1 or times.size < MIN_ROWS:
            msg = f"expected at least {MIN_ROWS} rows for a cubic interpolation, got {times.size}"
            raise ValueError(msg)
        if not np.isfinite(times).all():
            k = int(np.flatnonzero(~np.isfinite(times))[0])
            msg = f"expected finite times, got {times[k]!r} at row {k + 1}"
            raise ValueError(msg)
        steps = np.diff(times)
        if np.any(steps <= 0):
            k = int(np.flatnonzero(steps <= 0)[0]) + 1
            msg = f"expected strictly increasing times, got {times[k]:g} after {times[k - 1]:g} (row {k + 1})"
            raise ValueError(msg)
        n = as_vectors(normal, "orbit normals")
        if n.shape != (times.size, 3):
            msg = f"expected orbit normals of shape ({times.size}, 3), got {n.shape}"
            raise ValueError(msg)
        length = np.linalg.norm(n, axis=-1)
        if np.any(np.abs(length - 1.0) > 1e-3):
            k = int(np.argmax(np.abs(length - 1.0)))
            msg = f"expected unit orbit normals, got length {length[k]:.6g} at row {k + 1}"
            raise ValueError(msg)
        self.name = name
        self.span = (float(times[0]), float(times[-1]))
        self._normal = CubicSpline(times, n / length[:, None], axis=0)
        self.has_eccentricity = eccentricity_vector is not None
        if eccentricity_vector is not None:
            e = as_vectors(eccentricity_vector, "eccentricity vectors")
            if e.shape != (times.size, 3):
                msg = f"expected eccentricity vectors of shape ({times.size}, 3), got {e.shape}"
                raise ValueError(msg)
            size = np.linalg.norm(e, axis=-1)
            if np.any(size >= 1.0):
                k = int(np.argmax(size))
                msg = f"expected eccentricities below 1, got {size[k]:.6g} at row {k + 1}"
                raise ValueError(msg)
            self._ecc = CubicSpline(times, e, axis=0)

    def normal(self, t: ArrayLike) -> Array:
        """Interpolated unit orbit normal, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, within ``span``.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        n = self._normal(check_times(t, self.span, self.name))
        return n / np.linalg.norm(n, axis=-1, keepdims=True)

    def eccentricity_vector(self, t: ArrayLike) -> Array:
        """Interpolated eccentricity vector, J2000 ecliptic frame.

        Parameters
        ----------
        t : array_like, shape (...)
            Julian years from J2000, within ``span``.

        Returns
        -------
        numpy.ndarray, shape (..., 3)
        """
        if not self.has_eccentricity:
            msg = f"expected a table with the eccentricity (ex, ey, ez or e, varpi_deg), got {self.name}"
            raise NotImplementedError(msg)
        return self._ecc(check_times(t, self.span, self.name))

    def __repr__(self) -> str:
        return f"TableOrbit(name={self.name!r}, span={self.span})"


def _text_lines(path: str | os.PathLike[str]) -> list[str]:
    """The lines of a UTF-8 text file (a byte-order mark, as spreadsheets write it, dropped).

    A file that is not UTF-8 text (a binary file, another encoding) is a :class:`ValueError`
    naming the file and the first byte that is not.
    """
    with open(path, "rb") as stream:
        data = stream.read()
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        msg = (
            f"expected a UTF-8 text file, got byte 0x{data[exc.start]:02x} on line {line} of "
            f"{str(path)!r} (a binary file or another encoding)"
        )
        raise ValueError(msg) from None
    return text.splitlines(keepends=True)


def _parse_rows(path: str | os.PathLike[str]) -> tuple[list[str], list[tuple[int, list[str]]]]:
    """Header and numbered data rows of a CSV file, ``#`` comment lines and blank lines skipped."""
    numbered = enumerate(_text_lines(path), start=1)
    lines = [(k, line) for k, line in numbered if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        msg = f"expected a CSV header row and data rows, got an empty file {str(path)!r}"
        raise ValueError(msg)
    # One record per line (a quote may not open a field over several lines), so that every row
    # keeps its line number for the errors.
    parsed = [next(csv.reader([line])) for _, line in lines]
    header = [name.strip() for name in parsed[0]]
    return header, [(number, row) for (number, _), row in zip(lines[1:], parsed[1:], strict=True)]


def read_orbit_csv(path: str | os.PathLike[str]) -> TableOrbit:
    r"""Read an orbit history from a CSV file (see the module's notes for the columns).

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    TableOrbit

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (folder / "orbit.csv").write_text(
    ...     "t_years,e,inclination_deg,node_deg,varpi_deg\n"
    ...     "-2000,0.017,0.02,170,101\n-1000,0.017,0.01,172,102\n"
    ...     "0,0.0167,0,174,103\n1000,0.0166,0.01,176,104\n"
    ... )
    >>> read_orbit_csv(folder / "orbit.csv").span
    (-2000.0, 1000.0)
    """
    header, rows = _parse_rows(path)
    if "t_years" in header:
        time_column, scale = "t_years", 1.0
    elif "t_kyr" in header:
        time_column, scale = "t_kyr", 1000.0
    else:
        msg = f"expected a time column t_years or t_kyr in {str(path)!r}, got columns {', '.join(header)}"
        raise ValueError(msg)
    if all(c in header for c in VECTOR_COLUMNS):
        with_ecc = all(c in header for c in ECC_COLUMNS)
        wanted = [time_column, *VECTOR_COLUMNS, *(ECC_COLUMNS if with_ecc else ())]
    elif all(c in header for c in ELEMENT_COLUMNS):
        wanted = [time_column, *ELEMENT_COLUMNS]
    else:
        msg = (
            f"expected the columns nx, ny, nz[, ex, ey, ez] or e, inclination_deg, node_deg, varpi_deg in "
            f"{str(path)!r}, got columns {', '.join(header)}"
        )
        raise ValueError(msg)
    index = [header.index(c) for c in wanted]
    values = np.empty((len(rows), len(wanted)))
    for r, (line, row) in enumerate(rows):
        if len(row) != len(header):
            msg = f"expected {len(header)} values on line {line} of {str(path)!r}, got {len(row)}"
            raise ValueError(msg)
        for c, k in enumerate(index):
            text = row[k].strip()
            try:
                value = float(text)
            except ValueError:
                msg = f"expected a number in column {wanted[c]} on line {line} of {str(path)!r}, got {text!r}"
                raise ValueError(msg) from None
            if not np.isfinite(value):
                msg = f"expected a finite number in column {wanted[c]} on line {line} of {path!s}, got {text}"
                raise ValueError(msg)
            values[r, c] = value
    t = values[:, 0] * scale
    lines = [line for line, _ in rows]
    if len(rows) >= 2 and np.any(np.diff(t) <= 0):
        k = int(np.flatnonzero(np.diff(t) <= 0)[0]) + 1
        msg = (
            f"expected strictly increasing times, got {values[k, 0]:g} after {values[k - 1, 0]:g} "
            f"on line {lines[k]} of {path!s}"
        )
        raise ValueError(msg)
    if wanted[1] == "nx":
        ecc = values[:, 4:7] if len(wanted) == 7 else None
        return TableOrbit(t, values[:, 1:4], ecc, name=Path(path).name)
    for c, name in ((1, "eccentricity"), (2, "inclination")):  # the ranges of andoyer.planetary.parameters
        inside = [PARAMETERS[name].contains(value, degrees=True) for value in values[:, c]]
        if not all(inside):
            k = inside.index(False)
            try:
                PARAMETERS[name].check(float(values[k, c]), degrees=True)
            except ValueError as exc:
                msg = f"{exc} in column {wanted[c]} on line {lines[k]} of {str(path)!r}"
                raise ValueError(msg) from None
    e, inc, node, varpi = values[:, 1], *np.radians(values[:, 2:5].T)
    normal = normal_from_elements(inc, node)
    return TableOrbit(t, normal, eccentricity_from_elements(e, inc, node, varpi), name=Path(path).name)


def write_orbit_csv(path: str | os.PathLike[str], orbit: OrbitHistory, t: ArrayLike) -> None:
    """Sample an orbit history and write it as a vector CSV table (atomically).

    Parameters
    ----------
    path : str or path-like
    orbit : OrbitHistory
    t : array_like, shape (N,)
        Julian years from J2000, strictly increasing.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from andoyer.planetary.orbits import VondrakEcliptic
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "vondrak.csv"
    >>> write_orbit_csv(path, VondrakEcliptic(), np.linspace(-1e4, 1e4, 21))
    >>> path.read_text().splitlines()[0]
    't_years,nx,ny,nz'
    """
    times = np.asarray(t, dtype=float)
    columns = [times[:, None], orbit.normal(times)]
    header = ["t_years", *VECTOR_COLUMNS]
    if orbit.has_eccentricity:
        columns.append(orbit.eccentricity_vector(times))
        header += list(ECC_COLUMNS)
    table = np.concatenate(columns, axis=-1)
    text = ",".join(header) + "\n" + "".join(",".join(repr(float(x)) for x in row) + "\n" for row in table)
    atomic_write_bytes(path, text.encode())
