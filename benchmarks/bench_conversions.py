"""Chart-conversion throughput on one core, beside scipy's Euler-angle conversions, in one run.

Run: ``OMP_NUM_THREADS=1 taskset -c 0 python benchmarks/bench_conversions.py`` (``--quick``
for a short run, ``--repeats N`` to change the 5 interleaved repeats).

The peer is scipy's ``Rotation.as_euler("ZXZ")`` / ``Rotation.from_euler("ZXZ", ...)`` on the
same attitudes, which does strictly less work (angles only, no momenta): a yardstick for what a
vectorised conversion of this kind costs. The ``as_*`` conversions are compared with
``as_euler``, the ``from_*`` ones with ``from_euler``. ``1`` is a single state (``State`` of
shape ``()``, a single ``Rotation``, Python floats), timed per call in microseconds; the other
rows are arrays of N states, in states per second. Every measurement is repeated, the
conversions interleaved within each repeat so that load from other processes falls on all of
them alike (a repeat of a fast call is the fastest of 10 short loops); the table gives the best
and the median over the repeats, and the ratios (ours over scipy's rate, > 1 is faster) of the
bests and of the medians.
"""

from __future__ import annotations

import argparse
import os
import time
from collections.abc import Callable

import numpy as np
from scipy.spatial.transform import Rotation

from andoyer import State

PEERS = {
    "as_andoyer": "scipy as_euler",
    "from_andoyer": "scipy from_euler",
    "as_euler": "scipy as_euler",
    "from_euler": "scipy from_euler",
}


def seconds_per_call(fn: Callable[[], object], budget: float, slices: int = 10) -> float:
    """Seconds per call: the fastest of ``slices`` loops that together fill ``budget`` (one call at least).

    Taking the fastest slice of a repeat keeps a burst of load from another process, on this
    shared machine, out of that repeat's figure.
    """
    t0 = time.perf_counter()
    fn()
    once = max(time.perf_counter() - t0, 1e-9)
    loops = max(1, int(budget / slices / once))
    best = np.inf
    for _ in range(slices if loops > 1 or once < budget / slices else 1):
        t0 = time.perf_counter()
        for _ in range(loops):
            fn()
        best = min(best, (time.perf_counter() - t0) / loops)
    return best


def cases(n: int, rng: np.random.Generator) -> dict[str, Callable[[], object]]:
    """The six conversions on ``n`` random states (``n = 1``: one state, scalar fields)."""
    if n == 1:
        rot = Rotation.random(rng=rng)
        state = State.from_attitude(rot, rng.normal(size=3))
        andoyer = [float(v) for v in state.as_andoyer()]
        euler = [float(v) for v in state.as_euler()]
        angles = np.array(euler[:3])
    else:
        rot = Rotation.random(n, rng=rng)
        state = State.from_attitude(rot, rng.normal(size=(n, 3)))
        andoyer = list(state.as_andoyer())
        euler = list(state.as_euler())
        angles = np.stack(euler[:3], -1)
    return {
        "as_andoyer": state.as_andoyer,
        "from_andoyer": lambda: State.from_andoyer(*andoyer),
        "as_euler": state.as_euler,
        "from_euler": lambda: State.from_euler(*euler),
        "scipy as_euler": lambda: rot.as_euler("ZXZ"),
        "scipy from_euler": lambda: Rotation.from_euler("ZXZ", angles),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    sizes = [1, 10_000] if args.quick else [1, 100, 10_000, 1_000_000]
    budget = 0.02 if args.quick else 0.1
    rng = np.random.default_rng(0)
    print(f"threads: OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', 'unset')}; repeats: {args.repeats}")
    for n in sizes:
        fns = cases(n, rng)
        for fn in fns.values():  # warm-up: compilation, caches
            fn()
        times: dict[str, list[float]] = {name: [] for name in fns}
        for _ in range(args.repeats):
            for name, fn in fns.items():
                times[name].append(seconds_per_call(fn, budget))
        best = {name: min(t) for name, t in times.items()}
        median = {name: float(np.median(t)) for name, t in times.items()}
        if n == 1:
            print("\nsingle state: microseconds per call (best, median); ratio = scipy time / ours")
        else:
            print(f"\nN = {n}: states per second (best, median); ratio = ours / scipy")
        for name in fns:
            if n == 1:
                cols = f"{best[name] * 1e6:>9.2f} µs  {median[name] * 1e6:>9.2f} µs"
            else:
                cols = f"{n / best[name]:>11.3e}  {n / median[name]:>11.3e}"
            peer = PEERS.get(name)
            ratio = ""
            if peer:
                ratio = (
                    f"   ratio vs {peer}: best {best[peer] / best[name]:6.2f}"
                    f"  median {median[peer] / median[name]:6.2f}"
                )
            print(f"  {name:<17}{cols}{ratio}")


if __name__ == "__main__":
    main()
