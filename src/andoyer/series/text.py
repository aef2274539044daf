"""The text form of Poisson series: Python syntax such as ``"L**2/2*cos(2*l - g)"``.

:func:`series_to_text` writes it and :func:`parse_series` reads it back exactly.  The parser
walks the syntax tree (it never calls ``eval``) and accepts integers, ring
variables, ``+ - * / **`` (division by rationals or monomials, integer powers) and
``cos``/``sin`` of integer combinations of the angles.
"""

from __future__ import annotations

import ast
from collections.abc import Sequence
from typing import TYPE_CHECKING

from andoyer.series.components import Ring, Series

if TYPE_CHECKING:
    from andoyer.series.terms import Term

__all__ = ["parse_series", "series_to_text"]


def _linear_text(names: Sequence[str], k: Sequence[int]) -> str:
    out = ""
    for name, v in zip(names, k, strict=True):
        if not v:
            continue
        mag = name if abs(v) == 1 else f"{abs(v)}*{name}"
        if not out:
            out = mag if v > 0 else f"-{mag}"
        else:
            out += f" + {mag}" if v > 0 else f" - {mag}"
    return out


def _term_text(ring: Ring, t: Term) -> str:
    factors = [
        name if e == 1 else f"{name}**{e}" for name, e in zip(ring.poly_names, t.exponents, strict=True) if e
    ]
    if any(t.harmonics):
        factors.append(f"{t.kind}({_linear_text(ring.angles, t.harmonics)})")
    c = t.coeff
    if not factors:
        return str(c)
    body = "*".join(factors)
    if c == 1:
        return body
    if c == -1:
        return f"-{body}"
    return f"{c}*{body}"


def series_to_text(f: Series) -> str:
    """Plain-text form that :meth:`PoissonRing.__call__` parses back exactly.

    Parameters
    ----------
    f : PoissonSeries

    Returns
    -------
    str

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l", "g"], ["L", "G"])
    >>> series_to_text(R("-L/2*sin(l - 2*g) + 3"))
    '3 - 1/2*L*sin(l - 2*g)'
    """
    out = ""
    for t in f.terms():
        part = _term_text(f.ring, t)
        if not out:
            out = part
        elif part.startswith("-"):
            out += f" - {part[1:]}"
        else:
            out += f" + {part}"
    return out or "0"


def parse_series(ring: Ring, text: str) -> Series:
    """Parse a series expression written in Python syntax.

    Parameters
    ----------
    ring : PoissonRing
    text : str

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> parse_series(PoissonRing(["q"], ["p"]), "(p + 1)**2 * sin(q)**2")
    1/2 + p + 1/2*p**2 - 1/2*cos(2*q) - p*cos(2*q) - 1/2*p**2*cos(2*q)
    """
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        msg = f"expected a series expression in Python syntax, got {text!r} ({exc.msg})"
        raise ValueError(msg) from None
    return _Parser(ring, text).visit(tree.body)


class _Parser:
    def __init__(self, ring: Ring, text: str) -> None:
        self.ring = ring
        self.text = text

    def fail(self, node: ast.AST, what: str) -> ValueError:
        part = ast.get_source_segment(self.text.strip(), node) or ast.dump(node)
        return ValueError(f"expected {what}, got {part!r} in {self.text!r}")

    def visit(self, node: ast.AST) -> Series:
        ring = self.ring
        if isinstance(node, ast.Constant):
            if isinstance(node.value, int) and not isinstance(node.value, bool):
                return ring.constant(node.value)
            raise self.fail(node, "an integer constant (write rationals as p/q)")
        if isinstance(node, ast.Name):
            if node.id in ring.angles:
                raise self.fail(node, "angles only inside cos() or sin()")
            if node.id not in ring.poly_names:
                raise self.fail(node, f"a variable of {ring.variables}")
            return ring.gen(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            value = self.visit(node.operand)
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.BinOp):
            return self.binop(node)
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id in ("cos", "sin")
            and len(node.args) == 1
            and not node.keywords
        ):
            k = self.linear(node.args[0])
            return ring.cos(k) if node.func.id == "cos" else ring.sin(k)
        raise self.fail(node, "a Poisson-series expression")

    def binop(self, node: ast.BinOp) -> Series:
        if isinstance(node.op, ast.Pow):
            n = self.integer(node.right)
            return self.visit(node.left) ** n
        left, right = self.visit(node.left), self.visit(node.right)
        if isinstance(node.op, ast.Add):
            return left + right
        if isinstance(node.op, ast.Sub):
            return left - right
        if isinstance(node.op, ast.Mult):
            return left * right
        if isinstance(node.op, ast.Div):
            if not right.is_unit():
                raise self.fail(node.right, "a divisor that is a rational times a monomial")
            return left / right
        raise self.fail(node, "one of + - * / **")

    def integer(self, node: ast.AST) -> int:
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            return -self.integer(node.operand)
        if isinstance(node, ast.Constant) and type(node.value) is int:
            return node.value
        raise self.fail(node, "an integer exponent")

    def linear(self, node: ast.AST) -> tuple[int, ...]:
        k = self._linear(node)
        if k.pop("", 0):
            raise self.fail(node, "no constant phase in the trigonometric argument")
        return tuple(k.get(a, 0) for a in self.ring.angles)

    def _linear(self, node: ast.AST) -> dict[str, int]:
        if isinstance(node, ast.Name) and node.id in self.ring.angles:
            return {node.id: 1}
        if isinstance(node, ast.Constant) and type(node.value) is int:
            return {"": node.value}
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            sign = -1 if isinstance(node.op, ast.USub) else 1
            return {a: sign * v for a, v in self._linear(node.operand).items()}
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
            sign = -1 if isinstance(node.op, ast.Sub) else 1
            out = self._linear(node.left)
            for a, v in self._linear(node.right).items():
                out[a] = out.get(a, 0) + sign * v
            return out
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult):
            for factor, other in ((node.left, node.right), (node.right, node.left)):
                if isinstance(factor, ast.Constant) and type(factor.value) is int:
                    return {a: factor.value * v for a, v in self._linear(other).items()}
        raise self.fail(node, f"an integer combination of the angles {self.ring.angles}")
