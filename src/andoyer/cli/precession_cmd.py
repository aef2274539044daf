"""``andoyer precession``: the precession constant and rate of any body's spin axis about its orbit normal."""

from __future__ import annotations

import argparse
import json

from andoyer.cli.numbers import physical, positive_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output

EXAMPLES = """examples:
  andoyer precession earth
  andoyer precession saturn --format json
  andoyer precession mars --integrate 2 --format json
  andoyer precession earth --integrate 1 --step 8.227 --output earth.json --format json
  andoyer precession earth --moments lara2013
  andoyer precession --body-file my-planet.toml
BODY: a catalogued body (andoyer bodies) or --body-file PATH (JSON or TOML with the keys of
andoyer bodies NAME --format json). Every body: the precession constant alpha (satellites
included: the rings inside the Laplace radius, e.g. the Galilean satellites, Titan, Triton,
and the perturbers outside it, the Moon) and the precession rate psi_dot = alpha cos(obliquity)
(andoyer.planetary.precession_constant). A body lacking a value it needs is refused naming it.
The Earth and Mars also: the rate of regression of the angular momentum's node on the planet's
ecliptic from the averaged (secular) model of the Sun's (and Moon's) gravity-gradient torque, and
with --integrate YEARS from a full splitting integration (andoyer.planetary.precession).
Moments: the catalogue's by default (the Earth's IAU MHB2000 H = 0.00327379492: 50.40 arcsec/yr at
first order); --moments lara2013 takes Lara's (2013) Table 1 (H = 0.0032789: 50.48 arcsec/yr).
--dynamical-ellipticity H replaces the body's figure; refused for a body whose satellites inside
its Laplace radius need J2 and C/MR^2 apart (edit a body file instead).
JSON keys: body, perturbers, obliquity_deg, secular_arcsec_per_year, integrated_arcsec_per_year
(null without --integrate), integration_years, step_days (the last four null but for the Earth and
Mars), precession_constant, solar_precession_constant (without satellites; for a body in spin-orbit
resonance its J2 part), precession_rate (all three
arcsec/yr; precession_rate null where the obliquity is not known), effective_ellipticity
((J2 + q)/(C/MR^2 + l)), laplace_radius_km, resonance, satellites (name, regime ring|outer,
quadrupole, angular_momentum, torque, laplace_ratio).
"""


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.precession import MOMENT_SETS

    parser = commands.add_parser(
        "precession",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("body", nargs="?", type=str.lower, metavar="BODY", help="a catalogued body")
    add_body_file_argument(parser)
    parser.add_argument(
        "--integrate",
        type=positive_number,
        metavar="YEARS",
        help="also integrate the full torque this long (Earth, Mars)",
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
        help="H = (C - (A+B)/2)/C instead of the body's (0 < H < 1/2)",
    )
    parser.add_argument(
        "--moments",
        choices=MOMENT_SETS,
        default="catalogue",
        help="the moment set of the Earth or Mars: the catalogue's (default) or Lara's (2013) Table 1",
    )
    parser.add_argument("--format", choices=("text", "json"), default="text", help="default text")
    add_output_argument(parser)
    parser.set_defaults(run=run)


def add_body_file_argument(parser: argparse.ArgumentParser) -> None:
    """``--body-file PATH`` (shared with ``andoyer obliquity``)."""
    parser.add_argument(
        "--body-file", metavar="PATH", help="a body of your own (JSON or TOML) in place of BODY"
    )


def body_from_args(name: str | None, body_file: str | None):  # type: ignore[no-untyped-def]
    """The catalogue entry named, or the checked body of ``--body-file``: exactly one of them."""
    from andoyer import catalogue

    if (name is None) == (body_file is None):
        got = "neither" if name is None else f"both ({name!r} and --body-file {body_file!r})"
        msg = f"expected a BODY or a --body-file PATH, got {got}"
        raise CliError(msg)
    return catalogue.read_body(body_file) if body_file is not None else catalogue.get(name)


def render_text(fields: dict) -> str:
    """The rates as a few human-readable lines."""
    lines = [f"precession of the spin axis of {fields['body']} about its orbit normal"]
    if fields["obliquity_deg"] is not None:
        lines.append(f"obliquity: {fields['obliquity_deg']:.4f} deg")
    part = "J2 alone" if fields["resonance"] is not None else "no satellite"
    lines.append(
        f"precession constant: {fields['precession_constant']:.6g} arcsec/yr "
        f"({part}: {fields['solar_precession_constant']:.6g})"
    )
    if fields["precession_rate"] is not None:
        lines.append(f"precession rate alpha cos(obliquity): {fields['precession_rate']:.6g} arcsec/yr")
    for s in fields["satellites"]:
        share = (
            f"q {s['quadrupole']:.4g}, l {s['angular_momentum']:.4g}"
            if s["regime"] == "ring"
            else f"torque {s['torque']:.4g} of the Sun's"
        )
        lines.append(f"  satellite {s['name']} ({s['regime']}, a/r_L {s['laplace_ratio']:.3g}): {share}")
    if fields["secular_arcsec_per_year"] is not None:
        lines.append(f"perturbers: {', '.join(fields['perturbers'])}")
        lines.append(f"secular model: {fields['secular_arcsec_per_year']:.4f} arcsec/yr")
    if fields["integrated_arcsec_per_year"] is not None:
        lines.append(
            f"full integration ({fields['integration_years']:.3f} yr, step {fields['step_days']:.4f} d): "
            f"{fields['integrated_arcsec_per_year']:.4f} arcsec/yr"
        )
    return "\n".join(lines) + "\n"


def _check_model_options(args: argparse.Namespace, numerical: bool, name: str) -> None:
    """The options of the Earth's and Mars' numerical model, refused elsewhere."""
    if not numerical:
        given = [
            flag
            for flag, value in (("--integrate", args.integrate), ("--step", args.step))
            if value is not None
        ]
        if args.moments != "catalogue":
            given.append("--moments")
        if given:
            msg = (
                f"expected {', '.join(given)} only for the catalogue's earth or mars (the bodies with "
                f"mean perturbers), got {name}"
            )
            raise CliError(msg)
        return
    from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR

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


def run(args: argparse.Namespace) -> int:
    """Compute the constant (and the rates) and write them."""
    from andoyer.perturbations.solar_system import DAY
    from andoyer.planetary.precession import PLANETS, planet_body, precession_rates
    from andoyer.planetary.precession_constant import precession_constant

    entry = body_from_args(args.body, args.body_file)
    numerical = args.body_file is None and entry.key in PLANETS
    _check_model_options(args, numerical, entry.name if args.body_file is None else args.body_file)
    H = args.dynamical_ellipticity
    if numerical and H is None and args.moments != "catalogue":
        planet = planet_body(entry.key, args.moments)[0]
        H = 1 - (planet.A + planet.B) / 2  # the constant of the same moments
    constant = precession_constant(entry, dynamical_ellipticity=H)
    fields = {
        "body": entry.key if args.body_file is None else entry.name,
        "perturbers": [],
        "obliquity_deg": constant.as_dict()["obliquity_deg"],
        "secular_arcsec_per_year": None,
        "integrated_arcsec_per_year": None,
        "integration_years": None,
        "step_days": None,
    }
    if numerical:
        rates = precession_rates(
            entry.key,
            integrate=args.integrate,
            step=None if args.step is None else args.step * DAY,
            order=args.order,
            dynamical_ellipticity=args.dynamical_ellipticity,
            moments=args.moments,
        )
        fields.update(rates.as_dict())
    fields.update({k: v for k, v in constant.as_dict().items() if k != "obliquity_deg"})
    text = json.dumps(fields, indent=2) + "\n" if args.format == "json" else render_text(fields)
    with atomic_output(args.output) as stream:
        stream.write(text)
    return 0
