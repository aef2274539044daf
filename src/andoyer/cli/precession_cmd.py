"""``andoyer precession``: the precession rate of a planet's spin axis about its ecliptic pole."""

from __future__ import annotations

import argparse
import json

from andoyer.cli.numbers import physical, positive_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output

EXAMPLES = """examples:
  andoyer precession earth
  andoyer precession mars --integrate 2 --format json
  andoyer precession earth --integrate 1 --step 8.227 --output earth.json --format json
  andoyer precession earth --moments lara2013
Rates are arcseconds per Julian year of regression of the angular momentum's node on the
planet's ecliptic: from the averaged (secular) model, and with --integrate YEARS from a full
splitting integration of the Sun's (and Moon's) gravity-gradient torque (see andoyer.planetary.precession).
Moments: the catalogue's by default (the Earth's IAU MHB2000 H = 0.00327379492: 50.40 arcsec/yr at
first order); --moments lara2013 takes Lara's (2013) Table 1 (H = 0.0032789: 50.48 arcsec/yr).
JSON keys: body, perturbers, obliquity_deg, secular_arcsec_per_year, integrated_arcsec_per_year
(null without --integrate), integration_years, step_days.
"""


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.precession import MOMENT_SETS, PLANETS

    parser = commands.add_parser(
        "precession",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("body", type=str.lower, choices=PLANETS, help="the planet")
    parser.add_argument(
        "--integrate", type=positive_number, metavar="YEARS", help="also integrate the full torque this long"
    )
    parser.add_argument(
        "--step",
        type=positive_number,
        metavar="DAYS",
        help="splitting step (default: andoyer.planetary.precession.default_step)",
    )
    parser.add_argument("--order", type=int, choices=(2, 4, 6), default=2, help="splitting order")
    parser.add_argument(
        "--dynamical-ellipticity",
        type=physical("dynamical_ellipticity"),
        metavar="H",
        help="H = (C - (A+B)/2)/C instead of the named body's (0 < H < 1/2)",
    )
    parser.add_argument(
        "--moments",
        choices=MOMENT_SETS,
        default="catalogue",
        help="the moment set: the catalogue's (default) or Lara's (2013) Table 1",
    )
    parser.add_argument("--format", choices=("text", "json"), default="text", help="default text")
    add_output_argument(parser)
    parser.set_defaults(run=run)


def render_text(fields: dict) -> str:
    """The rates as a few human-readable lines."""
    lines = [
        f"precession of the angular momentum of {fields['body'].capitalize()} about its ecliptic pole",
        f"perturbers: {', '.join(fields['perturbers'])}",
        f"obliquity: {fields['obliquity_deg']:.4f} deg",
        f"secular model: {fields['secular_arcsec_per_year']:.4f} arcsec/yr",
    ]
    if fields["integrated_arcsec_per_year"] is not None:
        lines.append(
            f"full integration ({fields['integration_years']:.3f} yr, step {fields['step_days']:.4f} d): "
            f"{fields['integrated_arcsec_per_year']:.4f} arcsec/yr"
        )
    return "\n".join(lines) + "\n"


def run(args: argparse.Namespace) -> int:
    """Compute the rates and write them."""
    from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR
    from andoyer.planetary.precession import precession_rates

    if args.step is not None and args.integrate is None:
        msg = "expected --step only with --integrate YEARS, got --step alone"
        raise CliError(msg)
    if args.step is not None and args.step * DAY > args.integrate * JULIAN_YEAR / 2:
        half = args.integrate * JULIAN_YEAR / 2 / DAY
        msg = (
            f"expected --step of at most half of --integrate ({half:.6g} days for {args.integrate:g} years), "
            f"got {args.step:g} days"
        )
        raise CliError(msg)
    step = None if args.step is None else args.step * DAY
    rates = precession_rates(
        args.body,
        integrate=args.integrate,
        step=step,
        order=args.order,
        dynamical_ellipticity=args.dynamical_ellipticity,
        moments=args.moments,
    )
    fields = rates.as_dict()
    text = json.dumps(fields, indent=2) + "\n" if args.format == "json" else render_text(fields)
    with atomic_output(args.output) as stream:
        stream.write(text)
    return 0
