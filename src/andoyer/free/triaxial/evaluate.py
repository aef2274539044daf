r"""Scalar kernels of the theta series of the triaxial solution, written once.

Per epoch the triaxial solution needs ``sn, cn, dn`` of ``τ = 4K f`` (``f`` the polhode
phase in cycles) as theta quotients, and the scaled ``ϑ₁`` of the attitude.  With
``x = 2πf``, the nome ``q`` and the Chebyshev multiples of ``sin x``, ``cos x``, the
circular series (``k² ≤ 1/2``) are

.. math::
   \frac{ϑ_1}{…} ∝ \sum_n (−1)^n q^{n(n+1)} \sin(2n+1)x,\quad
   \frac{ϑ_2}{…} ∝ \sum_n q^{n(n+1)} \cos(2n+1)x,\quad
   ϑ_{3,4} = 1 + 2 \sum_n (±1)^n q^{n^2} \cos 2nx,

and the hyperbolic ones (``k² > 1/2``, Jacobi's imaginary transformation, ``q`` the complementary
nome, the phase reduced by half periods to ``|τ| ≤ K``) sums of ``q^{n²} zⁿ`` and ``q^{n²±n} ρⁿ``
with ``ρ = e^{−2y}``, ``z = q/ρ`` (:mod:`andoyer.free.triaxial.evaluate_numpy` derives both).  Each
formula is one function of arithmetic only (branches on the number of terms, a Python integer), so
the same text runs on floats in the compiled loops of :mod:`andoyer.free.triaxial.evaluate_compiled`
(registered with :func:`andoyer._jit.jitable`) and on whole arrays in
:mod:`andoyer.free.triaxial.evaluate_numpy`, with the same bits
(``tests/free/triaxial/test_free_triaxial_evaluate.py``).

The number of terms is a parameter: the compiled path takes them all (a per-state count
for the growing ``ϑ₁`` series), the numpy path the count of its block (terms below 1e-18
of the largest nome dropped).  A term left out is one below half an ulp of its sum.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable
from andoyer._quaternion import product
from andoyer.free.common.cycles import sincos_cycles

__all__ = ["circular", "half_angle", "hyperbolic"]

# the one Hamilton product, compiled inline into the kernels below
jitable(product)


@jitable
def circular(s1, c1, q, wa, wb, n_odd, n_even, n_w):
    r"""Numerators and ``ϑ₃``, ``1/ϑ₄`` of the circular series, and the ``ϑ₁`` of the attitude.

    ``sn ∝ num_s/ϑ₄``, ``cn ∝ num_c/ϑ₄``, ``dn ∝ ϑ₃/ϑ₄`` with
    ``num_s = Σ (−1)ⁿ q^{n(n+1)} sin(2n+1)x`` (``n < n_odd``),
    ``num_c = Σ q^{n(n+1)} cos(2n+1)x``,
    ``ϑ_{3,4} = 1 + 2 Σ_{1≤n≤n_even} (±1)ⁿ q^{n²} cos 2nx``;
    ``x_w = Σ_{n<n_w} wa_n sin(2n+1)x``, ``y_w = Σ wb_n cos(2n+1)x``.  The multiples come
    from the Chebyshev recurrence in ``2 cos 2x``.

    Parameters
    ----------
    s1, c1 : float or ndarray, shape (...)
        ``sin x``, ``cos x``.
    q : float or ndarray, shape (...)
        The nome, ``0 ≤ q ≤ e^{−π}``.
    wa, wb : indexable of 3 float or ndarray, shape (...)
        Coefficients of the ``ϑ₁`` series (read up to ``n_w``).
    n_odd, n_even, n_w : int
        Terms taken: ``1 ≤ n_odd ≤ 4``, ``0 ≤ n_even ≤ 4``, ``0 ≤ n_w ≤ 3`` (0: no ``ϑ₁``).

    Returns
    -------
    num_s, num_c, th3, inv, x_w, y_w : float or ndarray, shape (...)
        ``inv = 1/ϑ₄``; ``x_w = y_w = 0`` for ``n_w = 0``.

    Examples
    --------
    At ``x = 0`` and ``q = e^{−π}`` (``k² = 1/2``), ``ϑ₃/ϑ₄ = 1/√k' = 2^{1/4}``
    (DLMF 20.9.1, ``k' = ϑ₄²/ϑ₃²``):

    >>> num_s, num_c, th3, inv, _, _ = circular(0.0, 1.0, np.exp(-np.pi), (), (), 4, 4, 0)
    >>> round(float(th3 * inv), 15), float(num_s)
    (1.189207115002721, 0.0)
    """
    # Augmented assignments only to values made here: in place on arrays (each per-epoch
    # temporary costs page faults), plain arithmetic on floats; the inputs are never written.
    c2 = s1 * s1
    c2 *= -2.0
    c2 += 1.0
    tc2 = c2 + c2
    q2 = q * q
    q4 = q2 * q2
    q6 = q4 * q2
    q8 = q4 * q4
    # sin, cos((2n+1)x) by the Chebyshev recurrence in 2 cos 2x, as far as a series reads them
    n_mult = max(n_odd, n_w)
    s3, c3 = s1 * (tc2 + 1.0), c1 * (tc2 - 1.0)
    s5 = c5 = s7 = c7 = 0.0
    if n_mult > 2:
        s5, c5 = tc2 * s3, tc2 * c3
        s5 -= s1
        c5 -= c1
    if n_mult > 3:
        s7, c7 = tc2 * s5, tc2 * c5
        s7 -= s3
        c7 -= c3
    num_s, num_c = s1, c1
    if n_odd > 1:
        num_s, num_c = s1 - q2 * s3, c1 + q2 * c3
    if n_odd > 2:
        num_s += q6 * s5
        num_c += q6 * c5
    if n_odd > 3:
        num_s -= q6 * q6 * s7
        num_c += q6 * q6 * c7
    odd = even = 0.0
    c4 = c6 = 0.0
    if n_even > 0:
        odd = q * c2
    if n_even > 1:
        c4 = tc2 * c2
        c4 -= 1.0
        even = q4 * c4
    if n_even > 2:
        c6 = tc2 * c4
        c6 -= c2
        odd += q8 * q * c6
    if n_even > 3:
        c8 = tc2 * c6
        c8 -= c4
        even += q8 * q8 * c8
    inv = even - odd  # 1/ϑ₄ = 1/(1 + 2(even − odd))
    inv *= 2.0
    inv += 1.0
    inv = 1.0 / inv
    th3 = even + odd
    th3 *= 2.0
    th3 += 1.0
    x = y = 0.0
    if n_w > 0:
        x, y = wa[0] * s1, wb[0] * c1
    if n_w > 1:
        x += wa[1] * s3
        y += wb[1] * c3
    if n_w > 2:
        x += wa[2] * s5
        y += wb[2] * c5
    return num_s, num_c, th3, inv, x, y


@jitable
def hyperbolic(f, q, kk, n_sh, n_th):
    r"""``sn, cn, dn`` up to their constant factors by the hyperbolic series, and the reduced phase.

    ``f`` is reduced by half periods, ``f_w = f − j/2``, ``|f_w| ≤ 1/4`` (``sn, cn``
    change sign with ``j``); with ``e^{−y} = e^{−kk |f_w|}``, ``ρ = e^{−2y}``, ``z = q/ρ``:
    ``sh = Σ (−1)ⁿ (q^{n²+n} ρ^{n+1} − q^{n²} zⁿ)``, ``ch`` the sum of the same terms,
    ``t₄, t₃ = 1 + Σ (∓1)ⁿ (q^{n²−n} zⁿ + q^{n²} ρⁿ)`` (``n ≥ 1``), and the quotients
    ``sign(f_w) (−1)^j sh/ch``, ``(−1)^j t₄ e^{−y}/ch``, ``t₃ e^{−y}/ch``.

    Parameters
    ----------
    f : float or ndarray, shape (...)
        Polhode phase in cycles, ``|f| ≤ 1/2``.
    q, kk : float or ndarray, shape (...)
        The complementary nome (``q ≤ e^{−π}``) and ``2πK/K'`` (``y = kk |f_w|``).
    n_sh, n_th : int
        Terms taken (``n = 0`` included): ``1 ≤ n_sh ≤ 5``, ``1 ≤ n_th ≤ 5``.

    Returns
    -------
    sn, cn, dn : float or ndarray, shape (...)
        The quotients.
    fw, zi : float or ndarray, shape (...)
        The reduced phase and ``e^{−y}``.

    Examples
    --------
    Half a period on (``τ + 2K``), ``sn`` and ``cn`` change sign and ``dn`` does not
    (DLMF 22.4.3); here ``k² = 1/2`` (``K = K'``: ``q = e^{−π}``, ``kk = 2π``):

    >>> a = hyperbolic(0.125, np.exp(-np.pi), 2.0 * np.pi, 5, 5)
    >>> b = hyperbolic(-0.375, np.exp(-np.pi), 2.0 * np.pi, 5, 5)
    >>> [bool(u == v) for u, v in zip(a, (-b[0], -b[1], b[2], b[3], b[4]))]
    [True, True, True, True, True]
    """
    j = np.rint(2.0 * f)
    fw = f - 0.5 * j
    zi = np.exp(-kk * abs(fw))
    rho = zi * zi
    z = q / rho
    q2 = q * q
    q3 = q2 * q
    q4 = q2 * q2
    q6 = q3 * q3
    q12 = q6 * q6
    z2, r2 = z * z, rho * rho
    z3, r3 = z2 * z, r2 * rho
    r4 = r2 * r2
    # n-th terms: a = q^{n²} zⁿ, b = q^{n²+n} ρ^{n+1} (sh, ch); q^{n²−n} zⁿ + q^{n²} ρⁿ (t4, t3)
    sh, ch = 1.0 - rho, 1.0 + rho
    if n_sh > 1:
        a, b = q * z, q2 * r2
        sh, ch = sh + (b - a), ch + (a + b)
    if n_sh > 2:
        a, b = q4 * z2, q6 * r3
        sh, ch = sh + (a - b), ch + (a + b)
    if n_sh > 3:
        a, b = q6 * q3 * z3, q12 * r4
        sh, ch = sh + (b - a), ch + (a + b)
    if n_sh > 4:
        a, b = q12 * q4 * (z2 * z2), (q6 * q4) * (q6 * q4) * r4 * rho
        sh, ch = sh + (a - b), ch + (a + b)
    t4 = t3 = 1.0
    if n_th > 1:
        e = z + q * rho
        t4, t3 = t4 - e, t3 + e
    if n_th > 2:
        e = q2 * z2 + q4 * r2
        t4, t3 = t4 + e, t3 + e
    if n_th > 3:
        e = q6 * z3 + q6 * q3 * r3
        t4, t3 = t4 - e, t3 + e
    if n_th > 4:
        e = q12 * (z2 * z2) + q12 * q4 * r4
        t4, t3 = t4 + e, t3 + e
    inv = 1.0 / ch
    sgn = 1.0 - 2.0 * abs(j)  # (−1)^j for sn and cn
    sh = np.copysign(sh, fw) * (sgn * inv)
    return sh, t4 * (sgn * inv * zi), t3 * (inv * zi), fw, zi


@jitable
def half_angle(psi, slope, f_lin, x, y):
    r"""``(cos, sin)`` of ``Δψ/2 = 2π g + arg(x + iy)``, ``g = ψ_f/2 + slope·f`` reduced to ``[−1/2, 1/2]``.

    ``ψ_f`` is the secular phase of ``ψ`` in cycles (offset included, reduced), ``f`` the
    phase of the series (:func:`circular`: the polhode phase; :func:`hyperbolic`: the
    reduced ``f_w``) and ``(x, y)`` the scaled ``ϑ₁``: its argument enters through the
    normalised ``(x, y)``, so no ``atan2``.

    Parameters
    ----------
    psi, slope, f_lin : float or ndarray, shape (...)
        ``ψ_f``, the ``ϑ₁`` slope constant and ``f``.
    x, y : float or ndarray, shape (...)
        The real and imaginary parts of the scaled ``ϑ₁`` (not both zero).

    Returns
    -------
    cos, sin : float or ndarray, shape (...)

    Examples
    --------
    >>> [round(float(v), 15) for v in half_angle(0.5, 0.0, 0.0, 3.0, 4.0)]  # π/2 + arg(3 + 4i)
    [-0.8, 0.6]
    """
    g = 0.5 * psi + slope * f_lin
    g -= np.rint(g)
    sb, cb = sincos_cycles(g)
    inv = 1.0 / np.sqrt(x * x + y * y)
    xn, yn = x * inv, y * inv
    return cb * xn - sb * yn, cb * yn + sb * xn


