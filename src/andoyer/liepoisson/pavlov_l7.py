r"""Andoyer–Deprit coordinates on the six-dimensional leaves of l(7) (Pavlov §2).

A point of l(7) is ``(m, λ)``: body angular momentum and Pavlov's unit quaternion
λ = (w, x, y, z) of the attitude ``rot`` (body → reference), see
:mod:`andoyer.liepoisson.quaternion`. The coordinates ``(l, g, h, L, G, H)`` are the
project's Andoyer chart, ``rot = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)``, so λ is the product of
five half-angle quaternions (``q_z(a) = (cos a/2, 0, 0, sin a/2)``,
``q_x(a) = (cos a/2, sin a/2, 0, 0)``):

.. math::

    λ = q_z(h)\\, q_x(I)\\, q_z(g)\\, q_x(J)\\, q_z(l), \\qquad
    \\cos\\tfrac{I}{2} = \\sqrt{\\tfrac{G+H}{2G}},\\;
    \\sin\\tfrac{I}{2} = \\sqrt{\\tfrac{G-H}{2G}},\\;
    \\cos\\tfrac{J}{2} = \\sqrt{\\tfrac{G+L}{2G}},\\;
    \\sin\\tfrac{J}{2} = \\sqrt{\\tfrac{G-L}{2G}} .

Pavlov's printed eq. 2.14 equals ``-λ`` evaluated at ``h + π/2`` (his h is measured from
the projection of m on the reference plane, not from the node): see
``docs/errata-pavlov.md``.

Inverse: ``l, L, G`` from m as on so(3); ``m_ref = rot m``, ``H = m_ref,3``,
``h = atan2(m_ref,1, -m_ref,2)``; ``g`` from the remaining rotation
``q_z(g) = q_x(I)⁻¹ q_z(h)⁻¹ λ q_z(l)⁻¹ q_x(J)⁻¹``. Singular points: ``l = 0`` where
``sin J ≤ SINGULAR_TOL``, ``h = 0`` where ``sin I ≤ SINGULAR_TOL``; ``g`` then carries
the rest of the rotation, so ``(m, λ)`` is still reproduced.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from andoyer._validation import broadcast
from andoyer.liepoisson._domain import (
    SINGULAR_TOL,
    TWO_PI,
    as_components,
    as_scalars,
    body_angle_l,
    leading_shape,
    momenta,
    momentum_magnitude,
    unit_vectors,
    warn_singular,
    wrap_angle,
)
from andoyer.liepoisson.quaternion import quaternion_product, rotation_matrix

__all__ = ["L7Coordinates", "l7_from_andoyer", "l7_to_andoyer"]


class L7Coordinates(NamedTuple):
    """Andoyer–Deprit coordinates ``(l, g, h, L, G, H)`` on an l(7) leaf (arrays of equal shape)."""

    l: np.ndarray
    g: np.ndarray
    h: np.ndarray
    L: np.ndarray
    G: np.ndarray
    H: np.ndarray


def _half_angle_factors(p: np.ndarray, G: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``cos(A/2), sin(A/2)`` for ``cos A = p/G`` without cancellation."""
    return np.sqrt((G + p) / (2 * G)), np.sqrt((G - p) / (2 * G))


def _qz(c: np.ndarray, s: np.ndarray) -> np.ndarray:
    zero = np.zeros_like(c)
    return np.stack([c, zero, zero, s], axis=-1)


def _qx(c: np.ndarray, s: np.ndarray) -> np.ndarray:
    zero = np.zeros_like(c)
    return np.stack([c, s, zero, zero], axis=-1)


