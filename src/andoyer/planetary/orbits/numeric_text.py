r"""Whitespace-separated numeric tables (the published solution files): read fast, damage named by line.

The published orbital solutions (La2004, La2010, Zeebe's) are plain text: one row of numbers
per line, whitespace between them, Fortran ``D`` exponents in La2004's files, ``%`` or ``#``
comment lines in some copies, a few header lines in HNBody's output. :func:`read_table` reads
them with numpy's C parser (``numpy.loadtxt``) and checks what a damaged file shows:

* bytes that are not text (a binary file, another encoding) or a line that is not numbers;
* a line with another number of columns (a truncated last line, a file of another format);
* a value that is not finite (``nan``, ``inf``);
* times that do not run strictly one way (a repeated, swapped or pasted block).

Each is a :class:`ValueError` of one line naming the file and the line (1-based, counting
every line of the file). A UTF-8 byte-order mark, which an editor may add, is read as the
text it marks. Where the fast parse fails the file is scanned line by line to find the first
bad line; a good file is parsed once.

Memory: the file's text plus the table (8 bytes a value); :func:`read_table` refuses, before
reading, a file whose text and table would not fit in :func:`andoyer._limits.memory_limit`.
"""

from __future__ import annotations

import io
import os
from collections.abc import Iterator, Sequence
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from andoyer._limits import check_size

__all__ = ["Table", "first_row", "read_table"]

Array = NDArray[np.float64]
COMMENTS = ("#", "%")
# Characters per number in the files read here (La2004's D25.16 is the widest): a row count
# estimated from the size, for the memory check before reading.
_MIN_CHARS_PER_VALUE = 8


