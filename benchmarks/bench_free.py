"""Throughput and accuracy of the exact torque-free solution against numerical integration.

Side by side, in one process on one core:

* ``andoyer.free`` closed form: body angular momentum only, and momentum + attitude;
* scipy ``solve_ivp`` DOP853 at ``rtol = atol = 1e-12`` on the Euler equations with the
  quaternion kinematics (one call per body, dense output at the epochs), on a smaller
  sample, scaled to pairs per second;
* heyoka's Taylor integrator, when ``heyoka`` is importable (optional).

Workload: triaxial bodies (moments uniform in [1, 2], triangle inequality, SAM and LAM
mixed), random states and attitudes, epochs uniform in [0, 100 periods] of each body.
Throughput counts (body, epoch) pairs per second including the per-body set-up.
Accuracy is measured on a few bodies against the 57-digit Taylor-series reference of
``tests/free/free_reference.py`` at 100 periods.

The "1 epoch per body" rows build the solution for every body and evaluate it once (at
the body's last epoch, up to 100 periods), against heyoka's batch mode integrating each
body from 0 to that epoch: the set-up is not amortised.  With numba installed
:class:`andoyer.free.FreeMotion` builds and evaluates the triaxial solution in compiled
loops; ``ANDOYER_NUMBA=0`` in the environment measures the numpy path.

``--epochs``: 10 bodies × 10⁵ epochs over 100 periods (issue 17 item 1): the periodic
representation chosen automatically, the direct path, heyoka's ``propagate_grid`` at its
tightest tolerance, and a numba loop of one ``sin`` and one ``cos`` per pair.
``--setup``: set-up per body at 10⁴, 10⁵, 10⁶ bodies (item 3).  Both run each
measurement ``--repeat`` times interleaved and give the best and the median.  ``--epochs
--fresh`` times each run in fresh processes of its own instead (interleaved rounds): in one
process, whether a run's large outputs fault in fresh pages depends on what the allocator
kept from the run before it (measured: the periodic momentum 5.7 ms after itself, 8.5 ms
after heyoka's attitude run, 1287 page faults a call), so the in-process figures depend on
the order of the runs.

Run: ``python3 benchmarks/bench_free.py [--quick] [--epochs [--fresh] | --setup | --breakdown]``
(pins numpy to one thread; rates are per CPU second of the timed process, so they do not depend on other
load on the machine).
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import math  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "tests" / "free"))

from free_reference import TaylorReference, angle_between, relative_error  # noqa: E402

from andoyer._jit import NUMBA  # noqa: E402
from andoyer.free import FreeMotion  # noqa: E402

try:  # optional peer
    import heyoka as hy
except ImportError:  # pragma: no cover - optional
    hy = None


def workload(n_bodies, n_epochs, seed=0):
    rng = np.random.default_rng(seed)
    moments = rng.uniform(1.0, 2.0, (n_bodies, 3))
    moments[:, 2] = np.minimum(moments[:, 2], moments[:, 0] + moments[:, 1])
    m0 = rng.normal(size=(n_bodies, 3))
    q0 = Rotation.random(n_bodies, random_state=seed).as_quat()
    period = FreeMotion(moments, m0).periods.period
    t = rng.uniform(0.0, 100.0, (n_bodies, n_epochs)) * period[:, None]
    t.sort(axis=1)
    return moments, m0, q0, t


def rhs(_t, y, w, c):
    m1, m2, m3, x, yy, z, s = y
    wx, wy, wz = m1 * w[0], m2 * w[1], m3 * w[2]
    return [
        c[0] * m2 * m3,
        c[1] * m3 * m1,
        c[2] * m1 * m2,
        0.5 * (s * wx + yy * wz - z * wy),
        0.5 * (s * wy + z * wx - x * wz),
        0.5 * (s * wz + x * wy - yy * wx),
        -0.5 * (x * wx + yy * wy + z * wz),
    ]


def dop853(moments, m0, q0, t):
    out_m = np.empty((*t.shape, 3))
    out_q = np.empty((*t.shape, 4))
    for i in range(moments.shape[0]):
        w = 1.0 / moments[i]
        c = (w[2] - w[1], w[0] - w[2], w[1] - w[0])
        sol = solve_ivp(rhs, (0.0, t[i, -1]), np.concatenate([m0[i], q0[i]]), method="DOP853",
                        t_eval=t[i], rtol=1e-12, atol=1e-12, args=(w, c))
        out_m[i] = sol.y[:3].T
        out_q[i] = sol.y[3:].T
    return out_m, out_q


def heyoka_system():  # pragma: no cover - optional
    """Euler's equations with the quaternion kinematics as heyoka expressions (pars: 1/I)."""
    x = hy.make_vars("m1", "m2", "m3", "qx", "qy", "qz", "qw")
    w1, w2, w3 = (hy.par[i] for i in range(3))
    m1, m2, m3, qx, qy, qz, qw = x
    wx, wy, wz = m1 * w1, m2 * w2, m3 * w3
    return [
        (m1, (w3 - w2) * m2 * m3),
        (m2, (w1 - w3) * m3 * m1),
        (m3, (w2 - w1) * m1 * m2),
        (qx, 0.5 * (qw * wx + qy * wz - qz * wy)),
        (qy, 0.5 * (qw * wy + qz * wx - qx * wz)),
        (qz, 0.5 * (qw * wz + qx * wy - qy * wx)),
        (qw, -0.5 * (qx * wx + qy * wy + qz * wz)),
    ]


