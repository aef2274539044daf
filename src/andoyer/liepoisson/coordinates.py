"""Proposed canonical coordinates on a Lie–Poisson algebra, as sympy data.

A :class:`CanonicalCoordinates` names the canonical pairs ``(q_i, p_i)`` and the leaf
labels (Casimir coordinates), and gives the map to the algebra's generators
(``forward``: generators as expressions of the coordinates), its inverse
(``inverse``: coordinates as expressions of the generators), or both. The checker
in :mod:`andoyer.liepoisson.canonicity` consumes it.

The project's coordinates (:func:`andoyer_coordinates`) are the Andoyer–Deprit
variables of Pavlov's paper in the project's Andoyer convention; the Euler-angle
realisation (:func:`euler_coordinates`, Gurfil et al. eqs. 25–27) is given as a
forward map only.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from andoyer._quaternion import product
from andoyer.liepoisson.algebra import get_algebra

__all__ = ["CanonicalCoordinates", "andoyer_coordinates", "andoyer_symbols", "euler_coordinates"]


@dataclass(frozen=True)
class CanonicalCoordinates:
    """Proposed canonical coordinates on the leaves of a Lie–Poisson algebra.

    Parameters
    ----------
    algebra : str
        ``"so3"``, ``"e3"`` or ``"l7"``.
    pairs : tuple of (Symbol, Symbol)
        Canonical pairs ``(q_i, p_i)``, meant to satisfy ``{q_i, p_j} = δ_ij``.
    casimirs : tuple of Symbol
        Leaf labels, meant to commute with everything.
    forward : mapping of str to sympy expression, optional
        Generator name (as in ``get_algebra(algebra).generators``) to its expression in
        the coordinates.
    inverse : mapping of Symbol to sympy expression, optional
        Coordinate to its expression in ``get_algebra(algebra).symbols()``.
    sampler : callable, optional
        ``sampler(rng, n)`` returns coordinate values of shape (n, len(symbols)) in the
        order of :attr:`symbols`, inside the chart's domain.

    Examples
    --------
    >>> c = andoyer_coordinates("e3")
    >>> c.symbols
    (l, L, g, G, H)
    """

    algebra: str
    pairs: tuple[tuple[Any, Any], ...]
    casimirs: tuple[Any, ...] = ()
    forward: Mapping[str, Any] | None = None
    inverse: Mapping[Any, Any] | None = None
    sampler: Callable[[np.random.Generator, int], np.ndarray] | None = None

    def __post_init__(self) -> None:
        alg = get_algebra(self.algebra)
        if self.forward is None and self.inverse is None:
            raise ValueError("expected a forward or an inverse map, got neither")
        if self.forward is not None and set(self.forward) != set(alg.generators):
            raise ValueError(f"expected forward expressions for {alg.generators}, got {tuple(self.forward)}")
        if self.inverse is not None and set(self.inverse) != set(self.symbols):
            raise ValueError(f"expected inverse expressions for {self.symbols}, got {tuple(self.inverse)}")

    @property
    def symbols(self) -> tuple[Any, ...]:
        """Coordinates in the order ``q_1, p_1, q_2, p_2, ..., casimirs``.

        Examples
        --------
        >>> andoyer_coordinates("l7").symbols
        (l, L, g, G, h, H)
        """
        return tuple(s for pair in self.pairs for s in pair) + tuple(self.casimirs)

    def canonical_value(self, a: Any, b: Any) -> int:
        """The canonical bracket ``{a, b}`` the coordinates should satisfy: 1, -1 or 0.

        Examples
        --------
        >>> c = andoyer_coordinates("so3")
        >>> l, L, G = c.symbols
        >>> c.canonical_value(l, L), c.canonical_value(L, l), c.canonical_value(l, G)
        (1, -1, 0)
        """
        for q, p in self.pairs:
            if (a, b) == (q, p):
                return 1
            if (a, b) == (p, q):
                return -1
        return 0


def andoyer_symbols() -> dict[str, Any]:
    """The sympy symbols ``l, g, h`` (real) and ``L, H`` (real), ``G`` (positive).

    Examples
    --------
    >>> sorted(andoyer_symbols())
    ['G', 'H', 'L', 'g', 'h', 'l']
    """
    names = {n: sp.Symbol(n, real=True) for n in ("l", "g", "h", "L", "H")}
    names["G"] = sp.Symbol("G", positive=True)
    return names


def _andoyer_sampler(n_angles: int, with_h: bool) -> Callable[[np.random.Generator, int], np.ndarray]:
    def sample(rng: np.random.Generator, n: int) -> np.ndarray:
        G = rng.uniform(0.5, 2.0, n)
        L = G * rng.uniform(-0.95, 0.95, n)
        H = G * rng.uniform(-0.95, 0.95, n)
        angles = rng.uniform(0.0, 2 * np.pi, (n_angles, n))
        if n_angles == 1:  # so3: (l, L, G)
            return np.stack([angles[0], L, G], axis=-1)
        if not with_h:  # e3: (l, L, g, G, H)
            return np.stack([angles[0], L, angles[1], G, H], axis=-1)
        return np.stack([angles[0], L, angles[1], G, angles[2], H], axis=-1)

    return sample


def andoyer_coordinates(algebra: str) -> CanonicalCoordinates:
    """The project's Andoyer–Deprit coordinates on the leaves of ``algebra``.

    * so(3): pair ``(l, L)``, label ``G``; ``m = (√(G²−L²) sin l, √(G²−L²) cos l, L)``.
    * e(3): pairs ``(l, L), (g, G)``, label ``H = m·γ``; γ as in Pavlov eq. 1.7.
    * l(7): pairs ``(l, L), (g, G), (h, H)``; λ the quaternion of
      ``Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)`` (scalar first).

    Parameters
    ----------
    algebra : str

    Returns
    -------
    CanonicalCoordinates
        With forward map, inverse map and a sampler.

    Examples
    --------
    >>> c = andoyer_coordinates("so3")
    >>> c.forward["m1"]
    sqrt(G**2 - L**2)*sin(l)
    >>> c.inverse[c.symbols[0]]
    atan2(m1, m2)
    """
    alg = get_algebra(algebra)
    s = andoyer_symbols()
    ell, g, h, L, G, H = (s[k] for k in ("l", "g", "h", "L", "G", "H"))
    xs = alg.symbols()
    m = sp.Matrix(xs[:3])
    G_of_x = sp.sqrt(m.dot(m))
    inverse: dict[Any, Any] = {ell: sp.atan2(xs[0], xs[1]), L: xs[2], G: G_of_x}
    if algebra == "so3":
        rho = sp.sqrt(G**2 - L**2)
        forward = {"m1": rho * sp.sin(ell), "m2": rho * sp.cos(ell), "m3": L}
        return CanonicalCoordinates("so3", ((ell, L),), (G,), forward, inverse, _andoyer_sampler(1, False))
    if algebra == "e3":
        rho = sp.sqrt(G**2 - L**2)
        sI, cI, sJ, cJ = sp.sqrt(G**2 - H**2) / G, H / G, rho / G, L / G
        u = cI * sJ + sI * cJ * sp.cos(g)
        forward = {
            "m1": rho * sp.sin(ell),
            "m2": rho * sp.cos(ell),
            "m3": L,
            "gamma1": u * sp.sin(ell) + sI * sp.sin(g) * sp.cos(ell),
            "gamma2": u * sp.cos(ell) - sI * sp.sin(g) * sp.sin(ell),
            "gamma3": cI * cJ - sI * sJ * sp.cos(g),
        }
        gamma = sp.Matrix(xs[3:])
        H_of_x = m.dot(gamma)
        inverse[g] = _g_of(m, gamma, H_of_x)
        inverse[H] = H_of_x
        return CanonicalCoordinates(
            "e3", ((ell, L), (g, G)), (H,), forward, inverse, _andoyer_sampler(2, False)
        )
    if algebra != "l7":
        get_algebra(algebra)  # raises the standard error
    half = {k: (sp.sqrt((G + p) / (2 * G)), sp.sqrt((G - p) / (2 * G))) for k, p in (("I", H), ("J", L))}
    lam = _quat(
        _quat(_quat(_qz(h), _qx(*half["I"])), _qz(g)),
        _quat(_qx(*half["J"]), _qz(ell)),
    )
    rho = 2 * G * half["J"][0] * half["J"][1]
    forward = {"m1": rho * sp.sin(ell), "m2": rho * sp.cos(ell), "m3": L}
    forward.update({f"lambda{i}": lam[i] for i in range(4)})
    gamma = quaternion_gamma(xs[3:])
    m_ref = quaternion_matrix(xs[3:]) * m
    inverse[H] = m_ref[2]
    inverse[h] = sp.atan2(m_ref[0], -m_ref[1])
    inverse[g] = _g_of(m, gamma, m.dot(gamma))
    return CanonicalCoordinates(
        "l7", ((ell, L), (g, G), (h, H)), (), forward, inverse, _andoyer_sampler(3, True)
    )


def _g_of(m: Any, gamma: Any, H: Any) -> Any:
    """``g = atan2(G (γ1 m2 − γ2 m1), m3 H − G² γ3)`` (both arguments scaled by G√(G²−L²) > 0)."""
    G2 = m.dot(m)
    return sp.atan2(sp.sqrt(G2) * (gamma[0] * m[1] - gamma[1] * m[0]), m[2] * H - G2 * gamma[2])


def _qz(angle: Any) -> list[Any]:
    return [sp.cos(angle / 2), 0, 0, sp.sin(angle / 2)]


def _qx(c: Any, s: Any) -> list[Any]:
    return [c, s, 0, 0]


def _quat(a: list[Any], b: list[Any]) -> list[Any]:
    """Scalar-first product ``a ⊗ b`` of sympy quaternions (:func:`andoyer._quaternion.product`)."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    x, y, z, w = product(ax, ay, az, aw, bx, by, bz, bw)
    return [w, x, y, z]