def _decode(data: bytes, path: str) -> str:
    """UTF-8 text of ``data`` (a byte-order mark dropped); a non-text byte names its line."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        msg = (
            f"expected a text file of numbers, got byte 0x{data[exc.start]:02x} on line {line} of "
            f"{path!r} (a binary file or another encoding)"
        )
        raise ValueError(msg) from None


def _is_comment(line: str) -> bool:
    stripped = line.lstrip()
    return not stripped or stripped.startswith(COMMENTS)


def _fields(line: str) -> list[str]:
    return line.replace("D", "E").replace("d", "e").split()


def _numbers(fields: Sequence[str]) -> list[float] | None:
    try:
        return [float(x) for x in fields]
    except ValueError:
        return None


def header_length(text: str, limit: int) -> int:
    """How many leading lines (at most ``limit``) are not rows of numbers: comments or a header."""
    count = 0
    for line in io.StringIO(text):
        if count >= limit or (not _is_comment(line) and _numbers(_fields(line)) is not None):
            break
        count += 1
    return count


def _scan(text: str, path: str, names: Sequence[str], skip: int) -> Iterator[tuple[int, list[float]]]:
    """Line numbers and values of the data rows, raising on the first bad one."""
    for number, line in enumerate(io.StringIO(text), start=1):
        if number <= skip or _is_comment(line):
            continue
        fields = _fields(line)
        if len(fields) != len(names):
            msg = (
                f"expected {len(names)} columns ({' '.join(names)}) on line {number} of {path!r}, "
                f"got {len(fields)}"
            )
            raise ValueError(msg)
        values = _numbers(fields)
        if values is None:
            shown = line.strip()[:60]
            msg = f"expected numbers ({' '.join(names)}) on line {number} of {path!r}, got {shown!r}"
            raise ValueError(msg)
        yield number, values


#: Bytes read from the start of a file to recognise its format.
_SNIFF_BYTES = 1 << 16


def first_row(path: str | os.PathLike[str], header_lines: int = 3) -> tuple[int, str]:
    r"""The line number and text of a file's first data row (comments and a short header skipped).

    Reads only the file's first 64 KiB: enough to recognise a format from its columns.

    Parameters
    ----------
    path : str or path-like
    header_lines : int
        At most this many leading lines that are not numbers are passed over.

    Returns
    -------
    tuple of (int, str)
        1-based line number and the line (``(0, "")`` for a file without one).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "t.dat"
    >>> _ = path.write_text("% age e i\n0 0.1 1\n1 0.2 1\n")
    >>> first_row(path)
    (2, '0 0.1 1')
    """
    name = str(path)
    with open(path, "rb") as stream:
        data = stream.read(_SNIFF_BYTES)
    if len(data) == _SNIFF_BYTES:
        data = data[: data.rfind(b"\n") + 1] or data  # whole lines only (a cut UTF-8 character)
    text = _decode(data, name)
    skip = header_length(text, header_lines)
    for number, line in enumerate(io.StringIO(text), start=1):
        if number > skip and not _is_comment(line):
            return number, line.strip()
    return 0, ""


def _line_of(text: str, skip: int, row: int) -> int:
    """The line number of data row ``row`` (0-based; comments and the header skipped)."""
    seen = -1
    for number, line in enumerate(io.StringIO(text), start=1):
        if number > skip and not _is_comment(line):
            seen += 1
            if seen == row:
                return number
    return 0


class Table:
    """The rows of a numeric file, and the line each came from (for messages about a row).

    Attributes
    ----------
    values : numpy.ndarray, shape (N, C)
    path : str
    """

    def __init__(self, values: Array, path: str, text: str, skip: int) -> None:
        self.values, self.path = values, path
        self._text, self._skip = text, skip

    def line(self, row: int) -> int:
        """The 1-based line number of row ``row`` (0-based) of :attr:`values`."""
        return _line_of(self._text, self._skip, int(row))


def read_table(
    path: str | os.PathLike[str],
    names: Sequence[str],
    *,
    time_column: int = 0,
    header_lines: int = 0,
    min_rows: int = 4,
) -> Table:
    r"""The rows of a whitespace-separated numeric file, checked (see the module's notes).

    Parameters
    ----------
    path : str or path-like
    names : sequence of str
        The columns' names, one per column (named in errors).
    time_column : int
        The column whose values must run strictly one way (increasing or decreasing).
    header_lines : int
        At most this many leading lines that are not numbers are skipped as a header.
    min_rows : int
        The fewest data rows accepted.

    Returns
    -------
    Table
        ``values`` of shape (N, len(names)), in the file's order, and ``line(row)``.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "t.asc"
    >>> _ = path.write_text("% t e\n0. 0.1D+00\n-1. 0.2D+00\n-2. 0.3D+00\n-3. 0.4D+00\n")
    >>> table = read_table(path, ("t", "e"))
    >>> table.values[:, 1].tolist(), table.line(0)
    ([0.1, 0.2, 0.3, 0.4], 2)
    >>> _ = path.write_text("0. 0.1\n-1. 0.2\n-1. 0.3\n-3. 0.4\n")
    >>> read_table(path, ("t", "e"))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected strictly monotonic times (column t), got -1 after -1 on line 3 of '...t.asc'
    """
    name = str(path)
    size = Path(path).stat().st_size
    # The text (read once, then a copy with the exponents fixed) and the table of float64 values.
    rows = size / (_MIN_CHARS_PER_VALUE * len(names))
    check_size(f"reading {Path(path).name}", nbytes=3.0 * size + 2 * 8.0 * rows * len(names))
    text = _decode(Path(path).read_bytes(), name)
    skip = header_length(text, header_lines)
    try:
        # numpy's C parser; Fortran's D exponents made E first (La2004's files).
        values = np.loadtxt(
            io.StringIO(text.replace("D", "E").replace("d", "e")),
            comments=COMMENTS,
            skiprows=skip,
            ndmin=2,
            dtype=np.float64,
        )
    except ValueError:
        values = None
    if values is None or (values.size and values.shape[1] != len(names)):
        # Find and name the first bad line (this scan raises), or read a file numpy's parser refused.
        scanned = list(_scan(text, name, names, skip))
        values = np.array([v for _, v in scanned], dtype=np.float64).reshape(-1, len(names))
    table = Table(values, name, text, skip)
    if values.shape[0] < min_rows:
        msg = f"expected at least {min_rows} rows of {' '.join(names)} in {name!r}, got {values.shape[0]}"
        raise ValueError(msg)
    finite = np.isfinite(values)
    if not finite.all():
        row, column = np.argwhere(~finite)[0]
        msg = (
            f"expected finite numbers, got {float(values[row, column])!r} in column {names[column]} on line "
            f"{table.line(row)} of {name!r}"
        )
        raise ValueError(msg)
    t = values[:, time_column]
    steps = np.diff(t)
    direction = 1.0 if steps.size == 0 or steps[0] > 0 else -1.0
    bad = np.flatnonzero(direction * steps <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        msg = (
            f"expected strictly monotonic times (column {names[time_column]}), got {t[k]:g} after "
            f"{t[k - 1]:g} on line {table.line(k)} of {name!r}"
        )
        raise ValueError(msg)
    return table
