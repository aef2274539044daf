r"""The Euler and Andoyer conversions, each written once: scalar kernels for floats, numba and numpy.

Each kernel is one state's formula in arithmetic, :mod:`math` functions, ``min``/``max``
and :func:`andoyer._jit.select` for every branch (no ``if``), so that the one written
formula serves three paths:

- on floats it is the single-state fast path (no array is built, no numba is imported),
  as the ``*_floats`` functions below: the same source with each ``select`` compiled as a
  conditional expression (:func:`andoyer._jit.on_floats`), which is what numba makes of it;
- :mod:`andoyer.state._compiled` compiles the loops at the end of this module, which apply
  it over arrays of states: the same bits as the single state;
- :func:`andoyer._jit.on_arrays` runs the same code on whole numpy arrays (numpy's
  functions in place of :mod:`math`'s, :func:`numpy.where` for ``select``): the ``*_arrays``
  functions below, the path of small arrays and of an environment without numba. numpy's
  elementary functions may differ from the C library's by an ulp, so that path agrees
  with the other two within 2 ulp.

The singular charts are decided inside the kernels and returned as flags (a status, or
pole masks); the chart modules turn them into :class:`~andoyer.SingularChartWarning` or
``ValueError``. Both operands of a ``select`` are evaluated, so each division by a
quantity that vanishes on a singular chart divides by a safe one chosen first. The loops
live here, not in ``_compiled``, because numba's on-disk cache of a function is
invalidated only by changes to the file that defines it: a loop defined beside its
kernels is recompiled whenever they change. (The angle and quaternion kernels it calls,
:func:`andoyer._fastmath.atan2_2pi_one`, :func:`andoyer._quaternion.from_zxz_one` and
``from_xz_one``, live with their array forms: after editing one of them, touch this file
or clear the ``*.nbi``/``*.nbc`` cache.)
"""

from __future__ import annotations

from math import atan2, copysign, cos, sin, sqrt

from andoyer._fastmath import atan2_2pi_one as atan2_2pi
from andoyer._jit import on_arrays, on_floats, select
from andoyer._quaternion import apply, product
from andoyer._quaternion import from_xz_one as from_xz
from andoyer._quaternion import from_zxz_one as from_zxz

__all__ = [
    "HELPERS",
    "LOOPS",
    "andoyer_to_hub_arrays",
    "andoyer_to_hub_floats",
    "andoyer_to_hub_one",
    "euler_to_hub_arrays",
    "euler_to_hub_floats",
    "euler_to_hub_one",
    "hub_to_andoyer_arrays",
    "hub_to_andoyer_floats",
    "hub_to_andoyer_one",
    "hub_to_euler_arrays",
    "hub_to_euler_floats",
    "hub_to_euler_one",
    "transverse_momentum_arrays",
    "transverse_momentum_one",
    "unit_quaternion",
]

PI = 3.141592653589793
EPS = 2.220446049250313e-16  # np.finfo(float).eps
TINY = 2.2250738585072014e-308  # np.finfo(float).tiny

#: Status codes of :func:`euler_to_hub_one`.
REGULAR, SINGULAR, INFINITE_MOMENTUM = 0, 1, 2


def unit_quaternion(x: float, y: float, z: float, w: float) -> tuple[float, float, float, float]:
    """The quaternion divided by its norm ``sqrt(((x² + y²) + z²) + w²)``."""
    n = sqrt(((x * x + y * y) + z * z) + w * w)
    return x / n, y / n, z / n, w / n


def transverse_momentum_one(big: float, small: float, theta: float) -> tuple[float, float]:
    """``(big - small cos θ)`` and ``sin θ`` without cancellation near ``sin θ = 0``.

    Near ``θ = 0`` the physical state has ``big ≈ small`` and the difference is
    ``(big - small) + 2 small sin²(θ/2)``; near ``θ = π`` it is
    ``(big + small) - 2 small cos²(θ/2)``. Both forms are exact rearrangements.
    """
    s2, c2 = sin(0.5 * theta), cos(0.5 * theta)
    numerator = select(
        cos(theta) >= 0, (big - small) + 2.0 * small * s2 * s2, (big + small) - 2.0 * small * c2 * c2
    )
    return numerator, sin(theta)


