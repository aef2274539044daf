"""Check proposed canonical coordinates on a Lie–Poisson algebra, symbolically and numerically.

Two checks, depending on which map is known:

* :func:`check_coordinates` (needs ``inverse``, coordinates as functions of the
  generators, Pavlov's viewpoint): every bracket ``{z_a, z_b}`` is computed with
  the Lie–Poisson bracket and compared with the canonical value (``{q_i, p_j} = δ_ij``,
  labels commute with everything).
* :func:`check_poisson_map` (needs ``forward``, generators as functions of the
  coordinates, the viewpoint of Gurfil et al. eq. 28 and of Andoyer's method):
  every bracket of generators ``{x_a, x_b}`` is computed with the canonical bracket
  ``{f, k} = Σ_i ∂f/∂q_i ∂k/∂p_i − ∂f/∂p_i ∂k/∂q_i`` in the coordinates and
  compared with the structure ``P_ab(x)`` of the algebra. Together with a Jacobian
  of full rank on the Casimir level set this is canonicity; without it the map is
  a symplectic realisation (e.g. Euler angles on e(3)).

Symbolic: the difference is reduced to an algebraic normal form
(:func:`andoyer.liepoisson._identity.vanishes`); ``symbolic_ok`` means *proven*.
Numeric: the difference at seeded random points is at most
``tol · max(1, Σ|terms|)``, where ``Σ|terms|`` is the bracket evaluated with absolute
values (the scale of its rounding error).
"""

from __future__ import annotations

import itertools
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
import sympy as sp

from andoyer.liepoisson._identity import vanishes
from andoyer.liepoisson.algebra import LiePoissonAlgebra, get_algebra
from andoyer.liepoisson.coordinates import CanonicalCoordinates, andoyer_coordinates

__all__ = ["BracketRecord", "bracket_table", "check_coordinates", "check_poisson_map"]

_MAX_VALUE_CHARS = 160


@dataclass(frozen=True)
class BracketRecord:
    """One checked bracket relation ``{left, right} = expected``.

    Attributes
    ----------
    left, right : str
        Names of the two functions.
    value : str
        The bracket: the expected value when proven, else the computed expression
        (shortened beyond 160 characters).
    expected : str
        The value the relation requires.
    symbolic_ok : bool
        The difference was proven to vanish identically.
    numeric_ok : bool
        The difference is within tolerance at every sample point.
    max_error : float
        Largest scaled difference at the sample points.
    """

    left: str
    right: str
    value: str
    expected: str
    symbolic_ok: bool
    numeric_ok: bool
    max_error: float

    def as_dict(self) -> dict[str, Any]:
        """Plain dict (JSON-serialisable).

        Examples
        --------
        >>> BracketRecord("l", "L", "1", "1", True, True, 0.0).as_dict()["value"]
        '1'
        """
        return asdict(self)


def _level_relations(alg: LiePoissonAlgebra) -> tuple[tuple[Any, Any], ...]:
    if alg.unit_block is None:
        return ()
    xs = alg.symbols()[alg.unit_block]
    return ((xs[0], sum(x**2 for x in xs) - 1),)


def _shorten(expr: Any) -> str:
    text = sp.sstr(expr)
    return text if len(text) <= _MAX_VALUE_CHARS else text[: _MAX_VALUE_CHARS - 1] + "…"


def _evaluate_many(exprs: list[Any], symbols: tuple[Any, ...], pts: np.ndarray) -> np.ndarray:
    """Values of ``exprs`` at ``pts`` (N, len(symbols)), shape (len(exprs), N); one lambdify."""
    f = sp.lambdify([symbols], list(exprs), "numpy", cse=True)
    return np.stack([np.broadcast_to(np.asarray(v, dtype=float), pts.shape[:1]) for v in f(pts.T)])


def _gradients(exprs: list[Any], symbols: tuple[Any, ...], pts: np.ndarray) -> np.ndarray:
    """Gradients of ``exprs`` at ``pts``, shape (len(exprs), N, len(symbols))."""
    values = _evaluate_many([sp.diff(e, s) for e in exprs for s in symbols], symbols, pts)
    return values.reshape(len(exprs), len(symbols), -1).transpose(0, 2, 1)


