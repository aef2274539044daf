"""``andoyer convert``: convert states between charts."""

from __future__ import annotations

import argparse

import numpy as np

from andoyer.cli.chart_table import CHARTS, add_body_arguments, body_from_args, chart_columns_from_args
from andoyer.cli.output import add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer convert --from andoyer --to euler --values 0.1 0.2 0.3 0.9 1.0 0.5
  andoyer convert --from euler --to andoyer --input states.csv --format csv --output out.csv
columns:
""" + "\n".join(f"  {name:8s} {', '.join(chart.columns)}" for name, chart in CHARTS.items())


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "convert",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--from", dest="source", choices=tuple(CHARTS), required=True, help="chart of the input"
    )
    parser.add_argument(
        "--to", dest="target", choices=tuple(CHARTS), required=True, help="chart of the output"
    )
    given = parser.add_mutually_exclusive_group(required=True)
    given.add_argument("--values", nargs="+", type=float, metavar="X", help="one state, in column order")
    given.add_argument("--input", metavar="CSV", help="CSV file with a header naming the columns")
    parser.add_argument("--degrees", action="store_true", help="angles in degrees (input and output)")
    add_body_arguments(parser)
    parser.add_argument("--format", choices=("table", "csv"), default="table", help="default table")
    add_output_argument(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Read, convert and write."""
    source, target = CHARTS[args.source], CHARTS[args.target]
    columns = chart_columns_from_args(args, source)
    if args.degrees:
        columns = {c: np.radians(v) if c in source.angles else v for c, v in columns.items()}
    body = body_from_args(args) if (source.needs_body or target.needs_body) else None
    state = source.to_state([columns[c] for c in source.columns], body)
    values = [np.asarray(v, dtype=float) for v in target.from_state(state, body)]
    if args.degrees:
        values = [
            np.degrees(v) if c in target.angles else v for c, v in zip(target.columns, values, strict=True)
        ]
    rows = [list(r) for r in zip(*(v.tolist() for v in values), strict=True)]
    with atomic_output(args.output) as stream:
        stream.write(format_rows(target.columns, rows, args.format))
    return 0
