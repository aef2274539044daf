"""Formulas of Gurfil et al. (A.2, §5) checked numerically; the evidence for docs/errata-free.md.

Each test evaluates a printed formula (or its corrected form) with mpmath and compares it
with an independent computation: the energy integral, a quadrature, the exact motion.
"""

import mpmath as mp
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion

I1, I2, I3 = 1.0, 1.6, 2.2
M0 = np.array([0.3, 0.25, 1.0])  # SAM about the axis of I3
G = float(np.linalg.norm(M0))
D = float(np.sum(M0**2 / np.array([I1, I2, I3])))  # 2T = 2α₁
KAP2 = I3 * (I2 - I1) / (I1 * (I3 - I2))  # Sadov's κ², eq. (139)
LAM2 = KAP2 * (I1 / I3) * (I3 * D - G**2) / (G**2 - I1 * D)  # λ², eq. (139)


def _L(ell):
    """Andoyer's L from the energy integral: L² (1/I₃ − W) = 2T − G² W."""
    W = mp.sin(ell) ** 2 / I1 + mp.cos(ell) ** 2 / I2
    return mp.sqrt((G**2 * W - D) / (W - mp.mpf(1) / I3))


def _pi_gurfil(n, k2, z=None):
    """Gurfil's Π: the characteristic enters as 1 + n sin²θ (mpmath uses 1 − n sin²θ)."""
    return mp.ellippi(-n, k2) if z is None else mp.ellippi(-n, z, k2)


# -- Appendix A.2 -----------------------------------------------------------------------


def _euler_and_andoyer(seed):
    h, inc, g, J, ell = np.random.default_rng(seed).uniform(0.2, 1.3, 5)
    rot = Rotation.from_euler("ZXZ", [h, inc, g]) * Rotation.from_euler("XZ", [J, ell])
    _, theta, psi = rot.as_euler("ZXZ")
    return inc, J, ell, theta, psi


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a2_eq189_spherical_law_of_cosines(seed):
    inc, J, ell, theta, psi = _euler_and_andoyer(seed)
    rhs = np.cos(theta) * np.cos(J) + np.sin(theta) * np.sin(J) * np.cos(psi - ell)
    assert abs(np.cos(inc) - rhs) < 1e-15


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a2_eq191_needs_sin_theta_on_both_terms(seed):
    inc, J, ell, theta, psi = _euler_and_andoyer(seed)
    alpha, beta, gamma = np.sin(J) * np.sin(ell), np.sin(J) * np.cos(ell), np.cos(J)  # (169)-(171)
    printed = np.cos(theta) * gamma + np.sin(theta) * np.sin(psi) * alpha + np.cos(psi) * beta
    corrected = np.cos(theta) * gamma + np.sin(theta) * (np.sin(psi) * alpha + np.cos(psi) * beta)
    assert abs(np.cos(inc) - corrected) < 1e-15
    assert abs(np.cos(inc) - printed) > 1e-4


def test_a2_solution_matches_the_exact_motion():
    # (162)-(163), (167), (169)-(171), (180), (184)-(188): α' = a cn u, β' = b sn u,
    # γ' = √(1 − a²) dn u with u = n t, modulus κ² = (b² − a²)/(1 − a²); the state at
    # t = 0 has ξ₀ = atan2(β'/b, α'/a) and u₀ = F(ξ₀, κ)
    fm = FreeMotion([I1, I2, I3], M0)
    with mp.workdps(30):
        P2 = mp.mpf(D) / G**2
        a = mp.sqrt((P2 - 1 / mp.mpf(I3)) / (1 / mp.mpf(I1) - 1 / mp.mpf(I3)))
        b = mp.sqrt((P2 - 1 / mp.mpf(I3)) / (1 / mp.mpf(I2) - 1 / mp.mpf(I3)))
        k2 = (b**2 - a**2) / (1 - a**2)
        n = G * mp.sqrt((1 / mp.mpf(I1) - P2) * (1 / mp.mpf(I2) - 1 / mp.mpf(I3)))
        u0 = mp.ellipf(mp.atan2(M0[1] / G / b, M0[0] / G / a), k2)
        for t in (0.7, 5.0, 40.0):
            u = u0 + n * t
            paper = [
                G * a * mp.ellipfun("cn", u, m=k2),
                G * b * mp.ellipfun("sn", u, m=k2),
                G * mp.sqrt(1 - a**2) * mp.ellipfun("dn", u, m=k2),
            ]
            got = fm.momentum(t)
            assert max(abs(float(p) - g) for p, g in zip(paper, got, strict=True)) < 4e-15


# -- §5, Sadov's variables --------------------------------------------------------------


@pytest.mark.parametrize("ell", [0.3, 1.1, 2.5])
def test_s5_eq140_L_squared(ell):
    printed = (
        G**2
        * KAP2
        / (KAP2 + LAM2)
        * (1 - LAM2 + (KAP2 + LAM2) * np.sin(ell) ** 2)
        / (1 + KAP2 * np.sin(ell) ** 2)
    )
    assert abs(float(_L(ell)) ** 2 - printed) < 1e-15


def test_s5_unnumbered_jacobi_equation_has_2_alpha1_not_its_square():
    # (∂U/∂ℓ)² [(1/I₃ − 1/I₂) − (1/I₁ − 1/I₂) sin²ℓ] = (2α₁ − α₂²/I₂) − α₂² (1/I₁ − 1/I₂) sin²ℓ
    ell, alpha1 = 0.8, D / 2
    lhs = float(_L(ell)) ** 2 * ((1 / I3 - 1 / I2) - (1 / I1 - 1 / I2) * np.sin(ell) ** 2)
    tail = -(G**2) * (1 / I1 - 1 / I2) * np.sin(ell) ** 2
    assert abs(lhs - (2 * alpha1 - G**2 / I2 + tail)) < 1e-15
    assert abs(lhs - (2 * alpha1**2 - G**2 / I2 + tail)) > 1e-2  # as printed


