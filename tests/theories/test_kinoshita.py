"""Lara §5: the SAM theory expanded in Kinoshita's j, against the paper's printed expansions
and against the exact frequencies of the free body (mpmath quadrature)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp

from andoyer import RigidBody, State
from andoyer.theories.kinoshita import (
    andoyer_N_in_j,
    mean_action_in_j,
    precession_rate_in_j,
    secular_frequencies_in_j,
    symbols,
)
from andoyer.theories.sam_rotation import SAMRotation

S = symbols()
alpha, beta, G, C, j, l = (S[k] for k in ("alpha", "beta", "G", "C", "j", "l"))
s = sp.sqrt(1 - beta**2)
ALPHA, BETA = 0.3, 0.5


def same(a, b):
    """Equal as polynomials in j (and in cos/sin of l): each coefficient simplifies to 0."""
    diff = sp.expand(sp.expand_trig(a - b))
    return all(sp.simplify(c) == 0 for c in sp.Poly(diff, j).coeffs())


def test_kinoshita_n_l_is_the_printed_expansion():
    # Lara §5: n_ℓ' = (G'/C) α √(1−β²) [1 − j²/(2(1−β)) − 3β² j⁴/(16(1−β)²)] (i = 1, eq. 36)
    n_l, _ = secular_frequencies_in_j(order=2, j_order=4)
    printed = G / C * alpha * s * (1 - j**2 / (2 * (1 - beta)) - 3 * beta**2 * j**4 / (16 * (1 - beta) ** 2))
    assert same(n_l, printed)


def test_kinoshita_n_g_is_the_printed_expansion_with_eq_36_as_definition():
    # n_g' = (G'/C)[1 + (α/2)(1+β) j² + (α/32)(1+β) β²/(1−β)² j⁶]: exactly what eq. 36 taken as
    # the definition of j gives from q_1 (no j⁴ term).
    _, n_g = secular_frequencies_in_j(order=2, j_order=6)
    printed = (
        G
        / C
        * (1 + alpha / 2 * (1 + beta) * j**2 + alpha / 32 * (1 + beta) * beta**2 / (1 - beta) ** 2 * j**6)
    )
    assert same(n_g, printed)


def test_kinoshita_exact_j_changes_the_j4_and_j6_terms():
    # With j the minimum inclination (eq. 35 with the full eq. 34) the j⁴ term of n_g' is not 0
    # and its j⁶ term is not the printed one (docs/errata-lara.md).
    _, n_g = secular_frequencies_in_j(order=3, j_order=6, relation="exact")
    expected = (
        G
        / C
        * (
            1
            + alpha * (1 + beta) / 2 * j**2
            + alpha * (1 + beta) * (4 * beta - 1) / (24 * (1 - beta)) * j**4
            + alpha * (1 + beta) * (61 * beta**2 + 28 * beta + 1) / (720 * (1 - beta) ** 2) * j**6
        )
    )
    assert same(n_g, expected)
    x = mean_action_in_j(order=3, j_order=4, relation="exact")
    assert same(x, s / (2 * (1 - beta)) * j**2 + s * (4 * beta - 1) / (24 * (1 - beta) ** 2) * j**4)


def test_kinoshita_printed_frequency_sum_has_the_wrong_sign():
    # n_g' + n_ℓ' (the mean rate of μ = g − ν) to j²; the paper prints
    # α[1 − (1 − s)(1 − ½√((1+β)/(1−β)) j²)]; the sum of its own n_g', n_ℓ' has "+ ½".
    rate = precession_rate_in_j(order=2, j_order=2)
    k = s / (1 - beta)  # = √((1 + β)/(1 − β))
    corrected = G / C + G / C * alpha * (1 - (1 - s) * (1 + k * j**2 / 2))
    printed = G / C + G / C * alpha * (1 - (1 - s) * (1 - k * j**2 / 2))
    assert same(rate, corrected)
    assert not same(rate, printed)


def test_kinoshita_N_is_the_printed_expansion():
    # N = M (1 − j²/2 − β/(1−β) j² cos²ℓ') + O(j⁴)
    printed = 1 - j**2 / 2 - beta / (1 - beta) * j**2 * sp.cos(l) ** 2
    assert same(andoyer_N_in_j(order=2, j_order=2), printed)
    assert same(andoyer_N_in_j(order=3, j_order=2, relation="exact"), printed)


def test_kinoshita_N_at_the_minimum_inclination_is_cos_j():
    # At ℓ' = π/2 the figure axis is at its minimum inclination j: N/M = cos j (to j⁶).
    N = andoyer_N_in_j(order=3, j_order=6, relation="exact").subs(l, sp.pi / 2)
    assert same(N, 1 - j**2 / 2 + j**4 / 24 - j**6 / 720)


def exact_frequencies(j_min, dps=30):
    """n_ℓ and the mean rate of μ of the free body (eq. 3) at minimum inclination j, M = C = 1.

    On the level set, N(ν)² = M²(1 − k/(1 − β cos 2ν)) with k = (1 + β) sin² j; the period of
    ν is ∮ C dν/(α N (1 − β cos 2ν)) and μ̇ = (M/C)(1 + α(1 − β cos 2ν)).
    """
    with mpmath.workdps(dps):
        a, b, jm = mpmath.mpf(ALPHA), mpmath.mpf(BETA), mpmath.mpf(j_min)
        k = (1 + b) * mpmath.sin(jm) ** 2

        def w(nu):
            return 1 - b * mpmath.cos(2 * nu)

        def dt(nu):
            return 1 / (a * mpmath.sqrt(1 - k / w(nu)) * w(nu))

        period = mpmath.quad(dt, [0, mpmath.pi / 2, mpmath.pi, 3 * mpmath.pi / 2, 2 * mpmath.pi])
        mu = mpmath.quad(
            lambda nu: (1 + a * w(nu)) * dt(nu),
            [0, mpmath.pi / 2, mpmath.pi, 3 * mpmath.pi / 2, 2 * mpmath.pi],
        )
        return float(2 * mpmath.pi / period), float(mu / period)


def evaluate(expr, j_values):
    f = sp.lambdify(j, expr.subs({alpha: ALPHA, beta: BETA, G: 1, C: 1}), "mpmath")
    return np.array([float(f(x)) for x in j_values])


def test_kinoshita_expansions_against_exact_frequencies():
    js = np.array([0.2, 0.1, 0.05])
    exact = np.array([exact_frequencies(x) for x in js])
    n_l_36, _ = secular_frequencies_in_j(order=2, j_order=6)
    n_l_ex, _ = secular_frequencies_in_j(order=3, j_order=6, relation="exact")
    rate_ex = precession_rate_in_j(order=3, j_order=6, relation="exact")

    def order_of(err):
        return np.polyfit(np.log(js), np.log(err), 1)[0]

    assert order_of(np.abs(evaluate(n_l_ex, js) - exact[:, 0])) == pytest.approx(8, abs=0.3)
    assert order_of(np.abs(evaluate(rate_ex, js) - exact[:, 1])) == pytest.approx(8, abs=0.3)
    assert order_of(np.abs(evaluate(n_l_36, js) - exact[:, 0])) == pytest.approx(4, abs=0.3)
    k = np.sqrt((1 + BETA) / (1 - BETA))
    sq = np.sqrt(1 - BETA**2)
    printed_sum = 1 + ALPHA * (1 - (1 - sq) * (1 - k * js**2 / 2))
    corrected_sum = 1 + ALPHA * (1 - (1 - sq) * (1 + k * js**2 / 2))
    assert order_of(np.abs(printed_sum - exact[:, 1])) == pytest.approx(2, abs=0.2)
    assert order_of(np.abs(corrected_sum - exact[:, 1])) == pytest.approx(4, abs=0.3)
    # The theory's own secular frequencies at a state of minimum inclination j (ν = π/2).
    body = RigidBody.from_alpha_beta(ALPHA, BETA, C=1.0)
    n = SAMRotation(body, order=12).frequencies(State.from_andoyer(np.pi / 2, 0.0, 0.0, np.cos(js), 1.0, 0.3))
    np.testing.assert_allclose(n.n_l, exact[:, 0], rtol=1e-12)
    np.testing.assert_allclose(n.n_g + n.n_l, exact[:, 1], rtol=1e-13)


def test_kinoshita_errors():
    with pytest.raises(ValueError, match="even j_order"):
        secular_frequencies_in_j(j_order=3)
    with pytest.raises(ValueError, match="relation"):
        mean_action_in_j(relation="kinoshita")
    with pytest.raises(ValueError, match="Deprit order"):
        andoyer_N_in_j(order=0)


def test_kinoshita_N_expansion_along_the_motion():
    # N/M of states propagated by the order-12 theory, against the expansion in j at the mean ℓ'
    # of each state: error O(j⁶) through j⁴ (exact j), O(j⁴) for the printed j² formula.
    body = RigidBody.from_alpha_beta(ALPHA, BETA, C=1.0)
    rotation = SAMRotation(body, order=12)
    js = np.array([0.2, 0.1, 0.05])
    start = State.from_andoyer(np.pi / 2, 0.0, 0.0, np.cos(js), 1.0, 0.3)
    states = rotation.propagate(start[:, None], np.linspace(0.0, 5.0, 6))
    mean_l = rotation.mean_elements(states).sam_l
    N = states.m_body[..., 2] / np.linalg.norm(states.m_body, axis=-1)
    exact4 = sp.lambdify((j, l), andoyer_N_in_j(order=3, j_order=4, relation="exact").subs(beta, BETA))
    printed = 1 - js[:, None] ** 2 / 2 - BETA / (1 - BETA) * js[:, None] ** 2 * np.cos(mean_l) ** 2
    err4 = np.abs(exact4(js[:, None], mean_l) - N).max(axis=1)
    err2 = np.abs(printed - N).max(axis=1)
    assert np.polyfit(np.log(js), np.log(err4), 1)[0] == pytest.approx(6, abs=0.3)
    assert np.polyfit(np.log(js), np.log(err2), 1)[0] == pytest.approx(4, abs=0.3)
