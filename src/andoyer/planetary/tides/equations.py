r"""The secular tidal equations of the Earth–Moon system, written once as compiled scalar kernels.

**The torque.** A perturber ``p`` (the Moon, the Sun) of mass ``m_p`` on a circular orbit of
radius ``a_p``, mean motion ``n_p`` and unit normal ``k`` raises a degree-2 tide on the Earth
(spin ``ω`` about the unit axis ``s``, obliquity ``ε = ∠(s, k)``). Written in the Earth's frame,
the tide-raising potential is a sum of waves ``(m, j)``, ``m`` the order about ``s`` and
``j ∈ {2, 0, −2}`` the multiple of the perturber's longitude, of frequency
``σ_{mj} = m ω − j n_p``; their squared amplitudes, relative to the ``(2, 2)`` wave of
zero obliquity, are ``w_{mj}(ε) = d²_{mj}(ε)²·(1 for j = ±2, 2/3 for j = 0)`` (Wigner's
``d²``; Kaula's inclination functions). Each wave, lagged by the Earth's response
``k₂(σ)``, gives a torque along ``s`` proportional to ``m`` and a torque on the orbit along
``k`` proportional to ``j`` (the generators of the two angles), both proportional to
``Q(m, σ) ≡ −Im k₂(σ)`` (odd in ``σ``). With ``P_p = (3/2) G m_p² R⁵/a_p⁶``:

.. math::
   T_s &= -P_p \sum_{m=1,2}\sum_{j} \tfrac{m}{2}\, w_{mj}(\varepsilon)\, Q(m, m\omega - j n_p),\\
   T_k &= -P_p \Big[\sum_{m=1,2}\sum_{j} \tfrac{j}{2}\, w_{mj}(\varepsilon)\, Q(m, m\omega - j n_p)
          - w_{02}(\varepsilon)\, Q(0, 2 n_p)\Big],

``T_s = T·s`` and ``T_k = T·k`` the components of the torque ``T`` on the Earth. For the
constant time lag, ``Q = k₂Δt·σ``, the sums close to Mignard's (1979) and Néron de Surgy &
Laskar's (1997) vector torque ``T = −K[(ω/2)(s + cos ε k) − n k]``, ``K = 3k₂Δt G m² R⁵/a⁶``
(tested to round-off).

**The evolution** (``L = C(ω) ω``, the Earth's spin angular momentum; the Moon's orbit
circular and in the ecliptic, its node averaged, so that both perturbers share the normal
``k`` of the ecliptic):

.. math::
   \frac{d(C\omega)}{dt} = T_s^{M} + T_s^{\odot},\qquad
   \dot\varepsilon = \frac{\cos\varepsilon\,(T_s^{M}+T_s^{\odot}) - (T_k^{M}+T_k^{\odot})}
                          {C\,\omega\,\sin\varepsilon},\qquad
   \frac{m_r n a}{2}\,\dot a = -T_k^{M},

``m_r = M_E M_M/(M_E+M_M)``, ``n = √(G(M_E+M_M)/a³)``, ``C(ω) = C₀ + c₂(ω² − ω₀²)``
(centrifugal; ``d(Cω)/dt = (C + 2c₂ω²) ω̇``). Without the Sun, ``C(ω) ω cos ε + m_r√(G(M_E+M_M) a)``
is conserved (the projection of the Earth–Moon angular momentum on the ecliptic pole; the
part across it goes into the lunar inclination, which the averaging over the node holds fixed).

**Units of the kernels.** State ``(x, w, ε) = (a/a₀, ω/ω₀, ε)``, time in Julian years; the
constants vector ``c`` (:data:`SIZE` numbers, built by
:func:`andoyer.planetary.tides.evolution.kernel_constants`) carries the system in SI.

Examples
--------
>>> import math
>>> c1, c2 = kaula_weights(math.cos(0.4), math.sin(0.4))[:2]  # order 1 and 2 at ε = 0.4 rad
>>> round(sum(c2), 6) == round((3 + 2 * math.cos(0.4) ** 2 + 3 * math.cos(0.4) ** 4) / 8, 6)
True
"""

from __future__ import annotations

from math import isfinite, sin, sqrt

from andoyer._jit import jit
from andoyer.catalogue.units import JULIAN_YEAR

__all__ = [
    "CONSTANT_LAG",
    "CONSTANT_Q",
    "OCEAN",
    "SIZE",
    "advance",
    "kaula_weights",
    "lag",
    "rates",
    "torques",
]

#: Response kinds (the first number of a response's kernel parameters).
CONSTANT_LAG, CONSTANT_Q, OCEAN = 0, 1, 2

# Places in the constants vector c.
A0, W0, MU, MRED, C0, CC, PMOON, PSUN, NSUN, KIND, P1, P2, P3, P4, LAPLACE = range(15)
#: Length of the constants vector.
SIZE = 15

