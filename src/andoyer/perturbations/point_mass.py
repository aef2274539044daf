"""A perturbing point mass: its gravitational parameter and its orbit."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from andoyer.perturbations.orbits import Orbit

__all__ = ["PointMass"]


@dataclass(frozen=True)
class PointMass:
    """A perturbing point mass: gravitational parameter ``gm = G M`` and its orbit.

    Examples
    --------
    >>> from andoyer.perturbations import CircularOrbit
    >>> sun = PointMass(1.0, CircularOrbit(1.0, 1.0), name="Sun")
    >>> sun.name
    'Sun'
    """

    gm: float
    orbit: Orbit
    name: str = ""

    def __post_init__(self) -> None:
        if not np.isfinite(self.gm) or self.gm <= 0:
            msg = f"expected a positive finite gravitational parameter gm, got {self.gm!r}"
            raise ValueError(msg)
        if not isinstance(self.orbit, Orbit):
            msg = f"expected an Orbit, got {type(self.orbit).__name__}"
            raise ValueError(msg)
