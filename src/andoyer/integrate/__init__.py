"""Propagation of perturbed rotation: models and integrators."""

from andoyer.integrate.reference import integrate_reference
from andoyer.perturbations.model import Model

__all__ = ["Model", "integrate_reference"]
