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

The computation is exact polynomial arithmetic in ``u = j²`` over the field ℚ(τ, α) with
``β = (1 − τ²)/(1 + τ²)``, ``s = 2τ/(1 + τ²)``; coefficients are written back as
``A(β) + B(β)√(1 − β²)``.  Symbols: ``alpha, beta, G, C,
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
    """Exact arithmetic for the expansions.

    β and ``s = √(1 − β²)`` are parametrised rationally, ``β = (1 − τ²)/(1 + τ²)``,
    ``s = 2τ/(1 + τ²)`` (``τ = √((1 − β)/(1 + β))``), so every coefficient lies in the field
    ℚ(τ, α) with exact, canonical arithmetic.  ``G = C = 1`` inside (restored by scaling).
    A truncated series in ``u = j²`` is a list of dicts ``{trig: coefficient}``, ``trig`` being
    ``()`` or ``("cos"|"sin", k)`` for a harmonic ``k ℓ'``.
    """

    def __init__(self, top: int) -> None:
        import sympy as sp
        from sympy.polys.fields import field

        self.sp = sp
        self.S = symbols()
        self.top = top
        self.K, self.tau, self.alpha = field("tau, alpha", sp.QQ)
        self.beta = (1 - self.tau**2) / (1 + self.tau**2)
        self.s = 2 * self.tau / (1 + self.tau**2)

    def zero(self) -> list[dict[Any, Any]]:
        return [{} for _ in range(self.top + 1)]

    def series(self, f: PoissonSeries, at_half_pi: bool = False) -> dict[int, dict[Any, Any]]:
        """``f`` with ``L = x``, ``G = C = 1``: ``{power of x: {trig: coefficient}}``."""
        from math import cos, pi, sin

        values = {"G": 1, "C": 1, "alpha": self.alpha, "beta": self.beta, "s": self.s}
        names = f.ring.poly_names
        out: dict[int, dict[Any, Any]] = {}
        for t in f.terms():
            c = self.K(self.sp.Rational(t.coeff.numerator, t.coeff.denominator))
            power = 0
            for name, e in zip(names, t.exponents, strict=True):
                if name == "L":
                    power = e
                elif e:
                    c = c * values[name] ** e
            k = t.harmonics[0]
            if at_half_pi and k:
                c = c * round((cos if t.kind == "cos" else sin)(k * pi / 2))
                key: Any = ()
            else:
                key = (t.kind, k) if k else ()
            row = out.setdefault(power, {})
            row[key] = row.get(key, 0) + c
        return out

    def add_into(self, target: dict[Any, Any], row: dict[Any, Any], factor: Any = 1) -> None:
        for key, c in row.items():
            target[key] = target.get(key, 0) + c * factor

    def compose(self, poly_x: dict[int, dict[Any, Any]], x_of_u: list[Any]) -> list[dict[Any, Any]]:
        """``poly_x(x_of_u(u))`` truncated at ``u^top`` (``x_of_u`` scalar, no constant term)."""
        out, power = self.zero(), [1] + [0] * self.top
        for k in range(max(poly_x) + 1):
            if k:
                power = [sum(power[i] * x_of_u[n - i] for i in range(n + 1)) for n in range(self.top + 1)]
            for n in range(self.top + 1):
                if power[n] != 0:
                    self.add_into(out[n], poly_x.get(k, {}), power[n])
        return out

    def to_sympy(self, c: Any) -> Any:
        """A coefficient of ℚ(τ, α) as ``A(β) + B(β)√(1 − β²)``, factored."""
        sp = self.sp
        tau = sp.Symbol("tau", positive=True)
        expr = sp.sympify(c.as_expr()).subs(sp.Symbol("alpha"), self.S["alpha"]).subs(sp.Symbol("tau"), tau)
        mirrored = expr.subs(tau, -tau)
        even = sp.cancel((expr + mirrored) / 2)
        odd = sp.cancel((expr - mirrored) / 2 / (2 * tau / (1 + tau**2)))
        beta = self.S["beta"]
        root = sp.sqrt((1 - beta) / (1 + beta))
        A, B = (sp.cancel(part.subs(tau, root)) for part in (even, odd))
        r = sp.Symbol("r", positive=True)  # stands for √(1 − β²) while factoring
        return sp.factor(A + B * r).subs(r, sp.sqrt(1 - beta**2))

    def finish(self, coeffs: list[dict[Any, Any]], scale: Any = 1) -> Any:
        """Polynomial in ``j`` (trigonometric coefficients in ``ℓ'``), times ``scale``."""
        sp = self.sp
        l, j = self.S["l"], self.S["j"]
        terms = []
        for n, row in enumerate(coeffs):
            for key, c in row.items():
                if c != 0:
                    trig = 1 if key == () else getattr(sp, key[0])(key[1] * l)
                    terms.append(scale * self.to_sympy(c) * trig * j ** (2 * n))
        return sp.Add(*terms)


def _mean_action(w: _Work, order: int, relation: str) -> list[Any]:
    """``x(u)`` as scalar coefficients of ``u⁰ … u^top`` in ℚ(τ)."""
    x = [w.K(0)] * (w.top + 1)
    x[1] = w.s / (2 * (1 - w.beta))  # eq. 36
    if relation == "eq36":
        return x
    one_minus_cos = [0] + [
        (-1) ** (k + 1) * w.K(w.sp.Rational(1, factorial(2 * k))) for k in range(1, w.top + 1)
    ]
    L_half = w.series(lie_sum(sam_theory(max(order, w.top)).transform.direct("L")), at_half_pi=True)
    lhs = {k: {(): (1 - w.beta) / w.s * row.get((), 0)} for k, row in L_half.items()}  # x + O(x²)
    for _ in range(w.top):  # each pass fixes one more power of u
        residual = w.compose(lhs, x)
        x = [
            x[n] - (residual[n].get((), 0) - one_minus_cos[n]) * w.s / (1 - w.beta) for n in range(w.top + 1)
        ]
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
    sqrt(1 - beta**2)*(4*beta - 1)/(24*(beta - 1)**2)
    """
    _check(order, j_order, relation)
    w = _Work(j_order // 2)
    return w.finish([{(): c} for c in _mean_action(w, order, relation)])


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
    w = _Work(j_order // 2)
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    x = _mean_action(w, order, relation)
    scale = w.S["G"] / w.S["C"]  # T = (G²/C) f(L/G): both frequencies scale as G/C
    return tuple(w.finish(w.compose(w.series(T.diff(name)), x), scale) for name in ("L", "G"))


def precession_rate_in_j(order: int = 2, j_order: int = 2, relation: str = "eq36") -> Any:
    """Mean rate of Andoyer's ``g`` (Lara's ``μ = g − ν``, eq. 19): ``n_g' + n_ℓ'`` in ``j``.

    ``ν`` turns by ``−2π`` while ``ℓ`` turns by ``2π`` (eq. 18), hence the sum.

    Examples
    --------
    >>> precession_rate_in_j()
    G*alpha*j**2*(beta**2 + sqrt(1 - beta**2) - 1)/(2*C*(beta - 1)) + G*(alpha*sqrt(1 - beta**2) + 1)/C
    """
    _check(order, j_order, relation)
    w = _Work(j_order // 2)
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    x = _mean_action(w, order, relation)
    return w.finish(w.compose(w.series(T.diff("L") + T.diff("G")), x), w.S["G"] / w.S["C"])


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
    top = j_order // 2
    w = _Work(top)
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
    return w.finish(w.compose(w.series(N_over_M), _mean_action(w, order, relation)))
