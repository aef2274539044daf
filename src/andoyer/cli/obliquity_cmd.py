"""``andoyer obliquity``: the spin axis of a planet along a moving orbit (planetary.spin_axis)."""

from __future__ import annotations

import argparse

import numpy as np

from andoyer.catalogue.units import ARCSEC
from andoyer.cli import obliquity_ensemble
from andoyer.cli.numbers import finite_number, physical
from andoyer.cli.obliquity_body import add_body_arguments, migration_coupling, resolve_body, resonance_fields
from andoyer.cli.obliquity_tides import add_tides_argument, obliquity_tides
from andoyer.cli.output import CliError, add_output_argument, atomic_output

EXAMPLES = """examples:
  andoyer obliquity earth --span -200000 200000 --step 500 --format json
  andoyer obliquity earth --precession-rate 50.3848 --span -1000 1000 --step 100 --format table
  andoyer obliquity mars --orbit nbody --span -1000000 0 --step 1000 --plot mars.png
  andoyer obliquity saturn --span 0 1e8 --step 1e4 --drift-timescale 4e9 --format csv
BODY: earth, mars, venus, jupiter, saturn, uranus, neptune (default orbit: vondrak, nbody,
then secular), or --body-file PATH (a body named after a planet takes that planet's orbit; any
other needs --orbit PATH). The other planets' precession constant is their catalogued figure
with their satellites (andoyer precession BODY); --drift-timescale TAU drifts it,
alpha(t) = alpha0 (1 + t/TAU), or --migration SATELLITE moves that satellite out as
a(t) = a0 (1 + t/T0)^B (--migration-index B, default from its measured rate: Titan 11.3 cm/yr;
--migration-age T0, default the solar system's 4.5673e9 years; docs/spin-axis.md):
  andoyer obliquity saturn --migration titan --span -1e9 0 --step 1e4 --format csv
  andoyer obliquity earth --orbit secular --tides ocean --span -1e8 0 --step 1000 --format csv
T0, T1 and DT are Julian years from J2000 (negative = past); output at T0, T0+DT, ..., T1.
--precession-rate P is the rate of the luni-solar precession psi_A at J2000 in arcsec per Julian
year (default: Earth 50.38481507, IAU 2006; Mars 7.597); --dynamical-ellipticity H sets
(C - (A+B)/2)/C instead. --tidal-dissipation TD scales the modern tidal rates of the Earth-Moon
system (Zeebe & Lourens 2022; 0 = none). Ranges (andoyer.planetary.parameters): 0 < H < 1/2
(A + B >= C), P > 0 up to the rate of H = 1/2, 0 <= TD <= 1.2. DT must be below half the period
of the fastest angle printed (the precession, or the perihelion from the equinox, where e is at
least a tenth of its largest value), else the table would alias it: such a request is refused
(at once when the J2000 rates already alias it, otherwise after the run). Orbit sources: vondrak
(the Earth's ecliptic of Vondrak et al. 2011, +-200 kyr, no eccentricity), nbody (+-50 Myr),
secular (the long secular model, +-1 Gyr), laplace-lagrange (the linear theory), or a table file
PATH.
Tides: TD defaults to the present-day dissipation, 1, for the Earth (the real Earth dissipates:
over 5 Myr on the nbody orbit the obliquity is 0.21 deg from La2004 with it, 1.73 deg with 0) and
to 0 for bodies without a measured dissipation (Mars); --tidal-dissipation 0 leaves the tides out.
--tides MODEL (Earth only; ocean, the reference after Farhat et al. 2022, or constant-lag) couples
the axis to the tidal evolution of the Earth-Moon system (andoyer tides) instead; the tidal model
sets the dissipation and H, so --tidal-dissipation and --dynamical-ellipticity are refused with it.
JSON keys: t (years), obliquity (deg), precession (deg, p_A accumulated since J2000), axis (N x 3),
orbit_normal (N x 3, J2000 ecliptic frame), eccentricity and climatic_precession (e sin varpi,
varpi heliocentric from the moving equinox; null without eccentricity), precession_rate (arcsec/yr),
resonances (mode, frequency, distance = precession_rate + s_k, arcsec/yr, nearest first),
error_estimate (arcsec) and integration_step (years); with --tides also day_length (hours),
lunar_distance (km) and precession_constant (arcsec/yr) per row.
"""

