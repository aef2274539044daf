"""``andoyer series``: exact perturbation series (Lara's SAM triaxiality polynomials)."""

from __future__ import annotations

import argparse

from andoyer.cli.output import add_output_argument, atomic_output

FORMATS = ("md", "tex", "json")

EXAMPLES = """examples:
  andoyer series sam --order 4
  andoyer series sam --order 10 --format json --output sam10.json
  andoyer series sam --order 9 --format tex
The polynomials are those of Lara (2013) eqs. 30-34 with delta = (L'/G')/sqrt(1 - beta^2);
--order N prints every q_i, g_(i,m), l_(i,m), L_(i,m) with 1 <= i <= N (Deprit order N + 1).
JSON: {"q": {i: {"0": P}}, "g": {i: {m: P}}, "l": {i: {m: P}}, "L": {i: {m: P}}},
P = {power of beta: "p/q"}; L_(i,0) is the coefficient of beta^2 in eq. 34.
"""


def _order(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        msg = f"expected an integer order >= 1, got {text!r}"
        raise argparse.ArgumentTypeError(msg) from None
    if value < 1:
        msg = f"expected an integer order >= 1, got {value}"
        raise argparse.ArgumentTypeError(msg)
    return value


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser("series")
    theories = parser.add_subparsers(dest="theory", required=True)
    sam = theories.add_parser(
        "sam",
        help="triaxiality polynomials q_i, g_(i,m), l_(i,m), L_(i,m) of Lara's SAM theory",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sam.add_argument("--order", type=_order, required=True, metavar="N", help="highest index i (>= 1)")
    sam.add_argument("--format", choices=FORMATS, default="md", help="default md")
    add_output_argument(sam)
    sam.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Compute the tables and write them."""
    from andoyer.theories.sam_tables import sam_tables, tables_to_json, tables_to_latex, tables_to_markdown

    render = {"md": tables_to_markdown, "tex": tables_to_latex, "json": tables_to_json}[args.format]
    text = render(sam_tables(args.order))
    with atomic_output(args.output) as stream:
        stream.write(text if text.endswith("\n") else text + "\n")
    return 0
