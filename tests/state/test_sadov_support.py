"""Shared material for the Sadov tests: bodies, regime samplers, an independent action quadrature.

Nothing here calls the code under test: states are sampled from the Andoyer Hamiltonian
itself (energy first, then the momentum ``L`` that has that energy), and the reference
action is an mpmath quadrature of ``(1/2π)∮ L dl`` along the level set.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from andoyer import RigidBody

#: Bodies covering every supported labelling: b3 of largest or smallest moment, and the
#: intermediate axis along b2 or b1; near-axisymmetric, strongly triaxial, and I_i = I3.
BODIES = {
    "b3-max": RigidBody(1.0, 2.0, 2.5),
    "b3-max-b1-intermediate": RigidBody(2.0, 1.0, 2.5),
    "b3-min": RigidBody(3.0, 2.0, 1.2),
    "b3-min-b1-intermediate": RigidBody(2.0, 3.0, 1.0),
    "earth": RigidBody.from_ratios(0.9967200, 0.9967222, name="Earth"),
    "strongly-triaxial": RigidBody.from_ratios(0.229427, 0.963754),
    "b1-symmetric": RigidBody(1.0, 2.0, 2.0),
}
#: (moment scale, momentum scale)
SCALES = [(1.0, 1.0), (1e-6, 1e-6), (1e12, 1e-6), (1e-6, 1e12), (1e12, 1e12)]
REGIMES = ["circulation", "libration", "near-separatrix"]


def scaled(body: RigidBody, factor: float) -> RigidBody:
    return RigidBody(body.I1 * factor, body.I2 * factor, body.I3 * factor)


def inverse_moments(body: RigidBody) -> tuple[float, float, float, float, float]:
    """``a1, a2, a3`` and the inverse moments of the intermediate (``a_i``) and other in-plane axis."""
    a1, a2, a3 = (1.0 / body.I1, 1.0 / body.I2, 1.0 / body.I3)
    a_i = 1.0 / body.B
    a_e = a2 if body.I1 == body.B else a1
    return a1, a2, a3, a_i, a_e


def has_regime(body: RigidBody, regime: str) -> bool:
    _, _, a3, a_i, a_e = inverse_moments(body)
    return a_e != a_i if regime == "libration" else a_i != a3


#: (body name, regime) pairs that exist.
CASES = [(name, regime) for name in BODIES for regime in REGIMES if has_regime(BODIES[name], regime)]
#: A subset for the expensive checks of the default run (every labelling, both regions);
#: the slow run covers every case.
REPRESENTATIVE = [
    ("b3-max", "circulation"),
    ("b3-max-b1-intermediate", "libration"),
    ("b3-min", "libration"),
    ("b3-min-b1-intermediate", "circulation"),
    ("earth", "circulation"),
    ("earth", "libration"),
    ("strongly-triaxial", "circulation"),
    ("b1-symmetric", "libration"),
]


def sample(body: RigidBody, rng: np.random.Generator, n: int, regime: str, G: float = 1.0):
    """Andoyer states ``(l, g, h, L, G, H)`` of one regime, drawn from the Hamiltonian.

    The normalised energy is drawn first: circulation ``(e − a3)/(a_i − a3) ∈ [0.05, 0.95]``,
    libration ``(e − a_i)/(a_e − a_i) ∈ [0.05, 0.95]``, near the separatrix the same
    fractions in ``[1e-6, 1e-3]`` on either side; then ``l`` uniform among the
    angles that reach that energy, ``L = ±G x`` with ``x² = (p(l) − e)/(p(l) − a3)``.
    """
    a1, a2, a3, a_i, a_e = inverse_moments(body)
    if regime == "circulation":
        e = a3 + (a_i - a3) * rng.uniform(0.05, 0.95, n)
    elif regime == "libration":
        e = a_i + (a_e - a_i) * rng.uniform(0.05, 0.95, n)
    else:
        fraction = 10.0 ** rng.uniform(-6, -3, n)
        e = a_i + fraction * np.where(rng.uniform(size=n) < 0.5, a3 - a_i, a_e - a_i)
    l = np.empty(n)
    todo = np.ones(n, bool)
    while todo.any():
        trial = rng.uniform(0, 2 * np.pi, todo.sum())
        p = np.sin(trial) ** 2 * a1 + np.cos(trial) ** 2 * a2
        ok = (p - e[todo]) * (p - a3) > 0
        idx = np.flatnonzero(todo)[ok]
        l[idx] = trial[ok]
        todo[idx] = False
    p = np.sin(l) ** 2 * a1 + np.cos(l) ** 2 * a2
    x = np.sqrt((p - e) / (p - a3)) * rng.choice([-1.0, 1.0], n)
    g, h = rng.uniform(0, 2 * np.pi, (2, n))
    return l, g, h, G * x, np.full(n, G), G * rng.uniform(-1, 1, n)


def reference_action(
    body: RigidBody, l: float, L: float, G: float, dps: int = 30, separatrix: bool = False
) -> float:
    """``(1/2π)∮ L dl`` over the orbit of ``(l, L, G)`` by mpmath quadrature, with the sign convention.

    Circulation: ``(1/2π)∫₀^{2π} L dl`` along the level set (sign of ``L``). Libration:
    the enclosed area over ``2π``, signed by the component of the momentum along the axis
    the orbit encircles (``m1 = √(G² − L²) sin l`` for lobes at ``l = ±π/2``, ``m2`` for
    lobes at ``l = 0, π``). ``separatrix=True`` takes the energy ``1/I_i`` exactly instead
    of the state's (rounded) energy.
    """
    with mp.workdps(dps):
        a1, a2, a3 = (1 / mp.mpf(body.I1), 1 / mp.mpf(body.I2), 1 / mp.mpf(body.I3))
        l, L, G = mp.mpf(l), mp.mpf(L), mp.mpf(G)

        def p(t):
            return mp.sin(t) ** 2 * a1 + mp.cos(t) ** 2 * a2

        e = (p(l) * (G - L) * (G + L) + a3 * L * L) / (G * G)
        if separatrix:
            e = 1 / mp.mpf(body.B)

        def absL(t):
            return G * mp.sqrt(max((p(t) - e) / (p(t) - a3), 0))

        s2 = (e - a2) / (a1 - a2) if a1 != a2 else mp.mpf(-1)
        if not 0 < s2 < 1:
            quarter = [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]
            return float(mp.sign(L) * mp.quad(absL, quarter) / (2 * mp.pi))
        t1 = mp.asin(mp.sqrt(s2))
        lobes_at_half_pi = (p(mp.pi / 2) - e) * (p(mp.pi / 2) - a3) > 0
        if lobes_at_half_pi:
            centre = mp.pi / 2 if mp.sin(l) > 0 else 3 * mp.pi / 2
            half, sign = mp.pi / 2 - t1, mp.sign(mp.sin(l))
        else:
            centre = 0 if mp.cos(l) > 0 else mp.pi
            half, sign = t1, mp.sign(mp.cos(l))
        area = 2 * mp.quad(absL, [centre - half, centre, centre + half])
        return float(sign * area / (2 * mp.pi))


def reference_frequencies(
    body: RigidBody, l: float, L: float, G: float, dps: int = 30
) -> tuple[float, float]:
    """``(|ω_ℓ|, ω_g)`` as time averages along the orbit, by mpmath quadrature.

    ``T = ∮ dl / l̇`` with ``l̇ = ∂K/∂L = L (a3 − p(l))``, ``|ω_ℓ| = 2π/T``, and
    ``ω_g = ⟨ġ⟩ = (1/T) ∮ G p(l) dl / l̇`` (``φ_g − g`` is periodic). Librations are
    integrated over both branches with ``l = c + h sin θ``, which removes the inverse
    square-root singularities at the turning points.
    """
    with mp.workdps(dps):
        a1, a2, a3 = (1 / mp.mpf(body.I1), 1 / mp.mpf(body.I2), 1 / mp.mpf(body.I3))
        l, L, G = mp.mpf(l), mp.mpf(L), mp.mpf(G)

        def p(t):
            return mp.sin(t) ** 2 * a1 + mp.cos(t) ** 2 * a2

        e = (p(l) * (G - L) * (G + L) + a3 * L * L) / (G * G)

        def dt_dl(t):
            absL = G * mp.sqrt(abs((p(t) - e) / (p(t) - a3)))
            return 1 / (absL * abs(a3 - p(t)))

        s2 = (e - a2) / (a1 - a2)
        if not 0 < s2 < 1:
            nodes = [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]
            T = mp.quad(dt_dl, nodes)
            A = mp.quad(lambda t: G * p(t) * dt_dl(t), nodes)
        else:
            t1 = mp.asin(mp.sqrt(s2))
            centre, half = (
                (mp.pi / 2, mp.pi / 2 - t1) if (p(mp.pi / 2) - e) * (p(mp.pi / 2) - a3) > 0 else (0, t1)
            )

            def along(f):
                def g(theta):
                    t = centre + half * mp.sin(theta)
                    # At the nodes that round onto a turning point the weight cos θ is ~1e-30.
                    return 0 if p(t) == e else 2 * f(t) * dt_dl(t) * half * mp.cos(theta)

                return g

            nodes = [-mp.pi / 2, 0, mp.pi / 2]
            T = mp.quad(along(lambda t: 1), nodes)
            A = mp.quad(along(lambda t: G * p(t)), nodes)
        return float(2 * mp.pi / T), float(A / T)


def separatrix_distance(body: RigidBody, l, L, G):
    """``|e − a_i|`` relative to the width of the state's region (independent of the code)."""
    a1, a2, a3, a_i, a_e = inverse_moments(body)
    e = (np.sin(l) ** 2 * a1 + np.cos(l) ** 2 * a2) * (G - L) * (G + L) / G**2 + a3 * (L / G) ** 2
    width = np.where((e - a_i) * (a3 - a_i) > 0, a_i - a3, a_e - a_i)
    return np.abs(e - a_i) / np.abs(width)


def circle(d):
    """Differences of angles taken on the circle, in ``(−π, π]``."""
    return np.angle(np.exp(1j * np.asarray(d)))


@pytest.mark.parametrize(("name", "regime"), CASES)
def test_sampler_states_lie_in_their_regime(name, regime, rng):
    """The sampler's states have the energy of their regime (circulation: between 1/I3 and 1/I_i)."""
    body = BODIES[name]
    l, _, _, L, G, _ = sample(body, rng, 50, regime)
    _, _, a3, a_i, _ = inverse_moments(body)
    e = (np.sin(l) ** 2 / body.I1 + np.cos(l) ** 2 / body.I2) * (G - L) * (G + L) / G**2 + a3 * (L / G) ** 2
    circulates = (e - a_i) * (a3 - a_i) > 0
    if regime == "circulation":
        assert circulates.all()
    elif regime == "libration":
        assert not circulates.any()
    else:
        width = np.where(circulates, a_i - a3, inverse_moments(body)[4] - a_i)
        assert (np.abs(e - a_i) <= 1.01e-3 * np.abs(width)).all()
