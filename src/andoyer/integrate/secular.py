r"""Secular (averaged) rotation of a fast rotator under gravity-gradient torques.

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
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from andoyer import _quaternion as quat
from andoyer._validation import as_finite, as_vectors
from andoyer.body import RigidBody
from andoyer.integrate.secular_steps import COMPOSITIONS, propagate_controlled
from andoyer.perturbations.gravity import PointMass
from andoyer.perturbations.orbits import KeplerOrbit

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
    >>> from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR, OBLIQUITY, mean_perturbers
    >>> earth = bodies.get("earth")
    >>> sun = mean_perturbers("earth")[0]
    >>> model = SecularGravityGradient(earth, sun)
    >>> G = earth.C * 2 * np.pi / 86164.0905
    >>> rate = model.node_rate(G, G, G * np.cos(OBLIQUITY["earth"]))  # rad/s
    >>> round(float(-rate * JULIAN_YEAR * 206264.806), 2)  # the Sun's share, arcsec per year
    15.97
    """

    def __init__(self, body: RigidBody, perturbers: PointMass | Sequence[PointMass]) -> None:
        if not isinstance(body, RigidBody):
            msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
            raise ValueError(msg)
        self.body = body
        self.perturbers = (perturbers,) if isinstance(perturbers, PointMass) else tuple(perturbers)
        for p in self.perturbers:
            if not isinstance(p, PointMass) or not isinstance(p.orbit, KeplerOrbit):
                msg = f"expected PointMass perturbers on Kepler orbits, got {p!r}"
                raise ValueError(msg)
        I1, I2, I3 = body.moments
        self.dynamical_flattening = I3 - 0.5 * (I1 + I2)

    def _strength(self, p: PointMass, L: Array, G: Array) -> Array:
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
    def _normal(p: PointMass, t: Array) -> Array:
        orbit = p.orbit
        node = orbit.node + orbit.node_rate * (t - orbit.epoch)
        si, ci = np.sin(orbit.inclination), np.cos(orbit.inclination)
        return np.stack([si * np.sin(node), -si * np.cos(node), ci + 0 * node], -1)

    def potential(self, t: ArrayLike, M: ArrayLike, L: ArrayLike) -> Array:
        """``⟨ΔH⟩`` for reference-frame momenta ``M`` (..., 3) and ``L`` (...), at times ``t``."""
        M = as_vectors(M, "M")
        L = as_finite(L, "L")
        G = np.linalg.norm(M, axis=-1)
        t = as_finite(t, "t")
        return sum(
            self._strength(p, L, G) * (np.sum(M * self._normal(p, t), -1) / G) ** 2 for p in self.perturbers
        )

    def momentum_rate(self, t: ArrayLike, M: ArrayLike, L: ArrayLike) -> Array:
        """``dM/dt`` of the reference-frame angular momentum, shape (..., 3)."""
        M = as_vectors(M, "M")
        L = as_finite(L, "L")
        t = as_finite(t, "t")
        G2 = np.sum(M * M, axis=-1)
        rate = 0.0
        for p in self.perturbers:
            k = self._normal(p, t)
            coefficient = 2 * self._strength(p, L, np.sqrt(G2)) * np.sum(M * k, -1) / G2
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
            total = total + 2 * self._strength(p, L, G) * nk * dnk_dH
        return total

    def propagate_momentum(
        self,
        M0: ArrayLike,
        L: ArrayLike,
        t: ArrayLike,
        rtol: float = 1e-12,
        method: str = "rotations",
        order: int = 8,
        max_step: float | None = None,
    ) -> Array:
        """Integrate ``dM/dt`` from ``t = 0`` to the times ``t`` (1-D, increasing), shape (len(t), ..., 3).

        Parameters
        ----------
        M0 : array_like, shape (..., 3)
            Reference-frame angular momenta at ``t = 0``.
        L : array_like, shape (...)
            ``L = M·b3`` (constant in the averaged model).
        t : array_like, shape (K,)
            Output times, non-negative and increasing.
        rtol : float
            Relative tolerance: DOP853's (per step), or for ``"rotations"`` the target
            relative global error of ``M``, met by Richardson's estimate
            (:func:`~andoyer.integrate.secular_steps.propagate_controlled`).
        method : {"rotations", "dop853"}
            ``"rotations"`` (default): palindromic composition of the exact rotations
            about each ``k_p`` (:mod:`andoyer.integrate.secular_steps`), fixed steps of
            up to two radians of the fastest rate (years for the planets), ``|M|``
            conserved to round-off. ``"dop853"``: scipy's adaptive DOP853.
        order : {2, 4, 6, 8}
            Order of the composition (``"rotations"`` only).
        max_step : float, optional
            Upper bound on the step (``"rotations"`` only; same units as ``t``).

        Returns
        -------
        numpy.ndarray, shape (K, ..., 3)

        Examples
        --------
        >>> from andoyer import bodies
        >>> from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers
        >>> earth = bodies.get("earth")
        >>> model = SecularGravityGradient(earth, mean_perturbers("earth"))
        >>> G = earth.C * 2 * np.pi / 86164.0905
        >>> M0 = G * np.array([0.0, -np.sin(OBLIQUITY["earth"]), np.cos(OBLIQUITY["earth"])])
        >>> M = model.propagate_momentum(M0, G, [100 * JULIAN_YEAR])
        >>> round(float(np.arctan2(M[0, 0], -M[0, 1]) * 206264.806 / 100), 2)  # arcsec per year
        -50.35
        """
        M0 = as_vectors(M0, "M0")
        L = np.broadcast_to(as_finite(L, "L"), M0.shape[:-1])
        times = as_finite(t, "t")
        if times.ndim != 1 or np.any(np.diff(times) < 0) or times[0] < 0:
            msg = "expected increasing, non-negative output times (1-D), got another array"
            raise ValueError(msg)
        if method == "dop853":
            return self._propagate_dop853(M0, L, times, rtol)
        if method != "rotations":
            msg = f"expected method 'rotations' or 'dop853', got {method!r}"
            raise ValueError(msg)
        if order not in COMPOSITIONS:
            msg = f"expected order in {sorted(COMPOSITIONS)}, got {order!r}"
            raise ValueError(msg)
        if not rtol > 0 or (max_step is not None and not max_step > 0):
            msg = f"expected positive rtol and max_step, got {rtol!r} and {max_step!r}"
            raise ValueError(msg)
        shape = M0.shape
        M = M0.reshape(-1, 3)
        G = np.linalg.norm(M, axis=-1)
        coef = np.array([2 * self._strength(p, L.reshape(-1), G) / G**2 for p in self.perturbers])
        outer, inner = self._split_normals()
        k0 = self._normal(self.perturbers[outer[0]], 0.0) if outer else np.array([0.0, 0.0, 1.0])
        c0 = coef[outer].sum(axis=0) if outer else np.zeros(len(M))
        orbits = [self.perturbers[i].orbit for i in inner]
        normals = (
            np.array([np.sin(o.inclination) for o in orbits]),
            np.array([np.cos(o.inclination) for o in orbits]),
            np.array([o.node - o.node_rate * o.epoch for o in orbits]),
            np.array([o.node_rate for o in orbits]),
        )
        fastest = max([float(np.max(np.abs(coef) * G, initial=0.0)), *np.abs(normals[3])], default=0.0)
        drifting = coef[inner].reshape(len(inner), len(M))
        bound = np.inf if max_step is None else float(max_step)
        out, _ = propagate_controlled(M, c0, k0, drifting, normals, times, fastest, rtol, order, bound)
        return out.reshape((len(times), *shape))

    def _split_normals(self) -> tuple[list[int], list[int]]:
        """Perturbers about one fixed normal (the outer flow) and the rest (drifting or not)."""
        outer: list[int] = []
        inner: list[int] = []
        first = None
        for i, p in enumerate(self.perturbers):
            fixed = p.orbit.node_rate == 0 or np.sin(p.orbit.inclination) == 0
            k = self._normal(p, 0.0)
            if fixed and (first is None or np.array_equal(k, first)):
                first = k
                outer.append(i)
            else:
                inner.append(i)
        return outer, inner

    def _propagate_dop853(self, M0: Array, L: Array, times: Array, rtol: float) -> Array:
        """DOP853 steps over years: the model has no fast angle left."""
        shape = M0.shape

        def rhs(time: float, y: Array) -> Array:
            return self.momentum_rate(time, y.reshape(shape), L).ravel()

        scale = float(np.max(np.linalg.norm(M0, axis=-1)))
        sol = solve_ivp(
            rhs,
            (0.0, float(times[-1])),
            M0.ravel(),
            method="DOP853",
            t_eval=times,
            rtol=rtol,
            atol=1e-15 * scale,
        )
        return sol.y.T.reshape((len(times), *shape))
