"""``andoyer demo``: a tour of a named body's rotation state in every chart."""

from __future__ import annotations

import argparse
import sys

import numpy as np

from andoyer import bodies
from andoyer.cli.chart_table import CHARTS
from andoyer.cli.output import format_rows
from andoyer.state import State

#: Illustrative inclination of the angular momentum on the reference axis (radians).
DEMO_INCLINATION = 0.4


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser("demo", help="show a named body's state in every chart")
    parser.add_argument("--body", default="earth", choices=bodies.names())
    parser.set_defaults(run=run)


def demo_state(name: str) -> State:
    """One spin per sidereal period, the momentum ``J0`` (Lara Table 1) off the figure axis."""
    entry = bodies.info(name)
    G = entry.body.C * 2 * np.pi / entry.rotation_period
    return State.from_andoyer(0.3, 1.0, 0.5, G * np.cos(entry.J0), G, G * np.cos(DEMO_INCLINATION))


def run(args: argparse.Namespace) -> int:
    """Print the tour."""
    entry = bodies.info(args.body)
    body = entry.body
    state = demo_state(args.body)
    out = sys.stdout
    out.write(f"# andoyer demo: {body.name}\n\n")
    out.write(f"{body!r}\n")
    out.write(f"source: {entry.source}\n")
    out.write(
        f"alpha = {body.alpha:.10g}, beta = {body.beta:.10g}, kappa = {body.kappa:.10g}, "
        f"symmetry = {body.symmetry.value}\n\n"
    )
    out.write(
        f"State: one spin per {entry.rotation_period:.10g} s, angular momentum {entry.J0:.3g} rad "
        f"from the figure axis, I = {DEMO_INCLINATION} rad.\n"
    )
    out.write(f"rotation mode: {body.rotation_mode(state.m_body)}\n")
    out.write(f"energy T = {float(state.energy(body)):.17g}\n")
    out.write(f"omega (body) = {state.omega(body).tolist()}\n")
    out.write(f"m (reference) = {state.m_reference.tolist()}\n\n")
    for name, chart in CHARTS.items():
        values = [float(v) for v in chart.from_state(state)]
        out.write(f"## {name}\n")
        out.write(format_rows(chart.columns, [values], "table"))
        out.write("\n")
    return 0
