"""Evidence for docs/errata-sadov.md: Gurfil et al. §5 as printed against independent computations.

Each test evaluates the printed formula literally with mpmath (``ellippi(n, φ, m)`` has the
characteristic entering as ``1 − n sin²θ``), the corrected one, and a direct quadrature of the
definition; the library is used only where a test says so.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from test_sadov_support import circle, reference_action

from andoyer import RigidBody
from andoyer.state import andoyer_equations
from andoyer.state.sadov import andoyer_to_sadov, sadov_frequencies

mp.mp.dps = 30
BODY = RigidBody(1.0, 2.0, 2.5)  # I1 < I2 < I3, Gurfil's ordering; κ² = 5
CIRCULATING = (0.7, 0.3, 0.0, 0.95, 1.0, 0.2)  # (l, g, h, L, G, H): λ < 1
LIBRATING = (1.4, 0.3, 0.0, 0.3, 1.0, 0.2)  # λ > 1


def sadov_parameters(state):
    """Gurfil's κ², λ² (eq. 139) and z (eq. 142) of a state, in mpmath."""
    I1, I2, I3 = (mp.mpf(BODY.I1), mp.mpf(BODY.I2), mp.mpf(BODY.I3))
    l, L, G = (mp.mpf(state[0]), mp.mpf(state[3]), mp.mpf(state[4]))
    alpha1 = (mp.sin(l) ** 2 / I1 + mp.cos(l) ** 2 / I2) * (G**2 - L**2) / 2 + L**2 / (2 * I3)
    kappa2 = I3 * (I2 - I1) / (I1 * (I3 - I2))
    lam2 = kappa2 * I1 / I3 * (2 * I3 * alpha1 - G**2) / (G**2 - 2 * I1 * alpha1)
    z = mp.atan2(-mp.cos(l), mp.sqrt(1 + kappa2) * mp.sin(l))
    return kappa2, lam2, z, alpha1


def eq143(G, kappa2, lam2, n_sign):
    """Eq. 143 with Π(κ², λ) read as the characteristic ``n_sign·κ²`` (1 − n sin²θ)."""
    k2, l2 = kappa2, lam2
    bracket = (k2 + l2) * mp.ellippi(n_sign * k2, l2) - l2 * mp.ellipk(l2)
    return 2 * G * mp.sqrt(1 + k2) / (mp.pi * mp.sqrt(k2) * mp.sqrt(k2 + l2)) * bracket


def real_action(G, kappa2, lam2):
    """Eq. 143 (n = −κ²) for λ < 1, its reciprocal-modulus real form for λ > 1."""
    if lam2 < 1:
        return eq143(G, kappa2, lam2, -1)
    lam = mp.sqrt(lam2)
    bracket = (kappa2 + lam2) * mp.ellippi(-kappa2 / lam2, 1 / lam2) - lam2 * mp.ellipk(1 / lam2)
    return 2 * G * mp.sqrt(1 + kappa2) / (mp.pi * mp.sqrt(kappa2) * lam * mp.sqrt(kappa2 + lam2)) * bracket


def test_hamilton_jacobi_equation_has_2_alpha1_not_2_alpha1_squared():
    """The equation before (137): ``(2α1 − α2²/I2)``, printed ``(2α1² − α2²/I2)``."""
    alpha1 = sadov_parameters(CIRCULATING)[3]
    I1, I2, I3 = (mp.mpf(BODY.I1), mp.mpf(BODY.I2), mp.mpf(BODY.I3))
    l, L, G = (mp.mpf(CIRCULATING[0]), mp.mpf(CIRCULATING[3]), mp.mpf(CIRCULATING[4]))
    s2 = mp.sin(l) ** 2
    lhs = L**2 * ((1 / I3 - 1 / I2) - (1 / I1 - 1 / I2) * s2)
    correct = (2 * alpha1 - G**2 / I2) - G**2 * (1 / I1 - 1 / I2) * s2
    printed = (2 * alpha1**2 - G**2 / I2) - G**2 * (1 / I1 - 1 / I2) * s2
    assert abs(lhs - correct) < mp.mpf(10) ** -25
    assert abs(lhs - printed) > 0.1


