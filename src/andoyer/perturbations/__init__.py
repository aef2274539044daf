"""Disturbing models: each a Hamiltonian term ``ΔH`` with its torque, or a torque alone.

Each term carries its own pieces for the integrators (the term protocol of
:mod:`andoyer.perturbations.base`); the body is given once, to the :class:`Model`.

See :mod:`andoyer.perturbations.base` for the equations of motion they enter.
"""

from andoyer.perturbations.andoyer_form import andoyer_perturbed_equations
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.base import Perturbation, SumOfPerturbations
from andoyer.perturbations.equations import perturbed_rates
from andoyer.perturbations.frame import PrecessingFrame
from andoyer.perturbations.gravity import GravityGradient, PointMass
from andoyer.perturbations.heavy_top import (
    HeavyTop,
    kovalevskaya_integral,
    kovalevskaya_integral_e3,
    kovalevskaya_top,
    lagrange_top,
)
from andoyer.perturbations.model import Model
from andoyer.perturbations.orbits import CircularOrbit, KeplerOrbit, Orbit, TabulatedOrbit, solve_kepler
from andoyer.perturbations.user import LinearDamping, UserPotential, UserTorque

__all__ = [
    "CircularOrbit",
    "GravityGradient",
    "HeavyTop",
    "KeplerOrbit",
    "LinearDamping",
    "Model",
    "Orbit",
    "Perturbation",
    "PointMass",
    "PrecessingFrame",
    "SecularGravityGradient",
    "SumOfPerturbations",
    "TabulatedOrbit",
    "UserPotential",
    "UserTorque",
    "andoyer_perturbed_equations",
    "kovalevskaya_integral",
    "kovalevskaya_integral_e3",
    "kovalevskaya_top",
    "lagrange_top",
    "perturbed_rates",
    "solve_kepler",
]
