r"""Lara's triaxiality polynomials as tables: JSON, Markdown and LaTeX (the paper's Tables 2–5).

Normalisation of eqs. 30–34, ``δ = (L'/G')/√(1 − β²)``:

    T = G'²/(2C) [1 + 2α s x − α x² (1 + β² Σ δ^i q_i)],
    g = g' − x Σ δ^i Σ_m (−β)^m g_(i,m) sin 2mℓ',   ℓ = ℓ' + Σ δ^i Σ_m (−β)^m ℓ_(i,m) sin 2mℓ',
    L = L' + L' Σ δ^i (β² L_(i,0) − Σ_m (−β)^m L_(i,m) cos 2mℓ'),

with ``x = L'/G'``.  A table of order ``n`` holds every polynomial with index ``i ≤ n``; it comes
from Deprit order ``n + 1`` (``q_i`` enters the Hamiltonian at order ``i + 1``).

JSON schema: ``{"q": {i: {"0": P}}, "g": {i: {m: P}}, "l": {i: {m: P}}, "L": {i: {m: P}}}``,
``i`` and ``m`` decimal strings, ``P`` a map from the power of β (a decimal string) to the exact
rational coefficient ``"p/q"`` (``q ≥ 1``; zero coefficients are omitted).
"""

from __future__ import annotations

import json
import re
from fractions import Fraction
from typing import Any

from andoyer.theories.sam import check_order, sam_theory

__all__ = [
    "FAMILIES",
    "sam_tables",
    "tables_from_json",
    "tables_to_json",
    "tables_to_latex",
    "tables_to_markdown",
]

#: Table families, in the order of eqs. 30–34.
FAMILIES = ("q", "g", "l", "L")
Polynomial = dict[int, Fraction]
Tables = dict[str, dict[int, dict[int, Polynomial]]]

_TITLES = {
    "q": ("q_i", "eq. 30, averaged Hamiltonian"),
    "g": ("g_(i,m)", "eq. 32, transformation of g"),
    "l": ("ℓ_(i,m)", "eq. 33, transformation of ℓ"),
    "L": ("L_(i,m)", "eq. 34, transformation of L; m = 0 is the coefficient of β²"),
}
_TEX = {"q": "q_{{{i}}}", "g": "g_{{{i},{m}}}", "l": r"\ell_{{{i},{m}}}", "L": "L_{{{i},{m}}}"}
_RATIONAL = re.compile(r"-?\d+/[1-9]\d*")
_SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def sam_tables(order: int) -> Tables:
    """The polynomials ``q_i, g_(i,m), ℓ_(i,m), L_(i,m)`` for ``1 ≤ i ≤ order``, exact.

    Parameters
    ----------
    order : int
        Highest index ``i`` (``≥ 1``, at most ``MAX_ORDER − 1`` = 60: see
        :data:`andoyer.theories.sam.MAX_ORDER`).

    Returns
    -------
    dict
        ``tables[family][i][m] = {power of β: Fraction}`` (``m = 0`` for ``q``).

    Examples
    --------
    >>> t = sam_tables(3)
    >>> t["q"][3][0]
    {0: Fraction(3, 4), 2: Fraction(9, 32)}
    >>> t["L"][2][0], t["l"][1][1]
    ({0: Fraction(1, 4)}, {0: Fraction(1, 2)})
    """
    check_order(order, offset=1)  # from Deprit order + 1
    theory = sam_theory(order + 1)

    def poly(coeffs: tuple[Fraction, ...]) -> Polynomial:
        return {p: Fraction(c) for p, c in enumerate(coeffs) if c}

    out: Tables = {name: {} for name in FAMILIES}
    for i, coeffs in theory.q.items():
        if i <= order:
            out["q"][i] = {0: poly(coeffs)}
    for name in ("g", "l", "L"):
        for (i, m), coeffs in sorted(getattr(theory, name).items()):
            if i <= order:
                out[name].setdefault(i, {})[m] = poly(coeffs)
    return out


def tables_to_json(tables: Tables, indent: int | None = 2) -> str:
    """Serialise :func:`sam_tables` to the JSON schema of this module.

    Examples
    --------
    >>> doc = json.loads(tables_to_json(sam_tables(1)))
    >>> doc["q"], doc["g"]
    ({'1': {'0': {'0': '1/2'}}}, {'1': {'1': {'0': '1/4'}}})
    """
    doc = {
        name: {
            str(i): {
                str(m): {str(p): f"{c.numerator}/{c.denominator}" for p, c in sorted(poly.items())}
                for m, poly in sorted(row.items())
            }
            for i, row in sorted(tables[name].items())
        }
        for name in FAMILIES
    }
    return json.dumps(doc, indent=indent, ensure_ascii=False)


def _key(text: Any, what: str) -> int:
    if not isinstance(text, str) or not text.isdigit():
        msg = f"expected {what} as a decimal string, got {text!r}"
        raise ValueError(msg)
    return int(text)


