r"""Scalar kernels of the Euler and Andoyer conversions: one state, Python floats, :mod:`math`.

Each kernel repeats, operation for operation, the vectorised numpy formulas of
:mod:`andoyer.charts.euler`, :mod:`andoyer.charts.andoyer` and :mod:`andoyer._quaternion`
(same products, same order of sums, the same ``atan2`` built from ``atan`` as
:func:`andoyer._fastmath.atan2_2pi`), so the three paths agree to the last bits that
numpy's and the C library's elementary functions allow (measured: within 2 ulp).

The same kernels serve two paths: called from Python they are the single-state fast
path (no array is built, no numba is imported), and :mod:`andoyer.charts._compiled`
compiles the loops at the end of this module, which apply them over arrays of states.
Both therefore give bit-identical results for the same state. The loops live here, not
in ``_compiled``, because numba's on-disk cache of a function is invalidated only by
changes to the file that defines it: a loop defined beside its kernels is recompiled
whenever they change.
"""

from __future__ import annotations

import math

from andoyer._quaternion import apply, product

__all__ = [
    "HELPERS",
    "LOOPS",
    "andoyer_to_hub_one",
    "atan2_2pi",
    "euler_to_hub_one",
    "from_zxz",
    "hub_to_andoyer_one",
    "hub_to_euler_one",
    "unit_quaternion",
    "wrap_2pi",
]

PI = math.pi
TWO_PI = 2.0 * math.pi
HALF_PI = 0.5 * math.pi
EPS = 2.220446049250313e-16  # np.finfo(float).eps
TINY = 2.2250738585072014e-308  # np.finfo(float).tiny

#: Status codes of :func:`euler_to_hub_one`.
REGULAR, SINGULAR, INFINITE_MOMENTUM = 0, 1, 2


def wrap_2pi(a: float) -> float:
    """``a`` reduced to ``[0, 2π)``, as :func:`andoyer._fastmath.wrap_2pi`."""
    r = a % TWO_PI
    return 0.0 if r >= TWO_PI else r


def atan2_2pi(y: float, x: float) -> float:
    """``atan2(y, x)`` in ``[0, 2π)`` from ``atan`` (as :func:`andoyer._fastmath.atan2_2pi`)."""
    ax, ay = abs(x), abs(y)
    # atan(min/max) (max = 0 read as 1), written as branches: fewer calls from Python.
    if ay > ax:
        a = HALF_PI - math.atan(ax / ay)
    elif ax == 0:
        a = 0.0
    else:
        a = math.atan(ay / ax)
    if x < 0:
        a = PI - a
    if y < 0:
        a = TWO_PI - a
    return 0.0 if a >= TWO_PI else a


def unit_quaternion(x: float, y: float, z: float, w: float) -> tuple[float, float, float, float]:
    """The quaternion divided by its norm, summed in numpy's order (``State`` normalises so)."""
    n = math.sqrt(((x * x + y * y) + z * z) + w * w)
    return x / n, y / n, z / n, w / n


def from_zxz(a: float, b: float, c: float) -> tuple[float, float, float, float]:
    """Quaternion of ``Rz(a) Rx(b) Rz(c)`` (:func:`andoyer._quaternion.from_zxz`)."""
    half_sum = 0.5 * (a + c)
    half_diff = 0.5 * (a - c)
    cb, sb = math.cos(0.5 * b), math.sin(0.5 * b)
    x, y = sb * math.cos(half_diff), sb * math.sin(half_diff)
    return x, y, cb * math.sin(half_sum), cb * math.cos(half_sum)


def hub_to_euler_one(
    x: float, y: float, z: float, w: float, m1: float, m2: float, m3: float
) -> tuple[float, float, float, float, float, float, bool]:
    """Euler angles and momenta of one state, and whether it sits on ``sin θ = 0``.

    :func:`andoyer.charts.euler.hub_to_euler` with the singular tolerance ``2ε`` of
    :func:`andoyer._quaternion.to_zxz`. Off the singularity ``φ`` and ``ψ``, the sum and
    difference of the half angles ``atan2(z, w)`` and ``atan2(y, x)``, come from one
    ``atan2`` each of the products ``(zx ± wy, wx ∓ zy) = ρ_xy ρ_zw (sin, cos)(φ or ψ)``
    (as well conditioned: the error is ``2ε`` absolute), and ``cos ψ``, ``sin ψ`` from the
    same pair divided by ``ρ_xy ρ_zw``, not from ``cos``/``sin`` of the rounded ``ψ``.
    """
    tol = 2.0 * EPS
    rho_xy = math.sqrt(x * x + y * y)
    rho_zw = math.sqrt(z * z + w * w)
    at_zero = rho_xy <= tol
    at_pi = rho_zw <= tol and not at_zero
    if at_zero or at_pi:
        # Only φ ± ψ is defined: ψ = 0 and φ carries twice the half angle that is.
        half = math.atan2(z, w) if at_zero else math.atan2(y, x)
        theta = 0.0 if at_zero else PI
        return wrap_2pi(half + half), theta, 0.0, m3 if at_zero else -m3, m1, m3, True
    theta = 2.0 * atan2_2pi(rho_xy, rho_zw)
    phi = atan2_2pi(z * x + w * y, w * x - z * y)
    s_psi, c_psi = z * x - w * y, w * x + z * y
    psi = atan2_2pi(s_psi, c_psi)
    r = rho_xy * rho_zw
    Phi = apply(x, y, z, w, m1, m2, m3)[2]  # third reference component of m
    return phi, theta, psi, Phi, (m1 * c_psi - m2 * s_psi) / r, m3, False


