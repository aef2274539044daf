r"""Lara's SAM theory expanded in Kinoshita's ``j`` (Lara §5), as sympy expressions.

Kinoshita's integration constant ``j`` is the minimum of the inclination ``J`` of the figure
axis on the invariable plane.  On a SAM orbit ``J`` is smallest where ``cos 2ν = −1``, i.e. at
``ℓ = ℓ' = π/2`` (the corrections ``∝ sin 2mℓ'`` vanish there), so by eq. 21, exactly,

    1 − cos j = 1 − N/M = (1 − β) L(ℓ' = π/2, L')/(G' s),        s = √(1 − β²)      (eq. 35)

with ``L(ℓ', L')`` the direct transformation (eq. 34).  To first order this is Lara's eq. 36,
``j²/2 = (1 − β) δ' = √((1 − β)/(1 + β)) L'/G'``.  Two relations between ``j`` and the mean
action are offered:

* ``relation="eq36"``: eq. 36 taken as the definition of ``j`` (what Lara does in §5);
* ``relation="exact"``: eq. 35 with the full transformation, inverted as a series in ``j²``
  (the minimum inclination itself, exact through the order kept).

The computation is polynomial arithmetic in ``u = j²`` with coefficients rational in ``β`` and
``s`` (kept as a symbol, reduced by ``s² = 1 − β²`` at the end).  Symbols: ``alpha, beta, G, C,
j`` (positive) and ``l`` for the mean angle ``ℓ'``; ``G`` stands for ``G' = M``.
"""

from __future__ import annotations

from math import factorial
from typing import Any

from andoyer.series import PoissonSeries, lie_sum
from andoyer.theories.sam import sam_theory

__all__ = [
    "andoyer_N_in_j",
    "mean_action_in_j",
    "precession_rate_in_j",
    "secular_frequencies_in_j",
    "symbols",
]

RELATIONS = ("eq36", "exact")


def symbols() -> dict[str, Any]:
    """The sympy symbols of this module: ``alpha, beta, G, C, j`` (positive) and ``l``.

    Examples
    --------
    >>> sorted(symbols())
    ['C', 'G', 'alpha', 'beta', 'j', 'l']
    """
    import sympy as sp

    out = {n: sp.Symbol(n, positive=True) for n in ("alpha", "beta", "G", "C", "j")}
    out["l"] = sp.Symbol("l", real=True)
    return out


def _check(order: int, j_order: int, relation: str) -> None:
    if not isinstance(order, int) or isinstance(order, bool) or order < 1:
        msg = f"expected an integer Deprit order >= 1, got {order!r}"
        raise ValueError(msg)
    if not isinstance(j_order, int) or j_order < 2 or j_order % 2:
        msg = f"expected an even j_order >= 2, got {j_order!r}"
        raise ValueError(msg)
    if relation not in RELATIONS:
        msg = f"expected relation 'eq36' or 'exact', got {relation!r}"
        raise ValueError(msg)


class _Work:
    """Symbols of the computation: ``x = L'/G'``, ``u = j²`` and ``s`` independent of β."""

    def __init__(self) -> None:
        import sympy as sp

        self.sp = sp
        self.S = symbols()
        self.x = sp.Symbol("x", positive=True)
        self.u = sp.Symbol("u", positive=True)
        self.s = sp.Symbol("s", positive=True)

    def series(self, f: PoissonSeries) -> Any:
        """A SAM-ring series as a polynomial in ``x`` (``L = x G``)."""
        S = self.S
        subs = {"L": self.x * S["G"], "G": S["G"], "C": S["C"], "alpha": S["alpha"], "beta": S["beta"]}
        return self.sp.expand(f.to_sympy(subs | {"s": self.s, "l": S["l"]}))

    def truncate(self, expr: Any, top: int) -> Any:
        """Powers ``u^0 … u^top`` of a polynomial in ``u``."""
        sp = self.sp
        poly = sp.Poly(sp.expand(expr), self.u)
        return sp.Add(*(c * self.u**k for (k,), c in poly.terms() if k <= top))

    def compose(self, poly_x: Any, x_of_u: Any, top: int) -> Any:
        """``poly_x(x_of_u(u))`` truncated at ``u^top`` (``x_of_u`` has no constant term)."""
        sp = self.sp
        poly = sp.Poly(poly_x, self.x)
        out, power = sp.Integer(0), sp.Integer(1)
        for k in range(poly.degree() + 1):
            if k:
                power = self.truncate(power * x_of_u, top)
            c = poly.coeff_monomial(self.x**k)
            if c != 0:
                out += c * power
        return self.truncate(out, top)

    def first_order(self) -> Any:
        """Eq. 36: ``x = s u/(2(1 − β))``."""
        return self.s * self.u / (2 * (1 - self.S["beta"]))

    def finish(self, expr: Any, top: int) -> Any:
        """Collect in ``j``, reduce ``s² = 1 − β²`` and factor each coefficient."""
        sp = self.sp
        beta, j = self.S["beta"], self.S["j"]
        root = sp.sqrt(1 - beta**2)
        terms = []
        poly = sp.Poly(sp.expand(expr), self.u)
        for k in range(top + 1):
            c = sp.cancel(poly.coeff_monomial(self.u**k))
            num, den = sp.fraction(c)
            num = sp.rem(sp.expand(num), self.s**2 - 1 + beta**2, self.s)
            den = sp.rem(sp.expand(den), self.s**2 - 1 + beta**2, self.s)
            c = sp.factor(sp.cancel(num / den).subs(self.s, root))
            terms.append(c * j ** (2 * k))
        return sp.Add(*terms)


