"""Per-epoch evaluation of the triaxial solution from theta series, on arrays (numpy driver).

The constants come from :func:`andoyer.free.triaxial.setup_numpy.triaxial`; the formulas are
derived in :mod:`andoyer.free.triaxial`.  Per epoch: the polhode phase (double-double,
:func:`andoyer.free.common.cycles_numpy.cycles`), ``sin`` and ``cos`` of it by polynomials,
Chebyshev multiples, a few theta-series terms (their number chosen per block from the largest
nome, dropping terms below 1e-18), and for the attitude one more phase, one more ``sincos`` and
two quaternion products.  The formulas are the kernels of :mod:`andoyer.free.triaxial.evaluate`
(and the anchored attitude of :mod:`andoyer.free.common.polhode`), applied here to whole arrays
and by :mod:`andoyer.free.triaxial.evaluate_compiled` to one state at a time.
"""

from __future__ import annotations

import numpy as np

from andoyer.free.common.cycles import sincos_cycles
from andoyer.free.common.cycles_numpy import cycles
from andoyer.free.common.polhode_numpy import anchored_attitude
from andoyer.free.triaxial import evaluate as kernels
from andoyer.special.compensated import split

__all__ = ["circular", "evaluate", "half_angle", "hyperbolic"]

_NEGLIGIBLE = 1e-18  # series terms below this (relative to O(1)) are dropped per block


def _terms(powers, qmax):
    """Number of leading terms ``q^{p}`` of a series that exceed ``_NEGLIGIBLE``."""
    return sum(1 for p in powers if p == 0 or qmax**p > _NEGLIGIBLE)


def _assemble(c, parts, scale):
    """``m_k = scale · Σⱼ mu_j[k] partⱼ`` in place (per-epoch temporaries cost page faults)."""
    out = []
    tmp = np.empty_like(parts[0])
    for k in range(3):
        mk = c.mu_cn[k] * parts[0]
        np.multiply(c.mu_sn[k], parts[1], out=tmp)
        mk += tmp
        np.multiply(c.mu_dn[k], parts[2], out=tmp)
        mk += tmp
        if scale is not None:
            mk *= scale
        out.append(mk)
    return tuple(out)


def circular(c, t, tt, attitude):
    """Momentum (and attitude ingredients) by the circular series, ``k² ≤ 1/2``.

    The theta quotients in ``x = 2πf`` hold over the whole period, so the polhode phase
    ``f ∈ [−1/2, 1/2)`` needs no further reduction.

    Parameters
    ----------
    c : andoyer.free.triaxial.setup_numpy.Triaxial
        Constants shaped ``(r, 1)`` (vectors ``(k, r, 1)``).
    t, tt : ndarray
        Times and their Dekker split.
    attitude : bool
        Also return ``sn, cn, dn`` and the ``ϑ₁`` series of the attitude.

    Returns
    -------
    m : tuple of 3 ndarray
    sncndn : tuple of 3 ndarray or None
    phase : tuple ``(f, x, y)`` or None
        Phase in cycles and the real and imaginary parts of the scaled ``ϑ₁``.

    Examples
    --------
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> from andoyer.free.common.constants import rows
    >>> from andoyer.free.triaxial.setup_numpy import triaxial
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.3, 0.2, 1.0]]),
    ...                    np.array([False]))
    >>> c = rows(triaxial(fr), [0])
    >>> m, _, _ = circular(c, np.zeros((1, 1)), split(np.zeros((1, 1))), False)
    >>> [round(float(v[0, 0]), 14) for v in m]
    [0.3, 0.2, 1.0]
    """
    f = cycles(c.nu, t, tt, c.frac0)
    s1, c1 = sincos_cycles(f)
    qmax = float(np.max(c.q))
    n_odd = _terms((0, 2, 6, 12), qmax)  # q^{n(n+1)}
    n_even = _terms((1, 4, 9, 16), qmax) if qmax > 0 else 0  # q^{n²}
    n_w = _terms((0, 2, 8), qmax) if attitude else 0  # coefficients of ϑ₁(·|q²)
    num_s, num_c, th3, inv, x, y = kernels.circular(s1, c1, c.q, c.wa, c.wb, n_odd, n_even, n_w)
    m = _assemble(c, (num_c, num_s, th3), inv)
    if not attitude:
        return m, None, None
    sn, cn, dn = c.c_sn * inv * num_s, c.c_cn * inv * num_c, c.c_dn * inv * th3
    return m, (sn, cn, dn), (f, x, y)


