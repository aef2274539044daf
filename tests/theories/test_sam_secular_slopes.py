"""Lara's secular Hamiltonian is the free-body energy written in Sadov's action.

For every Deprit order N = 1..10 and β ∈ {0.06, 0.5, 0.98} (rigid bodies built with those β),
the exact series ``T_N(L', G)`` is summed in mpmath at the exact action ``J = (1/2π)∮ L dℓ`` of an
exact state and compared with the state's exact energy ``E``.  The reference (``E`` from eq. 27,
``J`` by quadrature of the level curve) never touches the series; it is tied to the bodies and to
Sadov's chart by float checks against ``State.energy`` and ``State.as_sadov``.
"""

from __future__ import annotations

from functools import cache

import mpmath
import numpy as np
import pytest

from andoyer import RigidBody, State
from andoyer.series import lie_sum
from andoyer.state.sam import sam_axes, sam_to_hub
from andoyer.theories import SAM_RING, sam_theory

DPS = 60
G = 1.0
BETAS = {0.06: 0.2, 0.5: 0.3, 0.98: 0.1}  # β: the α of the body built for it
# δ = L/(G s) of the state (at ℓ = π/4), halving. Small enough for the asymptotic regime: the
# series converges for δ ≲ 1/(2(1 + β)) ≥ 0.25, and the fitted slopes exceed N + 1 by 0.013-0.026
# (measured for all 30 cases). Large enough that the smallest error (≈ 4e-35 in energy units,
# N = 10) stays ~1e20 above the 60-digit rounding and the quadrature error (< 1e-70).
DELTAS = (0.02, 0.01, 0.005, 0.0025)
ORDERS = tuple(range(1, 11))


@cache
def body_for(beta: float) -> tuple[RigidBody, float, float, float]:
    """A body whose SAM chart has parameters (α, β): α(1 ± β) = C/A − 1, C/B − 1 (Lara eq. 2)."""
    alpha, C = BETAS[beta], 1.0
    body = RigidBody(C / (1 + alpha * (1 + beta)), C / (1 + alpha * (1 - beta)), C)
    axes = sam_axes(body, "SAM")
    return body, axes.alpha, axes.beta, axes.moments[2]


@cache
def exact_point(beta: float, delta: float) -> tuple[mpmath.mpf, mpmath.mpf, mpmath.mpf, mpmath.mpf]:
    """Energy ``E``, perturbation ``E − G²/2C``, action ``J`` and the quadrature's error estimate.

    The state is ``(ℓ, L) = (π/4, δ s G)`` of eq. 27 (``cos 2ℓ = 0``).  On ``K = E`` (G fixed),
    ``L(ℓ)`` is the small root of ``w L² − 2 s G L + c = 0``, ``w = 1 + β cos 2ℓ``,
    ``c = 2C (E − G²/2C)/α``, written ``c / (sG + √(s²G² − w c))`` to avoid cancellation; ``J`` is
    its mean over the period π of ℓ.
    """
    _, alpha, b, C = body_for(beta)
    with mpmath.workdps(DPS):
        a, b, c, g = (mpmath.mpf(x) for x in (alpha, b, C, G))
        s = mpmath.sqrt(1 - b**2)
        L0 = mpmath.mpf(delta) * s * g
        pert = a * s * g * L0 / c - a * L0**2 / (2 * c)
        k = 2 * c * pert / a

        def small_root(ell):
            w = 1 + b * mpmath.cos(2 * ell)
            return k / (s * g + mpmath.sqrt((s * g) ** 2 - w * k))

        J, err = mpmath.quad(small_root, [0, mpmath.pi / 2, mpmath.pi], error=True)
        return g**2 / (2 * c) + pert, pert, J / mpmath.pi, err / mpmath.pi


@cache
def secular_terms(order: int) -> tuple:
    """Real terms of ``T_N = Σ_(n≤N) K_n/n!`` of the order-N theory (exact rationals)."""
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    return tuple((t.coeff, t.exponents) for t in T.terms())


def secular_value(order: int, beta: float, L: mpmath.mpf) -> mpmath.mpf:
    """``T_N(L, G)`` summed term by term in mpmath (no float rounding)."""
    _, alpha, b, C = body_for(beta)
    with mpmath.workdps(DPS):
        values = {"L": L, "G": mpmath.mpf(G), "alpha": mpmath.mpf(alpha), "beta": mpmath.mpf(b)}
        values["C"] = mpmath.mpf(C)
        values["s"] = mpmath.sqrt(1 - values["beta"] ** 2)
        total = mpmath.mpf(0)
        for coeff, exps in secular_terms(order):
            term = mpmath.mpf(coeff.numerator) / coeff.denominator
            for name, e in zip(SAM_RING.poly_names, exps, strict=True):
                if e:
                    term *= values[name] ** e
            total += term
        return total


@pytest.mark.parametrize("beta", BETAS)
def test_sam_exact_point_is_the_body_energy_and_sadov_action(beta):
    # The mpmath reference against the library's float charts: eq. 27 with the body's (α, β, C)
    # is its energy, and J = G − I_ℓ with I_ℓ Sadov's action of the Andoyer l (b3 the SAM axis).
    body = body_for(beta)[0]
    s = np.sqrt(1 - body_for(beta)[2] ** 2)
    for delta in (DELTAS[0], DELTAS[-1]):
        energy, _, J, _ = exact_point(beta, delta)
        q, m = sam_to_hub(np.pi / 4, 0.1, 0.4, delta * s * G, G, 0.6 * G, 1.0, body=body, mode="SAM")
        state = State(q, m)
        assert float(state.energy(body)) == pytest.approx(float(energy), rel=1e-14)
        assert G - float(state.as_sadov(body).I_l) == pytest.approx(float(J), abs=1e-13 * G)


@pytest.mark.parametrize("order", ORDERS)
@pytest.mark.parametrize("beta", BETAS)
def test_sam_secular_error_falls_as_delta_to_the_n_plus_1(beta, order):
    # T_N misses Σ_(i≥N) (G²/2C) α x² β² q_i δ^i (x = L'/G' = s δ), i.e. O(δ^(N+2)) in energy
    # units; the perturbation E − G²/2C = (G²/2C) 2α s² δ (1 + O(δ)) is O(δ). Their ratio, the
    # relative error of the perturbation part, is (β² q_N / 2) δ^(N+1) (1 + O(δ)), with δ the
    # mean δ' = J/(G s) of the exact action (the series variable; the state's δ differs by
    # 1 + O(δ)).
    s = mpmath.sqrt(1 - mpmath.mpf(body_for(beta)[2]) ** 2)
    rel, mean_delta = [], []
    with mpmath.workdps(DPS):
        for delta in DELTAS:
            energy, pert, J, quad_err = exact_point(beta, delta)
            err = abs(secular_value(order, beta, J) - energy)
            # rounding and quadrature stay far below the measured error
            assert err > 1e6 * (quad_err + mpmath.mpf(10) ** (5 - DPS))
            rel.append(float(mpmath.log(err / abs(pert))))
            mean_delta.append(float(mpmath.log(J / (G * s))))
    slope = np.polyfit(mean_delta, rel, 1)[0]
    assert abs(slope - (order + 1)) <= 0.2, (slope, rel)