def hub_to_euler_one(
    x: float, y: float, z: float, w: float, m1: float, m2: float, m3: float
) -> tuple[float, float, float, float, float, float, bool]:
    """Euler angles and momenta of one state, and whether it sits on ``sin θ = 0``.

    Attitudes with ``sin(θ/2)`` or ``cos(θ/2)`` (the norms ``ρ_xy``, ``ρ_zw`` of the
    quaternion's pairs) at most ``2ε`` are snapped onto ``θ = 0`` or ``π``, where only
    ``φ ± ψ`` is defined: ``ψ = 0``, ``φ`` carries twice the half angle that is (``φ + ψ``
    at ``θ = 0``, ``φ - ψ`` at ``θ = π``), and ``Φ = ±Ψ``, ``Θ = m1``. Elsewhere ``φ`` and
    ``ψ``, the sum and difference of the half angles ``atan2(z, w)`` and ``atan2(y, x)``,
    come from one ``atan2`` each of the products ``(zx ± wy, wx ∓ zy) = ρ_xy ρ_zw (sin,
    cos)(φ or ψ)`` (as well conditioned: the error is ``2ε`` absolute), and ``cos ψ``,
    ``sin ψ`` from the same pair divided by ``ρ_xy ρ_zw``, not from ``cos``/``sin`` of the
    rounded ``ψ``.
    """
    tol = 2.0 * EPS
    rho_xy = sqrt(x * x + y * y)
    rho_zw = sqrt(z * z + w * w)
    at_zero = rho_xy <= tol
    at_pi = (rho_zw <= tol) & (rho_xy > tol)
    singular = at_zero | at_pi
    s_psi, c_psi = z * x - w * y, w * x + z * y
    Phi = apply(x, y, z, w, m1, m2, m3)[2]  # third reference component of m
    r = select(singular, 1.0, rho_xy * rho_zw)
    # On the singularity φ is twice the half angle atan2(z, w) (θ = 0) or atan2(y, x) (θ = π):
    # atan2(2 z w, w² - z²) or atan2(2 x y, x² - y²) (error 2ε absolute, the norm being 1 - 2ε²),
    # which lets one atan2 serve both cases (compiled, both operands of a select are evaluated).
    sy = select(singular, select(at_zero, 2.0 * z * w, 2.0 * x * y), z * x + w * y)
    sx = select(singular, select(at_zero, w * w - z * z, x * x - y * y), w * x - z * y)
    return (
        atan2_2pi(sy, sx),
        select(singular, select(at_zero, 0.0, PI), 2.0 * atan2_2pi(rho_xy, rho_zw)),
        select(singular, 0.0, atan2_2pi(s_psi, c_psi)),
        select(singular, select(at_zero, m3, -m3), Phi),
        select(singular, m1, (m1 * c_psi - m2 * s_psi) / r),
        m3,
        singular,
    )


def euler_to_hub_one(
    phi: float, theta: float, psi: float, Phi: float, Theta: float, Psi: float
) -> tuple[float, float, float, float, float, float, float, int]:
    """Unit quaternion and body momentum of one Euler state (``0 <= θ <= π`` checked before).

    ``m = (Θ cos ψ + X sin ψ, -Θ sin ψ + X cos ψ, Ψ)`` with ``X = (Φ - Ψ cos θ)/sin θ``
    (:func:`transverse_momentum_one`); the last entry is :data:`REGULAR`, :data:`SINGULAR`
    (``|sin θ| <= 2ε``: ``X = 0``) or :data:`INFINITE_MOMENTUM` (``Φ ≠ ±Ψ`` there, beyond
    ``8ε (|Φ| + |Ψ| + |Θ|)``: the caller raises).
    """
    numerator, st = transverse_momentum_one(Phi, Psi, theta)
    # sin(π) evaluates to 1.2e-16, not 0: |sin θ| <= 2ε is the singularity itself.
    singular = abs(st) <= 2.0 * EPS
    X = select(singular, 0.0, numerator / select(singular, 1.0, st))
    cp, sp = cos(psi), sin(psi)
    qx, qy, qz, qw = unit_quaternion(*from_zxz(phi, theta, psi))
    scale = max(abs(Phi) + abs(Psi) + abs(Theta), TINY)
    infinite = abs(numerator) > 8.0 * EPS * scale
    status = select(singular, select(infinite, INFINITE_MOMENTUM, SINGULAR), REGULAR)
    return qx, qy, qz, qw, Theta * cp + X * sp, -Theta * sp + X * cp, Psi, status


def andoyer_to_hub_one(
    l: float, g: float, h: float, L: float, G: float, H: float
) -> tuple[float, float, float, float, float, float, float]:
    """Unit quaternion and body momentum of one Andoyer state (momenta checked before).

    ``L`` and ``H`` are clipped to ``[-G, G]``; the attitude is
    ``Rz(h) Rx(I) Rz(g) · Rx(J) Rz(l)`` with ``I = atan2(√((G-H)(G+H)), H)``,
    ``J = atan2(√((G-L)(G+L)), L)``, and ``m = (√(G²-L²) sin l, √(G²-L²) cos l, L)``.
    """
    L = min(max(L, -G), G)
    H = min(max(H, -G), G)
    GsI = sqrt((G - H) * (G + H))
    GsJ = sqrt((G - L) * (G + L))
    px, py, pz, pw = from_zxz(h, atan2(GsI, H), g)
    rx, ry, rz, rw = from_xz(atan2(GsJ, L), l)
    qx, qy, qz, qw = unit_quaternion(*product(px, py, pz, pw, rx, ry, rz, rw))
    return qx, qy, qz, qw, GsJ * sin(l), GsJ * cos(l), L


