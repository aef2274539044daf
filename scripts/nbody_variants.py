"""Fill an N-body cache folder with a *variant* of the ``nbody`` source, to measure what it leaves out.

The cache key of :class:`andoyer.planetary.orbits.NBodyOrbit` does not know these variants, so each must
go to a folder of its own (``--cache``); ``scripts/compare_la2004.py`` then reads it through
``ANDOYER_CACHE_DIR`` (or ``--reference-cache``). Variants:

* ``moon-quadrupole``: the Earth–Moon pair seen from the Sun as a quadrupole on the Earth–Moon
  barycentre (REBOUNDx ``gravitational_harmonics``), ``J₂R² = ½ q/(1+q)² a_M² (1 + 3e_M²/2)
  (1 − 3 sin²i_M/2)``: the lunar orbit averaged over its mean anomaly and its 18.6-yr node,
  ``q = 0.0123000371`` (Moon/Earth mass ratio, JPL DE430), ``a_M = 384 399 km``,
  ``e_M = 0.0549``, ``i_M = 5.145°``; it adds ``(3/2) n J₂(R/a)² = 7.6″/cy`` to the
  barycentre's perihelion. The symmetry axis is the J2000 ecliptic pole (the lunar orbit
  precesses about the ecliptic of date, within 1.5° of it over 1 Myr): an estimate.
* ``plan94``: the planets started from ``erfa.plan94`` at J2000 (Simon et al. 1994: mean
  elements *with* their periodic perturbations, i.e. close to osculating states; the J2000
  equator turned to the ecliptic by ``ε₀``) instead of Standish's mean elements.
* ``no-gr`` and ``half-step``: ``gr=False``, ``step_days=2`` (plain settings of the source).

Several variants compose (``plan94 moon-quadrupole``).

Run: ``python3 scripts/nbody_variants.py moon-quadrupole --span -1000000 --cache /tmp/nb-moon``
(about 85 CPU s per Myr; ``half-step`` twice that).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from andoyer.planetary.orbits import nbody  # noqa: E402
from andoyer.planetary.spin_axis import EPSILON_0  # noqa: E402

MOON_MASS_RATIO = 0.0123000371  # Moon/Earth, JPL DE430 (Folkner et al. 2014)
MOON_A_KM, MOON_E, MOON_I_DEG = 384399.0, 0.0549, 5.145
AU_KM = 149597870.700


def moon_quadrupole() -> tuple[float, float]:
    """``(J₂, R)`` (R in au) of the Earth–Moon pair's averaged quadrupole, normalised to ``a_M``."""
    q = MOON_MASS_RATIO
    i = np.radians(MOON_I_DEG)
    j2 = 0.5 * q / (1 + q) ** 2 * (1 + 1.5 * MOON_E**2) * (1 - 1.5 * np.sin(i) ** 2)
    return float(j2), MOON_A_KM / AU_KM


def plan94_states() -> np.ndarray:
    """Heliocentric states (8, 6) of the planets at J2000 from ``erfa.plan94``, J2000 ecliptic, au, au/yr."""
    import erfa

    c, s = np.cos(EPSILON_0), np.sin(EPSILON_0)
    to_ecliptic = np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])
    rows = []
    for k in range(1, 9):
        position, velocity = erfa.plan94(2451545.0, 0.0, k)
        velocity_per_year = np.array(velocity) * 365.25  # au/day -> au/Julian year
        rows.append(np.concatenate([to_ecliptic @ np.array(position), to_ecliptic @ velocity_per_year]))
    return np.array(rows)


def install(variant: str) -> dict:
    """Patch ``make_simulation`` (``planetary.orbits.nbody``) for ``variant``; the NBodyOrbit options."""
    original = nbody.make_simulation
    if variant == "moon-quadrupole":
        j2, radius = moon_quadrupole()

        def make(step, gr, state=None, t=0.0):
            import reboundx

            sim, extras = original(step, gr, state, t)
            extras = extras if extras is not None else reboundx.Extras(sim)
            force = extras.load_force("gravitational_harmonics")
            extras.add_force(force)
            sim.particles[3].params["J2"] = j2  # the Earth–Moon barycentre
            sim.particles[3].params["R_eq"] = radius
            return sim, extras

        nbody.make_simulation = make
    elif variant == "plan94":
        start = np.concatenate([np.zeros((1, 6)), plan94_states()])

        def make(step, gr, state=None, t=0.0):
            if state is not None:  # resuming from the cache's last state
                return original(step, gr, state, t)
            sim, extras = original(step, gr, start, t)
            sim.move_to_com()
            return sim, extras

        nbody.make_simulation = make
    elif variant == "no-gr":
        return {"gr": False}
    elif variant == "half-step":
        return {"step_days": 2.0}
    else:
        msg = f"expected a variant among moon-quadrupole, plan94, no-gr, half-step, got {variant!r}"
        raise ValueError(msg)
    return {}


def main(argv: list[str] | None = None) -> None:
    """Integrate the variant over ``--span`` years from J2000 into ``--cache``."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("variant", nargs="+", choices=["moon-quadrupole", "plan94", "no-gr", "half-step"])
    parser.add_argument("--span", type=float, default=-1.0e6, help="years from J2000 (negative: the past)")
    parser.add_argument("--cache", required=True, help="a cache folder for this variant only")
    args = parser.parse_args(argv)
    os.environ["ANDOYER_CACHE_DIR"] = args.cache
    options = {}
    for variant in args.variant:  # several compose: each patch wraps the one before
        options.update(install(variant))
    orbit = nbody.NBodyOrbit("earth", progress=True, **options)
    orbit.normal(np.array([min(args.span, 0.0), max(args.span, 0.0)]))
    print(f"cached {' + '.join(args.variant)} to {args.span:g} years in {args.cache}")


if __name__ == "__main__":
    main()
