r"""Keplerian elements and the orbit's vectors: normal, eccentricity vector, position, velocity.

Angles in radians, in the frame of the elements (here the J2000 ecliptic and equinox):
inclination ``i``, longitude of the ascending node ``Ω``, longitude of perihelion
``ϖ = Ω + ω``, mean longitude ``λ = ϖ + M``. The orbit normal and the eccentricity
vector are

.. math::
   n = (\sin i \sin\Omega,\; -\sin i\cos\Omega,\; \cos i), \qquad
   e\,\hat P = e\,R_z(\Omega) R_x(i) R_z(\omega)\,(1, 0, 0)^T,

and the heliocentric state follows from Kepler's equation ``E − e sin E = M`` with
``r = a (cos E − e, √(1−e²) sin E, 0)`` in the orbit's own frame turned by the same
rotation. The inverse uses ``h = r × v`` and ``e = v × h/μ − r/|r|``; the elements of a
normal ``n`` and an eccentricity vector ``e`` are

.. math::
   i = \operatorname{atan2}(\sqrt{n_x^2 + n_y^2}, n_z), \quad
   \Omega = \operatorname{atan2}(n_x, -n_y), \quad
   \varpi = \Omega + \operatorname{atan2}(e\cdot(n\times\hat N),\; e\cdot\hat N),

with ``N̂ = (cos Ω, sin Ω, 0)`` the ascending node (``ω`` measured in the orbit plane).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._fastmath import wrap_2pi

__all__ = [
    "eccentricity_from_elements",
    "elements_from_vectors",
    "elements_to_state",
    "normal_from_elements",
    "state_to_vectors",
]

Array = NDArray[np.float64]


def _orbit_axes(i: Array, node: Array, omega: Array) -> tuple[Array, Array]:
    """Unit vectors to perihelion ``P`` and 90° ahead in the plane ``Q``, shape (..., 3)."""
    ci, si = np.cos(i), np.sin(i)
    cO, sO = np.cos(node), np.sin(node)
    cw, sw = np.cos(omega), np.sin(omega)
    P = np.stack([cw * cO - sw * sO * ci, cw * sO + sw * cO * ci, sw * si], axis=-1)
    Q = np.stack([-sw * cO - cw * sO * ci, -sw * sO + cw * cO * ci, cw * si], axis=-1)
    return P, Q


def normal_from_elements(inclination: ArrayLike, node: ArrayLike) -> Array:
    """Unit orbit normal from the inclination and node (radians).

    Parameters
    ----------
    inclination, node : array_like, shape (...)
        ``i`` and ``Ω`` in radians (a negative ``i`` is allowed: the node is then the
        descending one).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> normal_from_elements(0.0, 1.0).tolist()
    [0.0, -0.0, 1.0]
    """
    i, node = np.broadcast_arrays(np.asarray(inclination, float), np.asarray(node, float))
    return np.stack([np.sin(i) * np.sin(node), -np.sin(i) * np.cos(node), np.cos(i)], axis=-1)


def eccentricity_from_elements(
    eccentricity: ArrayLike, inclination: ArrayLike, node: ArrayLike, varpi: ArrayLike
) -> Array:
    """Eccentricity vector ``e P̂`` from ``e, i, Ω, ϖ`` (radians).

    Parameters
    ----------
    eccentricity, inclination, node, varpi : array_like, shape (...)

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> eccentricity_from_elements(0.1, 0.0, 0.3, 0.0).round(12).tolist()
    [0.1, 0.0, 0.0]
    """
    values = (eccentricity, inclination, node, varpi)
    e, i, node, varpi = np.broadcast_arrays(*(np.asarray(x, float) for x in values))
    P, _ = _orbit_axes(i, node, varpi - node)
    return e[..., None] * P


def _solve_kepler(M: Array, e: Array) -> Array:
    """Eccentric anomaly from the mean anomaly (Newton, quadratic convergence; e < 1)."""
    E = M + e * np.sin(M)
    for _ in range(50):
        dE = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
        E = E - dE
        if np.all(np.abs(dE) < 1e-15):
            break
    return E


def elements_to_state(
    mu: ArrayLike,
    a: ArrayLike,
    e: ArrayLike,
    inclination: ArrayLike,
    node: ArrayLike,
    varpi: ArrayLike,
    mean_longitude: ArrayLike,
) -> tuple[Array, Array]:
    """Position and velocity of a Keplerian ellipse about the centre ``μ = G(M + m)``.

    Parameters
    ----------
    mu : array_like, shape (...)
        Gravitational parameter (length³/time² in the caller's units).
    a, e : array_like, shape (...)
        Semi-major axis (length) and eccentricity (``0 ≤ e < 1``).
    inclination, node, varpi, mean_longitude : array_like, shape (...)
        ``i, Ω, ϖ, λ`` in radians.

    Returns
    -------
    r, v : numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> r, v = elements_to_state(1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> r.round(12).tolist(), v.round(12).tolist()
    ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    """
    mu, a, e, i, node, varpi, lam = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (mu, a, e, inclination, node, varpi, mean_longitude))
    )
    if np.any((e < 0) | (e >= 1)):
        msg = f"expected eccentricities in [0, 1), got {e.tolist()}"
        raise ValueError(msg)
    P, Q = _orbit_axes(i, node, varpi - node)
    E = _solve_kepler(np.remainder(lam - varpi, 2.0 * np.pi), e)
    b = np.sqrt(1.0 - e**2)
    x, y = a * (np.cos(E) - e), a * b * np.sin(E)
    Edot = np.sqrt(mu / a**3) / (1.0 - e * np.cos(E))
    vx, vy = -a * np.sin(E) * Edot, a * b * np.cos(E) * Edot
    r = x[..., None] * P + y[..., None] * Q
    v = vx[..., None] * P + vy[..., None] * Q
    return r, v


def state_to_vectors(mu: ArrayLike, r: ArrayLike, v: ArrayLike) -> tuple[Array, Array]:
    """Osculating unit normal and eccentricity vector of a relative orbit.

    Parameters
    ----------
    mu : array_like, shape (...)
        ``G(M + m)``.
    r, v : array_like, shape (..., 3)
        Relative position and velocity.

    Returns
    -------
    normal, eccentricity_vector : numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> n, e = state_to_vectors(1.0, [1.0, 0.0, 0.0], [0.0, 1.1, 0.0])
    >>> n.tolist(), e.round(12).tolist()
    ([0.0, 0.0, 1.0], [0.21, 0.0, 0.0])
    """
    r = np.asarray(r, float)
    v = np.asarray(v, float)
    mu = np.asarray(mu, float)[..., None]
    h = np.cross(r, v)
    ecc = np.cross(v, h) / mu - r / np.linalg.norm(r, axis=-1, keepdims=True)
    return h / np.linalg.norm(h, axis=-1, keepdims=True), ecc


def elements_from_vectors(
    normal: ArrayLike, eccentricity_vector: ArrayLike
) -> tuple[Array, Array, Array, Array]:
    r"""Eccentricity, inclination, node and longitude of perihelion of a normal and an eccentricity vector.

    The inverse of :func:`normal_from_elements` and :func:`eccentricity_from_elements`
    (module notes): ``ϖ = Ω + ω`` with ``ω`` the angle from the ascending node to the
    perihelion in the orbit plane. Where ``i = 0`` the node is ``atan2(0, −0) = 0`` and ``ϖ``
    is still the longitude of the perihelion; where ``e = 0``, ``ϖ`` is ``Ω``.

    Parameters
    ----------
    normal : array_like, shape (..., 3)
        Unit orbit normals (renormalised).
    eccentricity_vector : array_like, shape (..., 3)
        ``e`` times the unit vector to perihelion, in the orbit plane.

    Returns
    -------
    e, inclination, node, varpi : numpy.ndarray, shape (...)
        ``i`` in ``[0, π]``; ``Ω`` and ``ϖ`` in ``[0, 2π)`` (radians).

    Examples
    --------
    >>> n = normal_from_elements(0.1, 2.0)
    >>> e, i, node, varpi = elements_from_vectors(n, eccentricity_from_elements(0.2, 0.1, 2.0, 3.0))
    >>> [round(float(x), 12) for x in (e, i, node, varpi)]
    [0.2, 0.1, 2.0, 3.0]
    """
    n = np.asarray(normal, float)
    ecc = np.asarray(eccentricity_vector, float)
    n = n / np.linalg.norm(n, axis=-1, keepdims=True)
    inclination = np.arctan2(np.hypot(n[..., 0], n[..., 1]), n[..., 2])
    node = np.arctan2(n[..., 0], -n[..., 1])
    towards_node = np.stack([np.cos(node), np.sin(node), np.zeros_like(node)], axis=-1)
    ahead = np.cross(n, towards_node)  # in the plane, 90° past the node along the motion
    omega = np.arctan2(np.sum(ecc * ahead, axis=-1), np.sum(ecc * towards_node, axis=-1))
    return np.linalg.norm(ecc, axis=-1), inclination, wrap_2pi(node), wrap_2pi(node + omega)