def heyoka_integrator():  # pragma: no cover - optional
    """heyoka's adaptive Taylor integrator (scalar mode, compiled once)."""
    return hy.taylor_adaptive(heyoka_system(), [0.0] * 7, tol=1e-15, pars=[1.0, 1.0, 1.0])


def heyoka_batch_integrator():  # pragma: no cover - optional
    """heyoka's batch mode: ``recommended_simd_size()`` bodies integrated in SIMD lanes."""
    size = hy.recommended_simd_size()
    return hy.taylor_adaptive_batch(
        heyoka_system(), np.zeros((7, size)), tol=1e-15, pars=np.ones((3, size))
    )


def heyoka_batch_run(ta, moments, m0, q0, t):  # pragma: no cover - optional
    """Integrate ``len(moments)`` bodies (a multiple of the batch size) to their epochs ``t``."""
    size = ta.batch_size
    out_m = np.empty((*t.shape, 3))
    out_q = np.empty((*t.shape, 4))
    for i in range(0, moments.shape[0], size):
        lanes = slice(i, i + size)
        ta.set_time(np.zeros(size))
        ta.state[:] = np.concatenate([m0[lanes], q0[lanes]], axis=1).T
        ta.pars[:] = (1.0 / moments[lanes]).T
        grid = np.concatenate([np.zeros((1, size)), t[lanes].T])
        res = ta.propagate_grid(grid)[-1][1:]  # (epochs, 7, lanes)
        out_m[lanes] = np.moveaxis(res[:, :3], -1, 0)
        out_q[lanes] = np.moveaxis(res[:, 3:], -1, 0)
    return out_m, out_q


def heyoka_run(ta, moments, m0, q0, t):  # pragma: no cover - optional
    out_m = np.empty((*t.shape, 3))
    out_q = np.empty((*t.shape, 4))
    for i in range(moments.shape[0]):
        ta.time = 0.0
        ta.state[:] = np.concatenate([m0[i], q0[i]])
        ta.pars[:] = 1.0 / moments[i]
        res = ta.propagate_grid(np.concatenate([[0.0], t[i]]))[-1][1:]
        out_m[i] = res[:, :3]
        out_q[i] = res[:, 3:]
    return out_m, out_q


def angle(qa, qb):
    """Rotation angle between two arrays of (not necessarily unit) quaternions."""
    rel = (Rotation.from_quat(qa.reshape(-1, 4)).inv() * Rotation.from_quat(qb.reshape(-1, 4)))
    q = rel.as_quat()
    return 2.0 * np.arctan2(np.linalg.norm(q[:, :3], axis=-1), np.abs(q[:, 3]))


