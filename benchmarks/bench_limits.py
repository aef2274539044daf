"""Cost of the phase check (:mod:`andoyer._limits`) beside the free flow it guards.

Side by side in one process: ``FreeMotion(moments, m, q).propagate(t)`` (set-up and evaluation,
which now include the check) and the check alone (``spin_bound`` + ``check_spin_phase``) on the
same inputs, for one state (the splitting's separatrix path, one-shot calls) and for 2·10⁵
states (ensembles). Run: ``PYTHONPATH=src python3 benchmarks/bench_limits.py``.
"""

from __future__ import annotations

import timeit

import numpy as np

from andoyer._limits import check_spin_phase, spin_bound
from andoyer.free import FreeMotion


def main() -> None:
    """Print the check's cost as a fraction of the guarded call."""
    rng = np.random.default_rng(0)
    moments = np.array([1.0, 2.0, 3.0])
    t = np.asarray(0.5)
    for n, number in ((1, 3000), (200_000, 5)):
        m = rng.normal(size=(n, 3))
        q = np.tile([0.0, 0.0, 0.0, 1.0], (n, 1))
        flow = min(timeit.repeat(lambda m=m, q=q: FreeMotion(moments, m, q).propagate(t), number=number))
        guard = lambda m=m: check_spin_phase(moments, m, t, bound=spin_bound(moments, m))  # noqa: E731
        check = min(timeit.repeat(guard, number=number))
        print(
            f"{n:>7} states: free flow {flow / number * 1e6:10.1f} us, check {check / number * 1e6:7.1f} us "
            f"({check / flow:.1%} of the call)"
        )


if __name__ == "__main__":
    main()
