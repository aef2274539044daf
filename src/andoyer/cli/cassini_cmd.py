"""``andoyer cassini``: the Cassini states of a named body, a body file or values; the inverse problem."""

from __future__ import annotations

import argparse
import json
import math
from typing import TYPE_CHECKING

from andoyer.cli.numbers import finite_number, physical
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer cassini moon
  andoyer cassini titan --format json
  andoyer cassini europa --node catalogue
  andoyer cassini --body-file titan-ocean.toml
  andoyer cassini titan --obliquity 0.32 --obliquity-error 0.02
  andoyer cassini --j2 3.18e-5 --c22 9.98e-6 --moment-of-inertia 0.34 --orbital-period 15.945 \\
      --eccentricity 0.029 --node-period 703 --inclination 0.28 --mass-ratio 2.4e-4 --resonance 1
The states of Colombo's top (andoyer.planetary.cassini), numbered as Peale (1969): only those that exist.
BODY: a catalogued body with J2, C22, C/MR^2, orbit and resonance (moon, mercury, io, europa,
ganymede, callisto, titan), or --body-file PATH (JSON or TOML, the keys of andoyer bodies NAME
--format json). --node: where the node rate and inclination come from: model (the satellite
system's Laplace planes and node modes from the planet's J2, the Sun and the satellites),
catalogue (the body's node_period and inclination), auto (model for Jupiter's and Saturn's
satellites, catalogue otherwise).
The value options give a body whole: all of --j2 --c22 --moment-of-inertia --orbital-period
--eccentricity --node-period --inclination --mass-ratio --resonance, or none (a part of them would
leave the rest to another body: refused, naming what is missing; edit a body file instead).
--obliquity DEG [--obliquity-error DEG]: the inverse problem, C/MR^2 from an observed obliquity
(the body's own C/MR^2 is not used), with the catalogue's J2, C22 uncertainties carried through.
obliquity: spin axis to orbit normal (deg); inclination_to_laplace: spin axis to the Laplace pole
(deg); precession_constant (alpha), resonance_constant (beta), node_rate (g < 0) in arcsec per
Julian year; node_period in Julian years.
JSON keys: body, resonance, states (number, obliquity, inclination_to_laplace, stable),
precession_constant, resonance_constant, node_rate, inclination, node_source, node_period, modes
(node_period, inclination, phase, state, obliquity), obliquity, obliquity_range, and with
--obliquity: inverse (obliquity, obliquity_error, solutions: moment_of_inertia, error,
contributions).
"""

if TYPE_CHECKING:
    from andoyer.planetary.cassini import CassiniBody, ForcedObliquity

#: The value options: flag -> (destination, help). All nine give a body whole.
VALUES = {
    "--j2": ("j2", "unnormalised J2 = (C - (A+B)/2)/MR^2 (J2 > 0)"),
    "--c22": ("c22", "unnormalised C22 = (B - A)/4MR^2 (C22 <= J2/2)"),
    "--moment-of-inertia": ("moment_of_inertia", "polar moment C/MR^2 (0 < C/MR^2 <= 1)"),
    "--orbital-period": ("orbital_period", "sidereal orbital period, days (> 0)"),
    "--eccentricity": ("eccentricity", "orbital eccentricity (0 <= e < 1)"),
    "--node-period": ("node_period", "period of the node's regression, Julian years (> 0)"),
    "--inclination": ("inclination", "orbit to Laplace plane, degrees (0 < DEG < 90)"),
    "--mass-ratio": ("mass_ratio", "body mass over the primary's (0 <= m/M < 1)"),
    "--resonance": ("resonance", "spin-orbit ratio p = spin/mean motion (1 synchronous, 1.5 Mercury)"),
}

#: The value options checked against andoyer.planetary.parameters as they are read (as the API).
PARAMETER_OF = {
    "j2": physical("j2"),
    "c22": physical("c22"),
    "moment_of_inertia": physical("moment_of_inertia"),
    "eccentricity": physical("eccentricity"),
    "node_period": physical("node_period"),
    "inclination": physical("laplace_inclination", degrees=True),
}


def add_cassini_arguments(parser: argparse.ArgumentParser) -> None:
    """The options that give a body on the command line (shared with ``portrait cassini``)."""
    parser.add_argument("--body-file", metavar="PATH", help="a body of your own (JSON or TOML)")
    parser.add_argument(
        "--node",
        choices=("auto", "model", "catalogue"),
        default="auto",
        help="where the node rate and inclination come from (default auto)",
    )
    for flag, (dest, text) in VALUES.items():
        kind = PARAMETER_OF.get(dest, finite_number)
        parser.add_argument(flag, dest=dest, type=kind, metavar="X", help=text)


def _given(args: argparse.Namespace) -> dict[str, float]:
    return {dest: getattr(args, dest) for dest, _ in VALUES.values() if getattr(args, dest) is not None}


def _from_values(name: str, values: dict[str, float]) -> CassiniBody:
    """The body the value options give (all of them: the caller checked)."""
    from andoyer.planetary.cassini import CassiniBody

    if not values["orbital_period"] > 0:
        msg = f"expected --orbital-period > 0 (days), got {values['orbital_period']!r}"
        raise CliError(msg)
    from andoyer.catalogue.units import DAY, JULIAN_YEAR

    return CassiniBody(
        name=name,
        j2=values["j2"],
        c22=values["c22"],
        moment_of_inertia=values["moment_of_inertia"],
        mean_motion=2 * math.pi * JULIAN_YEAR / (values["orbital_period"] * DAY),
        eccentricity=values["eccentricity"],
        inclination=math.radians(values["inclination"]),
        node_rate=-2 * math.pi / values["node_period"],
        resonance=values["resonance"],
        mass_ratio=values["mass_ratio"],
        source="the command line",
    )


def forced_from_args(name: str | None, args: argparse.Namespace, inverse: bool = False) -> ForcedObliquity:
    """The body and its node modes: named, from a body file, or given whole by the value options.

    With ``inverse`` the moment of inertia is the unknown: it is neither needed nor accepted.
    """
    from andoyer.planetary.cassini import ForcedObliquity, NodeMode, forced_obliquity

    given = _given(args)
    needed = [dest for dest, _ in VALUES.values() if not (inverse and dest == "moment_of_inertia")]
    flag = {dest: f for f, (dest, _) in VALUES.items()}
    if inverse and "moment_of_inertia" in given:
        msg = "expected no --moment-of-inertia with --obliquity (the inverse problem solves for it), got one"
        raise CliError(msg)
    if given:
        missing = [flag[d] for d in needed if d not in given]
        if missing:
            msg = (
                f"expected every value option or none (a body given whole: use --body-file to change a "
                f"few), got {', '.join(flag[d] for d in given)} without {', '.join(missing)}"
            )
            raise CliError(msg)
        if args.body_file is not None:
            msg = f"expected the value options or --body-file, got both (--body-file {args.body_file!r})"
            raise CliError(msg)
        if args.node != "auto":
            msg = f"expected --node with a BODY or a --body-file (the values set the node), got {args.node!r}"
            raise CliError(msg)
        values = given if not inverse else {**given, "moment_of_inertia": _placeholder(given)}
        body = _from_values(name or "command line", values)
        return ForcedObliquity(body, (NodeMode(body.node_rate, body.inclination, 0.0),), "command line")
    if (name is None) == (args.body_file is None):
        got = "neither" if name is None else f"both ({name!r} and {args.body_file!r})"
        msg = f"expected a BODY, a --body-file or every value option, got {got}"
        raise CliError(msg)
    return forced_obliquity(_entry(name, args), args.node, unknown_moment=inverse)


def _entry(name: str | None, args: argparse.Namespace) -> object:
    from andoyer import catalogue

    return catalogue.read_body(args.body_file) if args.body_file is not None else catalogue.get(name)


def _placeholder(values: dict[str, float]) -> float:
    """A ``C/MR²`` the body accepts (the inverse problem does not use it): above ``J2 + 2C22``."""
    return min(1.0, max(0.3, 2 * values["j2"] + 4 * values["c22"]))


def cassini_body_from_args(name: str | None, args: argparse.Namespace) -> CassiniBody:
    """The body (its largest node mode) the command line names (shared with ``portrait cassini``).

    Without a name, a body file or values: the Moon.
    """
    if name is None and args.body_file is None and not _given(args):
        name = "moon"
    return forced_from_args(name, args).body


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "cassini",
        description="The Cassini states of a catalogued body (the Moon, Mercury, Titan, the Galilean "
        "satellites), of a body file or of a body given whole by its values; a satellite's node "
        "modes from its Laplace plane; C/MR^2 from an observed obliquity.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("body", nargs="?", type=str.lower, help="a catalogued body (see below)")
    parser.add_argument("--format", choices=("table", "json"), default="table", help="default table")
    add_cassini_arguments(parser)
    parser.add_argument(
        "--obliquity", type=finite_number, metavar="DEG", help="observed obliquity: solve for C/MR^2"
    )
    parser.add_argument(
        "--obliquity-error", type=finite_number, metavar="DEG", help="its one-sigma error (default 0)"
    )
    add_output_argument(parser)
    parser.set_defaults(run=run)


def cassini_fields(forced: ForcedObliquity) -> dict:
    """The JSON object of ``andoyer cassini`` (the keys of the epilog)."""
    from andoyer.catalogue.units import ARCSEC

    system = forced.body
    top = system.top()
    responses = forced.responses()
    low, high = forced.obliquity_range()
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
        "node_source": forced.source,
        "node_period": 2 * math.pi / abs(top.node_rate),
        "modes": [
            {
                "node_period": r.mode.period,
                "inclination": math.degrees(r.mode.inclination),
                "phase": math.degrees(r.mode.phase),
                "state": None if r.state is None else r.state.number,
                "obliquity": 0.0 if r.state is None else r.state.obliquity_deg,
            }
            for r in responses
        ],
        "obliquity": math.degrees(float(forced.obliquity(0.0))),
        "obliquity_range": [math.degrees(low), math.degrees(high)],
    }


def inverse_fields(forced: ForcedObliquity, obliquity: float, error: float, entry: object, node: str) -> dict:
    """The ``inverse`` object: ``C/MR²`` from an observed obliquity (degrees in, degrees out).

    ``entry`` (a catalogue body, or ``None`` for values given on the command line) brings the
    catalogue's uncertainties.
    """
    from andoyer.planetary.cassini import moment_of_inertia_from_obliquity

    if not 0 < obliquity < 90:
        msg = f"expected 0 < --obliquity < 90 degrees, got {obliquity!r}"
        raise CliError(msg)
    if not 0 <= error < 90:
        msg = f"expected 0 <= --obliquity-error < 90 degrees, got {error!r}"
        raise CliError(msg)
    solutions = moment_of_inertia_from_obliquity(
        entry if entry is not None else forced, math.radians(obliquity), math.radians(error), node=node
    )
    return {
        "obliquity": obliquity,
        "obliquity_error": error,
        "solutions": [
            {"moment_of_inertia": s.moment_of_inertia, "error": s.error, "contributions": s.contributions}
            for s in solutions
        ],
    }


def render_table(fields: dict) -> str:
    """The states as an aligned table, the modes, the constants and the inverse below it."""
    rows = [
        [s["number"], s["obliquity"], s["inclination_to_laplace"], "stable" if s["stable"] else "unstable"]
        for s in fields["states"]
    ]
    header = ["state", "obliquity_deg", "inclination_to_laplace_deg", "stability"]
    text = format_rows(header, rows, "table") + (
        f"body: {fields['body']}, inclination {fields['inclination']:.6g} deg, "
        f"precession constant {fields['precession_constant']:.8g} arcsec/yr, "
        f"resonance constant {fields['resonance_constant']:.8g} arcsec/yr, "
        f"node rate {fields['node_rate']:.8g} arcsec/yr (period {fields['node_period']:.6g} yr, "
        f"node from the {fields['node_source']})\n"
    )
    if len(fields["modes"]) > 1:
        modes = [
            [m["node_period"], m["inclination"], m["phase"], m["state"] or "-", m["obliquity"]]
            for m in fields["modes"]
        ]
        head = ["mode_period_yr", "inclination_deg", "phase_deg", "state", "obliquity_deg"]
        low, high = fields["obliquity_range"]
        text += (
            "\n"
            + format_rows(head, modes, "table")
            + (
                f"obliquity (modes summed) {fields['obliquity']:.6g} deg at the epoch, "
                f"between {low:.6g} and {high:.6g} deg over time\n"
            )
        )
    if "inverse" in fields:
        inverse = fields["inverse"]
        text += f"\nC/MR^2 from the obliquity {inverse['obliquity']:g} +- {inverse['obliquity_error']:g} deg:"
        if not inverse["solutions"]:
            text += " none (no rigid body in this Cassini state has that obliquity)\n"
        for s in inverse["solutions"]:
            parts = ", ".join(f"{k} {v:.3g}" for k, v in s["contributions"].items())
            text += f"\n  {s['moment_of_inertia']:.6g} +- {s['error']:.3g} ({parts})"
        text += "\n"
    return text


def run(args: argparse.Namespace) -> int:
    """Solve for the states (and the inverse problem) and write them."""
    inverse = args.obliquity is not None
    if args.obliquity_error is not None and not inverse:
        msg = "expected --obliquity with --obliquity-error, got --obliquity-error alone"
        raise CliError(msg)
    forced = forced_from_args(args.body, args, inverse=inverse)
    fields = cassini_fields(forced)
    if inverse:
        entry = None if forced.source == "command line" else _entry(args.body, args)
        error = args.obliquity_error or 0.0
        fields["inverse"] = inverse_fields(forced, args.obliquity, error, entry, args.node)
    text = json.dumps(fields, indent=2) + "\n" if args.format == "json" else render_table(fields)
    with atomic_output(args.output) as stream:
        stream.write(text)
    return 0
