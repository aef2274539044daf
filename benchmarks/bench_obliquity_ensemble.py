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
* peer, the same equations and steps: ``SecularOrbit("mars", step=h)`` (a fresh one: its own
  orbit integration) sampled by :func:`andoyer.planetary.spin_axis.spin_axis_history` (the
  library's general path; since ``rotate_on_samples`` it also interpolates the orbit inside its
  compiled rotations, so the two cost about the same), which agrees with the member to 1e-11 rad
  (``tests/planetary/spin_axis/test_spin_axis_members.py``).

CPU seconds of one process (``time.process_time``), numba's compilation done before the clock; each
the best of ``--repeat`` runs, the runs of the different measurements interleaved (a loaded machine).

Run: ``python3 benchmarks/bench_obliquity_ensemble.py [--years 2e7] [--interval 1e5] [--axes 10]
[--ensemble 1000 --orbits 100 --ensemble-years 1e8 --workers 2]``.
"""

from __future__ import annotations

import argparse
import os
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
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()

    from andoyer.planetary.orbits import SecularOrbit
    from andoyer.planetary.orbits import secular_flow as flow
    from andoyer.planetary.orbits.secular import secular_model, secular_tableau
    from andoyer.planetary.spin_axis import default_axis, member_obliquities, spin_axis_history

    zero = np.zeros((1, 16), complex)
    axis = default_axis("mars")
    member_obliquities("mars", -2e5, 1e5, zero, axis)  # compile outside the clock
    run = member_obliquities("mars", -args.years, args.interval, zero, axis)
    steps = round(args.years / run.orbit_step)
    samples = SecularOrbit("mars", step=run.orbit_step).samples  # the members keep the same samples
    model = secular_model()
    terms = model.terms
    tableau = secular_tableau(-run.orbit_step, samples)
    keep = np.array([3, 11])
    w = np.empty((steps * samples + 1, 2), complex)
    axes = max(int(args.axes), 1)
    shared = np.zeros((axes, 16), complex)
    rates = np.linspace(7.590, 7.610, axes)
    spin_axis_history(SecularOrbit("mars", step=run.orbit_step), "mars", [-2e5, 0.0])  # warm
    peer_history = []

    def member_run() -> None:
        member_obliquities("mars", -args.years, args.interval, zero, axis)

    def orbit_run() -> None:
        flow.integrate(model.w0.copy(), steps, -run.orbit_step, *tableau, *terms.arrays(), terms.linear, keep,
                       w, w.copy(), np.zeros(16))  # fmt: skip

    def peer_run() -> None:
        orbit = SecularOrbit("mars", step=run.orbit_step)
        peer_history[:] = [spin_axis_history(orbit, "mars", run.t[::-1], step=run.spin_step)]

    def shared_run() -> None:
        member_obliquities("mars", -args.years, args.interval, shared, axis, precession_rate=rates)

    cases = {"member": member_run, "orbit": orbit_run, "peer": peer_run, "shared": shared_run}
    best = dict.fromkeys(cases, np.inf)
    for _ in range(max(args.repeat, 1)):
        for name, case in cases.items():
            start = time.process_time()
            case()
            best[name] = min(best[name], time.process_time() - start)
    member, orbit, peer, together = best["member"], best["orbit"], best["peer"], best["shared"]
    gap = float(np.abs(peer_history[0].obliquity[::-1] - run.obliquity[0]).max())
    extra = (together - member) / max(axes - 1, 1)

    per_gyr = 1e9 / args.years
    print(f"Mars, {args.years:.3g} years back, output every {args.interval:g} yr, "
          f"orbit step {run.orbit_step:g} yr, spin step {run.spin_step:g} yr ({steps} steps)")  # fmt: skip
    print(f"  member_obliquities (compiled pass)  {member:8.3f} CPU s  = {member * per_gyr:7.1f} s per Gyr")
    print(f"    of which the orbit kernel         {orbit:8.3f} CPU s  ({100 * orbit / member:.0f} %)")
    print(f"  load average {os.getloadavg()[0]:.1f}; best of {args.repeat}")
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
