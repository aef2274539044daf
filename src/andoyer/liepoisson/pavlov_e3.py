r"""Andoyer–Deprit coordinates on the symplectic leaves of so(3) and e(3) (Pavlov §1).

Conventions are those of the project's Andoyer chart: ``rot = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l)``
(body → reference), ``cos I = H/G``, ``cos J = L/G``, ``0 ≤ I, J ≤ π``, and

.. math::

    m &= (\\sqrt{G^2-L^2}\\,\\sin l,\\; \\sqrt{G^2-L^2}\\,\\cos l,\\; L),\\\\
    γ_1 &= (\\cos I \\sin J + \\sin I \\cos J \\cos g)\\sin l + \\sin I \\sin g \\cos l,\\\\
    γ_2 &= (\\cos I \\sin J + \\sin I \\cos J \\cos g)\\cos l - \\sin I \\sin g \\sin l,\\\\
    γ_3 &= \\cos I \\cos J - \\sin I \\sin J \\cos g,

with ``γ`` the third row of ``rot.as_matrix()`` and ``H = m·γ`` (Pavlov eqs. 1.2, 1.7,
which hold as printed). ``(l, L)`` and ``(g, G)`` are canonical pairs on the leaf
``{|γ| = 1, m·γ = H}``; on so(3) ``(l, L)`` is canonical on the sphere ``|m| = G``.

Inverse, with the angles in ``[0, 2π)``:
``l = atan2(m1, m2)``, ``L = m3``, ``G = |m|``, ``H = m·γ`` and
``g = atan2(γ1 cos l - γ2 sin l, (γ1 sin l + γ2 cos l) cos J - γ3 sin J)``.

Singular points (a :class:`SingularChartWarning` is emitted): where ``sin J ≤ SINGULAR_TOL``
(m along the body axis b3) ``l`` is undefined and set to 0, ``g`` then carries ``g ± l``;
where ``sin I ≤ SINGULAR_TOL`` (γ parallel to m) ``g`` is undefined on e(3) and set to 0.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from andoyer._validation import broadcast
from andoyer.liepoisson._domain import (
    SINGULAR_TOL,
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

__all__ = [
    "E3Coordinates",
    "So3Coordinates",
    "e3_from_andoyer",
    "e3_to_andoyer",
    "so3_from_andoyer",
    "so3_to_andoyer",
]


class So3Coordinates(NamedTuple):
    """Cylindrical coordinates ``(l, L)`` on the sphere ``|m| = G`` (arrays of equal shape)."""

    l: np.ndarray
    L: np.ndarray
    G: np.ndarray


class E3Coordinates(NamedTuple):
    """Andoyer–Deprit coordinates ``(l, g, L, G)`` on the e(3) leaf labelled by ``H``."""

    l: np.ndarray
    g: np.ndarray
    L: np.ndarray
    G: np.ndarray
    H: np.ndarray


def so3_to_andoyer(m: Any) -> So3Coordinates:
    """Canonical coordinates ``(l, L)`` and Casimir ``G`` of a body angular momentum.

    Parameters
    ----------
    m : array_like, shape (..., 3)
        Body angular momentum, non-zero.

    Returns
    -------
    So3Coordinates
        ``l`` in ``[0, 2π)``, ``L = m3``, ``G = |m|``, each of shape (...).

    Raises
    ------
    ValueError
        If ``m = 0``, not finite, or not of last-axis length 3.

    Warns
    -----
    SingularChartWarning
        Where ``sin J ≤ SINGULAR_TOL``; ``l`` is set to 0 there.

    Examples
    --------
    >>> c = so3_to_andoyer([1.0, 0.0, 1.0])
    >>> float(c.l), float(c.L), round(float(c.G), 12)
    (1.5707963267948966, 1.0, 1.414213562373)
    """
    m = as_components("m", m, 3)
    G = momentum_magnitude(m)
    ell, *_ = body_angle_l(m, G, stacklevel=2)
    return So3Coordinates(ell[()], m[..., 2][()], G[()])


def so3_from_andoyer(l: Any, L: Any, G: Any) -> np.ndarray:
    """Body angular momentum ``m = (√(G²−L²) sin l, √(G²−L²) cos l, L)`` (Pavlov eq. 1.2).

    Parameters
    ----------
    l, L, G : array_like, broadcastable
        Angle, projection on b3 and magnitude; ``G > 0``, ``|L| ≤ G``.

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        If ``G ≤ 0``, ``|L| > G``, values are not finite or shapes do not broadcast.

    Examples
    --------
    >>> so3_from_andoyer(0.0, 0.6, 1.0)
    array([0. , 0.8, 0.6])
    """
    L, G, _ = momenta(L, G, None)
    ell, L, G = broadcast(("l", as_scalars("l", l)), ("L", L), ("G", G))
    rho = np.sqrt((G - L) * (G + L))
    return np.stack([rho * np.sin(ell), rho * np.cos(ell), L], axis=-1)


def e3_from_andoyer(l: Any, g: Any, L: Any, G: Any, H: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(m, γ)`` on the e(3) leaf from Andoyer–Deprit coordinates (Pavlov eqs. 1.2, 1.7).

    Parameters
    ----------
    l, g, L, G, H : array_like, broadcastable
        Angles and momenta; ``G > 0``, ``|L| ≤ G``, ``|H| ≤ G``.

    Returns
    -------
    m : numpy.ndarray, shape (..., 3)
        Body angular momentum.
    gamma : numpy.ndarray, shape (..., 3)
        Reference axis s3 in body components (third row of ``rot.as_matrix()``).

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
    >>> m, gamma = e3_from_andoyer(l, g, L, G, H)
    >>> rot = (Rotation.from_euler("ZXZ", [h, np.arccos(H / G), g])
    ...        * Rotation.from_euler("XZ", [np.arccos(L / G), l]))
    >>> bool(np.allclose(gamma, rot.as_matrix()[2], rtol=0, atol=1e-15))
    True
    >>> round(float(m @ gamma), 12)
    -0.7
    """
    L, G, H = momenta(L, G, H)
    ell, g, L, G, H = broadcast(
        ("l", as_scalars("l", l)), ("g", as_scalars("g", g)), ("L", L), ("G", G), ("H", H)
    )
    sin_J = np.sqrt((G - L) * (G + L)) / G
    cos_J = L / G
    sin_I = np.sqrt((G - H) * (G + H)) / G
    cos_I = H / G
    sl, cl, sg, cg = np.sin(ell), np.cos(ell), np.sin(g), np.cos(g)
    u = cos_I * sin_J + sin_I * cos_J * cg
    gamma = np.stack(
        [u * sl + sin_I * sg * cl, u * cl - sin_I * sg * sl, cos_I * cos_J - sin_I * sin_J * cg],
        axis=-1,
    )
    m = np.stack([G * sin_J * sl, G * sin_J * cl, L], axis=-1)
    return m, gamma