def timed(fn, *args, repeat=3):
    """Best CPU time of ``repeat`` runs (process time: one core, robust to other load)."""
    best = np.inf
    out = None
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn(*args)
        best = min(best, time.process_time() - t0)
    return best, out


def heyoka_momentum_integrator(tol):  # pragma: no cover - optional
    """Euler's equations alone (3 variables; pars: 1/I)."""
    return hy.taylor_adaptive(heyoka_system()[:3], [0.0] * 3, tol=tol, pars=[1.0, 1.0, 1.0])


def sincos_yardstick():
    """A compiled loop evaluating one ``sin`` and one ``cos`` per (body, epoch) pair (numba)."""
    import numba

    @numba.njit(cache=True)
    def loop(w, t, out):
        for i in range(t.shape[0]):
            for e in range(t.shape[1]):
                x = w[i] * t[i, e]
                out[i, e, 0] = math.sin(x)
                out[i, e, 1] = math.cos(x)

    return loop


SINCOS = "numba loop: one sin + one cos"
HY_M = "heyoka propagate_grid, momentum"
HY_F = "heyoka propagate_grid, momentum + attitude"


def epoch_runs(n_bodies, n_epochs, only=None):
    """The timed calls of :func:`many_epochs` by name (only ``only`` where given: no other set-up)."""
    moments, m0, q0, t = workload(n_bodies, n_epochs, seed=1)
    big = (moments[:, None], m0[:, None], q0[:, None])

    def closed(mode, attitude):
        def run():
            fm = FreeMotion(*big) if attitude else FreeMotion(*big[:2])
            fm.periodic_epochs = 0.0 if mode == "periodic" else np.inf
            return fm.propagate(t) if attitude else fm.momentum(t)
        return run

    def wanted(name):
        return only is None or name == only

    # "periodic": the piecewise representation forced; "direct": the per-epoch theta series
    runs = {f"{mode}, {what}": closed(mode, what == "momentum + attitude")
            for what in ("momentum", "momentum + attitude") for mode in ("periodic", "direct")}
    runs = {k: v for k, v in runs.items() if wanted(k)}
    if NUMBA and wanted(SINCOS):
        loop = sincos_yardstick()
        out = np.empty((*t.shape, 2))
        w = 1.0 / FreeMotion(moments, m0).periods.period
        loop(w, t[:1], out[:1])  # compile
        runs[SINCOS] = lambda: loop(w, t, out)
    tol = np.finfo(float).eps
    if hy is not None and wanted(HY_M):  # pragma: no cover - optional
        ta_m = heyoka_momentum_integrator(tol)

        def hy_momentum():
            out_m = np.empty((*t.shape, 3))
            for i in range(n_bodies):
                ta_m.time = 0.0
                ta_m.state[:] = m0[i]
                ta_m.pars[:] = 1.0 / moments[i]
                out_m[i] = ta_m.propagate_grid(np.concatenate([[0.0], t[i]]))[-1][1:]
            return out_m

        runs[HY_M] = hy_momentum
    if hy is not None and wanted(HY_F):  # pragma: no cover - optional
        ta_f = hy.taylor_adaptive(heyoka_system(), [0.0] * 7, tol=tol, pars=[1.0, 1.0, 1.0])
        runs[HY_F] = lambda: heyoka_run(ta_f, moments, m0, q0, t)
    return runs


def fresh_times(n_bodies, n_epochs, repeat, names):
    """CPU seconds of each run, measured in fresh processes of its own (a warm-up call, then three timed).

    The processes are interleaved by name, ``repeat`` rounds: no run sees the heap another
    left (in one process the allocator's state after one run changes whether the next
    one's large outputs fault in fresh pages, by up to 30%, depending on the order).
    """
    times = {k: [] for k in names}
    for _ in range(repeat):
        for k in names:
            cmd = [sys.executable, __file__, "--time-one", k, "--bodies", str(n_bodies), "--epochs-per-body",
                   str(n_epochs)]
            res = subprocess.run(cmd, capture_output=True, text=True, check=True)
            times[k] += [float(x) for x in res.stdout.split()]
    return times


