r"""The free-body Hamiltonian in each chart.

All three are the kinetic energy ``T = ½ m·I⁻¹m`` (Gurfil eq. 38) written in
different variables:

* state: ``½ Σ m_i² / I_i``;
* Euler chart (eq. 23):
  ``½ (s_ψ²/I1 + c_ψ²/I2) X² + Ψ²/(2 I3) + ½ (c_ψ²/I1 + s_ψ²/I2) Θ²
  + (1/I1 - 1/I2) X Θ s_ψ c_ψ`` with ``X = (Φ - Ψ c_θ)/s_θ``;
* Andoyer chart (eq. 89): ``½ (s_l²/I1 + c_l²/I2)(G² - L²) + L²/(2 I3)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, broadcast, broadcast_finite, check_momenta
from andoyer.body import RigidBody
from andoyer.charts.euler import transverse_momentum

__all__ = ["andoyer_hamiltonian", "euler_hamiltonian", "state_hamiltonian"]

Array = NDArray[np.float64]


def state_hamiltonian(body: RigidBody, m_body: ArrayLike) -> Array:
    """``½ m·I⁻¹m`` for body angular momenta (..., 3); shape (...).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> float(state_hamiltonian(RigidBody(1.0, 2.0, 2.5), [1.0, 2.0, 5.0]))
    6.5
    """
    return body.energy(m_body)


def euler_hamiltonian(
    body: RigidBody,
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> Array:
    """Gurfil eq. 23: the free Hamiltonian in Euler angles and momenta.

    ``φ`` is cyclic and does not enter. ``(Φ - Ψ cos θ)`` is formed without
    cancellation near ``sin θ = 0``, where the chart is singular (``sin θ = 0``
    raises unless ``Φ = ±Ψ`` there).

    Parameters
    ----------
    body : RigidBody
    phi, theta, psi, Phi, Theta, Psi : array_like, shape (...)
        Euler 3-1-3 angles and conjugate momenta; they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> e = (0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    >>> bool(abs(euler_hamiltonian(body, *e) - State.from_euler(*e).energy(body)) < 1e-15)
    True
    """
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    _, theta, psi, Phi, Theta, Psi = broadcast_finite(names, (phi, theta, psi, Phi, Theta, Psi))
    numerator, st = transverse_momentum(Phi, Psi, theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 in the Euler-chart Hamiltonian, got sin(theta) = 0"
        raise ValueError(msg)
    X = numerator / st
    I1, I2, I3 = body.moments
    s2, c2 = np.sin(psi) ** 2, np.cos(psi) ** 2
    return (
        0.5 * (s2 / I1 + c2 / I2) * X * X
        + Psi * Psi / (2 * I3)
        + 0.5 * (c2 / I1 + s2 / I2) * Theta * Theta
        + (I2 - I1) / (I1 * I2) * X * Theta * np.sin(psi) * np.cos(psi)
    )


def andoyer_hamiltonian(body: RigidBody, l: ArrayLike, L: ArrayLike, G: ArrayLike) -> Array:
    """Gurfil eq. 89 (Lara eq. 1): the free Hamiltonian in Andoyer variables.

    Only ``l``, ``L`` and ``G`` enter: ``g`` and ``h`` are cyclic.

    Parameters
    ----------
    body : RigidBody
    l, L, G : array_like, shape (...)
        Andoyer angle ``l`` and momenta ``L``, ``G`` (``|L| <= G``); they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> float(andoyer_hamiltonian(RigidBody(1.0, 2.0, 2.5), 0.0, 0.0, 2.0))  # G²/(2 I2)
    1.0
    """
    l, L, G = broadcast(("l", as_finite(l, "l")), ("L", as_finite(L, "L")), ("G", as_finite(G, "G")))
    check_momenta(L, G, np.zeros_like(G))
    I1, I2, I3 = body.moments
    sl, cl = np.sin(l), np.cos(l)
    return 0.5 * (sl * sl / I1 + cl * cl / I2) * (G - L) * (G + L) + L * L / (2 * I3)
