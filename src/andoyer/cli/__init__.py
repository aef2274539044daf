"""The ``andoyer`` command line.

Every sub-command answers bad arguments, bad input files and refusals of the
file system with a one-line message on standard error and exit code 2. Output
files are written through :func:`andoyer.cli.output.atomic_output`: a temporary
file renamed into place (so an interrupted run never leaves a half-written
file), through symbolic links, never over a directory or a device, with the
mode the umask gives; nothing the user made is ever deleted.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from typing import Any

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
from andoyer.cli.output import CliError, check_outputs

__all__ = ["main"]


# Numbers argparse must read as values, not options: -1, -.5, -1e300, -2.5E-3, -inf, -nan.
# Its own pattern (^-\d+$|^-\d*\.\d+$) misses exponents, so "--times -1e300" was an error.
_NEGATIVE_NUMBER = re.compile(r"^-(?:(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|inf|infinity|nan)$", re.IGNORECASE)


class _Parser(argparse.ArgumentParser):
    """One-line errors (exit 2), and negative numbers in every form read as values."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # No option of ours looks like a negative number, so such a token is always a value.
        self._negative_number_matcher = _NEGATIVE_NUMBER

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
    try:
        check_outputs(args)
        return int(args.run(args) or 0)
    except (CliError, ValueError) as exc:
        print(f"andoyer {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
    except OSError as exc:
        # The file system said no (a full disk, a read-only place, a vanished folder): the
        # user's to fix, so one line; any other exception is a bug and keeps its traceback.
        where = f" ({exc.filename})" if exc.filename else ""
        print(f"andoyer {args.command}: error: {exc.strerror or exc}{where}", file=sys.stderr)
        return 2
