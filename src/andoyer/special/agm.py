"""Complete elliptic integrals K and Π in double-double precision, by Gauss's AGM.

``K(m) = π / (2 M(1, √(1 − m)))`` where ``M`` is the arithmetic-geometric mean.  The
iteration converges quadratically and is run in double-double arithmetic, so ``K`` comes
out with about 30 significant digits; its high part is the correctly rounded ``K`` in all
but rare ties.  The free-rigid-body solution needs this precision for the period
``4K/ω``: a phase carried over 100 periods keeps its last digits only if ``K`` has more
than 16.
"""

from __future__ import annotations

import numpy as np

from andoyer.special.compensated import PI_DD, dd_add, dd_div, dd_mul, dd_sqrt

__all__ = ["agm_dd", "ellipk_dd", "ellippi_dd"]

_MAX_ITER = 64


def agm_dd(ah, al, bh, bl):
    """Arithmetic-geometric mean ``M(a, b)`` of two non-negative double-doubles.

    Parameters
    ----------
    ah, al, bh, bl : array_like
        High and low parts of ``a ≥ 0`` and ``b ≥ 0``, broadcast together.

    Returns
    -------
    hi, lo : ndarray
        ``M(a, b)`` as a double-double (``0`` when either argument is ``0``).

    Examples
    --------
    >>> hi, lo = agm_dd(1.0, 0.0, 2.0, 0.0)
    >>> float(hi)
    1.4567910310469068
    """
    ah, al, bh, bl = np.broadcast_arrays(*(np.asarray(x, dtype=np.float64) for x in (ah, al, bh, bl)))
    zero = (ah == 0) | (bh == 0)
    ah, al = np.where(zero, 1.0, ah), np.where(zero, 0.0, al)
    bh, bl = np.where(zero, 1.0, bh), np.where(zero, 0.0, bl)
    for _ in range(_MAX_ITER):
        sh, sl = dd_add(ah, al, bh, bl)
        ph, pl = dd_mul(ah, al, bh, bl)
        nbh, nbl = dd_sqrt(ph, pl)
        ah, al = 0.5 * sh, 0.5 * sl
        bh, bl = nbh, nbl
        dh, _ = dd_add(ah, al, -bh, -bl)
        if np.all(np.abs(dh) <= 1e-31 * np.abs(ah)):
            break
    return np.where(zero, 0.0, ah), np.where(zero, 0.0, al)


def ellipk_dd(mc_hi, mc_lo=0.0):
    """Complete elliptic integral of the first kind from the complementary parameter.

    ``K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ)`` with ``m = 1 − m'``, evaluated as
    ``π / (2 M(1, √m'))`` in double-double arithmetic.

    Parameters
    ----------
    mc_hi, mc_lo : array_like
        The complementary parameter ``m' = 1 − m ≥ 0`` as a double-double (``mc_lo`` may
        be ``0``).  ``m' = 0`` gives ``K = ∞``.

    Returns
    -------
    hi, lo : ndarray
        ``K`` as a double-double.

    Examples
    --------
    >>> hi, lo = ellipk_dd(0.5)
    >>> float(hi)
    1.8540746773013719
    """
    mc_hi = np.asarray(mc_hi, dtype=np.float64)
    kh, kl = dd_sqrt(mc_hi, mc_lo)
    mh, ml = agm_dd(1.0, 0.0, kh, kl)
    with np.errstate(divide="ignore", invalid="ignore"):
        hi, lo = dd_div(0.5 * PI_DD[0], 0.5 * PI_DD[1], mh, ml)
    zero = mh == 0
    return np.where(zero, np.inf, hi), np.where(zero, 0.0, lo)


def ellippi_dd(n_hi, n_lo, mc_hi, mc_lo=0.0):
    r"""Complete elliptic integral of the third kind ``Π(n|m)`` in double-double, ``n < 1``.

    ``Π(n|m) = ∫₀^{π/2} dθ / ((1 − n sin²θ) √(1 − m sin²θ))`` by the quadratically
    convergent AGM scheme of DLMF 19.8.6–8: with the AGM sequence ``aₖ, gₖ`` of
    ``(1, √m')``, ``p₀² = 1 − n``, ``Q₀ = 1``,
    ``p_{k+1} = (pₖ² + aₖgₖ)/(2pₖ)``, ``εₖ = (pₖ² − aₖgₖ)/(pₖ² + aₖgₖ)``,
    ``Q_{k+1} = Q_k εₖ/2``,

    .. math:: \Pi(n|m) = \frac{\pi}{4 M(1, \sqrt{m'})}
              \Big(2 + \frac{n}{1 - n} \sum_k Q_k\Big).

    Parameters
    ----------
    n_hi, n_lo : array_like
        Characteristic ``n < 1`` (entering as ``1 − n sin²θ``) as a double-double.
    mc_hi, mc_lo : array_like
        Complementary parameter ``m' = 1 − m > 0`` as a double-double.

    Returns
    -------
    hi, lo : ndarray
        ``Π(n|m)`` as a double-double.

    Examples
    --------
    >>> hi, lo = ellippi_dd(-0.5, 0.0, 0.5)
    >>> float(hi)
    1.4878469926687984
    """
    n_hi, n_lo, mc_hi, mc_lo = np.broadcast_arrays(
        *(np.asarray(x, dtype=np.float64) for x in (n_hi, n_lo, mc_hi, mc_lo))
    )
    ah, al = np.ones_like(mc_hi), np.zeros_like(mc_hi)
    gh, gl = dd_sqrt(mc_hi, mc_lo)
    p2h, p2l = dd_add(1.0, 0.0, -n_hi, -n_lo)
    ph, pl = dd_sqrt(p2h, p2l)
    qh, ql = np.ones_like(mc_hi), np.zeros_like(mc_hi)
    sh, sl = qh.copy(), ql.copy()
    for _ in range(_MAX_ITER):
        agh, agl = dd_mul(ah, al, gh, gl)
        numh, numl = dd_add(p2h, p2l, -agh, -agl)
        denh, denl = dd_add(p2h, p2l, agh, agl)
        eh, el = dd_div(numh, numl, denh, denl)
        ph, pl = dd_div(denh, denl, 2.0 * ph, 2.0 * pl)
        p2h, p2l = dd_mul(ph, pl, ph, pl)
        qh, ql = dd_mul(qh, ql, 0.5 * eh, 0.5 * el)
        sh, sl = dd_add(sh, sl, qh, ql)
        nah, nal = dd_add(ah, al, gh, gl)
        gh, gl = dd_sqrt(agh, agl)
        ah, al = 0.5 * nah, 0.5 * nal
        dh, _ = dd_add(ah, al, -gh, -gl)
        if np.all((np.abs(qh) <= 1e-33 * np.abs(sh)) & (np.abs(dh) <= 1e-31 * np.abs(ah))):
            break
    # π/(4M) (2 + n/(1 − n) Σ Q)
    rh, rl = dd_div(n_hi, n_lo, *dd_add(1.0, 0.0, -n_hi, -n_lo))
    th, tl = dd_add(2.0, 0.0, *dd_mul(rh, rl, sh, sl))
    fh, fl = dd_div(PI_DD[0], PI_DD[1], 4.0 * ah, 4.0 * al)
    return dd_mul(fh, fl, th, tl)
