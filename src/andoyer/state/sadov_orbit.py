r"""One orbit of the ``(l', L)`` cylinder in Sadov's standard frame: its action and its angles.

Notation (see :mod:`andoyer.state.sadov_frame` for ``ρ``): ``x = L/G``, ``s = sin l'``,
``c = cos l'``, and the normalised energy

.. math:: \tau = \frac{2T/G^2 - a_3}{a_e - a_3} = (1 - x^2)(1 - \rho c^2) \in [0, 1],

``τ = 0`` on the poles ``L = ±G``, ``τ = 1 − ρ`` on the separatrix, ``τ = 1`` at ``±b_e``.
The sign of ``δ = ρ s²(1 − x²) − (1 − ρ) x² = τ − (1 − ρ)`` tells the region: ``δ < 0``
circulation of ``l'``, ``δ > 0`` libration about ``±b_e``. Sadov's state function (eq. 139)
is ``λ² = ρτ / ((1 − ρ)(1 − τ))``.

Each region is parametrised by a pair ``(v, v_c)`` with ``v + v_c = 1`` that keeps both ends
accurate: circulation ``y = τ/(1 − ρ)``, ``y_c = −δ/(1 − ρ)``; libration
``w = (1 − τ)/ρ``, ``w_c = δ/ρ``. From them, without cancellation,

* circulation: ``1 − τ = ρ + (1 − ρ) y_c``, elliptic parameter ``m = λ² = ρ y/(1 − τ)``,
  ``m_c = y_c/(1 − τ)``, characteristic ``n = −κ² = −ρ/(1 − ρ)``;
* libration: ``1 − τ = ρ w``, ``τ = (1 − ρ) + ρ w_c``, ``m = 1/λ² = (1 − ρ) w/τ``,
  ``m_c = w_c/τ``, ``n = −κ²/λ² = −(1 − τ)/τ``.

Integrals are Legendre's with parameter ``m = k²`` and the characteristic entering as
``1 − n sin²θ`` (:mod:`andoyer.special`); ``R_J`` is Carlson's symmetric integral.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy import special as sc

from andoyer.special import am, ellipf, ellipk
from andoyer.state.sadov_frame import SadovFrame

__all__ = ["Orbit", "angles", "orbit", "point"]

Array = NDArray[np.float64]
HALF_PI = 0.5 * np.pi


class Orbit(NamedTuple):
    """Per-state constants of an orbit (all arrays of one 1-D shape)."""

    circ: NDArray[np.bool_]  # circulation (True) or libration (False)
    tau: Array  # τ
    omt: Array  # 1 − τ
    m: Array  # elliptic parameter
    mc: Array  # 1 − m
    n: Array  # characteristic of the third kind
    K: Array  # K(m)
    RJc: Array  # R_J(0, m_c, 1, 1 − n) = 3 (Π(n|m) − K(m)) / n
    u: Array  # |I_ℓ| / G
    dudtau: Array  # d(|I_ℓ|/G)/dτ (< 0)
    root: Array  # √((1 − ρ)(1 − τ)) or √(ρτ); φ_g − g = σ Q / root (eq. 147)


def orbit(frame: SadovFrame, circ: NDArray[np.bool_], v: Array, vc: Array) -> Orbit:
    r"""Constants of the orbits given by their region and the pair ``(v, v_c)``.

    The action fraction ``u = |I_ℓ|/G`` is eq. 143, corrected and rewritten with
    ``Π(n|m) = K(m) + (n/3) R_J(0, m_c, 1, 1 − n)`` so that no difference of large terms
    appears: circulation (``1 − n = 1 + κ² = 1/(1 − ρ)``)

    .. math:: u_c(\rho, \tau) = \frac{2}{\pi}\sqrt{\frac{1-\tau}{1-\rho}}
              \Big[K(m) - \frac{\rho}{3(1-\rho)(1-\tau)} R_J\big(0, m_c, 1, \tfrac{1}{1-\rho}\big)\Big],

    libration (the real part of eq. 143 for ``λ > 1``, reciprocal-modulus form)

    .. math:: u_l(\rho, \tau) = \frac{2}{\pi}\frac{1-\tau}{\sqrt{\rho\tau}}
              \Big[K(m) - \frac{1}{3\tau} R_J\big(0, m_c, 1, \tfrac{1}{\tau}\big)\Big].

    The bracket cancels as ``ρ → 1`` (circulation) and as ``τ → 0`` (libration); there
    the duality ``u_l(ρ, τ) = 1 − u_c(1 − ρ, 1 − τ)`` (the libration about ``b_e`` is a
    circulation in the Andoyer chart about ``b_e``; same pair ``(v, v_c)``, same ``m``)
    gives the value from the well-conditioned formula instead. ``du/dτ = −K(m)/(π
    √((1 − ρ)(1 − τ)))`` or ``−K(m)/(π √(ρτ))`` (eq. 145 with ``dλ/dτ``).

    Parameters
    ----------
    frame : SadovFrame
    circ : numpy.ndarray of bool, shape (n,)
        Circulation (True) or libration (False).
    v, vc : numpy.ndarray, shape (n,)
        The pair ``(y, y_c)`` or ``(w, w_c)``, ``v + v_c = 1``; ``v_c > 0``.

    Returns
    -------
    Orbit

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> frame = SadovFrame.from_body(RigidBody(1.0, 2.0, 2.5))
    >>> o = orbit(frame, np.array([True, False]), np.array([0.0, 0.0]), np.array([1.0, 1.0]))
    >>> o.u.tolist(), o.m.tolist()  # the pole (u = 1) and the libration centre (u = 0)
    ([1.0, 0.0], [0.0, 0.0])
    """
    rho, rho_c = np.float64(frame.rho), np.float64(frame.rho_c)
    with np.errstate(all="ignore"):
        # Libration entries are computed in the circulation branch too (and vice versa):
        # the masked values are discarded by np.where.
        omt = np.where(circ, rho + rho_c * vc, rho * v)
        tau = np.where(circ, rho_c * v, rho_c + rho * vc)
        den = np.where(circ, omt, tau)
        m_raw = np.where(circ, rho * v, rho_c * v) / den
        mc = vc / den
        p = np.where(circ, 1.0 / rho_c, 1.0 / tau)  # 1 − n
    p = np.where(np.isfinite(p), p, 1.0)
    # Give the special functions the accurate member of the pair (m, 1 − m).
    m = np.where(mc < 0.5, 1.0 - mc, m_raw)
    mc = np.where(mc < 0.5, mc, 1.0 - m_raw)
    K = ellipk(m, mc)
    RJc = sc.elliprj(0.0, mc, 1.0, p)
    dual = np.where(circ, rho_c < 0.5, tau < 0.5)
    with np.errstate(all="ignore"):
        # u = offset + A [K − B R_J(0, m_c, 1, q)], direct (q = 1 − n) or dual.
        A_direct = np.where(circ, np.sqrt(omt / rho_c), omt / np.sqrt(rho * tau))
        B_direct = np.where(circ, rho / (3.0 * rho_c * omt), 1.0 / (3.0 * tau))
        A_dual = np.where(circ, -tau / np.sqrt(rho_c * omt), -np.sqrt(tau / rho))
        B_dual = np.where(circ, 1.0 / (3.0 * omt), rho_c / (3.0 * rho * tau))
        q_dual = np.where(circ, 1.0 / omt, 1.0 / rho)
    RJ = RJc.copy()
    if dual.any():
        RJ[dual] = sc.elliprj(0.0, mc[dual], 1.0, q_dual[dual])
    with np.errstate(all="ignore"):
        A = np.where(dual, A_dual, A_direct)
        B = np.where(dual, B_dual, B_direct)
        u = np.where(dual, 1.0, 0.0) + A * (K - B * RJ) / HALF_PI
        root = np.where(circ, np.sqrt(rho_c * omt), np.sqrt(rho * tau))
        dudtau = -K / (np.pi * root)
    return Orbit(circ, tau, omt, m, mc, 1.0 - p, K, RJc, u, dudtau, root)


def _bracket(o: Orbit, phi: Array) -> Array:
    r"""``Q = Π(n; φ|m) − Π(n|m) F(φ|m)/K(m)``, the periodic part of eq. 147.

    ``Q`` has period ``π`` in ``φ`` (the multiples of the period cancel exactly), so it is
    evaluated on ``r = φ − jπ``, ``|r| <= π/2``, ``s = sin r``, ``Δ² = 1 − m s²``. For
    ``|n| <= 1``, with ``n`` factored out so that nothing cancels as ``n → 0``,

    .. math:: Q = \tfrac{n}{3}\big[s^3 R_J(\cos^2 r, Δ^2, 1, 1 - n s^2)
              - R_J(0, m_c, 1, 1 - n)\, F(r|m)/K(m)\big];

    for ``|n| > 1`` both terms approach ``F(r|m)`` and cancel, so the characteristic is
    changed to ``N = m/n`` (DLMF 19.7.8, ``|N| < 1``):

    .. math:: Q = -Q_N + s\, R_C\big(\cos^2 r\, Δ^2, (1 - n s^2)(1 - N s^2)\big)
              - \frac{\pi}{2} \frac{F(r|m)}{K(m)\sqrt{(1 - n)(1 - N)}},

    with ``Q_N`` the first form for the characteristic ``N``.
    """
    r = phi - np.round(phi / np.pi) * np.pi
    s, c = np.sin(r), np.cos(r)
    s2, c2 = s * s, c * c
    d2 = c2 + o.mc * s2
    ratio = ellipf(r, o.m, o.mc) / o.K
    large = np.abs(o.n) > 1.0
    N = np.where(large, o.m / np.where(large, o.n, 1.0), o.n)
    RJc = np.where(large, sc.elliprj(0.0, o.mc, 1.0, 1.0 - N), o.RJc)
    Q = N / 3.0 * (s * s2 * sc.elliprj(c2, d2, 1.0, 1.0 - N * s2) - RJc * ratio)
    if large.any():
        n, Nl = o.n[large], N[large]
        swapped = s[large] * sc.elliprc(c2[large] * d2[large], (1.0 - n * s2[large]) * (1.0 - Nl * s2[large]))
        swapped -= HALF_PI * ratio[large] / np.sqrt((1.0 - n) * (1.0 - Nl))
        Q[large] = swapped - Q[large]
    return Q


def angles(
    frame: SadovFrame, o: Orbit, sign: Array, sin_lp: Array, cos_lp: Array, x: Array
) -> tuple[Array, Array]:
    r"""``(φ_ℓ, φ_g − g)`` of states on the orbits ``o`` (eqs. 146–147, corrected).

    Circulation: Sadov's ``z`` (eq. 142) is ``z = atan2(−√(1 − ρ) cos l', sin l')`` and
    ``φ_ℓ = (π/2) (F(z|m) − F(z_0|m)) / K(m)`` with ``z_0`` the origin (the meridian of
    ``+b_i``, ``F(z_0) = ∓K``). Libration: ``ζ = atan2(−√(ρτ) cos l', x √(1 − ρ c²))``
    (``λ sin z = sin ζ``, ``L = G √(1 − τ) cos ζ``) and ``φ_ℓ = (π/2) F(ζ|m)/K(m)``.
    In both, ``φ_g = g + σ Q / root`` (``Q`` from :func:`_bracket`, ``root`` from
    :class:`Orbit`), with ``σ`` the sign of ``I_ℓ``.

    Parameters
    ----------
    frame : SadovFrame
    o : Orbit
        The states' orbits, shape (n,).
    sign, sin_lp, cos_lp, x : numpy.ndarray, shape (n,)
        ``σ``, ``sin l'``, ``cos l'`` and ``L/G``.

    Returns
    -------
    phi_l, dg : numpy.ndarray, shape (n,)
        ``φ_ℓ`` (unreduced) and ``φ_g − g``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> frame = SadovFrame.from_body(RigidBody(1.0, 2.0, 2.5))
    >>> o = orbit(frame, np.array([False]), np.array([0.5]), np.array([0.5]))
    >>> s, c, x, _ = point(frame, o, np.array([1.0]), np.array([0.7]))
    >>> norm = np.hypot(s, c)
    >>> phi_l, _ = angles(frame, o, np.array([1.0]), s / norm, c / norm, x)
    >>> round(float(phi_l[0]), 12)
    0.7
    """
    with np.errstate(invalid="ignore"):
        z = np.arctan2(-np.sqrt(frame.rho_c) * cos_lp, sin_lp)
        zeta = np.arctan2(
            -np.sqrt(frame.rho * o.tau) * cos_lp, x * np.sqrt(frame.rho_c + frame.rho * sin_lp**2)
        )
    arg = np.where(o.circ, z, zeta)
    offset = np.where(o.circ, -np.sign(frame.circulation_origin) * HALF_PI, 0.0)
    phi_l = HALF_PI * ellipf(arg, o.m, o.mc) / o.K + offset
    return phi_l, sign * _bracket(o, arg) / o.root


def point(frame: SadovFrame, o: Orbit, sign: Array, phi_l: Array) -> tuple[Array, Array, Array, Array]:
    r"""``(sin l', cos l', L/G, g − φ_g)`` (unnormalised sine and cosine) at angle ``φ_ℓ``.

    Inverts :func:`angles`: ``z = am(2K(φ_ℓ − φ_0)/π | m)`` and
    ``(sin l', cos l') ∝ (√(1 − ρ) cos z, −sin z)``, ``L = σ G √(1 − τ) dn``;
    ``ζ = am(2Kφ_ℓ/π | m)`` and ``(sin l', cos l') ∝ (σ √(ρτ) dn, −√(1 − τ) sin ζ)``,
    ``L = G √(1 − τ) cos ζ``, where ``dn = √(cos² + m_c sin²)`` of the amplitude.

    Parameters
    ----------
    frame : SadovFrame
    o : Orbit
        The states' orbits, shape (n,).
    sign, phi_l : numpy.ndarray, shape (n,)
        ``σ`` and ``φ_ℓ``.

    Returns
    -------
    sin_lp, cos_lp, x, dg : numpy.ndarray, shape (n,)
        Components proportional to ``(sin l', cos l')``, ``L/G`` and ``g − φ_g``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> frame = SadovFrame.from_body(RigidBody(1.0, 2.0, 2.5))
    >>> o = orbit(frame, np.array([True]), np.array([0.5]), np.array([0.5]))
    >>> s, c, x, dg = point(frame, o, np.array([1.0]), np.array([0.0]))
    >>> float(s[0]), float(c[0]), float(dg[0])  # the origin: the meridian of +b2, m1 = 0
    (0.0, 1.0, 0.0)
    """
    offset = np.where(o.circ, -np.sign(frame.circulation_origin) * HALF_PI, 0.0)
    arg = am((phi_l - offset) * o.K / HALF_PI, o.m, o.mc)
    s, c = np.sin(arg), np.cos(arg)
    dn = np.sqrt(c * c + o.mc * s * s)
    root = np.sqrt(o.omt)
    with np.errstate(invalid="ignore"):
        sin_lp = np.where(o.circ, np.sqrt(frame.rho_c) * c, sign * np.sqrt(frame.rho * o.tau) * dn)
    cos_lp = np.where(o.circ, -s, -root * s)
    x = np.where(o.circ, sign * root * dn, root * c)
    return sin_lp, cos_lp, x, -sign * _bracket(o, arg) / o.root
