"""Scalar double-double arithmetic and complete elliptic integrals, compiled by numba.

The same error-free transformations and AGM schemes as
:mod:`andoyer.special.compensated` and :mod:`andoyer.special.agm`, written for one
float64 pair at a time so that :mod:`andoyer.free.compiled_setup` can build the
constants of a body in one compiled loop instead of a few hundred array passes.  Each
function returns ``(hi, lo)`` tuples; without numba they are plain Python on floats.

Examples
--------
>>> hi, lo = dd_div(1.0, 0.0, 3.0, 0.0)
>>> hi, lo
(0.3333333333333333, 1.850371707708594e-17)
"""

from __future__ import annotations

import math

from andoyer._jit import NUMBA, jit

__all__ = [
    "dd_add",
    "dd_div",
    "dd_mul",
    "dd_sqrt",
    "ellipk_dd",
    "ellippi_dd",
    "split",
    "two_prod",
    "two_sum",
]

_SPLITTER = 134217729.0  # 2**27 + 1
_PI_HI, _PI_LO = 3.141592653589793, 1.2246467991473532e-16
_MAX_ITER = 64


@jit
def two_sum(a, b):
    """Error-free sum ``a + b = s + e`` (Knuth).

    Examples
    --------
    >>> two_sum(1.0, 1e-17)
    (1.0, 1e-17)
    """
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@jit
def _fast_two_sum(a, b):
    s = a + b
    return s, b - (s - a)


@jit
def split(a):
    """Dekker split ``a = hi + lo`` into 26-bit halves.

    Examples
    --------
    >>> hi, lo = split(0.1)
    >>> hi + lo == 0.1
    True
    """
    c = _SPLITTER * a
    hi = c - (c - a)
    return hi, a - hi


def _dekker_two_prod(a, b):
    """Error-free product ``a b = p + e`` (Dekker).

    Examples
    --------
    >>> _dekker_two_prod(0.1, 0.1)[1]
    -8.326672684688674e-19
    """
    p = a * b
    ah, al = split(a)
    bh, bl = split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


if NUMBA:
    from llvmlite import ir
    from numba.core import cgutils, types
    from numba.core.extending import intrinsic

    @intrinsic
    def _fma(typingctx, a, b, c):  # noqa: ARG001 - numba's intrinsic signature
        """``a b + c`` rounded once (LLVM's ``llvm.fma``: the instruction, or libm's ``fma``)."""
        sig = types.float64(types.float64, types.float64, types.float64)

        def codegen(context, builder, signature, args):  # noqa: ARG001
            d = ir.DoubleType()
            fn = cgutils.get_or_insert_function(builder.module, ir.FunctionType(d, [d, d, d]), "llvm.fma.f64")
            return builder.call(fn, args)

        return sig, codegen

    @jit
    def two_prod(a, b):
        """Error-free product ``a b = p + e`` (a fused multiply-add; Dekker's without numba).

        Examples
        --------
        >>> two_prod(0.1, 0.1)[1]
        -8.326672684688674e-19
        """
        p = a * b
        return p, _fma(a, b, -p)

else:  # pragma: no cover - depends on the environment
    two_prod = _dekker_two_prod


@jit
def dd_add(ah, al, bh, bl):
    """Double-double sum.

    Examples
    --------
    >>> dd_add(1.0, 0.0, -1.0, 1e-30)
    (1e-30, 0.0)
    """
    s, e = two_sum(ah, bh)
    t, f = two_sum(al, bl)
    s, e = _fast_two_sum(s, e + t)
    return _fast_two_sum(s, e + f)


@jit
def dd_mul(ah, al, bh, bl):
    """Double-double product.

    Examples
    --------
    >>> dd_mul(0.1, 0.0, 10.0, 0.0)
    (1.0, 5.551115123125783e-17)
    """
    p, e = two_prod(ah, bh)
    return _fast_two_sum(p, e + (ah * bl + al * bh))


@jit
def dd_div(ah, al, bh, bl):
    """Double-double quotient: one correction of ``a_h/b_h`` (relative error below 2⁻¹⁰²).

    ``t = a_h/b_h``, the remainder ``a − t b`` formed with an error-free product, and
    ``t + (a − t b)/b_h`` (Joldes, Muller & Popescu 2017, *DWDivDW2*: at most ``15u²``).

    Examples
    --------
    >>> dd_div(1.0, 0.0, 3.0, 0.0)
    (0.3333333333333333, 1.850371707708594e-17)
    """
    th = ah / bh
    ph, pl = two_prod(th, bh)
    pl += th * bl
    r = ((ah - ph) - pl) + al  # a_h − p_h is exact (Sterbenz)
    return _fast_two_sum(th, r / bh)


