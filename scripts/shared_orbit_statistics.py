"""Mars' obliquity statistics with each member on its own orbit against members sharing orbits.

The same number of members, once with an orbit each and once as ``--shared`` orbits carrying
``members / shared`` spin axes each (their precession rates spread in 7.590–7.610″/yr): the
statistics over ``--span`` years back from J2000 (mean and standard deviation over the members and
the last 80 % of the span, extremes, the probability of reaching 40° and 50°, the fraction of
time above 40°, the spread after 10 and 50 Myr) and the wall-clock time of each run (Dask,
``--workers`` local processes).

Run from the repository root:
``python3 scripts/shared_orbit_statistics.py [--members 40 --shared 4 --span 1e8 --seed 1]``.
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

from andoyer.ensemble import obliquity_ensemble


def statistics(members: int, orbits: int, span: float, seed: int, workers: int) -> dict[str, float]:
    """One ensemble's statistics (degrees, probabilities) and its wall-clock seconds."""
    start = time.perf_counter()
    ds = obliquity_ensemble(
        "mars", members, -span, span / 1000, orbits=orbits, seed=seed, n_workers=workers, progress=False
    )
    wall = time.perf_counter() - start
    eps = ds.obliquity.values
    late = eps[:, ds.time.values <= -0.2 * span]
    spread = ds["std"].values
    return {
        "orbits": orbits,
        "wall_s": wall,
        "mean_late": float(np.nanmean(late)),
        "std_late": float(np.nanstd(late)),
        "min": float(np.nanmin(eps)),
        "max": float(np.nanmax(eps)),
        "reached_40": float(ds.exceedance.sel(threshold=40.0)),
        "reached_50": float(ds.exceedance.sel(threshold=50.0)),
        "time_above_40": float(ds.fraction_of_time.sel(threshold=40.0)),
        "spread_10myr": float(spread[np.argmin(np.abs(ds.time.values + 1e7))]),
        "spread_50myr": float(spread[np.argmin(np.abs(ds.time.values + 5e7))]),
    }


def main() -> None:
    """Run both ensembles and print (and write) their statistics."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--members", type=int, default=40)
    parser.add_argument("--shared", type=int, default=4, help="orbits of the shared run")
    parser.add_argument("--span", type=float, default=1e8, help="years back from J2000")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--json", help="write both runs' statistics to this file")
    args = parser.parse_args()
    runs = (args.members, args.shared)
    rows = [statistics(args.members, k, args.span, args.seed, args.workers) for k in runs]
    for row in rows:
        print(", ".join(f"{k} {v:.4g}" for k, v in row.items()))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
