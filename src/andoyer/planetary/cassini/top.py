r"""Colombo's top: the Hamiltonian, its equilibria (the Cassini states), their stability and separatrix.

In the frame that turns with the orbit's node (Laplace pole ``K``, orbit normal ``k`` at
inclination ``i``, node rate ``g = Ω̇ < 0``), the orbit-averaged spin axis ``s`` of a body with
precession constant ``α`` and resonance constant ``β`` (:mod:`andoyer.planetary.cassini.body`)
obeys ``ds/dt = ∇𝓗 × s`` with

.. math::
   \mathcal H(\mathbf s) = -\frac{\alpha}{2}(\mathbf s\cdot\mathbf k)^2
   - \beta\,(\mathbf s\cdot\mathbf k) - g\,(\mathbf s\cdot\mathbf K).

**The Cassini equation.** Equilibria lie in the plane of ``k`` and ``K`` (Cassini's laws).
With the signed obliquity ``θ`` (angle from ``k`` to ``s``, positive towards ``K``, so that
``s·K = cos(θ − i)``), ``∂𝓗/∂θ = 0`` reads

.. math:: F(\theta) = (\alpha\cos\theta + \beta)\sin\theta + g\,\sin(\theta - i) = 0 ,

a quartic in ``tan(θ/2)``: two or four roots. They are numbered as Peale (1969) and Ward
(1975): the root with ``0 < θ < π`` (the spin axis beyond ``K`` seen from ``k``) is
**state 2**; those with ``−π < θ < 0``, by decreasing ``θ``, are **1, 4, 3** when there are
three and **3** alone otherwise (states 1 and 4 merge and vanish as ``|g|/α`` grows). The
Moon is in state 2, Mercury in state 1.

**Stability.** At an equilibrium the curvatures of ``𝓗`` along the plane and across it are

.. math:: \mathcal H_{\theta\theta} = \alpha\cos 2\theta + \beta\cos\theta + g\cos(\theta - i),
   \qquad \mathcal H_{\psi\psi} = \alpha\cos^2\theta + \beta\cos\theta + g\cos(\theta - i),

and the linearised flow has eigenvalues ``λ² = −𝓗_θθ 𝓗_ψψ``: an extremum (product > 0,
states 1, 2, 3) is stable, a saddle (product < 0, state 4) unstable. The separatrix is the
level ``𝓗 = 𝓗(state 4)``.

The portrait coordinates are ``(φ, θ)``: ``s = (sin θ cos φ, sin θ sin φ, cos θ)`` with ``k``
the pole and ``K = (sin i, 0, cos i)``, so ``𝓗 = −(α/2)cos²θ − β cos θ − g(cos i cos θ +
sin i sin θ cos φ)``; ``(φ, cos θ)`` are canonical (``φ̇ = ∂𝓗/∂cos θ``).

Examples
--------
>>> top = ColomboTop(alpha=1.0, beta=0.0, node_rate=-0.1, inclination=0.2)
>>> [(s.number, round(s.obliquity_deg, 3), s.stable) for s in top.states()]
[(1, 1.262, True), (2, 84.486, True), (3, 178.963, True), (4, 84.261, False)]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from andoyer._validation import as_finite

__all__ = ["CassiniState", "ColomboTop"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class CassiniState:
    """One equilibrium of Colombo's top.

    Attributes
    ----------
    number : int
        Peale's number, 1 to 4.
    theta : float
        Signed obliquity ``θ`` (radians; positive towards the Laplace pole).
    obliquity : float
        ``|θ|``, angle from the orbit normal to the spin axis (radians).
    inclination_to_laplace : float
        Angle from the Laplace pole to the spin axis, ``arccos(cos(θ − i))`` (radians).
    energy : float
        ``𝓗`` at the state (rad/yr).
    curvatures : tuple of float
        ``(𝓗_θθ, 𝓗_ψψ)``.
    stable : bool
        ``𝓗_θθ 𝓗_ψψ > 0`` (an extremum of ``𝓗``).
    """

    number: int
    theta: float
    obliquity: float
    inclination_to_laplace: float
    energy: float
    curvatures: tuple[float, float]
    stable: bool

    @property
    def obliquity_deg(self) -> float:
        """The obliquity in degrees."""
        return math.degrees(self.obliquity)

    @property
    def inclination_to_laplace_deg(self) -> float:
        """The inclination to the Laplace pole in degrees."""
        return math.degrees(self.inclination_to_laplace)


@dataclass(frozen=True)
class ColomboTop:
    """Colombo's top ``𝓗 = −(α/2)cos²θ − β cos θ − g s·K`` (see the module docstring).

    Parameters
    ----------
    alpha, beta : float
        Precession and resonance constants (rad per time unit), ``α > 0``, ``β ≥ 0``.
    node_rate : float
        ``g < 0`` (same unit), a regressing node (Peale's numbering assumes it).
    inclination : float
        ``0 < i < π/2`` (radians).

    Examples
    --------
    >>> top = ColomboTop(1.0, 0.0, -0.1, 0.2)
    >>> [(s.number, s.stable) for s in top.states()]
    [(1, True), (2, True), (3, True), (4, False)]
    """

    alpha: float
    beta: float
    node_rate: float
    inclination: float

    def __post_init__(self) -> None:
        values = (self.alpha, self.beta, self.node_rate, self.inclination)
        if not all(math.isfinite(float(v)) for v in values):
            msg = f"expected finite alpha, beta, node_rate, inclination, got {values!r}"
            raise ValueError(msg)
        if not (self.alpha > 0 and self.beta >= 0 and self.node_rate < 0):
            msg = f"expected alpha > 0, beta >= 0, node_rate < 0, got {values[:3]!r}"
            raise ValueError(msg)
        if not 0 < self.inclination < math.pi / 2:
            msg = f"expected 0 < inclination < pi/2, got {self.inclination!r}"
            raise ValueError(msg)
        if -self.node_rate < 1e-12 * (self.alpha + self.beta):
            # Slower, states 2 and 4 merge (in double precision) into the circle of equilibria
            # of a fixed orbit, and their numbering and stability lose their meaning.
            msg = (
                "expected a node rate at least 1e-12 of the precession constants (a precessing "
                f"orbit), got {self.node_rate!r} against alpha + beta = {self.alpha + self.beta!r}"
            )
            raise ValueError(msg)

    def equation(self, theta: ArrayLike) -> Array:
        """The Cassini function ``F(θ) = (α cos θ + β) sin θ + g sin(θ − i)``, shape of ``theta``.

        Examples
        --------
        >>> float(ColomboTop(1.0, 0.0, -0.1, 0.2).equation(0.0))  # -g sin i
        0.019866933079506124
        """
        t = as_finite(theta, "theta")
        g, i = self.node_rate, self.inclination
        return (self.alpha * np.cos(t) + self.beta) * np.sin(t) + g * np.sin(t - i)

    def derivative(self, theta: ArrayLike) -> Array:
        """``F'(θ) = 𝓗_θθ = α cos 2θ + β cos θ + g cos(θ − i)``.

        Examples
        --------
        >>> bool(ColomboTop(1.0, 0.5, -0.1, 0.2).derivative(0.0) == 1.5 - 0.1 * np.cos(0.2))
        True
        """
        t = as_finite(theta, "theta")
        g, i = self.node_rate, self.inclination
        return self.alpha * np.cos(2 * t) + self.beta * np.cos(t) + g * np.cos(t - i)

    def hamiltonian(self, theta: ArrayLike, phi: ArrayLike = 0.0) -> Array:
        """``𝓗(θ, φ)`` with ``θ`` the obliquity and ``φ`` the spin axis' longitude from ``K``.

        A signed ``θ`` at ``φ = 0`` is the in-plane value of the Cassini equation.

        Parameters
        ----------
        theta, phi : array_like, broadcastable

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> top = ColomboTop(1.0, 0.0, -0.1, 0.2)
        >>> bool(top.hamiltonian(0.2) == -0.5 * np.cos(0.2) ** 2 + 0.1)  # s = K
        True
        """
        t = as_finite(theta, "theta")
        p = as_finite(phi, "phi")
        i = self.inclination
        c = np.cos(t)
        return (
            -0.5 * self.alpha * c * c
            - self.beta * c
            - self.node_rate * (math.cos(i) * c + math.sin(i) * np.sin(t) * np.cos(p))
        )

    def vector_field(self, s: ArrayLike) -> Array:
        """``ds/dt = ∇𝓗 × s`` for spin axes (..., 3) in the portrait frame (``k = z``).

        Examples
        --------
        >>> top = ColomboTop(1.0, 0.0, -0.1, 0.2)
        >>> theta = top.states()[0].theta
        >>> s = [np.sin(theta), 0.0, np.cos(theta)]
        >>> bool(np.allclose(top.vector_field(s), 0.0, atol=1e-15))
        True
        """
        s = as_finite(s, "s")
        k = np.array([0.0, 0.0, 1.0])
        K = np.array([math.sin(self.inclination), 0.0, math.cos(self.inclination)])
        sk = s[..., 2:3]
        gradient = -(self.alpha * sk + self.beta) * k - self.node_rate * K
        return np.cross(gradient, s)

    def _candidates(self) -> list[float]:
        """Roots of F from the quartic in ``t = tan(θ/2)`` and from sign changes on a grid."""
        a, b, g, i = self.alpha, self.beta, self.node_rate, self.inclination
        # F (1 + t²)² / 2 = ½g sin i t⁴ + (b − a + g cos i) t³ + (a + b + g cos i) t − ½g sin i.
        coefficients = np.array(
            [
                0.5 * g * math.sin(i),
                b - a + g * math.cos(i),
                0.0,
                a + b + g * math.cos(i),
                -0.5 * g * math.sin(i),
            ]
        )
        roots = np.roots(coefficients / np.max(np.abs(coefficients)))
        near_real = roots[np.abs(roots.imag) <= 1e-6 * (1 + np.abs(roots))].real
        found = [float(2 * np.arctan(t)) for t in near_real]
        grid = np.linspace(-np.pi, np.pi, 4097)
        values = self.equation(grid)
        changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
        found.extend(
            brentq(lambda x: float(self.equation(x)), grid[j], grid[j + 1], xtol=1e-15) for j in changes
        )
        return found

    def _polish(self, theta: float) -> float:
        scale = self.alpha + self.beta + abs(self.node_rate)
        for _ in range(50):
            slope = float(self.derivative(theta))
            if abs(slope) < 1e-12 * scale:
                break
            step = float(self.equation(theta)) / slope
            theta -= step
            if abs(step) <= 1e-16 * max(1.0, abs(theta)):
                break
        return float(np.angle(np.exp(1j * theta)))

    def roots(self) -> Array:
        """Every solution of the Cassini equation, signed ``θ`` in ``(−π, π]``, increasing.

        Returns
        -------
        numpy.ndarray, shape (2,) or (4,)

        Examples
        --------
        >>> ColomboTop(1.0, 0.0, -2.0, 0.3).roots().size  # |g|/α past the bifurcation
        2
        """
        scale = self.alpha + self.beta + abs(self.node_rate)
        polished = sorted(self._polish(t) for t in self._candidates())
        unique: list[float] = []
        for t in polished:
            if abs(float(self.equation(t))) > 1e-10 * scale:
                continue
            if not unique or abs(t - unique[-1]) > 1e-9:
                unique.append(t)
        if len(unique) > 1 and abs(unique[0] + 2 * np.pi - unique[-1]) <= 1e-9:
            unique.pop(0)
        return np.array(unique)

    def least_obliquity_theta(self) -> float:
        """The signed ``θ`` of the state of least obliquity, fast: Newton from the linear answer.

        The small-angle forced solution ``θ₀ = i g/(α + β + g)`` (state 1 for ``|g| < α + β``,
        state 2 beyond) starts Newton's method on ``F``; the root is accepted when ``F`` keeps
        its sign between it and 0 and on the mirror interval (so no root of smaller ``|θ|``
        exists), else the full root set decides. It is the ``theta`` of the state with the
        smallest ``obliquity`` in :meth:`states`.

        Examples
        --------
        >>> top = ColomboTop(1.0, 0.0, -0.1, 0.2)
        >>> bool(top.least_obliquity_theta() == min(top.states(), key=lambda s: s.obliquity).theta)
        True
        """
        a, b, g, i = self.alpha, self.beta, self.node_rate, self.inclination
        kappa = a + b + g
        scale = a + b + abs(g)
        if abs(kappa) > 0.05 * scale:
            theta = i * g / kappa
            for _ in range(60):
                slope = float(self.derivative(theta))
                if abs(slope) < 1e-12 * scale or abs(theta) > 3.0:
                    break
                step = float(self.equation(theta)) / slope
                theta -= step
                if abs(step) <= 1e-15 * max(1.0, abs(theta)):
                    probe = np.linspace(0.0, 1.0, 65)[1:-1] * abs(theta)
                    values = self.equation(np.concatenate([-probe, probe]))
                    if abs(theta) < 3.0 and np.all(values > 0):
                        return float(theta)
                    break
        return min(self.states(), key=lambda s: s.obliquity).theta

    def states(self) -> list[CassiniState]:
        """The Cassini states that exist, numbered as Peale (1969), in order of number.

        Returns
        -------
        list of CassiniState

        Examples
        --------
        >>> [round(s.obliquity_deg, 3) for s in ColomboTop(1.0, 0.0, -2.0, 0.3).states()]
        [29.585, 168.443]
        """
        roots = self.roots()
        positive = [t for t in roots if t > 0]
        negative = sorted((t for t in roots if t <= 0), reverse=True)
        numbers = {1: (3,), 2: (1, 3), 3: (1, 4, 3)}.get(len(negative))
        if len(positive) != 1 or numbers is None:
            msg = f"expected one root in (0, pi) and one to three in (-pi, 0], got {roots.tolist()}"
            raise ValueError(msg)
        pairs = [(2, positive[0]), *zip(numbers, negative, strict=True)]
        return sorted((self._state(number, theta) for number, theta in pairs), key=lambda s: s.number)

    def _state(self, number: int, theta: float) -> CassiniState:
        along = float(self.derivative(theta))
        c = math.cos(theta)
        across = self.alpha * c * c + self.beta * c + self.node_rate * math.cos(theta - self.inclination)
        inclination = math.acos(max(-1.0, min(1.0, math.cos(theta - self.inclination))))
        return CassiniState(
            number=number,
            theta=theta,
            obliquity=abs(theta),
            inclination_to_laplace=inclination,
            energy=float(self.hamiltonian(theta)),
            curvatures=(along, across),
            stable=along * across > 0,
        )

    def separatrix_energy(self) -> float | None:
        """``𝓗`` of state 4, the separatrix level, or ``None`` where state 4 does not exist.

        Examples
        --------
        >>> ColomboTop(1.0, 0.0, -2.0, 0.3).separatrix_energy() is None
        True
        """
        for state in self.states():
            if state.number == 4:
                return state.energy
        return None

    def separatrix(self, phi: ArrayLike) -> Array:
        """The obliquities ``θ ∈ [0, π]`` of the separatrix at longitudes ``φ`` (NaN-padded to 4 each).

        Solves ``𝓗(θ, φ) = 𝓗(state 4)`` exactly: with ``X = cos θ``, ``b = β + g cos i``,
        ``c = g sin i cos φ`` and ``P(X) = −(α/2)X² − bX − E``, the level is ``P = c sin θ``,
        whose square is the quartic ``(α²/4)X⁴ + αbX³ + (b² + αE + c²)X² + 2bEX + E² − c² = 0``
        (roots batched through companion matrices; the sign of ``P`` picks the true ones).

        Parameters
        ----------
        phi : array_like, shape (m,)

        Returns
        -------
        numpy.ndarray, shape (m, 4)
            Sorted, NaN where fewer than four points; all NaN without a state 4.

        Examples
        --------
        >>> top = ColomboTop(1.0, 0.0, -0.1, 0.2)
        >>> theta = top.separatrix([0.5])
        >>> ok = np.isfinite(theta)
        >>> bool(np.allclose(top.hamiltonian(theta[ok], 0.5), top.separatrix_energy(), atol=1e-12))
        True
        """
        p = np.atleast_1d(as_finite(phi, "phi")).reshape(-1)
        out = np.full((p.size, 4), np.nan)
        energy = self.separatrix_energy()
        if energy is None:
            return out
        a, g, i = self.alpha, self.node_rate, self.inclination
        b = self.beta + g * math.cos(i)
        c = g * math.sin(i) * np.cos(p)
        quartic = np.stack(
            [
                np.full_like(c, a * a / 4),
                np.full_like(c, a * b),
                b * b + a * energy + c * c,
                np.full_like(c, 2 * b * energy),
                energy * energy - c * c,
            ],
            axis=-1,
        )
        companion = np.zeros((p.size, 4, 4))
        companion[:, 1:, :-1] = np.eye(3)
        companion[:, :, -1] = -quartic[:, :0:-1] / quartic[:, :1]
        X = np.linalg.eigvals(companion)
        real = np.abs(X.imag) <= 1e-7
        X = np.clip(X.real, -1.0, 1.0)
        theta = np.arccos(X)
        level = np.abs(self.hamiltonian(theta, p[:, None]) - energy)
        keep = real & (level <= 1e-9 * (a + abs(g) + self.beta))
        theta = np.where(keep, theta, np.nan)
        return np.sort(theta, axis=-1)
