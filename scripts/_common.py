"""Shared command-line handling of the paper-reproduction scripts: one ``--out`` folder."""

from __future__ import annotations

import argparse
from pathlib import Path


def output_folder(description: str, argv: list[str] | None = None) -> Path:
    """Parse ``--out DIR`` (default ``reproduced/``), create it and return it."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", default="reproduced", help="folder for the outputs (created)")
    out = Path(parser.parse_args(argv).out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def write(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` and say so."""
    path.write_text(text, encoding="utf-8")
    print(f"wrote {path}")
