"""Rigid-Earth nutation: andoyer.planetary.nutation's quarter-day RK4 against scipy's DOP853, same equations.

Model: the spin-averaged torque of the Moon and the Sun (lunar theory of
:mod:`andoyer.perturbations.lunar_theory`) on the Earth's unit angular momentum,
``ṁ = (3H/ω)(S m) × m + p ẑ × m`` in the frame of date, over 18.63 years (the shortest span
the nutation fits accept), from the same initial state.

* andoyer: :func:`andoyer.planetary.nutation.numeric._window_run` — ``S`` tabulated once on the half-step grid
  (vectorised lunar theory), then RK4 at a quarter day in plain Python floats;
* peer: :func:`scipy.integrate.solve_ivp` (DOP853, rtol 1e-11, atol 1e-14), evaluating the lunar
  theory at every right-hand-side call, as a general integrator must;
* also the analytic (second-order Fourier) series, for its cost.

Accuracy: the largest difference of ``m`` between the two integrations (radians → mas).

Run: ``python3 benchmarks/bench_nutation.py`` (pins numpy to one thread; CPU time of this process).
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import time  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from andoyer.planetary import nutation  # noqa: E402
from andoyer.planetary.nutation.numeric import _gradient_matrices, _window_run  # noqa: E402


def main() -> None:
    """Time both integrations and print a small table."""
    H, eps = nutation.H_MHB2000, nutation.MEAN_OBLIQUITY
    end = nutation.minimum_span() * 1.001
    start = time.process_time()
    series = nutation.nutation_series(H, "momentum", 0.5 * end, eps)
    series_cpu = time.process_time() - start
    start = time.process_time()
    run, _ = _window_run(0.0, end, H, eps)
    ours_cpu = time.process_time() - start
    p = series.precession * nutation.ARCSEC

    def rate(t: float, m: np.ndarray) -> np.ndarray:
        S = _gradient_matrices(np.array([t]), H)[0]
        return np.cross(S @ m, m) + p * np.cross([0.0, 0.0, 1.0], m)

    start = time.process_time()
    peer = solve_ivp(rate, (0.0, end), run.m[0], method="DOP853", rtol=1e-11, atol=1e-14, t_eval=run.t[::40])
    peer_cpu = time.process_time() - start
    gap = np.max(np.linalg.norm(peer.y.T - run.m[::40], axis=-1)) / nutation.ARCSEC * 1e3
    print(f"span {end:.3f} yr, {run.t.size - 1} RK4 steps; peer DOP853 {peer.nfev} right-hand sides")
    print(f"analytic series (FFT, second order): {series_cpu:.2f} s CPU")
    print(f"andoyer RK4 (tabulated S):            {ours_cpu:.2f} s CPU")
    print(f"scipy DOP853 (lunar theory per call): {peer_cpu:.2f} s CPU  -> ratio {peer_cpu / ours_cpu:.1f}x")
    print(f"largest difference of m: {gap:.4f} mas")


if __name__ == "__main__":
    main()
