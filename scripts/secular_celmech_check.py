"""Cross-check the secular model's Hamiltonian against celmech's independent expansion (optional).

celmech (Hadden & Tamayo 2022, AJ 164, 179; ``pip install celmech``; GPL, so not a dependency
of andoyer) builds the secular Hamiltonian from its own literal expansion of the disturbing
function (its ``disturbing_function`` module) and integrates it with its own integrator
(``SecularSystemSimulation``). Started from the same mean elements (the shipped
``data/secular_model.json``, invariable frame), its frequencies against andoyer's, both
measured by the same FMFT (:mod:`andoyer.planetary.orbits.frequencies`), compare the two
expansions:

* ``--first-order --model FILE``: both models without second-order terms (andoyer's made by
  ``scripts/make_secular_model.py --second-order "" --out FILE``). Measured (2026-11-28, 1.02 Myr
  from the same mean elements, no relativity on either side): the trajectories agree to 3×10⁻⁴
  in ``e e^{iϖ}`` and 2×10⁻⁴ in ``sin(i/2) e^{iΩ}``, the frequencies to 0.0006″/yr (inner
  planets) and 0.0023″/yr (``s_6``): two independent expansions of the same Hamiltonian;
* default: celmech with its 5:2 Jupiter–Saturn term (``resonances_to_include``: the 5:2 and
  its harmonics, the near-resonant ``|A_k|²`` and ``∂_Λ`` terms) against the shipped model.

It also times celmech's integrator (the side-by-side peer in ``benchmarks/RESULTS.md``).
Run in an environment with celmech:
``python3 scripts/secular_celmech_check.py [--span 2e6] [--every 250] [--first-order]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from andoyer.planetary.orbits.frequencies import fundamental_frequencies
from andoyer.planetary.orbits.laplace_lagrange import LA2004_G, LA2004_S
from andoyer.planetary.orbits.planets import PLANETS
from andoyer.planetary.orbits.secular import secular_model


def celmech_run(
    span: float, every: float, resonances: dict, order: int
) -> tuple[np.ndarray, np.ndarray, float]:
    """``z = e e^{iϖ}`` and ``ζ = sin(i/2) e^{iΩ}`` of celmech's secular simulation, and its CPU time."""
    import celmech.secular
    from celmech.poincare import Poincare, PoincareParticle
    from celmech.secular import SecularSystemSimulation

    # celmech 1.5.8's SecularSystemSimulation.integrate still calls Python 2's ``xrange``.
    celmech.secular.xrange = range

    model = secular_model()
    particles = []
    for j in range(len(PLANETS)):
        x, y, L = model.w0[j], model.w0[8 + j], model.Lambda[j]
        root = 1.0 - abs(x) ** 2 / (2 * L)
        e = np.sqrt(1.0 - root**2)
        inc = np.arccos(1.0 - abs(y) ** 2 / (2 * L * root))
        particles.append(
            PoincareParticle(
                m=model.gm[j], Mstar=model.sun, a=model.a[j], l=0.0, e=e, pomega=np.angle(x), inc=inc,
                Omega=np.angle(y), coordinates="canonical heliocentric", G=1.0,
            )
        )  # fmt: skip
    state = Poincare(G=1.0, poincareparticles=particles, coordinates="canonical heliocentric")
    sim = SecularSystemSimulation(
        state, dtFraction=1.0 / 20.0, max_order=order, resonances_to_include=resonances
    )
    # Whole steps per sample: its integrate() rounds the number of steps up and cannot go back.
    per = int(np.ceil(every / sim.dt))
    sim.dt = every / per
    count = int(span / every)
    z = np.empty((8, count), complex)
    zeta = np.empty_like(z)
    start = time.process_time()
    for k in range(count):
        if k:
            sim.integrate(sim.t + every - 0.5 * sim.dt)
        for j, p in enumerate(sim.state.particles[1:]):
            z[j, k] = p.e * np.exp(1j * p.pomega)
            zeta[j, k] = np.sin(p.inc / 2) * np.exp(1j * p.Omega)
    return z, zeta, time.process_time() - start


