r"""Equations of motion of the rigid body in each chart.

Right-hand sides are written without cancellation: the free Euler–Poinsot
equations as ``dm_i/dt = c_i m_j m_k`` with ``c_i = (I_j - I_k)/(I_j I_k)``
(cyclic ``i, j, k``), never as the literal cross product ``m × I⁻¹m``, which
on a near-axisymmetric body (Earth: ``(B - A)/A ≈ 2e-6``) subtracts two
nearly equal products and loses about three digits.

Signs: the body angular momentum obeys the so(3) Lie–Poisson bracket
``{F, K}(m) = -m·(∇F × ∇K)``, so ``{m1, m2} = -m3`` (Gurfil eq. 28) and
``dm/dt = {m, K} = m × ∇K``. The attitude ``q`` (body → reference) obeys
``dq/dt = ½ q ⊗ (ω, 0)`` with ``ω = I⁻¹ m`` in body components.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_vectors, broadcast_finite, check_momenta
from andoyer.body import RigidBody
from andoyer.charts.euler import transverse_momentum

__all__ = [
    "AndoyerRates",
    "EulerRates",
    "andoyer_equations",
    "attitude_rate",
    "euler_equations",
    "euler_poinsot",
    "euler_poinsot_omega",
    "lie_poisson",
]

Array = NDArray[np.float64]


def euler_poinsot(body: RigidBody, m_body: ArrayLike, torque: ArrayLike | None = None) -> Array:
    """``dm/dt`` of the body angular momentum (Gurfil eqs. 12, 14 in momentum form).

    ``dm_i/dt = c_i m_j m_k + u_i`` with ``c = body.euler_coefficients``.

    Parameters
    ----------
    body : RigidBody
    m_body : array_like, shape (..., 3)
        Body angular momentum.
    torque : array_like, shape (..., 3), optional
        External torque ``u`` in body components (the forced eq. 14).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> euler_poinsot(RigidBody(1.0, 2.0, 2.5), [1.0, 1.0, 1.0]).tolist()
    [-0.1, 0.6, -0.5]
    """
    m = as_vectors(m_body, "m_body")
    c = body.euler_coefficients
    rate = np.stack(
        [c[0] * m[..., 1] * m[..., 2], c[1] * m[..., 2] * m[..., 0], c[2] * m[..., 0] * m[..., 1]], axis=-1
    )
    if torque is not None:
        rate = rate + as_vectors(torque, "torque")
    return rate


def euler_poinsot_omega(body: RigidBody, omega: ArrayLike, torque: ArrayLike | None = None) -> Array:
    """``dω/dt`` from ``I dω/dt + ω × Iω = u`` (Gurfil eqs. 12, 14).

    ``dω_1/dt = ((I2 - I3) ω2 ω3 + u1)/I1`` and cyclic.

    Parameters
    ----------
    body : RigidBody
    omega : array_like, shape (..., 3)
        Body angular velocity.
    torque : array_like, shape (..., 3), optional
        External torque in body components.

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> euler_poinsot_omega(RigidBody(1.0, 2.0, 2.5), [1.0, 1.0, 1.0]).tolist()
    [-0.5, 0.75, -0.4]
    """
    w = as_vectors(omega, "omega")
    I1, I2, I3 = body.moments
    rate = np.stack(
        [
            (I2 - I3) * w[..., 1] * w[..., 2] / I1,
            (I3 - I1) * w[..., 2] * w[..., 0] / I2,
            (I1 - I2) * w[..., 0] * w[..., 1] / I3,
        ],
        axis=-1,
    )
    if torque is not None:
        rate = rate + as_vectors(torque, "torque") / body.moments
    return rate


def lie_poisson(m_body: ArrayLike, grad_hamiltonian: ArrayLike) -> Array:
    """Lie–Poisson equations ``dm/dt = {m, K} = m × ∇K`` for any Hamiltonian ``K(m)`` (eqs. 34–36).

    Parameters
    ----------
    m_body : array_like, shape (..., 3)
    grad_hamiltonian : array_like, shape (..., 3)
        ``∂K/∂m`` at ``m_body`` (for the free body, the angular velocity).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> lie_poisson([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).tolist()
    [0.0, 1.0, 0.0]
    """
    m = as_vectors(m_body, "m_body")
    grad = as_vectors(grad_hamiltonian, "grad_hamiltonian")
    return np.cross(m, grad)


def attitude_rate(quaternion: ArrayLike, omega_body: ArrayLike) -> Array:
    """``dq/dt = ½ q ⊗ (ω, 0)`` for attitude quaternions (body → reference), scalar last.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
    omega_body : array_like, shape (..., 3)
        Angular velocity in body components.

    Returns
    -------
    numpy.ndarray, shape (..., 4)

    Examples
    --------
    >>> attitude_rate([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 2.0]).tolist()
    [0.0, 0.0, 1.0, 0.0]
    """
    q = as_vectors(quaternion, "quaternion", 4)
    w = as_vectors(omega_body, "omega_body")
    w4 = np.concatenate([w, np.zeros((*w.shape[:-1], 1))], axis=-1)
    return 0.5 * quat.multiply(*np.broadcast_arrays(q, w4))


class EulerRates(NamedTuple):
    """Time derivatives of the Euler chart's variables."""

    phi: Array
    theta: Array
    psi: Array
    Phi: Array
    Theta: Array
    Psi: Array


class AndoyerRates(NamedTuple):
    """Time derivatives of the Andoyer variables."""

    l: Array
    g: Array
    h: Array
    L: Array
    G: Array
    H: Array


def euler_equations(
    body: RigidBody,
    phi: ArrayLike,
    theta: ArrayLike,
    psi: ArrayLike,
    Phi: ArrayLike,
    Theta: ArrayLike,
    Psi: ArrayLike,
) -> EulerRates:
    r"""Hamilton's equations of the Euler-chart Hamiltonian (eq. 23).

    With ``ω = I⁻¹ m`` and ``S = ω1 sin ψ + ω2 cos ψ``, the chain rule through
    eqs. 25–27 gives ``dφ/dt = S / sin θ``, ``dθ/dt = ω1 cos ψ - ω2 sin ψ``,
    ``dψ/dt = ω3 - S cot θ``, ``dΦ/dt = 0``, ``dΘ/dt = -S (Ψ - X cot θ)``,
    ``dΨ/dt = c3 m1 m2``, which reproduce the kinematic eqs. 5–7.

    Parameters
    ----------
    body : RigidBody
    phi, theta, psi, Phi, Theta, Psi : array_like, shape (...)
        They broadcast; ``sin θ ≠ 0``.

    Returns
    -------
    EulerRates

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> rates = euler_equations(RigidBody(1.0, 2.0, 2.5), 0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    >>> float(rates.Phi)
    0.0
    """
    names = ("phi", "theta", "psi", "Phi", "Theta", "Psi")
    _, theta, psi, Phi, Theta, Psi = broadcast_finite(names, (phi, theta, psi, Phi, Theta, Psi))
    numerator, st = transverse_momentum(Phi, Psi, theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 in the Euler-chart equations, got sin(theta) = 0"
        raise ValueError(msg)
    X = numerator / st
    cot = np.cos(theta) / st
    cp, sp = np.cos(psi), np.sin(psi)
    m1, m2 = Theta * cp + X * sp, -Theta * sp + X * cp
    I1, I2, I3 = body.moments
    w1, w2, w3 = m1 / I1, m2 / I2, Psi / I3
    S = w1 * sp + w2 * cp
    return EulerRates(
        S / st,
        w1 * cp - w2 * sp,
        w3 - S * cot,
        np.zeros_like(Phi),
        -S * (Psi - X * cot),
        body.euler_coefficients[2] * m1 * m2,
    )


def andoyer_equations(
    body: RigidBody,
    l: ArrayLike,
    g: ArrayLike,
    h: ArrayLike,
    L: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
) -> AndoyerRates:
    r"""Hamilton's equations of the Andoyer Hamiltonian (Gurfil eqs. 97–102).

    Written without cancellation:
    ``dl/dt = L (s_l² (I1 - I3)/(I1 I3) + c_l² (I2 - I3)/(I2 I3))``,
    ``dg/dt = G (s_l²/I1 + c_l²/I2)``, ``dh/dt = 0``,
    ``dL/dt = -(G - L)(G + L) s_l c_l (I2 - I1)/(I1 I2)``, ``dG/dt = dH/dt = 0``.

    Parameters
    ----------
    body : RigidBody
    l, g, h, L, G, H : array_like, shape (...)
        Andoyer variables; they broadcast.

    Returns
    -------
    AndoyerRates

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> rates = andoyer_equations(RigidBody(1.0, 2.0, 2.5), 0.0, 0.0, 0.0, 1.0, 2.0, 1.0)
    >>> float(rates.g), float(rates.l)
    (1.0, -0.1)
    """
    names = ("l", "g", "h", "L", "G", "H")
    l, g, h, L, G, H = broadcast_finite(names, (l, g, h, L, G, H))
    check_momenta(L, G, H)
    I1, I2, I3 = body.moments
    s2, c2 = np.sin(l) ** 2, np.cos(l) ** 2
    zero = np.zeros_like(G)
    return AndoyerRates(
        L * (s2 * (I1 - I3) / (I1 * I3) + c2 * (I2 - I3) / (I2 * I3)),
        G * (s2 / I1 + c2 / I2),
        zero,
        -(G - L) * (G + L) * np.sin(l) * np.cos(l) * (I2 - I1) / (I1 * I2),
        zero.copy(),
        zero.copy(),
    )
