"""``andoyer bodies``: the catalogue of named bodies, one body, or a body file checked.

``andoyer bodies`` prints every catalogued body (table or CSV: one row each; JSON: every body
with all its values, units, uncertainties and sources); ``andoyer bodies NAME`` one body;
``andoyer bodies --body-file PATH`` reads and checks a body file of the user's and prints it the
same way (the JSON of one body is the body-file format). ``--moments lara2013`` lists Lara's
(2013) Table 1 set instead of the catalogue's moments (the bodies ``--body NAME`` means in the
other commands).
"""

from __future__ import annotations

import argparse
import json
import re
import sys

from andoyer import catalogue

#: The columns of the table and CSV output: the first ten are those of earlier releases.
HEADER = (
    "name",
    "I1",
    "I2",
    "I3",
    "alpha",
    "beta",
    "kappa",
    "rotation_period_s",
    "J0_rad",
    "source",
    "kind",
    "primary",
    "gm_km3_s2",
    "radius_km",
    "j2",
    "c22",
    "moment_of_inertia",
    "dynamical_ellipticity",
    "pole_ra_deg",
    "pole_dec_deg",
    "rotation_rate_deg_d",
    "semi_major_axis_km",
    "eccentricity",
    "inclination_deg",
)
#: Catalogue keys of the columns after ``primary`` and the unit each is printed in.
_VALUES = (
    ("gm", "km3/s2"),
    ("radius", "km"),
    ("j2", "1"),
    ("c22", "1"),
    ("moment_of_inertia", "1"),
    ("dynamical_ellipticity", "1"),
    ("pole_ra", "deg"),
    ("pole_dec", "deg"),
    ("rotation_rate", "deg/d"),
    ("semi_major_axis", "km"),
    ("eccentricity", "1"),
    ("inclination", "deg"),
)
MOMENT_SETS = ("catalogue", "lara2013")


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "bodies",
        help="the catalogue of bodies with sources, one body, or a body file checked",
        description=(
            "Print the catalogue of bodies (GM, radius, J2, C22, C/MR2, moments, IAU pole, orbit), "
            "every value with its source in --format json. A body file (JSON or TOML) has the keys "
            "'andoyer bodies NAME --format json' prints."
        ),
    )
    parser.add_argument("name", nargs="?", help="one catalogued body (case-insensitive)")
    parser.add_argument("--body-file", metavar="PATH", help="read and check a body file (JSON or TOML)")
    parser.add_argument("--format", choices=("table", "csv", "json"), default="table", help="default table")
    parser.add_argument(
        "--moments",
        choices=MOMENT_SETS,
        default="catalogue",
        help="moment set of the I1..I3 columns: the catalogue's, or Lara's (2013) Table 1 (its four bodies)",
    )
    parser.set_defaults(run=run)


def _short(source: str) -> str:
    """A citation's author-and-year head, for the text table."""
    head = re.match(r"^(.{0,60}?\(\d{4}[a-z]?\))", source)
    return head.group(1) if head else source[:40]


def _row(body: catalogue.Body, moment_set: str | None, short: bool) -> list[object]:
    from andoyer.body import RigidBody

    cells: list[object] = [body.key]
    chosen = body.moment_sets.get(moment_set, {}) if moment_set else {}
    try:
        a, b = body.moments(moment_set)
    except ValueError:
        cells += ["", "", "", "", "", ""]
        moment_sources: list[str] = []
    else:
        rigid = RigidBody.from_ratios(a, b, name=body.name)
        cells += [rigid.I1, rigid.I2, rigid.I3, rigid.alpha, rigid.beta, rigid.kappa]
        quantities = [chosen.get(k) or getattr(body, k) for k in ("a_over_c", "b_over_c")]
        derived = ("dynamical_ellipticity", "j2", "c22", "moment_of_inertia")
        if None in quantities:  # the moments come from the figure (Body.moments)
            quantities = [getattr(body, k) for k in derived if getattr(body, k) is not None]
        moment_sources = [q.source for q in quantities if q is not None]
    period = chosen.get("rotation_period") or (None if moment_set else body.rotation_period)
    j0 = chosen.get("j0") or (None if moment_set else body.j0)
    cells += ["" if period is None else period.si(), "" if j0 is None else j0.si()]
    sources = list(dict.fromkeys(_short(s) if short else s for s in moment_sources))
    cells += ["; ".join(sources), body.kind, body.primary or ""]
    for key, unit in _VALUES:
        q = getattr(body, key)
        cells.append("" if q is None else q.to(unit))
    return cells


def rows(
    names: tuple[str, ...] | None = None, moment_set: str = "catalogue", short: bool = False
) -> list[list[object]]:
    """One row per body, in the order of :data:`HEADER` (empty cells where a value is absent).

    Parameters
    ----------
    names : tuple of str, optional
        Catalogued names (default: all; with ``moment_set="lara2013"`` those that have it).
    moment_set : {"catalogue", "lara2013"}
    short : bool
        Author-and-year citations (the text table) instead of full ones.
    """
    chosen = None if moment_set == "catalogue" else moment_set
    entries = [catalogue.get(n) for n in (names or catalogue.names())]
    if chosen is not None:
        entries = [e for e in entries if chosen in e.moment_sets]
    return [_row(e, chosen, short) for e in entries]


def run(args: argparse.Namespace) -> int:
    """Print the catalogue, one body, or a checked body file."""
    from andoyer.cli.output import CliError, format_rows

    if args.name is not None and args.body_file is not None:
        msg = f"expected a body NAME or --body-file, got both ({args.name!r} and {args.body_file!r})"
        raise CliError(msg)
    try:
        if args.body_file is not None:
            entries = [catalogue.read_body(args.body_file)]
        elif args.name is not None:
            entries = [catalogue.get(args.name)]
        else:
            entries = [catalogue.get(n) for n in catalogue.names()]
    except ValueError as err:
        raise CliError(str(err)) from None
    if args.format == "json":
        data = [e.to_dict() for e in entries]
        if args.moments != "catalogue":
            data = [d for d, e in zip(data, entries, strict=True) if args.moments in e.moment_sets]
        single = args.name is not None or args.body_file is not None
        json.dump(data[0] if single and data else data, sys.stdout, indent=2, ensure_ascii=False)
        sys.stdout.write("\n")
        return 0
    chosen = None if args.moments == "catalogue" else args.moments
    if chosen is not None:
        entries = [e for e in entries if chosen in e.moment_sets]
    table = [_row(e, chosen, short=args.format == "table") for e in entries]
    sys.stdout.write(format_rows(HEADER, table, args.format))
    return 0
