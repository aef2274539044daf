"""The one Hamilton product and the one Jacobi amplitude (issue 16 item 1), beside scipy, in one run.

Side by side, in one process on one core (CPU seconds, best of ``--repeat`` interleaved runs):

* ``andoyer._quaternion.multiply`` on 10⁶ quaternion pairs; peer: scipy's
  ``Rotation.__mul__`` (composition of the same rotations, which normalises too);
* ``andoyer.special.am`` on 10⁶ arguments and parameters; peer: the amplitude of
  ``scipy.special.ellipj`` (Cephes' AGM, less accurate for large ``u`` and ``m → 1``);
* the compiled amplitude kernel (``andoyer.free.common.elliptic.am`` in a numba loop),
  ns a call, for ``|u| ≤ 2`` and ``m`` uniform in [0, 1];
* ``andoyer.free.step_scalar.free_step`` (the one-step flow that calls both compiled) on 2·10⁴
  triaxial states.

Run: ``OMP_NUM_THREADS=1 taskset -c 0 python3 benchmarks/bench_kernels.py [--repeat 7]``.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import scipy.special as sc
from scipy.spatial.transform import Rotation

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from andoyer._jit import NUMBA, jit
from andoyer._quaternion import multiply
from andoyer.free.common.elliptic import am as am_kernel
from andoyer.free.step_scalar import free_step
from andoyer.special import am


@jit
def _am_loop(u, m, mc):  # pragma: no cover - run compiled
    total = 0.0
    for i in range(u.size):
        total += am_kernel(u[i], m[i], mc[i])
    return total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    n = 1_000_000
    p, q = rng.normal(size=(n, 4)), rng.normal(size=(n, 4))
    rp, rq = Rotation.from_quat(p), Rotation.from_quat(q)
    u, mc = rng.uniform(-50, 50, n), rng.uniform(0, 1, n)
    uk, mck = rng.uniform(-2, 2, 200_000), rng.uniform(0, 1, 200_000)
    moments = np.array([1.0, 1.7, 2.3])
    qs = rng.normal(size=(20_000, 4))
    qs /= np.linalg.norm(qs, axis=1)[:, None]
    ms = rng.normal(size=(20_000, 3))
    cases = {
        "multiply 1e6 (ms)": lambda: multiply(p, q),
        "scipy Rotation * 1e6 (ms)": lambda: rp * rq,
        "special.am 1e6 (ms)": lambda: am(u, 1 - mc, mc),
        "scipy ellipj phi 1e6 (ms)": lambda: sc.ellipj(u, 1 - mc)[3],
        "am kernel compiled 2e5 (ms)": lambda: _am_loop(uk, 1 - mck, mck),
        "free_step 2e4 (ms)": lambda: free_step(moments, qs, ms, 0.1),
    }
    for f in cases.values():
        f()  # compile, warm up
    best = dict.fromkeys(cases, np.inf)
    for _ in range(args.repeat):
        for name, f in cases.items():
            t0 = time.process_time()
            f()
            best[name] = min(best[name], time.process_time() - t0)
    print(f"numba: {NUMBA}; CPU ms, best of {args.repeat}")
    for name, t in best.items():
        print(f"  {name:32s} {1e3 * t:9.2f}")
    ratio_mul = best["multiply 1e6 (ms)"] / best["scipy Rotation * 1e6 (ms)"]
    ratio_am = best["special.am 1e6 (ms)"] / best["scipy ellipj phi 1e6 (ms)"]
    print(f"  multiply / scipy composition:  {ratio_mul:.2f}")
    print(f"  am / scipy ellipj:             {ratio_am:.2f}")
    print(f"  am kernel: {1e9 * best['am kernel compiled 2e5 (ms)'] / uk.size:.0f} ns a call")


if __name__ == "__main__":
    main()
