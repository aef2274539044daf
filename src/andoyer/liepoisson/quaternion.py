r"""Pavlov's quaternion λ and its relation to scipy's quaternions.

Pavlov's Hamilton–Rodrigues parameters ``λ = (λ0, λ1, λ2, λ3)`` (scalar first)
are the quaternion of the attitude ``rot`` (body → reference), i.e. scipy's
scalar-last quaternion reordered:

.. math::

    λ = (w, x, y, z), \\qquad (x, y, z, w) = \\text{rot.as\\_quat()} .

With this identification Pavlov's eq. 2.2 is the third row of ``rot.as_matrix()``,
i.e. γ, the reference axis s3 in body components, and the l(7) bracket
(Pavlov eq. 2.9) generates ``d rot/dt = rot·hat(ω)``. λ and -λ are the same attitude.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from andoyer._quaternion import product
from andoyer.liepoisson._domain import as_components, unit_vectors

__all__ = ["gamma_from_quaternion", "quaternion_from_scipy", "quaternion_to_scipy"]


def quaternion_from_scipy(quat: Any) -> np.ndarray:
    """Pavlov's λ (scalar first) from a scipy quaternion (scalar last).

    Parameters
    ----------
    quat : array_like, shape (..., 4)
        ``(x, y, z, w)`` as returned by ``Rotation.as_quat()``.

    Returns
    -------
    numpy.ndarray, shape (..., 4)
        ``λ = (w, x, y, z)``.

    Examples
    --------
    >>> from scipy.spatial.transform import Rotation
    >>> quaternion_from_scipy(Rotation.from_euler("Z", 1.0).as_quat()).round(6)
    array([0.877583, 0.      , 0.      , 0.479426])
    """
    q = as_components("quat", quat, 4)
    return np.concatenate([q[..., 3:], q[..., :3]], axis=-1)


def quaternion_to_scipy(lam: Any) -> np.ndarray:
    """Scipy's scalar-last quaternion from Pavlov's λ.

    Parameters
    ----------
    lam : array_like, shape (..., 4)
        ``(λ0, λ1, λ2, λ3) = (w, x, y, z)``.

    Returns
    -------
    numpy.ndarray, shape (..., 4)
        ``(x, y, z, w)``, ready for ``Rotation.from_quat``.

    Examples
    --------
    >>> quaternion_to_scipy([1.0, 0.0, 0.0, 0.0])
    array([0., 0., 0., 1.])
    """
    q = as_components("lam", lam, 4)
    return np.concatenate([q[..., 1:], q[..., :1]], axis=-1)


def gamma_from_quaternion(lam: Any) -> np.ndarray:
    r"""γ (reference axis s3 in body components) from λ, Pavlov eq. 2.2.

    .. math::

        γ = (2(λ_1λ_3 - λ_0λ_2),\\; 2(λ_0λ_1 + λ_2λ_3),\\; λ_0^2 - λ_1^2 - λ_2^2 + λ_3^2).

    Parameters
    ----------
    lam : array_like, shape (..., 4)
        Unit quaternion (norm checked to ``UNIT_TOL``, then normalised).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        If ``|λ| ≠ 1``.

    Examples
    --------
    >>> import numpy as np
    >>> from scipy.spatial.transform import Rotation
    >>> rot = Rotation.from_euler("ZXZ", [0.3, 1.1, -0.4])
    >>> lam = quaternion_from_scipy(rot.as_quat())
    >>> bool(np.allclose(gamma_from_quaternion(lam), rot.as_matrix()[2], atol=1e-15))
    True
    """
    q = unit_vectors("lam", as_components("lam", lam, 4))
    w, x, y, z = np.moveaxis(q, -1, 0)
    return np.stack([2 * (x * z - w * y), 2 * (w * x + y * z), w * w - x * x - y * y + z * z], axis=-1)


def quaternion_product(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product of scalar-first quaternions, shapes (..., 4).

    Pavlov's ``λ = (w, x, y, z)`` reordered to scalar last, multiplied by the project's one
    product :func:`andoyer._quaternion.product`, and reordered back.

    Parameters
    ----------
    a, b : ndarray, shape (..., 4)
        Scalar-first quaternions, broadcast together.

    Returns
    -------
    numpy.ndarray, shape (..., 4)
        ``a ⊗ b``, scalar first.

    Examples
    --------
    >>> quaternion_product(np.array([0.0, 1, 0, 0]), np.array([0.0, 0, 1, 0]))  # i j = k
    array([0., 0., 0., 1.])
    """
    aw, ax, ay, az = np.moveaxis(a, -1, 0)
    bw, bx, by, bz = np.moveaxis(b, -1, 0)
    x, y, z, w = product(ax, ay, az, aw, bx, by, bz, bw)
    return np.stack([w, x, y, z], axis=-1)


def rotation_matrix(lam: np.ndarray) -> np.ndarray:
    """Matrix of ``rot`` (body → reference) from a unit λ, shape (..., 3, 3).

    Examples
    --------
    >>> from scipy.spatial.transform import Rotation
    >>> rot = Rotation.from_euler("ZXZ", [0.3, 1.1, -0.4])
    >>> lam = quaternion_from_scipy(rot.as_quat())
    >>> bool(np.allclose(rotation_matrix(lam), rot.as_matrix(), atol=1e-15))
    True
    """
    w, x, y, z = np.moveaxis(lam, -1, 0)
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        axis=-2,
    )
