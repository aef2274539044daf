"""The spin axis' step from a requested accuracy (issue 25 item 5): error and cost against DOP853.

Mars on the N-body orbit (:func:`andoyer.planetary.orbits.orbit_history` ``"nbody"``, read from
the cache or integrated first: ~170 CPU s for 1 Myr), outputs every 1000 years from −1 Myr
to J2000, the default precession rate and axis. Rows:

* fixed steps and orders (``step=..., order=...``: the runs as before tolerances existed; the
  old default was 1000 years, order 8);
* ``tolerance=...`` and the default (no step: 0.01″): the step halved until two runs agree
  (:func:`andoyer.planetary.spin_axis.history.controlled_outputs`), with the run's
  ``error_estimate``;
* the peer: scipy's DOP853 (``integrate_axis_dop853``) at rtol 1e-12 on the same orbit and
  model; its own error (~1e-9 rad here, from DOP853 at 1e-12 against order 8 at 50-year steps)
  is the floor of the "error" column.

CPU time of this process (numba caches warm: a first call precedes the timings; the orbit's
spline is built before). Run: ``python3 benchmarks/bench_spin_axis_accuracy.py [--span 1e6]``.
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

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer.planetary.orbits import orbit_history  # noqa: E402
from andoyer.planetary.spin_axis import spin_axis_history  # noqa: E402
from andoyer.planetary.spin_axis.history import integrate_axis_dop853  # noqa: E402

ARCSEC = np.pi / 648000.0


def cpu(fn):
    start = time.process_time()
    out = fn()
    return out, time.process_time() - start


def best(fn, repeats=3):
    runs = [cpu(fn) for _ in range(repeats)]
    return runs[0][0], min(t for _, t in runs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--span", type=float, default=1e6, help="years before J2000")
    parser.add_argument("--body", default="mars")
    args = parser.parse_args()
    orbit = orbit_history("nbody", args.body)
    times = np.arange(-args.span, 1.0, 1000.0)
    spin_axis_history(orbit, args.body, times, step=1000.0, order=8)  # orbit, caches, compilation
    old = spin_axis_history(orbit, args.body, times, step=1000.0, order=8)
    reference, t_ref = cpu(
        lambda: integrate_axis_dop853(orbit, old.model, times, old.axis[-1], rtol=1e-12)
    )

    def error(h):
        return float(np.max(np.linalg.norm(h.axis - reference, axis=-1))) / ARCSEC

    print(f"{args.body}, N-body orbit, {times.size} outputs from {-args.span:g} yr to J2000")
    print(f"DOP853 rtol 1e-12: {t_ref:.2f} CPU s (the reference)")
    print(f"  {'run':28s} {'step (yr)':>9s} {'CPU s':>8s} {'error (as)':>10s} {'estimate (as)':>13s} "
          f"{'DOP853/run':>10s}")
    rows = [(f"step {s:g}, order {o}", {"step": s, "order": o})
            for s, o in ((1000.0, 8), (1000.0, 4), (500.0, 8), (250.0, 8), (100.0, 4))]
    rows += [(f"tolerance {tol / ARCSEC:g}″", {"tolerance": tol}) for tol in (ARCSEC, 0.1 * ARCSEC)]
    rows += [("default (0.01″)", {})]
    rows += [(f"tolerance {tol / ARCSEC:g}″", {"tolerance": tol}) for tol in (1e-3 * ARCSEC,)]
    for name, options in rows:
        h, seconds = best(lambda options=options: spin_axis_history(orbit, args.body, times, **options))
        estimate = "—" if h.error_estimate is None else f"{h.error_estimate / ARCSEC:.3g}"
        print(f"  {name:28s} {h.integration_step:9.4g} {seconds:8.3f} {error(h):10.3g} {estimate:>13s} "
              f"{t_ref / seconds:10.0f}")


if __name__ == "__main__":
    main()
