r"""Hamilton's equations of ``K = T + ΔH`` in Andoyer variables.

``ΔH`` is given on the hub, ``ΔH(t, q, m)``, with its torque ``τ`` and its
momentum gradient ``∂ΔH/∂m``. The Andoyer attitude
``R = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)`` turns, per unit change of each angle,
about a body-frame axis ``e_a``: ``b3`` for ``l``, the node
``j = (cos l, -sin l, 0)`` for ``J``, the momentum direction ``m/G`` for ``g``,
the node ``i`` for ``I`` and the vertical ``γ = Rᵀ s3`` for ``h``. Since
``δΔH = -τ·δθ`` for a body-frame rotation ``δθ``,

.. math::
   \frac{\partial\Delta H}{\partial a} = -\boldsymbol\tau\cdot\mathbf e_a
   + \frac{\partial\Delta H}{\partial\mathbf m}\cdot\frac{\partial\mathbf m}{\partial a},

with ``I(H, G)`` and ``J(L, G)`` entering through
``∂I/∂H = -1/(G sin I)``, ``∂I/∂G = cos I/(G sin I)`` and likewise for ``J``.
The chart is singular at ``sin I = 0`` and ``sin J = 0``, and so are these
equations there.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import broadcast_finite, check_momenta
from andoyer.charts.andoyer import andoyer_to_hub
from andoyer.equations import AndoyerRates, andoyer_equations
from andoyer.perturbations.model import Model

__all__ = ["andoyer_perturbed_equations"]

Array = NDArray[np.float64]


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
    body = model.body
    free = andoyer_equations(body, l, g, h, L, G, H)
    perturbation = model.perturbation
    if perturbation is None:
        return free
    if not perturbation.hamiltonian:
        msg = "expected Hamiltonian perturbations for the Andoyer-form equations, got a dissipative torque"
        raise ValueError(msg)
    t, l, g, h, L, G, H = broadcast_finite("tlghLGH", (t, l, g, h, L, G, H))
    check_momenta(L, G, H)
    q, m = andoyer_to_hub(l, g, h, L, G, H)
    tau = perturbation.torque(t, q, m)
    grad_m = perturbation.momentum_gradient(t, q, m)
    GsJ, GsI = np.sqrt((G - L) * (G + L)), np.sqrt((G - H) * (G + H))
    if np.any((GsJ == 0) | (GsI == 0)):
        msg = "expected sin I != 0 and sin J != 0 for the Andoyer-form equations, got a singular state"
        raise ValueError(msg)
    sl, cl = np.sin(l), np.cos(l)
    zero = np.zeros_like(l)
    e_l = np.stack([zero, zero, zero + 1.0], -1)
    e_J = np.stack([cl, -sl, zero], -1)
    e_g = m / G[..., None]
    gamma = quat.rotate(quat.conjugate(q), np.array([0.0, 0.0, 1.0]))
    e_h = gamma
    node_i = quat.rotate(quat.conjugate(q), np.stack([np.cos(h), np.sin(h), zero], -1))
    e_I = node_i

    def along(axis: Array) -> Array:
        return -np.sum(tau * axis, axis=-1)

    dm_dl = np.stack([GsJ * cl, -GsJ * sl, zero], -1)
    dm_dL = np.stack([-L / GsJ * sl, -L / GsJ * cl, zero + 1.0], -1)
    dm_dG = np.stack([G / GsJ * sl, G / GsJ * cl, zero], -1)

    def dot_m(d: Array) -> Array:
        return np.sum(grad_m * d, axis=-1)

    dI_dH, dI_dG = -G / (G * GsI), H / (G * GsI)
    dJ_dL, dJ_dG = -G / (G * GsJ), L / (G * GsJ)
    d_l = along(e_l) + dot_m(dm_dl)
    d_g = along(e_g)
    d_h = along(e_h)
    d_L = along(e_J) * dJ_dL + dot_m(dm_dL)
    d_G = along(e_I) * dI_dG + along(e_J) * dJ_dG + dot_m(dm_dG)
    d_H = along(e_I) * dI_dH
    return AndoyerRates(
        free.l + d_L,
        free.g + d_G,
        free.h + d_H,
        free.L - d_l,
        free.G - d_g,
        free.H - d_h,
    )
