"""The N-body orbit's step and integrator against its cost: what a cheaper run would give up.

Issue 25 item 1 asks for the N-body orbit at one fifth of the CPU time per Myr at the same
accuracy. The run is REBOUND's WHFast step and nothing else (sampling every 100 years and the
corrector applied at each sample are below 1 % of it; GR adds 2-3 %), so the only levers are a
longer step or a higher-order map. This script measures them side by side on the source's own
system (``nbody.planet_data``: the Sun and eight planets, REBOUNDx ``gr_potential``), each
against the source's setting (WHFast, Jacobi coordinates, order-17 corrector, a 4-day step), over
``--span`` years backwards from J2000, sampled every 100 years:

* the CPU-time ratio (4-day run / variant; ``time.process_time``, one process, one after the
  other), and
* the largest distance of each variant's osculating orbit normal (arcsec) and eccentricity vector
  from the 4-day run's, for Mercury, the Earth and Mars.

Variants: ``KIND:STEP_DAYS:OPTIONS`` with KIND ``whfast`` (OPTIONS e.g.
``kernel=MODIFIEDKICK,corrector2=1``) or ``saba`` (OPTIONS the SABA type, e.g. ``10_6_4``:
Laskar & Robutel 2001's SABA(10,6,4), Blanes et al. 2013).

Run: ``python3 benchmarks/bench_nbody_step.py --span -20000`` (about a minute), or
``python3 benchmarks/bench_nbody_step.py --span -1000000 whfast:16: whfast:20:`` (minutes).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

from andoyer.planetary.orbits.nbody import C_AU_PER_YEAR, _vectors, planet_data

SAMPLE_YEARS = 100.0
DEFAULT_VARIANTS = (
    "whfast:8:",
    "whfast:16:",
    "whfast:20:",
    "whfast:16:kernel=MODIFIEDKICK,corrector2=1",
    "saba:32:10_6_4",
    "saba:48:10_6_4",
    "saba:64:10_6_4",
)


def run(span: float, kind: str, step_days: float, options: str) -> tuple[float, np.ndarray, np.ndarray]:
    """CPU seconds, and the normals and eccentricity vectors (samples, 8, 3) of one variant."""
    import rebound
    import reboundx

    data = planet_data()
    sim = rebound.Simulation()
    sim.G = 1.0
    rows = np.concatenate([np.zeros((1, 6)), np.concatenate([data.position, data.velocity], axis=1)])
    for m, r in zip([data.sun_gm, *data.gm], rows, strict=True):
        sim.add(m=m, x=r[0], y=r[1], z=r[2], vx=r[3], vy=r[4], vz=r[5])
    sim.move_to_com()
    steps = max(1, round(SAMPLE_YEARS * 365.25 / step_days))
    if kind == "whfast":
        sim.integrator = "whfast"
        sim.integrator.corrector = 17
        sim.integrator.safe_mode = 0
        for pair in filter(None, options.split(",")):
            key, value = pair.split("=")
            setattr(sim.integrator, key, int(value) if value.isdigit() else value)
    elif kind == "saba":
        sim.integrator = "saba"
        sim.integrator.type = options
        sim.integrator.safe_mode = 0
    else:
        raise SystemExit(f"expected a variant kind whfast or saba, got {kind!r}")
    sim.dt = np.sign(span) * SAMPLE_YEARS / steps
    extras = reboundx.Extras(sim)
    force = extras.load_force("gr_potential")
    extras.add_force(force)
    force.params["c"] = C_AU_PER_YEAR
    times = np.sign(span) * np.arange(0.0, abs(span) + 1.0, SAMPLE_YEARS)
    states = np.empty((times.size, 9, 6))
    buf = np.empty((9, 6))
    start = time.process_time()
    for k, t in enumerate(times):
        if t != 0.0:
            sim.integrate(float(t) - 0.5 * sim.dt, exact_finish_time=0)
        sim.serialize_particle_data(xyzvxvyvz=buf)
        states[k] = buf
    seconds = time.process_time() - start
    normal, ecc = _vectors(states)
    return seconds, normal, ecc


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--span", type=float, default=-20000.0, help="years from J2000 (default -20000)")
    parser.add_argument("variants", nargs="*", default=list(DEFAULT_VARIANTS), help="KIND:STEP_DAYS:OPTIONS")
    args = parser.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)  # REBOUND's Kepler-solver note at long steps
    ref_seconds, ref_normal, ref_ecc = run(args.span, "whfast", 4.0, "")
    print(
        f"span {args.span:g} yr; WHFast corrector 17, 4 d (the source): {ref_seconds:.2f} CPU s "
        f"({ref_seconds / abs(args.span) * 1e6:.0f} s/Myr)"
    )
    print(f"{'variant':40s} {'CPU s':>7s} {'ratio':>6s}   normal (arcsec) Me / E / M      |Δe| Me / E / M")
    for variant in args.variants:
        kind, step, options = variant.split(":")
        seconds, normal, ecc = run(args.span, kind, float(step), options)
        cross = np.linalg.norm(np.cross(normal, ref_normal), axis=-1)
        angle = np.degrees(np.arctan2(cross, np.sum(normal * ref_normal, axis=-1))) * 3600.0
        de = np.linalg.norm(ecc - ref_ecc, axis=-1)
        a, e = angle.max(axis=0), de.max(axis=0)
        print(
            f"{variant:40s} {seconds:7.2f} {ref_seconds / seconds:6.2f}   "
            f"{a[0]:8.2g} {a[2]:8.2g} {a[3]:8.2g}   {e[0]:8.2g} {e[2]:8.2g} {e[3]:8.2g}"
        )


if __name__ == "__main__":
    main()