def test_s5_eq143_action_with_gurfils_sign_of_the_characteristic():
    with mp.workdps(30):
        action = mp.quad(_L, [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]) / (2 * mp.pi)
        kap, root = mp.sqrt(KAP2), mp.sqrt(KAP2 + LAM2)
        pre = 2 * G * mp.sqrt(1 + KAP2) / (mp.pi * kap * root)
        eq143 = pre * ((KAP2 + LAM2) * _pi_gurfil(KAP2, LAM2) - LAM2 * mp.ellipk(LAM2))
        assert abs(eq143 - action) < 1e-14  # the constants are doubles
        # read with the DLMF/A&S/mpmath convention (1 − n sin²θ) the same symbols fail:
        dlmf = pre * ((KAP2 + LAM2) * mp.ellippi(KAP2, LAM2) - LAM2 * mp.ellipk(LAM2))
        assert abs(dlmf - action) > 0.1


def test_s5_eq144_hamiltonian():
    H = G**2 / (2 * I1 * I3) * (I3 * LAM2 + I1 * KAP2) / (KAP2 + LAM2)
    assert abs(H - D / 2) < 1e-15


def _ell_of_z(z):
    """ℓ(z) from eq. (142)."""
    s = mp.sqrt(1 + KAP2 * mp.sin(z) ** 2)
    return mp.atan2(mp.cos(z) / s, -mp.sqrt(1 + KAP2) * mp.sin(z) / s)


@pytest.mark.parametrize("z", [0.4, 1.0, 1.4])
def test_s5_quadrature_of_L_has_F_not_K(z):
    # ∫_{ℓ(0)}^{ℓ(z)} L dℓ = (I_g/κ) √((1+κ²)/(κ²+λ²)) [(κ²+λ²) Π(z, κ², λ) − λ² F(z, λ)];
    # the text prints K(λ) in place of F(z, λ)
    with mp.workdps(30):
        quad = mp.quad(_L, [_ell_of_z(0), _ell_of_z(z)])
        pre = G / mp.sqrt(KAP2) * mp.sqrt((1 + KAP2) / (KAP2 + LAM2))
        pi_z = _pi_gurfil(KAP2, LAM2, z)
        corrected = pre * ((KAP2 + LAM2) * pi_z - LAM2 * mp.ellipf(z, LAM2))
        printed = pre * ((KAP2 + LAM2) * pi_z - LAM2 * mp.ellipk(LAM2))
        assert abs(corrected - quad) < 1e-14
        assert abs(printed - quad) > 1e-2


def test_s5_eq145_derivative_of_the_action():
    def action(lam):
        l2 = lam**2
        pre = 2 * G * mp.sqrt(1 + KAP2) / (mp.pi * mp.sqrt(KAP2) * mp.sqrt(KAP2 + l2))
        return pre * ((KAP2 + l2) * _pi_gurfil(KAP2, l2) - l2 * mp.ellipk(l2))

    with mp.workdps(30):
        lam = mp.sqrt(LAM2)
        eq145 = (
            -G
            * 2
            * mp.sqrt(KAP2)
            * lam
            * mp.sqrt(1 + KAP2)
            * mp.ellipk(LAM2)
            / (mp.pi * (KAP2 + LAM2) ** 1.5)
        )
        assert abs(mp.diff(action, lam) - eq145) < 1e-14


def test_s5_eq147_angles_are_linear_in_time_along_the_exact_motion():
    # φ_ℓ = (π/2) F(z, λ)/K(λ), φ_g = g + (1/κ)√((κ²+λ²)(1+κ²)) [Π(z, κ², λ) − Π(κ², λ) F/K]
    # evaluated on the exact motion (Andoyer angles from the attitude): both must advance
    # uniformly, φ_ℓ by −2π per period and φ_g at the precession rate of the solution.
    g0, J0, l0 = 0.3, float(np.arccos(M0[2] / G)), float(np.arctan2(M0[0], M0[1]))
    q0 = Rotation.from_euler("ZXZ", [g0, J0, l0]).as_quat()  # reference = invariable frame
    fm = FreeMotion([I1, I2, I3], M0, q0)
    T = float(fm.periods.period)
    t = np.linspace(0.0, 1.7 * T, 241)
    m, q = fm.propagate(t)
    g = np.unwrap(Rotation.from_quat(q).as_euler("ZXZ")[:, 0])
    ell = np.unwrap(np.arctan2(m[:, 0], m[:, 1]))
    z = np.unwrap([float(mp.atan2(-mp.cos(x), mp.sqrt(1 + KAP2) * mp.sin(x))) for x in ell])
    with mp.workdps(30):
        K = mp.ellipk(LAM2)
        pre = mp.sqrt((KAP2 + LAM2) * (1 + KAP2)) / mp.sqrt(KAP2)
        pc = _pi_gurfil(KAP2, LAM2)
        F = [mp.ellipf(x, LAM2) for x in z]
        phi_l = np.array([float(mp.pi / 2 * f / K) for f in F])
        phi_g = np.array(
            [
                float(gi + pre * (_pi_gurfil(KAP2, LAM2, x) - pc * f / K))
                for gi, x, f in zip(g, z, F, strict=True)
            ]
        )
    for phi, rate in ((phi_l, -2 * np.pi / T), (phi_g, float(fm.periods.precession_rate))):
        fit = np.polyfit(t, phi, 1)
        assert np.max(np.abs(phi - np.polyval(fit, t))) < 1e-12
        assert abs(fit[0] - rate) < 1e-12 * abs(rate)
