"""Sadov's action I_ℓ, the Hamiltonian H(I_ℓ, I_g) and the frequencies, against independent computations."""

from __future__ import annotations

import numpy as np
import pytest
from test_sadov_support import (
    BODIES,
    CASES,
    REPRESENTATIVE,
    SCALES,
    inverse_moments,
    reference_action,
    reference_frequencies,
    sample,
    scaled,
    separatrix_distance,
)

from andoyer import RigidBody
from andoyer.state import andoyer_hamiltonian
from andoyer.state.sadov import (
    andoyer_to_sadov,
    sadov_frequencies,
    sadov_hamiltonian,
    separatrix_action,
)
from andoyer.state.sadov_frame import SadovFrame
from andoyer.state.sadov_solve import solve

EPS = np.finfo(float).eps


def check_action_against_quadrature(body, rng, regime, n, moment_scale=1.0, momentum_scale=1.0):
    body = scaled(body, moment_scale)
    l, g, h, L, G, H = sample(body, rng, n, regime, G=momentum_scale)
    I_l = andoyer_to_sadov(body, l, g, h, L, G, H).I_l
    for k in range(n):
        ref = reference_action(body, l[k], L[k], G[k])
        assert abs(I_l[k] - ref) <= 1e-13 * abs(ref), (k, I_l[k], ref)


@pytest.mark.parametrize(("name", "regime"), CASES)
def test_action_matches_quadrature(name, regime, rng):
    """Eq. 143 (corrected, both regions) = (1/2π)∮ L dl by 30-digit quadrature, to 1e-13."""
    check_action_against_quadrature(BODIES[name], rng, regime, 2)


@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES[1:])
@pytest.mark.parametrize("regime", ["circulation", "libration"])
def test_action_matches_quadrature_at_every_scale(moment_scale, momentum_scale, regime, rng):
    check_action_against_quadrature(BODIES["b3-max"], rng, regime, 1, moment_scale, momentum_scale)


@pytest.mark.slow
@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES)
@pytest.mark.parametrize(("name", "regime"), CASES)
def test_action_matches_quadrature_many_states(name, regime, moment_scale, momentum_scale, rng):
    check_action_against_quadrature(BODIES[name], rng, regime, 6, moment_scale, momentum_scale)


@pytest.mark.parametrize("name", [n for n in BODIES if n != "b1-symmetric"])
def test_separatrix_action_is_two_over_pi_arctan_kappa(name):
    """``u_s = (2/π) arctan κ`` (Sadov), against the quadrature along the separatrix itself.

    κ² = I3 (I_i − I_e)/(I_e (I3 − I_i)) is eq. 139 with (I1, I2) → (I_e, I_i); it equals
    ``body.kappa²`` when b3 has the largest moment and its inverse when b3 has the smallest.
    """
    body = BODIES[name]
    _, _, a3, a_i, _ = inverse_moments(body)
    # The separatrix through the intermediate axis: energy a_i; take the state where L is largest.
    I_e = body.I2 if body.I1 == body.B else body.I1
    l = np.pi / 2 if I_e == body.I1 else 0.0
    p = 1.0 / I_e
    x = np.sqrt((p - a_i) / (p - a3))
    ref = reference_action(body, l, x, 1.0, separatrix=True)
    I_i = body.B
    kappa = np.sqrt(body.I3 * (I_i - I_e) / (I_e * (body.I3 - I_i)))
    assert kappa == pytest.approx(body.kappa if body.I3 == body.C else 1 / body.kappa, rel=1e-14)
    assert separatrix_action(body, 1.0) == pytest.approx(2 / np.pi * np.arctan(kappa), rel=1e-15)
    assert separatrix_action(body, 1.0) == pytest.approx(ref, rel=1e-13)