def andoyer_run(span: float, every: float, path: str | None) -> tuple[np.ndarray, np.ndarray]:
    """A model's ``e e^{iϖ}`` and ``sin(i/2) e^{iΩ}`` over the same times, its polynomial only.

    Relativity, which celmech's secular simulation leaves out, and the pruning are left out here.
    """
    import json
    from importlib import resources

    from andoyer.planetary.orbits.secular_flow import FlowTerms, default_step, integrate, lawson_matrices

    model = secular_model(path)
    if path is None:
        data = resources.files("andoyer.planetary.orbits").joinpath("data/secular_model.json")
        text = data.read_text("utf-8")
    else:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    raw = json.loads(text)["terms"]
    exponents = np.zeros((len(raw), 32), dtype=np.int64)
    coefficients = np.array([re for _, re, _ in raw])
    for row, (factors, _, _) in enumerate(raw):
        for var, power in factors:
            exponents[row, var] = power
    terms = FlowTerms.from_polynomial(exponents, coefficients, 8)
    per = int(np.ceil(every / default_step(terms.linear, 1.0 / 20.0)))
    count = int(span / every)
    tableau = lawson_matrices(terms.linear, every / per)
    w = model.w0.copy()
    keep = np.arange(16)
    samples = np.empty((count, 16), complex)
    out, out_d = np.empty((per + 1, 16), complex), np.empty((per + 1, 16), complex)
    for k in range(count):
        samples[k] = w
        integrate(
            w, per, every / per, *tableau, *terms.arrays(), terms.linear, keep, out, out_d, np.zeros(16)
        )
    x, y, L = samples[:, :8], samples[:, 8:], model.Lambda[None, :]
    root = 1.0 - np.abs(x) ** 2 / (2 * L)
    e = np.sqrt(1.0 - root**2)
    cos_i = 1.0 - np.abs(y) ** 2 / (2 * L * root)
    return (e * np.exp(1j * np.angle(x))).T, (np.sqrt((1 - cos_i) / 2) * np.exp(1j * np.angle(y))).T


def main() -> None:
    """Run both, analyse both, print the table (″/yr)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--span", type=float, default=1.024e6)
    parser.add_argument("--every", type=float, default=250.0)
    parser.add_argument("--order", type=int, default=4)
    parser.add_argument("--first-order", action="store_true")
    parser.add_argument("--model", help="andoyer's model file (default: the shipped one)")
    args = parser.parse_args()
    resonances = {} if args.first_order else {(5, 6): [(5, 3)]}
    zc, zetac, seconds = celmech_run(args.span, args.every, resonances, args.order)
    print(
        f"celmech: {args.span / 1e6:g} Myr in {seconds:.1f} CPU s ({seconds / args.span * 1e9:.0f} s per Gyr)"
    )
    gc, sc = fundamental_frequencies(zc, zetac, args.every, LA2004_G, LA2004_S)
    za, zetaa = andoyer_run(args.span, args.every, args.model)
    ga, sa = fundamental_frequencies(za, zetaa, args.every, LA2004_G, LA2004_S)
    for j in range(8):
        dz, dzeta = np.abs(zc[j] - za[j]).max(), np.abs(zetac[j] - zetaa[j]).max()
        print(f"{PLANETS[j]:8s} max |Δz| {dz:.1e} (|z| ≤ {np.abs(za[j]).max():.3f}), max |Δζ| {dzeta:.1e}")
    for key, a, c in (("g", ga, gc), ("s", sa, sc)):
        for j in range(8):
            print(f"{key}{j + 1} andoyer {a[j]:10.4f} celmech {c[j]:10.4f} diff {a[j] - c[j]:+8.4f}")


if __name__ == "__main__":
    main()
