"""Chart-conversion throughput: states per second on one core, beside scipy's Euler-angle conversions.

Run: ``python benchmarks/bench_conversions.py`` (add ``--quick`` for a short run).
The peer is scipy's ``Rotation.from_euler("ZXZ", ...)`` / ``as_euler("ZXZ")``,
which does strictly less work (angles only, no momenta): it is a yardstick for
what a vectorised conversion of this kind costs, not a competitor.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from scipy.spatial.transform import Rotation

from andoyer import State


def best_rate(fn, n, budget=0.5, repeats=7):
    """Best-of-``repeats`` throughput in items per second, looping small sizes to fill ``budget``."""
    fn()
    t0 = time.perf_counter()
    fn()
    once = max(time.perf_counter() - t0, 1e-9)
    loops = max(1, int(budget / repeats / once))
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(loops):
            fn()
        best = min(best, (time.perf_counter() - t0) / loops)
    return n / best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    sizes = [1, 100, 10_000, 1_000_000] if not args.quick else [1, 10_000]
    rng = np.random.default_rng(0)
    print(f"threads: OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', 'unset')}")
    header = (
        f"{'N':>9}  {'state->andoyer':>15}  {'andoyer->state':>15}  {'state->euler':>13}  "
        f"{'euler->state':>13}  {'scipy as_euler':>15}  {'scipy from_euler':>16}  {'ratio s->a / scipy':>18}"
    )
    print("states per second (best of 7, one process, one thread)")
    print(header)
    for n in sizes:
        rot = Rotation.random(n, rng=rng)
        m = rng.normal(size=(n, 3))
        state = State.from_attitude(rot, m)
        andoyer = state.as_andoyer()
        euler = state.as_euler()
        angles = np.stack([euler.phi, euler.theta, euler.psi], -1)
        rates = [
            best_rate(state.as_andoyer, n),
            best_rate(lambda a=andoyer: State.from_andoyer(*a), n),
            best_rate(state.as_euler, n),
            best_rate(lambda e=euler: State.from_euler(*e), n),
            best_rate(lambda r=rot: r.as_euler("ZXZ"), n),
            best_rate(lambda a=angles: Rotation.from_euler("ZXZ", a), n),
        ]
        print(
            f"{n:>9}  {rates[0]:>15.3e}  {rates[1]:>15.3e}  {rates[2]:>13.3e}  {rates[3]:>13.3e}  "
            f"{rates[4]:>15.3e}  {rates[5]:>16.3e}  {rates[0] / rates[4]:>18.2f}"
        )


if __name__ == "__main__":
    main()
