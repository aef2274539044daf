r"""Cassini states: the equilibria of Colombo's top (Peale 1969; Ward 1975; Henrard & Murigande 1987).

A body with second-degree gravity coefficients ``(J2, C22)`` and polar moment ``C/MR²``
circles its primary on an orbit of inclination ``i`` to a Laplace plane; the orbit's node
regresses uniformly, ``Ω̇ = g < 0``. Averaged over the orbit and the rotation, the spin axis
``s`` (a unit vector; principal-axis rotation about the axis of ``C``) obeys, in the frame
that turns with the node (Laplace pole ``K``, orbit normal ``k`` fixed in it),

.. math::
   \frac{d\mathbf s}{dt} = \nabla\mathcal H \times \mathbf s, \qquad
   \mathcal H(\mathbf s) = -\frac{\alpha}{2}(\mathbf s\cdot\mathbf k)^2
   - \beta\,(\mathbf s\cdot\mathbf k) - g\,(\mathbf s\cdot\mathbf K),

the Hamiltonian of Colombo's top per unit spin angular momentum ``G = Cω`` (rad/yr). It is the
Andoyer pair ``(h, H/G)`` of a frame with ``k`` as the reference axis: ``s·k = cos θ = H/G``,
and the last term is the precessing frame's ``ΔH = −μ·M`` (Gurfil et al. eq. 126) with
``μ = g K`` (:class:`~andoyer.perturbations.PrecessingFrame`). The sign convention is the
project's: ``dM/dt = ∇H × M`` for reference-frame momenta
(:class:`~andoyer.perturbations.averaged_gravity.SecularGravityGradient`).

**The constants.** The orbit-averaged MacCullagh energy of a body rotating about ``C``,
``U = (3μ_p/2r³) r̂·I r̂``, with ``C − A = MR²(J2 + 2C22)``, ``B − A = 4MR²C22``,
``⟨r̂r̂ᵀ/r³⟩ = (1 − kkᵀ)/(2a³(1−e²)^{3/2})`` and, in a ``p:1`` spin–orbit resonance
(the long axis ``A`` aligned with the primary at periapsis), the Hansen coefficient

.. math:: G_p(e) = \frac{1}{2\pi}\oint \Big(\frac ar\Big)^3 \cos(2f - 2pM)\, dM
   \qquad (G_1 = 1 - \tfrac52 e^2 + \tfrac{13}{16}e^4 + \dots,\ \
   G_{3/2} = \tfrac72 e - \tfrac{123}{16}e^3 + \tfrac{489}{128}e^5 + \dots),

is ``U = −(3n'^2MR²/4)[(J2/(1−e²)^{3/2} + C22 G_p)\cos^2θ + 2 C22 G_p \cos θ] + const``
with ``n'^2 = μ_p/a³ = n²/(1 + m/M)``. Divided by ``G = C ω`` (``ω = p n``):

.. math::
   \alpha = \frac{3 n'^2}{2\omega}\,\frac{J_2 (1-e^2)^{-3/2} + C_{22} G_p(e)}{C/MR^2}, \qquad
   \beta = \frac{3 n'^2}{2\omega}\,\frac{C_{22} G_p(e)}{C/MR^2}.

A non-resonant (fast) rotator averages ``C22`` out: ``β = 0`` and ``α`` keeps the ``J2``
term only, the precession constant of :mod:`andoyer.planetary.precession`. For a synchronous body at
small obliquity ``α + β ≈ (3n/2)(C − A)/C``.

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

Left out: the forced physical librations (the Moon's, Mercury's 88-day 38.5″ libration), the
non-uniform motion of the orbit (the Moon's solar perturbations, Mercury's pericentre
precession), tides and core–mantle friction (the Moon's pole lags its Cassini state by about
0.26″, Williams et al. 2001) and the non-rigid response: see ``docs/cassini.md``.

Examples
--------
>>> from andoyer.planetary import cassini
>>> [(s.number, round(s.obliquity_deg, 2), s.stable) for s in cassini.states("moon")]
[(2, 6.69, True), (3, 175.68, True)]
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from andoyer._validation import as_finite
from andoyer.planetary.parameters import check

__all__ = [
    "BODIES",
    "CassiniBody",
    "CassiniState",
    "ColomboTop",
    "eccentricity_function",
    "get",
    "states",
]

Array = NDArray[np.float64]
ARCSEC = math.pi / 648000.0
DAYS_PER_YEAR = 365.25  # Julian year


def eccentricity_function(eccentricity: ArrayLike, resonance: float) -> Array:
    r"""Peale's ``G_p(e) = (1/2π)∮ (a/r)³ cos(2f − 2pM) dM`` (the Hansen coefficient ``X^{-3,2}_{2p}``).

    Computed by the trapezoidal rule in the eccentric anomaly, ``(a/r)³ dM = dE/(1 − e cos E)²``,
    exact to round-off for ``e ≤ 0.9`` (the integrand is analytic and periodic).

    Parameters
    ----------
    eccentricity : array_like, shape (...)
        ``0 ≤ e < 1``.
    resonance : float
        ``p = ω/n`` with ``2p`` a positive integer (1 synchronous, 1.5 Mercury).

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> e = 0.05
    >>> round(float(eccentricity_function(e, 1.0)), 8), round(1 - 2.5 * e**2 + 13 / 16 * e**4, 8)
    (0.99375508, 0.99375508)
    """
    e = as_finite(eccentricity, "eccentricity")
    twice = 2 * float(resonance)
    if not (twice >= 1 and twice == round(twice)):
        msg = f"expected a spin-orbit resonance p with 2p a positive integer, got {resonance!r}"
        raise ValueError(msg)
    if np.any((e < 0) | (e >= 1)):
        msg = f"expected 0 <= eccentricity < 1, got {_describe_first(e)}"
        raise ValueError(msg)
    E = np.linspace(0.0, 2 * np.pi, 4097)[:-1]
    shape = e.shape
    ee = e.reshape(-1, 1)
    f = 2 * np.arctan2(np.sqrt(1 + ee) * np.sin(E / 2), np.sqrt(1 - ee) * np.cos(E / 2))
    M = E - ee * np.sin(E)
    integrand = np.cos(2 * f - twice * M) / (1 - ee * np.cos(E)) ** 2
    return integrand.mean(axis=-1).reshape(shape)


def _describe_first(values: Array) -> str:
    """The first offending value of a bounds check, for error messages."""
    return repr(float(values.flat[0])) if values.size == 1 else f"values in [{values.min()}, {values.max()}]"


def _positive_finite(value: float, name: str) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        msg = f"expected a positive finite {name}, got {value!r}"
        raise ValueError(msg)
    return v


@dataclass(frozen=True)
class CassiniBody:
    """A body on a uniformly precessing orbit: everything the Cassini states depend on.

    Rates are radians per Julian year and angles radians (the API's units).

    Attributes
    ----------
    name : str
    j2, c22 : float
        Unnormalised degree-2 coefficients, ``J2 = (C − (A+B)/2)/MR²``, ``C22 = (B − A)/4MR²``.
    moment_of_inertia : float
        ``C/MR²`` (same ``R`` as ``J2`` and ``C22``), in ``(0, 1]``.
    mean_motion : float
        Orbital mean motion ``n`` (rad/yr).
    eccentricity : float
    inclination : float
        Orbit to Laplace plane, ``0 < i < π/2``.
    node_rate : float
        ``g = Ω̇ < 0`` (rad/yr), a regressing node.
    resonance : float or None
        Spin–orbit ratio ``p = ω/n`` (1 synchronous, 1.5 Mercury); ``None`` for a
        non-resonant rotator spinning at ``spin_rate``.
    spin_rate : float or None
        ``ω`` (rad/yr), required when ``resonance`` is ``None``.
    mass_ratio : float
        Body mass over the primary's: the torque uses ``μ_p/a³ = n²/(1 + m/M)``.
    source : str
        Where the numbers come from.

    Examples
    --------
    >>> moon = get("moon")
    >>> round(moon.precession_constant / ARCSEC, 1), round(moon.resonance_constant / ARCSEC, 1)
    (14797.8, 1452.4)
    """

    name: str
    j2: float
    c22: float
    moment_of_inertia: float
    mean_motion: float
    eccentricity: float
    inclination: float
    node_rate: float
    resonance: float | None = 1.0
    spin_rate: float | None = None
    mass_ratio: float = 0.0
    source: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        for name in ("j2", "c22", "moment_of_inertia", "mean_motion", "eccentricity", "inclination",
                     "node_rate", "mass_ratio"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
                msg = f"expected a finite real {name}, got {value!r}"
                raise ValueError(msg)
        c = check("moment_of_inertia", self.moment_of_inertia)
        j2, c22 = check("j2", self.j2), check("c22", self.c22)
        if not j2 >= 2 * c22:
            msg = f"expected J2 > 0 and 0 <= C22 <= J2/2 (C the largest moment), got J2={j2!r}, C22={c22!r}"
            raise ValueError(msg)
        a = c - j2 - 2 * c22
        b = c - j2 + 2 * c22
        if not (a > 0 and a + b >= c):
            msg = f"expected moments A > 0 with A + B >= C, got A={a!r}, B={b!r}, C={c!r} (units MR^2)"
            raise ValueError(msg)
        _positive_finite(self.mean_motion, "mean_motion")
        check("eccentricity", self.eccentricity)
        check("laplace_inclination", self.inclination)
        if not self.node_rate < 0:
            msg = f"expected a regressing node (node_rate < 0), got {self.node_rate!r}"
            raise ValueError(msg)
        if self.mass_ratio < 0:
            msg = f"expected mass_ratio >= 0, got {self.mass_ratio!r}"
            raise ValueError(msg)
        if self.resonance is None:
            if self.spin_rate is None:
                msg = "expected a spin_rate for a non-resonant body (resonance=None), got None"
                raise ValueError(msg)
            _positive_finite(self.spin_rate, "spin_rate")
        else:
            eccentricity_function(0.0, self.resonance)  # validates p

    @property
    def rotation_rate(self) -> float:
        """``ω = p n`` in resonance, else ``spin_rate`` (rad/yr)."""
        return self.spin_rate if self.resonance is None else self.resonance * self.mean_motion

    def _scale(self) -> float:
        n2 = self.mean_motion**2 / (1 + self.mass_ratio)
        return 3 * n2 / (2 * self.rotation_rate * self.moment_of_inertia)

    @property
    def eccentricity_factor(self) -> float:
        """``G_p(e)`` of the resonance (0 for a non-resonant body)."""
        if self.resonance is None:
            return 0.0
        return float(eccentricity_function(self.eccentricity, self.resonance))

    @property
    def precession_constant(self) -> float:
        """``α`` (rad/yr): the coefficient of ``−cos²θ/2`` in ``𝓗``."""
        x = (1 - self.eccentricity**2) ** 1.5
        return self._scale() * (self.j2 / x + self.c22 * self.eccentricity_factor)

    @property
    def resonance_constant(self) -> float:
        """``β`` (rad/yr): the coefficient of ``−cos θ`` in ``𝓗`` (0 unless resonant)."""
        return self._scale() * self.c22 * self.eccentricity_factor

    def top(self) -> ColomboTop:
        """The body's :class:`ColomboTop`."""
        return ColomboTop(self.precession_constant, self.resonance_constant, self.node_rate, self.inclination)

    def replace(self, **changes: object) -> CassiniBody:
        """A copy with some attributes changed (validated again)."""
        return replace(self, **changes)


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
            [np.full_like(c, a * a / 4), np.full_like(c, a * b), b * b + a * energy + c * c,
             np.full_like(c, 2 * b * energy), energy * energy - c * c],
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


# Named bodies. Rates in rad per Julian year; every number is cited where it is set.
_DEG = math.pi / 180.0
_TURN_PER_DAY = 2 * math.pi * DAYS_PER_YEAR

BODIES: dict[str, CassiniBody] = {
    "moon": CassiniBody(
        name="moon",
        # GRAIL gravity field GL0660B (Konopliv et al. 2013, JGR Planets 118, 1415), unnormalised,
        # R = 1738 km. The digits are UNVERIFIED (review, 2026: no reachable source prints them), but
        # they agree to 0.11% and 0.12% with the solid Moon's J2 = 2.0307e-4, C22 = 2.2367e-5 implied
        # at R = 1738 km by the LLR/GRAIL values below; a J2 change of 1e-7 moves state 2 by 0.001°.
        j2=2.0330e-4,
        c22=2.2394e-5,
        # Williams et al. (2014, JGR Planets 119, 1546), as SHTOOLS lists them
        # (pyshtools/constants/Moon.py): the solid Moon's mean moment I/MR² = 0.393112 ± 0.000012 at
        # the mean radius 1737.151 km, β = (C − A)/B = 631.0213e-6, γ = (B − A)/C = 227.7317e-6. With
        # B/C = (1 + γ)/(1 + β), A/C = B/C − γ: C/MR² = 3 (I/MR²)/(1 + A/C + B/C), rescaled by
        # (1737.151/1738)² to the gravity field's R = 1738 km: 0.392863. (0.393112 itself is a mean
        # moment at another radius, not C/MR²; the earlier 0.3929, said to come from issue 15, is not
        # in that issue. The whole Moon's I/MR² = 0.3931 ± 0.0002, Konopliv et al. 1998, would move
        # state 2 by 0.002°.)
        moment_of_inertia=0.392863,
        # Mean orbit (Astronomical Almanac; Simon et al. 1994): sidereal month 27.321661 d,
        # e = 0.0549, i = 5.145° to the ecliptic (5.145396°, Meeus, Astronomical Algorithms;
        # the Moon's Laplace plane to < 0.01°), node period 6798.38 d (18.613 yr, retrograde).
        mean_motion=_TURN_PER_DAY / 27.321661,
        eccentricity=0.0549,
        inclination=5.145 * _DEG,
        node_rate=-_TURN_PER_DAY / 6798.38,
        resonance=1.0,
        # Earth/Moon mass ratio 81.30056 (IAU 2009 system of constants).
        mass_ratio=1 / 81.30056,
        source=(
            "Konopliv et al. 2013 (J2, C22; unverified digits); Williams et al. 2014 (I/MR2 + 2 J2/3); "
            "mean lunar orbit"
        ),
    ),
    "mercury": CassiniBody(
        name="mercury",
        # MESSENGER gravity (Smith et al. 2012, Science 336, 214): J2 = 5.03e-5, C22 = 0.81e-5,
        # R = 2440 km (UNVERIFIED digits: the paper is confirmed, these numbers are not);
        # C/MR² = 0.346 ± 0.014 (Margot et al. 2012, JGR 117, E00L09; confirmed by its abstract).
        j2=5.03e-5,
        c22=0.81e-5,
        moment_of_inertia=0.346,
        # Orbital period 87.969 d, e = 0.20563 (J2000 mean elements, Standish); inclination 8.6° to
        # the Laplace plane and node period ≈ 325 kyr (attributed to Yseboodt & Margot 2006, Icarus
        # 181, 327; UNVERIFIED: not found in a reachable source. The obliquity scales as |g| sin i;
        # the project's secular theory with La2004 frequencies suggests 7.95° and 328 kyr, i.e.
        # 1.889′ instead of 2.059′: see docs/cassini.md).
        mean_motion=_TURN_PER_DAY / 87.969257,
        eccentricity=0.20563,
        inclination=8.6 * _DEG,
        node_rate=-2 * math.pi / 325_000.0,
        resonance=1.5,
        # Sun/Mercury mass ratio 6023600 (IAU 2009 system of constants).
        mass_ratio=1 / 6023600.0,
        source="Smith et al. 2012 (J2, C22); Margot et al. 2012 (C/MR2); Yseboodt & Margot 2006 (i, node)",
    ),
}


def get(name: str) -> CassiniBody:
    """A named body (``"moon"``, ``"mercury"``), case-insensitive.

    Examples
    --------
    >>> get("Mercury").resonance
    1.5
    """
    key = str(name).lower()
    if key not in BODIES:
        msg = f"expected a body in {sorted(BODIES)}, got {name!r}"
        raise ValueError(msg)
    return BODIES[key]


def states(body: CassiniBody | str) -> list[CassiniState]:
    """The Cassini states of a body (or a named body), numbered as Peale (1969).

    Parameters
    ----------
    body : CassiniBody or str

    Returns
    -------
    list of CassiniState
        Those that exist, in order of number.

    Examples
    --------
    >>> state1 = next(s for s in states("mercury") if s.number == 1)
    >>> round(state1.obliquity_deg * 60, 2)  # arcmin; Margot et al. (2012) measure 2.04 ± 0.08
    2.06
    """
    system = get(body) if isinstance(body, str) else body
    if not isinstance(system, CassiniBody):
        msg = f"expected a CassiniBody or a body name, got {type(body).__name__}"
        raise ValueError(msg)
    return system.top().states()
