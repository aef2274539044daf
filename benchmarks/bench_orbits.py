"""Orbit histories: the cost of the N-body source per simulated kyr, and of evaluating each source.

* N-body: ``andoyer.planetary.orbits.nbody.make_simulation`` (the Sun and eight planets, WHFast with
  the order-17 corrector, the source's step of about 4 days), with and without REBOUNDx's
  ``gr_potential``, over ``--years`` of simulated time; the peer is REBOUND's IAS15 (adaptive,
  15th order, machine precision) on the same system over ``--peer-years``, scaled per kyr.
* Evaluation: ``normal(t)`` of each source on ``--points`` times within ±20 kyr, best of 5
  (the N-body source read from its cache).

Run: ``python3 benchmarks/bench_orbits.py [--years 2000] [--peer-years 50] [--points 100000]``.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np


def cpu(fn, repeat=1):
    best = np.inf
    for _ in range(repeat):
        start = time.process_time()
        fn()
        best = min(best, time.process_time() - start)
    return best


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--years", type=float, default=2000.0)
    parser.add_argument("--peer-years", type=float, default=50.0)
    parser.add_argument("--points", type=int, default=100000)
    args = parser.parse_args()

    from andoyer.planetary.orbits import LaplaceLagrangeOrbit, NBodyOrbit, SecularOrbit, VondrakEcliptic
    from andoyer.planetary.orbits.nbody import make_simulation

    print(f"N-body cost, CPU s per simulated kyr ({args.years:g} yr; IAS15 over {args.peer_years:g} yr)")
    rows = []
    for label, integrator, gr, years in (
        ("WHFast 4 d, GR", "whfast", True, args.years),
        ("WHFast 4 d, no GR", "whfast", False, args.years),
        ("IAS15, no GR (peer)", "ias15", False, args.peer_years),
    ):
        sim, extras = make_simulation(4.0 / 365.25, gr)
        if integrator == "ias15":
            sim.integrator = "ias15"
        seconds = cpu(lambda sim=sim, years=years: sim.integrate(years, exact_finish_time=0))
        del extras
        rows.append((label, seconds / years * 1000.0))
    peer = rows[-1][1]
    for label, per_kyr in rows:
        ratio = peer / per_kyr
        print(f"  {label:22s} {per_kyr:9.3f} s/kyr   {per_kyr * 1000:8.0f} s/Myr   peer/this {ratio:6.1f}")

    t = np.random.default_rng(1).uniform(-2e4, 2e4, args.points)
    with tempfile.TemporaryDirectory() as folder:
        os.environ["ANDOYER_CACHE_DIR"] = folder
        nbody = NBodyOrbit("earth", progress=False)
        nbody.normal([-2e4, 2e4])  # integrate once (cached), outside the clock
        secular = SecularOrbit("earth")
        secular.normal([-2e4, 2e4])  # integrate once, outside the clock
        sources = {
            "vondrak": VondrakEcliptic(),
            "laplace-lagrange": LaplaceLagrangeOrbit("earth"),
            "secular (integrated)": secular,
            "nbody (cached)": nbody,
        }
        print(f"normal(t) on {args.points} times, CPU seconds (best of 5)")
        for name, orbit in sources.items():
            seconds = cpu(lambda orbit=orbit: orbit.normal(t), repeat=5)
            print(f"  {name:16s} {seconds:8.4f} s   {args.points / seconds:10.3e} times/s")
        start = time.perf_counter()
        NBodyOrbit("earth", progress=False).normal(t)
        wall = time.perf_counter() - start
        print(f"  a fresh NBodyOrbit reading the ±20 kyr cache and evaluating: {wall:.3f} s wall")


if __name__ == "__main__":
    main()
