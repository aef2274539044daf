"""The charts the command line can read and write, with their column names."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from andoyer import bodies
from andoyer.body import RigidBody
from andoyer.cli.output import CliError, read_csv_columns
from andoyer.state import State
from andoyer.state.registry import Chart, charts


@dataclass(frozen=True)
class ChartColumns:
    """How one chart maps to and from the state on the command line."""

    columns: tuple[str, ...]
    angles: tuple[str, ...]
    to_state: Callable[[Sequence[np.ndarray], RigidBody | None], State]
    from_state: Callable[[State, RigidBody | None], Sequence[np.ndarray]]
    needs_body: bool = False


# The charts the command line offers, in the order of its help; their signatures come from the
# registry (andoyer.state.registry), written once in each chart's module.
CLI_CHARTS = ("state", "euler", "andoyer", "sadov", "serret")


def _columns(chart: Chart) -> ChartColumns:
    """The command line's view of a registered chart (its options left at their defaults)."""
    return ChartColumns(
        chart.columns,
        chart.angles,
        lambda v, body: chart.to_state(State, v, body),
        lambda s, body: tuple(chart.from_state(s, body)),
        needs_body=chart.needs_body,
    )


CHARTS: dict[str, ChartColumns] = {name: _columns(charts()[name]) for name in CLI_CHARTS}


def add_body_arguments(parser: argparse.ArgumentParser) -> None:
    """``--body NAME`` or ``--moments I1 I2 I3`` for the charts and models that need the inertia."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--body", choices=bodies.names(), help="a named body (andoyer bodies)")
    group.add_argument(
        "--moments", nargs=3, type=float, metavar=("I1", "I2", "I3"), help="principal moments of inertia"
    )


def body_from_args(args: argparse.Namespace) -> RigidBody:
    """The body named on the command line.

    Moments that break the triangle inequality are accepted (Euler's equations hold for any
    positive moments) with their :class:`~andoyer.body.NonPhysicalInertiaWarning`, which
    :func:`andoyer.cli.main` prints as one line on standard error.
    """
    if getattr(args, "moments", None) is not None:
        return RigidBody(*args.moments)
    if getattr(args, "body", None) is not None:
        return bodies.get(args.body)
    msg = "expected --body NAME or --moments I1 I2 I3 for this chart, got neither"
    raise CliError(msg)


def add_time_arguments(parser: argparse.ArgumentParser) -> None:
    """``--times T ...`` or ``--range START STOP COUNT`` (one of them required)."""
    when = parser.add_mutually_exclusive_group(required=True)
    when.add_argument(
        "--times", nargs="+", type=float, metavar="T", help="output times (the state's time unit)"
    )
    when.add_argument(
        "--range",
        nargs=3,
        type=float,
        metavar=("START", "STOP", "COUNT"),
        help="COUNT output times evenly from START to STOP",
    )


def times_from_args(args: argparse.Namespace) -> np.ndarray:
    """The output times of :func:`add_time_arguments`, checked finite."""
    if args.range is not None:
        start, stop, count = args.range
        if not (np.isfinite(start) and np.isfinite(stop)):
            msg = f"expected a finite START and STOP in --range, got {start!r} and {stop!r}"
            raise CliError(msg)
        if not (np.isfinite(count) and count >= 1 and count == int(count)):
            msg = f"expected a positive integer COUNT in --range, got {count!r}"
            raise CliError(msg)
        return np.linspace(start, stop, int(count))
    times = np.asarray(args.times, dtype=float)
    if not np.all(np.isfinite(times)):
        msg = f"expected finite times, got {times.tolist()!r}"
        raise CliError(msg)
    return times


def chart_columns_from_args(args: argparse.Namespace, source: ChartColumns) -> dict[str, np.ndarray]:
    """The columns of chart ``source`` given by ``--values X ...`` (one state) or ``--input CSV``."""
    if args.values is not None:
        if len(args.values) != len(source.columns):
            msg = (
                f"expected {len(source.columns)} values ({', '.join(source.columns)}), got {len(args.values)}"
            )
            raise CliError(msg)
        return {c: np.array([v]) for c, v in zip(source.columns, args.values, strict=True)}
    return read_csv_columns(args.input, source.columns)
