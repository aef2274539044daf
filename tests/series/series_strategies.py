"""Random Poisson series for the tests: seeded numpy generators and hypothesis strategies."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from hypothesis import strategies as st

from andoyer.series import PoissonRing, PoissonSeries

SAM_RING = PoissonRing(["l", "g"], ["L", "G"], ["beta", "s", "a"], relations={"beta": "1 - s**2"})
PLAIN_RING = PoissonRing(["x", "y"], ["X", "Y"], ["c"])
POLY_RING = PoissonRing(["t"], ["q", "p", "T"], pairs=[("q", "p"), ("t", "T")])


def random_series(
    ring: PoissonRing,
    rng: np.random.Generator,
    *,
    nterms: int = 6,
    max_harmonic: int = 3,
    max_degree: int = 3,
    negative: bool = True,
) -> PoissonSeries:
    """A random real series: rational coefficients, Laurent monomials, cos/sin terms."""
    terms = []
    low = -1 if negative else 0
    for _ in range(nterms):
        num = int(rng.integers(-9, 10)) or 1
        den = int(rng.integers(1, 7))
        exps = []
        for name in ring.poly_names:
            lo = 0 if name in ring.relations else low
            exps.append(int(rng.integers(lo, max_degree + 1)))
        k = [int(rng.integers(-max_harmonic, max_harmonic + 1)) for _ in ring.angles]
        kind = "cos" if rng.random() < 0.5 else "sin"
        terms.append((Fraction(num, den), exps, kind, k))
    return ring.from_terms(terms)


def series_strategy(ring: PoissonRing, max_terms: int = 4) -> st.SearchStrategy[PoissonSeries]:
    """Hypothesis strategy for small random series of ``ring``."""
    coeff = st.fractions(min_value=-20, max_value=20, max_denominator=12)
    exps = st.tuples(*(st.integers(0 if n in ring.relations else -2, 3) for n in ring.poly_names))
    harm = st.tuples(*(st.integers(-3, 3) for _ in ring.angles))
    term = st.tuples(coeff, exps, st.sampled_from(["cos", "sin"]), harm)
    return st.lists(term, max_size=max_terms).map(ring.from_terms)