def time_one(name, n_bodies, n_epochs, calls=3):
    """Print the CPU seconds of ``calls`` calls of run ``name`` after a warm-up call (:func:`fresh_times`)."""
    fn = epoch_runs(n_bodies, n_epochs, only=name)[name]
    fn()
    for _ in range(calls):
        t0 = time.process_time()
        fn()
        print(time.process_time() - t0)


def many_epochs(n_bodies, n_epochs, repeat, fresh=False):
    """Issue 17 item 1: a few bodies, many epochs each, over 100 periods of m(t)."""
    moments, m0, q0, t = workload(n_bodies, n_epochs, seed=1)
    pairs = t.size
    runs = epoch_runs(n_bodies, n_epochs)
    if fresh:
        times = fresh_times(n_bodies, n_epochs, repeat, list(runs))
    else:
        times = {k: [] for k in runs}
        for _ in range(repeat):  # interleaved: the machine is shared
            for k, fn in runs.items():
                t0 = time.process_time()
                fn()
                times[k].append(time.process_time() - t0)
    tol = np.finfo(float).eps
    if hy is not None:  # pragma: no cover - optional
        ta_f = hy.taylor_adaptive(heyoka_system(), [0.0] * 7, tol=tol, pars=[1.0, 1.0, 1.0])
    # accuracy at 100 periods (2 bodies) against the Taylor reference
    errs = {}
    for i in range(2):
        t_end = 100.0 * float(FreeMotion(moments[i], m0[i]).periods.period)
        mr, qr = TaylorReference(moments[i], m0[i], q0[i]).advance_to(t_end)
        for mode, thresh in (("periodic", 0.0), ("direct", np.inf)):
            fm = FreeMotion(moments[i], m0[i], q0[i])
            fm.periodic_epochs = thresh
            m, q = fm.propagate(t_end)
            e = errs.setdefault(mode, [0.0, 0.0])
            e[0], e[1] = max(e[0], relative_error(mr, m)), max(e[1], angle_between(qr, q))
        if hy is not None:  # pragma: no cover - optional
            mh, qh = heyoka_run(ta_f, moments[i : i + 1], m0[i : i + 1], q0[i : i + 1], np.array([[t_end]]))
            e = errs.setdefault("heyoka", [0.0, 0.0])
            e[0] = max(e[0], relative_error(mr, mh[0, 0]))
            e[1] = max(e[1], angle_between(qr, qh[0, 0] / np.linalg.norm(qh[0, 0])))
    how = ("each in fresh processes of its own (a warm-up call, then 3 timed), processes interleaved" if fresh
           else "interleaved in this process")
    print(f"many epochs per body: {n_bodies} bodies x {n_epochs} epochs in [0, 100 periods], {repeat} runs"
          f" {how} (CPU time, one core); pairs/s best and median")
    print(f"{'method':46s} {'best':>10s} {'median':>10s}")
    rate = {}
    for k, ts in times.items():
        rate[k] = pairs / min(ts), pairs / float(np.median(ts))
        print(f"{k:46s} {rate[k][0]:10.3e} {rate[k][1]:10.3e}")
    for what in ("momentum", "momentum + attitude"):
        p, d = rate[f"periodic, {what}"], rate[f"direct, {what}"]
        line = f"{what}: periodic / direct {p[0] / d[0]:.1f}x (median {p[1] / d[1]:.1f}x)"
        if HY_M in rate and HY_F in rate:  # pragma: no cover - optional
            h = rate[HY_M if what == "momentum" else HY_F]
            line += f"; periodic / heyoka {p[0] / h[0]:.1f}x (median {p[1] / h[1]:.1f}x)"
        if SINCOS in rate:
            y = rate[SINCOS]
            line += f"; periodic / sin+cos loop {p[0] / y[0]:.2f}x (median {p[1] / y[1]:.2f}x)"
        print(line)
    for k, (em, eq) in errs.items():
        print(f"error at 100 periods vs the 57-digit reference, {k}: |dm|/|m| {em:.1e}, attitude {eq:.1e}")
    print(f"heyoka at tol = {tol:.1e} (its tightest in double): it cannot reach 1e-14 over 100 periods")
    auto = "periodic" if n_epochs >= FreeMotion.periodic_epochs else "direct"
    print(f"FreeMotion's automatic choice at {n_epochs} epochs per body: {auto}"
          f" (FreeMotion.periodic_epochs = {FreeMotion.periodic_epochs:g}); build included in the rates")


