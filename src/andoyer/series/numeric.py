"""Compile Poisson series to vectorised numpy functions.

The series is turned once into Python source that evaluates the monomials from tables of
powers and each distinct trigonometric argument once, then compiled; calls broadcast their
arguments like any numpy expression.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.series.components import Series

__all__ = ["CompiledSeries"]

_CHUNK = 16  # terms per source line: short lines keep the compiler's recursion shallow


def _power_name(name: str, e: int) -> str:
    return f"v_{name}" if e == 1 else (f"p_{name}_{e}" if e > 0 else f"m_{name}_{-e}")


def _source(f: Series, used: tuple[str, ...]) -> str:
    ring = f.ring
    lines = [f"def _evaluate({', '.join('v_' + n for n in used)}):"]
    powers: dict[str, set[int]] = {}
    groups: dict[tuple[str, tuple[int, ...]], list[str]] = {}
    for t in f.terms():
        factors = [repr(float(t.coeff))]
        for name, e in zip(ring.poly_names, t.exponents, strict=True):
            if e:
                powers.setdefault(name, set()).add(e)
                factors.append(_power_name(name, e))
        groups.setdefault((t.kind, t.harmonics), []).append("*".join(factors))
    for name, exps in powers.items():
        top, bottom = max(*exps, 0), min(*exps, 0)
        lines.extend(
            f"    p_{name}_{e} = {'v_' + name if e == 2 else f'p_{name}_{e - 1}'} * v_{name}"
            for e in range(2, top + 1)
        )
        if bottom < 0:
            lines.append(f"    m_{name}_1 = 1.0 / v_{name}")
        lines.extend(f"    m_{name}_{e} = m_{name}_{e - 1} * m_{name}_1" for e in range(2, -bottom + 1))
    lines.append("    acc = 0.0")
    for (kind, k), parts in groups.items():
        lines.append("    h = 0.0")
        lines.extend(
            f"    h = h + ({' + '.join(parts[start : start + _CHUNK])})"
            for start in range(0, len(parts), _CHUNK)
        )
        if any(k):
            arg = " + ".join(f"{v} * v_{a}" for a, v in zip(ring.angles, k, strict=True) if v)
            lines.append(f"    acc = acc + h * np.{kind}({arg})")
        else:
            lines.append("    acc = acc + h")
    lines.append("    return acc")
    return "\n".join(lines) + "\n"


class CompiledSeries:
    """A Poisson series compiled to a vectorised float64 numpy function.

    Parameters
    ----------
    series : PoissonSeries

    Attributes
    ----------
    variables : tuple of str
        Accepted argument names, in positional order (``ring.variables``).
    used : tuple of str
        The variables the series depends on (the others may be omitted).
    source : str
        The generated Python source.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"], ["a"])
    >>> f = CompiledSeries(R("a*p**-1*sin(q) + 1"))
    >>> f(q=[[0.0], [1.5707963267948966]], p=[1.0, 2.0], a=3.0)
    array([[1. , 1. ],
           [4. , 2.5]])
    """

    def __init__(self, series: Series) -> None:
        self.series = series
        self.variables = series.ring.variables
        self.used = series.variables()
        self.source = _source(series, self.used)
        namespace: dict[str, Any] = {"np": np}
        exec(compile(self.source, "<andoyer.series.compiled>", "exec"), namespace)
        self._evaluate = namespace["_evaluate"]

    def __call__(self, *args: ArrayLike, **kwargs: ArrayLike) -> NDArray[np.float64]:
        """Evaluate at broadcast arrays given positionally or by name."""
        if len(args) > len(self.variables):
            msg = f"expected at most {len(self.variables)} positional values, got {len(args)}"
            raise ValueError(msg)
        values = dict(zip(self.variables, args, strict=False))
        for name, v in kwargs.items():
            if name not in self.variables or name in values:
                msg = f"expected one value per variable of {self.variables}, got {name!r} again"
                if name not in self.variables:
                    msg = f"expected variables of {self.variables}, got {name!r}"
                raise ValueError(msg)
            values[name] = v
        missing = [n for n in self.used if n not in values]
        if missing:
            msg = f"expected values for {list(self.used)}, got none for {missing}"
            raise ValueError(msg)
        arrays = {n: np.asarray(v, dtype=np.float64) for n, v in values.items()}
        try:
            shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
        except ValueError:
            shapes = ", ".join(f"{n} {a.shape}" for n, a in arrays.items())
            msg = f"expected shapes that broadcast together, got {shapes}"
            raise ValueError(msg) from None
        out = self._evaluate(*(arrays[n] for n in self.used))
        return np.asarray(out, dtype=np.float64) + np.zeros(shape)

    def __repr__(self) -> str:
        return f"CompiledSeries({self.series!r})"
