"""Seeded bodies and states covering every regime of torque-free motion.

Each case is ``(name, moments, m0, q0, t_unit)``: ``t_unit`` is the period of ``m(t)``
where it has one (computed here from the classical formula in mpmath, not by the code
under test) and a comparable time scale otherwise.  Moments are given in a random axis
order so that the working-frame relabelling is exercised.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
from scipy.spatial.transform import Rotation

# Earth: A/C and B/C as in the issue, C in kg m², one turn per sidereal day
EARTH_C = 8.034e37
EARTH_AB = (0.9967200, 0.9967222)
SIDEREAL_DAY = 86164.0905


def polhode_period(moments, m0):
    """``4K(k²)/ω`` (Landau–Lifshitz §37) at 50 digits; ``None`` without a finite period."""
    with mp.workdps(50):
        A, B, C = sorted(mp.mpf(float(x)) for x in moments)
        order = np.argsort(moments, kind="stable")
        m = [mp.mpf(float(m0[i])) for i in order]
        G2 = sum(x * x for x in m)
        D = m[0] ** 2 / A + m[1] ** 2 / B + m[2] ** 2 / C
        if B in (A, C) or D == G2 / B:
            return None
        if D < G2 / B:  # SAM
            k2 = (B - A) * (C * D - G2) / ((C - B) * (G2 - A * D))
            om2 = (C - B) * (G2 - A * D) / (A * B * C)
        else:  # LAM: A and C exchanged
            k2 = (C - B) * (G2 - A * D) / ((B - A) * (C * D - G2))
            om2 = (B - A) * (C * D - G2) / (A * B * C)
        return float(4 * mp.ellipk(k2) / mp.sqrt(om2))


def _state(rng, moments, regime, tries=10_000):
    """Random unit-free momentum in the requested regime (SAM or LAM) for these moments."""
    w = 1.0 / np.asarray(moments)
    mid = np.argsort(moments)[1]
    for _ in range(tries):
        m = rng.normal(size=3)
        D, G2 = np.sum(m * m * w), np.sum(m * m)
        if (G2 * w[mid] > D) == (regime == "SAM"):
            return m
    raise RuntimeError("no state found")


def with_k2(moments, k2, m1=1.0, m2=0.3):
    """State ``(m1, m2, m3)`` with modulus ``k²`` in SAM, sorted moments ``A < B < C``.

    ``k² = e₁₂P₁/(e₂₃P₃)`` with ``P₁ = m₁²e₁₃ + m₂²e₂₃`` and ``P₃ = m₂²e₁₂ + m₃²e₁₃``
    (Landau–Lifshitz §37), solved for ``m₃``; ``k² > 1`` gives a LAM state whose own
    modulus is ``1/k²``.
    """
    A, B, C = moments
    e12, e13, e23 = 1 / A - 1 / B, 1 / A - 1 / C, 1 / B - 1 / C
    P1 = m1**2 * e13 + m2**2 * e23
    m3 = np.sqrt((e12 * P1 / (e23 * k2) - m2**2 * e12) / e13)
    return np.array([m1, m2, m3])


def complementary_parameter(moments, m0):
    """``1 − k²`` of the state from the exact inputs (mpmath, 60 digits)."""
    with mp.workdps(60):
        A, B, C = sorted(mp.mpf(float(x)) for x in moments)
        m = [mp.mpf(float(m0[i])) for i in np.argsort(moments, kind="stable")]
        G2 = sum(x * x for x in m)
        D = m[0] ** 2 / A + m[1] ** 2 / B + m[2] ** 2 / C
        if D < G2 / B:
            return float((G2 / B - D) * (1 / A - 1 / C) / ((1 / B - 1 / C) * (G2 / A - D)))
        return float((D - G2 / B) * (1 / A - 1 / C) / ((1 / A - 1 / B) * (D - G2 / C)))


def cases():
    """The full list (26 states)."""
    rng = np.random.default_rng(20240613)
    out = []

    def add(name, moments, m0, t_unit=None):
        moments = np.asarray(moments, dtype=float)
        m0 = np.asarray(m0, dtype=float)
        perm = rng.permutation(3)
        moments, m0 = moments[perm], m0[perm]
        q0 = Rotation.random(random_state=rng.integers(2**31)).as_quat()
        if t_unit is None:
            t_unit = polhode_period(moments, m0)
        out.append((name, moments, m0, q0, t_unit))

    for regime in ("SAM", "LAM"):
        for k in range(6):
            inertia = rng.uniform(1.0, 2.0, 3)
            add(f"{regime.lower()}-{k}", inertia, _state(rng, inertia, regime))
    abc = np.array([1.0, 1.7, 2.3])
    add("near-separatrix-sam-1e-10", abc, with_k2(abc, 1 - 1e-10))
    add("near-separatrix-lam-1e-10", abc, with_k2(abc, 1 / (1 - 1e-10)))
    add("near-separatrix-sam-1e-6", abc, with_k2(abc, 1 - 1e-6))
    add("near-pure-spin", [1.2, 1.5, 2.0], [1e-6, -2e-6, 1.0])
    C = EARTH_C
    earth = [EARTH_AB[0] * C, EARTH_AB[1] * C, C]
    G = C * 2 * np.pi / SIDEREAL_DAY
    wobble = np.array([0.6 * np.sin(0.3), 0.8 * np.sin(0.3), np.cos(0.3)])
    add("earth-wobble-0.3", earth, G * wobble)
    add("earth-wobble-1e-6", earth, G * np.array([1e-6, 0.5e-6, 1.0]))
    add("sphere", [1.3, 1.3, 1.3], [0.2, -0.4, 0.7], t_unit=2 * np.pi * 1.3 / np.sqrt(0.69))
    add("oblate", [1.0, 1.0, 1.6], [0.5, 0.3, 0.9], t_unit=2 * np.pi / (0.9 * (1 - 1 / 1.6)))
    add("prolate", [0.8, 1.5, 1.5], [0.5, 0.3, 0.9], t_unit=2 * np.pi / (0.5 * (1 / 0.8 - 1 / 1.5)))
    # exactly on the separatrix: m3² (1/B − 1/C) = m1² (1/A − 1/B), here 1/A − 1/B =
    # 1/B − 1/C = 1/12 and m1 = m3; ω = 1/8, so 50 time units is 2π/ω
    add("separatrix", [3.0, 4.0, 6.0], [1.0, 0.5, 1.0], t_unit=50.0)
    # either side of k² = 1/2, where the theta series switch from circular to hyperbolic
    add("k2-below-half", abc, with_k2(abc, 0.5 - 1e-12))
    add("k2-above-half", abc, with_k2(abc, 0.5 + 1e-12))
    scale = rng.uniform(0.5, 2.0, 3)
    add("scaled-small-moments", 1e-6 * scale, 1e12 * _state(rng, scale, "SAM"))
    add("scaled-large-moments", 1e12 * scale[::-1], 1e-6 * _state(rng, scale[::-1], "LAM"))
    return out


FAST = ("sam-0", "lam-0", "near-separatrix-sam-1e-10", "earth-wobble-0.3", "scaled-small-moments")
