"""The Earth–Moon tidal history: andoyer's compiled Dormand–Prince 5(4) against scipy's DOP853.

Equations (both sides): :func:`andoyer.planetary.tides.equations.rates`, the secular tidal
equations of ``(a/a₀, ω/ω₀, ε)`` with the Sun's tide, compiled by numba (scipy calls the same
compiled kernel through a Python right-hand side).

* andoyer: :func:`andoyer.planetary.tides.tidal_history` (the compiled loop, steps ending on the
  output times; default ``rtol`` 1e-11), *after a warm-up call*, including the outputs' description;
* peer: scipy ``solve_ivp`` DOP853 with ``rtol = atol`` and ``t_eval``, on a ladder of tolerances;
  its time is that of the cheapest tolerance at least as accurate as andoyer.

Cases: the reference ocean model from J2000 back 4.3 Gyr, output every 10 Myr; the constant time
lag back 1.1 Gyr, output every 10 Myr. Accuracy: the largest difference in ``(a/a₀, ω/ω₀, ε)``
against DOP853 at rtol 1e-13.

Run: ``python3 benchmarks/bench_tides.py [--repeats 5]`` (numpy pinned to one thread).
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer._jit import NUMBA  # noqa: E402
from andoyer.planetary.tides import EarthMoonSystem, tidal_history, tidal_model  # noqa: E402
from andoyer.planetary.tides import equations as eq  # noqa: E402
from andoyer.planetary.tides.evolution import kernel_constants  # noqa: E402

SYSTEM = EarthMoonSystem()


def _states(h):
    x = h.lunar_distance * 1e3 / SYSTEM.lunar_semi_major_axis
    return np.stack([x, h.spin_rate / SYSTEM.spin_rate, h.obliquity], axis=1)


def _dop853(c, times, rtol):
    def rhs(_t, y):
        return eq.rates(y[0], y[1], y[2], c, 1)

    start = [1.0, 1.0, SYSTEM.obliquity]
    sol = solve_ivp(rhs, (0.0, times[0]), start, method="DOP853", rtol=rtol, atol=rtol, t_eval=times[::-1])
    return sol.y.T[::-1]


def _best(run, repeats):
    best = np.inf
    for _ in range(repeats):
        start = time.process_time()
        run()
        best = min(best, time.process_time() - start)
    return best


def main(argv: list[str] | None = None) -> None:
    """Print one line per case."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    print(f"numba compiled: {NUMBA}")
    for name, start in (("ocean", -4.3e9), ("constant-lag", -1.1e9)):
        times = np.linspace(start, 0.0, round(-start / 1e7) + 1)
        c = kernel_constants(tidal_model(name), SYSTEM)
        reference = _dop853(c, times, 1e-13)
        tidal_history(times, name)  # warm-up: compile or load the cached kernels
        ours = _best(lambda n=name, t=times: tidal_history(t, n), args.repeats)
        error = np.abs(_states(tidal_history(times, name)) - reference).max()
        peer = None
        for rtol in (1e-9, 1e-10, 1e-11, 1e-12, 1e-13):
            their_error = np.abs(_dop853(c, times, rtol) - reference).max() if rtol > 1e-13 else 0.0
            if their_error <= error:
                cost = _best(lambda t=times, r=rtol, cc=c: _dop853(cc, t, r), args.repeats)
                peer = (rtol, cost, their_error)
                break
        line = f"{name}: {times.size} outputs, andoyer {ours * 1e3:.2f} ms CPU, error {error:.1e}"
        if peer is not None:
            rtol, cost, their_error = peer
            line += f"; DOP853 as accurate (rtol {rtol:g}, error {their_error:.1e}): {cost * 1e3:.1f} ms"
            line += f" ({cost / ours:.0f}x)"
        print(line)


if __name__ == "__main__":
    main()