def l7_from_andoyer(l: Any, g: Any, h: Any, L: Any, G: Any, H: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(m, λ)`` on the l(7) leaf ``|λ| = 1`` from Andoyer–Deprit coordinates.

    Parameters
    ----------
    l, g, h, L, G, H : array_like, broadcastable
        Angles and momenta; ``G > 0``, ``|L| ≤ G``, ``|H| ≤ G``.

    Returns
    -------
    m : numpy.ndarray, shape (..., 3)
        Body angular momentum.
    lam : numpy.ndarray, shape (..., 4)
        Pavlov's quaternion ``(w, x, y, z)`` of ``rot``; 4π-periodic in each angle.

    Raises
    ------
    ValueError
        If ``G ≤ 0``, ``|L| > G``, ``|H| > G``, values are not finite or shapes do not
        broadcast.

    Examples
    --------
    >>> import numpy as np
    >>> from scipy.spatial.transform import Rotation
    >>> l, g, h, L, G, H = 0.4, 1.3, 2.0, 0.5, 1.5, -0.7
    >>> m, lam = l7_from_andoyer(l, g, h, L, G, H)
    >>> rot = (Rotation.from_euler("ZXZ", [h, np.arccos(H / G), g])
    ...        * Rotation.from_euler("XZ", [np.arccos(L / G), l]))
    >>> q = rot.as_quat()  # scalar last
    >>> bool(np.allclose(lam, np.sign(lam @ q[[3, 0, 1, 2]]) * q[[3, 0, 1, 2]], atol=1e-15))
    True
    """
    L, G, H = momenta(L, G, H)
    ell, g, h, L, G, H = broadcast(
        ("l", as_scalars("l", l)),
        ("g", as_scalars("g", g)),
        ("h", as_scalars("h", h)),
        ("L", L),
        ("G", G),
        ("H", H),
    )
    cI, sI = _half_angle_factors(H, G)
    cJ, sJ = _half_angle_factors(L, G)
    front = quaternion_product(
        quaternion_product(_qz(np.cos(h / 2), np.sin(h / 2)), _qx(cI, sI)),
        _qz(np.cos(g / 2), np.sin(g / 2)),
    )
    back = quaternion_product(_qx(cJ, sJ), _qz(np.cos(ell / 2), np.sin(ell / 2)))
    lam = quaternion_product(front, back)
    rho = 2 * G * sJ * cJ
    m = np.stack([rho * np.sin(ell), rho * np.cos(ell), L], axis=-1)
    return m, lam


def l7_to_andoyer(m: Any, lam: Any, *, double_cover: bool = False) -> L7Coordinates:
    """Andoyer–Deprit coordinates of a point ``(m, λ)`` of l(7) with ``|λ| = 1``.

    Parameters
    ----------
    m : array_like, shape (..., 3)
        Body angular momentum, non-zero.
    lam : array_like, shape (..., 4)
        Pavlov's quaternion ``(w, x, y, z)``; norm checked to ``UNIT_TOL``, then normalised.
    double_cover : bool, optional
        If False (default) all angles are in ``[0, 2π)`` and :func:`l7_from_andoyer`
        returns ``±λ`` (the same attitude). If True, ``g`` is in ``[0, 4π)`` so that
        :func:`l7_from_andoyer` returns λ itself.

    Returns
    -------
    L7Coordinates
        Each of shape (...).

    Raises
    ------
    ValueError
        If ``|λ| ≠ 1``, ``m = 0``, values are not finite or leading shapes do not broadcast.

    Warns
    -----
    SingularChartWarning
        Where ``sin J ≤ SINGULAR_TOL`` (``l`` set to 0) or ``sin I ≤ SINGULAR_TOL``
        (``h`` set to 0).

    Examples
    --------
    >>> import numpy as np
    >>> m, lam = l7_from_andoyer(0.4, 5.0, 2.0, 0.5, 1.5, -0.7)
    >>> np.round(l7_to_andoyer(m, lam), 12)
    array([ 0.4,  5. ,  2. ,  0.5,  1.5, -0.7])
    >>> m, lam = l7_from_andoyer(0.4, 5.0 + 2 * np.pi, 2.0, 0.5, 1.5, -0.7)
    >>> bool(np.allclose(l7_from_andoyer(*l7_to_andoyer(m, lam, double_cover=True))[1], lam))
    True
    """
    m = as_components("m", m, 3)
    lam = as_components("lam", lam, 4)
    shape = leading_shape(m=m, lam=lam)
    m = np.broadcast_to(m, (*shape, 3))
    lam = unit_vectors("lam", np.broadcast_to(lam, (*shape, 4)))
    G = momentum_magnitude(m)
    ell, _, _, _, _ = body_angle_l(m, G, stacklevel=2)
    m_ref = np.einsum("...ij,...j->...i", rotation_matrix(lam), m)
    L = m[..., 2]
    H = np.clip(m_ref[..., 2], -G, G)
    singular = np.hypot(m_ref[..., 0], m_ref[..., 1]) / G <= SINGULAR_TOL
    warn_singular(
        singular,
        f"sin I ≤ {SINGULAR_TOL:g} (m along the reference axis s3): h is undefined, set to 0",
        2,
    )
    h = np.where(singular, 0.0, wrap_angle(np.arctan2(m_ref[..., 0], -m_ref[..., 1])))
    cI, sI = _half_angle_factors(H, G)
    cJ, sJ = _half_angle_factors(L, G)
    # conjugates (inverse rotations) peel the known factors off λ
    rest = quaternion_product(_qz(np.cos(h / 2), -np.sin(h / 2)), lam)
    rest = quaternion_product(_qx(cI, -sI), rest)
    rest = quaternion_product(rest, _qz(np.cos(ell / 2), -np.sin(ell / 2)))
    rest = quaternion_product(rest, _qx(cJ, -sJ))
    g = 2.0 * np.arctan2(rest[..., 3], rest[..., 0])
    g = wrap_angle(g, 2 * TWO_PI if double_cover else TWO_PI)
    return L7Coordinates(ell[()], g[()], h[()], L[()], G[()], H[()])
