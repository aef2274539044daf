"""Chaotic-obliquity members: where the time goes, and the compiled pass against the library's general path.

* andoyer: :func:`andoyer.planetary.spin_axis.member_obliquities` (one Mars member on the secular
  model: its Lawson–DOP853 orbit kernel and the compiled spin-axis pass), ``--years`` back from
  J2000, output every ``--interval`` years.
* the orbit alone: the secular model's kernel (:func:`andoyer.planetary.orbits.secular_flow.integrate`)
  over the same steps (and samples), the part the spin axis cannot save.
* shared orbits: ``--axes K`` members on one orbit (equal perturbations, precession rates
  spread in 7.590–7.610″/yr): the cost of one more spin axis on an orbit already integrated.
* ``--ensemble N --orbits K``: the public API (:func:`andoyer.ensemble.obliquity_ensemble`, Dask,
  ``--workers`` local processes) over ``--ensemble-years``, wall-clock seconds.
* peer, the same equations and steps: ``SecularOrbit("mars", step=h)`` sampled by
  :func:`andoyer.planetary.spin_axis.spin_axis_history` (numpy Hermite interpolation and
  Poincaré-to-vector conversion at every stage, then the compiled rotations), which agrees with
  the member to 1e-11 rad (``tests/planetary/spin_axis/test_spin_axis_members.py``).

CPU seconds of one process (``time.process_time``), numba's compilation done before the clock.

Run: ``python3 benchmarks/bench_obliquity_ensemble.py [--years 2e7] [--interval 1e5] [--axes 10]
[--ensemble 1000 --orbits 100 --ensemble-years 1e8 --workers 2]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--years", type=float, default=2e7)
    parser.add_argument("--interval", type=float, default=1e5)
    parser.add_argument("--axes", type=int, default=10, help="spin axes on one orbit (shared-orbit row)")
    parser.add_argument("--ensemble", type=int, help="members of a public-API run (wall clock)")
    parser.add_argument("--orbits", type=int, help="distinct orbits of that run (default: --ensemble)")
    parser.add_argument("--ensemble-years", type=float, default=1e8)
    parser.add_argument("--workers", type=int, default=2)
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
    samples = SecularOrbit("mars", step=run.orbit_step).samples  # the members keep the same samples
    tableau = flow.lawson_matrices(terms.linear, -run.orbit_step, samples)
    state = model.w0.copy()
    keep = np.array([3, 11])
    w = np.empty((steps * samples + 1, 2), complex)
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

    axes = max(int(args.axes), 1)
    shared = np.zeros((axes, 16), complex)
    rates = np.linspace(7.590, 7.610, axes)
    start = time.process_time()
    axis = default_axis("mars")
    member_obliquities("mars", -args.years, args.interval, shared, axis, precession_rate=rates)
    together = time.process_time() - start
    extra = (together - member) / max(axes - 1, 1)

    per_gyr = 1e9 / args.years
    print(f"Mars, {args.years:.3g} years back, output every {args.interval:g} yr, "
          f"orbit step {run.orbit_step:g} yr, spin step {run.spin_step:g} yr ({steps} steps)")  # fmt: skip
    print(f"  member_obliquities (compiled pass)  {member:8.3f} CPU s  = {member * per_gyr:7.1f} s per Gyr")
    print(f"    of which the orbit kernel         {orbit:8.3f} CPU s  ({100 * orbit / member:.0f} %)")
    print(f"  peer: SecularOrbit + spin_axis_history {peer:5.3f} CPU s  = {peer * per_gyr:7.1f} s per Gyr"
          f"   peer/this {peer / member:5.2f}")  # fmt: skip
    print(f"  largest obliquity difference, member vs peer: {gap:.2e} rad")
    print(f"  {axes} axes on one orbit {together:8.3f} CPU s: one more axis {extra:.3f} CPU s "
          f"= {extra * per_gyr:5.2f} s per Gyr")  # fmt: skip
    scale = 1e8 / args.years / 2
    for orbits in (1000, 100):
        cost = (orbits * member + (1000 - orbits) * extra) * scale
        print(f"  10^3 members of 100 Myr on {orbits} orbits at these rates: {cost:.0f} s on 2 cores")
    if args.ensemble:
        from andoyer.ensemble import obliquity_ensemble

        obliquity_ensemble("mars", 2, -2e5, 1e5, scheduler="synchronous", progress=False)  # compile
        start = time.perf_counter()
        ds = obliquity_ensemble(
            "mars", args.ensemble, -args.ensemble_years, args.interval, orbits=args.orbits,
            n_workers=args.workers, progress=False,
        )  # fmt: skip
        wall = time.perf_counter() - start
        print(f"  obliquity_ensemble: {args.ensemble} members on {ds.attrs['orbits']} orbits, "
              f"{args.ensemble_years:.3g} years, {args.workers} workers: {wall:.1f} s wall")  # fmt: skip


if __name__ == "__main__":
    main()
