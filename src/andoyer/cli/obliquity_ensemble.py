"""``andoyer obliquity BODY --ensemble N``: chaotic-obliquity statistics over perturbed secular orbits.

The options are registered on ``andoyer obliquity`` (:func:`add_arguments`) and the command hands
over to :func:`run` when ``--ensemble`` is given (:mod:`andoyer.ensemble.obliquity`).
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from andoyer.cli.numbers import finite_number
from andoyer.cli.output import CliError

HELP = """with --ensemble N (chaotic-obliquity statistics, orbit: the long secular model):
  andoyer obliquity mars --ensemble 100 --span -1e9 0 --step 1e6 --format json
  andoyer obliquity earth --no-moon --ensemble 50 --span -1e8 0 --step 1e5 --out moonless.zarr
N members, each the secular model from the J2000 state perturbed by --perturbation X (default 1e-6
in e and i; seeded by --seed) and, for Mars, a precession rate uniform in 7.590-7.610 arcsec/yr
(radio tracking; or the --precession-rate / --dynamical-ellipticity given). One end of --span must
be 0 (J2000); --step defaults to |span|/1000. JSON keys: members (N), t (years), mean, std, min,
max (deg, per time over the members), density (bins: edges in deg, pdf: per deg, normalised over
all members and times), exceedance (threshold in deg -> probability that the obliquity reached it
within the span), first_passage (threshold -> each member's first time, or null). --out F.zarr|F.nc
keeps the histories and the statistics (resumable: rerun after an interruption); --plot PNG draws
the density and a few histories. --orbits K (a divisor of N): the members share K orbits, N/K spin
axes on each differing by their precession rate (about K orbits' cost plus N axes'; a tenth each):
  andoyer obliquity mars --ensemble 1000 --orbits 100 --span -1e8 0 --step 1e5 --out mars.zarr
"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The ensemble's options of ``andoyer obliquity``."""
    group = parser.add_argument_group("chaotic-obliquity ensembles")
    group.add_argument("--ensemble", type=int, metavar="N", help="statistics over N members (see below)")
    group.add_argument(
        "--perturbation",
        type=finite_number,
        metavar="X",
        help="size of each member's perturbation of the J2000 secular state (default 1e-6)",
    )
    group.add_argument("--seed", type=int, metavar="S", help="seed of the members (default 0)")
    group.add_argument(
        "--orbits", type=int, metavar="K", help="distinct orbits, a divisor of N (default N: one per member)"
    )
    group.add_argument(
        "--thresholds",
        nargs="+",
        type=finite_number,
        metavar="DEG",
        help="obliquity thresholds of the exceedance, degrees (default 40 50 60)",
    )
    group.add_argument("--no-moon", action="store_true", help="the Earth without the Moon (with --ensemble)")
    group.add_argument("--out", metavar="FILE", help="FILE.zarr or FILE.nc: histories and statistics")
    group.add_argument("--workers", type=int, metavar="W", help="local Dask workers (default 2)")
    group.add_argument("--scheduler", metavar="ADDR", help="Dask scheduler address, e.g. tcp://host:8786")


def _refuse_without_ensemble(args: argparse.Namespace) -> None:
    given = [
        name
        for name in ("perturbation", "seed", "orbits", "thresholds", "out", "workers", "scheduler")
        if getattr(args, name) is not None
    ]
    if args.no_moon:
        given.append("no_moon")
    if given:
        flags = ", ".join("--" + name.replace("_", "-") for name in given)
        msg = f"expected {flags} only with --ensemble N, got no --ensemble"
        raise CliError(msg)


#: The bodies whose members the ensemble integrates (andoyer.planetary.spin_axis.members).
ENSEMBLE_BODIES = ("mars", "earth")


def _refuse_body(args: argparse.Namespace) -> None:
    """One line for what the members cannot take: a body file, another planet, the alpha drift."""
    if args.body_file is not None:
        msg = (
            f"expected a BODY in {', '.join(ENSEMBLE_BODIES)} with --ensemble (its members are those "
            f"bodies' spin axes), got --body-file {args.body_file!r}"
        )
        raise CliError(msg)
    if args.body not in ENSEMBLE_BODIES:
        got = "none" if args.body is None else repr(args.body)
        msg = f"expected a BODY in {', '.join(ENSEMBLE_BODIES)} with --ensemble, got {got}"
        raise CliError(msg)
    if getattr(args, "drift_timescale", None) is not None or getattr(args, "migration", None) is not None:
        flag = "--drift-timescale" if args.drift_timescale is not None else "--migration"
        msg = f"expected no precession-constant drift with --ensemble (members keep theirs), got {flag}"
        raise CliError(msg)


def check(args: argparse.Namespace) -> bool:
    """Whether the command is an ensemble; refuses the ensemble's options without ``--ensemble``."""
    if args.ensemble is None:
        _refuse_without_ensemble(args)
        return False
    return True


def _plain(values: np.ndarray) -> list:
    """A list of floats, NaN as ``None`` (JSON null), for the nested objects."""
    return [None if not np.isfinite(v) else float(v) for v in np.asarray(values, dtype=float)]


def _fields(ds, members: int) -> dict:
    """The JSON object (numbers as numpy arrays; NaN written as null)."""
    thresholds = [f"{v:g}" for v in ds.threshold.values]
    return {
        "members": members,
        "t": ds.time.values,
        "mean": ds["mean"].values,
        "std": ds["std"].values,
        "min": ds["min"].values,
        "max": ds["max"].values,
        "density": {"bins": _plain(ds.bin_edges.values), "pdf": _plain(ds.pdf.values)},
        "exceedance": {k: float(v) for k, v in zip(thresholds, ds.exceedance.values, strict=True)},
        "first_passage": {k: _plain(ds.first_passage.values[i]) for i, k in enumerate(thresholds)},
    }


def run(args: argparse.Namespace) -> int:
    """Run the ensemble and write its statistics (JSON, CSV or a table; the dataset; a picture)."""
    from andoyer.cli.output import atomic_output, output_store, output_target, write_json, write_rows

    try:
        from andoyer.ensemble import obliquity_ensemble
    except ImportError as exc:
        msg = f"expected the ensemble extra (pip install 'andoyer[ensemble]'), got {exc}"
        raise CliError(msg) from exc
    members = args.ensemble
    if members < 1:
        msg = f"expected --ensemble N with N >= 1 members, got {members}"
        raise CliError(msg)
    _refuse_body(args)
    if args.orbit is not None and args.orbit != "secular":
        msg = f"expected --orbit secular (or none) with --ensemble (secular members), got {args.orbit!r}"
        raise CliError(msg)
    if args.tidal_dissipation:
        msg = f"expected --tidal-dissipation 0 with --ensemble (no tides), got {args.tidal_dissipation}"
        raise CliError(msg)
    if args.no_moon and args.body != "earth":
        msg = f"expected --no-moon with the Earth, got {args.body}"
        raise CliError(msg)
    t0, t1 = args.span
    if (t0 != 0.0) == (t1 != 0.0):
        msg = f"expected --span T0 T1 with one end at J2000 (0) and the other not, got {t0:g} {t1:g}"
        raise CliError(msg)
    if t1 < t0:
        msg = f"expected --span T0 T1 with T1 >= T0, got {t0!r} {t1!r}"
        raise CliError(msg)
    end = t0 if t1 == 0.0 else t1
    step = abs(end) / 1000.0 if args.step is None else args.step
    if not step > 0:
        msg = f"expected --step DT > 0 years, got {step!r}"
        raise CliError(msg)
    if args.plot is not None and not args.plot.lower().endswith(".png"):
        msg = f"expected --plot PATH ending in .png, got {args.plot!r}"
        raise CliError(msg)
    out = None
    if args.out is not None:
        if not str(args.out).lower().endswith((".zarr", ".nc")):
            msg = f"expected --out ending in .zarr or .nc, got {args.out!r}"
            raise CliError(msg)
        out = output_target(args.out) if str(args.out).lower().endswith(".nc") else output_store(args.out)
    workers = 2 if args.workers is None else args.workers
    if workers < 1:
        msg = f"expected --workers W >= 1, got {workers}"
        raise CliError(msg)
    seed = 0 if args.seed is None else args.seed
    if seed < 0:
        msg = f"expected --seed S >= 0, got {seed}"
        raise CliError(msg)
    thresholds = [40.0, 50.0, 60.0] if args.thresholds is None else args.thresholds
    if not all(0.0 <= v <= 180.0 for v in thresholds):
        msg = f"expected --thresholds between 0 and 180 degrees, got {thresholds}"
        raise CliError(msg)
    body = "moonless-earth" if args.no_moon else args.body
    kwargs = {}
    if args.perturbation is not None:
        kwargs["perturbation"] = args.perturbation
    if args.orbits is not None:
        kwargs["orbits"] = args.orbits
    try:
        ds = obliquity_ensemble(
            body, members, end, step, precession_rate=args.precession_rate,
            dynamical_ellipticity=args.dynamical_ellipticity, thresholds=np.radians(thresholds), seed=seed,
            out=out, scheduler=args.scheduler, n_workers=workers, progress=sys.stderr.isatty(), **kwargs,
        )  # fmt: skip
    except ValueError as exc:
        raise CliError(str(exc)) from exc
    figure = None
    if args.plot is not None:
        from andoyer.plot import obliquity_ensemble_figure

        figure = obliquity_ensemble_figure(ds)
    with atomic_output(args.output) as stream:
        if args.format == "json":
            write_json(stream, _fields(ds, members))
        else:
            header = ["t_yr", "members", "mean_deg", "std_deg", "min_deg", "max_deg"]
            columns = [
                ds.time.values,
                ds["members"].values,
                *(ds[k].values for k in ("mean", "std", "min", "max")),
            ]
            write_rows(stream, header, columns, args.format)
    if figure is not None:
        with atomic_output(args.plot, binary=True) as stream:
            figure.savefig(stream, format="png", dpi=120)
    return 0
