"""Tables, CSV, JSON and atomic files for the command line.

Long outputs are written a block of rows at a time (:func:`write_rows`, :func:`write_json`)
from numpy columns, so that what a command holds is its numbers (8 bytes each), never the
text of its whole output or a Python object per number; the text is that of
:func:`format_rows` and :func:`json.dumps`, byte for byte.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import errno
import io
import json
import os
import stat
import sys
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import IO

import numpy as np
from numpy.typing import ArrayLike

from andoyer._files import atomic_replace

__all__ = [
    "CliError",
    "add_output_argument",
    "atomic_output",
    "check_outputs",
    "format_rows",
    "output_store",
    "output_target",
    "read_csv_columns",
    "write_json",
    "write_rows",
]

#: Rows formatted at once by :func:`write_rows` and :func:`write_json`.
BLOCK_ROWS = 65536
#: Seconds to format one number (a bound of the measured 0.2-0.4 µs of ``repr`` and ``.12g``).
FORMAT_SECONDS = 1e-6


class CliError(Exception):
    """A user error on the command line: printed as one line, exit code 2."""


def format_rows(header: Sequence[str], rows: Sequence[Sequence[object]], fmt: str) -> str:
    """Render rows as an aligned text table or as CSV; floats keep 17 significant digits in CSV."""

    def cell(value: object, precise: bool) -> str:
        if isinstance(value, float | np.floating):
            return repr(float(value)) if precise else f"{float(value):.12g}"
        return str(value)

    if fmt == "csv":
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        writer.writerow(header)
        writer.writerows([[cell(v, precise=True) for v in row] for row in rows])
        return buffer.getvalue()
    table = [list(header)] + [[cell(v, precise=False) for v in row] for row in rows]
    widths = [max(len(r[i]) for r in table) for i in range(len(header))]
    lines = ["  ".join(c.rjust(w) for c, w in zip(r, widths, strict=True)) for r in table]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines) + "\n"


def _columns(columns: Sequence[ArrayLike]) -> list[np.ndarray]:
    arrays = [np.asarray(c, dtype=np.float64) for c in columns]
    if not arrays or any(a.ndim != 1 or a.shape != arrays[0].shape for a in arrays):
        msg = f"expected columns of one length, got shapes {[a.shape for a in arrays]}"
        raise ValueError(msg)
    return arrays


def write_rows(
    stream: IO[str],
    header: Sequence[str] | None,
    columns: Sequence[ArrayLike],
    fmt: str,
    rows: int = BLOCK_ROWS,
) -> None:
    """Write float ``columns`` (each of shape (N,)) as :func:`format_rows` would, ``rows`` rows at a time.

    CSV is written in one pass (``header=None``: rows only, to go on a CSV already begun);
    an aligned table in two (the widths first, then the rows), formatting each block anew:
    neither holds more text than one block's.

    Examples
    --------
    >>> out = io.StringIO()
    >>> write_rows(out, ["t", "x"], [[0.0, 10.0], [0.5, -1e-20]], "table", rows=1)
    >>> print(out.getvalue(), end="")
     t       x
    --  ------
     0     0.5
    10  -1e-20
    >>> out.getvalue() == format_rows(["t", "x"], [[0.0, 0.5], [10.0, -1e-20]], "table")
    True
    """
    arrays = _columns(columns)
    if (header is None and fmt != "csv") or (header is not None and len(header) != len(arrays)):
        msg = f"expected one header per column, got {header!r} for {len(arrays)} columns"
        raise ValueError(msg)
    count = arrays[0].size
    blocks = [slice(k, k + rows) for k in range(0, count, rows)]
    if fmt == "csv":
        if header is not None:
            buffer = io.StringIO()
            csv.writer(buffer, lineterminator="\n").writerow(header)
            stream.write(buffer.getvalue())
        for part in blocks:
            cells = zip(*(map(repr, a[part].tolist()) for a in arrays), strict=True)
            stream.write("".join(",".join(row) + "\n" for row in cells))
        return
    widths = [len(h) for h in header]
    for part in blocks:
        for i, a in enumerate(arrays):
            widths[i] = max(widths[i], *(len(format(v, ".12g")) for v in a[part].tolist()))
    stream.write("  ".join(h.rjust(w) for h, w in zip(header, widths, strict=True)) + "\n")
    stream.write("  ".join("-" * w for w in widths) + "\n")
    for part in blocks:
        pairs = zip(arrays, widths, strict=True)
        text = [[format(v, ".12g").rjust(w) for v in a[part].tolist()] for a, w in pairs]
        cells = zip(*text, strict=True)
        stream.write("".join("  ".join(row) + "\n" for row in cells))


def write_json(stream: IO[str], fields: Mapping[str, object], rows: int = BLOCK_ROWS) -> None:
    r"""Write ``json.dumps(fields)`` and a newline, numpy arrays a block of ``rows`` at a time.

    A value that is a numpy array (of floats, any shape: its first axis is cut into blocks)
    is written as its ``tolist()`` would be; any other value by :func:`json.dumps`.

    Examples
    --------
    >>> import numpy as np
    >>> fields = {"t": np.array([0.0, 1.5, np.nan]), "axis": np.eye(3), "rate": 2.0, "e": None}
    >>> out = io.StringIO()
    >>> write_json(out, fields, rows=2)
    >>> out.getvalue() == json.dumps({k: v.tolist() if isinstance(v, np.ndarray) else v
    ...                               for k, v in fields.items()}) + "\n"
    True
    """
    stream.write("{")
    for k, (key, value) in enumerate(fields.items()):
        stream.write((", " if k else "") + json.dumps(key) + ": ")
        if not isinstance(value, np.ndarray) or value.ndim == 0:
            stream.write(json.dumps(value.tolist() if isinstance(value, np.ndarray) else value))
            continue
        stream.write("[")
        for first in range(0, len(value), rows):
            text = json.dumps(value[first : first + rows].tolist())[1:-1]
            stream.write((", " if first else "") + text)
        stream.write("]")
    stream.write("}\n")


_KINDS = (
    (stat.S_ISDIR, "the directory"),
    (stat.S_ISFIFO, "the FIFO"),
    (stat.S_ISCHR, "the character device"),
    (stat.S_ISBLK, "the block device"),
    (stat.S_ISSOCK, "the socket"),
)


def _kind(mode: int) -> str:
    return next((name for test, name in _KINDS if test(mode)), "the special file")


def _resolve(path: str | os.PathLike[str]) -> tuple[Path, int | None]:
    """``os.path.realpath(path)`` and its ``st_mode`` (``None``: nothing there); bad names refused."""
    text = os.fspath(path)
    if not text:
        msg = "expected a name for the output, got ''"
        raise CliError(msg)
    real = Path(os.path.realpath(text))
    try:
        mode = os.stat(real).st_mode
    except FileNotFoundError:
        mode = None
    except OSError as exc:  # a loop of links, a name too long, a folder we may not search
        msg = f"expected a usable output path, got {text!r} ({exc.strerror})"
        raise CliError(msg) from exc
    if mode is None and os.path.islink(text):
        msg = f"expected an output path, got the dangling symbolic link {text!r} (to {str(real)!r})"
        raise CliError(msg)
    if mode is None and not real.parent.is_dir():
        msg = f"expected an existing directory for the output, got {str(real.parent)!r}"
        raise CliError(msg)
    return real, mode


def _refusal(exc: OSError, path: str | os.PathLike[str], folder: Path) -> str:
    """What a file system's refusal to create a file in ``folder`` means, as a message's end."""
    where = repr(str(folder))
    if exc.errno in (errno.EACCES, errno.EPERM):
        why = f"{exc.strerror}: no permission to write in the folder {where}"
    elif exc.errno == errno.EROFS:
        why = f"{exc.strerror}: the folder {where} cannot be written"
    elif exc.errno in (errno.ENOENT, errno.EOPNOTSUPP, errno.EINVAL) and folder.is_dir():
        why = f"the folder {where} takes no new files: a special file system, like /proc or /sys"
    else:
        why = exc.strerror or str(exc)
    return f"expected a writable place for the output, got {os.fspath(path)!r} ({why})"


def _probe(real: Path, path: str | os.PathLike[str]) -> None:
    """Create and remove a file beside ``real`` as the atomic write will; a refusal is a :class:`CliError`."""
    try:
        fd, name = tempfile.mkstemp(prefix=f".{real.name}.", suffix=".probe", dir=real.parent)
    except OSError as exc:
        raise CliError(_refusal(exc, path, real.parent)) from exc
    os.close(fd)
    os.unlink(name)


def output_target(path: str | os.PathLike[str]) -> Path:
    r"""The regular file an output path names, symbolic links followed; :class:`CliError` otherwise.

    The answer is ``os.path.realpath(path)``: writing there replaces a link's target and keeps
    the link. Refused: an empty name, a dangling link (it could point anywhere), anything that
    exists and is not a regular file (a directory, a FIFO, a device such as ``/dev/full``: use
    ``-`` for standard output) or that we may not write, a path whose folder does not exist.

    Examples
    --------
    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> (folder / "link.csv").symlink_to(folder / "data.csv")
    >>> (folder / "data.csv").write_text("x\n")
    2
    >>> output_target(folder / "link.csv") == (folder / "data.csv").resolve()
    True
    >>> output_target(folder)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    andoyer.cli.output.CliError: expected a regular file for the output (...), got the directory '...'
    """
    real, mode = _resolve(path)
    if mode is not None and not stat.S_ISREG(mode):
        msg = (
            f"expected a regular file for the output (- for standard output), "
            f"got {_kind(mode)} {os.fspath(path)!r}"
        )
        raise CliError(msg)
    if mode is not None and not os.access(real, os.W_OK):
        # A rename would replace it all the same: respect the protection as open() would.
        msg = f"expected a writable file for the output, got the read-only file {os.fspath(path)!r}"
        raise CliError(msg)
    _probe(real, path)
    return real


def output_store(path: str | os.PathLike[str]) -> Path:
    """The folder (a Zarr store) an output path names, links followed; :class:`CliError` otherwise.

    Like :func:`output_target` for a store that is a directory: refused are an empty name, a
    dangling link, anything that exists and is not a directory, a missing parent folder.

    Examples
    --------
    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> output_store(folder / "e.zarr") == folder.resolve() / "e.zarr"
    True
    """
    real, mode = _resolve(path)
    if mode is not None and not stat.S_ISDIR(mode):
        kind = "the file" if stat.S_ISREG(mode) else _kind(mode)
        msg = f"expected a directory (a Zarr store) or a new name for the output, got {kind} {str(path)!r}"
        raise CliError(msg)
    return real


def add_output_argument(
    parser: argparse.ArgumentParser,
    flag: str = "--output",
    text: str = "write here instead of standard output",
) -> None:
    """Add an output-file option; :func:`check_outputs` checks it before the command runs.

    Its destination is listed in the parser's default ``output_paths``.
    """
    action = parser.add_argument(flag, metavar="FILE", help=text)
    parser.set_defaults(output_paths=(*(parser.get_default("output_paths") or ()), action.dest))


def check_outputs(args: argparse.Namespace) -> None:
    """Refuse, before any work, an output path of :func:`add_output_argument` that cannot be written.

    ``-`` (standard output) and absent options pass; others must satisfy :func:`output_target`
    (checked again when the file is written). Two outputs may not name the same file (through
    links, relative paths or hard links), nor both be ``-``: one would overwrite the other.
    """
    seen: dict[object, str] = {}
    for dest in getattr(args, "output_paths", ()):
        path = getattr(args, dest, None)
        if path is None:
            continue
        flag = "--" + dest.replace("_", "-")
        same: list[object] = ["-"] if path == "-" else []
        if path != "-":
            real = output_target(path)
            same.append(real)
            with contextlib.suppress(OSError):  # an existing file: a hard link is the same file too
                info = os.stat(real)
                same.append((info.st_dev, info.st_ino))
        for key in same:
            if key in seen:
                where = "standard output" if key == "-" else repr(os.fspath(path))
                msg = f"expected different files for {seen[key]} and {flag}, got {where} for both"
                raise CliError(msg)
        seen.update(dict.fromkeys(same, flag))


@contextlib.contextmanager
def atomic_output(path: str | os.PathLike[str] | None, binary: bool = False) -> Iterator[IO]:
    r"""Yield a stream: stdout for ``None`` or ``-``, else a temporary file renamed on success.

    The file is written beside :func:`output_target`'s answer (so through symbolic links) and
    renamed over it only once the block has finished: an interrupted or failed command leaves
    the previous file, if any, untouched, and nothing else. The new file gets the mode of the
    file it replaces, else ``0o666 & ~umask`` (what ``open()`` gives). An error of the file
    system is a :class:`CliError` naming the path.

    Examples
    --------
    >>> import tempfile
    >>> out = Path(tempfile.mkdtemp()) / "table.txt"
    >>> with atomic_output(out) as stream:
    ...     _ = stream.write("1 2\n")
    >>> out.read_text()
    '1 2\n'
    """
    if path is None or os.fspath(path) == "-":
        if not binary:
            yield sys.stdout
            return
        buffer = getattr(sys.stdout, "buffer", None)
        if buffer is None:
            msg = "expected a binary standard output for -, got a text-only stream"
            raise CliError(msg)
        sys.stdout.flush()
        yield buffer
        buffer.flush()
        return
    target = output_target(path)
    how = {"mode": "wb"} if binary else {"mode": "w", "newline": ""}
    try:
        with atomic_replace(target) as part, open(part, **how) as stream:
            yield stream
            stream.flush()
            os.fsync(stream.fileno())
    except OSError as exc:
        if isinstance(exc, BrokenPipeError):
            raise
        raise CliError(_refusal(exc, path, target.parent)) from exc


def read_csv_columns(path: str, columns: Sequence[str]) -> dict[str, np.ndarray]:
    """Read the named float columns of a CSV file with a header row."""
    try:
        # utf-8-sig: a spreadsheet's byte-order mark would otherwise stick to the first column's name
        with open(path, newline="", encoding="utf-8-sig") as stream:
            reader = csv.DictReader(stream)
            missing = [c for c in columns if c not in (reader.fieldnames or [])]
            if missing:
                msg = f"expected CSV columns {', '.join(columns)}, got {', '.join(reader.fieldnames or [])}"
                raise CliError(msg)
            rows = list(reader)
    except OSError as exc:
        msg = f"expected a readable CSV file, got {path!r} ({exc.strerror})"
        raise CliError(msg) from exc
    except UnicodeDecodeError as exc:
        msg = f"expected a UTF-8 CSV file, got {path!r} (byte 0x{exc.object[exc.start]:02x} is not UTF-8)"
        raise CliError(msg) from None
    if not rows:
        msg = f"expected at least one data row, got an empty table in {path!r}"
        raise CliError(msg)
    out = {}
    for name in columns:
        cells = [row[name] for row in rows]
        try:
            out[name] = np.array(cells, dtype=float)
        except (TypeError, ValueError) as exc:
            msg = f"expected numbers in column {name!r}, got {exc}"
            raise CliError(msg) from exc
    return out
