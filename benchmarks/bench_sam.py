"""Cost of Lara's SAM theory by Lie transforms, against a plain-sympy Deprit, side by side.

Run ``python benchmarks/bench_sam.py [--quick]``.  Each measurement runs in a fresh Python
process (``--child``) so that the peak memory is its own: wall time of ``sam_theory(N)``
(Deprit normalisation, the direct transformations of ℓ, g, L and the exact tables of
eqs. 30–34), peak resident memory (``ru_maxrss``, which also sees python-flint's C allocations)
and its growth over the process after imports, and the peak of Python allocations
(``tracemalloc``, which does not see flint).

The peer is a plain-sympy implementation of the same order-4 theory (symbolic α, β, s, C, L, G;
brackets by ``diff`` + product-to-sum ``TR8``, averages and quadratures term by term) computing
the same objects: ``K_0..K_4`` and the direct transformations of ℓ, g, L.  Its new Hamiltonian
and transformation are checked equal to the engine's at a rational point before the ratio is
printed.  ``--quick`` skips order 20.
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
import tracemalloc
from math import comb
from pathlib import Path
from typing import Any

SRC = str(Path(__file__).resolve().parents[1] / "src")


# ------------------------------------------------------------------------ plain-sympy Deprit
def sympy_theory(order: int) -> dict[str, Any]:
    """Deprit's triangle for eq. 27 in plain sympy, averaged over ℓ, with the direct maps."""
    import sympy as sp
    from sympy.simplify.fu import TR8

    l, g = sp.symbols("l g", real=True)
    L, G, alpha, beta, s, C = sp.symbols("L G alpha beta s C", positive=True)
    omega = alpha * s * G / C

    def canon(f: Any) -> Any:
        return sp.expand(TR8(sp.expand(f)))

    def bracket(f: Any, w: Any) -> Any:
        return canon(
            sp.diff(f, l) * sp.diff(w, L) - sp.diff(f, L) * sp.diff(w, l) - sp.diff(f, G) * sp.diff(w, g)
        )

    def split(f: Any) -> tuple[Any, Any]:
        """Average over ℓ and the solution W of ω ∂W/∂ℓ = f − ⟨f⟩."""
        mean, w = sp.Integer(0), sp.Integer(0)
        for term in sp.Add.make_args(f):
            coeff, trig = term.as_independent(l)
            if trig == 1:
                mean += term
            else:
                w += coeff * sp.integrate(trig, l) / omega
        return mean, sp.expand(w)

    H = [G**2 / (2 * C) + alpha * s * G * L / C, -alpha * L**2 * (1 + beta * sp.cos(2 * l)) / (2 * C)]
    H += [sp.Integer(0)] * (order + 1 - len(H))
    table = [H] + [[None] * (order + 1) for _ in range(order)]
    W: list[Any] = []
    K = [H[0]]
    for n in range(1, order + 1):
        for q in range(1, n + 1):
            m = n - q
            acc = table[q - 1][m + 1]
            for k in range(m + 1):
                if k + 1 < n:
                    acc += comb(m, k) * bracket(table[q - 1][m - k], W[k])
            table[q][m] = canon(acc)
        mean, w = split(table[n][0])
        for q in range(1, n + 1):
            table[q][n - q] = canon(table[q][n - q] + mean - table[n][0])
        W.append(w)
        K.append(mean)

    def direct(f0: Any, conjugate: Any = None) -> list[Any]:
        rows = [[f0] + [sp.Integer(0)] * order]
        out = [f0]
        for n in range(1, order + 1):
            for q in range(1, n + 1):
                m = n - q
                if len(rows) <= q:
                    rows.append([None] * (order + 1))
                acc = rows[q - 1][m + 1]
                for k in range(m + 1):
                    first = conjugate is not None and q == 1 and m - k == 0
                    acc += comb(m, k) * (
                        sp.diff(W[k], conjugate) if first else bracket(rows[q - 1][m - k], W[k])
                    )
                rows[q][m] = canon(acc)
            out.append(rows[n][0])
        return out

    return {
        "K": K,
        "l": direct(sp.Integer(0), L),
        "g": direct(sp.Integer(0), G),
        "L": direct(L),
        "symbols": (l, L, G, alpha, beta, s, C),
    }