@jit
def dd_sqrt(ah, al):
    """Double-double square root of a non-negative double-double (one Newton step).

    Examples
    --------
    >>> dd_sqrt(2.0, 0.0)
    (1.4142135623730951, -9.667293313452912e-17)
    """
    x = math.sqrt(ah)
    if x == 0.0:
        return 0.0, 0.0
    ph, pl = two_prod(x, x)
    r = ((ah - ph) - pl) + al  # the remainder a − x², a_h − p_h exact (Sterbenz)
    return _fast_two_sum(x, r / (2.0 * x))


@jit
def ellipk_dd(mc_hi, mc_lo):
    """``K(m) = π/(2 M(1, √m'))`` in double-double from ``m' = 1 − m > 0``.

    Examples
    --------
    >>> ellipk_dd(0.5, 0.0)[0]
    1.8540746773013719
    """
    gh, gl = dd_sqrt(mc_hi, mc_lo)
    if gh == 0.0:
        return math.inf, 0.0
    ah, al = 1.0, 0.0
    for _ in range(_MAX_ITER):
        sh, sl = dd_add(ah, al, gh, gl)
        ph, pl = dd_mul(ah, al, gh, gl)
        gh, gl = dd_sqrt(ph, pl)
        ah, al = 0.5 * sh, 0.5 * sl
        dh, _ = dd_add(ah, al, -gh, -gl)
        if abs(dh) <= 2.220446049250313e-16 * abs(ah):  # then (a + g)/2 is M to 2⁻¹⁰⁸
            break
    sh, sl = dd_add(ah, al, gh, gl)
    return dd_div(_PI_HI, _PI_LO, sh, sl)


@jit
def ellippi_dd(n_hi, n_lo, mc_hi, mc_lo):
    """``Π(n|m)`` for ``n < 1``, ``m' > 0`` by the AGM scheme of DLMF 19.8.6–8, and ``K(m)``.

    Returns the double-doubles ``(Π_hi, Π_lo, K_hi, K_lo)``: both come from the same AGM
    sequence of ``(1, √m')``, ``K = π/(2M)``, and the shared iteration is why they are
    computed together (see :func:`andoyer.special.agm.ellippi_dd`).

    Examples
    --------
    >>> p_hi, _, k_hi, _ = ellippi_dd(-0.5, 0.0, 0.5, 0.0)
    >>> p_hi, k_hi
    (1.4878469926687984, 1.8540746773013719)
    """
    ah, al = 1.0, 0.0
    gh, gl = dd_sqrt(mc_hi, mc_lo)
    p2h, p2l = dd_add(1.0, 0.0, -n_hi, -n_lo)
    ph, pl = dd_sqrt(p2h, p2l)
    qh, ql = 1.0, 0.0
    sh, sl = 1.0, 0.0
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
        # |a − g| ≤ 2⁻⁵² a: M = (a + g)/2 − (a − g)²/(16a) + …, the mean is M to 2⁻¹⁰⁸,
        # and εₖ = O(a − g) makes the rest of Σ Q below 2⁻¹⁰⁸ once Q is below 1e-17
        if abs(qh) <= 1e-17 * abs(sh) and abs(dh) <= 2.220446049250313e-16 * abs(ah):
            break
    ah, al = dd_add(ah, al, gh, gl)
    ah, al = 0.5 * ah, 0.5 * al
    # π/(4M) (2 + n/(1 − n) Σ Q) and K = π/(2M)
    oh, ol = dd_add(1.0, 0.0, -n_hi, -n_lo)
    rh, rl = dd_div(n_hi, n_lo, oh, ol)
    mh, ml = dd_mul(rh, rl, sh, sl)
    th, tl = dd_add(2.0, 0.0, mh, ml)
    kh, kl = dd_div(0.5 * _PI_HI, 0.5 * _PI_LO, ah, al)
    fh, fl = dd_mul(kh, kl, 0.5, 0.0)
    pih, pil = dd_mul(fh, fl, th, tl)
    return pih, pil, kh, kl
