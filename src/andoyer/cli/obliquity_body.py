"""The body of ``andoyer obliquity``: a planet by name or ``--body-file``, its default orbit, the α drift.

Kept apart from :mod:`andoyer.cli.obliquity_cmd` (which several features share) so that the
command's hunks stay an option's registration and one call.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError

#: The planets with a spin axis (Mercury is a Cassini state: andoyer cassini) and their default orbit.
DEFAULT_ORBIT = {
    "earth": "vondrak",
    "mars": "nbody",
    "venus": "secular",
    "jupiter": "secular",
    "saturn": "secular",
    "uranus": "secular",
    "neptune": "secular",
}


def add_body_arguments(parser: argparse.ArgumentParser) -> None:
    """BODY (optional with ``--body-file``), ``--body-file PATH`` and ``--drift-timescale TAU``."""
    parser.add_argument(
        "body",
        nargs="?",
        type=str.lower,
        choices=tuple(DEFAULT_ORBIT),
        metavar="BODY",
        help=", ".join(DEFAULT_ORBIT),
    )
    parser.add_argument(
        "--body-file", metavar="PATH", help="a body of your own (JSON or TOML) in place of BODY"
    )
    parser.add_argument(
        "--drift-timescale",
        type=finite_number,
        metavar="TAU",
        help="precession constant alpha(t) = alpha0 (1 + t/TAU), t and TAU in years (satellite migration)",
    )


#: Longest drift timescale taken (years): over the longest orbit (1 Gyr) it moves alpha by 1e-6.
MAX_DRIFT_TIMESCALE = 1e15


def resolve_body(args: argparse.Namespace) -> tuple[Any, str | None, str, float]:
    """``(body, planet, default orbit source, drift per year)`` of the command line.

    ``body`` is the planet's name or the checked :class:`~andoyer.catalogue.Body` of the body file;
    ``planet`` the planet whose named orbit sources apply (a body file named after a planet takes
    that planet's orbit; another needs ``--orbit PATH``).
    """
    from andoyer import catalogue

    if (args.body is None) == (args.body_file is None):
        got = "neither" if args.body is None else f"both ({args.body!r} and --body-file {args.body_file!r})"
        msg = f"expected a BODY or a --body-file PATH, got {got}"
        raise CliError(msg)
    drift = 0.0
    if args.drift_timescale is not None:
        if not 0 < abs(args.drift_timescale) <= MAX_DRIFT_TIMESCALE:
            msg = (
                f"expected 0 < |--drift-timescale TAU| <= {MAX_DRIFT_TIMESCALE:g} years "
                "(alpha = alpha0 (1 + t/TAU); a longer TAU drifts alpha by under 1e-6 over the "
                f"secular orbit's 1 Gyr), got {args.drift_timescale:g}"
            )
            raise CliError(msg)
        drift = 1.0 / args.drift_timescale
    if args.body_file is None:
        return args.body, args.body, DEFAULT_ORBIT[args.body], drift
    body = catalogue.read_body(args.body_file)
    planet = body.key if body.key in DEFAULT_ORBIT else None
    if planet is None and (args.orbit is None or args.orbit in DEFAULT_ORBIT.values()):
        msg = (
            f"expected --orbit PATH (an orbit table) for the body file's {body.name!r} (the named orbit "
            f"sources know the planets {', '.join(DEFAULT_ORBIT)}), got {args.orbit or 'none'}"
        )
        raise CliError(msg)
    return body, planet, "secular" if planet is None else DEFAULT_ORBIT[planet], drift


def resonance_fields(precession_rate: float) -> list[dict]:
    """The JSON ``resonances``: the nodal modes ``s_k`` and the distance ``ψ̇ + s_k`` (″/yr), nearest first."""
    from andoyer.planetary.spin_axis.resonances import resonance_distances

    if not math.isfinite(precession_rate):
        return []
    return resonance_distances(precession_rate)