def e3_to_andoyer(m: Any, gamma: Any) -> E3Coordinates:
    """Andoyer–Deprit coordinates of a point ``(m, γ)`` of e(3) with ``|γ| = 1``.

    Parameters
    ----------
    m : array_like, shape (..., 3)
        Body angular momentum, non-zero.
    gamma : array_like, shape (..., 3)
        Unit vector (norm checked to ``UNIT_TOL``, then normalised).

    Returns
    -------
    E3Coordinates
        ``l, g`` in ``[0, 2π)``, ``L = m3``, ``G = |m|``, ``H = m·γ``, each of shape (...).

    Raises
    ------
    ValueError
        If ``|γ| ≠ 1``, ``m = 0``, values are not finite or leading shapes do not broadcast.

    Warns
    -----
    SingularChartWarning
        Where ``sin J ≤ SINGULAR_TOL`` (``l`` set to 0) or ``sin I ≤ SINGULAR_TOL``
        (``g`` set to 0).

    Examples
    --------
    >>> import numpy as np
    >>> m, gamma = e3_from_andoyer(0.4, 1.3, 0.5, 1.5, -0.7)
    >>> np.round(e3_to_andoyer(m, gamma), 12)
    array([ 0.4,  1.3,  0.5,  1.5, -0.7])
    """
    m = as_components("m", m, 3)
    gamma = as_components("gamma", gamma, 3)
    shape = leading_shape(m=m, gamma=gamma)
    m = np.broadcast_to(m, (*shape, 3))
    gamma = unit_vectors("gamma", np.broadcast_to(gamma, (*shape, 3)))
    G = momentum_magnitude(m)
    ell, sl, cl, sin_J, cos_J = body_angle_l(m, G, stacklevel=2)
    g1, g2, g3 = np.moveaxis(gamma, -1, 0)
    sin_I_sin_g = g1 * cl - g2 * sl
    sin_I_cos_g = (g1 * sl + g2 * cl) * cos_J - g3 * sin_J
    singular = np.hypot(sin_I_sin_g, sin_I_cos_g) <= SINGULAR_TOL
    warn_singular(
        singular,
        f"sin I ≤ {SINGULAR_TOL:g} (γ parallel to m): g is undefined on e(3), set to 0",
        2,
    )
    g = np.where(singular, 0.0, wrap_angle(np.arctan2(sin_I_sin_g, sin_I_cos_g)))
    H = np.clip(np.sum(m * gamma, axis=-1), -G, G)
    return E3Coordinates(ell[()], g[()], m[..., 2][()], G[()], H[()])
