"""``andoyer orbit``: the planets' elements from any orbit source or solution file (planetary.orbits)."""

from __future__ import annotations

import argparse
import json
import math

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer orbit secular --span -1e8 0 --step 1e5 --format netcdf --output secular.nc
  andoyer orbit nbody --planets earth mars --span -1e6 0 --step 1000 --format csv
  andoyer orbit La2010a_alkhqp3L.dat --span -1e7 0 --step 1e4 --format json
  andoyer orbit solution.txt --orbit-format zb18a --step 1e4
SOURCE is nbody, secular, laplace-lagrange, vondrak (the Earth's ecliptic: i and node only) or a
file: a CSV orbit table, La2004 (INSOLN/INSOLP...ASC), La2010 (..._alkhqp3L.dat, ..._ecc3L.dat),
ZB18a (ems-plan3.dat), ZB17/ZB18a/ZB20 eccentricity (ZB20a.dat), ZB23 (ZB23.Rxx.eiop.dat),
recognised from the name or the columns or named with --orbit-format (docs/orbits.md).
T0, T1 and DT are Julian years from J2000 (negative = past); default span: the file's, or
-1e5 0 for a named source. Elements in the J2000 ecliptic and equinox: a (au), e, inclination,
perihelion (longitude, varpi = node + argument), node (deg); null (JSON), empty (CSV, table) or
NaN (NetCDF) where the source does not know one (the N-body cache keeps no a; an eccentricity
solution gives e alone). JSON keys: source, t, planets, elements (per planet, per element, a
list over t). CSV and table: one row per time and planet, columns t_yr, planet, a_au, e,
inclination_deg, perihelion_deg, node_deg. NetCDF (needs --output; the ensemble extra, for
xarray): variables a, e, inclination, perihelion, node over (time, planet).
"""

DEFAULT_SPAN = (-1.0e5, 0.0)
DEFAULT_STEP = 1000.0
_MAX_ROWS = 10_000_000
#: Bytes per element value while the output is built (float64 and its formatted text, a bound).
_BYTES_PER_VALUE = 64.0
_HEADER = ("t_yr", "planet", "a_au", "e", "inclination_deg", "perihelion_deg", "node_deg")


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.orbits.factory import SOLUTION_FORMATS

    parser = commands.add_parser(
        "orbit",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "source",
        metavar="SOURCE",
        help="nbody, secular, laplace-lagrange, vondrak, or the path of an orbit or solution file",
    )
    parser.add_argument(
        "--planets",
        nargs="+",
        type=str.lower,
        metavar="PLANET",
        help="the planets written (default: all the source knows)",
    )
    parser.add_argument(
        "--span",
        nargs=2,
        type=finite_number,
        metavar=("T0", "T1"),
        help="first and last output time, Julian years from J2000 (default: the file's, or -1e5 0)",
    )
    parser.add_argument(
        "--step",
        type=finite_number,
        metavar="DT",
        default=DEFAULT_STEP,
        help="output step, years (default 1000)",
    )
    parser.add_argument(
        "--orbit-format",
        choices=SOLUTION_FORMATS,
        help="the format of a SOURCE file (default: recognised from its name or columns)",
    )
    parser.add_argument(
        "--format",
        choices=("json", "csv", "table", "netcdf"),
        default="json",
        help="output format (default json); netcdf needs --output",
    )
    add_output_argument(parser)
    parser.set_defaults(run=run)


def _rows(record) -> list[list[object]]:  # type: ignore[no-untyped-def]
    columns = record.columns()
    keys = ("a", "e", "inclination", "perihelion", "node")
    rows = []
    for i, t in enumerate(record.t):
        for j, planet in enumerate(record.planets):
            values = [float(columns[k][i, j]) for k in keys]
            rows.append([float(t), planet, *("" if math.isnan(v) else v for v in values)])
    return rows


def run(args: argparse.Namespace) -> int:
    """Build the source's planets, sample their elements, write them."""
    from pathlib import Path

    from andoyer._limits import check_size
    from andoyer.planetary.orbits.factory import SOURCES, planet_orbits
    from andoyer.planetary.spin_axis import output_times

    if args.format == "netcdf" and args.output in (None, "-"):
        msg = "expected --output FILE with --format netcdf (a binary file), got standard output"
        raise CliError(msg)
    named = args.source in SOURCES
    if not named and not Path(args.source).is_file():
        msg = f"expected SOURCE among {', '.join(SOURCES)} or an existing orbit file, got {args.source!r}"
        raise CliError(msg)
    if named and args.orbit_format is not None:
        msg = f"expected --orbit-format only with a SOURCE file, got the {args.source} orbit"
        raise CliError(msg)
    if args.format == "netcdf":
        try:
            import xarray  # noqa: F401
        except ImportError as exc:
            msg = f"expected xarray for --format netcdf (pip install 'andoyer[ensemble]'), got {exc}"
            raise CliError(msg) from exc
    options = {"progress": None} if args.source in ("nbody", "secular") else {}
    system = planet_orbits(args.source, args.planets, args.orbit_format, **options)
    if args.span is not None:
        t0, t1 = args.span
    elif named:
        t0, t1 = DEFAULT_SPAN
    else:
        t0, t1 = system.span
    lo, hi = system.span
    if t0 < lo or t1 > hi:
        msg = (
            f"expected --span T0 T1 within the {system.name} orbit's span {lo:g} to {hi:g} years from "
            f"J2000, got {t0:g} {t1:g}"
        )
        raise CliError(msg)
    times = output_times(t0, t1, args.step)
    planets = system.select(args.planets)
    rows = times.size * len(planets)
    if rows > _MAX_ROWS:
        msg = f"expected at most {_MAX_ROWS} rows (times x planets), got {rows}: a longer --step"
        raise CliError(msg)
    check_size(f"the elements of {rows} rows", nbytes=_BYTES_PER_VALUE * 6 * rows)
    record = system.elements(times, planets)
    if args.format == "netcdf":
        data = record.to_dataset().to_netcdf()  # NetCDF 3 through scipy: no further dependency
        with atomic_output(args.output, binary=True) as stream:
            stream.write(bytes(data))
        return 0
    text = (
        json.dumps(record.as_dict()) + "\n"
        if args.format == "json"
        else format_rows(_HEADER, _rows(record), args.format)
    )
    with atomic_output(args.output) as stream:
        stream.write(text)
    return 0
