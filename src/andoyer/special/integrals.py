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
``K`` and the complete ``Π`` come from AGM schemes in double-double arithmetic.

Accuracy (tests against mpmath at 40+ digits, ``1 − m`` down to 1e-300): ``K`` within
1 ulp, ``E``, ``F``, ``E(φ|m)`` and the complete ``Π`` within a few ulps.  The incomplete
``Π(n; φ|m)`` loses some digits for large negative ``n`` (terms of opposite signs):
relative errors up to ~8 ulps for ``|n| ≤ 10`` and ~30 ulps at ``n = −1000``.
"""

from __future__ import annotations

import numpy as np
from scipy import special as sc

from andoyer.special.agm import ellipk_dd, ellippi_dd
from andoyer.special.compensated import PI_DD, dd_add, dd_div, two_prod
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
    """Complete elliptic integral of the second kind ``E(m)``.

    ``E(m) = 2 R_G(0, 1 − m, 1)`` (DLMF 19.25.1) for ``m ≤ 1/2``; for ``m > 1/2``, where that
    form loses digits as ``m → 1``, Legendre's relation (DLMF 19.7.1) with
    ``K(m') − E(m') = (m'/3) R_D(0, m, 1)`` gives the cancellation-free
    ``E(m) = [π/2 + K(m) (m'/3) R_D(0, m, 1)] / K(m')``.

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
    near = mc < 0.5
    with np.errstate(divide="ignore", invalid="ignore"):
        legendre = (0.5 * np.pi + ellipk_dd(mc)[0] * (mc / 3.0) * sc.elliprd(0.0, m, 1.0)) / (
            ellipk_dd(np.where(near, m, 0.5))[0]
        )
    return np.where(near, np.where(mc == 0, 1.0, legendre), 2.0 * sc.elliprg(0.0, mc, 1.0))


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
        ``E(φ|m) = 2jE(m) + E(r|m)`` with ``E(r|m) = sin r · R_F − (m/3) sin³r · R_D``
        (DLMF 19.25.9) for ``|r| ≤ π/4`` and, where those two terms would cancel (``r`` near
        ``π/2``, ``m`` near 1), ``E(r|m) = [2R_G − cos²r R_F − |cos r| Δ] / sin r``
        (DLMF 19.25.10 with ``c = csc²r``), all at ``(cos²r, Δ², 1)``.

    Examples
    --------
    >>> float(ellipeinc(1.0, 0.5))
    0.927329883624440
    """
    m, mc = parameter_pair(m, mc)
    j, r = _reduce_angle(phi)
    s, c2, d2 = _trig(r, mc)
    rf = sc.elliprf(c2, d2, 1.0)
    near = np.abs(r) > 0.25 * np.pi
    with np.errstate(divide="ignore", invalid="ignore"):
        small = s * rf - (m / 3.0) * s**3 * sc.elliprd(c2, d2, 1.0)
        large = (2.0 * sc.elliprg(c2, d2, 1.0) - c2 * rf - np.sqrt(c2 * d2)) / s
    return np.where(j == 0, 0.0, 2.0 * j * ellipe(m, mc)) + np.where(near, large, small)


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
        ``Π(n|m)`` by the AGM scheme of DLMF 19.8.6 in double-double arithmetic
        (:func:`andoyer.special.agm.ellippi_dd`), correctly rounded in practice; for
        ``n > 1`` the principal value ``K(m) − Π(m/n|m)`` (DLMF 19.6.5).

    Examples
    --------
    >>> float(ellippi(-0.5, 0.5))
    1.48784699266880
    >>> float(ellippi(0.0, 0.5) - ellipk(0.5))
    0.0
    """
    m, mc = parameter_pair(m, mc)
    n, m, mc = np.broadcast_arrays(np.asarray(n, dtype=np.float64), m, mc)
    above = n > 1
    with np.errstate(divide="ignore", invalid="ignore"):
        # n > 1: PV = K − Π(m/n | m), with m/n < 1 computed in double-double
        nn = np.where(above, n, 0.5)
        ratio = dd_div(m, 0.0, nn, 0.0)
        nh = np.where(above, ratio[0], np.where(n == 1, 0.0, n))
        nl = np.where(above, ratio[1], 0.0)
        ph, pl = ellippi_dd(nh, nl, mc)
        kh, kl = ellipk_dd(mc)
        pv = dd_add(kh, kl, -ph, -pl)[0]
    return np.where(n == 1, np.inf, np.where(above, pv, ph))


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
        ``Π(n; φ|m) = 2jΠ(n|m) + Π(n; r|m)`` with, for ``|r| ≤ π/4`` (or ``n ≥ 1``, ``m = 1``),
        ``Π(n; r|m) = sin r R_F(cos²r, Δ², 1) + (n/3) sin³r R_J(cos²r, Δ², 1, 1 − n sin²r)``
        (DLMF 19.25.14) and otherwise the complement
        ``Π(n|m) − ∫_r^{π/2}``: with ``S = cos r``, ``ñ = n/(n − 1)`` and
        ``x, y, z = m'(1 − S²), m' + mS², m'``,
        ``∫_r^{π/2} = [S R_F(x, y, z) + (ñ/3) S³ m' R_J(x, y, z, m'(1 − ñS²))]/(1 − n)``
        (substitution ``θ → π/2 − θ`` and Carlson's reduction), which avoids the
        cancellation of the two terms above near ``π/2`` as ``m → 1``.

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
    near = (np.abs(r) > 0.25 * np.pi) & (mc > 0) & (n < 1)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        third = np.where(n == 0, 0.0, (n / 3.0) * (s * s2) * sc.elliprj(c2, d2, 1.0, 1.0 - n * s2))
        direct = s * sc.elliprf(c2, d2, 1.0) + third
        complete = ellippi(n, m, mc)
        cr = np.cos(r)
        nt = n / (n - 1.0)
        x, y = mc * (1.0 - cr * cr), mc + m * (cr * cr)
        tail = cr * sc.elliprf(x, y, mc) + np.where(
            nt == 0, 0.0, (nt / 3.0) * cr**3 * mc * sc.elliprj(x, y, mc, mc * (1.0 - nt * cr * cr))
        )
        comp = np.copysign(complete - tail / (1.0 - n), r)
        whole = np.where(j == 0, 0.0, 2.0 * j * complete)
    return whole + np.where(near, comp, direct)
