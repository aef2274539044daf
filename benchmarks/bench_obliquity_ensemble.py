"""Chaotic-obliquity members: where the time goes, and the compiled pass against the library's general path.

* andoyer: :func:`andoyer.planetary.spin_axis.member_obliquities` (one Mars member on the secular
  model: its Lawson–DOP853 orbit kernel and the compiled spin-axis pass), ``--years`` back from
  J2000, output every ``--interval`` years.
* the orbit alone: the secular model's kernel (:func:`andoyer.planetary.orbits.secular_flow.integrate`)
  over the same steps, the part the spin axis cannot save.
* peer, the same equations and steps: ``SecularOrbit("mars", step=h)`` sampled by
  :func:`andoyer.planetary.spin_axis.spin_axis_history` (numpy Hermite interpolation and
  Poincaré-to-vector conversion at every stage, then the compiled rotations), which agrees with
  the member to 1e-11 rad (``tests/planetary/spin_axis/test_spin_axis_members.py``).

CPU seconds of one process (``time.process_time``), numba's compilation done before the clock.

Run: ``python3 benchmarks/bench_obliquity_ensemble.py [--years 2e7] [--interval 1e5]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--years", type=float, default=2e7)
    parser.add_argument("--interval", type=float, default=1e5)
    args = parser.parse_args()

    from andoyer.planetary.orbits import SecularOrbit
    from andoyer.planetary.orbits import secular_flow as flow
    from andoyer.planetary.orbits.secular import secular_model
    from andoyer.planetary.spin_axis import default_axis, member_obliquities, spin_axis_history

    zero = np.zeros((1, 16), complex)
    member_obliquities("mars", -2e5, 1e5, zero, default_axis("mars"))  # compile outside the clock
    start = time.process_time()
    run = member_obliquities("mars", -args.years, args.interval, zero, default_axis("mars"))
    member = time.process_time() - start
    steps = round(args.years / run.orbit_step)

    model = secular_model()
    terms = model.terms
    tableau = flow.lawson_matrices(terms.linear, -run.orbit_step)
    state = model.w0.copy()
    keep = np.array([3, 11])
    w = np.empty((steps + 1, 2), complex)
    start = time.process_time()
    flow.integrate(state, steps, -run.orbit_step, *tableau, *terms.arrays(), terms.linear, keep, w, w.copy(),
                   np.zeros(16))  # fmt: skip
    orbit = time.process_time() - start

    spin_axis_history(SecularOrbit("mars", step=run.orbit_step), "mars", [-2e5, 0.0])  # warm
    start = time.process_time()
    peer_orbit = SecularOrbit("mars", step=run.orbit_step)
    history = spin_axis_history(peer_orbit, "mars", run.t[::-1], step=run.spin_step)
    peer = time.process_time() - start
    gap = float(np.abs(history.obliquity[::-1] - run.obliquity[0]).max())

    per_gyr = 1e9 / args.years
    print(f"Mars, {args.years:.3g} years back, output every {args.interval:g} yr, "
          f"orbit step {run.orbit_step:g} yr, spin step {run.spin_step:g} yr ({steps} steps)")  # fmt: skip
    print(f"  member_obliquities (compiled pass)  {member:8.3f} CPU s  = {member * per_gyr:7.1f} s per Gyr")
    print(f"    of which the orbit kernel         {orbit:8.3f} CPU s  ({100 * orbit / member:.0f} %)")
    print(f"  peer: SecularOrbit + spin_axis_history {peer:5.3f} CPU s  = {peer * per_gyr:7.1f} s per Gyr"
          f"   peer/this {peer / member:5.2f}")  # fmt: skip
    print(f"  largest obliquity difference, member vs peer: {gap:.2e} rad")
    print(f"  10^3 members of 100 Myr at this rate: {1e3 * member * 1e8 / args.years / 2:.0f} s on 2 cores")


if __name__ == "__main__":
    main()
