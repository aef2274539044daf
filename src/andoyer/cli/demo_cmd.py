"""``andoyer demo``: a tour of a named body's rotation state in every chart."""

from __future__ import annotations

import argparse
import sys
from typing import TextIO

import numpy as np

from andoyer import bodies
from andoyer.body import RigidBody
from andoyer.cli.chart_table import CHARTS
from andoyer.cli.output import format_rows
from andoyer.free import FreeRotation
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
        values = [float(v) for v in chart.from_state(state, body)]
        out.write(f"## {name}\n")
        out.write(format_rows(chart.columns, [values], "table"))
        out.write("\n")
    write_exact_propagation(out, body, state, entry.rotation_period)
    return 0


def write_exact_propagation(out: TextIO, body: RigidBody, state: State, rotation_period: float) -> None:
    """The closed-form torque-free motion of the demo state: period, and 100 periods later."""
    free = FreeRotation(body)
    periods = free.periods(state)
    period = float(periods.period)
    out.write("## exact torque-free propagation\n")
    out.write(f"regime: {free.regime(state)}\n")
    out.write(
        f"period of m(t) (free wobble): {period:.10g} s = {period / rotation_period:.6g} rotation periods\n"
    )
    later = free.propagate(state, 100 * period)
    drift = float(abs(later.m_body - state.m_body).max() / abs(state.m_body).max())
    energy = abs(float(later.energy(body) / state.energy(body)) - 1)
    out.write(f"after 100 periods: |m - m0|/|m0| = {drift:.2e}, relative energy change = {energy:.2e}\n")
