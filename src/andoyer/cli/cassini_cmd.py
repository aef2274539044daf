"""``andoyer cassini``: the Cassini states of the Moon or Mercury (or of either with other moments)."""

from __future__ import annotations

import argparse
import json
import math
from typing import TYPE_CHECKING

from andoyer.cli.numbers import physical
from andoyer.cli.output import add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer cassini moon
  andoyer cassini mercury --format json
  andoyer cassini mercury --moment-of-inertia 0.34 --node-period 300000 --inclination 8.6
The states of Colombo's top (andoyer.planetary.cassini), numbered as Peale (1969): only those that exist.
obliquity: spin axis to orbit normal (deg); inclination_to_laplace: spin axis to the Laplace pole
(deg); precession_constant (alpha) and resonance_constant (beta) in arcsec per Julian year;
node_rate (g < 0, regression) in arcsec per Julian year.
JSON keys: body, resonance, states (number, obliquity, inclination_to_laplace, stable),
precession_constant, resonance_constant, node_rate, inclination.
"""
ARCSEC = math.pi / 648000.0

if TYPE_CHECKING:
    from andoyer.planetary.cassini import CassiniBody


def add_cassini_arguments(parser: argparse.ArgumentParser) -> None:
    """The options that override a named body's moments and orbit (shared with ``portrait cassini``).

    Each is checked against its range in :mod:`andoyer.planetary.parameters`, as the API checks it.
    """
    parser.add_argument(
        "--j2", type=physical("j2"), metavar="J2", help="unnormalised J2 = (C - (A+B)/2)/MR^2 (J2 > 0)"
    )
    parser.add_argument(
        "--c22", type=physical("c22"), metavar="C22", help="unnormalised C22 = (B - A)/4MR^2 (C22 <= J2/2)"
    )
    parser.add_argument(
        "--moment-of-inertia",
        type=physical("moment_of_inertia"),
        metavar="C_MR2",
        help="polar moment C/MR^2 (0 < C/MR^2 <= 1)",
    )
    parser.add_argument(
        "--node-period",
        type=physical("node_period"),
        metavar="YEARS",
        help="period of the node's regression, Julian years (> 0)",
    )
    parser.add_argument(
        "--inclination",
        type=physical("laplace_inclination", degrees=True),
        metavar="DEG",
        help="orbit to Laplace plane, degrees (0 < DEG < 90)",
    )


def cassini_body_from_args(name: str, args: argparse.Namespace) -> CassiniBody:
    """The named body with the command line's overrides (ValueError on non-physical values)."""
    from andoyer.planetary import cassini

    changes: dict[str, float] = {}
    if args.j2 is not None:
        changes["j2"] = args.j2
    if args.c22 is not None:
        changes["c22"] = args.c22
    if args.moment_of_inertia is not None:
        changes["moment_of_inertia"] = args.moment_of_inertia
    if args.node_period is not None:
        changes["node_rate"] = -2 * math.pi / args.node_period
    if args.inclination is not None:
        changes["inclination"] = math.radians(args.inclination)
    return cassini.get(name).replace(**changes)


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.cassini import BODIES

    parser = commands.add_parser(
        "cassini",
        description="The Cassini states of the Moon or of Mercury, from their numbers or from the "
        "J2, C22, C/MR^2, node period and inclination given here (other bodies: andoyer.planetary."
        "cassini.CassiniBody in Python).",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("body", type=str.lower, choices=sorted(BODIES), help="the body whose numbers start")
    parser.add_argument("--format", choices=("table", "json"), default="table", help="default table")
    add_cassini_arguments(parser)
    add_output_argument(parser)
    parser.set_defaults(run=run)


def cassini_fields(system: CassiniBody) -> dict:
    """The JSON object of ``andoyer cassini``."""
    top = system.top()
    return {
        "body": system.name,
        "resonance": system.resonance,
        "states": [
            {
                "number": s.number,
                "obliquity": s.obliquity_deg,
                "inclination_to_laplace": s.inclination_to_laplace_deg,
                "stable": s.stable,
            }
            for s in top.states()
        ],
        "precession_constant": top.alpha / ARCSEC,
        "resonance_constant": top.beta / ARCSEC,
        "node_rate": top.node_rate / ARCSEC,
        "inclination": math.degrees(top.inclination),
    }


def render_table(fields: dict) -> str:
    """The states as an aligned table and the constants below it."""
    rows = [
        [s["number"], s["obliquity"], s["inclination_to_laplace"], "stable" if s["stable"] else "unstable"]
        for s in fields["states"]
    ]
    header = ["state", "obliquity_deg", "inclination_to_laplace_deg", "stability"]
    return format_rows(header, rows, "table") + (
        f"body: {fields['body']}, inclination {fields['inclination']:.6g} deg, "
        f"precession constant {fields['precession_constant']:.8g} arcsec/yr, "
        f"resonance constant {fields['resonance_constant']:.8g} arcsec/yr, "
        f"node rate {fields['node_rate']:.8g} arcsec/yr\n"
    )


def run(args: argparse.Namespace) -> int:
    """Solve for the states and write them."""
    fields = cassini_fields(cassini_body_from_args(args.body, args))
    text = json.dumps(fields, indent=2) + "\n" if args.format == "json" else render_table(fields)
    with atomic_output(args.output) as stream:
        stream.write(text)
    return 0
