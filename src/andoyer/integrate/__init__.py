"""Propagation of perturbed rotation: models and integrators."""

from andoyer.integrate.model import Model
from andoyer.integrate.reference import integrate_reference

__all__ = ["Model", "integrate_reference"]
