r"""Daily-mean insolation at the top of the atmosphere (Berger 1978).

For a latitude ``φ``, the Sun's true longitude ``λ`` (from the moving equinox of date; ``λ = π/2``
at the northern summer solstice), obliquity ``ε``, eccentricity ``e`` and heliocentric longitude
of perihelion ``ϖ`` (from the moving equinox; the Sun's geocentric perihelion is at ``ϖ + π``):

.. math:: \sin\delta = \sin\varepsilon\sin\lambda, \qquad
   \frac{a}{r} = \frac{1 + e\cos(\lambda - \varpi - \pi)}{1 - e^2}
   = \frac{1 - e\cos(\lambda - \varpi)}{1 - e^2},

.. math:: \bar Q = \frac{S_0}{\pi}\Big(\frac{a}{r}\Big)^2
   \big(H_0 \sin\varphi\sin\delta + \cos\varphi\cos\delta\sin H_0\big), \qquad
   \cos H_0 = -\tan\varphi\tan\delta,

``H₀`` the hour angle of sunset, clipped to ``[0, π]`` (polar night, polar day). ``S₀`` is the
solar constant at the mean distance ``a`` (default 1361 W/m², Kopp & Lean 2011, GRL 38, L01706).
Berger (1978), J. Atmos. Sci. 35, 2362, eq. (10); the daily average is over a whole day at fixed
``λ``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite

__all__ = ["daily_insolation"]


def daily_insolation(
    latitude: ArrayLike,
    solar_longitude: ArrayLike,
    obliquity: ArrayLike,
    eccentricity: ArrayLike,
    perihelion: ArrayLike,
    solar_constant: float = 1361.0,
) -> NDArray[np.float64]:
    """Daily-mean insolation ``Q̄`` (W/m²) of Berger (1978), broadcast over the arguments.

    Parameters
    ----------
    latitude : array_like, shape (...)
        ``φ``, radians in ``[−π/2, π/2]``.
    solar_longitude : array_like, shape (...)
        ``λ``, radians.
    obliquity : array_like, shape (...)
        ``ε``, radians.
    eccentricity : array_like, shape (...)
        ``e`` in ``[0, 1)``.
    perihelion : array_like, shape (...)
        ``ϖ`` (heliocentric, from the moving equinox), radians.
    solar_constant : float
        W/m².

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    65° N at the June solstice, J2000 (ε = 23.439°, e = 0.0167, ϖ = 102.94°):

    >>> q = daily_insolation(np.radians(65), np.pi / 2, np.radians(23.439), 0.0167, np.radians(102.94))
    >>> round(float(q), 1)
    477.9
    """
    values = (latitude, solar_longitude, obliquity, eccentricity, perihelion)
    names = ("latitude", "solar_longitude", "obliquity", "eccentricity", "perihelion")
    phi, lam, eps, e, varpi = (as_finite(v, name) for v, name in zip(values, names, strict=True))
    if np.any(np.abs(phi) > np.pi / 2 + 1e-12) or np.any((e < 0) | (e >= 1)):
        msg = "expected latitudes within ±π/2 and eccentricities in [0, 1), got values outside"
        raise ValueError(msg)
    sin_d = np.sin(eps) * np.sin(lam)
    cos_d = np.sqrt(1 - sin_d**2)
    x = -np.tan(phi) * sin_d / np.maximum(cos_d, 1e-300)
    h0 = np.arccos(np.clip(x, -1.0, 1.0))
    ratio = (1 - e * np.cos(lam - varpi)) / ((1 - e) * (1 + e))
    return solar_constant / np.pi * ratio**2 * (h0 * np.sin(phi) * sin_d + np.cos(phi) * cos_d * np.sin(h0))