def check_coordinates(
    coords: CanonicalCoordinates,
    *,
    n_points: int = 1000,
    seed: int = 0,
    tol: float = 1e-12,
    symbolic: bool = True,
) -> list[BracketRecord]:
    """Check all brackets ``{z_a, z_b}`` of coordinates given as functions of the generators.

    Parameters
    ----------
    coords : CanonicalCoordinates
        Must have ``inverse``. The symbolic proof is tried in the generators, with the unit
        constraint of γ or λ, then (if ``forward`` is given) in the coordinates after
        substituting the forward map.
    n_points : int, optional
        Number of random points of the algebra (``LiePoissonAlgebra.sample``).
    seed : int, optional
    tol : float, optional
        Numeric tolerance (scaled, see module docstring).
    symbolic : bool, optional
        Skip the symbolic proof when False (``symbolic_ok`` is then False).

    Returns
    -------
    list of BracketRecord
        One per unordered pair ``a < b`` in the order of ``coords.symbols``.

    Raises
    ------
    ValueError
        If ``coords`` has no inverse map.

    Examples
    --------
    >>> [(r.left, r.right, r.value, r.symbolic_ok, r.numeric_ok)
    ...  for r in check_coordinates(andoyer_coordinates("so3"), n_points=50)]
    [('l', 'L', '1', True, True), ('l', 'G', '0', True, True), ('L', 'G', '0', True, True)]
    """
    if coords.inverse is None:
        raise ValueError("expected coordinates with an inverse map, got inverse=None")
    alg = get_algebra(coords.algebra)
    xs = alg.symbols()
    points = alg.sample(np.random.default_rng(seed), n_points)
    grads = dict(
        zip(coords.symbols, _gradients([coords.inverse[z] for z in coords.symbols], xs, points), strict=True)
    )
    P = alg.poisson_tensor(points)
    absP = np.abs(P)
    substitution = None
    if coords.forward is not None:
        substitution = {x: coords.forward[name] for x, name in zip(xs, alg.generators, strict=True)}
    records = []
    for a, b in itertools.combinations(coords.symbols, 2):
        expected = coords.canonical_value(a, b)
        value = np.einsum("...a,...ab,...b->...", grads[a], P, grads[b])
        scale = np.einsum("...a,...ab,...b->...", np.abs(grads[a]), absP, np.abs(grads[b]))
        err = np.abs(value - expected) / np.maximum(1.0, scale)
        max_err = float(np.max(err)) if err.size else 0.0
        proven = False
        expr = sp.Integer(expected)
        if symbolic:
            bracket = alg.bracket_sym_unexpanded(coords.inverse[a], coords.inverse[b])
            # in the generators on the Casimir level set first (a stronger statement, and
            # faster on l(7)); then in the coordinates, after the forward substitution
            proven = vanishes(bracket - expected, _level_relations(alg))
            if not proven and substitution is not None:
                proven = vanishes(bracket - expected, substitution=substitution)
            if not proven:
                expr = bracket if substitution is None else sp.Symbol("<not proven>")
        records.append(
            BracketRecord(
                str(a),
                str(b),
                _shorten(expr),
                str(expected),
                proven,
                bool(np.all(err <= tol)),
                max_err,
            )
        )
    return records


