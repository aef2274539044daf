"""``andoyer brackets``: the bracket table of the canonical coordinates of a Lie–Poisson algebra."""

from __future__ import annotations

import argparse
import json

from andoyer.cli.output import add_output_argument, atomic_output, format_rows

ALGEBRAS = ("so3", "e3", "l7")


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "brackets",
        description=(
            "Computes every bracket of the project's canonical coordinates on the chosen Lie-Poisson "
            "algebra, symbolically (sympy normal form) and numerically (seeded points)."
        ),
    )
    parser.add_argument("--algebra", choices=ALGEBRAS, required=True, help="the Lie-Poisson algebra")
    parser.add_argument("--format", choices=("table", "json"), default="table", help="default table")
    add_output_argument(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Compute and print the table; exit status 1 if any bracket fails."""
    from andoyer.liepoisson import bracket_table

    table = bracket_table(args.algebra)
    with atomic_output(args.output) as stream:
        if args.format == "json":
            json.dump(table, stream, indent=2)
            stream.write("\n")
        else:
            header = ("left", "right", "value", "symbolic_ok", "numeric_ok")
            stream.write(format_rows(header, [[row[k] for k in header] for row in table], "table"))
    return 0 if all(row["symbolic_ok"] and row["numeric_ok"] for row in table) else 1
