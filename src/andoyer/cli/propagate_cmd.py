"""``andoyer propagate``: propagation of states (torque-free or under a named model), written in any chart."""

from __future__ import annotations

import argparse
import sys

import numpy as np

from andoyer._limits import check_size
from andoyer.cli.chart_table import (
    CHARTS,
    add_body_arguments,
    add_time_arguments,
    body_from_args,
    chart_columns_from_args,
    times_from_args,
)
from andoyer.cli.named_models import MODELS, add_model_arguments, model_from_args
from andoyer.cli.output import CliError, add_output_argument, atomic_output, format_rows
from andoyer.free_rotation import FreeRotation
from andoyer.integrate.propagation import propagate
from andoyer.integrate.splitting import DEFAULT_RTOL, LARGEST_RTOL, SMALLEST_RTOL

EXAMPLES = """examples:
  andoyer propagate --body eros --from andoyer --values 0.1 0.2 0.3 0.99 1.0 0.5 --times 0 10 100
  andoyer propagate --moments 1 2 3 --from state --input s.csv --range 0 100 11 --to sadov --format csv
  andoyer propagate --model heavy-top --weight 0.5 --center-of-mass 0 0 0.3 --moments 1 1 0.5 \
      --values 0.1 0.2 0.3 0.9 1.0 0.5 --range 0 10 11 --method splitting --step 0.01
  andoyer propagate --model earth-lunisolar --method secular --values 0 0 0 7.28e-5 7.29e-5 6.69e-5 \
      --range 0 3.15576e9 11 --to andoyer
Times are in the units of the angular momentum and moments (e.g. seconds for SI values); the
solar-system models (gravity-gradient-sun, earth-lunisolar, mars-solar) use seconds, and the
states are given at t = 0. --method: exact (closed-form flow, --model free only; the default
there), reference (DOP853; the default otherwise), splitting (--step, or the order and step
chosen from --rtol, default 1e-3), secular (mean states of a fast rotator: gravity-gradient
and precessing-frame models).
"""

METHODS = ("exact", "reference", "splitting", "secular")
#: Peak memory and time per output row (measured: 10⁶ rows of the Andoyer chart, 1.6 GB, 41 s).
_ROW_BYTES = 2000
_ROW_SECONDS = 4e-5


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "propagate",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_body_arguments(parser)
    add_model_arguments(parser)
    parser.add_argument("--method", choices=METHODS, help="default: exact for --model free, else reference")
    parser.add_argument("--step", type=float, metavar="H", help="splitting step (time units)")
    parser.add_argument("--order", type=int, choices=(2, 4, 6), help="splitting order (default 4)")
    parser.add_argument(
        "--rtol",
        type=float,
        metavar="R",
        help="splitting: relative error of the momentum wanted, the order and step chosen from it "
        "(instead of --step; default 1e-3; the estimate is printed on stderr)",
    )
    parser.add_argument(
        "--from",
        dest="source",
        choices=tuple(CHARTS),
        default="andoyer",
        help="chart of the input (default andoyer)",
    )
    parser.add_argument("--to", dest="target", choices=tuple(CHARTS), default=None, help="default: --from")
    given = parser.add_mutually_exclusive_group(required=True)
    given.add_argument("--values", nargs="+", type=float, metavar="X", help="one state, in column order")
    given.add_argument("--input", metavar="CSV", help="CSV file with a header naming the columns")
    add_time_arguments(parser)
    parser.add_argument("--format", choices=("table", "csv"), default="table", help="default table")
    add_output_argument(parser)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Read the states, propagate them, write one row per (state, time)."""
    named = MODELS[args.model]
    if args.body is None and args.moments is None and named.default_body is not None:
        args.body = named.default_body
    body = body_from_args(args)
    model = model_from_args(body, args)
    method = args.method or ("exact" if args.model == "free" else "reference")
    options = _method_options(args, method)
    source = CHARTS[args.source]
    target = CHARTS[args.target or args.source]
    columns = chart_columns_from_args(args, source)
    state = source.to_state([columns[c] for c in source.columns], body)
    # one row per (time, state), held as Python text until written: refuse what cannot fit,
    # before the times themselves are laid out
    count = args.range[2] if args.range is not None else len(args.times)
    rows = count * state.size if np.isfinite(count) else 0  # a bad COUNT: times_from_args says so
    check_size("an output table", steps=rows, nbytes=rows * _ROW_BYTES, step_seconds=_ROW_SECONDS)
    times = times_from_args(args)
    if method == "exact":
        out = FreeRotation(body).propagate(state.reshape(1, -1), times[:, None])
    else:
        out = propagate(model, state.reshape(1, -1), times[:, None], method=method, **options)
        if method == "splitting" and "step" not in options:
            print(f"andoyer propagate: splitting order {out.order}, step {out.step:.6g}, estimated "
                  f"relative error {out.error_estimate:.3g} (rtol {options['rtol']:.3g})", file=sys.stderr)
    if target is CHARTS["serret"]:
        # Serret's t0 is a time: referred to the rows' own times with the start (t = 0) as the
        # epoch of the period branch, so the elements stay constant down the table.
        values = [np.asarray(v, dtype=float) for v in out.as_serret(body, t=times[:, None], epoch=0.0)]
    else:
        values = [np.asarray(v, dtype=float) for v in target.from_state(out, body)]
    n_states = state.size
    rows = [
        [float(times[i]), j, *(float(v[i, j]) for v in values)]
        for i in range(len(times))
        for j in range(n_states)
    ]
    with atomic_output(args.output) as stream:
        stream.write(format_rows(("t", "state", *target.columns), rows, args.format))
    return 0


def _method_options(args: argparse.Namespace, method: str) -> dict[str, float]:
    """The integrator options given on the command line, checked against the method."""
    if method == "exact" and args.model != "free":
        msg = f"expected --method reference, splitting or secular for --model {args.model}, got exact"
        raise CliError(msg)
    if method != "splitting":
        given = [
            flag
            for flag, value in (("--step", args.step), ("--order", args.order), ("--rtol", args.rtol))
            if value is not None
        ]
        if given:
            msg = f"expected {', '.join(given)} only with --method splitting, got --method {method}"
            raise CliError(msg)
        return {}
    if args.rtol is not None or args.step is None:
        rtol = DEFAULT_RTOL if args.rtol is None else args.rtol
        if not (np.isfinite(rtol) and SMALLEST_RTOL <= rtol <= LARGEST_RTOL):
            msg = f"expected an --rtol from {SMALLEST_RTOL:g} to {LARGEST_RTOL:g}, got {args.rtol!r}"
            raise CliError(msg)
        options: dict[str, float] = {"rtol": rtol}
        if args.order is not None:
            options["order"] = args.order
        return options if args.step is None else {**options, "step": args.step}
    if not (np.isfinite(args.step) and args.step > 0):
        msg = f"expected a positive --step (or an --rtol) for --method splitting, got {args.step!r}"
        raise CliError(msg)
    return {"step": args.step, "order": args.order or 4}
