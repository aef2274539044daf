"""``andoyer orbit``: the planets' elements from any orbit source or solution file (planetary.orbits)."""

from __future__ import annotations

import argparse
import json
import math
import sys

import numpy as np

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows

EXAMPLES = """examples:
  andoyer orbit secular --span -1e8 0 --step 1e5 --format netcdf --output secular.nc
  andoyer orbit nbody --planets earth mars --span -1e6 0 --step 1000 --format csv
  andoyer orbit La2010a_alkhqp3L.dat --span -1e7 0 --step 1e4 --format json
  andoyer orbit solution.txt --orbit-format zb18a --step 1e4
  andoyer orbit nbody --members 16 --seed 1 --span -2e7 0 --step 1e4 --format netcdf --output ens.nc
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
--members N (nbody only): an ensemble of N N-body orbits, member 0 the nominal one, member k
with the heliocentric position of --perturb (default mercury) moved by --delta au (default
1e-10, 15 m) in a direction seeded by (--seed, k); one member per Dask task (--workers, or
--scheduler ADDR), each cached in the N-body cache, so that a rerun resumes them
(docs/ensembles.md). Then JSON adds members, seed, delta, perturb and each element is a list
over members of lists over t; CSV and table add a column member; NetCDF a dim member.
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
    parser.add_argument("--members", type=int, metavar="N", help="an N-body ensemble of N members (nbody)")
    parser.add_argument("--seed", type=int, default=0, metavar="S", help="seed of the members' perturbations")
    parser.add_argument(
        "--delta",
        type=finite_number,
        default=1e-10,
        metavar="AU",
        help="displacement of the perturbed planet, au (default 1e-10)",
    )
    parser.add_argument(
        "--perturb", type=str.lower, default="mercury", metavar="PLANET", help="planet displaced"
    )
    parser.add_argument("--workers", type=int, default=2, metavar="W", help="local Dask workers (default 2)")
    parser.add_argument("--scheduler", metavar="ADDR", help="Dask scheduler address, or synchronous")
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


def _member_rows(records) -> list[list[object]]:  # type: ignore[no-untyped-def]
    rows = []
    for k, record in enumerate(records):
        rows += [[row[0], k, *row[1:]] for row in _rows(record)]
    rows.sort(key=lambda row: (row[0], row[1]))  # by time, then member (then planet, kept)
    return rows


def _ensemble(args: argparse.Namespace, times, planets: tuple[str, ...]) -> str | bytes:  # type: ignore[no-untyped-def]
    """Integrate the members, then their elements in the output format."""
    from andoyer.planetary.orbits.planet_elements import ElementsFromOrbit, PlanetOrbits

    try:
        from andoyer.ensemble.nbody import nbody_member, run_nbody_ensemble
    except ImportError as exc:
        msg = f"expected the ensemble extra for --members (pip install 'andoyer[ensemble]'), got {exc}"
        raise CliError(msg) from exc
    if args.members < 1:
        msg = f"expected --members N >= 1, got {args.members}"
        raise CliError(msg)
    if args.workers < 1:
        msg = f"expected --workers W >= 1, got {args.workers}"
        raise CliError(msg)
    if args.seed < 0:
        msg = f"expected --seed S >= 0, got {args.seed}"
        raise CliError(msg)
    settings = {"seed": args.seed, "delta": args.delta, "perturb": args.perturb}
    span = (float(times[0]), float(times[-1]))
    run_nbody_ensemble(
        args.members,
        span,
        scheduler=args.scheduler,
        n_workers=args.workers,
        progress=sys.stderr.isatty(),
        **settings,
    )
    records = []
    for k in range(args.members):
        members = {
            p: ElementsFromOrbit(
                nbody_member(k, p, max_span=max(abs(span[0]), abs(span[1]), 1000.0), **settings)
            )
            for p in planets
        }
        records.append(PlanetOrbits(members, "nbody").elements(times))
    if args.format == "netcdf":
        import xarray as xr

        ds = xr.concat([r.to_dataset() for r in records], dim="member")
        ds = ds.assign_coords(member=np.arange(args.members))
        ds.attrs.update({"seed": args.seed, "delta_au": args.delta, "perturb": args.perturb})
        return bytes(ds.to_netcdf())
    if args.format == "json":
        first = records[0].as_dict()
        elements = {
            p: {k: [r.as_dict()["elements"][p][k] for r in records] for k in first["elements"][p]}
            for p in first["planets"]
        }
        fields = {**first, "members": args.members, **settings, "elements": elements}
        return json.dumps(fields) + "\n"
    return format_rows((_HEADER[0], "member", *_HEADER[1:]), _member_rows(records), args.format)


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
    if args.members is not None and args.source != "nbody":
        msg = f"expected --members only with SOURCE nbody, got {args.source!r}"
        raise CliError(msg)
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
    if args.members is not None:
        rows *= max(args.members, 1)
    check_size(f"the elements of {rows} rows", nbytes=_BYTES_PER_VALUE * 6 * rows)
    if args.members is not None:
        result = _ensemble(args, times, planets)
        with atomic_output(args.output, binary=isinstance(result, bytes)) as stream:
            stream.write(result)
        return 0
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