def _mean_action(w: _Work, order: int, top: int, relation: str) -> Any:
    """``x(u)`` as a polynomial in ``u`` with coefficients in β, s."""
    sp = w.sp
    x1 = w.first_order()
    if relation == "eq36":
        return x1
    beta = w.S["beta"]
    one_minus_cos = sum((-1) ** (k + 1) * w.u**k / sp.factorial(2 * k) for k in range(1, top + 1))
    L_half = w.series(lie_sum(sam_theory(max(order, top)).transform.direct("L"))).subs(w.S["l"], sp.pi / 2)
    lhs = sp.expand((1 - beta) / w.s * L_half / w.S["G"])
    slope = lhs.coeff(w.x, 1)
    x = x1
    for _ in range(top):  # Newton-like fixed point: one more power of u per pass
        x = w.truncate(x - (w.compose(lhs, x, top) - one_minus_cos) / slope, top)
    return x


def mean_action_in_j(order: int = 2, j_order: int = 4, relation: str = "eq36") -> Any:
    """``x = L'/G'`` as a polynomial in ``j`` through ``j^j_order``.

    Parameters
    ----------
    order : int
        Deprit order of the SAM theory (``relation="exact"`` uses at least ``j_order/2``).
    j_order : int
        Highest (even) power of ``j`` kept.
    relation : {"eq36", "exact"}

    Returns
    -------
    sympy.Expr

    Examples
    --------
    >>> mean_action_in_j(relation="eq36")
    -j**2*sqrt(1 - beta**2)/(2*(beta - 1))
    >>> mean_action_in_j(j_order=4, relation="exact").coeff(symbols()["j"], 4)
    -sqrt(1 - beta**2)*(3*beta**2 - 2*beta + 1)/(24*(beta - 1)**2)
    """
    _check(order, j_order, relation)
    w = _Work()
    return w.finish(_mean_action(w, order, j_order // 2, relation), j_order // 2)


def secular_frequencies_in_j(order: int = 2, j_order: int = 6, relation: str = "eq36") -> tuple[Any, Any]:
    """``(n_ℓ', n_g')`` of the averaged Hamiltonian (eq. 30) expanded in ``j`` (Lara §5).

    Parameters
    ----------
    order : int
        Deprit order of the theory (``2`` keeps ``q_1`` only: Lara's "i = 1").
    j_order : int
        Highest (even) power of ``j`` kept.
    relation : {"eq36", "exact"}
        How ``j`` relates to the mean action (module docstring).

    Returns
    -------
    (sympy.Expr, sympy.Expr)
        Polynomials in ``j``.

    Examples
    --------
    >>> n_l, n_g = secular_frequencies_in_j(order=2, j_order=6)
    >>> n_g
    G*alpha*beta**2*j**6*(beta + 1)/(32*C*(beta - 1)**2) + G*alpha*j**2*(beta + 1)/(2*C) + G/C
    """
    _check(order, j_order, relation)
    w = _Work()
    top = j_order // 2
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    x = _mean_action(w, order, top, relation)
    return tuple(w.finish(w.compose(w.series(T.diff(name)), x, top), top) for name in ("L", "G"))


def precession_rate_in_j(order: int = 2, j_order: int = 2, relation: str = "eq36") -> Any:
    """Mean rate of Andoyer's ``g`` (Lara's ``μ = g − ν``, eq. 19): ``n_g' + n_ℓ'`` in ``j``.

    ``ν`` turns by ``−2π`` while ``ℓ`` turns by ``2π`` (eq. 18), hence the sum.

    Examples
    --------
    >>> precession_rate_in_j()
    G*alpha*j**2*(-beta**2 - sqrt(1 - beta**2) + 1)/(2*C*(beta - 1)) + G*(alpha*sqrt(1 - beta**2) + 1)/C
    """
    _check(order, j_order, relation)
    w = _Work()
    top = j_order // 2
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    x = _mean_action(w, order, top, relation)
    return w.finish(w.compose(w.series(T.diff("L") + T.diff("G")), x, top), top)


def andoyer_N_in_j(order: int = 2, j_order: int = 2, relation: str = "eq36") -> Any:
    """``N/M`` (eq. 21 with eqs. 33–34) in powers of ``j`` at the mean angle ``ℓ'`` (Lara §5).

    ``cos 2ℓ = cos(2ℓ' + 2Δℓ)`` is expanded in ``Δℓ = O(j²)``.

    Returns
    -------
    sympy.Expr
        ``1 − j²/2 − β j² cos²ℓ'/(1 − β) + O(j⁴)`` for ``j_order = 2``.

    Examples
    --------
    >>> import sympy as sp
    >>> S = symbols()
    >>> printed = 1 - S["j"]**2 / 2 - S["beta"] / (1 - S["beta"]) * S["j"]**2 * sp.cos(S["l"])**2
    >>> sp.simplify(sp.expand_trig(andoyer_N_in_j() - printed))
    0
    """
    _check(order, j_order, relation)
    w = _Work()
    top = j_order // 2
    theory = sam_theory(max(order, top)).transform
    R = theory.ring
    dl, L_old = lie_sum(theory.direct_angle("l")), lie_sum(theory.direct("L"))
    # cos(2ℓ' + 2Δℓ) by Taylor in Δℓ = O(x); products of trigonometric series stay exact here.
    cos_d, sin_d, power = R.zero, R.zero, R.one
    for k in range(top + 1):
        term = power / factorial(k)
        if k % 2:
            sin_d += term * (-1) ** (k // 2)
        else:
            cos_d += term * (-1) ** (k // 2)
        power = power * (dl * 2)
    cos_2l = R("cos(2*l)") * cos_d - R("sin(2*l)") * sin_d
    N_over_M = R.one - L_old * R("G**-1 * s**-1") * (R.one + R("beta") * cos_2l)
    x = _mean_action(w, order, top, relation)
    return w.finish(w.compose(w.series(N_over_M), x, top), top)
