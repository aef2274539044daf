r"""Scalar elliptic kernels of the free rotation: Carlson's integrals, the amplitude, unwrapped ``Π``.

Plain Python on floats, compiled with numba through :func:`andoyer._jit.jit` when it is
installed, so that the one-step flow (:mod:`andoyer.free.step_scalar`) and the compiled set-up
(:mod:`andoyer.free.triaxial.setup_compiled`) call one definition of each formula. The amplitude
``am`` is :func:`andoyer.special.jacobi.amplitude` (the same kernel serves
:func:`andoyer.special.am` on arrays), registered here for the compiled kernels.
The vectorised numpy path uses scipy's ``elliprf``/``elliprj`` and the theta series of
:mod:`andoyer.special.theta` instead, which are accurate over many periods.
"""

from __future__ import annotations

import math

from andoyer._jit import jit, jitable, when_compiled
from andoyer.special.jacobi import amplitude

__all__ = ["am", "carlson_rf", "carlson_rj", "elliprf", "third_minus_a_unwrapped"]

#: The Jacobi amplitude ``am(u | m)`` given ``mc = 1 − m``: the one kernel
#: :func:`andoyer.special.jacobi.amplitude`, registered so that compiled kernels call it.
am = jitable(amplitude)


@jit
def carlson_rf(x, y, z):
    """Carlson's ``R_F(x, y, z)`` for ``x, y, z ≥ 0``, at most one zero (DLMF 19.36.1).

    Examples
    --------
    >>> from scipy.special import ellipk
    >>> bool(abs(carlson_rf(0.0, 0.5, 1.0) / ellipk(0.5) - 1.0) < 1e-15)
    True
    """
    a0 = (x + y + z) / 3.0
    x0, y0 = x, y
    q = max(abs(a0 - x), abs(a0 - y), abs(a0 - z)) * 424.0  # (3 r)^(-1/6), r = eps/4 (Carlson 1995)
    a = a0
    f = 1.0
    while f * q >= abs(a):
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * sy + sy * sz + sz * sx
        x, y, z, a = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (a + lam)
        f *= 0.25
    X = (a0 - x0) / a * f
    Y = (a0 - y0) / a * f
    Z = -(X + Y)
    e2 = X * Y - Z * Z
    e3 = X * Y * Z
    return (
        1.0
        - e2 / 10.0
        + e3 / 14.0
        + e2 * e2 / 24.0
        - 3.0 * e2 * e3 / 44.0
        - 5.0 * e2 * e2 * e2 / 208.0
        + 3.0 * e3 * e3 / 104.0
        + e2 * e2 * e3 / 16.0
    ) / math.sqrt(a)


@jit
def _rc_one(e):
    """``R_C(1, 1 + e)`` for ``e > −1``: ``atan(√e)/√e`` (``atanh`` for ``e < 0``)."""
    if e > 0.0:
        r = math.sqrt(e)
        return math.atan(r) / r
    if e < 0.0:
        r = math.sqrt(-e)
        return math.atanh(r) / r
    return 1.0


@jit
def carlson_rj(x, y, z, p):
    """Carlson's ``R_J(x, y, z, p)`` for ``x, y, z ≥ 0`` (one zero at most), ``p > 0`` (DLMF 19.36.2).

    Examples
    --------
    >>> from scipy.special import elliprj
    >>> bool(abs(carlson_rj(1.0, 2.0, 3.0, 4.0) / elliprj(1.0, 2.0, 3.0, 4.0) - 1.0) < 1e-15)
    True
    """
    a0 = (x + y + z + 2.0 * p) / 5.0
    delta = (p - x) * (p - y) * (p - z)
    x0, y0, z0 = x, y, z
    q = max(abs(a0 - x), abs(a0 - y), abs(a0 - z), abs(a0 - p)) * 644.0  # (r/4)^(-1/6)
    a = a0
    f = 1.0
    f3 = 1.0
    total = 0.0
    while f * q >= abs(a):
        sx, sy, sz, sp = math.sqrt(x), math.sqrt(y), math.sqrt(z), math.sqrt(p)
        lam = sx * sy + sy * sz + sz * sx
        d = (sp + sx) * (sp + sy) * (sp + sz)
        total += f * _rc_one(f3 * delta / (d * d)) / d
        x, y, z, p = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (p + lam)
        a = 0.25 * (a + lam)
        f *= 0.25
        f3 *= 1.0 / 64.0
    X = (a0 - x0) / a * f
    Y = (a0 - y0) / a * f
    Z = (a0 - z0) / a * f
    P = -0.5 * (X + Y + Z)
    e2 = X * Y + X * Z + Y * Z - 3.0 * P * P
    e3 = X * Y * Z + 2.0 * e2 * P + 4.0 * P * P * P
    e4 = (2.0 * X * Y * Z + e2 * P + 3.0 * P * P * P) * P
    e5 = X * Y * Z * P * P
    series = (
        1.0
        - 3.0 * e2 / 14.0
        + e3 / 6.0
        + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
    )
    return f * series / (a * math.sqrt(a)) + 6.0 * total


@jit
def third_minus_a_unwrapped(phi, m, mc, kap2, c3, pi_full, a_full):
    """Unwrapped ``Π(−κ²; φ | m) − c A(φ)`` (``pi_full``, ``a_full``: their values at ``π/2``)."""
    j = math.floor(phi / math.pi + 0.5)
    r = phi - j * math.pi
    s, c = math.sin(r), math.cos(r)
    dn2 = mc + m * c * c
    s3 = s * s * s
    pi_r = s * carlson_rf(c * c, dn2, 1.0) - kap2 / 3.0 * s3 * carlson_rj(c * c, dn2, 1.0, 1.0 + kap2 * s * s)
    root = math.sqrt(1.0 + kap2)
    a_r = math.atan2(root * s, c) / root
    return 2.0 * j * (pi_full - c3 * a_full) + pi_r - c3 * a_r


def elliprf(x, y, z):
    """Carlson's ``R_F(x, y, z)`` (DLMF 19.16.1) for kernels written once: scipy's on arrays, else ours.

    Inside a compiled kernel it is :func:`carlson_rf`; called from Python with an array it is
    :func:`scipy.special.elliprf` (vectorised, the same function to its last ulp or two).

    Parameters
    ----------
    x, y, z : float or ndarray, shape (...)
        Non-negative, at most one zero.

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> import numpy as np
    >>> round(float(elliprf(0.0, 1.0, 2.0)), 13)  # the lemniscate constant Γ(1/4)²/(4√(2π))
    1.3110287771461
    >>> elliprf(np.array([0.0]), 1.0, 2.0).round(13).tolist()
    [1.3110287771461]
    """
    import numpy as np

    if any(isinstance(a, np.ndarray) for a in (x, y, z)):
        from scipy.special import elliprf as rf

        return rf(x, y, z)
    return carlson_rf(x, y, z)


@when_compiled
def _compiled_elliprf(overload):
    @overload(elliprf)
    def _elliprf_compiled(x, y, z):  # noqa: ARG001 - numba's overload signature
        return lambda x, y, z: carlson_rf(x, y, z)  # noqa: PLW0108 - numba wants a Python implementation
