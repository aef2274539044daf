"""Complete elliptic integrals K and Π in double-double precision, by Gauss's AGM.

``K(m) = π / (2 M(1, √(1 − m)))`` where ``M`` is the arithmetic-geometric mean.  The
iteration converges quadratically and is run in double-double arithmetic, so ``K`` comes
out with about 30 significant digits; its high part is the correctly rounded ``K`` in all
but rare ties.  The free-rigid-body solution needs this precision for the period
``4K/ω``: a phase carried over 100 periods keeps its last digits only if ``K`` has more
than 16.

As the double-double operations they are built on (:mod:`andoyer.special.compensated`),
the schemes are written once: from Python they run element-wise on numpy arrays (the loop
stops when every element has converged, :func:`andoyer._jit.every`) or on floats, and the
compiled set-up of the free solution (:mod:`andoyer.free.triaxial.setup_compiled`) compiles them
inline, one body at a time.
"""

from __future__ import annotations

import math

from andoyer._jit import every, jitable, select
from andoyer.special.compensated import PI_DD, dd_add, dd_div, dd_mul, dd_sqrt

__all__ = ["agm_dd", "ellipk_dd", "ellippi_dd", "ellippi_k_dd"]

_MAX_ITER = 64
# |a − g| ≤ 2⁻⁵² a stops the iteration: M = (a + g)/2 − (a − g)²/(16a) + …, so the next
# mean is M to 2⁻¹⁰⁸, below the double-double's own rounding
_CONVERGED = 2.220446049250313e-16


@jitable
def agm_dd(ah, al, bh, bl):
    """Arithmetic-geometric mean ``M(a, b)`` of two non-negative double-doubles.

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low parts of ``a ≥ 0`` and ``b ≥ 0``, broadcast together.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        ``M(a, b)`` as a double-double (``0`` when either argument is ``0``).

    Examples
    --------
    >>> hi, lo = agm_dd(1.0, 0.0, 2.0, 0.0)
    >>> float(hi)
    1.4567910310469068
    """
    zero = (ah == 0.0) | (bh == 0.0)
    ah, al = select(zero, 1.0, ah), select(zero, 0.0, al)
    bh, bl = select(zero, 1.0, bh), select(zero, 0.0, bl)
    done = zero  # an element that has converged keeps its values while the others go on
    for _ in range(_MAX_ITER):
        sh, sl = dd_add(ah, al, bh, bl)
        ph, pl = dd_mul(ah, al, bh, bl)
        nbh, nbl = dd_sqrt(ph, pl)
        ah, al = select(done, ah, 0.5 * sh), select(done, al, 0.5 * sl)
        bh, bl = select(done, bh, nbh), select(done, bl, nbl)
        dh, _ = dd_add(ah, al, -bh, -bl)
        done = done | (abs(dh) <= _CONVERGED * abs(ah))
        if every(done):
            break
    sh, sl = dd_add(ah, al, bh, bl)
    return select(zero, 0.0, 0.5 * sh), select(zero, 0.0, 0.5 * sl)


@jitable
def ellipk_dd(mc_hi, mc_lo=0.0):
    """Complete elliptic integral of the first kind from the complementary parameter.

    ``K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ)`` with ``m = 1 − m'``, evaluated as
    ``π / (2 M(1, √m'))`` in double-double arithmetic.

    Parameters
    ----------
    mc_hi, mc_lo : float or ndarray, shape (...)
        The complementary parameter ``m' = 1 − m ≥ 0`` as a double-double (``mc_lo`` may
        be ``0``).  ``m' = 0`` gives ``K = ∞``.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        ``K`` as a double-double.

    Examples
    --------
    >>> hi, lo = ellipk_dd(0.5)
    >>> float(hi)
    1.8540746773013719
    """
    gh, gl = dd_sqrt(mc_hi, mc_lo)
    mh, ml = agm_dd(1.0, 0.0, gh, gl)
    zero = mh == 0.0
    kh, kl = dd_div(0.5 * PI_DD[0], 0.5 * PI_DD[1], select(zero, 1.0, mh), ml)
    return select(zero, math.inf, kh), select(zero, 0.0, kl)