def check_sympy_against_engine(result: dict[str, Any], order: int) -> None:
    """The baseline must agree with andoyer at a rational point before it is timed."""
    import sympy as sp

    from andoyer.theories import sam_theory

    l, L, G, alpha, beta, s, C = result["symbols"]
    T = sam_theory(order).transform
    point = {l: sp.Rational(3, 7), L: sp.Rational(1, 50), G: sp.Rational(11, 10), alpha: sp.Rational(3, 10)}
    point |= {beta: sp.Rational(3, 5), s: sp.Rational(4, 5), C: sp.Rational(7, 5)}
    names = {"l": l, "L": L, "G": G, "alpha": alpha, "beta": beta, "s": s, "C": C}
    engine = {
        "K": T.new_hamiltonian,
        "l": T.direct_angle("l"),
        "g": T.direct_angle("g"),
        "L": T.direct("L"),
    }
    for key, ours in engine.items():
        for n, (a, b) in enumerate(zip(result[key], ours, strict=True)):
            diff = sp.N(a.subs(point) - b.to_sympy(names).subs(point), 50)
            if abs(diff) > 1e-40:
                msg = f"plain-sympy {key}_{n} differs from andoyer by {diff}"
                raise AssertionError(msg)


# ----------------------------------------------------------------------------- children
def child(kind: str, order: int) -> None:
    sys.path.insert(0, SRC)
    import sympy  # imported in both children: the same baseline memory

    from andoyer.theories import sam as sam_module

    def run() -> Any:
        return sam_module.sam_theory.__wrapped__(order) if kind == "engine" else sympy_theory(order)

    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    start = time.perf_counter()
    result = run()
    elapsed = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    # tracemalloc slows Python allocations several times: a second, untimed run for the Python peak
    # (sympy's expression cache cleared first, so that the run redoes its work).
    sympy.core.cache.clear_cache()
    tracemalloc.start()
    run()
    _, py_peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    if kind == "sympy":
        check_sympy_against_engine(result, order)
    print(
        json.dumps({"time": elapsed, "rss_peak_kib": peak, "rss_growth_kib": peak - base, "py_peak": py_peak})
    )


def measure(kind: str, order: int) -> dict[str, float]:
    out = subprocess.run(
        [sys.executable, __file__, "--child", kind, str(order)], capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="skip order 20")
    parser.add_argument("--child", nargs=2, metavar=("KIND", "ORDER"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(args.child[0], int(args.child[1]))
        return
    orders = (4, 10, *(() if args.quick else (20,)))
    rows = [("andoyer sam_theory", order, measure("engine", order)) for order in orders]
    rows.append(("plain sympy", 4, measure("sympy", 4)))
    print("Lara's SAM theory by Deprit's Lie transforms, one fresh process per row")
    header = (
        "implementation",
        "order",
        "time (s)",
        "peak RSS (MiB)",
        "RSS growth (MiB)",
        "Python peak (MiB)",
    )
    print(f"{header[0]:20s} {header[1]:>5s} " + " ".join(f"{h:>17s}" for h in header[2:]))
    for name, order, r in rows:
        values = (r["time"], r["rss_peak_kib"] / 1024, r["rss_growth_kib"] / 1024, r["py_peak"] / 2**20)
        print(f"{name:20s} {order:5d} " + " ".join(f"{v:17.3f}" for v in values))
    ratio = rows[-1][2]["time"] / rows[0][2]["time"]
    print(f"order 4: plain sympy / andoyer = {ratio:.0f}x (the sympy results are checked equal to andoyer's)")
    print("andoyer rows include the exact tables of eqs. 30-34; the sympy row stops at the series.")


if __name__ == "__main__":
    main()
