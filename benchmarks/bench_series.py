"""Speed of the exact Poisson-series engine against peers, measured side by side.

Run ``python benchmarks/bench_series.py [--quick]``.  Prints, for series products and Poisson
brackets with exact rational coefficients, the time per pair of real terms for

* ``andoyer.series`` (python-flint ``fmpq_mpoly`` in the exponential representation),
* a plain-sympy baseline (expressions, ``expand`` + product-to-sum ``TR8``),
* a pure-Python baseline (dict of ``(exponents, kind, harmonic) -> Fraction``), the design
  alternative to python-flint,

and the ratios, then the time of Deprit's normalisation of Lara's SAM Hamiltonian.
Every baseline result is checked equal to the engine's result before it is timed.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np
import sympy
from sympy.simplify.fu import TR8

from andoyer.series import LieTransform, PoissonRing, PoissonSeries, deprit

RING = PoissonRing(["l", "g"], ["L", "G"], ["a", "c"])


def random_series(
    rng: np.random.Generator, nterms: int, denominators: str, harmonic: int = 6
) -> PoissonSeries:
    """Sparse random series: few products merge, the worst case per pair of terms.

    ``denominators="wide"`` draws them in 1..49 (their lcm grows fast under sums);
    ``"small"`` draws 2^a 3^b as in perturbation theories.
    """
    terms = []
    while len(terms) < nterms:
        k = [int(rng.integers(-harmonic, harmonic + 1)) for _ in range(2)]
        e = [int(rng.integers(-2, 5)), int(rng.integers(-2, 5)), int(rng.integers(0, 3)), 0]
        if denominators == "wide":
            den = int(rng.integers(1, 50))
        else:
            den = 2 ** int(rng.integers(0, 6)) * 3 ** int(rng.integers(0, 3))
        coeff = Fraction(int(rng.integers(-99, 100)) or 1, den)
        terms.append((coeff, e, "cos" if rng.random() < 0.5 else "sin", k))
    return RING.from_terms(terms)


def best_time(func: Callable[[], Any], repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        best = min(best, time.perf_counter() - start)
    return best


# ---------------------------------------------------------------- plain sympy baseline
def sympy_product(a: Any, b: Any) -> Any:
    return sympy.expand(TR8(sympy.expand(a * b)))


def sympy_bracket(a: Any, b: Any, pairs: list[tuple[Any, Any]]) -> Any:
    out = sum(
        sympy.diff(a, q) * sympy.diff(b, p) - sympy.diff(a, p) * sympy.diff(b, q) for q, p in pairs
    )
    return sympy.expand(TR8(sympy.expand(out)))


# ---------------------------------------------------------------- pure Python baseline
def py_series(f: PoissonSeries) -> dict[tuple[Any, ...], Fraction]:
    return {(t.exponents, t.kind == "sin", t.harmonics): t.coeff for t in f.terms()}


def _canon(k: tuple[int, ...]) -> tuple[int, tuple[int, ...]]:
    for v in k:
        if v:
            return (1, k) if v > 0 else (-1, tuple(-x for x in k))
    return 0, k


def py_product(a: dict, b: dict) -> dict:
    """cos·cos, cos·sin, sin·sin by the product-to-sum rules, exact Fractions."""
    out: dict = {}
    half = Fraction(1, 2)
    for (ea, sa, ka), ca in a.items():
        for (eb, sb, kb), cb in b.items():
            c = ca * cb * half
            e = tuple(x + y for x, y in zip(ea, eb, strict=True))
            ks = tuple(x + y for x, y in zip(ka, kb, strict=True))
            kd = tuple(x - y for x, y in zip(ka, kb, strict=True))
            if not sa and not sb:  # cos cos = [cos(a−b) + cos(a+b)]/2
                parts = ((False, kd, c), (False, ks, c))
            elif sa and sb:  # sin sin = [cos(a−b) − cos(a+b)]/2
                parts = ((False, kd, c), (False, ks, -c))
            elif sa:  # sin a cos b = [sin(a+b) + sin(a−b)]/2
                parts = ((True, ks, c), (True, kd, c))
            else:  # cos a sin b = [sin(a+b) − sin(a−b)]/2
                parts = ((True, ks, c), (True, kd, -c))
            for sine, k, v in parts:
                sign, kk = _canon(k)
                if sine and sign == 0:
                    continue
                key = (e, sine, kk)
                out[key] = out.get(key, 0) + (v * sign if sine else v)
    return {k: v for k, v in out.items() if v}


def py_equal(d: dict, f: PoissonSeries) -> bool:
    return d == py_series(f)


def run(sizes: list[int], sympy_sizes: list[int], repeat: int, denominators: str) -> None:
    rng = np.random.default_rng(2024)
    syms = {n: sympy.Symbol(n) for n in RING.variables}
    pairs = [(syms[q], syms[p]) for q, p in RING.pairs]
    print(
        f"\nRandom sparse series in 2 angles, 2 momenta, 2 parameters; {denominators} denominators"
        "\n(µs per pair of real terms; the bracket has 4 products of derivatives)"
    )
    header = f"{'terms':>9} {'op':>8} {'andoyer':>10} {'pure-py':>10} {'sympy':>10}"
    print(header + f" {'py/andoyer':>11} {'sympy/andoyer':>14}")
    for n in sizes:
        a = random_series(rng, n, denominators)
        b = random_series(rng, n, denominators)
        na, nb = len(a), len(b)
        pairs_count = na * nb
        t_mul = best_time(lambda a=a, b=b: a * b, repeat)
        t_br = best_time(lambda a=a, b=b: a.bracket(b), repeat)
        prod = a * b
        t_py = float("nan")
        if n <= 400:
            pa, pb = py_series(a), py_series(b)
            assert py_equal(py_product(pa, pb), prod)
            t_py = best_time(lambda pa=pa, pb=pb: py_product(pa, pb), 1)
        t_sym_mul = t_sym_br = float("nan")
        if n in sympy_sizes:
            sa, sb = a.to_sympy(syms), b.to_sympy(syms)
            assert RING.from_sympy(sympy_product(sa, sb)) == prod
            assert RING.from_sympy(sympy_bracket(sa, sb, pairs)) == a.bracket(b)
            t_sym_mul = best_time(lambda sa=sa, sb=sb: sympy_product(sa, sb), 1)
            t_sym_br = best_time(lambda sa=sa, sb=sb: sympy_bracket(sa, sb, pairs), 1)
        for op, t_ours, t_p, t_s in (
            ("product", t_mul, t_py, t_sym_mul),
            ("bracket", t_br, float("nan"), t_sym_br),
        ):
            per = [1e6 * t / pairs_count for t in (t_ours, t_p, t_s)]
            print(
                f"{na:>4}x{nb:<4} {op:>8} {per[0]:>10.3f} {per[1]:>10.3f} {per[2]:>10.1f}"
                f" {t_p / t_ours:>11.1f} {t_s / t_ours:>14.0f}"
            )


SAM = PoissonRing(
    ["l", "g"], ["L", "G"], ["alpha", "beta", "s", "C"], relations={"beta": "1 - s**2"}
)
SAM_H = [SAM("G**2/(2*C) + alpha*s*G*L/C"), SAM("-alpha*L**2/(2*C)*(1 + beta*cos(2*l))")]


def run_deprit_operands(order: int, repeat: int) -> None:
    """Per-pair cost on the operands Deprit's method really multiplies (SAM theory)."""
    T = deprit(SAM_H, order, ["l"])
    direct_l = T.direct_angle("l")
    cases = [
        (f"W{order - 1} x W{order}", T.generator[-2], T.generator[-1]),
        (f"dl{order} x W{order}", direct_l[-1], T.generator[-1]),
        (f"dl{order} x dl{order - 1}", direct_l[-1], direct_l[-2]),
    ]
    print(f"\nOperands of the SAM theory at order {order} (µs per pair of real terms)")
    print(f"{'operands':>16} {'terms':>9} {'product':>9} {'bracket':>9}")
    for name, a, b in cases:
        n = len(a) * len(b)
        t_mul = best_time(lambda a=a, b=b: a * b, repeat)
        t_br = best_time(lambda a=a, b=b: a.bracket(b), repeat)
        print(f"{name:>16} {len(a):>4}x{len(b):<4} {1e6 * t_mul / n:>9.3f} {1e6 * t_br / n:>9.3f}")


def run_sam(orders: list[int]) -> None:
    H0, H1 = SAM_H
    print("\nDeprit normalisation of Lara's SAM Hamiltonian (eq. 27), averaging over l")
    print(f"{'order':>6} {'normalise [s]':>14} {'+ l, g, L maps [s]':>19} {'terms K_N':>10}")
    for order in orders:
        start = time.perf_counter()
        T: LieTransform = deprit([H0, H1], order, ["l"])
        t_norm = time.perf_counter() - start
        T.direct_angle("l")
        T.direct_angle("g")
        T.direct("L")
        t_all = time.perf_counter() - start
        print(f"{order:>6} {t_norm:>14.3f} {t_all:>19.3f} {len(T.new_hamiltonian[-1]):>10}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes only")
    args = parser.parse_args()
    if args.quick:
        run([20, 100], [20], repeat=3, denominators="wide")
        run_deprit_operands(10, repeat=3)
        run_sam([6, 10])
    else:
        for denominators in ("wide", "small"):
            run([20, 100, 400, 1500], [20], repeat=5, denominators=denominators)
        run_deprit_operands(12, repeat=5)
        run_sam([6, 10, 12, 16, 20])


if __name__ == "__main__":
    main()
