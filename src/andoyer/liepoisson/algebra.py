r"""Lie–Poisson algebras so(3), e(3) and l(7) with linear Poisson tensors.

Every algebra here is a linear Poisson structure on R^n with generators
``x = (x_1, ..., x_n)`` and structure constants ``C``:

.. math::

    \\{F, K\\}(x) = \\sum_{a,b,c} C_{ab}^{\\;c}\\, x_c\\,
    \\frac{\\partial F}{\\partial x_a}\\frac{\\partial K}{\\partial x_b},
    \\qquad \\dot x = \\{x, K\\} = P(x)\\,\\nabla K,
    \\qquad P_{ab}(x) = \\sum_c C_{ab}^{\\;c} x_c .

The sign is the one of Gurfil et al. eq. 28 and Pavlov eqs. 1.1, 2.9 for the
body angular momentum ``m``: ``{m1, m2} = -m3`` (cyclic), and the canonical
bracket of the same library is ``{q, p} = +1``. Written with vectors:

* so(3):  ``{F, K} = -m·(∇F × ∇K)``;
* e(3):   ``{F, K} = -m·(∇_m F × ∇_m K) - γ·(∇_m F × ∇_γ K + ∇_γ F × ∇_m K)``,
  so ``{m_i, γ_j} = -ε_ijk γ_k``, ``{γ_i, γ_j} = 0``;
* l(7):   ``{m_i, λ} = -½ λ ⊗ (0, e_i)`` (quaternion product, λ = (λ0, λ1, λ2, λ3)
  scalar first), i.e. ``{m_i, λ0} = ½ λ_i``,
  ``{m_i, λ_j} = -½ (ε_ijk λ_k + δ_ij λ0)``, ``{λ_μ, λ_ν} = 0``.

With ``γ`` the reference axis s3 in body components and λ the quaternion of
the body-to-reference rotation, the Hamiltonian flows are the rigid-body
equations ``ṁ = m × ∇_m K + γ × ∇_γ K``, ``γ̇ = γ × ∇_m K`` and
``λ̇ = ½ λ ⊗ (0, ∇_m K)`` (``d rot/dt = rot·hat(ω)`` with ``ω = ∇_m K``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from andoyer.liepoisson._domain import as_components, leading_shape
from andoyer.liepoisson.casimirs import Casimir, quadratic_form
from andoyer.liepoisson.structure_constants import e3_structure, l7_structure, so3_structure

__all__ = ["ALGEBRA_NAMES", "Casimir", "LiePoissonAlgebra", "get_algebra"]

ALGEBRA_NAMES = ("so3", "e3", "l7")


@dataclass(frozen=True)
class LiePoissonAlgebra:
    """A linear (Lie–)Poisson structure with its Casimirs.

    Parameters
    ----------
    name : str
        ``"so3"``, ``"e3"`` or ``"l7"``.
    generators : tuple of str
        Names of the coordinates ``x_a`` (``m1``, ..., ``gamma1``, ..., ``lambda0``, ...).
    structure : numpy.ndarray, shape (n, n, n)
        Structure constants ``C[a, b, c]``, antisymmetric in ``a, b``.
    casimirs : tuple of Casimir
        Functions that commute with every function.
    unit_block : slice or None
        Generators constrained to the unit sphere on the physical leaves
        (γ for e(3), λ for l(7)); used by :meth:`sample`.

    Examples
    --------
    >>> import numpy as np
    >>> so3 = get_algebra("so3")
    >>> m = np.array([0.3, -1.2, 0.5])
    >>> float(so3.bracket(m, [1, 0, 0], [0, 1, 0]))  # {m1, m2} = -m3
    -0.5
    """

    name: str
    generators: tuple[str, ...]
    structure: np.ndarray = field(repr=False)
    casimirs: tuple[Casimir, ...] = field(repr=False)
    unit_block: slice | None = field(default=None, repr=False)

    @property
    def dim(self) -> int:
        """Number of generators ``n``.

        Examples
        --------
        >>> get_algebra("l7").dim
        7
        """
        return len(self.generators)

    def poisson_tensor(self, x: Any) -> np.ndarray:
        """Poisson tensor ``P(x)``.

        Parameters
        ----------
        x : array_like, shape (..., n)

        Returns
        -------
        numpy.ndarray, shape (..., n, n)
            ``P_ab(x) = Σ_c C[a, b, c] x_c``; ``P_ab = {x_a, x_b}``.

        Examples
        --------
        >>> get_algebra("so3").poisson_tensor([0.0, 0.0, 2.0])
        array([[ 0., -2.,  0.],
               [ 2.,  0.,  0.],
               [ 0.,  0.,  0.]])
        """
        x = as_components("x", x, self.dim)
        return np.einsum("abc,...c->...ab", self.structure, x)

    def bracket(self, x: Any, grad_f: Any, grad_k: Any) -> np.ndarray:
        """Bracket ``{F, K}(x) = ∇Fᵀ P(x) ∇K`` from gradients.

        Parameters
        ----------
        x, grad_f, grad_k : array_like, shape (..., n)
            Point and the gradients of ``F`` and ``K`` there; leading axes broadcast.

        Returns
        -------
        numpy.ndarray, shape (...)

        Examples
        --------
        >>> e3 = get_algebra("e3")
        >>> x = [0.0, 0.0, 0.0, 0.1, 0.2, 0.9]
        >>> float(e3.bracket(x, [1, 0, 0, 0, 0, 0], [0, 0, 0, 0, 1, 0]))  # {m1, γ2} = -γ3
        -0.9
        """
        x = as_components("x", x, self.dim)
        gf = as_components("grad_f", grad_f, self.dim)
        gk = as_components("grad_k", grad_k, self.dim)
        leading_shape(x=x, grad_f=gf, grad_k=gk)
        return np.einsum("abc,...c,...a,...b->...", self.structure, x, gf, gk)[()]

    def vector_field(self, x: Any, grad_k: Any) -> np.ndarray:
        """Hamiltonian vector field ``ẋ = P(x) ∇K``.

        Parameters
        ----------
        x, grad_k : array_like, shape (..., n)

        Returns
        -------
        numpy.ndarray, shape (..., n)

        Examples
        --------
        Free rigid body, ``K = ½ Σ m_i²/I_i``: ``ṁ = m × ω``.

        >>> import numpy as np
        >>> m, inertia = np.array([1.0, 2.0, 3.0]), np.array([1.0, 2.0, 4.0])
        >>> get_algebra("so3").vector_field(m, m / inertia)
        array([-1.5 ,  2.25, -1.  ])
        >>> np.cross(m, m / inertia)
        array([-1.5 ,  2.25, -1.  ])
        """
        x = as_components("x", x, self.dim)
        gk = as_components("grad_k", grad_k, self.dim)
        leading_shape(x=x, grad_k=gk)
        return np.einsum("abc,...c,...b->...a", self.structure, x, gk)

    def hamiltonian_rhs(
        self, gradient: Callable[[np.ndarray], np.ndarray]
    ) -> Callable[[float, np.ndarray], np.ndarray]:
        """Right-hand side ``f(t, x) = P(x) ∇K(x)`` for ``scipy.integrate.solve_ivp``.

        Parameters
        ----------
        gradient : callable
            ``gradient(x)`` returns ``∇K`` with the shape (n,) of ``x``.

        Returns
        -------
        callable
            ``f(t, x)`` with ``x`` of shape (n,).

        Examples
        --------
        >>> import numpy as np
        >>> f = get_algebra("so3").hamiltonian_rhs(lambda m: m / np.array([1.0, 2.0, 4.0]))
        >>> f(0.0, np.array([1.0, 2.0, 3.0]))
        array([-1.5 ,  2.25, -1.  ])
        """

        def rhs(_t: float, x: np.ndarray) -> np.ndarray:
            return self.vector_field(x, gradient(x))

        return rhs

    def sample(self, rng: np.random.Generator, size: int) -> np.ndarray:
        """Random points, shape (size, n): ``m ~ N(0, 1)``, γ or λ uniform on the unit sphere.

        Examples
        --------
        >>> import numpy as np
        >>> x = get_algebra("l7").sample(np.random.default_rng(0), 5)
        >>> x.shape, bool(np.allclose(np.linalg.norm(x[:, 3:], axis=-1), 1.0))
        ((5, 7), True)
        """
        x = rng.standard_normal((size, self.dim))
        if self.unit_block is not None:
            block = x[:, self.unit_block]
            x[:, self.unit_block] = block / np.linalg.norm(block, axis=-1, keepdims=True)
        return x

    # ----- symbolic side (sympy imported lazily) -----

    def symbols(self) -> tuple[Any, ...]:
        """Sympy symbols of the generators, named as :attr:`generators` (real).

        Examples
        --------
        >>> get_algebra("e3").symbols()
        (m1, m2, m3, gamma1, gamma2, gamma3)
        """
        import sympy as sp

        return tuple(sp.Symbol(name, real=True) for name in self.generators)

    def poisson_tensor_sym(self) -> Any:
        """Poisson tensor as a sympy ``Matrix`` in :meth:`symbols`.

        Examples
        --------
        >>> get_algebra("so3").poisson_tensor_sym()
        Matrix([
        [  0, -m3,  m2],
        [ m3,   0, -m1],
        [-m2,  m1,   0]])
        """
        import sympy as sp

        xs = self.symbols()
        rows = []
        for a in range(self.dim):
            row = []
            for b in range(self.dim):
                entry = sum(
                    (
                        sp.nsimplify(self.structure[a, b, c]) * xs[c]
                        for c in range(self.dim)
                        if self.structure[a, b, c] != 0
                    ),
                    sp.Integer(0),
                )
                row.append(entry)
            rows.append(row)
        return sp.Matrix(rows)

    def bracket_sym(self, f: Any, k: Any) -> Any:
        """Bracket of two sympy expressions of :meth:`symbols` (not simplified).

        Examples
        --------
        >>> l7 = get_algebra("l7")
        >>> m1, m2, m3, q0, q1, q2, q3 = l7.symbols()
        >>> l7.bracket_sym(m1, q0)
        lambda1/2
        >>> l7.bracket_sym(m3 * q0, m1)
        -lambda0*m2 - lambda1*m3/2
        """
        import sympy as sp

        return sp.expand(self.bracket_sym_unexpanded(f, k))

    def bracket_sym_unexpanded(self, f: Any, k: Any) -> Any:
        """As :meth:`bracket_sym`, keeping the derivatives' structure (for substitution).

        Examples
        --------
        >>> so3 = get_algebra("so3")
        >>> m1, m2, m3 = so3.symbols()
        >>> so3.bracket_sym_unexpanded(m1 * m2, m3)
        -m1**2 + m2**2
        """
        import sympy as sp

        xs = self.symbols()
        P = self.poisson_tensor_sym()
        gf = [sp.diff(f, x) for x in xs]
        gk = [sp.diff(k, x) for x in xs]
        return sp.Add(
            *(
                gf[a] * P[a, b] * gk[b]
                for a in range(self.dim)
                for b in range(self.dim)
                if P[a, b] != 0 and gf[a] != 0 and gk[b] != 0
            )
        )

    def vector_field_sym(self, k: Any) -> Any:
        """Hamiltonian vector field ``P(x)∇K`` of a sympy expression, a column ``Matrix``.

        Examples
        --------
        >>> e3 = get_algebra("e3")
        >>> m1, m2, m3, g1, g2, g3 = e3.symbols()
        >>> e3.vector_field_sym(m3**2 / 2).T  # rotation about b3
        Matrix([[m2*m3, -m1*m3, 0, gamma2*m3, -gamma1*m3, 0]])
        """
        import sympy as sp

        xs = self.symbols()
        grad = sp.Matrix([sp.diff(k, x) for x in xs])
        return (self.poisson_tensor_sym() * grad).applyfunc(sp.expand)


def _build(name: str) -> LiePoissonAlgebra:
    m = ("m1", "m2", "m3")
    if name == "so3":
        return LiePoissonAlgebra(
            "so3",
            m,
            so3_structure(),
            (Casimir("m·m", quadratic_form(3, [(0, 0), (1, 1), (2, 2)])),),
        )
    if name == "e3":
        return LiePoissonAlgebra(
            "e3",
            (*m, "gamma1", "gamma2", "gamma3"),
            e3_structure(),
            (
                Casimir("γ·γ", quadratic_form(6, [(3, 3), (4, 4), (5, 5)])),
                Casimir("m·γ", quadratic_form(6, [(0, 3), (1, 4), (2, 5)])),
            ),
            slice(3, 6),
        )
    return LiePoissonAlgebra(
        "l7",
        (*m, "lambda0", "lambda1", "lambda2", "lambda3"),
        l7_structure(),
        (Casimir("λ·λ", quadratic_form(7, [(3, 3), (4, 4), (5, 5), (6, 6)])),),
        slice(3, 7),
    )


_ALGEBRAS = {name: _build(name) for name in ALGEBRA_NAMES}


def get_algebra(name: str) -> LiePoissonAlgebra:
    """Return the algebra ``"so3"``, ``"e3"`` or ``"l7"``.

    Parameters
    ----------
    name : str

    Returns
    -------
    LiePoissonAlgebra

    Raises
    ------
    ValueError
        For any other name.

    Examples
    --------
    >>> get_algebra("l7").generators
    ('m1', 'm2', 'm3', 'lambda0', 'lambda1', 'lambda2', 'lambda3')
    >>> [c.name for c in get_algebra("e3").casimirs]
    ['γ·γ', 'm·γ']
    """
    if name not in _ALGEBRAS:
        raise ValueError(f"expected one of {ALGEBRA_NAMES}, got {name!r}")
    return _ALGEBRAS[name]
