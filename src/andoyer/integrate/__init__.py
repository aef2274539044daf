"""Propagation of perturbed rotation: one package per method, and the call that picks one.

``andoyer.propagate(model, state, t, method=M)`` (:func:`~andoyer.integrate.propagation.propagate`)
runs the method ``M`` of its own package: :mod:`andoyer.integrate.reference` (DOP853 or heyoka on
the full equations), :mod:`andoyer.integrate.splitting` (the exact free flow composed with kicks
and frame rotations) and :mod:`andoyer.integrate.secular` (the averaged model of a fast
rotator). The output times they share are :mod:`andoyer.integrate.output`; the exact rotations
and the composition schemes they share with the spin axis, :mod:`andoyer.compositions`.
"""

from andoyer.integrate.propagation import propagate
from andoyer.integrate.reference import integrate_reference
from andoyer.integrate.reference.euler_poisson import (
    euler_poisson_integrals,
    euler_poisson_rates,
    integrate_euler_poisson,
)
from andoyer.perturbations.model import Model

__all__ = [
    "Model",
    "euler_poisson_integrals",
    "euler_poisson_rates",
    "integrate_euler_poisson",
    "integrate_reference",
    "propagate",
]