DEFAULT_SPAN = (-200000.0, 0.0)
DEFAULT_STEP = 1000.0


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    from andoyer.planetary.orbits.factory import SOLUTION_FORMATS

    parser = commands.add_parser(
        "obliquity",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_body_arguments(parser)
    parser.add_argument(
        "--orbit",
        metavar="SOURCE",
        help="vondrak|nbody|secular|laplace-lagrange|PATH (default: earth vondrak, mars nbody)",
    )
    parser.add_argument(
        "--orbit-format",
        choices=SOLUTION_FORMATS,
        help="the format of an --orbit PATH (default: recognised from its name or columns; docs/orbits.md)",
    )
    parser.add_argument(
        "--span",
        nargs=2,
        type=finite_number,
        metavar=("T0", "T1"),
        default=DEFAULT_SPAN,
        help="first and last output time, Julian years from J2000, within the orbit's span "
        "(default -200000 0)",
    )
    parser.add_argument(
        "--step",
        type=finite_number,
        metavar="DT",
        help="output step, years (default 1000; with --ensemble |span|/1000); below half the period of "
        "the fastest angle printed",
    )
    strength = parser.add_mutually_exclusive_group()
    strength.add_argument(
        "--precession-rate",
        type=physical("precession_rate"),
        metavar="P",
        help="psi_A rate at J2000, arcsec/yr (default: the body's; P > 0, at most that of H = 1/2)",
    )
    strength.add_argument(
        "--dynamical-ellipticity",
        type=physical("dynamical_ellipticity"),
        metavar="H",
        help="H = (C - (A+B)/2)/C instead of a precession rate (0 < H < 1/2)",
    )
    parser.add_argument(
        "--tidal-dissipation",
        type=physical("tidal_dissipation"),
        metavar="TD",
        help="modern tidal rates times TD, Earth only (default: the present-day dissipation, 1, for the "
        "Earth; 0, none, for bodies without a measured one; 0 <= TD <= 1.2)",
    )
    parser.add_argument(
        "--tolerance",
        type=finite_number,
        metavar="ARCSEC",
        help="largest error of the axis wanted, arcsec (default 0.01; the JSON's error_estimate)",
    )
    add_tides_argument(parser)
    parser.add_argument("--format", choices=("json", "csv", "table"), default="table", help="default table")
    add_output_argument(parser)
    add_output_argument(parser, "--plot", "PNG of obliquity and climatic precession")
    obliquity_ensemble.add_arguments(parser)
    parser.epilog += obliquity_ensemble.HELP
    parser.set_defaults(run=run)


def orbit_source(name: str, body: str, orbit_format: str | None = None):
    """The orbit history named on the command line (:func:`andoyer.planetary.orbits.orbit_history`).

    Parameters
    ----------
    name : str
        ``vondrak``, ``nbody``, ``secular`` or a table path.
    body : str
    orbit_format : str, optional
        The format of a file (:data:`andoyer.planetary.orbits.SOLUTION_FORMATS`).

    Returns
    -------
    OrbitHistory

    Examples
    --------
    >>> orbit_source("vondrak", "earth").name
    'vondrak'
    """
    from andoyer.planetary.orbits import orbit_history

    return orbit_history(name, body, orbit_format)


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
        "resonances": resonance_fields(h.precession_rate),
        "error_estimate": None if h.error_estimate is None else h.error_estimate / ARCSEC,
        "integration_step": h.integration_step,
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


#: Bytes a table file of an orbit takes in memory while it is read, per byte of the file (a bound:
#: measured 24 for a 27 MB file of 250 000 rows, the CSV module's strings and lists).
TABLE_BYTES_PER_BYTE = 48
#: Bytes per point of a drawn curve (two panels; measured about 100 for PNG, SVG and PDF).
PLOT_POINT_BYTES = 200


def _costs(args: argparse.Namespace, orbit, stream_csv: bool, tides=None) -> dict:  # type: ignore[no-untyped-def]
    """What the command adds to the integration's cost (:func:`~andoyer.planetary.spin_axis.check_run`)."""
    from andoyer.cli.output import BLOCK_ROWS, FORMAT_SECONDS
    from andoyer.planetary.spin_axis.history import HISTORY_ROW_BYTES

    width = len(_header(orbit.has_eccentricity))
    passes = 2 if args.format == "table" else 1
    if stream_csv:  # a block of the history and its text
        row_bytes, fixed = 0.0, BLOCK_ROWS * (HISTORY_ROW_BYTES + 40 * width)
    else:  # the history, its columns in degrees while they are written, and a block's text
        row_bytes, fixed = HISTORY_ROW_BYTES + 16.0, BLOCK_ROWS * 40 * width
    if args.plot is not None:
        row_bytes += PLOT_POINT_BYTES
    extra_bytes, extra_seconds = (0.0, 0.0) if tides is None else (tides.row_bytes, tides.row_seconds)
    if stream_csv:  # the tidal columns of a block at a time
        fixed += BLOCK_ROWS * extra_bytes
    else:
        row_bytes += extra_bytes
    return {
        "row_bytes": row_bytes,
        "row_seconds": width * FORMAT_SECONDS * passes + extra_seconds,
        "fixed_bytes": fixed,
    }


def _check_table(source: str) -> None:
    """Refuse an orbit table file too large to read in memory (a named source passes)."""
    import os

    from andoyer._limits import check_size
    from andoyer.planetary.orbits.factory import SOURCES

    if source in SOURCES or not os.path.isfile(source):
        return
    size = os.path.getsize(source) * TABLE_BYTES_PER_BYTE
    check_size(f"an orbit table {source!r} that fits in memory", nbytes=size)


def _check_span(orbit, source: str, body: str, t0: float, t1: float) -> None:  # type: ignore[no-untyped-def]
    """Refuse a span outside the orbit's, naming the named sources that reach it."""
    from andoyer.planetary.orbits import SOURCES, source_span

    lo, hi = orbit.span
    if lo <= t0 and t1 <= hi:
        return
    others = []
    for name in SOURCES:
        try:
            a, b = source_span(name, body)
        except ValueError:  # vondrak for Mars
            continue
        if name != source and a <= t0 and t1 <= b:
            others.append(f"--orbit {name}")
    hint = f"; {' or '.join(others)} reach{'es' if len(others) == 1 else ''} it" if others else ""
    msg = (
        f"expected --span T0 T1 within the {orbit.name} orbit's span {lo:g} to {hi:g} years from J2000, "
        f"got {t0:g} {t1:g}{hint}"
    )
    raise CliError(msg)


def _check_sampling_before(orbit, body, args: argparse.Namespace, tides, drift: float) -> None:  # type: ignore[no-untyped-def]
    """Refuse before the integration an output step over which p_A turns a whole turn at its J2000 rate.

    The rate changes over a run (with the obliquity, the eccentricity, the tides), so the exact
    check (:func:`_check_sampling`, half a turn between any two outputs) needs the run; a whole
    turn at the J2000 rate is refused at once: the rate would have to halve at every output for
    the run to pass.
    """
    from andoyer.planetary.spin_axis import build_model, default_axis

    try:
        s0 = default_axis(body)
        model = build_model(
            orbit, body, s0, args.precession_rate, args.dynamical_ellipticity, tides.tidal_dissipation, drift
        )
    except ValueError:
        return  # the run refuses it in its own words
    n0 = orbit.normal(0.0)
    e0 = float(np.linalg.norm(orbit.eccentricity_vector(0.0))) if orbit.has_eccentricity else None
    rate = abs(model.precession_rate(float(np.arctan2(np.linalg.norm(np.cross(s0, n0)), s0 @ n0)), e0))
    if orbit.has_eccentricity:  # the perihelion from the equinox turns at about ψ̇ + ϖ̇
        earlier = max(orbit.span[0], -10.0)  # near J2000: an N-body orbit integrates nothing more for it
        ev = orbit.eccentricity_vector(np.array([earlier, 0.0]))
        turned = np.arctan2(np.cross(ev[0], ev[1]) @ n0, ev[0] @ ev[1])
        rate += abs(turned / ARCSEC / -earlier) if earlier < 0 else 0.0
    turn = rate * ARCSEC * args.step
    if turn >= 2 * np.pi:
        most = args.step * np.pi / turn
        msg = (
            f"expected --step DT below half the period of the fastest angle printed (the precession p_A "
            f"or the perihelion from the equinox; the table and the plot would alias it), got DT = "
            f"{args.step:g} years, over which it turns {turn / (2 * np.pi):.3g} times at its J2000 rate "
            f"({rate:.4g} arcsec/yr): take DT below {most:.4g} years"
        )
        raise CliError(msg)


def _check_sampling(h, step: float) -> None:  # type: ignore[no-untyped-def]
    """Refuse outputs that undersample the precession: an angle turns half a turn or more between two."""
    if h.largest_turn < np.pi:
        return
    turns = h.largest_turn / (2 * np.pi)
    most = step * np.pi / h.largest_turn
    msg = (
        f"expected --step DT below half the period of the fastest angle printed (the precession p_A "
        f"or the perihelion from the equinox; the table and the plot would alias it), got DT = {step:g} "
        f"years, over which it turns by up to {turns:.3g} turns: take DT below {most:.4g} years"
    )
    raise CliError(msg)


def run(args: argparse.Namespace) -> int:
    """Integrate the axis and write the table (and the plot), a block of rows at a time."""
    from andoyer.cli.output import write_json, write_rows
    from andoyer.planetary.spin_axis import SpinAxisHistory, output_times, spin_axis_blocks

    tides = obliquity_tides(args)
    if obliquity_ensemble.check(args):
        return obliquity_ensemble.run(args)
    if args.step is None:
        args.step = DEFAULT_STEP
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
    body, planet, default_source, drift = resolve_body(args)
    source = args.orbit or default_source
    _check_table(source)
    orbit = orbit_source(source, planet or "earth", args.orbit_format)
    _check_span(orbit, source, planet or "earth", t0, t1)
    times = output_times(t0, t1, args.step)
    if times.size > 1:
        _check_sampling_before(orbit, body, args, tides, drift)
    stream_csv = args.format == "csv" and args.plot is None
    blocks = spin_axis_blocks(
        orbit,
        body,
        times,
        precession_rate=args.precession_rate,
        dynamical_ellipticity=args.dynamical_ellipticity,
        tidal_dissipation=tides.tidal_dissipation,
        coupling=migration_coupling(args, body, tides.coupling),
        ellipticity_drift=drift,
        tolerance=None if args.tolerance is None else args.tolerance * ARCSEC,
        **_costs(args, orbit, stream_csv, tides),
        what=f"an obliquity run of {times.size} output times",
    )
    first = next(blocks)  # the integration, before anything is written
    _check_sampling(first, args.step)
    if stream_csv:
        # Rows are written as they are described: a refusal or an interruption during the
        # integration leaves no output.
        with atomic_output(args.output) as stream:
            header = _header(orbit.has_eccentricity) + tides.header
            write_rows(stream, header, _columns(first) + tides.columns(first.t), "csv")
            for block in blocks:
                write_rows(stream, None, _columns(block) + tides.columns(block.t), "csv")
        return 0
    h = SpinAxisHistory.concatenate([first, *blocks])
    figure = None
    if args.plot is not None:
        from andoyer.plot import obliquity_history

        figure = obliquity_history(h)
    with atomic_output(args.output) as stream:
        if args.format == "json":
            write_json(stream, _fields(h) | tides.fields(h.t))
        else:
            header = _header(orbit.has_eccentricity) + tides.header
            write_rows(stream, header, _columns(h) + tides.columns(h.t), args.format)
    if figure is not None:
        with atomic_output(args.plot, binary=True) as stream:
            figure.savefig(stream, format="png", dpi=120)
    return 0
