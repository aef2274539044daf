"""``andoyer obliquity``: the spin axis of the Earth or Mars along a moving orbit (planetary.spin_axis)."""

from __future__ import annotations

import argparse

import numpy as np

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError, add_output_argument, atomic_output

EXAMPLES = """examples:
  andoyer obliquity earth --span -200000 200000 --step 500 --format json
  andoyer obliquity earth --precession-rate 50.3848 --span -1000 1000 --step 100 --format table
  andoyer obliquity mars --orbit nbody --span -1000000 0 --step 1000 --plot mars.png
T0, T1 and DT are Julian years from J2000 (negative = past); output at T0, T0+DT, ..., T1.
--precession-rate P is the rate of the luni-solar precession psi_A at J2000 in arcsec per Julian
year (default: Earth 50.38481507, IAU 2006; Mars 7.597); --dynamical-ellipticity H sets
(C - (A+B)/2)/C instead. --tidal-dissipation TD scales the modern tidal rates of the Earth-Moon
system (Zeebe & Lourens 2022; 0 = none). Orbit sources: vondrak (the Earth's ecliptic of
Vondrak et al. 2011, +-200 kyr, no eccentricity), nbody, secular, or a table file PATH.
JSON keys: t (years), obliquity (deg), precession (deg, p_A accumulated since J2000), axis (N x 3),
orbit_normal (N x 3, J2000 ecliptic frame), eccentricity and climatic_precession (e sin varpi,
varpi heliocentric from the moving equinox; null without eccentricity), precession_rate (arcsec/yr).
"""

DEFAULT_ORBIT = {"earth": "vondrak", "mars": "nbody"}
DEFAULT_SPAN = (-200000.0, 0.0)
DEFAULT_STEP = 1000.0


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "obliquity",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("body", type=str.lower, choices=tuple(DEFAULT_ORBIT), metavar="BODY")
    parser.add_argument(
        "--orbit", metavar="SOURCE", help="vondrak|nbody|secular|PATH (default: earth vondrak, mars nbody)"
    )
    parser.add_argument("--span", nargs=2, type=finite_number, metavar=("T0", "T1"), default=DEFAULT_SPAN)
    parser.add_argument(
        "--step", type=finite_number, metavar="DT", default=DEFAULT_STEP, help="output step, years"
    )
    strength = parser.add_mutually_exclusive_group()
    strength.add_argument(
        "--precession-rate", type=finite_number, metavar="P", help="psi_A rate at J2000, arcsec/yr"
    )
    strength.add_argument("--dynamical-ellipticity", type=finite_number, metavar="H")
    parser.add_argument("--tidal-dissipation", type=finite_number, metavar="TD", default=0.0)
    parser.add_argument("--format", choices=("json", "csv", "table"), default="table")
    add_output_argument(parser)
    add_output_argument(parser, "--plot", "PNG of obliquity and climatic precession")
    parser.set_defaults(run=run)


def orbit_source(name: str, body: str):
    """The orbit history named on the command line (:func:`andoyer.planetary.orbits.orbit_history`).

    Parameters
    ----------
    name : str
        ``vondrak``, ``nbody``, ``secular`` or a table path.
    body : str

    Returns
    -------
    OrbitHistory

    Examples
    --------
    >>> orbit_source("vondrak", "earth").name
    'vondrak'
    """
    from andoyer.planetary.orbits import orbit_history

    return orbit_history(name, body)


def _fields(h) -> dict:
    """The JSON object, numbers as numpy arrays (:func:`andoyer.cli.output.write_json` streams them)."""
    cp = h.climatic_precession
    return {
        "t": h.t,
        "obliquity": np.degrees(h.obliquity),
        "precession": np.degrees(h.precession),
        "axis": h.axis,
        "orbit_normal": h.orbit_normal,
        "eccentricity": h.eccentricity,
        "climatic_precession": cp,
        "precession_rate": h.precession_rate,
    }


def _header(has_eccentricity: bool) -> list[str]:
    header = ["t_yr", "obliquity_deg", "precession_deg", "sx", "sy", "sz", "nx", "ny", "nz"]
    # columns only where the orbit source knows the eccentricity
    return [*header, "eccentricity", "climatic_precession"] if has_eccentricity else header


def _columns(h) -> list:
    """The table's columns of a history (or of a block of one)."""
    columns = [h.t, np.degrees(h.obliquity), np.degrees(h.precession), *h.axis.T, *h.orbit_normal.T]
    cp = h.climatic_precession
    return columns if cp is None else [*columns, h.eccentricity, cp]


