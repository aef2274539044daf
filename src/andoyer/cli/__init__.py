"""The ``andoyer`` command line.

Every sub-command answers bad arguments, bad input files and refusals of the
file system with a one-line message on standard error and exit code 2. Output
files are written through :func:`andoyer.cli.output.atomic_output`: a temporary
file renamed into place (so an interrupted run never leaves a half-written
file), through symbolic links, never over a directory or a device, with the
mode the umask gives; nothing the user made is ever deleted.

Ctrl-C (SIGINT) ends a command with one line on stderr, ``interrupted`` and what was kept
(the N-body orbit integrated so far stays in its cache), and exit code 130 (128 + SIGINT,
the shell's convention); the output file is left as it was.
"""

from __future__ import annotations

import argparse
import importlib
import re
import sys
import warnings
from collections.abc import Sequence
from typing import Any

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


#: Every sub-command: its module (with ``register(commands)`` and ``run(args)``) and the one-line
#: help of ``andoyer --help``. A module is imported only when its command runs, so that
#: ``andoyer --help`` and each command pay only for what they use.
COMMANDS: dict[str, tuple[str, str]] = {
    "demo": (
        "andoyer.cli.demo_cmd",
        "tour a named body: every chart, exact and series propagation, precession, pictures",
    ),
    "bodies": (
        "andoyer.cli.bodies_cmd",
        "the catalogue of bodies with their sources, one body, or a body file checked",
    ),
    "convert": ("andoyer.cli.convert_cmd", "convert states between charts"),
    "propagate": (
        "andoyer.cli.propagate_cmd",
        "propagate states (torque-free or under a model) and write any chart at the requested times",
    ),
    "precession": (
        "andoyer.cli.precession_cmd",
        "precession rate of the spin axis of the Earth (Sun + Moon) or Mars (Sun), arcsec/yr",
    ),
    "cassini": (
        "andoyer.cli.cassini_cmd",
        "Cassini states (equilibria of Colombo's top) of the Moon or Mercury, moments and orbit changeable",
    ),
    "nutation": (
        "andoyer.cli.nutation_cmd",
        "rigid-Earth luni-solar nutation (dpsi, deps) of the figure, momentum or rotation axis",
    ),
    "obliquity": (
        "andoyer.cli.obliquity_cmd",
        "obliquity, general and climatic precession of the Earth or Mars over 10^3-10^7 years",
    ),
    "orbit": (
        "andoyer.cli.orbit_cmd",
        "the planets' elements from an orbit source (N-body, secular, ...) or a published solution file",
    ),
    "tides": (
        "andoyer.cli.tides_cmd",
        "the Earth-Moon tidal history: lunar distance, day length, precession constant, obliquity (Gyr)",
    ),
    "ensemble": (
        "andoyer.cli.ensemble_cmd",
        "propagate a seeded Monte-Carlo ensemble of states on Dask (Zarr or NetCDF, resumable)",
    ),
    "brackets": (
        "andoyer.cli.brackets_cmd",
        "verify the brackets of the Andoyer-Deprit coordinates of so(3), e(3) or l(7)",
    ),
    "series": ("andoyer.cli.series_cmd", "exact perturbation series (Lara's SAM theory)"),
    "portrait": (
        "andoyer.cli.portrait_cmd",
        "draw a phase portrait, the momentum sphere, Lara's Fig. 1, a polhode, precession or Colombo's top",
    ),
}

#: ``build_parser(ALL)`` builds every command's full parser (for tests that walk them all).
ALL = "*"


def build_parser(command: str | None = ALL) -> argparse.ArgumentParser:
    """The argument parser of the ``andoyer`` command.

    Parameters
    ----------
    command : str or None
        The sub-command whose full parser is built (its module imported); the others get a
        stub with their help line, which is what ``andoyer --help`` lists (``None``: stubs
        only). ``ALL`` (the default) builds every one.

    Examples
    --------
    >>> sorted(build_parser(None)._subparsers._group_actions[0].choices) == sorted(COMMANDS)
    True
    """
    parser = _Parser(prog="andoyer", description="Rigid-body rotation in canonical variables.")
    from andoyer import __version__

    parser.add_argument("--version", action="version", version=f"andoyer {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for name, (module, help_line) in COMMANDS.items():
        if command in (name, ALL):
            importlib.import_module(module).register(commands)
        else:
            commands.add_parser(name, help=help_line, add_help=False)
    return parser


def _command_in(argv: Sequence[str]) -> str | None:
    """The sub-command named in ``argv``: its first word that is not an option."""
    return next((word for word in argv if not word.startswith("-")), None)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status.

    Examples
    --------
    >>> main(["bodies", "--moments", "lara2013", "--format", "csv"])  # doctest: +ELLIPSIS
    name,I1,I2,I3,alpha,beta,kappa,rotation_period_s,J0_rad,source,...
    earth,0.99672,0.9967222,1.0,...
    0
    """
    words = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(_command_in(words))
    args = parser.parse_args(words)
    # After parsing: --help and usage errors end above without loading numpy (cli.output needs it).
    from andoyer._limits import show_progress
    from andoyer.cli.output import CliError, check_outputs

    name = f"andoyer {args.command}"

    # The library's warnings (a lost phase digit, moments no body has, a singular chart, a
    # repaired store) are kept until the command has run: each is then one line on stderr, and a
    # command that fails prints only its error, so every failure is one line.
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            check_outputs(args)
            with show_progress(prefix=name):
                code = int(args.run(args) or 0)
        except KeyboardInterrupt as exc:
            # What was kept (an N-body cache) is the exception's message, if any; the output
            # files are written only once complete, so nothing half-written is left.
            kept = " ".join(str(exc).split())
            print(f"{name}: interrupted{'; ' + kept if kept else ''}", file=sys.stderr)
            return 130
        except (CliError, ValueError) as exc:
            print(f"{name}: error: {exc}", file=sys.stderr)
            return 2
        except MemoryError as exc:
            # Every command estimates its memory before the work and refuses what cannot fit
            # (andoyer._limits.check_size); this is the net under those estimates.
            print(f"{name}: error: expected a request that fits in memory, got one that ran out ({exc})",
                  file=sys.stderr)
            return 2
        except BrokenPipeError:
            return 0
        except OSError as exc:
            # The file system said no (a full disk, a read-only place, a vanished folder): the
            # user's to fix, so one line; any other exception is a bug and keeps its traceback.
            where = f" ({exc.filename})" if exc.filename else ""
            print(f"{name}: error: {exc.strerror or exc}{where}", file=sys.stderr)
            return 2
    shown = set()
    for warning in caught:
        # Only the library's own kind of warning (UserWarning and its subclasses, RuntimeWarning)
        # is the user's business; the dependencies' deprecation notes are not.
        text = " ".join(str(warning.message).split())
        if issubclass(warning.category, UserWarning | RuntimeWarning) and text not in shown:
            shown.add(text)
            print(f"{name}: warning: {text}", file=sys.stderr)
    return code