def tables_from_json(text: str) -> Tables:
    """Parse the JSON of :func:`tables_to_json` back to exact Fractions (schema checked).

    Examples
    --------
    >>> tables_from_json(tables_to_json(sam_tables(2))) == sam_tables(2)
    True
    """
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        msg = f"expected a JSON document, got invalid JSON ({exc.msg})"
        raise ValueError(msg) from exc
    if not isinstance(doc, dict) or set(doc) != set(FAMILIES):
        got = sorted(doc) if isinstance(doc, dict) else type(doc).__name__
        msg = f"expected an object with keys {list(FAMILIES)}, got {got}"
        raise ValueError(msg)
    out: Tables = {}
    for name in FAMILIES:
        out[name] = {}
        for i, row in doc[name].items():
            out[name][_key(i, "index i")] = {}
            for m, poly in row.items():
                coeffs = {}
                for p, c in poly.items():
                    if not isinstance(c, str) or not _RATIONAL.fullmatch(c):
                        msg = f"expected a rational 'p/q' for {name}[{i}][{m}][{p}], got {c!r}"
                        raise ValueError(msg)
                    coeffs[_key(p, "power of beta")] = Fraction(c)
                out[name][int(i)][_key(m, "harmonic m")] = coeffs
    return out


def _plain(poly: Polynomial) -> str:
    parts = []
    for p, c in sorted(poly.items()):
        mag = abs(c)
        body = (
            str(mag)
            if p == 0
            else ("" if mag == 1 else f"{mag} ") + ("β" if p == 1 else f"β{str(p).translate(_SUPERSCRIPT)}")
        )
        parts.append(("− " if c < 0 else "+ ") + body)
    text = " ".join(parts) or "+ 0"
    return text[2:] if text.startswith("+ ") else "−" + text[2:]


def _tex(poly: Polynomial) -> str:
    parts = []
    for p, c in sorted(poly.items()):
        mag = abs(c)
        coeff = (
            str(mag.numerator) if mag.denominator == 1 else rf"\frac{{{mag.numerator}}}{{{mag.denominator}}}"
        )
        if p:
            coeff = ("" if mag == 1 else coeff) + (r"\beta" if p == 1 else rf"\beta^{{{p}}}")
        parts.append(("-" if c < 0 else "+") + " " + coeff)
    text = " ".join(parts) or "+ 0"
    return text[2:] if text.startswith("+ ") else text


def tables_to_markdown(tables: Tables) -> str:
    """Readable Markdown tables, one per family, rows ``(i, m)``.

    Examples
    --------
    >>> print(tables_to_markdown(sam_tables(3)).split(2 * chr(10))[1])
    | i | q_i |
    | ---: | :--- |
    | 1 | 1/2 |
    | 2 | 5/8 |
    | 3 | 3/4 + 9/32 β² |
    """
    blocks = ["# Triaxiality polynomials of Lara's SAM theory (δ = (L'/G')/√(1 − β²))"]
    for name in FAMILIES:
        symbol, caption = _TITLES[name]
        if name == "q":
            lines = [f"| i | {symbol} |", "| ---: | :--- |"]
            lines += [f"| {i} | {_plain(row[0])} |" for i, row in sorted(tables[name].items())]
        else:
            lines = [f"| i | m | {symbol} |", "| ---: | ---: | :--- |"]
            lines += [
                f"| {i} | {m} | {_plain(poly)} |"
                for i, row in sorted(tables[name].items())
                for m, poly in sorted(row.items())
            ]
        blocks.append("\n".join(lines))
        blocks.append(f"*{symbol}: {caption}.*")
    return "\n\n".join(blocks) + "\n"


def tables_to_latex(tables: Tables) -> str:
    r"""One LaTeX ``tabular`` per family (plain LaTeX), preceded by a comment naming it.

    Examples
    --------
    >>> print(tables_to_latex(sam_tables(3)).splitlines()[5])
    3 & $\frac{3}{4} + \frac{9}{32}\beta^{2}$ \\
    """
    out = []
    for name in FAMILIES:
        symbol, caption = _TITLES[name]
        if name == "q":
            out += [f"% {symbol}: {caption}", r"\begin{tabular}{rl}", r"$i$ & $q_i(\beta)$ \\ \hline"]
            out += [f"{i} & ${_tex(row[0])}$ \\\\" for i, row in sorted(tables[name].items())]
        else:
            head = _TEX[name].format(i="i", m="m")
            out += [
                f"% {name}_(i,m): {caption.replace('ℓ', 'l')}",
                r"\begin{tabular}{rrl}",
                rf"$i$ & $m$ & ${head}(\beta)$ \\ \hline",
            ]
            out += [
                f"{i} & {m} & ${_tex(poly)}$ \\\\"
                for i, row in sorted(tables[name].items())
                for m, poly in sorted(row.items())
            ]
        out += [r"\end{tabular}", ""]
    return "\n".join(out)