def setup_scaling(sizes, repeat):
    """Issue 17 item 3: set-up cost per body against the number of bodies."""
    times = {n: [] for n in sizes}
    data = {n: workload(n, 1, seed=2)[:3] for n in sizes}
    for _ in range(repeat):
        for n in sizes:
            t0 = time.process_time()
            FreeMotion(*data[n])
            times[n].append((time.process_time() - t0) / n)
    print(f"set-up per body (FreeMotion(moments, m0, q0)), {repeat} runs interleaved, compiled: {NUMBA}")
    for n in sizes:
        best, med = min(times[n]) * 1e6, np.median(times[n]) * 1e6
        print(f"{n:9d} bodies: best {best:6.2f} us, median {med:6.2f} us,"
              f" ratio to {sizes[0]}: {min(times[n]) / min(times[sizes[0]]):.2f}x")


def breakdown(n_bodies, n_epochs, repeat):
    """Issue 25 item 2: where the time of ``n_bodies`` x ``n_epochs`` with the set-up included goes.

    The set-up alone, the set-up with the periodic representation built (what the many-epoch
    path would pay before its first epoch), the direct evaluation (the automatic choice below
    :attr:`FreeMotion.periodic_epochs`) with and without the attitude, and the numba loop of
    one ``sin`` and one ``cos`` per pair as the machine's yardstick, interleaved in this process.
    """
    moments, m0, q0, t = workload(n_bodies, n_epochs)
    big = (moments[:, None], m0[:, None], q0[:, None])

    def built():
        fm = FreeMotion(*big)
        fm._periodic_groups(True)

    runs = {
        "momentum + attitude (set-up included)": lambda: FreeMotion(*big).propagate(t),
        "momentum (set-up included)": lambda: FreeMotion(*big[:2]).momentum(t),
        "set-up alone (with q0)": lambda: FreeMotion(*big),
        "set-up + periodic build (attitude)": built,
    }
    if NUMBA:
        loop = sincos_yardstick()
        out = np.empty((*t.shape, 2))
        w = 1.0 / FreeMotion(moments, m0).periods.period
        loop(w, t[:1], out[:1])  # compile
        runs[SINCOS] = lambda: loop(w, t, out)
    for fn in runs.values():
        fn()  # compile and warm
    times = {k: [] for k in runs}
    for _ in range(repeat):
        for k, fn in runs.items():
            t0 = time.process_time()
            fn()
            times[k].append(time.process_time() - t0)
    auto = "periodic" if n_epochs >= FreeMotion.periodic_epochs else "direct"
    print(f"{n_bodies} bodies x {n_epochs} sorted random epochs in [0, 100 periods], {repeat} runs"
          " interleaved"
          f" (CPU time, one core); automatic choice: {auto}")
    print(f"{'run':46s} {'best ms':>9s} {'median ms':>10s} {'pairs/s':>10s}")
    for k, ts in times.items():
        print(f"{k:46s} {min(ts) * 1e3:9.1f} {np.median(ts) * 1e3:10.1f} {t.size / min(ts):10.3e}")
    if SINCOS in times:
        for k in ("momentum + attitude (set-up included)", "momentum (set-up included)"):
            print(f"{k}: rate / sin+cos loop {min(times[SINCOS]) / min(times[k]):.3f}"
                  f" (median {np.median(times[SINCOS]) / np.median(times[k]):.3f})")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes (smoke run)")
    ap.add_argument("--epochs", action="store_true", help="many epochs per body (10 x 1e5)")
    ap.add_argument("--setup", action="store_true", help="set-up per body from 1e4 to 1e6 bodies")
    ap.add_argument("--breakdown", action="store_true",
                    help="1000 x 2000 with the set-up included: where the time goes")
    ap.add_argument("--repeat", type=int, default=5, help="interleaved runs of --epochs/--setup")
    ap.add_argument("--fresh", action="store_true",
                    help="--epochs: time each run in a fresh process of its own (interleaved)")
    ap.add_argument("--time-one", help=argparse.SUPPRESS)  # a child of --fresh: the run's name
    ap.add_argument("--bodies", type=int, default=10, help=argparse.SUPPRESS)
    ap.add_argument("--epochs-per-body", type=int, default=100_000, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.time_one:
        time_one(args.time_one, args.bodies, args.epochs_per_body)
        return
    if args.breakdown:
        breakdown(200 if args.quick else 1000, 500 if args.quick else 2000, args.repeat)
        return
    if args.epochs:
        many_epochs(10, 5000 if args.quick else 100_000, args.repeat, fresh=args.fresh)
        return
    if args.setup:
        setup_scaling((10_000, 100_000) if args.quick else (10_000, 100_000, 1_000_000), args.repeat)
        return
    nb, ne = (200, 500) if args.quick else (2000, 2000)
    nb_ivp, ne_ivp = (4, 50) if args.quick else (20, 200)
    n_ref = 1 if args.quick else 3

    moments, m0, q0, t = workload(nb, ne)
    pairs = nb * ne

    def closed_momentum():
        return FreeMotion(moments[:, None], m0[:, None]).momentum(t)

    def closed_full():
        return FreeMotion(moments[:, None], m0[:, None], q0[:, None]).propagate(t)

    def per_state():  # one epoch per body: set-up cost not amortised
        return FreeMotion(moments, m0, q0).propagate(t[:, -1])

    def per_state_momentum():
        return FreeMotion(moments, m0).momentum(t[:, -1])

    t_mom, _ = timed(closed_momentum)
    t_full, _ = timed(closed_full)
    t_one, _ = timed(per_state)
    t_one_m, _ = timed(per_state_momentum)
    t_setup, _ = timed(lambda: FreeMotion(moments, m0, q0))

    mi, m0i, q0i = moments[:nb_ivp], m0[:nb_ivp], q0[:nb_ivp]
    ti = t[:nb_ivp, :: ne // ne_ivp][:, :ne_ivp]
    t_ivp, (m_ivp, q_ivp) = timed(dop853, mi, m0i, q0i, ti, repeat=1)
    m_cf, q_cf = FreeMotion(mi[:, None], m0i[:, None], q0i[:, None]).propagate(ti)
    dm_ivp = np.max(np.linalg.norm(m_ivp - m_cf, axis=-1) / np.linalg.norm(m0i, axis=-1)[:, None])
    dq_ivp = np.max(angle(q_ivp, q_cf))
    t_hy = t_hyb = t_hyb_one = None
    ta = heyoka_integrator() if hy is not None else None
    if ta is not None:  # pragma: no cover - optional
        t_hy, _ = timed(heyoka_run, ta, mi, m0i, q0i, ti, repeat=1)
        tb = heyoka_batch_integrator()
        nb_hy = max(nb_ivp // tb.batch_size, 1) * tb.batch_size  # at least one batch (--quick: few bodies)
        mi, m0i, q0i, ti = (np.resize(a, (max(nb_hy, len(a)), *a.shape[1:])) for a in (mi, m0i, q0i, ti))
        t_hyb, (m_hb, _) = timed(heyoka_batch_run, tb, mi[:nb_hy], m0i[:nb_hy], q0i[:nb_hy],
                                  ti[:nb_hy], repeat=1)
        # one epoch per body, at the end of the span (t <= 100 periods), on more bodies
        nb_one = (min(nb, 10 * nb_ivp) // tb.batch_size) * tb.batch_size
        t_hyb_one, _ = timed(heyoka_batch_run, tb, moments[:nb_one], m0[:nb_one], q0[:nb_one],
                             t[:nb_one, -1:], repeat=1)
        m_cfb = FreeMotion(mi[:nb_hy, None], m0i[:nb_hy, None]).momentum(ti[:nb_hy])
        dm_hyb = np.max(np.linalg.norm(m_hb - m_cfb, axis=-1) / np.linalg.norm(m0i[:nb_hy], axis=-1)[:, None])

    # accuracy at 100 periods against the Taylor-series reference
    fm = FreeMotion(moments[:n_ref], m0[:n_ref], q0[:n_ref])
    err_m = err_q = ivp_m = ivp_q = hy_m = hy_q = 0.0
    for i in range(n_ref):
        t_end = 100.0 * float(fm.periods.period[i])
        ref = TaylorReference(moments[i], m0[i], q0[i])
        mr, qr = ref.advance_to(t_end)
        m, q = FreeMotion(moments[i], m0[i], q0[i]).propagate(t_end)
        err_m = max(err_m, relative_error(mr, m))
        err_q = max(err_q, angle_between(qr, q))
        mv, qv = dop853(moments[i : i + 1], m0[i : i + 1], q0[i : i + 1], np.array([[t_end]]))
        ivp_m = max(ivp_m, relative_error(mr, mv[0, 0]))
        ivp_q = max(ivp_q, angle_between(qr, qv[0, 0] / np.linalg.norm(qv[0, 0])))
        if ta is not None:  # pragma: no cover - optional
            mh, qh = heyoka_run(ta, moments[i : i + 1], m0[i : i + 1], q0[i : i + 1],
                                np.array([[t_end]]))
            hy_m = max(hy_m, relative_error(mr, mh[0, 0]))
            hy_q = max(hy_q, angle_between(qr, qh[0, 0] / np.linalg.norm(qh[0, 0])))

    rows = [
        ("closed form, momentum", pairs / t_mom, f"{err_m:.1e}", "-"),
        ("closed form, momentum + attitude", pairs / t_full, f"{err_m:.1e}", f"{err_q:.1e}"),
        ("closed form, 1 epoch per body", nb / t_one, f"{err_m:.1e}", f"{err_q:.1e}"),
        ("closed form, 1 epoch per body, momentum", nb / t_one_m, f"{err_m:.1e}", "-"),
        ("scipy DOP853 rtol=atol=1e-12", nb_ivp * ne_ivp / t_ivp, f"{ivp_m:.1e}", f"{ivp_q:.1e}"),
    ]
    if t_hy is not None:  # pragma: no cover - optional
        rows.append(("heyoka taylor_adaptive tol=1e-15", nb_ivp * ne_ivp / t_hy, f"{hy_m:.1e}",
                     f"{hy_q:.1e}"))
        rows.append((f"heyoka batch ({tb.batch_size} lanes) tol=1e-15", nb_hy * ne_ivp / t_hyb,
                     f"{hy_m:.1e}", f"{hy_q:.1e}"))
        rows.append(("heyoka batch, 1 epoch per body", nb_one / t_hyb_one, "", ""))
    print(f"workload: {nb} bodies x {ne} epochs in [0, 100 periods] (peer: {nb_ivp} x {ne_ivp});"
          f" set-up {t_setup / nb * 1e6:.1f} us/body")
    print(f"{'method':42s} {'pairs/s':>12s} {'|dm|/|m| @100T':>16s} {'attitude @100T':>15s}")
    for name, rate, em, eq in rows:
        print(f"{name:42s} {rate:12.3e} {em:>16s} {eq:>15s}")
    print(f"speed-up closed form (momentum + attitude) / DOP853: {rows[1][1] / rows[4][1]:.0f}x;"
          f" DOP853 vs closed form at the sampled epochs: |dm|/|m| {dm_ivp:.1e},"
          f" attitude {dq_ivp:.1e} rad")
    if t_hyb is not None:  # pragma: no cover - optional
        batch = nb_hy * ne_ivp / t_hyb
        print(f"closed form / heyoka batch: momentum {rows[0][1] / batch:.0f}x, momentum + attitude"
              f" {rows[1][1] / batch:.0f}x (many epochs per body); one epoch per body"
              f" {rows[2][1] / (nb_one / t_hyb_one):.0f}x; heyoka batch vs closed form at the"
              f" epochs: |dm|/|m| {dm_hyb:.1e}")
    print("rates are pairs per CPU second on one core (numpy single-threaded); compiled set-up and"
          f" evaluation (numba): {'yes' if NUMBA else 'no'}")


if __name__ == "__main__":
    main()
