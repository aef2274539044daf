r"""Complete and incomplete elliptic integrals of the first, second and third kinds.

Conventions (Legendre's forms with the *parameter* ``m = k²``, DLMF §19.2, A&S §17.2):

.. math::
   F(\varphi|m) &= \int_0^\varphi \frac{d\theta}{\sqrt{1 - m\sin^2\theta}}, \qquad
   K(m) = F(\tfrac{\pi}{2}|m), \\
   E(\varphi|m) &= \int_0^\varphi \sqrt{1 - m\sin^2\theta}\, d\theta, \qquad
   E(m) = E(\tfrac{\pi}{2}|m), \\
   \Pi(n;\varphi|m) &= \int_0^\varphi
      \frac{d\theta}{(1 - n\sin^2\theta)\sqrt{1 - m\sin^2\theta}}, \qquad
   \Pi(n|m) = \Pi(n;\tfrac{\pi}{2}|m).

The characteristic enters as ``1 − n sin²θ`` (so ``n < 0`` is the "hyperbolic" side; the
free rigid body needs ``n = −κ² ≤ 0``).  For ``n > 1`` the integrals are Cauchy principal
values (DLMF 19.6.5, 19.25.16), as scipy's ``elliprj`` returns them for a negative last
argument.

All are evaluated through Carlson's symmetric integrals (scipy ``elliprf``, ``elliprd``,
``elliprg``, ``elliprj``; DLMF 19.25.1, 19.25.5, 19.25.7, 19.25.14) after reducing
``φ = jπ + r`` with ``|r| ≤ π/2`` (π in double-double) and using
``F(jπ + r) = 2jK + F(r)`` and its analogues; the Carlson arguments are
``cos²r`` and ``Δ² = cos²r + m' sin²r``, which keeps full precision as ``m → 1``.
``K`` itself comes from the double-double AGM.
"""

from __future__ import annotations

import numpy as np
from scipy import special as sc

from andoyer.special.agm import ellipk_dd
from andoyer.special.compensated import PI_DD, two_prod
from andoyer.special.parameter import parameter_pair

__all__ = ["ellipe", "ellipeinc", "ellipf", "ellipk", "ellippi", "ellippiinc"]


def _reduce_angle(phi):
    """``φ = jπ + r`` with integer ``j`` and ``|r| ≤ π/2``, subtracting ``jπ`` in double-double."""
    phi = np.asarray(phi, dtype=np.float64)
    if not np.all(np.isfinite(phi)):
        bad = phi[~np.isfinite(phi)].ravel()[:3]
        raise ValueError(f"expected a finite amplitude phi, got {bad}")
    j = np.round(phi / PI_DD[0])
    p, e = two_prod(j, PI_DD[0])
    r = ((phi - p) - e) - j * PI_DD[1]
    return j, r


def _trig(r, mc):
    s = np.sin(r)
    c = np.cos(r)
    c2 = c * c
    return s, c2, c2 + mc * (s * s)


def ellipk(m, mc=None):
    """Complete elliptic integral of the first kind ``K(m)``.

    Parameters
    ----------
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately (see :mod:`andoyer.special.parameter`).

    Returns
    -------
    ndarray
        ``K(m)``; ``inf`` at ``m = 1``.

    Examples
    --------
    >>> float(ellipk(0.5))
    1.8540746773013719
    >>> float(ellipk(1 - 1e-20, mc=1e-20))
    24.4121452910603
    """
    m, mc = parameter_pair(m, mc)
    return ellipk_dd(mc)[0]


def ellipe(m, mc=None):
    """Complete elliptic integral of the second kind ``E(m) = 2 R_G(0, 1 − m, 1)``.

    Parameters
    ----------
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``E(m)``; ``1`` at ``m = 1``.

    Examples
    --------
    >>> float(ellipe(0.5))
    1.35064388104768
    """
    m, mc = parameter_pair(m, mc)
    return 2.0 * sc.elliprg(0.0, mc, 1.0)


