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
            "Write a report folder covering a named body: README.md with tables of the body in every "
            "chart, its exact torque-free propagation, Lara's SAM series against the exact solution "
            "and Earth's precession, and PNG pictures of the precession and the phase portraits; the "
            "summary is also printed. The folder must be new, empty or a previous report (marked by "
            "its .andoyer-demo file); nothing in it is deleted."
        ),
    )
    parser.add_argument(
        "--body", default="earth", choices=bodies.names(), help="the body toured (default earth)"
    )
    parser.add_argument(
        "--out",
        default="andoyer-demo",
        metavar="DIR",
        help="report folder: a new or empty one, or a previous report whose files are replaced",
    )
    parser.add_argument(
        "--force",
        action="store_true",
        help="also write into a folder holding other things (only the report's files are replaced)",
    )
    parser.add_argument("--quiet", action="store_true", help="do not print the summary")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Write the report and print its summary."""
    summary = write_report(args.body, args.out, force=args.force)
    if not args.quiet:
        sys.stdout.write(summary)
        sys.stdout.write(f"\nreport written to {args.out}/README.md\n")
    return 0
