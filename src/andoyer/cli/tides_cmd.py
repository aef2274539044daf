"""``andoyer tides``: the tidal history of the Earth–Moon system (planetary.tides)."""

from __future__ import annotations

import argparse
import json
import math

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer tides earth --span -3e9 0 --step 1e7 --format json --output tides.json
  andoyer tides earth --model constant-lag --span -1e9 0 --step 1e8
  andoyer tides earth --span -2.5e9 0 --step 5e6 --plot tides.png
T0, T1 and DT are Julian years from J2000 (negative = past), within the age of the Moon
(4.425 Gyr); output at T0, T0+DT, ..., T1. --model ocean (default) is a resonant global ocean
after Farhat et al. (2022), fitted to the lunar recession of 3.830 cm/yr and the age of the
Moon; constant-lag is a constant time lag calibrated to the same recession (it brings the Moon
to the Earth about 1.1 Gyr ago: earlier times are refused). --no-solar-tide leaves out the
Sun's tide on the Earth. --obliquity EPS is the obliquity at J2000 in degrees (default IAU
2006, 23.4393). A span the model cannot reach (the Moon inside the Laplace-plane transition)
is refused. JSON keys: t (years), day_length (hours, the mean solar day), lunar_distance (km),
precession_constant (arcsec/yr, alpha cos(obliquity), Laskar et al. 2004), obliquity (deg),
dynamical_ellipticity (H), model.
"""

DEFAULT_SPAN = (-1.0e9, 0.0)
DEFAULT_STEP = 1.0e7
_MAX_POINTS = 1_000_000


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "tides",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "body", type=str.lower, choices=("earth",), metavar="BODY", help="earth (the Earth-Moon system)"
    )
    parser.add_argument(
        "--model",
        choices=("ocean", "constant-lag"),
        default="ocean",
        help="the Earth's tidal response: ocean (default, after Farhat et al. 2022) or constant-lag",
    )
    parser.add_argument(
        "--span",
        nargs=2,
        type=finite_number,
        metavar=("T0", "T1"),
        default=DEFAULT_SPAN,
        help="first and last output time, Julian years from J2000 (default -1e9 0)",
    )
    parser.add_argument(
        "--step",
        type=finite_number,
        metavar="DT",
        default=DEFAULT_STEP,
        help="output step, years (default 1e7)",
    )
    parser.add_argument(
        "--obliquity", type=finite_number, metavar="EPS", help="obliquity at J2000, degrees (default 23.4393)"
    )
    parser.add_argument("--no-solar-tide", action="store_true", help="leave out the Sun's tide on the Earth")
    parser.add_argument(
        "--format", choices=("json", "csv", "table"), default="table", help="output format (default table)"
    )
    add_output_argument(parser)
    add_output_argument(parser, "--plot", "PNG of distance, day length, precession constant and obliquity")
    parser.set_defaults(run=run)


def _table(fields: dict, fmt: str) -> str:
    header = ["t_yr", "day_length_h", "lunar_distance_km", "precession_constant_arcsec_yr", "obliquity_deg",
              "dynamical_ellipticity"]
    keys = ["t", "day_length", "lunar_distance", "precession_constant", "obliquity", "dynamical_ellipticity"]
    rows = [[float(fields[k][i]) for k in keys] for i in range(len(fields["t"]))]
    return format_rows(header, rows, fmt)


def run(args: argparse.Namespace) -> int:
    """Integrate the tidal history and write the table (and the plot)."""
    t0, t1 = args.span
    if not args.step > 0:
        msg = f"expected --step DT > 0 years, got {args.step!r}"
        raise CliError(msg)
    if t1 < t0:
        msg = f"expected --span T0 T1 with T1 >= T0, got {t0!r} {t1!r}"
        raise CliError(msg)
    if (t1 - t0) / args.step >= _MAX_POINTS:
        msg = f"expected at most {_MAX_POINTS} output times, got {(t1 - t0) / args.step:.3g}"
        raise CliError(msg)
    if args.obliquity is not None:
        from andoyer.planetary.parameters import check

        check("obliquity", args.obliquity, degrees=True)
    if args.plot is not None and not args.plot.lower().endswith(".png"):
        msg = f"expected --plot PATH ending in .png, got {args.plot!r}"
        raise CliError(msg)
    from andoyer.planetary.spin_axis import output_times
    from andoyer.planetary.tides import tidal_history

    times = output_times(t0, t1, args.step)
    h = tidal_history(
        times,
        args.model,
        solar_tide=not args.no_solar_tide,
        obliquity=None if args.obliquity is None else math.radians(args.obliquity),
    )
    fields = h.as_dict()
    text = json.dumps(fields) + "\n" if args.format == "json" else _table(fields, args.format)
    figure = None
    if args.plot is not None:
        from andoyer.plot import tidal_history_plot

        figure = tidal_history_plot(h)
    with atomic_output(args.output) as stream:
        stream.write(text)
    if figure is not None:
        with atomic_output(args.plot, binary=True) as stream:
            figure.savefig(stream, format="png", dpi=120)
    return 0