def ellipf(phi, m, mc=None):
    """Incomplete elliptic integral of the first kind ``F(φ|m)``.

    Parameters
    ----------
    phi : array_like
        Amplitude ``φ`` (radians, any real value).
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``F(φ|m) = 2jK(m) + sin r · R_F(cos²r, Δ², 1)`` for ``φ = jπ + r``.

    Examples
    --------
    >>> float(ellipf(1.0, 0.5))
    1.08321677284517
    >>> float(ellipf(np.pi, 0.5) - 2 * ellipk(0.5))
    0.0
    """
    m, mc = parameter_pair(m, mc)
    j, r = _reduce_angle(phi)
    s, c2, d2 = _trig(r, mc)
    with np.errstate(invalid="ignore"):
        whole = np.where(j == 0, 0.0, 2.0 * j * ellipk_dd(mc)[0])
    return whole + s * sc.elliprf(c2, d2, 1.0)


def ellipeinc(phi, m, mc=None):
    """Incomplete elliptic integral of the second kind ``E(φ|m)``.

    Parameters
    ----------
    phi : array_like
        Amplitude ``φ`` (radians, any real value).
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``E(φ|m) = 2jE(m) + sin r · R_F − (m/3) sin³r · R_D`` (DLMF 19.25.9).

    Examples
    --------
    >>> float(ellipeinc(1.0, 0.5))
    0.927329883624440
    """
    m, mc = parameter_pair(m, mc)
    j, r = _reduce_angle(phi)
    s, c2, d2 = _trig(r, mc)
    part = s * sc.elliprf(c2, d2, 1.0) - (m / 3.0) * s**3 * sc.elliprd(c2, d2, 1.0)
    return np.where(j == 0, 0.0, 2.0 * j * ellipe(m, mc)) + part


def ellippi(n, m, mc=None):
    """Complete elliptic integral of the third kind ``Π(n|m)``.

    Parameters
    ----------
    n : array_like
        Characteristic, entering as ``1 − n sin²θ``; ``n > 1`` gives the Cauchy principal
        value, ``n = 1`` gives ``inf``.
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``Π(n|m) = R_F(0, m', 1) + (n/3) R_J(0, m', 1, 1 − n)`` (DLMF 19.25.2).

    Examples
    --------
    >>> float(ellippi(-0.5, 0.5))
    1.48784699266880
    >>> float(ellippi(0.0, 0.5) - ellipk(0.5))
    0.0
    """
    m, mc = parameter_pair(m, mc)
    n = np.asarray(n, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        third = np.where(n == 0, 0.0, (n / 3.0) * sc.elliprj(0.0, mc, 1.0, 1.0 - n))
        out = ellipk_dd(mc)[0] + third
    return np.where(n == 1, np.inf, out)


def ellippiinc(n, phi, m, mc=None):
    """Incomplete elliptic integral of the third kind ``Π(n; φ|m)``.

    Parameters
    ----------
    n : array_like
        Characteristic, entering as ``1 − n sin²θ``; where ``1 − n sin²θ`` changes sign
        on the path the result is the Cauchy principal value.
    phi : array_like
        Amplitude ``φ`` (radians, any real value).
    m : array_like
        Parameter ``m ≤ 1``.
    mc : array_like, optional
        ``1 − m`` given separately.

    Returns
    -------
    ndarray
        ``Π(n; φ|m) = 2jΠ(n|m) + sin r R_F(cos²r, Δ², 1)
        + (n/3) sin³r R_J(cos²r, Δ², 1, 1 − n sin²r)`` (DLMF 19.25.14).

    Examples
    --------
    >>> float(ellippiinc(-0.5, 1.0, 0.5))
    0.956040663326747
    """
    m, mc = parameter_pair(m, mc)
    n = np.asarray(n, dtype=np.float64)
    j, r = _reduce_angle(phi)
    s, c2, d2 = _trig(r, mc)
    s2 = s * s
    with np.errstate(divide="ignore", invalid="ignore"):
        third = np.where(n == 0, 0.0, (n / 3.0) * (s * s2) * sc.elliprj(c2, d2, 1.0, 1.0 - n * s2))
        whole = np.where(j == 0, 0.0, 2.0 * j * ellippi(n, m, mc))
    return whole + s * sc.elliprf(c2, d2, 1.0) + third
