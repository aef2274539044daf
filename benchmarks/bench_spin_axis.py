"""Secular spin-axis evolution: andoyer's exact-rotation composition against scipy's DOP853.

Equations (both sides): ``ṡ = α(t) (s·n(t)) (s×n(t))`` of :mod:`andoyer.planetary.spin_axis`, the Earth
with ``ψ̇ = 50.3848″/yr`` at J2000 (Sun + node-averaged Moon), started from the IAU 2006 mean pole.

* andoyer: :func:`andoyer.planetary.spin_axis.spin_axis_history` (order-8 composition of exact rotations,
  default step, compiled with numba when installed), *after a warm-up call*, including the
  orbit evaluation and the description (obliquity, p_A, e sin ϖ);
* peer: :func:`andoyer.planetary.spin_axis.history.integrate_axis_dop853` (scipy ``solve_ivp`` DOP853,
  the orbit evaluated at every right-hand-side call) on a ladder of tolerances; the peer's time
  is that of the cheapest tolerance at least as accurate as andoyer, plus the snvec-like setting
  ``rtol = atol = 1e-5`` (Zeebe & Lourens 2022 integrate with atol 1e-5).

Orbits: ``quasi`` — a 1-Myr Earth-like analytic orbit (three inclination modes and two
eccentricity modes with Laplace–Lagrange-like frequencies: cheap to evaluate, so the integrators
are what is timed); ``vondrak`` — :class:`andoyer.planetary.orbits.VondrakEcliptic` over its ±200 kyr.
Accuracy: the largest angle between the axis and a reference (andoyer at a quarter of the step,
checked against DOP853 at rtol 1e-13) over the output times.

The whole command ``andoyer obliquity earth --span -200000 200000 --step 500`` is timed as a
process (best of ``--repeats``, wall clock).

Run: ``python3 benchmarks/bench_spin_axis.py [--repeats 5]`` (numpy pinned to one thread).
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import resource  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer._jit import NUMBA  # noqa: E402
from andoyer.planetary.orbits import VondrakEcliptic  # noqa: E402
from andoyer.planetary.spin_axis import build_model, mean_pole_j2000, output_times, spin_axis_history  # noqa: E402
from andoyer.planetary.spin_axis.history import DEFAULT_STEP, integrate_axis, integrate_axis_dop853  # noqa: E402

RATE = 50.3848


class QuasiPeriodicOrbit:
    """An Earth-like orbit: p + iq = Σ a_k exp(i(g_k t + φ_k)), h + ik = Σ b_k exp(i(s_k t + χ_k)).

    Frequencies and amplitudes of the size of the Laplace–Lagrange modes of the inner planets
    (″/yr: s = −5.6, −6.6, −19.2; g = 7.5, 17.4); not a solution of the Solar System.
    """

    name = "quasi"
    span = (-2e6, 2e6)
    has_eccentricity = True
    ARC = np.pi / 648000 / 1.0
    INC = ((0.0150, -5.61, 0.3), (0.0080, -6.57, 1.9), (0.0040, -19.2, 4.0))
    ECC = ((0.0190, 7.46, 0.5), (0.0160, 17.4, 2.2))

    def _sum(self, t, modes):
        t = np.asarray(t, dtype=float)
        z = 0.0 + 0.0j
        for amp, freq, phase in modes:
            z = z + amp * np.exp(1j * (freq * self.ARC * t + phase))
        return z

    def normal(self, t):
        z = self._sum(t, self.INC) - self._sum(0.0, self.INC)  # the J2000 ecliptic at t = 0
        p, q = np.real(z), np.imag(z)
        n = np.stack([q, -p, np.ones_like(p)], axis=-1)
        return n / np.linalg.norm(n, axis=-1, keepdims=True)

    def eccentricity_vector(self, t):
        z = self._sum(t, self.ECC)
        n = self.normal(t)
        v = np.stack([np.real(z), np.imag(z), np.zeros_like(np.real(z))], axis=-1)
        return v - np.sum(v * n, -1, keepdims=True) * n  # in the orbit plane


def angle(a, b):
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), np.sum(a * b, axis=-1))


def best_cpu(fn, repeats):
    best = np.inf
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        best = min(best, time.process_time() - t0)
    return best


def compare(orbit, times, repeats):
    s0 = mean_pole_j2000()
    model = build_model(orbit, "earth", s0, RATE)
    spin_axis_history(orbit, "earth", times, precession_rate=RATE)  # warm-up (numba, erfa)
    ours_time = best_cpu(lambda: spin_axis_history(orbit, "earth", times, precession_rate=RATE), repeats)
    ours = spin_axis_history(orbit, "earth", times, precession_rate=RATE).axis
    _, fine, index = integrate_axis(orbit, model, times, s0[None, :], step=DEFAULT_STEP / 4)
    reference = fine[0, index]
    dop_ref = integrate_axis_dop853(orbit, model, times, s0, rtol=1e-13)
    err_ours = angle(ours, reference).max()
    check = angle(dop_ref, reference).max()
    print(f"  reference check: andoyer(step/4) vs DOP853 rtol 1e-13: {check:.1e} rad")
    print(f"  andoyer order 8, step {DEFAULT_STEP:g} yr: {ours_time * 1e3:.1f} ms CPU, "
          f"error {err_ours:.1e} rad")
    rows = []
    for rtol in (1e-5, 1e-7, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13):
        t0 = time.process_time()
        out = integrate_axis_dop853(orbit, model, times, s0, rtol=rtol)
        cost = time.process_time() - t0
        err = angle(out, reference).max()
        rows.append((rtol, cost, err, abs(np.linalg.norm(out, axis=-1) - 1).max()))
        print(f"  DOP853 rtol=atol={rtol:.0e}: {cost * 1e3:8.1f} ms CPU, error {err:.1e} rad, "
              f"max ||s|-1| {rows[-1][3]:.1e}, ratio {cost / ours_time:6.1f}x")
    same = [r for r in rows if r[2] <= max(err_ours, 1e-12)]
    if same:
        r = same[0]
        print(f"  => cheapest DOP853 as accurate (rtol {r[0]:.0e}): {r[1] / ours_time:.0f}x andoyer's time")
    else:
        r = rows[-1]
        print(f"  => no DOP853 tolerance reaches andoyer's accuracy; at rtol {r[0]:.0e} it is "
              f"{r[2] / max(err_ours, 1e-16):.0f}x less accurate and {r[1] / ours_time:.0f}x slower")
    snvec = rows[0]
    print(f"  => snvec-like DOP853 (1e-5): {snvec[1] / ours_time:.0f}x andoyer's time, "
          f"error {snvec[2]:.1e} rad")
    return ours_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print(f"numba: {NUMBA}")
    print("quasi-periodic Earth-like orbit, 1 Myr (-1 Myr to 0), output every 1 kyr:")
    compare(QuasiPeriodicOrbit(), output_times(-1e6, 0.0, 1000.0), args.repeats)
    print("vondrak, -200 kyr to +200 kyr, output every 1 kyr:")
    compare(VondrakEcliptic(), output_times(-2e5, 2e5, 1000.0), args.repeats)
    command = [sys.executable, "-m", "andoyer", "obliquity", "earth", "--span", "-200000", "200000",
               "--step", "500", "--format", "json", "--output", os.devnull]
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    walls, cpus = [], []
    for _ in range(args.repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(command, check=True, env=env)
        walls.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    print(f"process `andoyer obliquity earth --span -200000 200000 --step 500`: best {min(walls):.2f} s wall "
          f"(median {np.median(walls):.2f}), best {min(cpus):.2f} s CPU (median {np.median(cpus):.2f}); "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
