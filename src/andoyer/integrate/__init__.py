"""Propagation of perturbed rotation: models and integrators."""

from andoyer.integrate.euler_poisson import (
    euler_poisson_integrals,
    euler_poisson_rates,
    integrate_euler_poisson,
)
from andoyer.integrate.reference import integrate_reference
from andoyer.perturbations.model import Model

__all__ = [
    "Model",
    "euler_poisson_integrals",
    "euler_poisson_rates",
    "integrate_euler_poisson",
    "integrate_reference",
]
