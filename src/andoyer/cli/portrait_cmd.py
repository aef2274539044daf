"""``andoyer portrait``: the pictures of :mod:`andoyer.plot` written as PNG or SVG files."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from andoyer import plot
from andoyer.body import RigidBody
from andoyer.cli.cassini_cmd import add_cassini_arguments, cassini_body_from_args
from andoyer.cli.chart_table import add_body_arguments, body_from_args
from andoyer.cli.output import CliError, add_output_argument, atomic_output
from andoyer.free_rotation import FreeRotation
from andoyer.state import State

EXAMPLES = """examples:
  andoyer portrait phase --body eros --out phase.svg
  andoyer portrait sphere --moments 1 2 3 --levels 4 --elev-deg 30 --out sphere.png
  andoyer portrait lara --out lara-fig1.png                    (Lara 2013 Fig. 1, beta = 0.8)
  andoyer portrait polhode --moments 1 2 3 --values 0.5 0 0 0.9 1 0.9 --out poinsot.png
  andoyer portrait precession --moments 1 1 1.5 --values 0 0 0 0.9 2 2 --duration 10
  andoyer portrait cassini --body moon --out cassini.png        (Colombo's top, Cassini states)
The state (--values) is in Andoyer variables l g h L G H; angles in radians.
"""
FORMATS = ("png", "svg")
DEFAULT_STATE = (0.5, 0.0, 0.0, 0.9, 1.0, 0.9)
#: Largest side of a PNG in pixels (matplotlib's Agg renderer refuses 2^16 and more).
MAX_PIXELS = 2**16
#: What is drawn is bounded (issue 26: ``--levels 100000000`` ran without end): energy contours
#: of Colombo's top (1000 take 30 s), energy levels on each side of the separatrix of the free
#: body (500 take a minute and 400 MB), and the points of a precession curve (a million take
#: 600 MB; no figure shows more).
MAX_CASSINI_LEVELS = 1000
MAX_LEVELS_PER_SIDE = 500
MAX_CURVE_POINTS = 1_000_000
#: Bytes per point of a precession curve: the states, the angles and matplotlib's paths
#: (measured 430 at a million points).
CURVE_POINT_BYTES = 1024
#: Smallest side of a PNG in pixels: Agg writes no image below 1.5 (rounded to one), 2 keeps clear.
MIN_PIXELS = 2


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command and its six pictures to the parser."""
    parser = commands.add_parser(
        "portrait",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    kinds = parser.add_subparsers(dest="kind", required=True)
    helps = {
        "phase": "(l, L) phase portrait of the free body with its separatrix (Gurfil Fig. 4)",
        "sphere": "angular-momentum sphere with the energy contours (Gurfil Fig. 1)",
        "lara": "free body vs. main problem of SAM rotation (Lara Fig. 1)",
        "polhode": "polhode and herpolhode of a state (exact free motion)",
        "precession": "precession, obliquity and nutation of a freely rotating state",
    }
    for kind, text in helps.items():
        sub = kinds.add_parser(kind, help=text, description=text)
        add_body_arguments(sub)
        add_output_argument(sub, "--out", f"PNG or SVG file, or - for stdout (default portrait-{kind}.png)")
        sub.add_argument("--format", choices=FORMATS, help="default: from the file suffix")
        sub.add_argument("--dpi", type=float, default=150.0, help="resolution of PNG output (default 150)")
        if kind in ("phase", "sphere"):
            sub.add_argument("--G", type=float, default=1.0, help="angular-momentum magnitude (default 1)")
            sub.add_argument(
                "--levels", type=int, default=5, help="energy levels on each side of the separatrix"
            )
        if kind in ("sphere", "polhode"):
            sub.add_argument("--elev-deg", type=float, default=25.0, help="viewing elevation, degrees")
            sub.add_argument("--azim-deg", type=float, default=35.0, help="viewing azimuth, degrees")
        if kind == "lara":
            sub.add_argument(
                "--beta", type=float, help="triaxiality (default: the body's, else 0.8 as in Lara)"
            )
            sub.add_argument("--ratio-min", type=float, default=0.88, help="lower edge in N/M (default 0.88)")
        if kind in ("polhode", "precession"):
            sub.add_argument(
                "--values",
                nargs=6,
                type=float,
                metavar=("l", "g", "h", "L", "G", "H"),
                default=DEFAULT_STATE,
                help="the state in Andoyer variables (default 0.5 0 0 0.9 1 0.9)",
            )
            sub.add_argument(
                "--duration", type=float, help="time span (default: one period of m, five for precession)"
            )
        if kind == "precession":
            sub.add_argument("--steps", type=int, default=2001, help="number of output times (default 2001)")
            sub.add_argument(
                "--axis",
                choices=("figure", "momentum"),
                default="figure",
                help="the axis drawn (default figure)",
            )
            sub.add_argument("--degrees", action="store_true", help="angles in degrees")
        sub.set_defaults(run=run)
    _register_cassini(kinds)


def _register_cassini(kinds: argparse._SubParsersAction) -> None:
    from andoyer.planetary.cassini import BODIES

    text = "phase portrait of Colombo's top with the Cassini states and the separatrix"
    sub = kinds.add_parser("cassini", help=text, description=text)
    sub.add_argument("--body", type=str.lower, choices=sorted(BODIES), help="default moon")
    add_cassini_arguments(sub)
    sub.add_argument(
        "--out", metavar="FILE", help="PNG or SVG file, or - for stdout (default portrait-cassini.png)"
    )
    sub.add_argument("--format", choices=FORMATS, help="default: from the file suffix")
    sub.add_argument("--dpi", type=float, default=150.0, help="resolution of PNG output (default 150)")
    sub.add_argument("--levels", type=int, default=24, help="number of energy contours (default 24)")
    sub.set_defaults(run=run)


def _format(args: argparse.Namespace, path: str) -> str:
    suffix = Path(path).suffix.lower().lstrip(".") if path != "-" else ""
    if args.format is not None:
        if suffix and suffix != args.format:
            msg = f"expected a .{args.format} file for --format {args.format}, got {path!r}"
            raise CliError(msg)
        return args.format
    if suffix not in FORMATS:
        msg = f"expected --out ending in .png or .svg (or --format), got {path!r}"
        raise CliError(msg)
    return suffix


def _state(args: argparse.Namespace) -> State:
    return State.from_andoyer(*args.values)


def _figure(args: argparse.Namespace) -> Figure:
    kind = args.kind
    if kind == "lara":
        if args.beta is not None:
            beta = args.beta
        elif args.body is not None or args.moments is not None:
            beta = body_from_args(args).beta
        else:
            beta = 0.8
        return plot.lara_portrait(beta, ratio_min=args.ratio_min)
    if kind == "cassini":
        if not 1 <= args.levels <= MAX_CASSINI_LEVELS:
            msg = f"expected 1 <= --levels <= {MAX_CASSINI_LEVELS} (contours drawn), got {args.levels}"
            raise CliError(msg)
        return plot.cassini_portrait(cassini_body_from_args(args.body, args), levels=args.levels)
    body = body_from_args(args)
    if kind == "phase":
        return plot.phase_portrait(body, args.G, _levels(body, args))
    if kind == "sphere":
        return plot.momentum_sphere(body, args.G, _levels(body, args), **_view(args))
    state = _state(args)
    if args.duration is not None and not (np.isfinite(args.duration) and args.duration > 0):
        msg = f"expected a finite --duration > 0, got {args.duration!r}"
        raise CliError(msg)
    if kind == "polhode":
        _view(args)  # checked, although plot.poinsot does not take a view yet
        return plot.poinsot(body, state, args.duration)
    if not 2 <= args.steps <= MAX_CURVE_POINTS:
        msg = f"expected 2 <= --steps <= {MAX_CURVE_POINTS} (points drawn), got {args.steps}"
        raise CliError(msg)
    from andoyer._limits import check_size

    check_size(f"a precession picture of {args.steps} points", nbytes=args.steps * CURVE_POINT_BYTES)
    duration = args.duration
    if duration is None:
        period = float(FreeRotation(body).periods(state).period)
        duration = 5 * period if np.isfinite(period) else 100.0
    t = np.linspace(0.0, duration, args.steps)
    return plot.precession(t, FreeRotation(body).propagate(state, t), args.axis, degrees=args.degrees)


def _view(args: argparse.Namespace) -> dict[str, float]:
    """The viewing angles in radians, checked: elevation within ±90°, azimuth within ±360°."""
    if not abs(args.elev_deg) <= 90:  # NaN fails too
        msg = f"expected --elev-deg within [-90, 90], got {args.elev_deg!r}"
        raise CliError(msg)
    if not abs(args.azim_deg) <= 360:
        msg = f"expected --azim-deg within [-360, 360], got {args.azim_deg!r}"
        raise CliError(msg)
    return {"elev": np.radians(args.elev_deg), "azim": np.radians(args.azim_deg)}


def _levels(body: RigidBody, args: argparse.Namespace) -> np.ndarray:
    if not 0 <= args.levels <= MAX_LEVELS_PER_SIDE:
        msg = f"expected 0 <= --levels <= {MAX_LEVELS_PER_SIDE} (levels on each side), got {args.levels}"
        raise CliError(msg)
    return plot.default_energies(body, args.G, args.levels)


def run(args: argparse.Namespace) -> int:
    """Draw the picture and write it atomically."""
    path = args.out if args.out is not None else f"portrait-{args.kind}.png"
    fmt = _format(args, path)
    if not (np.isfinite(args.dpi) and args.dpi > 0):
        msg = f"expected a finite --dpi > 0, got {args.dpi!r}"
        raise CliError(msg)
    figure = _figure(args)
    sides = figure.get_size_inches()
    if fmt == "png" and max(sides) * args.dpi >= MAX_PIXELS:
        limit = MAX_PIXELS / max(sides)
        msg = f"expected --dpi below {limit:.0f} for this picture, got {args.dpi!r}"
        raise CliError(msg)
    if fmt == "png" and min(sides) * args.dpi < MIN_PIXELS:
        limit = MIN_PIXELS / min(sides)
        msg = f"expected --dpi of at least {limit:.3g} (sides of {MIN_PIXELS} px), got {args.dpi!r}"
        raise CliError(msg)
    with atomic_output(path, binary=True) as stream:
        figure.savefig(stream, format=fmt, dpi=args.dpi)
    return 0
