r"""A body on a uniformly precessing orbit (:class:`CassiniBody`): its precession and resonance constants.

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

Examples
--------
>>> body = CassiniBody("x", j2=2e-4, c22=2e-5, moment_of_inertia=0.39, mean_motion=84.0,
...                    eccentricity=0.05, inclination=0.09, node_rate=-0.34)
>>> round(body.precession_constant, 6), round(body.resonance_constant, 6)
(0.07128, 0.006421)
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.planetary.cassini.top import ColomboTop
from andoyer.planetary.parameters import check

__all__ = ["CassiniBody", "eccentricity_function"]

Array = NDArray[np.float64]

#: The largest spin-orbit ratio ``p``: the quadrature of ``G_p(e)`` (4096 points in the
#: eccentric anomaly) resolves ``cos 2pM`` far beyond it.
MAX_RESONANCE = 100


def eccentricity_function(eccentricity: ArrayLike, resonance: float) -> Array:
    r"""Peale's ``G_p(e) = (1/2π)∮ (a/r)³ cos(2f − 2pM) dM`` (the Hansen coefficient ``X^{-3,2}_{2p}``).

    Computed by the trapezoidal rule in the eccentric anomaly, ``(a/r)³ dM = dE/(1 − e cos E)²``,
    exact to round-off for ``e ≤ 0.9`` (the integrand is analytic and periodic).

    Parameters
    ----------
    eccentricity : array_like, shape (...)
        ``0 ≤ e < 1``.
    resonance : float
        ``p = ω/n`` with ``2p`` a positive integer up to :data:`MAX_RESONANCE` ``× 2`` (1
        synchronous, 1.5 Mercury).

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
    if not (1 <= twice <= 2 * MAX_RESONANCE and twice == round(twice)):
        msg = (
            f"expected a spin-orbit resonance p with 2p a positive integer, p <= {MAX_RESONANCE}, "
            f"got {resonance!r}"
        )
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
    >>> from andoyer.planetary import cassini
    >>> from andoyer.catalogue.units import ARCSEC
    >>> moon = cassini.get("moon")
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
        for name in (
            "j2",
            "c22",
            "moment_of_inertia",
            "mean_motion",
            "eccentricity",
            "inclination",
            "node_rate",
            "mass_ratio",
        ):
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
        if not 0 <= self.mass_ratio < 1:
            msg = f"expected 0 <= mass_ratio < 1 (a body lighter than its primary), got {self.mass_ratio!r}"
            raise ValueError(msg)
        if not self.mean_motion > abs(self.node_rate):
            msg = (
                "expected a mean motion above the node's rate (the averages over the orbit need "
                f"n >> |g|), got n = {self.mean_motion!r}, g = {self.node_rate!r} rad/yr"
            )
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

    @cached_property
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
