"""Lara's short-axis-mode (SAM) theory of the free rigid body by Deprit's Lie transforms.

Lara (2013), §3–4.  In the action–angle variables ``(ℓ, g, L, G)`` of the *main problem of SAM
rotation* (Lara's letters; they are not Andoyer's ``(l, g, L, G)``), the free-body Hamiltonian
is (eq. 27)

    K = G²/(2C) + α s G L / C − α L² (1 + β cos 2ℓ) / (2C),    s = √(1 − β²),

with Andoyer's inertia parameters ``α(1 ± β) = C/A − 1, C/B − 1`` (eq. 2).  The last term is
smaller by ``δ = L/(G s)`` than the second, so ``H₀ = G²/(2C) + α s G L / C`` and
``ε H₁ = −α L² (1 + β cos 2ℓ)/(2C)`` with ε = 1 (each Deprit order adds one power of δ).
Averaging over ℓ to order N gives (eq. 30)

    T = G'²/(2C) [1 + 2α s x − α x² (1 + β² Σ_(i≥1) δ^i q_i(β))],   x = L'/G',  δ = x / s,

and the transformation (eqs. 32–34; ``k = (i+1)//2``)

    g = g' − x Σ δ^i Σ_(m=1..k) (−β)^m g_(i,m) sin 2mℓ',
    ℓ = ℓ' + Σ δ^i Σ_(m=1..i) (−β)^m ℓ_(i,m) sin 2mℓ',
    L = L' + L' Σ δ^i (β² L_(i,0) − Σ_(m=1..k) (−β)^m L_(i,m) cos 2mℓ'),   G = G'.

The triaxiality polynomials ``q_i, g_(i,m), ℓ_(i,m), L_(i,m)`` are computed here exactly, as
tuples of rational coefficients of ``1, β, β², …``.  (Eq. 31 of the extracted paper reads
"δ^i = L'/G' /√(1−β²)"; the definition used in eq. 30 is ``δ = L'/(G'√(1−β²))``.)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from math import comb, factorial
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.catalogue.units import DAY, HOUR
from andoyer.series import CompiledSeries, LieTransform, PoissonRing, PoissonSeries, deprit, lie_sum

__all__ = [
    "MAX_ORDER",
    "SAM_RING",
    "SAMTheory",
    "beta_polynomial_value",
    "sam_hamiltonian",
    "sam_theory",
]

#: Highest Deprit order :func:`sam_theory` computes. The cost grows like ``N⁷`` (measured on a
#: loaded 2-core machine: order 41 in 42 s, order 51 in 189 s), so order 61 takes about
#: 11 minutes and order 200 would take about a month: refused with the estimate.
MAX_ORDER = 61


def estimated_seconds(order: int) -> float:
    """Measured cost of :func:`sam_theory` at Deprit order ``order``: ``42 s · (order/41)⁷``.

    Examples
    --------
    >>> round(estimated_seconds(41)), round(estimated_seconds(201) / 86400)
    (42, 33)
    """
    return 42.0 * (order / 41.0) ** 7


def check_order(order: int, name: str = "order", offset: int = 0) -> None:
    """Refuse an order below 1, or whose Deprit order ``order + offset`` is past :data:`MAX_ORDER`.

    Examples
    --------
    >>> check_order(62)  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
    ...
    ValueError: expected an integer order between 1 and 61 (the cost grows like N^7:
    order 61 takes about 11 minutes), got 62 (would take about 13 minutes)
    """
    if not isinstance(order, int) or isinstance(order, bool) or order < 1:
        msg = f"expected an integer {name} >= 1, got {order!r}"
        raise ValueError(msg)
    if order + offset > MAX_ORDER:
        top, need = estimated_seconds(MAX_ORDER), estimated_seconds(order + offset)
        msg = (
            f"expected an integer {name} between 1 and {MAX_ORDER - offset} (the cost grows like N^7: "
            f"{name} {MAX_ORDER - offset} takes about {_duration(top)}), got {order} "
            f"(would take about {_duration(need)})"
        )
        raise ValueError(msg)


def _duration(seconds: float) -> str:
    for unit, size in (("days", DAY), ("hours", HOUR), ("minutes", 60.0)):
        if seconds >= 2 * size:
            return f"{seconds / size:.0f} {unit}"
    return f"{seconds:.0f} seconds"

SAM_RING = PoissonRing(["l", "g"], ["L", "G"], ["alpha", "beta", "s", "C"], relations={"beta": "1 - s**2"})

BetaPolynomial = tuple[Fraction, ...]


def sam_hamiltonian() -> tuple[PoissonSeries, PoissonSeries]:
    """Lara's eq. 27 split for Deprit's method: ``K = H₀ + ε H₁`` with ε = 1.

    Returns
    -------
    (PoissonSeries, PoissonSeries)
        ``H₀ = G²/(2C) + α s G L/C`` and ``H₁ = −α L² (1 + β cos 2ℓ)/(2C)`` in
        :data:`SAM_RING` (``s = √(1−β²)``, reduced by ``β² = 1 − s²``).

    Examples
    --------
    >>> H0, H1 = sam_hamiltonian()
    >>> H1
    -1/2*L**2*alpha*C**-1 - 1/2*L**2*alpha*beta*C**-1*cos(2*l)
    """
    R = SAM_RING
    return R("G**2/(2*C) + alpha*s*G*L/C"), R("-alpha*L**2/(2*C)*(1 + beta*cos(2*l))")


def beta_polynomial_value(coeffs: BetaPolynomial, beta: ArrayLike) -> NDArray[np.float64]:
    """Evaluate a polynomial given by its rational coefficients of ``1, β, β², …``.

    Parameters
    ----------
    coeffs : tuple of Fraction
    beta : array_like

    Returns
    -------
    ndarray
        Same shape as ``beta``.

    Examples
    --------
    >>> float(beta_polynomial_value((Fraction(3, 4), 0, Fraction(9, 32)), 0.5))
    0.8203125
    """
    b = as_finite(beta, "beta")
    out = np.zeros_like(b)
    for c in reversed(coeffs):
        out = out * b + float(c)
    return out


def _as_beta_polynomial(series: PoissonSeries, monomial: PoissonSeries) -> BetaPolynomial:
    """Exact polynomial P(β) with ``series = P(β) · monomial`` (s² = 1 − β² expanded)."""
    R = series.ring
    ratio = series * monomial.inverse()
    coeffs: dict[int, Fraction] = {}
    i_beta, i_s = R.poly_names.index("beta"), R.poly_names.index("s")
    for t in ratio.terms():
        others = [e for j, e in enumerate(t.exponents) if j not in (i_beta, i_s)]
        e_s = t.exponents[i_s]
        if any(others) or any(t.harmonics) or e_s < 0 or e_s % 2:
            msg = f"expected a polynomial in beta times {monomial}, got {series}"
            raise ValueError(msg)
        half = e_s // 2  # s^(2h) = (1 − β²)^h
        for j in range(half + 1):
            power = t.exponents[i_beta] + 2 * j
            coeffs[power] = coeffs.get(power, Fraction(0)) + t.coeff * comb(half, j) * (-1) ** j
    top = max((p for p, c in coeffs.items() if c), default=-1)
    return tuple(coeffs.get(p, Fraction(0)) for p in range(top + 1))


def _divide_by_beta_power(poly: BetaPolynomial, m: int, sign: int) -> BetaPolynomial:
    if any(poly[:m]):
        msg = f"expected a polynomial divisible by beta^{m}, got coefficients {poly}"
        raise ValueError(msg)
    return tuple(c * sign for c in poly[m:])


@dataclass(frozen=True)
class SAMTheory:
    """Lara's SAM theory to Deprit order ``N``: exact polynomials and vectorised evaluation.

    Attributes
    ----------
    order : int
        Deprit order ``N``: ``q_i`` for ``i ≤ N − 1``, the transformation for ``i ≤ N``.
    transform : LieTransform
        The normalising transformation, with ``new_hamiltonian`` ``(K₀, …, K_N)``.
    q, g, l, L : dict
        ``q[i]``, ``g[(i, m)]``, ``l[(i, m)]``, ``L[(i, m)]`` (``m = 0`` for ``L_(i,0)``):
        coefficient tuples of ``1, β, β², …`` (eqs. 30, 32–34).

    Examples
    --------
    >>> theory = sam_theory(3)
    >>> theory.q[1], theory.l[(1, 1)], theory.g[(1, 1)], theory.L[(2, 0)]
    ((Fraction(1, 2),), (Fraction(1, 2),), (Fraction(1, 4),), (Fraction(1, 4),))
    """

    order: int
    transform: LieTransform
    q: dict[int, BetaPolynomial]
    g: dict[tuple[int, int], BetaPolynomial]
    l: dict[tuple[int, int], BetaPolynomial]
    L: dict[tuple[int, int], BetaPolynomial]
    _compiled: dict[str, CompiledSeries] = field(default_factory=dict, repr=False, compare=False)

    def _series(self, name: str) -> CompiledSeries:
        if name not in self._compiled:
            T = self.transform
            series = {
                "T": lambda: lie_sum(T.new_hamiltonian),
                "n_l": lambda: lie_sum(T.new_hamiltonian).diff("L"),
                "n_g": lambda: lie_sum(T.new_hamiltonian).diff("G"),
                "dl": lambda: lie_sum(T.direct_angle("l")),
                "dg": lambda: lie_sum(T.direct_angle("g")),
                "L": lambda: lie_sum(T.direct("L")),
                "il": lambda: lie_sum(T.inverse_angle("l")),
                "ig": lambda: lie_sum(T.inverse_angle("g")),
                "iL": lambda: lie_sum(T.inverse("L")),
            }[name]()
            self._compiled[name] = series.compile()
        return self._compiled[name]

    def _args(self, alpha: ArrayLike, beta: ArrayLike, C: ArrayLike) -> dict[str, Any]:
        # β < 0 and α < 0 arise for other axis labellings (LAM: α* < 0, β = −β*); the series
        # are polynomials in β and s = √(1 − β²), valid for |β| < 1.
        b = np.asarray(beta, dtype=np.float64)
        if not np.all(np.abs(b) < 1):
            msg = f"expected -1 < beta < 1, got {b[~(np.abs(b) < 1)].flat[0]!r}"
            raise ValueError(msg)
        a, c = np.asarray(alpha, dtype=np.float64), np.asarray(C, dtype=np.float64)
        if not (np.all(a != 0) and np.all(c > 0)):
            msg = "expected alpha != 0 and C > 0, got alpha = 0 or C <= 0"
            raise ValueError(msg)
        return {"alpha": a, "beta": b, "s": np.sqrt((1 - b) * (1 + b)), "C": c}

    def secular_hamiltonian(
        self, L: ArrayLike, G: ArrayLike, alpha: ArrayLike, beta: ArrayLike, C: ArrayLike
    ) -> NDArray[np.float64]:
        """The averaged Hamiltonian ``T(L', G')`` of eq. 30 (broadcast arrays).

        Parameters
        ----------
        L, G : array_like
            New momenta ``L'``, ``G'``.
        alpha, beta, C : array_like
            Andoyer's parameters and the largest moment of inertia.

        Returns
        -------
        ndarray

        Examples
        --------
        >>> round(float(sam_theory(3).secular_hamiltonian(0.01, 1.0, 0.1, 0.5, 2.0)), 12)
        0.250430509041
        """
        return self._series("T")(L=L, G=G, **self._args(alpha, beta, C))

    def frequencies(
        self, L: ArrayLike, G: ArrayLike, alpha: ArrayLike, beta: ArrayLike, C: ArrayLike
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Secular frequencies ``(n_ℓ, n_g) = (∂T/∂L', ∂T/∂G')``.

        Parameters
        ----------
        L, G, alpha, beta, C : array_like
            As in :meth:`secular_hamiltonian`.

        Returns
        -------
        (ndarray, ndarray)

        Examples
        --------
        >>> n_l, n_g = sam_theory(3).frequencies(0.0, 1.0, 0.1, 0.6, 2.0)
        >>> float(n_l), float(n_g)    # α s G / C and G / C at L' = 0
        (0.04, 0.5)
        """
        args = self._args(alpha, beta, C)
        return self._series("n_l")(L=L, G=G, **args), self._series("n_g")(L=L, G=G, **args)

    def direct(
        self,
        l_sam: ArrayLike,
        g_sam: ArrayLike,
        L_sam: ArrayLike,
        G_sam: ArrayLike,
        *,
        alpha: ArrayLike,
        beta: ArrayLike,
        C: ArrayLike,
    ) -> tuple[NDArray[np.float64], ...]:
        """Old SAM variables ``(ℓ, g, L, G)`` from new ones ``(ℓ', g', L', G')`` (eqs. 32–34).

        Parameters
        ----------
        l_sam, g_sam, L_sam, G_sam : array_like
            New (averaged) variables.
        alpha, beta, C : array_like

        Returns
        -------
        tuple of 4 ndarray

        Examples
        --------
        >>> l, g, L, G = sam_theory(2).direct(0.3, 0.0, 0.0, 1.0, alpha=0.1, beta=0.5, C=2.0)
        >>> float(l), float(L)
        (0.3, 0.0)
        """
        v = {"l": l_sam, "g": g_sam, "L": L_sam, "G": G_sam, **self._args(alpha, beta, C)}
        l_old = np.asarray(l_sam, dtype=np.float64) + self._series("dl")(**v)
        g_old = np.asarray(g_sam, dtype=np.float64) + self._series("dg")(**v)
        G_old = np.asarray(G_sam, dtype=np.float64) + np.zeros_like(l_old)
        return l_old, g_old, self._series("L")(**v), G_old

    def inverse(
        self,
        l_sam: ArrayLike,
        g_sam: ArrayLike,
        L_sam: ArrayLike,
        G_sam: ArrayLike,
        *,
        alpha: ArrayLike,
        beta: ArrayLike,
        C: ArrayLike,
    ) -> tuple[NDArray[np.float64], ...]:
        """New variables ``(ℓ', g', L', G')`` from old ones (inverse Lie transformation).

        Parameters
        ----------
        l_sam, g_sam, L_sam, G_sam : array_like
            Old variables ``(ℓ, g, L, G)``.
        alpha, beta, C : array_like

        Returns
        -------
        tuple of 4 ndarray

        Examples
        --------
        >>> T = sam_theory(3)
        >>> new = T.inverse(0.3, 0.2, 0.01, 1.0, alpha=0.1, beta=0.5, C=2.0)
        >>> old = T.direct(*new, alpha=0.1, beta=0.5, C=2.0)
        >>> bool(abs(old[0] - 0.3) < 1e-8 and abs(old[2] - 0.01) < 1e-8)  # O(δ⁴), δ ≈ 0.012
        True
        """
        v = {"l": l_sam, "g": g_sam, "L": L_sam, "G": G_sam, **self._args(alpha, beta, C)}
        l_new = np.asarray(l_sam, dtype=np.float64) + self._series("il")(**v)
        g_new = np.asarray(g_sam, dtype=np.float64) + self._series("ig")(**v)
        G_new = np.asarray(G_sam, dtype=np.float64) + np.zeros_like(l_new)
        return l_new, g_new, self._series("iL")(**v), G_new