def _joined(blocks: list):
    """One history from consecutive blocks of it."""
    from andoyer.planetary.spin_axis import SpinAxisHistory

    def join(name: str):
        parts = [getattr(b, name) for b in blocks]
        return None if parts[0] is None else np.concatenate(parts)

    first = blocks[0]
    fields = ("t", "axis", "orbit_normal", "obliquity", "precession", "eccentricity", "perihelion")
    return SpinAxisHistory(
        *(join(name) for name in fields), first.precession_rate, first.model, first.orbit_name
    )


#: Bytes a table file of an orbit takes in memory while it is read, per byte of the file (a bound:
#: measured 24 for a 27 MB file of 250 000 rows, the CSV module's strings and lists).
TABLE_BYTES_PER_BYTE = 48
#: Bytes per point of a drawn curve (two panels; measured about 100 for PNG, SVG and PDF).
PLOT_POINT_BYTES = 200


def _check_cost(args: argparse.Namespace, orbit, times: np.ndarray, stream_csv: bool) -> None:
    """Refuse a request that cannot fit in memory or time, before any work (and ready the orbit)."""
    from andoyer.cli.output import BLOCK_ROWS, FORMAT_SECONDS
    from andoyer.planetary.spin_axis import check_run
    from andoyer.planetary.spin_axis.history import HISTORY_ROW_BYTES

    width = len(_header(orbit.has_eccentricity))
    passes = 2 if args.format == "table" else 1
    if stream_csv:  # a block of the history and its text
        row_bytes, fixed = 0.0, BLOCK_ROWS * (HISTORY_ROW_BYTES + 40 * width)
    else:  # the history, its columns in degrees while they are written, and a block's text
        row_bytes, fixed = HISTORY_ROW_BYTES + 16.0, BLOCK_ROWS * 40 * width
    if args.plot is not None:
        row_bytes += PLOT_POINT_BYTES
    what = f"an obliquity run of {times.size} output times"
    check_run(orbit, times, what, row_bytes=row_bytes, row_seconds=width * FORMAT_SECONDS * passes,
              fixed_bytes=fixed)


def _check_table(source: str) -> None:
    """Refuse an orbit table file too large to read in memory (a named source passes)."""
    import os

    from andoyer._limits import check_size
    from andoyer.planetary.orbits.factory import SOURCES

    if source in SOURCES or not os.path.isfile(source):
        return
    size = os.path.getsize(source) * TABLE_BYTES_PER_BYTE
    check_size(f"an orbit table {source!r} that fits in memory", nbytes=size)


def run(args: argparse.Namespace) -> int:
    """Integrate the axis and write the table (and the plot), a block of rows at a time."""
    from andoyer.cli.output import write_json, write_rows
    from andoyer.planetary.spin_axis import output_times, spin_axis_blocks

    t0, t1 = args.span
    if not args.step > 0:
        msg = f"expected --step DT > 0 years, got {args.step!r}"
        raise CliError(msg)
    if t1 < t0:
        msg = f"expected --span T0 T1 with T1 >= T0, got {t0!r} {t1!r}"
        raise CliError(msg)
    if args.plot is not None and not args.plot.lower().endswith(".png"):
        msg = f"expected --plot PATH ending in .png, got {args.plot!r}"
        raise CliError(msg)
    source = args.orbit or DEFAULT_ORBIT[args.body]
    _check_table(source)
    orbit = orbit_source(source, args.body)
    times = output_times(t0, t1, args.step)
    blocks = spin_axis_blocks(
        orbit,
        args.body,
        times,
        precession_rate=args.precession_rate,
        dynamical_ellipticity=args.dynamical_ellipticity,
        tidal_dissipation=args.tidal_dissipation,
    )
    stream_csv = args.format == "csv" and args.plot is None
    _check_cost(args, orbit, times, stream_csv)
    if stream_csv:
        # Rows are written as they are described; the first block (the integration) comes
        # before anything is written, so a refusal or an interruption there leaves no output.
        first = next(blocks)
        with atomic_output(args.output) as stream:
            write_rows(stream, _header(orbit.has_eccentricity), _columns(first), "csv")
            for block in blocks:
                write_rows(stream, None, _columns(block), "csv")
        return 0
    h = _joined(list(blocks))
    figure = None
    if args.plot is not None:
        from andoyer.plot import obliquity_history

        figure = obliquity_history(h)
    with atomic_output(args.output) as stream:
        if args.format == "json":
            write_json(stream, _fields(h))
        else:
            write_rows(stream, _header(orbit.has_eccentricity), _columns(h), args.format)
    if figure is not None:
        with atomic_output(args.plot, binary=True) as stream:
            figure.savefig(stream, format="png", dpi=120)
    return 0
