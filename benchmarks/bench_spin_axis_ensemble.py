"""Ensembles of spin-axis histories on one shared orbit: many members per compiled pass against one each.

Issue 25 item 4: ``--members`` (10^4) Earth spin-axis histories of ``--years`` (1 Myr) back from
J2000 on one shared orbit (Laplace–Lagrange, ``LaplaceLagrangeOrbit("earth")``), output every
1 kyr, each member with its own precession rate (45–55 ″/yr) and tidal dissipation (0–1.2),
through the public API :func:`andoyer.ensemble.run_ensemble` with
:class:`~andoyer.ensemble.spin_axis.SpinAxisPropagator`.

* andoyer, vectorised: chunks of ``--chunk`` members, each chunk one compiled pass of
  :func:`andoyer.planetary.spin_axis.stepping.rotate_stages` (the orbit's normals and
  eccentricity computed once per chunk, the members the innermost loop).
* peer, the per-history path: the same API and kernel with ``chunk=1`` (one history per pass,
  the orbit sampled again for each), on ``--peer-members`` members, scaled per member.

Both in one process with ``scheduler="synchronous"`` (one core, wall seconds, numba compiled
before the clock), best of ``--repeat``; then the vectorised run on a local Dask cluster of
``--workers`` processes (wall seconds, cluster start-up excluded: ``local_client``).
The two agree to round-off (``tests/ensemble/test_spin_axis_ensemble_vectorised.py``).

Run: ``python3 benchmarks/bench_spin_axis_ensemble.py [--members 10000] [--years 1e6]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def _run(members: int, chunk: int, times, scheduler="synchronous"):  # type: ignore[no-untyped-def]
    from andoyer.ensemble import run_ensemble
    from andoyer.ensemble.spin_axis import SpinAxisPropagator, SpinParameterSampler
    from andoyer.planetary.orbits import LaplaceLagrangeOrbit

    sampler = SpinParameterSampler("earth", precession_rate=(45.0, 55.0), tidal_dissipation=(0.0, 1.2))
    propagator = SpinAxisPropagator(LaplaceLagrangeOrbit("earth"), "earth")
    return run_ensemble(
        sampler,
        members,
        times,
        propagator=propagator,
        chunk=chunk,
        output="euler",
        scheduler=scheduler,
        progress=False,
    )


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--members", type=int, default=10_000)
    parser.add_argument("--years", type=float, default=1e6)
    parser.add_argument("--chunk", type=int, default=1000)
    parser.add_argument("--peer-members", type=int, default=100)
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args()
    times = np.linspace(-args.years, 0.0, round(args.years / 1000.0) + 1)
    _run(4, 2, times)  # compile
    many, one = [], []
    for _ in range(args.repeat):
        t = time.perf_counter()
        _run(args.members, args.chunk, times)
        many.append((time.perf_counter() - t) / args.members)
        t = time.perf_counter()
        _run(args.peer_members, 1, times)
        one.append((time.perf_counter() - t) / args.peer_members)
    print(f"{args.members} x {args.years:.3g} yr, outputs {times.size}, one core (synchronous):")
    print(
        f"  vectorised, chunk {args.chunk}: {min(many) * 1e3:.3f} ms/member -> "
        f"{min(many) * args.members:.1f} s for {args.members}"
    )
    print(
        f"  per-history (chunk 1, {args.peer_members} members): {min(one) * 1e3:.3f} ms/member -> "
        f"{min(one) * args.members:.1f} s for {args.members}"
    )
    print(f"  ratio per-history / vectorised: {min(one) / min(many):.1f}")
    if args.workers > 0:
        from andoyer.ensemble import local_client

        with local_client(args.workers) as client:
            _run(4 * args.workers, 4, times, client)  # compile in the workers
            t = time.perf_counter()
            _run(args.members, args.chunk, times, client)
            wall = time.perf_counter() - t
        print(f"  Dask, {args.workers} worker processes, chunk {args.chunk}: {wall:.1f} s wall")


if __name__ == "__main__":
    main()