_YEAR = JULIAN_YEAR


@jit
def kaula_weights(c, s):
    """``w_{mj}(ε)``, ``j = 2, 0, −2`` (orders 1, 2), and ``w_{0,±2}``, from ``c = cos ε``, ``s = sin ε``."""
    s2 = s * s
    p = (1.0 + c) * (1.0 + c)
    q = (1.0 - c) * (1.0 - c)
    return (
        (p * s2 / 4.0, s2 * c * c, q * s2 / 4.0),
        (p * p / 16.0, s2 * s2 / 4.0, q * q / 16.0),
        3.0 * s2 * s2 / 8.0,
    )


@jit
def lag(kind, order, sigma, p1, p2, p3, p4):
    """``Q(m, σ) = −Im k₂(σ)`` of the response ``kind`` at frequency ``sigma`` (rad/s), order ``m``.

    ``CONSTANT_LAG``: ``p1 σ`` (``p1 = k₂Δt``, s). ``CONSTANT_Q``: ``p1 sign σ`` (``p1 = k₂/Q``).
    ``OCEAN``: the solid part ``p1 sign σ`` plus, for the semidiurnal order ``m = 2``, the
    ocean's ``p2 σσ_R / ((p3 − σ²)² + σ²σ_R²)``, ``σ_R = p4`` (see
    :class:`andoyer.planetary.tides.OceanTides`).
    """
    if kind == CONSTANT_LAG:
        return p1 * sigma
    sign = 1.0 if sigma > 0.0 else (-1.0 if sigma < 0.0 else 0.0)
    q = p1 * sign
    if kind == OCEAN and order == 2:
        d = p3 - sigma * sigma
        e = sigma * p4
        q += p2 * e / (d * d + e * e)
    return q


@jit
def torques(kind, p1, p2, p3, p4, strength, n, w, eps):
    """``(T_s, T_k)`` on the Earth from one perturber: ``strength = P_p``, mean motion ``n``, spin ``w``."""
    c = 1.0 - 2.0 * sin(eps / 2.0) ** 2  # cos ε, accurate near ε = 0 as well
    s = sin(eps)
    first, second, zero = kaula_weights(c, s)
    ts = 0.0
    tk = 0.0
    for k in range(3):
        j = 2.0 - 2.0 * k
        q1 = lag(kind, 1, w - j * n, p1, p2, p3, p4)
        q2 = lag(kind, 2, 2.0 * w - j * n, p1, p2, p3, p4)
        ts += 0.5 * first[k] * q1 + second[k] * q2
        tk += 0.5 * j * (first[k] * q1 + second[k] * q2)
    tk -= zero * lag(kind, 0, 2.0 * n, p1, p2, p3, p4)
    return -strength * ts, -strength * tk


@jit
def rates(x, w, eps, c, solar):
    """``(dx/dt, dw/dt, dε/dt)`` per Julian year at ``x = a/a₀``, ``w = ω/ω₀``, ``ε``; ``solar``: 0 or 1."""
    a = x * c[A0]
    omega = w * c[W0]
    n = sqrt(c[MU] / (a * a * a))
    kind = int(c[KIND])
    ts, tk = torques(kind, c[P1], c[P2], c[P3], c[P4], c[PMOON] / a**6, n, omega, eps)
    adot = -2.0 * tk / (c[MRED] * n * a)
    if solar != 0:
        ts2, tk2 = torques(kind, c[P1], c[P2], c[P3], c[P4], c[PSUN], c[NSUN], omega, eps)
        ts += ts2
        tk += tk2
    moment = c[C0] + c[CC] * (omega * omega - c[W0] * c[W0])
    wdot = ts / (moment + 2.0 * c[CC] * omega * omega)
    s = sin(eps)
    edot = 0.0
    if s != 0.0:
        edot = ((1.0 - 2.0 * sin(eps / 2.0) ** 2) * ts - tk) / (moment * omega * s)
    return adot / c[A0] * _YEAR, wdot / c[W0] * _YEAR, edot * _YEAR