def hyperbolic(c, t, tt, attitude):
    """Momentum (and attitude ingredients) by the hyperbolic series, ``k² > 1/2``.

    The theta quotients of Jacobi's imaginary transformation converge on the half period
    ``|τ| ≤ K``: the phase is reduced by half periods, ``sn, cn`` changing sign.

    Parameters
    ----------
    c : andoyer.free.triaxial.setup_numpy.Triaxial
        Constants shaped ``(r, 1)`` (vectors ``(k, r, 1)``).
    t, tt : ndarray
        Times and their Dekker split.
    attitude : bool
        Also return ``sn, cn, dn`` and the ``ϑ₁`` series of the attitude.

    Returns
    -------
    m : tuple of 3 ndarray
    sncndn : tuple of 3 ndarray or None
    phase : tuple ``(f_w, x, y)`` or None
        Reduced phase in cycles and the parts of the scaled ``ϑ₁``.

    Examples
    --------
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> from andoyer.free.common.constants import rows
    >>> from andoyer.free.triaxial.setup_numpy import triaxial
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[1.0, 0.0, 2.0]]),
    ...                    np.array([False]))
    >>> c = rows(triaxial(fr), [0])
    >>> bool(c.circular[0, 0])
    False
    >>> m, _, _ = hyperbolic(c, np.zeros((1, 1)), split(np.zeros((1, 1))), False)
    >>> [round(float(v[0, 0]), 14) for v in m]
    [1.0, 0.0, 2.0]
    """
    f = cycles(c.nu, t, tt, c.frac0)
    q = c.q
    qmax = float(np.max(q))
    n_sh = _terms((0, 1, 4, 9, 16), qmax)  # q^{n²} zⁿ
    n_th = _terms((0, 0, 2, 6, 12), qmax)  # q^{n² − n} zⁿ
    sh, t4, t3, fw, zi = kernels.hyperbolic(f, q, c.kk, n_sh, n_th)
    m = _assemble(c, (t4, sh, t3), None)
    if not attitude:
        return m, None, None
    sn, cn, dn = c.c_sn * sh, c.c_cn * t4, c.c_dn * t3
    # ϑ₁(a + ib | q*) scaled by e^{−|b|}: Σ wₙ (ζⁿ ± ζ^{−n−1}), ζ = e^{2|b|} = 1/zi
    n_w = _terms((0, 2, 6, 12, 20, 30), float(np.max(np.sqrt(q))))
    zeta = 1.0 / zi
    up, down = 1.0, zi
    x = c.wa[0] * (1.0 + zi)
    y = c.wb[0] * (1.0 - zi)
    for n in range(1, n_w):
        up = up * zeta
        down = down * zi
        x = x + c.wa[n] * (up + down)
        y = y + c.wb[n] * (up - down)
    return m, (sn, cn, dn), (fw, x, np.where(fw < 0, -y, y))


def half_angle(c, t, tt, phase):
    """``(cos, sin)`` of ``Δψ/2`` (up to a common sign) from the kernels' phase output.

    ``Δψ/2 = π(f_ψ + ψ₀) + 2π slope·f + arg(x + iy)`` with ``f_ψ`` the secular phase of
    ``ψ`` in cycles; the ``arg`` enters through the normalised ``(x, y)``, so no ``atan2``.

    Parameters
    ----------
    c : andoyer.free.triaxial.setup_numpy.Triaxial
        Constants shaped ``(r, 1)``.
    t, tt : ndarray
        Times and their Dekker split.
    phase : tuple
        ``(f, x, y)`` from :func:`circular` or :func:`hyperbolic`.

    Returns
    -------
    cos, sin : ndarray

    Examples
    --------
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> from andoyer.free.common.constants import rows
    >>> from andoyer.free.triaxial.setup_numpy import triaxial
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.3, 0.2, 1.0]]),
    ...                    np.array([False]))
    >>> c = rows(triaxial(fr, np.array([[0.0, 0.0, 0.0, 1.0]])), [0])
    >>> t = np.zeros((1, 1))
    >>> _, _, phase = circular(c, t, split(t), True)
    >>> [round(float(v[0, 0]), 14) for v in half_angle(c, t, split(t), phase)]
    [1.0, 0.0]
    """
    f_lin, x, y = phase
    return kernels.half_angle(cycles(c.nu_psi, t, tt, c.psi0), c.slope, f_lin, x, y)


def evaluate(c, t, attitude=True):
    """Body angular momentum and attitude of triaxial states at times ``t``.

    Parameters
    ----------
    c : andoyer.free.triaxial.setup_numpy.Triaxial
        Constants, all of one series kind (all circular or all hyperbolic), with fields
        shaped to broadcast against ``t`` (vectors with a leading axis of 3 or 4).
    t : ndarray
        Times since the initial state.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray
        Body-frame angular momentum components.
    q : tuple of 4 ndarray or None
        Attitude quaternion components ``(x, y, z, w)``.

    Examples
    --------
    >>> from andoyer.free.common.polhode_numpy import polhode_frame
    >>> from andoyer.free.triaxial.setup_numpy import triaxial
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.3, 0.2, 1.0]]),
    ...                    np.array([False]))
    >>> m, _ = evaluate(triaxial(fr), np.zeros(1), attitude=False)
    >>> [round(float(v[0]), 14) for v in m]
    [0.3, 0.2, 1.0]
    """
    tt = split(t)
    kernel = circular if np.all(c.circular) else hyperbolic
    m, sncndn, phase = kernel(c, t, tt, attitude)
    if not attitude:
        return m, None
    sn, cn, dn = sncndn
    arc = ((c.v_sn, sn), (c.v_cn, cn))
    return m, anchored_attitude(c, half_angle(c, t, tt, phase), arc, c.a3 * dn)
