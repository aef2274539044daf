"""The uniform motions (regular precession, spheres, steady spins, rest) on both paths, and one body.

The kernels of :mod:`andoyer.free.uniform` run per state compiled (``setup_compiled``,
``evaluate_compiled``: ``FreeMotion`` with the compiled backend) and on whole arrays
(``setup_numpy``, ``evaluate_numpy``: the numpy backend). CPU-independent wall times, best of
``--repeat``:

* ``FreeMotion`` of one Earth-like axisymmetric body (set-up and periods, with an attitude;
  without), and ``setup_compiled.uniform_table`` alone for that body (µs);
* 10⁵ axisymmetric bodies: ``FreeMotion`` set-up on each backend, ``uniform_axes`` plus
  ``uniform`` (the numpy set-up alone) and ``propagate`` at 8 epochs (ms); the peer of the
  numpy path is the compiled one, run side by side;
* ``step_scalar.free_step`` on 10⁴ axisymmetric states (ns a state).

Run: ``OMP_NUM_THREADS=1 python3 benchmarks/bench_uniform.py [--repeat 7]``.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from andoyer.free.motion import FreeMotion
from andoyer.free.step_scalar import free_step
from andoyer.free.uniform import setup_compiled, setup_numpy
from andoyer.regime import Regime


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=7)
    r = parser.parse_args().repeat
    # Earth-like: (C − A)/C ≈ 0.00328 (the dynamical ellipticity H = 0.0032738, Williams 1994),
    # one turn per sidereal day (Ω = 7.292115e-5 rad/s)
    mom = np.array([0.99672, 0.99672, 1.0])
    m = np.array([1e-6, 2e-6, 7.292115e-5])
    q = np.array([0.1, 0.2, 0.3, 0.9])
    FreeMotion(mom, m, q).propagate(np.array([1.0]))
    with_q = best(lambda: FreeMotion(mom, m, q).periods, 200 * r)
    print(f"FreeMotion, one body, set-up + periods  {1e6 * with_q:8.1f} µs")
    no_q = best(lambda: FreeMotion(mom, m), 200 * r)
    print(f"FreeMotion, one body, no attitude       {1e6 * no_q:8.1f} µs")
    one = (mom[None], m[None], np.array([Regime.AXISYMMETRIC]), q[None] / np.linalg.norm(q))
    setup_compiled.uniform_table(*one)
    table = best(lambda: setup_compiled.uniform_table(*one), 700 * r)
    print(f"uniform_table, one body                 {1e6 * table:8.2f} µs")
    rng = np.random.default_rng(0)
    n = 10**5
    M = np.repeat(rng.uniform(0.5, 1, (n, 1)), 3, 1)
    M[:, 2] = rng.uniform(0.5, 1, n)
    m0 = rng.normal(size=(n, 3))
    q0 = rng.normal(size=(n, 4))
    t = np.linspace(0, 100, 8)[:, None]
    for backend in ("numpy", "compiled"):
        fm = FreeMotion(M, m0, q0, backend=backend)
        fm.propagate(t)
        setup = best(lambda b=backend: FreeMotion(M, m0, q0, backend=b).periods, r)
        prop = best(lambda f=fm: f.propagate(t), r)
        print(f"10^5 bodies, {backend:8s}: set-up {1e3 * setup:7.1f} ms, 8 epochs {1e3 * prop:7.1f} ms")
    regime = np.full(n, Regime.AXISYMMETRIC)
    qn = q0 / np.linalg.norm(q0, axis=1)[:, None]
    alone = best(lambda: setup_numpy.uniform(m0, *setup_numpy.uniform_axes(M, m0, regime), qn), r)
    print(f"10^5 bodies, uniform_axes + uniform     {1e3 * alone:8.1f} ms")
    k = 10**4
    free_step(M[:k], qn[:k], m0[:k], 0.1)
    step = best(lambda: free_step(M[:k], qn[:k], m0[:k], 0.1), 3 * r)
    print(f"free_step, 10^4 axisymmetric states     {1e9 * step / k:8.0f} ns a state")


if __name__ == "__main__":
    main()
