"""``andoyer demo [--body NAME] [--out DIR]``: the end-to-end tour, written as a report folder."""

from __future__ import annotations

import argparse
import sys

from andoyer import bodies
from andoyer.cli.demo_report import write_report


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "demo",
        description=(
            "Write a report folder (README.md plus pictures) covering a named body in every chart, "
            "its exact torque-free propagation, Lara's SAM series against the exact solution, "
            "Earth's precession and the phase portraits; the summary is also printed."
        ),
    )
    parser.add_argument("--body", default="earth", choices=bodies.names())
    parser.add_argument("--out", default="andoyer-demo", metavar="DIR", help="report folder (replaced)")
    parser.add_argument("--quiet", action="store_true", help="do not print the summary")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Write the report and print its summary."""
    summary = write_report(args.body, args.out)
    if not args.quiet:
        sys.stdout.write(summary)
        sys.stdout.write(f"\nreport written to {args.out}/README.md\n")
    return 0