def _tables(T: LieTransform) -> dict[str, dict[Any, BetaPolynomial]]:
    R = SAM_RING
    N = T.order
    q = {}
    for n in range(2, N + 1):
        i = n - 1
        # K_n/n! = −(G²/2C) α x² β² δ^i q_i  with x = L/G, δ = x/s
        mono = R(f"alpha/(2*C) * L**{i + 2} * G**{-i} * s**{-i}")
        poly = _as_beta_polynomial(T.new_hamiltonian[n] / factorial(n), mono)
        q[i] = _divide_by_beta_power(poly, 2, -1)
    dl, dg, dL = T.direct_angle("l"), T.direct_angle("g"), T.direct("L")
    g_tab, l_tab, L_tab = {}, {}, {}
    for i in range(1, N + 1):
        delta_i = R(f"L**{i} * G**{-i} * s**{-i}")
        terms = {name: series[i] / factorial(i) for name, series in (("l", dl), ("g", dg), ("L", dL))}
        # One coefficient per harmonic 2mℓ (each harmonic carries many monomials).
        harmonics = {name: sorted({t.harmonics[0] // 2 for t in f.terms()}) for name, f in terms.items()}
        for m in harmonics["l"]:
            coeff = terms["l"].trig_coefficient("sin", [2 * m, 0])
            l_tab[(i, m)] = _divide_by_beta_power(_as_beta_polynomial(coeff, delta_i), m, (-1) ** m)
        for m in harmonics["g"]:
            coeff = terms["g"].trig_coefficient("sin", [2 * m, 0])
            poly = _as_beta_polynomial(coeff, delta_i * R("L/G"))
            g_tab[(i, m)] = _divide_by_beta_power(poly, m, -((-1) ** m))
        for m in harmonics["L"]:
            coeff = terms["L"].trig_coefficient("cos", [2 * m, 0])
            poly = _as_beta_polynomial(coeff, delta_i * R("L"))
            if m == 0:
                L_tab[(i, 0)] = _divide_by_beta_power(poly, 2, 1)
            else:
                L_tab[(i, m)] = _divide_by_beta_power(poly, m, -((-1) ** m))
        bad = [t for s in terms.values() for t in s.terms() if t.harmonics[1] or t.harmonics[0] % 2]
        if bad:
            msg = f"expected harmonics 2mℓ only in the SAM transformation, got {bad[0]}"
            raise AssertionError(msg)
    return {"q": q, "g": g_tab, "l": l_tab, "L": L_tab}


@lru_cache(maxsize=8)
def sam_theory(order: int = 12) -> SAMTheory:
    """Compute Lara's SAM theory to Deprit order ``order`` (cached).

    Parameters
    ----------
    order : int
        ``N ≥ 1``; the paper tabulates ``q_i`` to ``i = 10`` and the transformation to ``i = 9``
        (``N = 11``); ``N = 12`` takes a fraction of a second; at most :data:`MAX_ORDER`.

    Returns
    -------
    SAMTheory

    Examples
    --------
    >>> sam_theory(6).q[5]
    (Fraction(1, 1), Fraction(0, 1), Fraction(177, 64), Fraction(0, 1), Fraction(45, 128))
    """
    check_order(order)
    T = deprit(list(sam_hamiltonian()), order, ["l"])
    tables = _tables(T)
    return SAMTheory(order, T, tables["q"], tables["g"], tables["l"], tables["L"])
