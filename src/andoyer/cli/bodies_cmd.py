"""``andoyer bodies``: the catalogue of named bodies."""

from __future__ import annotations

import argparse
import json
import sys

from andoyer import bodies

HEADER = ("name", "I1", "I2", "I3", "alpha", "beta", "kappa", "rotation_period_s", "J0_rad", "source")


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser("bodies")
    parser.add_argument("--format", choices=("table", "csv", "json"), default="table", help="default table")
    parser.set_defaults(run=run)


def rows() -> list[list[object]]:
    """One row per catalogued body, in the order of :data:`HEADER`."""
    out = []
    for name in bodies.names():
        entry = bodies.info(name)
        b = entry.body
        out.append(
            [name, b.I1, b.I2, b.I3, b.alpha, b.beta, b.kappa, entry.rotation_period, entry.J0, entry.source]
        )
    return out


def run(args: argparse.Namespace) -> int:
    """Print the catalogue."""
    from andoyer.cli.output import format_rows

    if args.format == "json":
        json.dump([dict(zip(HEADER, r, strict=True)) for r in rows()], sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_rows(HEADER, rows(), args.format))
    return 0