@pytest.mark.parametrize(("name", "regime"), CASES)
def test_hamiltonian_of_actions_equals_andoyer_hamiltonian(name, regime, rng):
    """H(I_ℓ, I_g) (eq. 144 after inverting eq. 143) = the Andoyer Hamiltonian of the state."""
    body = BODIES[name]
    l, g, h, L, G, H = sample(body, rng, 50, regime, G=3.0)
    s = andoyer_to_sadov(body, l, g, h, L, G, H)
    ref = andoyer_hamiltonian(body, l, L, G)
    # Near the separatrix the action fixes the energy better than the state does.
    tol = 4 * EPS if regime != "near-separatrix" else 8 * EPS
    assert np.max(np.abs(sadov_hamiltonian(body, s.I_l, s.I_g) / ref - 1)) <= tol


def check_time_averages(body, rng, regime, n, moment_scale=1.0, momentum_scale=1.0):
    """|ω_ℓ| = 2π/T and ω_g = ⟨ġ⟩ by 30-digit quadrature along the orbit."""
    body = scaled(body, moment_scale)
    l, g, h, L, G, H = sample(body, rng, n, regime, G=momentum_scale)
    s = andoyer_to_sadov(body, l, g, h, L, G, H)
    w = sadov_frequencies(body, s.I_l, s.I_g)
    # Within d of the separatrix the state fixes the orbit only to ε/d (the chart's conditioning).
    conditioning = 1e-16 / separatrix_distance(body, l, L, G)
    for k in range(n):
        omega_l, omega_g = reference_frequencies(body, l[k], L[k], G[k])
        assert abs(w.omega_l[k]) == pytest.approx(omega_l, rel=1e-13 + conditioning[k])
        assert w.omega_g[k] == pytest.approx(omega_g, rel=1e-14 + conditioning[k])


@pytest.mark.slow
@pytest.mark.parametrize(("name", "regime"), REPRESENTATIVE)
def test_frequencies_equal_time_averages_along_the_orbit(name, regime, rng):
    check_time_averages(BODIES[name], rng, regime, 1)


@pytest.mark.slow
@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES)
@pytest.mark.parametrize(("name", "regime"), CASES)
def test_frequencies_equal_time_averages_many_states(name, regime, moment_scale, momentum_scale, rng):
    check_time_averages(BODIES[name], rng, regime, 3, moment_scale, momentum_scale)


def check_richardson(body, rng, regime, n, moment_scale=1.0, momentum_scale=1.0):
    """(ω_ℓ, ω_g) in closed form = central differences of H(I_ℓ, I_g), Richardson-extrapolated."""
    body = scaled(body, moment_scale)
    l, g, h, L, G, H = sample(body, rng, n, regime, G=momentum_scale)
    s = andoyer_to_sadov(body, l, g, h, L, G, H)
    u = np.abs(s.I_l) / s.I_g
    # Steps well inside the region: H is not analytic across the separatrix.
    gap = np.minimum.reduce([np.abs(u - separatrix_action(body, 1.0)), 1 - u, u]) * s.I_g
    step = 1e-2 * gap
    k = np.array([1.0, -1.0, 0.5, -0.5])[:, None] * step
    H_l = sadov_hamiltonian(body, s.I_l + k, s.I_g)
    H_g = sadov_hamiltonian(body, s.I_l, s.I_g + k)
    w = sadov_frequencies(body, s.I_l, s.I_g)
    scale = sadov_hamiltonian(body, s.I_l, s.I_g) / step  # the rounding in the differences
    for values, omega in ((H_l, w.omega_l), (H_g, w.omega_g)):
        fd = (4 * (values[2] - values[3]) / step - (values[0] - values[1]) / (2 * step)) / 3
        assert np.all(np.abs(omega - fd) <= 1e-7 * np.abs(omega) + 1e-13 * scale)


@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_frequencies_equal_richardson_differences_of_hamiltonian(name, regime, rng):
    check_richardson(BODIES[name], rng, regime, 4)


@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES[1:])
@pytest.mark.parametrize("regime", ["circulation", "libration"])
def test_frequencies_equal_richardson_differences_at_every_scale(regime, moment_scale, momentum_scale, rng):
    check_richardson(BODIES["strongly-triaxial"], rng, regime, 4, moment_scale, momentum_scale)


