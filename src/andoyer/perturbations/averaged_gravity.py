r"""The averaged gravity-gradient term: the secular model of a fast rotator's angular momentum.

Averaging ``ΔH`` of :class:`~andoyer.perturbations.GravityGradient` uniformly
over the body's rotation about ``b3`` (``l``), over the rotation about the
angular momentum (``g``, at fixed ``J``) and over each perturber's mean
anomaly gives, up to constants,

.. math::
   \langle\Delta H\rangle = \sum_p \kappa_p\,(\mathbf n\cdot\mathbf k_p)^2, \qquad
   \kappa_p = -\frac{3\mu_p}{4a_p^3(1-e_p^2)^{3/2}}
   \Big(C - \frac{A+B}{2}\Big)\frac{3\cos^2 J - 1}{2},

with ``n = M/G`` the angular-momentum direction, ``k_p`` the orbit normal of
perturber ``p`` (time-dependent when its node drifts), ``C = I3`` and
``A + B = I1 + I2``. It uses the two averages
``⟨b3 b3ᵀ⟩_g = cos²J n nᵀ + ½ sin²J (1 - n nᵀ)`` and
``⟨r̂ r̂ᵀ/r³⟩_M = (1 - k kᵀ) / (2 a³ (1 - e²)^{3/2})``. In Andoyer variables,
``n·k = sin I sin i cos(h - Ω) + cos I cos i`` and Hamilton's equations of
``⟨ΔH⟩`` give ``ḣ = ∂⟨ΔH⟩/∂H`` and ``Ḣ = -∂⟨ΔH⟩/∂h`` (``G``, ``L`` constant);
the non-singular vector form integrated here is

.. math:: \dot{\mathbf M} = \sum_p \frac{2\kappa_p (\mathbf M\cdot\mathbf k_p)}{G^2}\,
   \mathbf k_p\times\mathbf M .

Averaging uniformly in ``l`` is exact for an axisymmetric body and first order
in the triaxiality otherwise: the model targets the major planets.

:meth:`andoyer.perturbations.GravityGradient.secular_average` gives this model; its flow
is integrated by :func:`andoyer.integrate.secular.propagate_momentum`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_finite, as_vectors
from andoyer.body import RigidBody
from andoyer.perturbations.orbits import KeplerOrbit
from andoyer.perturbations.point_mass import PointMass

__all__ = ["SecularGravityGradient"]

Array = NDArray[np.float64]


class SecularGravityGradient:
    """The averaged gravity-gradient model of a fast rotator (see the module docstring).

    Parameters
    ----------
    body : RigidBody
        ``b3`` is the figure (rotation) axis.
    perturbers : sequence of PointMass
        Each on a :class:`~andoyer.perturbations.KeplerOrbit` (its node and
        periapsis may drift linearly; the drift enters through ``k_p(t)``).

    Examples
    --------
    >>> from andoyer import bodies
    >>> from andoyer.catalogue.units import ARCSEC
    >>> from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR, OBLIQUITY, mean_perturbers
    >>> earth = bodies.get("earth")
    >>> sun = mean_perturbers("earth")[0]
    >>> model = SecularGravityGradient(earth, sun)
    >>> G = earth.C * 2 * np.pi / 86164.0905
    >>> rate = model.node_rate(G, G, G * np.cos(OBLIQUITY["earth"]))  # rad/s
    >>> round(float(-rate * JULIAN_YEAR / ARCSEC), 2)  # the Sun's share, arcsec per year
    15.97
    """

    #: Its flow is a composition of exact rotations about the orbit normals
    #: (:func:`andoyer.integrate.secular.propagate_momentum`, compiled with numba).
    exact_rotations = True

    def __init__(self, body: RigidBody, perturbers: PointMass | Sequence[PointMass]) -> None:
        if not isinstance(body, RigidBody):
            msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
            raise ValueError(msg)
        self.body = body
        self.perturbers = (perturbers,) if isinstance(perturbers, PointMass) else tuple(perturbers)
        if not self.perturbers:
            msg = "expected one or more PointMass perturbers on Kepler orbits, got none"
            raise ValueError(msg)
        for p in self.perturbers:
            if not isinstance(p, PointMass) or not isinstance(p.orbit, KeplerOrbit):
                msg = f"expected PointMass perturbers on Kepler orbits, got {p!r}"
                raise ValueError(msg)
        I1, I2, I3 = body.moments
        self.dynamical_flattening = I3 - 0.5 * (I1 + I2)

    def strength(self, p: PointMass, L: Array, G: Array) -> Array:
        """``κ_p`` of perturber ``p`` for ``L`` and ``G`` (...), see the module docstring."""
        orbit = p.orbit
        a, e = orbit.semi_major_axis, orbit.eccentricity
        cos_j2 = (L / G) ** 2
        return (
            -3
            * p.gm
            / (4 * a**3 * ((1 - e) * (1 + e)) ** 1.5)
            * self.dynamical_flattening
            * (3 * cos_j2 - 1)
            / 2
        )

    @staticmethod
    def normal(p: PointMass, t: Array) -> Array:
        """The orbit normal ``k_p(t)`` of perturber ``p`` (reference components), shape (..., 3)."""
        orbit = p.orbit
        node = orbit.node + orbit.node_rate * (t - orbit.epoch)
        si, ci = np.sin(orbit.inclination), np.cos(orbit.inclination)
        if np.ndim(node) == 0:  # one time (the set-up of every secular run): no stacking of arrays
            return np.array([si * np.sin(node), -si * np.cos(node), ci + 0 * node])
        return np.stack([si * np.sin(node), -si * np.cos(node), ci + 0 * node], -1)

    def potential(self, t: ArrayLike, M: ArrayLike, L: ArrayLike) -> Array:
        """``⟨ΔH⟩`` for reference-frame momenta ``M`` (..., 3) and ``L`` (...), at times ``t``."""
        M = as_vectors(M, "M")
        L = as_finite(L, "L")
        G = np.linalg.norm(M, axis=-1)
        t = as_finite(t, "t")
        return sum(
            self.strength(p, L, G) * (np.sum(M * self.normal(p, t), -1) / G) ** 2 for p in self.perturbers
        )

    def momentum_rate(self, t: ArrayLike, M: ArrayLike, L: ArrayLike) -> Array:
        """``dM/dt`` of the reference-frame angular momentum, shape (..., 3)."""
        M = as_vectors(M, "M")
        L = as_finite(L, "L")
        t = as_finite(t, "t")
        G2 = np.sum(M * M, axis=-1)
        rate = 0.0
        for p in self.perturbers:
            k = self.normal(p, t)
            coefficient = 2 * self.strength(p, L, np.sqrt(G2)) * np.sum(M * k, -1) / G2
            rate = rate + coefficient[..., None] * quat.cross(k, M)
        return rate * np.ones_like(M)

    def node_rate(
        self, L: ArrayLike, G: ArrayLike, H: ArrayLike, t: ArrayLike = 0.0, h: ArrayLike = 0.0
    ) -> Array:
        """``dh/dt = ∂⟨ΔH⟩/∂H`` in Andoyer variables (singular at ``sin I = 0``)."""
        L, G, H, t, h = (as_finite(v, n) for v, n in ((L, "L"), (G, "G"), (H, "H"), (t, "t"), (h, "h")))
        cI, sI = H / G, np.sqrt((G - H) * (G + H)) / G
        total = 0.0
        for p in self.perturbers:
            orbit = p.orbit
            node = orbit.node + orbit.node_rate * (t - orbit.epoch)
            si, ci = np.sin(orbit.inclination), np.cos(orbit.inclination)
            nk = sI * si * np.cos(h - node) + cI * ci
            dnk_dH = si * np.cos(h - node) * (-cI / (G * sI)) + ci / G
            total = total + 2 * self.strength(p, L, G) * nk * dnk_dH
        return total

    def split_normals(self) -> tuple[list[int], list[int]]:
        """Perturbers about one fixed normal (the outer flow) and the rest (drifting or not)."""
        outer: list[int] = []
        inner: list[int] = []
        first = None
        for i, p in enumerate(self.perturbers):
            fixed = p.orbit.node_rate == 0 or np.sin(p.orbit.inclination) == 0
            k = self.normal(p, 0.0)
            if fixed and (first is None or np.array_equal(k, first)):
                first = k
                outer.append(i)
            else:
                inner.append(i)
        return outer, inner
