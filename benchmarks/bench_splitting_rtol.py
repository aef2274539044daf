"""The splitting's step and order from an ``rtol`` (issue 25 item 3): is the accuracy met, and how fast?

For each model, ``andoyer.propagate(model, state, t, method="splitting", rtol=R)`` (the probe's
error model chooses the order and the step, then one run) at ``--outputs`` output times over
the span, against heyoka's Taylor integrator on the same equations side by side in this
process:

* accuracy: ``max |M − M_ref| / |M(t₀)|`` of the reference-frame momentum over every output
  time (what ``rtol`` bounds), ``M_ref`` from heyoka at tol 1e-15 over the full span
  (``propagate_grid`` at the same times);
* cost: CPU time of this process (numpy on one thread), the splitting's the median of three
  calls including its probe; heyoka's one ``propagate_grid`` over the full span at each
  tolerance, its compilation excluded;
* ratio: heyoka's cost at the cheapest tolerance whose measured error is at most the
  splitting's measured error ("equal accuracy"), and, second column, at most the requested
  ``rtol``, over the splitting's cost.

Models (``--models``):

* ``earth``: the Earth under the Sun and the Moon on their mean orbits, ``--years`` (default
  1000) years (the model of ``bench_precession.py``);
* ``mars``: Mars under the Sun on its mean orbit (``bodies.get("mars")``, its sidereal day,
  obliquity 25.19°), ``--years`` years;
* ``top``: a fast heavy top, ``RigidBody(1.0, 1.2, 1.5)``, ``HeavyTop(0.5, (0, 0.1, 0.3))``,
  ``|m| = 10`` tilted 0.3 rad, over 2000 time units (~2000 turns, ~5 precession periods);
* ``satellite``: a triaxial satellite ``RigidBody(0.7, 1.0, 1.3)`` spinning about its major
  axis at ~10 turns per orbit on a circular orbit (``n = 1``, ``GM = r = 1``, inclined 0.3 rad)
  under the gravity gradient, over 100 orbits.

Run: ``python3 benchmarks/bench_splitting_rtol.py [--models earth,mars,top,satellite]``
``[--rtols 1e-3,1e-4,1e-5,1e-6] [--outputs 200] [--years 1000]``.
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "benchmarks"))

import heyoka as hy  # noqa: E402

from andoyer import RigidBody, State, bodies, propagate  # noqa: E402
from andoyer.integrate.reference.heyoka import heyoka_system  # noqa: E402
from andoyer.perturbations import CircularOrbit, GravityGradient, HeavyTop, Model, PointMass  # noqa: E402
from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR, OBLIQUITY, mean_perturbers  # noqa: E402
from bench_precession import MODEL as EARTH_MODEL  # noqa: E402
from bench_precession import SIDEREAL_DAY  # noqa: E402
from bench_precession import START as EARTH_START  # noqa: E402

TOLS = (1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12)


def models(years):
    """``name -> (model, state, span, scale, time unit, unit name)`` (heyoka holds ``m/scale``)."""
    top_body = RigidBody(1.0, 1.2, 1.5)
    tilt = Rotation.from_rotvec([0.3, 0.0, 0.0])
    top_state = State.from_attitude(tilt, [0.0, 0.0, 10.0])
    sat_body = RigidBody(0.7, 1.0, 1.3)
    sat_state = State.from_attitude(Rotation.from_rotvec([0.2, 0.1, 0.0]), [0.05, 0.02, 13.0])
    earth = PointMass(1.0, CircularOrbit(1.0, 1.0, inclination=0.3))
    mars, mars_day = bodies.get("mars"), bodies.info("mars").rotation_period
    mars_model = Model(mars, GravityGradient(mean_perturbers("mars")))
    mars_spin = mars.C * 2 * np.pi / mars_day
    mars_state = State.from_attitude(Rotation.from_euler("X", OBLIQUITY["mars"]), [0.0, 0.0, mars_spin])
    return {
        "earth": (EARTH_MODEL, EARTH_START, years * JULIAN_YEAR, 1 / DAY, DAY, "sidereal d", SIDEREAL_DAY),
        "mars": (mars_model, mars_state, years * JULIAN_YEAR, 1 / DAY, DAY, "sols", mars_day),
        "top": (Model(top_body, HeavyTop(0.5, [0.0, 0.1, 0.3])), top_state, 2000.0, 1.0, 1.0, "units", 1.0),
        "satellite": (Model(sat_body, GravityGradient(earth)), sat_state, 200 * np.pi, 1.0, 1.0, "units", 1),
    }


def heyoka_momenta(model, start, times, tol, scale, unit):
    """Reference-frame momenta at ``times`` from heyoka at ``tol``, and the CPU time of the run."""
    system, pars = heyoka_system(model, scale=scale, time_unit=unit)
    y0 = [*start.quaternion.tolist(), *(start.m_body / scale).tolist()]
    ta = hy.taylor_adaptive(system, y0, pars=pars, tol=tol, compact_mode=True)
    grid = np.concatenate([[0.0], times / unit])
    began = time.process_time()
    out = ta.propagate_grid(grid)[5][1:]
    cost = time.process_time() - began
    q, m = out[:, :4], out[:, 4:] * scale
    return Rotation.from_quat(q / np.linalg.norm(q, axis=1)[:, None]).apply(m), cost


def relative_error(M, ref, start):
    return float(np.max(np.linalg.norm(M - ref, axis=-1)) / np.linalg.norm(start.m_reference))


def splitting(model, start, times, **options):
    """The public splitting path: its momenta, the state (its choice), the median CPU s of three calls."""
    costs = []
    for _ in range(3):
        began = time.process_time()
        out = propagate(model, start, times, method="splitting", **options)
        costs.append(time.process_time() - began)
    return out.m_reference, out, statistics.median(costs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--models", default="earth,mars,top,satellite")
    parser.add_argument("--rtols", default="1e-3,1e-4,1e-5,1e-6")
    parser.add_argument("--outputs", type=int, default=200)
    parser.add_argument("--years", type=float, default=1000.0)
    args = parser.parse_args()
    rtols = [float(x) for x in args.rtols.split(",")]
    table = models(args.years)
    print(f"heyoka {hy.__version__}; load average {os.getloadavg()[0]:.1f}")
    for name in args.models.split(","):
        model, start, span, scale, unit, unit_name, unit_size = table[name]
        times = np.linspace(span / args.outputs, span, args.outputs)
        propagate(model, start, times[:2], method="splitting", rtol=0.1)  # numba caches outside the timings
        ref, ref_cost = heyoka_momenta(model, start, times, 1e-15, scale, unit)
        peers = {}
        for tol in TOLS:
            M, cost = heyoka_momenta(model, start, times, tol, scale, unit)
            peers[tol] = (relative_error(M, ref, start), cost)
        print(f"\n{name}: span {span / unit_size:g} {unit_name}, {args.outputs} outputs; "
              f"reference heyoka 1e-15 ({ref_cost:.2f} CPU s)")
        for tol, (err, cost) in peers.items():
            print(f"  heyoka tol {tol:.0e}: error {err:.2e}, {cost:.3f} CPU s")

        def matched(err, peers=peers, ref_cost=ref_cost):
            ok = [(cost, tol) for tol, (e, cost) in peers.items() if e <= err]
            return min(ok) if ok else (ref_cost, 1e-15)

        print(
            f"  {'rtol':>6} {'order':>5} {'step':>9} {'probe':>9} {'estimate':>9} {'error':>9} {'met':>4} "
            f"{'CPU s':>7} {'peer tol':>8} {'ratio':>6} {'tol@rtol':>8} {'ratio@rtol':>10}"
        )
        for rtol in rtols:
            M, out, cost = splitting(model, start, times, rtol=rtol)
            err = relative_error(M, ref, start)
            peer_cost, tol = matched(err)
            rtol_cost, rtol_tol = matched(rtol)
            step, probe = out.step / unit_size, out.probe_length / unit_size
            print(
                f"  {rtol:6.0e} {out.order:5d} {step:9.4g} {probe:9.4g} "
                f"{out.error_estimate:9.2e} {err:9.2e} {'yes' if err <= rtol else 'NO':>4} {cost:7.3f} "
                f"{tol:8.0e} {peer_cost / cost:6.3g} {rtol_tol:8.0e} {rtol_cost / cost:10.3g}"
            )
        if name == "earth":
            for step in (6.7, 3.35):
                M, _, cost = splitting(model, start, times, step=step * SIDEREAL_DAY, order=2)
                err = relative_error(M, ref, start)
                peer_cost, tol = matched(err)
                print(f"  fixed step {step} sidereal d, order 2: error {err:.2e}, {cost:.3f} CPU s, "
                      f"peer tol {tol:.0e}, ratio {peer_cost / cost:.1f}")


if __name__ == "__main__":
    main()
