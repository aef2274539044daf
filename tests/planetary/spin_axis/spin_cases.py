"""Test-only orbit histories with closed forms, and helpers for the spin-axis tests."""

from __future__ import annotations

import numpy as np


class PrecessingOrbit:
    """An orbit whose node regresses uniformly: ``n = (sin i sin Ω, −sin i cos Ω, cos i)``, ``Ω = Ω₀ + g t``.

    The perihelion sits at the argument ``ω = ω₀ + k t`` from the node, with a constant ``e``.
    In the frame turning with the node the spin-axis problem is autonomous (Colombo's top).
    """

    name = "test-precessing"
    span = (-1e9, 1e9)
    has_eccentricity = True

    def __init__(self, inclination=0.03, node0=0.4, node_rate=-2 * np.pi / 70000.0, e=0.05, omega0=1.1,
                 apsidal_rate=2 * np.pi / 25000.0):
        self.i, self.node0, self.g = inclination, node0, node_rate
        self.e, self.omega0, self.k = e, omega0, apsidal_rate

    def node(self, t):
        return self.node0 + self.g * np.asarray(t, dtype=float)

    def normal(self, t):
        node = self.node(t)
        si, ci = np.sin(self.i), np.cos(self.i)
        return np.stack([si * np.sin(node), -si * np.cos(node), ci + 0 * node], axis=-1)

    def node_vector(self, t):
        node = self.node(t)
        return np.stack([np.cos(node), np.sin(node), 0 * node], axis=-1)

    def eccentricity_vector(self, t):
        u = self.node_vector(t)
        v = np.cross(self.normal(t), u)
        w = (self.omega0 + self.k * np.asarray(t, dtype=float))[..., None]
        return self.e * (np.cos(w) * u + np.sin(w) * v)


class FixedOrbit(PrecessingOrbit):
    """A fixed ecliptic ``n = z`` with a fixed perihelion on ``+x`` (``e`` given)."""

    name = "test-fixed"

    def __init__(self, e=0.0167):
        super().__init__(inclination=0.0, node0=0.0, node_rate=0.0, e=e, omega0=0.0, apsidal_rate=0.0)


def angle(a, b):
    """Angle between unit vectors (accurate when small)."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), np.sum(a * b, axis=-1))