def hub_to_andoyer_one(
    x: float, y: float, z: float, w: float, m1: float, m2: float, m3: float
) -> tuple[float, float, float, float, float, float, bool, bool]:
    """Andoyer variables of one state with ``G > 0``, and whether it sits on ``sin J = 0``, ``sin I = 0``.

    ``l = atan2(m1, m2)``, ``h = atan2(M1, -M2)`` (``M`` the reference components) and
    ``g`` the angle, about ``m``, from the node ``i = (cos h, sin h, 0)`` (reference frame)
    to the node ``j = (cos l, -sin l, 0)`` (body frame), built from the same ``h`` and
    ``l`` that are returned, which keeps the attitude round trip exact even where they are
    ill-conditioned. Within ``4ε G`` of a pole (``|m1, m2|`` or ``|M1, M2|``) the state is
    snapped onto it: ``l = 0`` and ``L = ±G``, or ``h = 0`` and ``H = ±G``.
    """
    G = sqrt(m1 * m1 + m2 * m2 + m3 * m3)
    # Rotation matrix A of the quaternion (body -> reference); only products are needed.
    xx, yy, zz = x * x, y * y, z * z
    xy, xz, yz, xw, yw, zw = x * y, x * z, y * z, x * w, y * w, z * w
    a00, a01, a02 = 1 - 2 * (yy + zz), 2 * (xy - zw), 2 * (xz + yw)
    a10, a11, a12 = 2 * (xy + zw), 1 - 2 * (xx + zz), 2 * (yz - xw)
    M1 = a00 * m1 + a01 * m2 + a02 * m3
    M2 = a10 * m1 + a11 * m2 + a12 * m3
    M3 = 2 * (xz - yw) * m1 + 2 * (yz + xw) * m2 + (1 - 2 * (xx + yy)) * m3
    rho_body = sqrt(m1 * m1 + m2 * m2)
    rho_ref = sqrt(M1 * M1 + M2 * M2)
    # Within a few ulp of a pole the direction of the node is round-off; snapping onto the
    # pole (L or H = ±G exactly) keeps the round trip exact where (L, G, H) could not.
    pole_tol = 4.0 * EPS * G
    on_pole_j = rho_body <= pole_tol
    on_pole_i = rho_ref <= pole_tol
    safe_body = select(on_pole_j, 1.0, rho_body)
    safe_ref = select(on_pole_i, 1.0, rho_ref)
    sl = select(on_pole_j, 0.0, m1 / safe_body)
    cl = select(on_pole_j, 1.0, m2 / safe_body)
    sh = select(on_pole_i, 0.0, M1 / safe_ref)
    ch = select(on_pole_i, 1.0, -M2 / safe_ref)
    # Node i seen in the body frame is Aᵀ i; g: sin g ∝ m·(i × j), cos g ∝ G i·j, with
    # m·(i × j) = i·(j × m) and j × m = (-sin l m3, -cos l m3, rho_body).
    i1, i2, i3 = ch * a00 + sh * a10, ch * a01 + sh * a11, ch * a02 + sh * a12
    sin_g = rho_body * i3 - m3 * (sl * i1 + cl * i2)
    cos_g = G * (i1 * cl - i2 * sl)
    return (
        atan2_2pi(sl, cl),
        atan2_2pi(sin_g, cos_g),
        atan2_2pi(sh, ch),
        select(on_pole_j, copysign(G, m3), m3),
        G,
        select(on_pole_i, copysign(G, M3), M3),
        on_pole_j,
        on_pole_i,
    )


#: The kernels as the single-state fast path: each ``select`` a conditional expression
#: (``andoyer._jit.on_floats``), the bits of the compiled loops.
(
    hub_to_euler_floats,
    euler_to_hub_floats,
    andoyer_to_hub_floats,
    hub_to_andoyer_floats,
) = on_floats(
    atan2_2pi,
    unit_quaternion,
    from_zxz,
    from_xz,
    transverse_momentum_one,
    hub_to_euler_one,
    euler_to_hub_one,
    andoyer_to_hub_one,
    hub_to_andoyer_one,
)[-4:]

#: The kernels on whole numpy arrays (1-D slices of equal length; ``andoyer._jit.on_arrays``).
(
    transverse_momentum_arrays,
    hub_to_euler_arrays,
    euler_to_hub_arrays,
    andoyer_to_hub_arrays,
    hub_to_andoyer_arrays,
) = on_arrays(
    unit_quaternion,
    transverse_momentum_one,
    hub_to_euler_one,
    euler_to_hub_one,
    andoyer_to_hub_one,
    hub_to_andoyer_one,
)[-5:]


# --------------------------------------------------------------------------------------
# Loops over arrays of states, compiled by andoyer.state._compiled (plain Python here: the
# *_arrays functions, not these, serve arrays where numba is missing).


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
    atan2_2pi,
    unit_quaternion,
    from_zxz,
    from_xz,
    transverse_momentum_one,
    hub_to_euler_one,
    euler_to_hub_one,
    hub_to_andoyer_one,
    andoyer_to_hub_one,
)
