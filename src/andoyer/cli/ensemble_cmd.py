"""``andoyer ensemble``: a Monte-Carlo ensemble of exact free motions on Dask, resumable."""

from __future__ import annotations

import argparse
import warnings

import numpy as np

from andoyer._limits import PhasePrecisionWarning, check_phase
from andoyer.cli.chart_table import add_body_arguments, add_time_arguments, body_from_args, times_from_args
from andoyer.cli.output import CliError, output_store, output_target

EXAMPLES = """examples:
  andoyer ensemble --body eros --samples 1000000 --range 0 1e5 10 --out eros.zarr --workers 2
  andoyer ensemble --moments 1 2 3 --samples 5000 --times 0 1 2 --out e.nc --sampler momentum
  andoyer ensemble --body earth --samples 100000000 --range 0 1e6 4 --out /shared/e.zarr \\
      --scheduler tcp://10.0.0.1:8786
Rerun the same command after an interruption: completed chunks are kept, the rest is computed.
Samples (--sampler andoyer): l, g, h uniform on [0, 2pi); G uniform in --G; L = G cos J and
H = G cos I with cos J, cos I uniform in --cos-J, --cos-I. (--sampler momentum): m_body
uniform in the box --m-low..--m-high, attitude uniform on SO(3).
"""


def register(commands: argparse._SubParsersAction) -> None:
    """Add the sub-command to the parser."""
    parser = commands.add_parser(
        "ensemble",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_body_arguments(parser)
    parser.add_argument("--samples", type=int, required=True, metavar="N", help="number of initial states")
    add_time_arguments(parser)
    parser.add_argument("--out", required=True, metavar="FILE", help="FILE.zarr or FILE.nc")
    parser.add_argument("--chunk", type=int, metavar="K", help="samples per chunk (default ~2^18 pairs)")
    parser.add_argument("--workers", type=int, default=2, metavar="W", help="local cluster workers")
    parser.add_argument("--scheduler", metavar="ADDR", help="Dask scheduler address, e.g. tcp://host:8786")
    parser.add_argument("--seed", type=int, default=0, metavar="S", help="seed of the samples (default 0)")
    parser.add_argument(
        "--output",
        choices=("state", "andoyer", "euler"),
        default="state",
        help="variables stored (default state)",
    )
    parser.add_argument(
        "--sampler",
        choices=("andoyer", "momentum"),
        default="andoyer",
        help="how states are drawn (see below)",
    )
    parser.add_argument(
        "--G", nargs=2, type=float, default=(1.0, 1.0), metavar=("LOW", "HIGH"), help="range of G (andoyer)"
    )
    parser.add_argument(
        "--cos-J",
        nargs=2,
        type=float,
        default=(-1.0, 1.0),
        metavar=("LOW", "HIGH"),
        help="range of L/G (andoyer)",
    )
    parser.add_argument(
        "--cos-I",
        nargs=2,
        type=float,
        default=(-1.0, 1.0),
        metavar=("LOW", "HIGH"),
        help="range of H/G (andoyer)",
    )
    parser.add_argument(
        "--m-low",
        nargs=3,
        type=float,
        default=(-1.0, -1.0, -1.0),
        metavar="M",
        help="box corner of m_body (momentum)",
    )
    parser.add_argument(
        "--m-high",
        nargs=3,
        type=float,
        default=(1.0, 1.0, 1.0),
        metavar="M",
        help="other corner of m_body (momentum)",
    )
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Build the sampler and run the ensemble; the store is the output (atomic and resumable)."""
    try:
        from andoyer.ensemble import AndoyerSampler, MomentumSampler, run_ensemble
    except ImportError as exc:
        msg = f"expected the ensemble extra (pip install 'andoyer[ensemble]'), got {exc}"
        raise CliError(msg) from exc
    body = body_from_args(args)
    if not str(args.out).lower().endswith((".zarr", ".nc")):
        msg = f"expected --out ending in .zarr or .nc, got {args.out!r}"
        raise CliError(msg)
    # Links followed (a linked store is resumed where it lies), never a device or a FIFO: a
    # NetCDF output is a regular file, a Zarr store a directory.
    nc = str(args.out).lower().endswith(".nc")
    out = output_target(args.out) if nc else output_store(args.out)
    if args.sampler == "andoyer":
        sampler = AndoyerSampler(G=tuple(args.G), cos_J=tuple(args.cos_J), cos_I=tuple(args.cos_I))
        largest = float(np.max(np.abs(args.G)))
    else:
        sampler = MomentumSampler(low=tuple(args.m_low), high=tuple(args.m_high))
        largest = float(np.linalg.norm(np.maximum(np.abs(args.m_low), np.abs(args.m_high))))
    times = times_from_args(args)
    # the workers' warnings never reach this terminal: check the phase of the fastest sample here
    check_phase(largest / float(np.min(body.moments)), times, "the ensemble's free motion")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PhasePrecisionWarning)  # said once above, not once per chunk
        run_ensemble(
            sampler,
            args.samples,
            times,
            body=body,
            out=out,
            chunk=args.chunk,
            seed=args.seed,
            output=args.output,
            scheduler=args.scheduler,
            n_workers=args.workers,
            progress=not args.quiet,
        )
    return 0