def euler_to_hub_one(
    phi: float, theta: float, psi: float, Phi: float, Theta: float, Psi: float
) -> tuple[float, float, float, float, float, float, float, int]:
    """Unit quaternion and body momentum of one Euler state (``0 <= θ <= π`` checked before).

    :func:`andoyer.charts.euler.euler_to_hub` followed by ``State``'s normalisation; the
    last entry is :data:`REGULAR`, :data:`SINGULAR` (``sin θ = 0``: ``X = 0``) or
    :data:`INFINITE_MOMENTUM` (``Φ ≠ ±Ψ`` there: the caller raises).
    """
    # transverse_momentum(Phi, Psi, theta)
    if math.cos(theta) >= 0:
        s2 = math.sin(0.5 * theta)
        numerator = (Phi - Psi) + 2.0 * Psi * s2 * s2
    else:
        c2 = math.cos(0.5 * theta)
        numerator = (Phi + Psi) - 2.0 * Psi * c2 * c2
    st = math.sin(theta)
    status = REGULAR
    X = 0.0
    if abs(st) <= 2.0 * EPS:
        status = SINGULAR
        scale = max(abs(Phi) + abs(Psi) + abs(Theta), TINY)
        if abs(numerator) > 8.0 * EPS * scale:
            status = INFINITE_MOMENTUM
    else:
        X = numerator / st
    cp, sp = math.cos(psi), math.sin(psi)
    qx, qy, qz, qw = unit_quaternion(*from_zxz(phi, theta, psi))
    return qx, qy, qz, qw, Theta * cp + X * sp, -Theta * sp + X * cp, Psi, status


def andoyer_to_hub_one(
    l: float, g: float, h: float, L: float, G: float, H: float
) -> tuple[float, float, float, float, float, float, float]:
    """Unit quaternion and body momentum of one Andoyer state (momenta checked before).

    :func:`andoyer.charts.andoyer.andoyer_to_hub` (``L``, ``H`` clipped to ``[-G, G]``)
    followed by ``State``'s normalisation.
    """
    L = min(max(L, -G), G)
    H = min(max(H, -G), G)
    GsI = math.sqrt((G - H) * (G + H))
    GsJ = math.sqrt((G - L) * (G + L))
    px, py, pz, pw = from_zxz(h, math.atan2(GsI, H), g)
    b = math.atan2(GsJ, L)
    cb, sb = math.cos(0.5 * b), math.sin(0.5 * b)
    cc, sc = math.cos(0.5 * l), math.sin(0.5 * l)
    rx, ry, rz, rw = sb * cc, -sb * sc, cb * sc, cb * cc
    qx, qy, qz, qw = unit_quaternion(*product(px, py, pz, pw, rx, ry, rz, rw))
    return qx, qy, qz, qw, GsJ * math.sin(l), GsJ * math.cos(l), L