@jitable
def ellippi_k_dd(n_hi, n_lo, mc_hi, mc_lo):
    r"""``Π(n|m)`` and ``K(m)`` together, from one AGM sequence, in double-double; ``n < 1``.

    ``Π(n|m) = ∫₀^{π/2} dθ / ((1 − n sin²θ) √(1 − m sin²θ))`` by the quadratically
    convergent AGM scheme of DLMF 19.8.6–8: with the AGM sequence ``aₖ, gₖ`` of
    ``(1, √m')``, ``p₀² = 1 − n``, ``Q₀ = 1``,
    ``p_{k+1} = (pₖ² + aₖgₖ)/(2pₖ)``, ``εₖ = (pₖ² − aₖgₖ)/(pₖ² + aₖgₖ)``,
    ``Q_{k+1} = Q_k εₖ/2``,

    .. math:: \Pi(n|m) = \frac{\pi}{4 M(1, \sqrt{m'})}
              \Big(2 + \frac{n}{1 - n} \sum_k Q_k\Big), \qquad K(m) = \frac{\pi}{2M}.

    Parameters
    ----------
    n_hi, n_lo : float or ndarray, shape (...)
        Characteristic ``n < 1`` (entering as ``1 − n sin²θ``) as a double-double.
    mc_hi, mc_lo : float or ndarray, shape (...)
        Complementary parameter ``m' = 1 − m > 0`` as a double-double.

    Returns
    -------
    pi_hi, pi_lo, k_hi, k_lo : float or ndarray, shape (...)
        ``Π(n|m)`` and ``K(m)`` as double-doubles.

    Examples
    --------
    >>> p_hi, _, k_hi, _ = ellippi_k_dd(-0.5, 0.0, 0.5, 0.0)
    >>> float(p_hi), float(k_hi)
    (1.4878469926687984, 1.8540746773013719)
    """
    ah, al = 1.0, 0.0
    gh, gl = dd_sqrt(mc_hi, mc_lo)
    p2h, p2l = dd_add(1.0, 0.0, -n_hi, -n_lo)
    ph, pl = dd_sqrt(p2h, p2l)
    qh, ql = 1.0, 0.0
    sh, sl = 1.0, 0.0
    done = False  # an element that has converged keeps its values while the others go on
    for _ in range(_MAX_ITER):
        agh, agl = dd_mul(ah, al, gh, gl)
        numh, numl = dd_add(p2h, p2l, -agh, -agl)
        denh, denl = dd_add(p2h, p2l, agh, agl)
        eh, el = dd_div(numh, numl, denh, denl)
        nph, npl = dd_div(denh, denl, 2.0 * ph, 2.0 * pl)
        ph, pl = select(done, ph, nph), select(done, pl, npl)
        np2h, np2l = dd_mul(ph, pl, ph, pl)
        p2h, p2l = select(done, p2h, np2h), select(done, p2l, np2l)
        nqh, nql = dd_mul(qh, ql, 0.5 * eh, 0.5 * el)
        qh, ql = select(done, qh, nqh), select(done, ql, nql)
        nsh, nsl = dd_add(sh, sl, qh, ql)
        sh, sl = select(done, sh, nsh), select(done, sl, nsl)
        nah, nal = dd_add(ah, al, gh, gl)
        ngh, ngl = dd_sqrt(agh, agl)
        gh, gl = select(done, gh, ngh), select(done, gl, ngl)
        ah, al = select(done, ah, 0.5 * nah), select(done, al, 0.5 * nal)
        dh, _ = dd_add(ah, al, -gh, -gl)
        # εₖ = O(a − g) makes the rest of Σ Q below 2⁻¹⁰⁸ once Q is below 1e-17
        done = done | ((abs(qh) <= 1e-17 * abs(sh)) & (abs(dh) <= _CONVERGED * abs(ah)))
        if every(done):
            break
    ah, al = dd_add(ah, al, gh, gl)
    ah, al = 0.5 * ah, 0.5 * al
    # π/(4M) (2 + n/(1 − n) Σ Q) and K = π/(2M)
    oh, ol = dd_add(1.0, 0.0, -n_hi, -n_lo)
    rh, rl = dd_div(n_hi, n_lo, oh, ol)
    mh, ml = dd_mul(rh, rl, sh, sl)
    th, tl = dd_add(2.0, 0.0, mh, ml)
    kh, kl = dd_div(0.5 * PI_DD[0], 0.5 * PI_DD[1], ah, al)
    pih, pil = dd_mul(0.5 * kh, 0.5 * kl, th, tl)
    return pih, pil, kh, kl


def ellippi_dd(n_hi, n_lo, mc_hi, mc_lo=0.0):
    """Complete elliptic integral of the third kind ``Π(n|m)`` in double-double, ``n < 1``.

    The ``Π`` of :func:`ellippi_k_dd` (DLMF 19.8.6–8).

    Parameters
    ----------
    n_hi, n_lo : float or ndarray, shape (...)
        Characteristic ``n < 1`` (entering as ``1 − n sin²θ``) as a double-double.
    mc_hi, mc_lo : float or ndarray, shape (...)
        Complementary parameter ``m' = 1 − m > 0`` as a double-double.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        ``Π(n|m)`` as a double-double.

    Examples
    --------
    >>> hi, lo = ellippi_dd(-0.5, 0.0, 0.5)
    >>> float(hi)
    1.4878469926687984
    """
    pih, pil, _, _ = ellippi_k_dd(n_hi, n_lo, mc_hi, mc_lo)
    return pih, pil