def test_eq140_and_eq144_as_printed():
    """L² (eq. 140) and H (eq. 144) in terms of κ, λ hold as printed."""
    kappa2, lam2, _, alpha1 = sadov_parameters(CIRCULATING)
    l, L, G = (mp.mpf(CIRCULATING[0]), mp.mpf(CIRCULATING[3]), mp.mpf(CIRCULATING[4]))
    s2 = mp.sin(l) ** 2
    L2 = G**2 * kappa2 / (kappa2 + lam2) * (1 - lam2 + (kappa2 + lam2) * s2) / (1 + kappa2 * s2)
    I1, I3 = mp.mpf(BODY.I1), mp.mpf(BODY.I3)
    H = G**2 / (2 * I1 * I3) * (I3 * lam2 + I1 * kappa2) / (kappa2 + lam2)
    assert abs(L2 - L**2) < mp.mpf(10) ** -25
    assert abs(H - alpha1) < mp.mpf(10) ** -25


def test_eq143_characteristic_is_minus_kappa2():
    """Π(κ², λ) in eq. 143 means ∫ dθ / ((1 + κ² sin²θ) √(1 − λ² sin²θ)), i.e. n = −κ²."""
    kappa2, lam2, _, _ = sadov_parameters(CIRCULATING)
    ref = reference_action(BODY, *CIRCULATING[0:1], CIRCULATING[3], CIRCULATING[4])
    corrected = eq143(CIRCULATING[4], kappa2, lam2, -1)
    literal = eq143(CIRCULATING[4], kappa2, lam2, +1)  # κ² = 5 > 1: a principal value
    assert abs(corrected / ref - 1) < 1e-14
    assert abs(literal / ref - 1) > 0.5


def test_incomplete_quadrature_of_L_ends_with_F_not_K():
    """∫_{π/2}^{l} L dl = (G/κ)√((1+κ²)/(κ²+λ²)) [(κ²+λ²) Π(−κ²; z|λ²) − λ² F(z|λ²)];
    the printed ``λ² K(λ)`` does not vanish at the lower limit ``z = 0``."""
    kappa2, lam2, z, alpha1 = sadov_parameters(CIRCULATING)
    I1, I2, I3 = (mp.mpf(BODY.I1), mp.mpf(BODY.I2), mp.mpf(BODY.I3))
    G = mp.mpf(CIRCULATING[4])

    def L_of(t):
        p = mp.sin(t) ** 2 / I1 + mp.cos(t) ** 2 / I2
        return mp.sqrt((2 * alpha1 - G**2 * p) / (1 / I3 - p))

    direct = mp.quad(L_of, [mp.pi / 2, mp.mpf(CIRCULATING[0]) + 2 * mp.pi])
    z_end = z + 2 * mp.pi  # the path from l = π/2 to l0 + 2π; z runs continuously with l
    coef = G / mp.sqrt(kappa2) * mp.sqrt((1 + kappa2) / (kappa2 + lam2))
    corrected = coef * ((kappa2 + lam2) * mp.ellippi(-kappa2, z_end, lam2) - lam2 * mp.ellipf(z_end, lam2))
    printed = coef * ((kappa2 + lam2) * mp.ellippi(-kappa2, z_end, lam2) - lam2 * mp.ellipk(lam2))
    assert abs(corrected / direct - 1) < 1e-25
    assert abs(printed / direct - 1) > 1e-3


@pytest.mark.slow
def test_eq143_for_libration_is_the_real_part_in_reciprocal_modulus_form():
    """For λ > 1, K(λ) and Π(κ², λ) are complex; the libration action is the real part,
    ``(2G√(1+κ²))/(πκλ√(κ²+λ²)) [(κ²+λ²) Π(−κ²/λ²|1/λ²) − λ² K(1/λ²)]``."""
    kappa2, lam2, _, _ = sadov_parameters(LIBRATING)
    assert lam2 > 1
    G = LIBRATING[4]
    ref = reference_action(BODY, LIBRATING[0], LIBRATING[3], G)
    literal = eq143(G, kappa2, lam2, -1)
    assert abs(mp.im(literal)) > 1e-3  # not a real action
    assert abs(mp.re(literal) / ref - 1) < 1e-14
    assert abs(real_action(G, kappa2, lam2) / ref - 1) < 1e-14


