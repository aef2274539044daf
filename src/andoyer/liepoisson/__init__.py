"""Lie–Poisson layer: so(3), e(3), l(7), their Casimirs and Pavlov's canonical coordinates.

Numeric part (numpy only):

* :func:`get_algebra` → :class:`LiePoissonAlgebra` (brackets from gradients,
  Hamiltonian vector fields, Casimirs);
* Andoyer–Deprit coordinates on the leaves: :func:`so3_to_andoyer`,
  :func:`so3_from_andoyer`, :func:`e3_to_andoyer`, :func:`e3_from_andoyer`,
  :func:`l7_to_andoyer`, :func:`l7_from_andoyer`;
* the heavy top on an e(3) leaf in ``(l, g, L, G; H)``: :func:`heavy_top_hamiltonian`,
  :func:`heavy_top_equations` (→ :class:`LeafRates`), :func:`heavy_top_rhs`;
* Pavlov's quaternion λ = (w, x, y, z): :func:`quaternion_from_scipy`,
  :func:`quaternion_to_scipy`, :func:`gamma_from_quaternion`.

Symbolic part (needs sympy, imported on first use):

* :class:`CanonicalCoordinates`, :func:`andoyer_coordinates`, :func:`euler_coordinates`;
* the canonicity checker :func:`check_coordinates`, :func:`check_poisson_map`,
  :func:`bracket_table` (records :class:`BracketRecord`);
* Pavlov's tables :func:`pavlov_table`, :func:`check_pavlov_table`; Andoyer's method
  :func:`andoyer_momenta`, :func:`euler_momenta`.

Sign convention: ``{m1, m2} = -m3`` (Gurfil et al. eq. 28), ``{m_i, γ_j} = -ε_ijk γ_k``,
``{q, p} = +1``; ``ẋ = {x, K}``. See ``docs/liepoisson.md``.
"""

from __future__ import annotations

import importlib
from typing import Any

from andoyer.liepoisson._domain import SINGULAR_TOL, UNIT_TOL, SingularChartWarning
from andoyer.liepoisson.algebra import ALGEBRA_NAMES, Casimir, LiePoissonAlgebra, get_algebra
from andoyer.liepoisson.heavy_top import (
    LeafRates,
    heavy_top_equations,
    heavy_top_hamiltonian,
    heavy_top_rhs,
)
from andoyer.liepoisson.pavlov_e3 import (
    E3Coordinates,
    So3Coordinates,
    e3_from_andoyer,
    e3_to_andoyer,
    so3_from_andoyer,
    so3_to_andoyer,
)
from andoyer.liepoisson.pavlov_l7 import L7Coordinates, l7_from_andoyer, l7_to_andoyer
from andoyer.liepoisson.quaternion import (
    gamma_from_quaternion,
    quaternion_from_scipy,
    quaternion_to_scipy,
)

_SYMBOLIC = {
    "CanonicalCoordinates": "coordinates",
    "andoyer_coordinates": "coordinates",
    "andoyer_symbols": "coordinates",
    "euler_coordinates": "coordinates",
    "BracketRecord": "canonicity",
    "bracket_table": "canonicity",
    "check_coordinates": "canonicity",
    "check_poisson_map": "canonicity",
    "TableEntry": "pavlov_tables",
    "check_pavlov_table": "pavlov_tables",
    "pavlov_table": "pavlov_tables",
    "andoyer_momenta": "andoyer_method",
    "euler_momenta": "andoyer_method",
}

__all__ = [
    "ALGEBRA_NAMES",
    "SINGULAR_TOL",
    "UNIT_TOL",
    # symbolic (lazy)
    "BracketRecord",
    "CanonicalCoordinates",
    "Casimir",
    "E3Coordinates",
    "L7Coordinates",
    "LeafRates",
    "LiePoissonAlgebra",
    "SingularChartWarning",
    "So3Coordinates",
    "TableEntry",
    "andoyer_coordinates",
    "andoyer_momenta",
    "andoyer_symbols",
    "bracket_table",
    "check_coordinates",
    "check_pavlov_table",
    "check_poisson_map",
    "e3_from_andoyer",
    "e3_to_andoyer",
    "euler_coordinates",
    "euler_momenta",
    "gamma_from_quaternion",
    "get_algebra",
    "heavy_top_equations",
    "heavy_top_hamiltonian",
    "heavy_top_rhs",
    "l7_from_andoyer",
    "l7_to_andoyer",
    "pavlov_table",
    "quaternion_from_scipy",
    "quaternion_to_scipy",
    "so3_from_andoyer",
    "so3_to_andoyer",
]


def __getattr__(name: str) -> Any:
    """Import the sympy-based modules on first use."""
    if name in _SYMBOLIC:
        module = importlib.import_module(f"andoyer.liepoisson.{_SYMBOLIC[name]}")
        return getattr(module, name)
    if name == "AndoyerRates":  # deprecated name of LeafRates; the module warns
        return getattr(importlib.import_module("andoyer.liepoisson.heavy_top"), name)
    raise AttributeError(f"module 'andoyer.liepoisson' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
