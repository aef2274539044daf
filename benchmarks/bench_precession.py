"""Earth's precession under the Sun and the Moon: splitting and the secular model against heyoka.

Model: ``bodies.get("earth")`` (moments normalised to C = 1), spinning once per sidereal
day about its figure axis, obliquity 23.44°, torqued by the Sun and the Moon on their mean
orbits (:func:`andoyer.perturbations.solar_system.mean_perturbers`). The precession angle
is Andoyer's node ``h = atan2(M₁, −M₂)`` of the angular momentum in the ecliptic frame.

* splitting: :func:`andoyer.integrate.splitting.integrate_splitting`, order 2, exact free
  flow (compiled lean kernel when numba is installed), over the full span;
* secular: :class:`andoyer.perturbations.averaged_gravity.SecularGravityGradient` on the averaged
  equations, over the full span: its default propagation (composition of exact rotations
  about the orbit normals, order 8, step set by Richardson's estimate for ``rtol``, compiled
  with numba when installed) at two tolerances, and its DOP853 path for comparison. Its
  CPU time is the mean over repeated calls (a call takes about a millisecond);
* the public path ``andoyer.propagate(model, state, t, method="secular")`` (mean state:
  the compiled rotations for ``M̄`` plus the exact free motion), mean CPU time as above;
* ``--order4-steps``: order-4 splitting rows at those steps (the accuracy-vs-cost curve);
* peer: heyoka's Taylor integrator on the same equations (quaternion + body momentum, the
  orbits through ``kepE``), time in days, over ``--peer-years`` at a ladder of
  tolerances; its cost is scaled to the full span by the measured cost per year (stated
  in the output). Without heyoka, scipy's DOP853 (:func:`integrate_reference`) is the peer.

Accuracy: the error of the precession angle at ``--peer-years`` against heyoka at
tol 1e-15 (cross-checked with order-4 splitting at a small step). Each method is compared
with the cheapest peer tolerance that is at least as accurate.

Run: ``python3 benchmarks/bench_precession.py [--years 1000] [--peer-years 2] [--steps 0.37,...]``
``[--order4-steps 3.7,6.7] [--rtols 1e-4,1e-5]`` (``--rtols``: rows of
``propagate(..., method="splitting", rtol=R, order=2)``, the step chosen by the probe's error
model, :mod:`andoyer.integrate.splitting.probe`; ``benchmarks/bench_splitting_rtol.py`` checks
that model against heyoka at many output times);
``--growth`` prints only the step-doubling distance ``|M_h − M_{h/2}| / |M|`` from one lunar
month to 1000 years at orders 2 and 4 (the shape of the splitting's error in time)
(pins numpy to one thread; CPU time of this process).

The step of the splitting can be a sizable fraction of the day and even several days:
the free flow is exact, and what is left of the leading error term averages out over
the spin unless the step resonates with it (multiples of half a sidereal day alias the
semi-diurnal term of the triaxiality ``B − A``); the first table quantifies this. For the
Earth the recommended step is 6.7 sidereal days at order 2 (rate error 7e-6″/yr, 0.09″ of
short-period error, about 60× heyoka at matched accuracy; ``benchmarks/RESULTS.md``).
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
from scipy.spatial.transform import Rotation  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer import (  # noqa: E402
    State,
    bodies,
    propagate,
)
from andoyer._jit import NUMBA  # noqa: E402
from andoyer.integrate import integrate_reference  # noqa: E402
from andoyer.integrate.reference.heyoka import heyoka_system  # noqa: E402
from andoyer.integrate.secular import propagate_momentum  # noqa: E402
from andoyer.integrate.splitting import integrate_splitting  # noqa: E402
from andoyer.perturbations import GravityGradient, Model  # noqa: E402
from andoyer.perturbations.averaged_gravity import SecularGravityGradient  # noqa: E402
from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR, OBLIQUITY, mean_perturbers  # noqa: E402

try:
    import heyoka as hy
except ImportError:  # pragma: no cover - optional
    hy = None

SIDEREAL_DAY = 86164.0905
ARCSEC = 180 * 3600 / np.pi
EARTH = bodies.get("earth")
PERTURBERS = mean_perturbers("earth")
MODEL = Model(EARTH, GravityGradient(PERTURBERS))
G0 = EARTH.C * 2 * np.pi / SIDEREAL_DAY
START = State.from_attitude(Rotation.from_euler("X", OBLIQUITY["earth"]), [0.0, 0.0, G0])


def node(M):
    """Precession angle (Andoyer's h) of reference-frame momenta (..., 3)."""
    return np.arctan2(M[..., 0], -M[..., 1])


def wrapped(a):
    return (a + np.pi) % (2 * np.pi) - np.pi


def cpu(fn):
    t = time.process_time()
    out = fn()
    return out, time.process_time() - t


def splitting_h(years, step_days, order=2):
    out = integrate_splitting(MODEL, START, [years * JULIAN_YEAR], step=step_days * SIDEREAL_DAY, order=order)
    return float(node(out.m_reference[0]))


def controlled_h(years, rtol, order=2):
    """The public splitting path, its step chosen from ``rtol`` (the probe); its step and estimate too."""
    out = propagate(MODEL, START, [years * JULIAN_YEAR], method="splitting", rtol=rtol, order=order)
    return float(node(out.m_reference[0])), out.step / SIDEREAL_DAY, out.error_estimate


#: Output times of the ``--growth`` table: 1, 2, 4, 8 lunar months, then 1 to 1000 years.
GROWTH_TIMES = np.array(
    [27.32 * DAY * k for k in (1, 2, 4, 8)] + [JULIAN_YEAR * y for y in (1, 10, 100, 1000)]
)


def growth_table(orders=(2, 4), steps=(13.7, 6.85, 3.43)):
    """The step-doubling distance ``|M_h − M_{h/2}| / |M|`` against time: how the splitting error grows.

    Shows the shape an error model fitted on a short probe must have (issue 25 item 3): whether
    the distance grows linearly in time for the whole span or saturates (a bounded term).
    """
    scale = float(np.linalg.norm(START.m_reference))
    print("step-doubling distance |M_h - M_h/2| / |M| at t (relative)")
    heads = [f"{k} mo" for k in (1, 2, 4, 8)] + [f"{y} yr" for y in (1, 10, 100, 1000)]
    print("  order  h (sid. d)  " + "  ".join(f"{h:>8}" for h in heads) + "   CPU s (both runs)")
    for order in orders:
        for step in steps:
            t = time.process_time()
            coarse = integrate_splitting(MODEL, START, GROWTH_TIMES, step * SIDEREAL_DAY, order).m_reference
            fine = integrate_splitting(MODEL, START, GROWTH_TIMES, step * SIDEREAL_DAY / 2, order).m_reference
            cost = time.process_time() - t
            dist = np.linalg.norm(coarse - fine, axis=-1) / scale
            print(f"  {order:5d}  {step:10.2f}  " + "  ".join(f"{d:8.1e}" for d in dist) + f"   {cost:.2f}")


def cpu_mean(fn, least=0.5):
    """Mean CPU time of ``fn`` over as many calls as fill ``least`` seconds (at least one)."""
    out, spent = cpu(fn)
    calls = 1
    while spent < least:
        more = max(1, int(calls * min(10.0, 1.2 * least / max(spent, 1e-6))))
        out, extra = cpu(lambda more=more: [fn() for _ in range(more)][-1])
        spent, calls = spent + extra, calls + more
    return out, spent / calls


def secular_h(years, rtol=1e-12, method="rotations"):
    secular = SecularGravityGradient(EARTH, PERTURBERS)
    M = propagate_momentum(
        secular, START.m_reference, G0, np.array([0.0, years * JULIAN_YEAR]), rtol=rtol, method=method
    )
    return float(node(M[-1]))


def public_secular_h(years):
    """The public path: ``andoyer.propagate(model, state, t, method="secular")`` (a full mean state)."""
    out = propagate(MODEL, START, years * JULIAN_YEAR, method="secular")
    return float(node(out.m_reference))


def heyoka_integrator(tol):  # pragma: no cover - optional
    """Quaternion + body momentum under Sun and Moon, time in days (compiled once per tol).

    The library's formulation (:func:`andoyer.integrate.reference.heyoka.heyoka_system`,
    orbits through ``kepE``), with momenta held as ``m·DAY``.
    """
    system, pars = heyoka_system(MODEL, scale=1 / DAY, time_unit=DAY)
    y0 = [*START.quaternion.tolist(), *(START.m_body * DAY).tolist()]
    return hy.taylor_adaptive(system, y0, pars=pars, tol=tol, compact_mode=True)


def heyoka_h(ta, years):  # pragma: no cover - optional
    y0 = [*START.quaternion.tolist(), *(START.m_body * DAY).tolist()]
    ta.time = 0.0
    ta.state[:] = y0
    ta.propagate_until(years * JULIAN_YEAR / DAY)
    q, m = ta.state[:4], ta.state[4:]
    return float(node(Rotation.from_quat(q / np.linalg.norm(q)).apply(m)))


def dop853_h(rtol, years):
    out = integrate_reference(MODEL, START, [years * JULIAN_YEAR], rtol=rtol, atol=rtol * 1e-2)
    return float(node(out.m_reference[0]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--years", type=float, default=1000.0)
    parser.add_argument("--peer-years", type=float, default=2.0)
    parser.add_argument("--steps", default="0.37,1.37,3.7,6.7", help="splitting steps in sidereal days")
    parser.add_argument(
        "--order4-steps", default="", help="order-4 splitting steps in sidereal days (accuracy-vs-cost rows)"
    )
    parser.add_argument("--rate-years", type=float, default=20.0, help="span of the rate-vs-step table")
    parser.add_argument(
        "--rtols", default="", help="rows of propagate(method='splitting', rtol=R, order=2) at these R"
    )
    parser.add_argument(
        "--growth", action="store_true", help="only the table of the step-doubling distance against time"
    )
    args = parser.parse_args()
    if args.growth:
        splitting_h(0.01, 1.0)  # compile / load the numba caches outside the timings
        growth_table()
        return
    S, Y = args.peer_years, args.years
    h0 = float(node(START.m_reference))
    steps = [float(x) for x in args.steps.split(",")]
    print(f"numba: {NUMBA}; heyoka: {hy is not None}; span {Y:g} yr, peer span {S:g} yr")
    print(f"splitting steps (sidereal days): {steps}")
    splitting_h(0.01, steps[0])  # compile / load the numba caches outside the timings
    secular_h(1.0)

    # 1. precession rate against the step (the leading splitting error averages over the spin)
    print(f"\nprecession over {args.rate_years:g} yr against the step (order 2)")
    ref_rate = wrapped(splitting_h(args.rate_years, 0.05, order=4) - h0) * ARCSEC / args.rate_years
    print(f"  reference (order 4, step 0.05 d): {ref_rate:.6f} arcsec/yr")
    print("  step (sidereal d)   rate (arcsec/yr)   rate error (arcsec/yr)   steps/yr")
    for frac in (0.05, 0.1, 0.25, 0.37, 0.5, 0.73, 1.0, 1.37, 2.5, 3.7, 4.7, 6.7, 8.7, 9.7):
        rate = wrapped(splitting_h(args.rate_years, frac) - h0) * ARCSEC / args.rate_years
        per_year = JULIAN_YEAR / (frac * SIDEREAL_DAY)
        print(f"  {frac:17.2f}   {rate:16.6f}   {rate - ref_rate:22.2e}   {per_year:8.0f}")

    # 2. accuracy at the peer span against heyoka at tol 1e-15 (or DOP853 at 1e-13)
    if hy is not None:
        tols = (1e-15, 1e-12, 1e-9, 1e-6, 1e-4, 1e-3)
        peers = {}
        for tol in tols:
            ta, t_build = cpu(lambda tol=tol: heyoka_integrator(tol))
            value, t_run = cpu(lambda ta=ta: heyoka_h(ta, S))
            peers[tol] = (value, t_run / S)
            print(f"heyoka tol {tol:.0e}: built in {t_build:.1f} s, {t_run:.2f} s CPU for {S:g} yr")
        ref = peers[1e-15][0]
        peer_name = "heyoka"
    else:
        rtols = (1e-13, 1e-11, 1e-9, 1e-7)
        peers = {}
        for rtol in rtols:
            value, t_run = cpu(lambda rtol=rtol: dop853_h(rtol, S))
            peers[rtol] = (value, t_run / S)
        ref = peers[1e-13][0]
        peer_name = "DOP853"
    check = splitting_h(S, 0.05, order=4)
    print(
        f"reference at {S:g} yr: {peer_name} vs order-4 splitting (step 0.05 d): "
        f"{wrapped(check - ref) * ARCSEC:.2e} arcsec"
    )
    print(f"\nerror of the precession angle at {S:g} yr (arcsec)")
    for key, (value, per_year) in peers.items():
        err = abs(wrapped(value - ref)) * ARCSEC
        print(f"  {peer_name} {key:.0e}: {err:.2e}   ({per_year:.4f} CPU s per year)")

    def matched(err):
        """Cheapest peer setting at least as accurate as ``err`` (the reference itself excluded)."""
        ok = [
            (per_year, key)
            for key, (value, per_year) in peers.items()
            if key != min(peers) and abs(wrapped(value - ref)) * ARCSEC <= err
        ]
        return min(ok) if ok else (peers[min(peers)][1], min(peers))

    # 3. the full span, side by side
    rows = []
    for step in steps:
        err = abs(wrapped(splitting_h(S, step) - ref)) * ARCSEC
        value, t_own = cpu(lambda step=step: splitting_h(Y, step))
        half = splitting_h(Y, step / 2)
        rows.append(
            (f"splitting order 2, step {step} d", err, t_own, abs(wrapped(value - half)) * ARCSEC, value)
        )
    for step in [float(x) for x in args.order4_steps.split(",") if x]:
        err = abs(wrapped(splitting_h(S, step, order=4) - ref)) * ARCSEC
        value, t_own = cpu(lambda step=step: splitting_h(Y, step, order=4))
        half = splitting_h(Y, step / 2, order=4)
        rows.append(
            (f"splitting order 4, step {step} d", err, t_own, abs(wrapped(value - half)) * ARCSEC, value)
        )
    for rtol in [float(x) for x in args.rtols.split(",") if x]:
        err = abs(wrapped(controlled_h(S, rtol)[0] - ref)) * ARCSEC
        (value, step, estimate), t_own = cpu(lambda rtol=rtol: controlled_h(Y, rtol))
        print(f"rtol {rtol:.0e}: step {step:.3f} sidereal d, estimate {estimate:.2e} (relative M), {Y:g} yr")
        rows.append((f"splitting rtol {rtol:.0e} (order 2)", err, t_own, float("nan"), value))
    best = rows[0][4]
    secular_best = secular_h(Y, 1e-12, "dop853")
    for rtol, method in ((1e-12, "rotations"), (1e-6, "rotations"), (1e-12, "dop853"), (1e-8, "dop853")):
        err = abs(wrapped(secular_h(S, rtol, method) - ref)) * ARCSEC
        timer = cpu_mean if method == "rotations" else cpu
        value, t_own = timer(lambda rtol=rtol, method=method: secular_h(Y, rtol, method))
        name = f"secular ({method} rtol {rtol:.0e})"
        own = abs(wrapped(value - secular_best)) * ARCSEC
        rows.append((name, err, t_own, abs(wrapped(value - best)) * ARCSEC, value))
        print(f"{name} vs secular DOP853 rtol 1e-12 at {Y:g} yr: {own:.2e} arcsec")
    err = abs(wrapped(public_secular_h(S) - ref)) * ARCSEC
    value, t_own = cpu_mean(lambda: public_secular_h(Y))
    rows.append(("propagate(method='secular')", err, t_own, abs(wrapped(value - best)) * ARCSEC, value))
    print(f"propagate(method='secular') vs secular DOP853 rtol 1e-12 at {Y:g} yr: "
          f"{abs(wrapped(value - secular_best)) * ARCSEC:.2e} arcsec")
    print(
        f"\nover {Y:g} yr; error at {S:g} yr vs {peer_name} 1e-15; 'spread' = splitting step vs step/2, "
        f"secular vs the first splitting row; peer cost = CPU s per year at {S:g} yr x {Y:g}"
    )
    print(
        f"  {'method':38s} {'err@peer (as)':>13s} {'precession (as)':>16s} {'spread (as)':>11s} "
        f"{'CPU s':>9s} {'peer tol':>8s} {'peer CPU s':>10s} {'ratio':>8s}"
    )
    for name, err, t_own, spread, value in rows:
        per_year, key = matched(err)
        peer_cost = per_year * Y
        print(
            f"  {name:38s} {err:13.2e} {wrapped(value - h0) * ARCSEC:16.3f} {spread:11.2e} {t_own:9.2e} "
            f"{key:8.0e} {peer_cost:10.2f} {peer_cost / t_own:8.1f}"
        )


if __name__ == "__main__":
    main()
