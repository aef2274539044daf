r"""Hamilton's equations of a model's ``K = T + ΔH`` in Andoyer variables.

The equations are the Andoyer chart's (:func:`andoyer.state.andoyer.andoyer_equations`,
derived in :mod:`andoyer.state.andoyer`); this module hands them a :class:`Model`'s body
and perturbation.
"""

from __future__ import annotations

from numpy.typing import ArrayLike

from andoyer.perturbations.model import Model
from andoyer.state.andoyer import AndoyerRates, andoyer_equations

__all__ = ["andoyer_perturbed_equations"]


def andoyer_perturbed_equations(
    model: Model,
    t: ArrayLike,
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
) -> AndoyerRates:
    """Rates of the Andoyer variables under ``T + ΔH`` of a Hamiltonian model.

    Parameters
    ----------
    model : Model
        Body and Hamiltonian perturbations (a dissipative torque has no Andoyer Hamiltonian).
    t : array_like, shape (...)
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer variables off the singular set ``sin I sin J = 0``; all broadcast.

    Returns
    -------
    AndoyerRates

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import PrecessingFrame
    >>> model = Model(RigidBody(1.0, 1.0, 1.0), PrecessingFrame([0.0, 0.0, 0.25]))
    >>> rates = andoyer_perturbed_equations(model, 0.0, 0.1, 0.2, 0.3, 0.5, 1.0, 0.6)
    >>> round(float(rates.h), 15)  # ΔH = -μ H: the node regresses at μ
    -0.25
    """
    return andoyer_equations(model.body, l, g, h, L, G, H, perturbation=model.perturbation, t=t)
