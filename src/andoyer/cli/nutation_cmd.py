"""``andoyer nutation``: the rigid-Earth luni-solar nutation of the figure (or another) axis."""

from __future__ import annotations

import argparse
import math

from andoyer.cli.numbers import finite_number, physical
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer nutation earth --span 0 20 --step 0.01 --format csv --output nutation.csv
  andoyer nutation earth --span 0 18.7 --step 0.1 --terms
  andoyer nutation earth --span -10 10 --step 0.05 --axis momentum --format json --plot nut.png
Times are Julian years TT from J2000; dpsi and deps are the nutations in longitude and in
obliquity (arcsec) of the chosen axis, referred to the mean ecliptic and equinox of date, from an
integration of the Moon's and the Sun's torque on the oblate Earth (andoyer.planetary.nutation).
--terms fits the principal terms over the span, which must cover one period of the slowest
(the 18.6-year node, 18.613 years), and lists them beside IAU 2000A (non-rigid).
JSON keys: t, dpsi, deps (and with --terms: terms, precession_arcsec_per_year).
"""

_MAX_POINTS = 2_000_000


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.nutation import AXES, H_MHB2000

    parser = commands.add_parser(
        "nutation",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "body", type=str.lower, choices=("earth",), help="the Earth (the only body with a lunar theory)"
    )
    parser.add_argument(
        "--span",
        nargs=2,
        type=finite_number,
        metavar=("T0", "T1"),
        required=True,
        help="first and last output time, Julian years from J2000 (within -100000 to 39747)",
    )
    parser.add_argument("--step", type=finite_number, metavar="DT", required=True, help="years")
    parser.add_argument(
        "--dynamical-ellipticity",
        type=physical("dynamical_ellipticity"),
        metavar="H",
        default=H_MHB2000,
        help=f"H = (C - (A+B)/2)/C (default {H_MHB2000}, MHB2000)",
    )
    parser.add_argument(
        "--axis", choices=AXES, default="figure", help="the axis whose nutation is given (default figure)"
    )
    parser.add_argument("--terms", action="store_true", help="print the fitted principal terms")
    parser.add_argument("--format", choices=("json", "csv", "table"), default="table", help="default table")
    add_output_argument(parser)
    add_output_argument(parser, "--plot", "also draw dpsi and deps (PNG, SVG or PDF)")
    parser.set_defaults(run=run)


def _times(t0: float, t1: float, step: float):  # type: ignore[no-untyped-def]
    import numpy as np

    if not step > 0:
        msg = f"expected --step DT > 0, got {step!r}"
        raise CliError(msg)
    if t1 < t0:
        msg = f"expected --span T0 T1 with T1 >= T0, got {t0!r} {t1!r}"
        raise CliError(msg)
    if t1 > t0 and step > t1 - t0:
        msg = f"expected --step no longer than the span {t1 - t0!r}, got {step!r}"
        raise CliError(msg)
    count = math.floor((t1 - t0) / step * (1 + 1e-12)) + 1
    if count > _MAX_POINTS:
        msg = f"expected at most {_MAX_POINTS} output times, got {count} (raise --step)"
        raise CliError(msg)
    return t0 + step * np.arange(count)


def _plot_format(path: str) -> str:
    fmt = path.rsplit(".", 1)[-1].lower() if "." in path else ""
    if fmt not in ("png", "svg", "pdf"):
        msg = f"expected a --plot file ending in .png, .svg or .pdf, got {path!r}"
        raise CliError(msg)
    return fmt


#: Bytes per point of a drawn curve (two panels; measured about 100 for PNG, SVG and PDF).
PLOT_POINT_BYTES = 200


def _check_cost(args: argparse.Namespace, t) -> float:  # type: ignore[no-untyped-def]
    """Refuse a request that cannot fit in memory or time, before any work; its seconds."""
    from andoyer._limits import check_size
    from andoyer.cli.output import BLOCK_ROWS, FORMAT_SECONDS
    from andoyer.planetary.nutation import nutation_cost

    seconds, nbytes = nutation_cost(t, passes=2 if args.terms else 1)
    seconds += t.size * 3 * FORMAT_SECONDS * (2 if args.format == "table" else 1)
    nbytes += BLOCK_ROWS * 3 * 40  # a block's text
    if args.plot is not None:
        nbytes += t.size * PLOT_POINT_BYTES
    check_size(f"a nutation run of {t.size} output times", nbytes=nbytes, seconds=seconds)
    return seconds


def run(args: argparse.Namespace) -> int:
    """Compute the nutation and write it (and the terms, and the picture), a block of rows at a time."""
    from andoyer._limits import announce
    from andoyer.cli.output import write_json, write_rows
    from andoyer.perturbations.lunar_theory import check_span
    from andoyer.planetary import nutation
    from andoyer.planetary.precession import check_dynamical_ellipticity

    H = check_dynamical_ellipticity(args.dynamical_ellipticity)
    t0, t1 = args.span
    check_span(t0, t1, "--span T0 T1")
    end = max(t1, t0 + nutation.minimum_span() * 1.001)  # the integration covers one 18.6-year node
    check_span(t0, end, f"--span T0 T1 and the integration's {end - t0:.4g} years from T0")
    t = _times(t0, t1, args.step)
    fmt_plot = None if args.plot is None else _plot_format(args.plot)
    seconds = _check_cost(args, t)
    announce(seconds, f"integrating the nutation over {max(t1 - t0, nutation.minimum_span()):.6g} years")
    table = nutation.terms_table((t0, t1), H, args.axis) if args.terms else None
    dpsi, deps = nutation.nutation(t, H, args.axis)
    if args.plot is not None:
        from andoyer.plot.nutation import nutation_plot

        figure = nutation_plot(t, dpsi, deps, f"rigid-Earth nutation, {args.axis} axis, H = {H}")
        with atomic_output(args.plot, binary=True) as stream:
            figure.savefig(stream, format=fmt_plot, dpi=120)
    with atomic_output(args.output) as stream:
        if args.format == "json":
            fields = {"t": t, "dpsi": dpsi, "deps": deps}
            if table is not None:
                fields["terms"] = table["terms"]
                fields["precession_arcsec_per_year"] = table["precession"]
            write_json(stream, fields)
        elif table is not None:
            header = list(table["terms"][0])
            rows = [
                [" ".join(map(str, row[key])) if isinstance(row[key], list) else row[key] for key in header]
                for row in table["terms"]
            ]
            stream.write(format_rows(header, rows, args.format))
            if args.format == "table":
                stream.write(f"luni-solar precession (integrated): {table['precession']:.4f} arcsec/yr\n")
        else:
            write_rows(stream, ["t", "dpsi", "deps"], [t, dpsi, deps], args.format)
    return 0
