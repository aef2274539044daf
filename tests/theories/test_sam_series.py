"""Lara's SAM theory: triaxiality polynomials checked against the exact action (mpmath
quadrature), the transformation against numerical integration, low orders against the paper."""

from __future__ import annotations

from fractions import Fraction
from math import factorial

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from andoyer.series import lie_sum
from andoyer.theories import SAM_RING, sam_hamiltonian, sam_theory

ALPHA, BETA, C, G = 0.3, 0.6, 1.0, 1.0  # s = 0.8


def _exact_energy_and_action(L0: float, dps: int = 50):
    """Energy of K at (ℓ = π/4, L = L0) and the exact action (1/2π)∮ L dℓ on that level set.

    On K(ℓ, L) = E (G fixed) L(ℓ) is the small root of the quadratic
    α(1 + β cos 2ℓ)/(2C) L² − α s G/C L + (E − G²/2C) = 0, integrated by mpmath quadrature.
    """
    with mpmath.workdps(dps):
        a, b, c, g = (mpmath.mpf(x) for x in (ALPHA, BETA, C, G))
        s = mpmath.sqrt(1 - b**2)
        L0 = mpmath.mpf(L0)
        energy = g**2 / (2 * c) + a * s * g * L0 / c - a * L0**2 / (2 * c)  # cos 2ℓ = 0

        def small_root(ell):
            w = 1 + b * mpmath.cos(2 * ell)
            disc = (s * g) ** 2 - 2 * w * c * (energy - g**2 / (2 * c)) / a
            return (s * g - mpmath.sqrt(disc)) / w

        action = mpmath.quad(small_root, [0, mpmath.pi / 2, mpmath.pi]) / mpmath.pi
        return energy, action


def _secular_mp(order: int, L, dps: int = 50):
    """T(L', G) of the exact series summed in mpmath (no float rounding)."""
    T = lie_sum(sam_theory(order).transform.new_hamiltonian)
    values = {"L": L, "G": G, "alpha": ALPHA, "beta": BETA, "s": None, "C": C}
    with mpmath.workdps(dps):
        values = {k: mpmath.mpf(v) for k, v in values.items() if v is not None}
        values["s"] = mpmath.sqrt(1 - values["beta"] ** 2)
        total = mpmath.mpf(0)
        for t in T.terms():
            term = mpmath.mpf(t.coeff.numerator) / t.coeff.denominator
            for name, e in zip(SAM_RING.poly_names, t.exponents, strict=True):
                term *= values[name] ** e
            total += term
        return total


@pytest.mark.parametrize(
    ("order", "levels"),
    [(3, (0.08, 0.04, 0.02)), (6, (0.04, 0.02, 0.01)), (12, (0.02, 0.01, 0.005))],
)
def test_sam_secular_hamiltonian_matches_exact_action(order, levels):
    # T(L') with L' the exact action must give back the energy, error O(δ^(N+2)) (the last
    # kept term K_N/N! is O(x² δ^(N−1)) relative to G²/2C).
    errors = []
    for L0 in levels:
        energy, action = _exact_energy_and_action(L0)
        with mpmath.workdps(50):
            errors.append(abs(_secular_mp(order, action) - energy))
    slopes = [float(mpmath.log(errors[i] / errors[i + 1], 2)) for i in range(2)]
    assert all(abs(slope - (order + 2)) < 0.35 for slope in slopes), slopes


def test_sam_secular_float_evaluation_matches_exact_series():
    theory = sam_theory(6)
    L = np.array([0.0, 0.01, 0.05])
    got = theory.secular_hamiltonian(L, G, ALPHA, BETA, C)
    ref = [float(_secular_mp(6, x)) for x in L]
    np.testing.assert_allclose(got, ref, rtol=1e-15)


def test_sam_low_order_frequencies_match_paper_section_5():
    # Lara §5 (i = 1): n_ℓ = (G/C) α (s − x − (3/4) β² x²/s),
    # n_g = (G/C) (1 + α s x + α β² x³/(4 s)) (the j-form of the paper, j²/2 = (1 − β) δ).
    R = SAM_RING
    T = lie_sum(sam_theory(2).transform.new_hamiltonian)
    n_l = R("G/C*alpha*(s - L/G - 3/4*beta**2*L**2*G**-2*s**-1)")
    n_g = R("G/C*(1 + alpha*s*L/G + alpha*beta**2*L**3*G**-3*s**-1/4)")
    assert T.diff("L") == n_l
    assert T.diff("G") == n_g


def test_sam_polynomial_structure_matches_eqs_32_to_34():
    # K(ℓ + π/2; −β) = K(ℓ; β), so the coefficient of cos/sin 2mℓ is (−β)^m times an even
    # polynomial in β: the form of eqs. 30 and 32–34.
    theory = sam_theory(9)
    for table in (theory.q, theory.g, theory.l, theory.L):
        for coeffs in table.values():
            assert all(c == 0 for c in coeffs[1::2])
            assert coeffs[0] != 0
    for i in range(1, 10):
        k = (i + 1) // 2
        assert {m for (j, m) in theory.l if j == i} == set(range(1, i + 1))
        assert {m for (j, m) in theory.g if j == i} == set(range(1, k + 1))
        assert {m for (j, m) in theory.L if j == i} - {0} == set(range(1, k + 1))
    assert theory.q[1] == (Fraction(1, 2),)
    assert theory.q[3] == (Fraction(3, 4), 0, Fraction(9, 32))


