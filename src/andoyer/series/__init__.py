"""Exact Poisson series and Deprit's Lie-transform engine.

A :class:`PoissonRing` declares angles, momenta, parameters, canonical pairs, quadratic
relations and truncation weights; a :class:`PoissonSeries` is an exact sum of rational
coefficient × Laurent monomial × ``cos``/``sin`` of an integer combination of angles.
:func:`deprit` normalises a Hamiltonian ``H = Σ εⁿ/n! Hₙ`` to any order.

Examples
--------
>>> from andoyer.series import PoissonRing
>>> R = PoissonRing(["q"], ["p"])
>>> f = R("p * cos(q)")
>>> f.bracket(R("p**2/2")), f.average(), (f * f).average()
(-p**2*sin(q), 0, 1/2*p**2)
"""

from andoyer.series.averaging import average, frequencies, solve_homological
from andoyer.series.bracket import derivative, poisson_bracket
from andoyer.series.deprit import LieTransform, deprit, lie_sum
from andoyer.series.numeric import CompiledSeries
from andoyer.series.poisson import PoissonRing, PoissonSeries
from andoyer.series.terms import Term

__all__ = [
    "CompiledSeries",
    "LieTransform",
    "PoissonRing",
    "PoissonSeries",
    "Term",
    "average",
    "deprit",
    "derivative",
    "frequencies",
    "lie_sum",
    "poisson_bracket",
    "solve_homological",
]