def check_poisson_map(
    coords: CanonicalCoordinates,
    *,
    n_points: int = 1000,
    seed: int = 0,
    tol: float = 1e-12,
    symbolic: bool = True,
) -> list[BracketRecord]:
    """Check that the forward map sends the canonical bracket to the Lie–Poisson bracket.

    For every pair of generators ``a < b``: ``{X_a, X_b}_canonical(z) = P_ab(X(z))``.

    Parameters
    ----------
    coords : CanonicalCoordinates
        Must have ``forward`` and a ``sampler`` (coordinate points) or an ``inverse``
        (then the points are the images of random algebra points).
    n_points, seed, tol, symbolic
        As in :func:`check_coordinates`.

    Returns
    -------
    list of BracketRecord
        One per pair of generators.

    Raises
    ------
    ValueError
        If there is no forward map, or neither a sampler nor an inverse map.

    Examples
    --------
    Gurfil et al. eq. 28 and the kinematics: the Euler-angle realisation of so(3).

    >>> from andoyer.liepoisson.coordinates import euler_coordinates
    >>> [(r.left, r.right, r.value, r.symbolic_ok, r.numeric_ok)
    ...  for r in check_poisson_map(euler_coordinates("so3"), n_points=50)]
    [('m1', 'm2', '-m3', True, True), ('m1', 'm3', 'm2', True, True),
     ('m2', 'm3', '-m1', True, True)]
    """
    if coords.forward is None:
        raise ValueError("expected coordinates with a forward map, got forward=None")
    alg = get_algebra(coords.algebra)
    zs = coords.symbols
    rng = np.random.default_rng(seed)
    if coords.sampler is not None:
        zpts = np.asarray(coords.sampler(rng, n_points), dtype=float)
    elif coords.inverse is not None:
        xpts = alg.sample(rng, n_points)
        zpts = _evaluate_many([coords.inverse[z] for z in zs], alg.symbols(), xpts).T
    else:
        raise ValueError("expected a sampler or an inverse map for the numeric check, got neither")
    X = [coords.forward[name] for name in alg.generators]
    jac = np.moveaxis(_gradients(X, zs, zpts), 0, -2)  # (N, n, nz)
    omega = np.zeros((len(zs), len(zs)))
    for q, p in coords.pairs:
        omega[zs.index(q), zs.index(p)] = 1.0
        omega[zs.index(p), zs.index(q)] = -1.0
    canonical = jac @ omega @ np.swapaxes(jac, -1, -2)
    scale_can = np.abs(jac) @ np.abs(omega) @ np.abs(np.swapaxes(jac, -1, -2))
    xvals = _evaluate_many(X, zs, zpts).T
    structure = alg.poisson_tensor(xvals)
    scale = np.maximum(1.0, scale_can + np.abs(alg.poisson_tensor(np.abs(xvals))))
    err = np.abs(canonical - structure) / scale
    P_sym = alg.poisson_tensor_sym()
    substitution = dict(zip(alg.symbols(), X, strict=True))
    records = []
    for a, b in itertools.combinations(range(alg.dim), 2):
        expected = P_sym[a, b]
        proven = False
        shown = expected
        if symbolic:
            bracket = sum(
                sp.diff(X[a], q) * sp.diff(X[b], p) - sp.diff(X[a], p) * sp.diff(X[b], q)
                for q, p in coords.pairs
            )
            proven = vanishes(bracket - expected.xreplace(substitution))
            if not proven:
                shown = bracket
        max_err = float(np.max(err[:, a, b])) if n_points else 0.0
        records.append(
            BracketRecord(
                alg.generators[a],
                alg.generators[b],
                _shorten(shown),
                str(expected),
                proven,
                bool(np.all(err[:, a, b] <= tol)),
                max_err,
            )
        )
    return records


def bracket_table(algebra: str) -> list[dict[str, Any]]:
    """Bracket table of the project's Andoyer–Deprit coordinates of ``algebra``.

    Feeds ``andoyer brackets --algebra so3|e3|l7 [--format json]``: every pair of
    coordinates of :func:`~andoyer.liepoisson.coordinates.andoyer_coordinates`,
    checked symbolically and at 1000 seeded points.

    Parameters
    ----------
    algebra : str
        ``"so3"``, ``"e3"`` or ``"l7"``.

    Returns
    -------
    list of dict
        Keys ``left, right, value, expected, symbolic_ok, numeric_ok, max_error``.

    Raises
    ------
    ValueError
        For an unknown algebra.

    Examples
    --------
    >>> [(r["left"], r["right"], r["value"]) for r in bracket_table("so3")]
    [('l', 'L', '1'), ('l', 'G', '0'), ('L', 'G', '0')]
    """
    get_algebra(algebra)
    return [r.as_dict() for r in check_coordinates(andoyer_coordinates(algebra))]
