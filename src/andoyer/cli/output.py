"""Tables, CSV and atomic files for the command line."""

from __future__ import annotations

import contextlib
import csv
import io
import os
import sys
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TextIO

import numpy as np

__all__ = ["CliError", "atomic_output", "format_rows", "read_csv_columns"]


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


@contextlib.contextmanager
def atomic_output(path: str | None) -> Iterator[TextIO]:
    """Yield a text stream: stdout for ``None`` or ``-``, else a temporary file renamed on success."""
    if path in (None, "-"):
        yield sys.stdout
        return
    target = Path(path)
    if not target.parent.exists():
        msg = f"expected an existing directory for the output file, got {str(target.parent)!r}"
        raise CliError(msg)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    try:
        with os.fdopen(fd, "w", newline="") as stream:
            yield stream
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def read_csv_columns(path: str, columns: Sequence[str]) -> dict[str, np.ndarray]:
    """Read the named float columns of a CSV file with a header row."""
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            missing = [c for c in columns if c not in (reader.fieldnames or [])]
            if missing:
                msg = f"expected CSV columns {', '.join(columns)}, got {', '.join(reader.fieldnames or [])}"
                raise CliError(msg)
            rows = list(reader)
    except OSError as exc:
        msg = f"expected a readable CSV file, got {path!r} ({exc.strerror})"
        raise CliError(msg) from exc
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