def quaternion_gamma(lam: Any) -> Any:
    """Pavlov eq. 2.2 as a sympy column: γ from λ = (λ0, λ1, λ2, λ3).

    Examples
    --------
    >>> import sympy as sp
    >>> quaternion_gamma(sp.symbols("w x y z")).T
    Matrix([[-2*w*y + 2*x*z, 2*w*x + 2*y*z, w**2 - x**2 - y**2 + z**2]])
    """
    w, x, y, z = lam
    return sp.Matrix([2 * (x * z - w * y), 2 * (w * x + y * z), w**2 - x**2 - y**2 + z**2])


def quaternion_matrix(lam: Any) -> Any:
    """Sympy matrix of ``rot`` (body → reference) from λ, homogeneous of degree 2.

    Examples
    --------
    >>> import sympy as sp
    >>> quaternion_matrix(sp.symbols("w x y z"))[2, :] == quaternion_gamma(sp.symbols("w x y z")).T
    True
    """
    w, x, y, z = lam
    return sp.Matrix(
        [
            [w**2 + x**2 - y**2 - z**2, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w**2 - x**2 + y**2 - z**2, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (w * x + y * z), w**2 - x**2 - y**2 + z**2],
        ]
    )


def euler_coordinates(algebra: str) -> CanonicalCoordinates:
    """Euler angles 3-1-3 and their momenta, ``rot = Rz(φ) Rx(θ) Rz(ψ)`` (forward map only).

    The body momentum is Gurfil et al. eqs. 25–27,
    ``m1 = (Φ sψ + Θ sθ cψ − Ψ sψ cθ)/sθ``, ``m2 = (Φ cψ − Θ sψ sθ − Ψ cψ cθ)/sθ``,
    ``m3 = Ψ``; γ is the third row of the rotation matrix and λ its quaternion
    ``q_z(φ) q_x(θ) q_z(ψ)``. The map is a Poisson map (a symplectic realisation); on
    so(3) and e(3) it is not a chart (φ does not enter).

    Parameters
    ----------
    algebra : str

    Returns
    -------
    CanonicalCoordinates
        Pairs ``(φ, Φ), (θ, Θ), (ψ, Ψ)``, forward map and a sampler with
        ``θ ∈ [0.2, π − 0.2]``.

    Examples
    --------
    >>> euler_coordinates("e3").forward["gamma3"]
    cos(theta)
    """
    alg = get_algebra(algebra)
    phi, theta, psi, Phi, Theta, Psi = sp.symbols("phi theta psi Phi Theta Psi", real=True)
    st, ct, sp_, cp_ = sp.sin(theta), sp.cos(theta), sp.sin(psi), sp.cos(psi)
    forward = {
        "m1": (Phi * sp_ + Theta * st * cp_ - Psi * sp_ * ct) / st,
        "m2": (Phi * cp_ - Theta * sp_ * st - Psi * cp_ * ct) / st,
        "m3": Psi,
    }
    if algebra == "e3":
        forward.update({"gamma1": st * sp_, "gamma2": st * cp_, "gamma3": ct})
    elif algebra == "l7":
        lam = _quat(_quat(_qz(phi), _qx(sp.cos(theta / 2), sp.sin(theta / 2))), _qz(psi))
        forward.update({f"lambda{i}": lam[i] for i in range(4)})

    def sample(rng: np.random.Generator, n: int) -> np.ndarray:
        angles = rng.uniform(0.0, 2 * np.pi, (n, 3))
        angles[:, 1] = rng.uniform(0.2, np.pi - 0.2, n)
        mom = rng.standard_normal((n, 3))
        return np.stack([angles[:, 0], mom[:, 0], angles[:, 1], mom[:, 1], angles[:, 2], mom[:, 2]], axis=-1)

    return CanonicalCoordinates(alg.name, ((phi, Phi), (theta, Theta), (psi, Psi)), (), forward, None, sample)
