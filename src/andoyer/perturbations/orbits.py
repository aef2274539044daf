r"""Orbits of perturbing bodies, as positions in the reference frame.

Elements are referred to the reference frame ``s``: inclination ``i`` on the
``s1 s2`` plane, longitude of the ascending node ``Ω`` from ``s1``, argument of
periapsis ``ω``. The position is

.. math:: \mathbf r = R_z(\Omega)\, R_x(i)\, R_z(\omega)\,
   a\,(\cos E - e,\ \sqrt{1-e^2}\,\sin E,\ 0),
   \qquad E - e \sin E = M = M_0 + n (t - t_0),

with ``Ω`` and ``ω`` optionally drifting linearly (a mean orbit with a
regressing node, such as the Moon's).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors

__all__ = ["CircularOrbit", "KeplerOrbit", "Orbit", "TabulatedOrbit", "solve_kepler"]

Array = NDArray[np.float64]


def solve_kepler(mean_anomaly: ArrayLike, eccentricity: ArrayLike) -> Array:
    """Eccentric anomaly ``E`` with ``E - e sin E = M`` for ``0 <= e < 1``, vectorised.

    Newton's iteration from ``E0 = M + 0.85 e sign(sin M)`` (Danby), on ``M``
    reduced to ``[-π, π)``; it converges to round-off for every ``e < 1`` in a
    few steps.

    Parameters
    ----------
    mean_anomaly : array_like, shape (...)
    eccentricity : array_like, shape (...)

    Returns
    -------
    numpy.ndarray, shape (...)
        ``E`` on the same branch as ``M`` (``E - M`` is ``2π``-periodic).

    Examples
    --------
    >>> E = solve_kepler(1.0, 0.5)
    >>> round(float(E - 0.5 * np.sin(E)), 15)
    1.0
    """
    M = as_finite(mean_anomaly, "mean_anomaly")
    e = as_finite(eccentricity, "eccentricity")
    if np.any((e < 0) | (e >= 1)):
        msg = f"expected 0 <= eccentricity < 1, got {float(np.max(np.abs(e))):.17g}"
        raise ValueError(msg)
    turns = np.floor((M + np.pi) / (2 * np.pi))
    Mr = M - 2 * np.pi * turns
    E = Mr + 0.85 * e * np.sign(np.sin(Mr))
    for _ in range(60):
        f = E - e * np.sin(E) - Mr
        step = f / (1 - e * np.cos(E))
        E = E - step
        if np.all(np.abs(step) <= 4 * np.finfo(float).eps * np.maximum(1.0, np.abs(E))):
            break
    return E + 2 * np.pi * turns


def _frame_rotation(node: Array, inclination: Array, periapsis: Array) -> Array:
    cO, sO = np.cos(node), np.sin(node)
    ci, si = np.cos(inclination), np.sin(inclination)
    cw, sw = np.cos(periapsis), np.sin(periapsis)
    # Columns: images of the perifocal x and y axes.
    px = np.stack([cO * cw - sO * ci * sw, sO * cw + cO * ci * sw, si * sw], axis=-1)
    py = np.stack([-cO * sw - sO * ci * cw, -sO * sw + cO * ci * cw, si * cw], axis=-1)
    return np.stack([px, py], axis=-1)


class Orbit:
    """Position of a perturber in the reference frame, ``position(t) -> (..., 3)``."""

    def position(self, t: ArrayLike) -> Array:
        """Position at times ``t`` (...), shape (..., 3)."""
        raise NotImplementedError


class KeplerOrbit(Orbit):
    """A Keplerian ellipse with optional linear drift of node and periapsis.

    Parameters
    ----------
    semi_major_axis, eccentricity, inclination, node, periapsis : float
        ``a > 0``, ``0 <= e < 1``, angles in radians.
    mean_anomaly : float
        ``M0`` at ``epoch``.
    mean_motion : float
        ``n`` (radians per time unit).
    epoch : float
    node_rate, periapsis_rate : float
        Linear drift of ``Ω`` and ``ω`` (radians per time unit).

    Examples
    --------
    >>> orbit = KeplerOrbit(2.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0)
    >>> orbit.position(0.0).round(12).tolist()  # periapsis at a (1 - e)
    [1.0, 0.0, 0.0]
    """

    def __init__(
        self,
        semi_major_axis: float,
        eccentricity: float,
        inclination: float,
        node: float,
        periapsis: float,
        mean_anomaly: float,
        mean_motion: float,
        epoch: float = 0.0,
        node_rate: float = 0.0,
        periapsis_rate: float = 0.0,
    ) -> None:
        values = {
            "semi_major_axis": semi_major_axis,
            "eccentricity": eccentricity,
            "inclination": inclination,
            "node": node,
            "periapsis": periapsis,
            "mean_anomaly": mean_anomaly,
            "mean_motion": mean_motion,
            "epoch": epoch,
            "node_rate": node_rate,
            "periapsis_rate": periapsis_rate,
        }
        for name, value in values.items():
            setattr(self, name, float(as_finite(value, name)))
        if self.semi_major_axis <= 0:
            msg = f"expected semi_major_axis > 0, got {self.semi_major_axis!r}"
            raise ValueError(msg)
        if not 0 <= self.eccentricity < 1:
            msg = f"expected 0 <= eccentricity < 1, got {self.eccentricity!r}"
            raise ValueError(msg)

    def position(self, t: ArrayLike) -> Array:
        """Position at times ``t`` (...), shape (..., 3)."""
        dt = as_finite(t, "t") - self.epoch
        E = solve_kepler(self.mean_anomaly + self.mean_motion * dt, self.eccentricity)
        a, e = self.semi_major_axis, self.eccentricity
        x = a * (np.cos(E) - e)
        y = a * np.sqrt((1 - e) * (1 + e)) * np.sin(E)
        frame = _frame_rotation(
            self.node + self.node_rate * dt,
            np.full_like(dt, self.inclination),
            self.periapsis + self.periapsis_rate * dt,
        )
        return frame[..., 0] * x[..., None] + frame[..., 1] * y[..., None]

    def __repr__(self) -> str:
        return f"KeplerOrbit(a={self.semi_major_axis!r}, e={self.eccentricity!r}, i={self.inclination!r})"


class CircularOrbit(KeplerOrbit):
    """A circular orbit of radius ``radius``: ``r = radius (cos u, sin u, 0)`` rotated by ``Ω``, ``i``.

    ``u = phase + mean_motion (t - epoch)`` is the argument of latitude.

    Examples
    --------
    >>> orbit = CircularOrbit(1.0, 2 * np.pi)
    >>> orbit.position(0.25).round(12).tolist()
    [0.0, 1.0, 0.0]
    """

    def __init__(
        self,
        radius: float,
        mean_motion: float,
        inclination: float = 0.0,
        node: float = 0.0,
        phase: float = 0.0,
        epoch: float = 0.0,
        node_rate: float = 0.0,
    ) -> None:
        super().__init__(radius, 0.0, inclination, node, 0.0, phase, mean_motion, epoch, node_rate)

    def position(self, t: ArrayLike) -> Array:
        """Position at times ``t`` (...), shape (..., 3)."""
        dt = as_finite(t, "t") - self.epoch
        u = self.mean_anomaly + self.mean_motion * dt
        frame = _frame_rotation(
            self.node + self.node_rate * dt, np.full_like(dt, self.inclination), np.zeros_like(dt)
        )
        a = self.semi_major_axis
        return frame[..., 0] * (a * np.cos(u))[..., None] + frame[..., 1] * (a * np.sin(u))[..., None]


class TabulatedOrbit(Orbit):
    """A perturber whose position is a user function of time, ``f(t) -> (..., 3)``.

    Examples
    --------
    >>> orbit = TabulatedOrbit(lambda t: np.stack([np.cos(t), np.sin(t), 0 * t], -1))
    >>> orbit.position(0.0).tolist()
    [1.0, 0.0, 0.0]
    """

    def __init__(self, function: Callable[[Array], ArrayLike]) -> None:
        if not callable(function):
            msg = f"expected a callable position(t), got {type(function).__name__}"
            raise ValueError(msg)
        self.function = function

    def position(self, t: ArrayLike) -> Array:
        """Position at times ``t`` (...), shape (..., 3)."""
        return as_vectors(self.function(as_finite(t, "t")), "position(t)")