@jit
def _stages(x, w, e, h, c, solar):
    """One Dormand–Prince 5(4) step from ``(x, w, e)``: the 5th-order state and the error estimate."""
    k1 = rates(x, w, e, c, solar)
    k2 = rates(x + h * k1[0] / 5.0, w + h * k1[1] / 5.0, e + h * k1[2] / 5.0, c, solar)
    y3 = [0.0, 0.0, 0.0]
    y4 = [0.0, 0.0, 0.0]
    y5 = [0.0, 0.0, 0.0]
    y6 = [0.0, 0.0, 0.0]
    y = (x, w, e)
    for i in range(3):
        y3[i] = y[i] + h * (3.0 / 40.0 * k1[i] + 9.0 / 40.0 * k2[i])
    k3 = rates(y3[0], y3[1], y3[2], c, solar)
    for i in range(3):
        y4[i] = y[i] + h * (44.0 / 45.0 * k1[i] - 56.0 / 15.0 * k2[i] + 32.0 / 9.0 * k3[i])
    k4 = rates(y4[0], y4[1], y4[2], c, solar)
    for i in range(3):
        y5[i] = y[i] + h * (
            19372.0 / 6561.0 * k1[i]
            - 25360.0 / 2187.0 * k2[i]
            + 64448.0 / 6561.0 * k3[i]
            - 212.0 / 729.0 * k4[i]
        )
    k5 = rates(y5[0], y5[1], y5[2], c, solar)
    for i in range(3):
        y6[i] = y[i] + h * (
            9017.0 / 3168.0 * k1[i]
            - 355.0 / 33.0 * k2[i]
            + 46732.0 / 5247.0 * k3[i]
            + 49.0 / 176.0 * k4[i]
            - 5103.0 / 18656.0 * k5[i]
        )
    k6 = rates(y6[0], y6[1], y6[2], c, solar)
    new = [0.0, 0.0, 0.0]
    for i in range(3):
        new[i] = y[i] + h * (
            35.0 / 384.0 * k1[i]
            + 500.0 / 1113.0 * k3[i]
            + 125.0 / 192.0 * k4[i]
            - 2187.0 / 6784.0 * k5[i]
            + 11.0 / 84.0 * k6[i]
        )
    k7 = rates(new[0], new[1], new[2], c, solar)
    err = [0.0, 0.0, 0.0]
    for i in range(3):
        err[i] = h * (
            71.0 / 57600.0 * k1[i]
            - 71.0 / 16695.0 * k3[i]
            + 71.0 / 1920.0 * k4[i]
            - 17253.0 / 339200.0 * k5[i]
            + 22.0 / 525.0 * k6[i]
            - 1.0 / 40.0 * k7[i]
        )
    return new[0], new[1], new[2], err[0], err[1], err[2]


@jit
def _above_floor(x, w, c):
    """``a − r_L(ω)``, metres: the distance above the Laplace-plane transition (``r_L⁵ ∝ J₂ ∝ ω²``)."""
    return x * c[A0] - (c[LAPLACE] * w * w) ** 0.2


@jit
def advance(x, w, e, times, c, solar, rtol, out):
    """Integrate from ``t = 0`` through ``times`` (monotone away from 0) into ``out`` (N, 3).

    Dormand–Prince 5(4) with the error ``max_i |err_i|/(rtol (1 + |y_i|))`` held below 1; every
    step ends on an output time it would pass, so the outputs are step ends (no interpolation).
    Returns ``(count, status, t_stop)``: ``status`` 0 (done), 1 (the Moon fell below the
    Laplace-plane transition at ``t_stop``, interpolated), 2 (a non-finite state) or 3 (too many
    steps: a million beyond one per output time); ``count`` outputs are filled.
    """
    t = 0.0
    end = times[times.shape[0] - 1]
    direction = 1.0 if end > 0.0 else -1.0
    step = direction * min(abs(end), 1.0e6)  # the controller's step; a landing may shorten one
    k = 0
    g = _above_floor(x, w, c)
    # every output time ends a step of its own: the budget is a million steps beyond those
    for _ in range(1000000 + 2 * times.shape[0]):
        if k == times.shape[0]:
            return k, 0, t
        target = times[k]
        h = step
        landing = direction * (t + h - target) >= 0.0
        if landing:
            h = target - t
        nx, nw, ne, ex, ew, ee = _stages(x, w, e, h, c, solar)
        error = max(
            abs(ex) / (rtol * (1.0 + abs(x))),
            abs(ew) / (rtol * (1.0 + abs(w))),
            abs(ee) / (rtol * (1.0 + abs(e))),
        )
        if not (isfinite(nx) and isfinite(nw) and isfinite(ne) and isfinite(error)):
            if abs(h) < 1.0e-6:
                return k, 2, t
            step = 0.25 * h
            continue
        factor = 5.0 if error == 0.0 else min(5.0, max(0.2, 0.9 * error**-0.2))
        if error > 1.0:
            step = h * min(factor, 0.9)
            continue
        g_new = _above_floor(nx, nw, c)
        if g_new < 0.0:
            return k, 1, t + h * g / (g - g_new)
        t = target if landing else t + h
        x, w, e, g = nx, nw, ne, g_new
        if landing:
            out[k, 0] = x
            out[k, 1] = w
            out[k, 2] = e
            k += 1
            step = direction * max(abs(step), abs(h * factor))
        else:
            step = h * factor
    return k, 3, t
