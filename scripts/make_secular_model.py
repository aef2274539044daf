"""Write ``src/andoyer/planetary/orbits/data/secular_model.json``: the secular model's Hamiltonian.

Two steps, both from the package's own code and data:

1. the mean elements at J2000 (:func:`andoyer.planetary.orbits.mean_elements.mean_elements`):
   the N-body solution of :mod:`andoyer.planetary.orbits.nbody` (DE421's states at J2000,
   DE440 masses, REBOUND WHFast, GR through REBOUNDx) over ±5 kyr, every 1/16 yr, averaged
   by a local polynomial fit, in the invariable plane: ``Λ_j``, ``a_j``, the mean motions
   ``n_j``, ``x_j``, ``y_j`` and the rotation from the J2000 ecliptic;
2. the polynomial secular Hamiltonian
   (:func:`andoyer.planetary.orbits.disturbing.secular_hamiltonian`): every pair's averaged
   interaction to degree 4 in eccentricities and inclinations, and the second-order terms of
   Jupiter and Saturn (all harmonics ``|k| ≤ 16``, the 5:2 near-resonance among them) to
   degree 6.

About 5 minutes on one core. Run from the repository root:
``python3 scripts/make_secular_model.py [--degree 4] [--out PATH]``.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import time
from pathlib import Path

import numpy as np

from andoyer.planetary.orbits.disturbing import secular_hamiltonian
from andoyer.planetary.orbits.mean_elements import mean_elements
from andoyer.planetary.orbits.planets import PLANETS, planet_data

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "src" / "andoyer" / "planetary" / "orbits" / "data" / "secular_model.json"


def main() -> None:
    """Measure, expand, write."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--degree", type=int, default=4, help="degree of the first-order expansion")
    parser.add_argument("--degree2", type=int, default=6, help="degree of the second-order terms")
    parser.add_argument("--second-order", default="4-5", help="pairs with second-order terms, e.g. 4-5,5-6")
    parser.add_argument("--max-harmonic", type=int, default=16)
    parser.add_argument("--high-degree", default="", help="pairs expanded to degree 6, e.g. 4-5")
    parser.add_argument("--window", type=float, default=5000.0, help="half-width of the mean-element fit, yr")
    parser.add_argument("--out", default=str(OUT))
    args = parser.parse_args()
    pairs = tuple(tuple(int(i) for i in p.split("-")) for p in args.second_order.split(",") if p)
    high = tuple(tuple(int(i) for i in p.split("-")) for p in args.high_degree.split(",") if p)
    start = time.time()
    mean = mean_elements(window=args.window)
    print(f"mean elements: {time.time() - start:.0f} s", flush=True)
    exponents, coefficients = secular_hamiltonian(
        mean.sun, mean.gm, mean.a, mean.Lambda, mean.n, degree=args.degree,
        second_order_pairs=pairs, degree2=args.degree2, max_harmonic=args.max_harmonic,
        high_degree_pairs=high,
        progress=lambda msg: print(f"{msg}: {time.time() - start:.0f} s", flush=True),
    )  # fmt: skip
    terms = []
    for m, c in zip(exponents, coefficients, strict=True):
        nz = np.nonzero(m)[0]
        terms.append([[[int(v), int(m[v])] for v in nz], float(c.real), float(c.imag)])
    planets_digest = planet_data().digest
    document = {
        "description": (
            "The secular Hamiltonian of the eight planets in Poincare variables (x, y: complex; "
            "variables 0-7 x, 8-15 conj(x), 16-23 y, 24-31 conj(y), Sun outwards) and the mean "
            "elements at J2000 in the invariable frame. Written by scripts/make_secular_model.py."
        ),
        "units": {"length": "au", "time": "Julian year", "gm": "au^3/yr^2", "angles": "rad"},
        "planets": list(PLANETS),
        "planets_j2000_sha256": planets_digest,
        "settings": {
            "degree": args.degree,
            "degree2": args.degree2,
            "second_order_pairs": [list(p) for p in pairs],
            "max_harmonic": args.max_harmonic,
            "high_degree_pairs": [list(p) for p in high],
            "window_years": args.window,
        },
        "sun_gm": mean.sun,
        "gm": mean.gm.tolist(),
        "Lambda": mean.Lambda.tolist(),
        "a": mean.a.tolist(),
        "n": mean.n.tolist(),
        "x0": [[float(z.real), float(z.imag)] for z in mean.x],
        "y0": [[float(z.real), float(z.imag)] for z in mean.y],
        "rotation": mean.rotation.tolist(),
        "terms": terms,
    }
    text = json.dumps(document, indent=None, separators=(",", ":"))
    Path(args.out).write_text(text + "\n", encoding="utf-8")
    print(f"wrote {args.out}: {len(terms)} terms, sha256 {hashlib.sha256(text.encode()).hexdigest()[:16]}")


if __name__ == "__main__":
    main()
