"""The long secular orbit model: CPU seconds per Gyr of orbit, against peers on the same equations.

* andoyer: ``SecularOrbit("mars").normal(t)`` over ``--years`` (default 1 Gyr, backwards from
  J2000), the compiled Lawson–DOP853 flow at the default step, the samples kept every half step
  (fresh object each time; numba's compilation cached beforehand).
* before/after (``--before SRC``, e.g. ``/path/to/an/older/checkout/src``): the same measurement
  in alternating processes, this tree's andoyer and the one under ``SRC``, ``--repeat`` times each
  (``--years`` each), so that the machine's load falls on both alike.
* peer 1, the same equations: scipy's ``solve_ivp(method="DOP853")`` on ``ẇ = L w + N(w)``
  (real and imaginary parts), with andoyer's *compiled* right-hand side, at the tolerance
  (``--rtol``) that gives the same error after ``--peer-years`` as andoyer's default step
  (both measured against andoyer at a 40th of the shortest period); scaled to a Gyr.
* peer 2, celmech's own secular integrator (``SecularSystemSimulation``, degree 4, its 5:2
  Jupiter–Saturn terms, RK at a 20th of the shortest period), when celmech is installed
  (``pip install celmech``; not an andoyer dependency): its own equations, not the same ones.

Run: ``python3 benchmarks/bench_secular_orbit.py [--years 1e9] [--peer-years 2e6] [--before SRC]``.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

#: One process's measurement: CPU s for SecularOrbit("mars") over YEARS, compilation outside the clock.
ONE_RUN = """
import sys, time
from andoyer.planetary.orbits import SecularOrbit
SecularOrbit("mars").normal(-1e5)
orbit = SecularOrbit("mars")
start = time.process_time()
orbit.normal(-float(sys.argv[1]))
print(time.process_time() - start)
"""


def before_after(years: float, before: str, repeat: int) -> None:
    """CPU s per Gyr of this tree's andoyer and the one under ``before``, in alternating processes."""
    ours = str(Path(__file__).resolve().parents[1] / "src")
    per = {"before": [], "after": []}
    for _ in range(repeat):
        for label, src in (("before", before), ("after", ours)):
            env = {**os.environ, "PYTHONPATH": src}
            out = subprocess.run(
                [sys.executable, "-c", ONE_RUN, str(years)], env=env, capture_output=True, text=True,
                check=True,
            )  # fmt: skip
            per[label].append(float(out.stdout.split()[-1]) / years * 1e9)
    ratios = np.array(per["before"]) / np.array(per["after"])
    print(
        f"before/after over {years:.3g} yr, {repeat} alternating pairs: before "
        f"{min(per['before']):.1f}-{max(per['before']):.1f} s per Gyr, after "
        f"{min(per['after']):.1f}-{max(per['after']):.1f} s per Gyr, ratio "
        f"{ratios.min():.2f}-{ratios.max():.2f} (load {os.getloadavg()[0]:.1f})"
    )


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--years", type=float, default=1e9)
    parser.add_argument("--peer-years", type=float, default=2e6)
    parser.add_argument("--rtol", type=float, default=1e-9)
    parser.add_argument("--celmech-years", type=float, default=2e4)
    parser.add_argument("--before", help="an older andoyer's src folder, measured alternately with this one")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    if args.before:
        before_after(args.years, args.before, args.repeat)
        return

    from scipy.integrate import solve_ivp

    from andoyer.planetary.orbits import SecularOrbit
    from andoyer.planetary.orbits import secular_flow as flow
    from andoyer.planetary.orbits.secular import LONG_STEP_FRACTION, secular_model

    model = secular_model()
    terms = model.terms
    SecularOrbit("mars").normal(-1e5)  # compile (or load numba's cache) outside the clock
    orbit = SecularOrbit("mars")
    start = time.process_time()
    orbit.normal(-args.years)
    seconds = time.process_time() - start
    per_gyr = seconds / args.years * 1e9
    print(
        f"andoyer SecularOrbit: {args.years:.3g} yr in {seconds:.2f} CPU s = {per_gyr:.1f} s per Gyr "
        f"(step {orbit.step:.0f} yr, {len(orbit._runs[-1].w)} samples kept, {orbit.samples} per step)"
    )

    # Errors after peer-years against a fine run of andoyer's flow.
    fine = flow.default_step(terms.linear, 1.0 / 40.0)
    steps = round(args.peer_years / fine)
    h = args.peer_years / steps
    tableau = flow.lawson_matrices(terms.linear, h)
    reference = model.w0.copy()
    keep = np.zeros(1, dtype=np.int64)
    flow.integrate(
        reference,
        steps,
        h,
        *tableau,
        *terms.arrays(),
        terms.linear,
        keep,
        np.empty((steps + 1, 1), complex),
        np.empty((steps + 1, 1), complex),
        np.zeros(16),
    )
    default = flow.default_step(terms.linear, LONG_STEP_FRACTION)
    steps = round(args.peer_years / default)
    tableau = flow.lawson_matrices(terms.linear, args.peer_years / steps, 2)  # two samples a step
    ours = model.w0.copy()
    start = time.process_time()
    flow.integrate(
        ours,
        steps,
        args.peer_years / steps,
        *tableau,
        *terms.arrays(),
        terms.linear,
        keep,
        np.empty((2 * steps + 1, 1), complex),
        np.empty((2 * steps + 1, 1), complex),
        np.zeros(16),
    )
    ours_seconds = time.process_time() - start
    ours_error = np.abs(ours - reference).max() / np.abs(reference).max()

    powers = np.empty(4 * terms.count * terms.width, complex)
    node = np.empty(terms.parent.size, complex)
    nonlinear = np.empty(16, complex)
    arrays = terms.arrays()

    def rhs(_t, y):
        w = y[:16] + 1j * y[16:]
        flow._nonlinear(w, 8, *arrays, powers, node, nonlinear)
        dw = terms.linear @ w + nonlinear
        return np.concatenate([dw.real, dw.imag])

    y0 = np.concatenate([model.w0.real, model.w0.imag])
    start = time.process_time()
    sol = solve_ivp(rhs, (0.0, args.peer_years), y0, method="DOP853", rtol=args.rtol, atol=1e-14)
    peer_seconds = time.process_time() - start
    peer = sol.y[:16, -1] + 1j * sol.y[16:, -1]
    peer_error = np.abs(peer - reference).max() / np.abs(reference).max()
    print(
        f"over {args.peer_years:.3g} yr: andoyer {ours_seconds:.3f} CPU s (error {ours_error:.1e}), "
        f"scipy DOP853 rtol {args.rtol:g} {peer_seconds:.3f} CPU s "
        f"(error {peer_error:.1e}, {sol.nfev} evaluations); "
        f"peer/andoyer {peer_seconds / ours_seconds:.1f}x; "
        f"scipy per Gyr {peer_seconds / args.peer_years * 1e9:.0f} s"
    )

    if importlib.util.find_spec("celmech") is None:
        print("celmech: not installed (pip install celmech), peer 2 skipped")
        return
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
    from secular_celmech_check import celmech_run

    _, _, celmech_seconds = celmech_run(args.celmech_years, 250.0, {(5, 6): [(5, 3)]}, 4)
    per = celmech_seconds / args.celmech_years * 1e9
    print(
        f"celmech SecularSystemSimulation: {args.celmech_years:.3g} yr in {celmech_seconds:.2f} CPU s = "
        f"{per:.3g} s per Gyr; celmech/andoyer {per / per_gyr:.0f}x"
    )


if __name__ == "__main__":
    main()
