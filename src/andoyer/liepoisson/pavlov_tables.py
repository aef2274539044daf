"""Pavlov's bracket tables (eqs. 1.3–1.6 for e(3), 2.10–2.13 for l(7)), corrected, and their check.

Pavlov's method: take the canonical pair ``(l, L)`` and the Casimir ``G`` of the
subalgebra so(3) (eq. 1.2), compute their brackets with the remaining generators
(γ or λ) in the big algebra, then solve these relations, read as partial
differential equations ``{l, x} = ∂x/∂L``, ``{L, x} = -∂x/∂l``, ``{G, x} = -∂x/∂g``
(and ``{H, x} = -∂x/∂h`` on l(7)), for the generators as functions of the
coordinates. :func:`check_pavlov_table` verifies each table entry both ways:

* ``via="lie-poisson"``: the left side computed with the Lie–Poisson bracket from
  ``l = atan2(m1, m2)``, ``L = m3``, ``G = |m|`` (and ``H = m·γ``), compared with the
  right side;
* ``via="canonical"``: the left side computed with the canonical bracket from the
  solution (Pavlov eqs. 1.7, 2.14 in the project's convention), i.e. the solution
  satisfies the PDE system.

The one entry printed wrong is ``{l, λ1}`` in eq. 2.12 (``printed`` holds Pavlov's
version; see ``docs/errata-pavlov.md``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
import sympy as sp

from andoyer.liepoisson._identity import vanishes
from andoyer.liepoisson.algebra import LiePoissonAlgebra, get_algebra
from andoyer.liepoisson.canonicity import (
    BracketRecord,
    _evaluate_many,
    _level_relations,
    _shorten,
)
from andoyer.liepoisson.coordinates import (
    CanonicalCoordinates,
    andoyer_coordinates,
    andoyer_symbols,
)

__all__ = ["TableEntry", "check_pavlov_table", "pavlov_table"]


@dataclass(frozen=True)
class TableEntry:
    """One relation ``{left, right} = rhs`` of Pavlov's tables.

    Attributes
    ----------
    equation : str
        Pavlov's equation number.
    left, right : str
        A coordinate (``l, L, G, H``) or a generator name (``gamma1``, ``lambda0``, ...).
    rhs : sympy expression
        Right side (corrected), in ``l, L, G, H`` and the generators.
    printed : sympy expression or None
        Pavlov's printed right side where it differs from ``rhs``.
    """

    equation: str
    left: str
    right: str
    rhs: Any
    printed: Any = None


def pavlov_table(algebra: Literal["e3", "l7"]) -> tuple[TableEntry, ...]:
    """Pavlov's bracket table for ``"e3"`` (eqs. 1.3–1.6) or ``"l7"`` (eqs. 2.10–2.13).

    Parameters
    ----------
    algebra : {"e3", "l7"}

    Returns
    -------
    tuple of TableEntry

    Raises
    ------
    ValueError
        For another algebra.

    Examples
    --------
    >>> t = pavlov_table("e3")
    >>> len(t), t[9].equation, t[9].left, t[9].right, t[9].rhs
    (15, '1.5', 'l', 'gamma1', -gamma3*sin(l)/sqrt(G**2 - L**2))
    >>> [(e.equation, e.left, e.right) for e in pavlov_table("l7") if e.printed is not None]
    [('2.12', 'l', 'lambda1')]
    """
    s = andoyer_symbols()
    ell, L, G, H = s["l"], s["L"], s["G"], s["H"]
    rho = sp.sqrt(G**2 - L**2)
    sl, cl = sp.sin(ell), sp.cos(ell)
    if algebra == "e3":
        g1, g2, g3 = get_algebra("e3").symbols()[3:]
        rows = [
            ("1.3", "l", "L", sp.Integer(1)),
            ("1.3", "G", "L", 0),
            ("1.3", "G", "l", 0),
            ("1.3", "gamma1", "gamma2", 0),
            ("1.3", "gamma1", "gamma3", 0),
            ("1.3", "gamma2", "gamma3", 0),
            ("1.4", "L", "gamma1", -g2),
            ("1.4", "L", "gamma2", g1),
            ("1.4", "L", "gamma3", 0),
            ("1.5", "l", "gamma1", -sl * g3 / rho),
            ("1.5", "l", "gamma2", -cl * g3 / rho),
            ("1.5", "l", "gamma3", (H - L * g3) / (G**2 - L**2)),
            ("1.6", "G", "gamma1", (rho * cl * g3 - L * g2) / G),
            ("1.6", "G", "gamma2", (L * g1 - rho * sl * g3) / G),
            ("1.6", "G", "gamma3", rho * (sl * g2 - cl * g1) / G),
        ]
        return tuple(TableEntry(e, a, b, sp.sympify(r)) for e, a, b, r in rows)
    if algebra != "l7":
        raise ValueError(f"expected 'e3' or 'l7', got {algebra!r}")
    q0, q1, q2, q3 = get_algebra("l7").symbols()[3:]
    # same radicals as the half-angle factors of the l(7) map, so that proofs match
    rho = sp.sqrt(G - L) * sp.sqrt(G + L)
    half = sp.Rational(1, 2)
    a, b = rho / (2 * G), L / (2 * G)
    rows = [
        ("2.10", "L", "lambda0", half * q3),
        ("2.10", "L", "lambda1", -half * q2),
        ("2.10", "L", "lambda2", half * q1),
        ("2.10", "L", "lambda3", -half * q0),
        ("2.11", "H", "lambda0", half * q3),
        ("2.11", "H", "lambda1", half * q2),
        ("2.11", "H", "lambda2", -half * q1),
        ("2.11", "H", "lambda3", -half * q0),
        ("2.12", "l", "lambda0", (q1 * cl - q2 * sl) / (2 * rho)),
        ("2.12", "l", "lambda1", -(q0 * cl + q3 * sl) / (2 * rho)),
        ("2.12", "l", "lambda2", (q0 * sl - q3 * cl) / (2 * rho)),
        ("2.12", "l", "lambda3", (q1 * sl + q2 * cl) / (2 * rho)),
        ("2.13", "G", "lambda0", a * (q1 * sl + q2 * cl) + b * q3),
        ("2.13", "G", "lambda1", a * (-q0 * sl + q3 * cl) - b * q2),
        ("2.13", "G", "lambda2", -a * (q0 * cl + q3 * sl) + b * q1),
        ("2.13", "G", "lambda3", a * (q2 * sl - q1 * cl) - b * q0),
    ]
    printed = {("2.12", "lambda1"): -(q3 * cl + q0 * sl) / (2 * rho)}
    return tuple(TableEntry(e, x, y, sp.sympify(r), printed.get((e, y))) for e, x, y, r in rows)


def check_pavlov_table(
    algebra: Literal["e3", "l7"],
    *,
    via: Literal["lie-poisson", "canonical"] = "lie-poisson",
    printed: bool = False,
    n_points: int = 1000,
    seed: int = 0,
    tol: float = 1e-12,
    symbolic: bool = True,
) -> list[BracketRecord]:
    """Verify every entry of Pavlov's table for ``algebra``, symbolically and numerically.

    Parameters
    ----------
    algebra : {"e3", "l7"}
    via : {"lie-poisson", "canonical"}, optional
        Compute the left side with the Lie–Poisson bracket of the coordinate functions,
        or with the canonical bracket of the solution (see module docstring).
    printed : bool, optional
        Check Pavlov's printed right sides instead of the corrected ones.
    n_points, seed, tol, symbolic
        As in :func:`andoyer.liepoisson.canonicity.check_coordinates`.

    Returns
    -------
    list of BracketRecord
        One per table entry; ``value`` is the right side when proven.

    Examples
    --------
    >>> rec = check_pavlov_table("l7", printed=True, n_points=100)
    >>> [(r.left, r.right, r.symbolic_ok, r.numeric_ok) for r in rec
    ...  if not (r.symbolic_ok and r.numeric_ok)]
    [('l', 'lambda1', False, False)]
    """
    if via not in ("lie-poisson", "canonical"):
        raise ValueError(f"expected via='lie-poisson' or 'canonical', got {via!r}")
    alg = get_algebra(algebra)
    coords = andoyer_coordinates(algebra)
    table = pavlov_table(algebra)
    rhs = [e.printed if printed and e.printed is not None else e.rhs for e in table]
    check = _via_lie_poisson if via == "lie-poisson" else _via_canonical
    proven, errors = check(alg, coords, table, rhs, n_points=n_points, seed=seed, symbolic=symbolic)
    return [
        BracketRecord(
            e.left,
            e.right,
            _shorten(r) if ok else "<not proven>",
            _shorten(r),
            ok,
            bool(err <= tol),
            float(err),
        )
        for e, r, ok, err in zip(table, rhs, proven, errors, strict=True)
    ]


def _via_lie_poisson(
    alg: LiePoissonAlgebra,
    coords: CanonicalCoordinates,
    table: tuple[TableEntry, ...],
    rhs: list[Any],
    *,
    n_points: int,
    seed: int,
    symbolic: bool,
) -> tuple[list[bool], np.ndarray]:
    xs = alg.symbols()
    names = {str(z): z for z in coords.symbols}
    functions = {n: coords.inverse[names[n]] for n in names}
    functions.update(zip(alg.generators, xs, strict=True))
    H = names.get("H")
    m_of_lLG = {x: coords.forward[n] for x, n in zip(xs[:3], alg.generators[:3], strict=True)}
    proven = []
    for entry, r in zip(table, rhs, strict=True):
        ok = False
        if symbolic:
            bracket = alg.bracket_sym_unexpanded(functions[entry.left], functions[entry.right])
            r_x = r.xreplace({H: coords.inverse[H]}) if H is not None else r
            ok = vanishes(bracket - r_x, _level_relations(alg), substitution=m_of_lLG)
        proven.append(ok)
    pts = alg.sample(np.random.default_rng(seed), n_points)
    used = sorted({e.left for e in table} | {e.right for e in table})
    grads = _evaluate_many([sp.diff(functions[n], x) for n in used for x in xs], xs, pts)
    grads = dict(zip(used, grads.reshape(len(used), len(xs), -1).transpose(0, 2, 1), strict=True))
    z_values = _evaluate_many([coords.inverse[z] for z in coords.symbols], xs, pts)
    expected = _evaluate_many(rhs, (*xs, *coords.symbols), np.column_stack([pts, z_values.T]))
    P = alg.poisson_tensor(pts)
    errors = []
    for entry, want in zip(table, expected, strict=True):
        gf, gk = grads[entry.left], grads[entry.right]
        value = np.einsum("...a,...ab,...b->...", gf, P, gk)
        scale = np.einsum("...a,...ab,...b->...", np.abs(gf), np.abs(P), np.abs(gk))
        errors.append(np.max(np.abs(value - want) / np.maximum(1.0, scale + np.abs(want))))
    return proven, np.array(errors)


def _via_canonical(
    alg: LiePoissonAlgebra,
    coords: CanonicalCoordinates,
    table: tuple[TableEntry, ...],
    rhs: list[Any],
    *,
    n_points: int,
    seed: int,
    symbolic: bool,
) -> tuple[list[bool], np.ndarray]:
    zs = coords.symbols
    names = {str(z): z for z in zs}
    functions = dict(names)
    functions.update(coords.forward)
    fwd = {x: coords.forward[n] for x, n in zip(alg.symbols(), alg.generators, strict=True)}
    derivative: dict[tuple[str, Any], Any] = {}

    def d(name: str, z: Any) -> Any:
        if (name, z) not in derivative:
            derivative[name, z] = sp.diff(functions[name], z)
        return derivative[name, z]

    brackets, rhs_z, proven = [], [], []
    for entry, r in zip(table, rhs, strict=True):
        f, k = entry.left, entry.right
        bracket = sum(d(f, q) * d(k, p) - d(f, p) * d(k, q) for q, p in coords.pairs)
        brackets.append(bracket)
        rhs_z.append(r.xreplace(fwd))
        proven.append(bool(symbolic) and vanishes(bracket - rhs_z[-1]))
    pts = coords.sampler(np.random.default_rng(seed), n_points)
    values = _evaluate_many(brackets + rhs_z, zs, pts)
    value, want = values[: len(table)], values[len(table) :]
    errors = np.max(np.abs(value - want) / np.maximum(1.0, np.abs(want)), axis=-1)
    return proven, errors
