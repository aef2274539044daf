"""The ``andoyer`` command line.

Every sub-command answers bad arguments or bad input files with a one-line
message on standard error and exit code 2, and writes output files
atomically (a temporary file renamed into place), so an interrupted run
never leaves a half-written file.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from collections.abc import Sequence

from andoyer._limits import PhasePrecisionWarning, show_progress
from andoyer.cli import (
    bodies_cmd,
    brackets_cmd,
    convert_cmd,
    demo_cmd,
    ensemble_cmd,
    portrait_cmd,
    precession_cmd,
    propagate_cmd,
    series_cmd,
)
from andoyer.cli.output import CliError

__all__ = ["main"]


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # type: ignore[override]
        self.exit(2, f"{self.prog}: error: {message}\n")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``andoyer`` command."""
    parser = _Parser(prog="andoyer", description="Rigid-body rotation in canonical variables.")
    from andoyer import __version__

    parser.add_argument("--version", action="version", version=f"andoyer {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for module in (
        demo_cmd,
        bodies_cmd,
        convert_cmd,
        propagate_cmd,
        precession_cmd,
        ensemble_cmd,
        brackets_cmd,
        series_cmd,
        portrait_cmd,
    ):
        module.register(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status.

    Examples
    --------
    >>> main(["bodies", "--format", "csv"])  # doctest: +ELLIPSIS
    name,I1,I2,I3,alpha,beta,kappa,rotation_period_s,J0_rad,source
    earth,0.99672,0.9967222,1.0,...
    0
    """
    parser = build_parser()
    args = parser.parse_args(argv)

    def one_line(message: Warning | str, *_where: object, **_options: object) -> None:
        print(f"andoyer {args.command}: warning: {message}", file=sys.stderr)

    try:
        with warnings.catch_warnings(), show_progress():
            # a warning is one line on stderr, never a traceback (even where filters say error)
            warnings.simplefilter("default", PhasePrecisionWarning)
            warnings.showwarning = one_line
            return int(args.run(args) or 0)
    except (CliError, ValueError) as exc:
        print(f"andoyer {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