@pytest.mark.parametrize("name", [n for n in BODIES if n not in {"b1-symmetric"}])
def test_frequency_limits_are_euler_free_precession_and_small_oscillations(name):
    """Small oscillations about b3 and about b_e, from H ≈ G² a/2 + ν J with J the oscillator action.

    At the pole ``J = G − |I_ℓ|`` and ``ν = G √((a1 − a3)(a2 − a3))`` (Euler's free precession,
    ``a = 1/I``), so ``ω_ℓ = ∓ν`` and ``ω_g = G a3 ± ν``; at a libration centre ``J = |I_ℓ|``,
    ``ν = G √((a_e − a_i)(a_e − a3))``, ``ω_g = G a_e``. Signs follow ``sign(a_e − a3)``.
    """
    body = BODIES[name]
    a1, a2, a3, a_i, a_e = inverse_moments(body)
    G = 2.0
    pole = sadov_frequencies(body, G, G)
    sign = np.sign(a1 - a3)
    assert pole.omega_l == pytest.approx(-sign * G * np.sqrt((a1 - a3) * (a2 - a3)), rel=1e-14)
    assert pole.omega_g == pytest.approx(G * (a3 + sign * np.sqrt((a1 - a3) * (a2 - a3))), rel=1e-14)
    centre = sadov_frequencies(body, 0.0, G)
    sign = np.sign(a_e - a3)
    assert centre.omega_l == pytest.approx(-sign * G * np.sqrt((a_e - a_i) * (a_e - a3)), rel=1e-14)
    assert centre.omega_g == pytest.approx(G * a_e, rel=1e-14)
    assert sadov_frequencies(body, -0.0, G).omega_l == -centre.omega_l


@pytest.mark.parametrize("name", list(BODIES))
def test_solver_inverts_the_action_to_round_off(name):
    """u → orbit → u on a grid that includes 1e-300 from either end and from the separatrix.

    Near the separatrix the two terms of eq. 143 grow like ``log(1/m_c)`` and cancel, so the
    achievable residual is ``ε log(1/m_c)``; targets within that of ``u_s`` end on the floor
    ``m_c ≈ 1e-300``.
    """
    frame = SadovFrame.from_body(BODIES[name])
    u_s = frame.separatrix_fraction
    grid = [1e-300, 1e-200, 1e-30, 1e-8, 0.1, 0.5, 0.9, 1 - 1e-8, 1 - 2 * EPS]
    u = np.concatenate([np.asarray(grid), u_s * np.asarray(grid), u_s + (1 - u_s) * np.asarray(grid)])
    u = u[(u != u_s) & (u > 0) & (u <= 1)]
    o = solve(frame, u)
    conditioning = np.maximum(1.0, np.log(1.0 / o.mc))
    assert np.all(np.abs(o.u - u) <= 4 * EPS * u * conditioning)
    assert np.all(o.circ == (u > u_s))


@pytest.mark.parametrize(
    "body", [RigidBody(1.0, 1.0, 1.5), RigidBody(2.0, 2.0, 1.5), RigidBody(1.0, 1.0, 1.0)]
)
def test_axisymmetric_about_b3_hamiltonian_and_frequencies_are_andoyers(body, rng):
    """I1 = I2: H = ½(G² − I_ℓ²)/I1 + I_ℓ²/(2 I3), ω_ℓ = (1/I3 − 1/I1) I_ℓ, ω_g = G/I1."""
    G = rng.uniform(0.5, 2, 20)
    I_l = G * rng.uniform(-1, 1, 20)
    ref = 0.5 * (G**2 - I_l**2) / body.I1 + I_l**2 / (2 * body.I3)
    assert np.allclose(sadov_hamiltonian(body, I_l, G), ref, rtol=1e-15, atol=0)
    w = sadov_frequencies(body, I_l, G)
    assert np.allclose(w.omega_l, (1 / body.I3 - 1 / body.I1) * I_l, rtol=1e-15, atol=1e-300)
    assert np.allclose(w.omega_g, G / body.I1, rtol=1e-15, atol=0)