def hub_to_andoyer_one(
    x: float, y: float, z: float, w: float, m1: float, m2: float, m3: float
) -> tuple[float, float, float, float, float, float, bool, bool]:
    """Andoyer variables of one state with ``G > 0``, and whether it sits on ``sin J = 0``, ``sin I = 0``.

    :func:`andoyer.charts.andoyer._hub_to_andoyer_kernel`, line for line.
    """
    G = math.sqrt(m1 * m1 + m2 * m2 + m3 * m3)
    xx, yy, zz = x * x, y * y, z * z
    xy, xz, yz, xw, yw, zw = x * y, x * z, y * z, x * w, y * w, z * w
    a00, a01, a02 = 1 - 2 * (yy + zz), 2 * (xy - zw), 2 * (xz + yw)
    a10, a11, a12 = 2 * (xy + zw), 1 - 2 * (xx + zz), 2 * (yz - xw)
    M1 = a00 * m1 + a01 * m2 + a02 * m3
    M2 = a10 * m1 + a11 * m2 + a12 * m3
    M3 = 2 * (xz - yw) * m1 + 2 * (yz + xw) * m2 + (1 - 2 * (xx + yy)) * m3
    rho_body = math.sqrt(m1 * m1 + m2 * m2)
    rho_ref = math.sqrt(M1 * M1 + M2 * M2)
    pole_tol = 4.0 * EPS * G
    on_pole_j = rho_body <= pole_tol
    on_pole_i = rho_ref <= pole_tol
    if on_pole_j:
        sl, cl = 0.0, 1.0
    else:
        sl, cl = m1 / rho_body, m2 / rho_body
    if on_pole_i:
        sh, ch = 0.0, 1.0
    else:
        sh, ch = M1 / rho_ref, -M2 / rho_ref
    i1, i2, i3 = ch * a00 + sh * a10, ch * a01 + sh * a11, ch * a02 + sh * a12
    sin_g = rho_body * i3 - m3 * (sl * i1 + cl * i2)
    cos_g = G * (i1 * cl - i2 * sl)
    return (
        atan2_2pi(sl, cl),
        atan2_2pi(sin_g, cos_g),
        atan2_2pi(sh, ch),
        math.copysign(G, m3) if on_pole_j else m3,
        G,
        math.copysign(G, M3) if on_pole_i else M3,
        on_pole_j,
        on_pole_i,
    )


# --------------------------------------------------------------------------------------
# Loops over arrays of states, compiled by andoyer.charts._compiled (plain Python here: the
# numpy path, not these, serves arrays where numba is missing).


def hub_to_euler_loop(q, m, out, singular):  # pragma: no cover - run compiled
    """Euler variables into ``out`` (6, n) and the singular mask (n,) of ``q`` (n, 4), ``m`` (n, 3)."""
    for i in range(q.shape[0]):
        r = hub_to_euler_one(q[i, 0], q[i, 1], q[i, 2], q[i, 3], m[i, 0], m[i, 1], m[i, 2])
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i] = r[0], r[1], r[2], r[3], r[4], r[5]
        singular[i] = r[6]


def euler_to_hub_loop(phi, theta, psi, Phi, Theta, Psi, q, m, status):  # pragma: no cover - run compiled
    """Unit quaternions into ``q`` (n, 4), momenta into ``m`` (n, 3), statuses (n,) of Euler arrays (n,)."""
    for i in range(phi.shape[0]):
        r = euler_to_hub_one(phi[i], theta[i], psi[i], Phi[i], Theta[i], Psi[i])
        q[i, 0], q[i, 1], q[i, 2], q[i, 3] = r[0], r[1], r[2], r[3]
        m[i, 0], m[i, 1], m[i, 2] = r[4], r[5], r[6]
        status[i] = r[7]


def hub_to_andoyer_loop(q, m, out, on_pole_j, on_pole_i):  # pragma: no cover - run compiled
    """Andoyer variables into ``out`` (6, n) and the pole masks; returns the count of zero momenta."""
    zero = 0
    for i in range(q.shape[0]):
        m1, m2, m3 = m[i, 0], m[i, 1], m[i, 2]
        if m1 * m1 + m2 * m2 + m3 * m3 <= 0:
            zero += 1
            continue
        r = hub_to_andoyer_one(q[i, 0], q[i, 1], q[i, 2], q[i, 3], m1, m2, m3)
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i] = r[0], r[1], r[2], r[3], r[4], r[5]
        on_pole_j[i] = r[6]
        on_pole_i[i] = r[7]
    return zero


def andoyer_to_hub_loop(l, g, h, L, G, H, q, m):  # pragma: no cover - run compiled
    """Unit quaternions into ``q`` (n, 4) and momenta into ``m`` (n, 3) of checked Andoyer arrays (n,)."""
    for i in range(l.shape[0]):
        r = andoyer_to_hub_one(l[i], g[i], h[i], L[i], G[i], H[i])
        q[i, 0], q[i, 1], q[i, 2], q[i, 3] = r[0], r[1], r[2], r[3]
        m[i, 0], m[i, 1], m[i, 2] = r[4], r[5], r[6]


#: Every function the loops call, which the compiled module registers with numba.
LOOPS = (hub_to_euler_loop, euler_to_hub_loop, hub_to_andoyer_loop, andoyer_to_hub_loop)
HELPERS = (
    product,
    apply,
    wrap_2pi,
    atan2_2pi,
    unit_quaternion,
    from_zxz,
    hub_to_euler_one,
    euler_to_hub_one,
    hub_to_andoyer_one,
    andoyer_to_hub_one,
)