def test_sam_tables_reconstruct_the_transformation():
    # Rebuild Δℓ from the ℓ_(i,m) table (eq. 33) and compare with the engine's series.
    theory = sam_theory(5)
    R = SAM_RING
    dl = theory.transform.direct_angle("l")
    for i in range(1, 6):
        rebuilt = R.zero
        for (j, m), coeffs in theory.l.items():
            if j == i:
                poly = sum((R.constant(c) * R.gen("beta") ** p for p, c in enumerate(coeffs)), R.zero)
                rebuilt += poly * R(f"(-beta)**{m} * sin({2 * m}*l)")
        assert dl[i] / factorial(i) == rebuilt * R(f"L**{i}*G**{-i}*s**{-i}")


def _k_rhs(_t, y):
    ell, _g, L = y
    s = np.sqrt(1 - BETA**2)
    w = 1 + BETA * np.cos(2 * ell)
    dl = ALPHA * s * G / C - ALPHA * L * w / C
    dg = G / C + ALPHA * s * L / C
    dL = -ALPHA * L**2 * BETA * np.sin(2 * ell) / C  # −∂K/∂ℓ
    return [dl, dg, dL]


@pytest.mark.parametrize("order", [2, 3])
def test_sam_transformation_reproduces_integrated_motion(order):
    theory = sam_theory(order)
    errors = []
    levels = (0.08, 0.04, 0.02)
    for L0 in levels:
        y0 = [0.3, 0.1, L0]
        n_l0 = ALPHA * np.sqrt(1 - BETA**2) * G / C
        t = np.linspace(0, 2 * np.pi / n_l0, 9)
        sol = solve_ivp(_k_rhs, (0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-13, atol=1e-15)
        new = theory.inverse(*y0, G, alpha=ALPHA, beta=BETA, C=C)
        n_l, n_g = theory.frequencies(new[2], G, ALPHA, BETA, C)
        old = theory.direct(new[0] + n_l * t, new[1] + n_g * t, new[2], G, alpha=ALPHA, beta=BETA, C=C)
        err = max(
            np.max(np.abs(old[0] - sol.y[0])),
            np.max(np.abs(old[1] - sol.y[1])),
            np.max(np.abs(old[2] - sol.y[2])) / L0,
        )
        errors.append(err)
    slopes = [np.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(abs(slope - (order + 1)) < 0.5 for slope in slopes), (errors, slopes)


def test_sam_hamiltonian_is_eq_27():
    H0, H1 = sam_hamiltonian()
    K = SAM_RING("G**2/(2*C)*(1 + 2*alpha*s*L/G*(1 - L/G*(1 + beta*cos(2*l))/(2*s)))")
    assert H0 + H1 == K


def test_sam_errors():
    with pytest.raises(ValueError, match="order >= 1"):
        sam_theory(0)
    with pytest.raises(ValueError, match="-1 < beta < 1"):
        sam_theory(2).secular_hamiltonian(0.01, 1.0, 0.1, 1.0, 1.0)
    with pytest.raises(ValueError, match="-1 < beta < 1"):
        sam_theory(2).secular_hamiltonian(0.01, 1.0, 0.1, np.nan, 1.0)
    with pytest.raises(ValueError, match="alpha != 0"):
        sam_theory(2).frequencies(0.01, 1.0, 0.0, 0.5, 1.0)
    with pytest.raises(ValueError, match="C > 0"):
        sam_theory(2).frequencies(0.01, 1.0, 0.1, 0.5, -1.0)


def test_sam_theory_order_1_has_no_q_and_the_first_transformation():
    theory = sam_theory(1)
    assert theory.q == {}
    assert theory.l == {(1, 1): (Fraction(1, 2),)}
    assert {(1, 1): (Fraction(1, 2),)} == theory.L
    assert theory.g == {(1, 1): (Fraction(1, 4),)}


def test_sam_theory_negative_alpha_and_beta_is_the_same_series():
    # The LAM labelling evaluates the polynomials at α < 0, β < 0: K(ℓ + π/2; −β) = K(ℓ; β), so
    # the secular Hamiltonian is even in β and linear in α.
    theory = sam_theory(5)
    a = theory.secular_hamiltonian(0.02, 1.0, 0.3, 0.6, 1.0)
    b = theory.secular_hamiltonian(0.02, 1.0, 0.3, -0.6, 1.0)
    assert a == pytest.approx(b, rel=1e-15)
    c = theory.secular_hamiltonian(0.02, 1.0, -0.3, 0.6, 1.0)
    assert (a - 0.5) == pytest.approx(-(c - 0.5), rel=1e-13)