def test_separatrix_value_and_eq145_derivative():
    """f(1) = (2/π) arctan κ, and ∂I_ℓ/∂λ = −(2/π) G κ λ √(1+κ²) K(λ)/(κ²+λ²)^{3/2} (eq. 145),
    with K(λ) → K(1/λ²)/λ for λ > 1, against central differences of the action."""
    kappa2 = mp.mpf(5)
    near_one = real_action(1, kappa2, 1 - mp.mpf(10) ** -20)
    assert abs(near_one - 2 / mp.pi * mp.atan(mp.sqrt(kappa2))) < 1e-17
    h = mp.mpf(10) ** -12
    for lam in (mp.sqrt(mp.mpf("0.4")), mp.sqrt(mp.mpf("2.5"))):
        lam2 = lam**2
        numeric = (real_action(1, kappa2, (lam + h) ** 2) - real_action(1, kappa2, (lam - h) ** 2)) / (2 * h)
        K = mp.ellipk(lam2) if lam2 < 1 else mp.ellipk(1 / lam2) / lam
        formula = -2 / mp.pi * mp.sqrt(kappa2) * lam * mp.sqrt(1 + kappa2) * K / (kappa2 + lam2) ** 1.5
        assert abs(numeric / formula - 1) < 1e-15


def printed_angles(state, sign_in_phi_g):
    """Eq. 147 evaluated literally (characteristic −κ²), optionally with the sign of L."""
    kappa2, lam2, z, _ = sadov_parameters(state)
    K, F = mp.ellipk(lam2), mp.ellipf(z, lam2)
    phi_l = mp.pi / 2 * F / K
    sign = mp.sign(state[3]) if sign_in_phi_g else 1
    coef = mp.sqrt((kappa2 + lam2) * (1 + kappa2)) / mp.sqrt(kappa2)
    phi_g = state[1] + sign * coef * (mp.ellippi(-kappa2, z, lam2) - mp.ellippi(-kappa2, lam2) * F / K)
    return float(phi_l), float(phi_g)


@pytest.mark.parametrize("L", [0.95, -0.95])
def test_eq147_holds_up_to_the_origin_of_phi_l_and_the_sign_of_L(L):
    """The library's angles are eq. 147 with φ_ℓ shifted by π/2 (origin at the meridian of b2
    instead of b1) and with ``σ = sign L`` in φ_g; the printed φ_g (no σ) is wrong for L < 0."""
    state = (*CIRCULATING[:3], L, *CIRCULATING[4:])
    s = andoyer_to_sadov(BODY, *state)
    phi_l, phi_g = printed_angles(state, sign_in_phi_g=True)
    assert abs(circle(s.phi_l - phi_l - np.pi / 2)) < 1e-14
    assert abs(circle(s.phi_g - phi_g)) < 1e-14
    unsigned = printed_angles(state, sign_in_phi_g=False)[1]
    assert (abs(circle(s.phi_g - unsigned)) < 1e-14) == (L > 0)


def test_printed_phi_g_does_not_advance_uniformly_for_negative_L():
    """Along a DOP853 trajectory with L < 0, eq. 147 without ``sign L`` oscillates by O(0.1) rad
    about the uniform advance, while the corrected φ_g stays on it."""
    state = (CIRCULATING[0], CIRCULATING[1], 0.0, -0.95, 1.0, 0.2)
    w = sadov_frequencies(BODY, andoyer_to_sadov(BODY, *state).I_l, 1.0)
    t = np.linspace(0, 2 * np.pi / abs(float(w.omega_l)), 40)
    sol = solve_ivp(
        lambda _, y: np.array(andoyer_equations(BODY, *y)),
        (0, t[-1]),
        state,
        method="DOP853",
        rtol=1e-12,
        atol=1e-12,
        t_eval=t,
    )
    spread = {}
    for signed in (True, False):
        phi = np.array([printed_angles(tuple(y), signed)[1] for y in sol.y.T])
        residual = circle(phi - phi[0] - float(w.omega_g) * t)
        spread[signed] = np.ptp(residual)
    assert spread[True] < 1e-9
    assert spread[False] > 0.05
