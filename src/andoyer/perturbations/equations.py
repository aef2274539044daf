r"""Equations of motion of a perturbed body on the hub ``(q, m)``.

.. math::
   \dot q = \tfrac12\, q\otimes(\boldsymbol\omega + \partial\Delta H/\partial\mathbf m,\ 0),\qquad
   \dot{\mathbf m} = c \odot (m_2 m_3, m_3 m_1, m_1 m_2)
   + \mathbf m\times\partial\Delta H/\partial\mathbf m + \boldsymbol\tau,

the free part written without cancellation (:func:`andoyer.state.hub.euler_poinsot`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation, hub_arrays, times

__all__ = ["perturbed_rates"]

Array = NDArray[np.float64]


def perturbed_rates(
    body: RigidBody, model: Perturbation | None, t: ArrayLike, q: ArrayLike, m: ArrayLike
) -> tuple[Array, Array]:
    """``(dq/dt, dm/dt)`` of attitude quaternions (..., 4) and body momenta (..., 3).

    Parameters
    ----------
    body : RigidBody
    model : Perturbation or None
        ``None`` gives the free body.
    t : array_like, shape (...)
    q : array_like, shape (..., 4)
        Attitude, body → reference, scalar last.
    m : array_like, shape (..., 3)
        Body angular momentum.

    Returns
    -------
    dq, dm : numpy.ndarray, shapes (..., 4) and (..., 3)

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import PrecessingFrame
    >>> frame = PrecessingFrame([0, 0, 1.0])
    >>> dq, dm = perturbed_rates(RigidBody(1, 1, 1), frame, 0.0, [0, 0, 0, 1.0], [0, 0, 1.0])
    >>> dq.tolist(), dm.tolist()  # spinning with the frame: no relative motion
    ([0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    """
    q, m = hub_arrays(q, m)
    return _perturbed_rates(body, model, times(t), q, m)


def _perturbed_rates(
    body: RigidBody, model: Perturbation | None, t: Array, q: Array, m: Array
) -> tuple[Array, Array]:
    """:func:`perturbed_rates` on validated arrays (the integrators' inner loop)."""
    c = body.euler_coefficients
    m0, m1, m2 = m[..., 0], m[..., 1], m[..., 2]
    rate = np.stack([c[0] * m1 * m2, c[1] * m2 * m0, c[2] * m0 * m1], axis=-1)
    velocity = m / body.moments
    if model is not None:
        if not model.attitude_only:
            gradient = model._momentum_gradient(t, q, m)
            velocity = velocity + gradient
            rate = rate + quat.cross(m, gradient)
        rate = rate + model._torque(t, q, m)
    w4 = np.concatenate([velocity, np.zeros((*velocity.shape[:-1], 1))], axis=-1)
    dq = 0.5 * quat.multiply(*np.broadcast_arrays(q, w4))
    return dq, rate * np.ones(np.broadcast_shapes(rate.shape, (*dq.shape[:-1], 3)))
