"""The expansion of the disturbing function: jets, Kepler orbits, pair averages, harmonics, GR.

Independent checks: jet arithmetic against numpy polynomials; the Kepler-orbit jets against
:func:`andoyer.planetary.orbits.elements.elements_to_state` (Newton's solution of Kepler's
equation); the quadratic coefficients against Laplace coefficients (Murray & Dermott 1999,
§7.2: the classical secular disturbing function); every coefficient to degree 4 against a
least-squares fit of the directly averaged ``1/|r_j − r_k|`` (a plain double trapezoid over the
two mean longitudes at finite eccentricities and inclinations); a harmonic of ``H_1`` against
the direct Fourier transform of ``H_1`` itself.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from andoyer.planetary.orbits.disturbing import (
    kepler_jets,
    pair_expansion,
    pair_grid_size,
    relativity_constant,
    to_poincare,
)
from andoyer.planetary.orbits.elements import elements_to_state
from andoyer.planetary.orbits.jets import JetSpace
from andoyer.planetary.orbits.laplace import laplace_coefficient

ARCSEC = np.pi / (180.0 * 3600.0)


def evaluate(space: JetSpace, jet: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Σ c_m Π values^m, for values of shape (..., V)."""
    monomials = np.prod(values[..., None, :] ** space.exponents, axis=-1)
    return np.asarray(jet) @ monomials


def poincare_uv(e, i, varpi, node):
    """u = x/√Λ, v = y/√Λ of Poincaré's variables from the elements."""
    root = np.sqrt(1.0 - e * e)
    u = np.sqrt(2.0 * (1.0 - root)) * np.exp(1j * varpi)
    v = np.sqrt(2.0 * root * (1.0 - np.cos(i))) * np.exp(1j * node)
    return u, v


@given(
    st.lists(st.floats(-2, 2), min_size=6, max_size=6),
    st.lists(st.floats(-2, 2), min_size=6, max_size=6),
    st.floats(-1, 1),
    st.floats(-1, 1),
)
@settings(max_examples=30, deadline=None)
def test_jet_product_matches_polynomial_product(a, b, x, y):
    space = JetSpace(2, 2)
    ja, jb = np.array(a, dtype=complex), np.array(b, dtype=complex)
    point = np.array([x, y])
    full = evaluate(space, ja, point) * evaluate(space, jb, point)
    # The product truncated at degree 2 differs from the full product by its degree 3-4 terms.
    big = JetSpace(2, 4)
    exact = big.multiply(big.embed(ja, space, [0, 1]), big.embed(jb, space, [0, 1]))
    assert evaluate(big, exact, point) == pytest.approx(full, abs=1e-12)
    truncated = space.multiply(ja, jb)
    low = big.embed(truncated, space, [0, 1])
    high = exact - low
    assert np.all(big.degrees[np.abs(high) > 1e-14] > 2)


def test_jet_power_and_exp_match_taylor_series():
    space = JetSpace(1, 6)
    w = space.variable(0)
    # (1 + w)^(-1/2) and exp(2w): Taylor coefficients by hand.
    half = space.power(space.add_constant(w, 1.0), -0.5)
    expected = [1, -1 / 2, 3 / 8, -5 / 16, 35 / 128, -63 / 256, 231 / 1024]
    np.testing.assert_allclose(half.real, expected, rtol=1e-15)
    np.testing.assert_allclose(
        space.exp(2.0 * w).real, [2.0**n / np.prod(np.arange(1, n + 1)) for n in range(7)]
    )


def test_jet_conjugate_swaps_pairs():
    space = JetSpace(2, 2)
    jet = space.zeros()
    jet[space.index[(2, 0)]] = 1 + 2j  # (1+2i) u²
    conj = space.conjugate(jet, [(0, 1)])
    assert conj[space.index[(0, 2)]] == 1 - 2j
    assert np.count_nonzero(conj) == 1


def test_kepler_jets_match_elements_to_state():
    # The degree-4 jets differ from the exact Kepler orbit (position and ∂/∂λ) by O(scale^5):
    # halving every eccentricity and inclination divides the largest difference by 2^5.
    rng = np.random.default_rng(7)
    lam = 2 * np.pi * np.arange(32) / 32
    r, dr = kepler_jets(lam, 4)
    space = JetSpace(4, 4)
    shapes = [(rng.uniform(0.2, 1.0, 2), rng.uniform(0, 2 * np.pi, 2)) for _ in range(4)]

    def worst(scale):
        out = 0.0
        for (e, i), (varpi, node) in shapes:
            u, v = poincare_uv(scale * e, scale * i, varpi, node)
            point = np.array([u, np.conj(u), v, np.conj(v)])
            pos, vel = elements_to_state(1.0, 1.0, scale * e, scale * i, node, varpi, lam)
            jet_pos = np.stack([evaluate(space, r[c], point) for c in range(3)], axis=-1)
            jet_vel = np.stack([evaluate(space, dr[c], point) for c in range(3)], axis=-1)  # n a = 1
            assert np.abs(jet_pos.imag).max() < 1e-13
            out = max(out, np.abs(jet_pos.real - pos).max(), np.abs(jet_vel.real - vel).max())
        return out

    coarse, fine = worst(0.04), worst(0.02)
    assert coarse < 10 * 0.04**5
    assert 28 < coarse / fine < 36


def test_pair_grid_size_resolves_the_harmonics():
    assert pair_grid_size(0.5, 4) % 16 == 0
    assert pair_grid_size(0.72, 4) > pair_grid_size(0.5, 4) > pair_grid_size(0.2, 4)


@pytest.fixture(scope="module")
def pair():
    # A Jupiter-Saturn-like pair, with the second-order harmonics kept (|k| ≤ 6).
    sun, masses, axes = 1.0, (1e-3, 3e-4), (1.0, 1.85)
    return sun, masses, axes, pair_expansion(sun, masses, axes, degree=4, max_harmonic=6)


@pytest.mark.slow
def test_pair_quadratic_terms_are_laplace_coefficients(pair):
    # ⟨H_1⟩ = −(m_j m_k/a_k)[½ b_{1/2}^(0) + ⅛ α b_{3/2}^(1)(e_j² + e_k² − I_j² − I_k²)
    #          − ¼ α b_{3/2}^(2) e_j e_k cos Δϖ + ¼ α b_{3/2}^(1) I_j I_k cos ΔΩ] (M&D §7.2).
    _, (mj, mk), (aj, ak), expansion = pair
    space = JetSpace(8, 4)
    alpha = aj / ak
    b1, b2 = laplace_coefficient(1.5, 1, alpha), laplace_coefficient(1.5, 2, alpha)
    b0 = laplace_coefficient(0.5, 0, alpha)
    unit = -mj * mk / ak

    def c(*m):
        return expansion.mean[space.index[m]] / unit

    assert c(0, 0, 0, 0, 0, 0, 0, 0) == pytest.approx(0.5 * b0, rel=1e-13)
    assert c(1, 1, 0, 0, 0, 0, 0, 0) == pytest.approx(alpha * b1 / 8, rel=1e-12)
    assert c(0, 0, 0, 0, 1, 1, 0, 0) == pytest.approx(alpha * b1 / 8, rel=1e-12)
    assert c(1, 0, 0, 0, 0, 1, 0, 0) == pytest.approx(-alpha * b2 / 8, rel=1e-12)
    assert c(0, 0, 1, 1, 0, 0, 0, 0) == pytest.approx(-alpha * b1 / 8, rel=1e-12)
    assert c(0, 0, 1, 0, 0, 0, 0, 1) == pytest.approx(alpha * b1 / 8, rel=1e-12)


def direct_average(sun, masses, axes, elements, nodes=96):
    """⟨−m_j m_k/|r_j − r_k|⟩ over both mean longitudes: a plain double trapezoid on exact orbits."""
    (mj, mk), (aj, ak) = masses, axes
    lam = 2 * np.pi * np.arange(nodes) / nodes
    (ej, ij, wj, Oj), (ek, ik, wk, Ok) = elements
    rj, _ = elements_to_state(sun + mj, aj, ej, ij, Oj, wj, lam)
    rk, _ = elements_to_state(sun + mk, ak, ek, ik, Ok, wk, lam)
    distance = np.linalg.norm(rj[:, None, :] - rk[None, :, :], axis=-1)
    return -mj * mk * np.mean(1.0 / distance)


@pytest.mark.slow
def test_pair_coefficients_match_direct_quadrature(pair):
    # Fit the directly averaged interaction at 600 random small eccentricities and inclinations
    # (≤ 0.015) with every monomial the secular part may hold to degree 6 (d'Alembert: zero total
    # phase, even in the inclinations); the degree-6 monomials absorb the truncation, and each
    # fitted coefficient of degree ≤ 4 must equal the expansion's.
    sun, masses, axes, expansion = pair
    big = JetSpace(8, 6)
    e = big.exponents
    charge = e[:, 0] - e[:, 1] + e[:, 2] - e[:, 3] + e[:, 4] - e[:, 5] + e[:, 6] - e[:, 7]
    even = (e[:, 2] + e[:, 3] + e[:, 6] + e[:, 7]) % 2 == 0
    basis = np.nonzero((charge == 0) & even & (big.degrees > 0))[0]
    rng = np.random.default_rng(2024)
    rows, values = [], []
    b0 = laplace_coefficient(0.5, 0, axes[0] / axes[1])
    constant = -masses[0] * masses[1] / axes[1] * 0.5 * b0
    for _ in range(600):
        el = [(0.015 * rng.uniform(), 0.015 * rng.uniform(), *rng.uniform(0, 2 * np.pi, 2)) for _ in range(2)]
        uj, vj = poincare_uv(el[0][0], el[0][1], el[0][2], el[0][3])
        uk, vk = poincare_uv(el[1][0], el[1][1], el[1][2], el[1][3])
        point = np.array([uj, np.conj(uj), vj, np.conj(vj), uk, np.conj(uk), vk, np.conj(vk)])
        rows.append(np.prod(point[None, :] ** e[basis], axis=1))
        values.append(direct_average(sun, masses, axes, el) - constant)
    M = np.array(rows)
    # Real unknowns: the real and imaginary parts of each coefficient (H is real: Re of Σ c M).
    design = np.concatenate([M.real, -M.imag], axis=1)
    scale = np.abs(design).max(axis=0)
    scale[scale == 0] = 1.0  # the imaginary part of a real (self-conjugate) monomial
    solution, *_ = np.linalg.lstsq(design / scale, np.array(values), rcond=None)
    solution /= scale
    fitted = solution[: basis.size] + 1j * solution[basis.size :]
    small = JetSpace(8, 4)
    # Conjugate monomials share the real part: compare c_m + c_m̄ (the function's real coefficient).
    checked = 0
    for k, b in enumerate(basis):
        if big.degrees[b] > 4:
            continue
        m = tuple(e[b])
        mbar = (m[1], m[0], m[3], m[2], m[5], m[4], m[7], m[6])
        kb = int(np.nonzero(basis == big.index[mbar])[0][0])
        fit = fitted[k] + np.conj(fitted[kb])
        exact = expansion.mean[small.index[m]] + np.conj(expansion.mean[small.index[mbar]])
        scale_m = np.abs(expansion.mean[small.degrees == big.degrees[b]]).max()
        assert abs(fit - exact) < 1e-5 * scale_m, (m, fit, exact)
        checked += 1
    assert checked == 60


def test_pair_harmonic_matches_direct_fourier_transform(pair):
    # The 5:2-like harmonic k = (−2, 5) of H_1 (direct + indirect) at small finite elements, from
    # the expansion and from a direct 2-d Fourier transform of H_1 on exact Kepler orbits.
    sun, (mj, mk), (aj, ak), expansion = pair
    space = JetSpace(8, 4)
    k = np.array([-2, 5])
    row = int(np.nonzero(np.all(expansion.harmonics == k, axis=1))[0][0])
    nodes = 96
    lam = 2 * np.pi * np.arange(nodes) / nodes
    rng = np.random.default_rng(5)
    for scale in (0.02, 0.01):
        el = [
            (scale * rng.uniform(0.5, 1), scale * rng.uniform(0.5, 1), *rng.uniform(0, 2 * np.pi, 2))
            for _ in range(2)
        ]
        (ej, ij, wj, Oj), (ek, ik, wk, Ok) = el
        rj, vj = elements_to_state(sun + mj, aj, ej, ij, Oj, wj, lam)
        rk, vk = elements_to_state(sun + mk, ak, ek, ik, Ok, wk, lam)
        beta_j, beta_k = sun * mj / (sun + mj), sun * mk / (sun + mk)
        h = -mj * mk / np.linalg.norm(rj[:, None] - rk[None, :], axis=-1)
        h += beta_j * beta_k / sun * np.einsum("ac,bc->ab", vj, vk)
        direct = np.mean(h * np.exp(-1j * (k[0] * lam[:, None] + k[1] * lam[None, :])))
        uj, wv = poincare_uv(ej, ij, wj, Oj)
        uk, wk2 = poincare_uv(ek, ik, wk, Ok)
        point = np.array([uj, np.conj(uj), wv, np.conj(wv), uk, np.conj(uk), wk2, np.conj(wk2)])
        series = evaluate(space, expansion.amplitudes[row], point)
        # Degree 3 is the leading order; degree 5 is the first left out.
        assert abs(series - direct) < 0.02 * abs(direct) * (scale / 0.02) ** 2


def test_to_poincare_scales_by_lambda():
    space = JetSpace(8, 2)
    jet = space.zeros()
    jet[space.index[(1, 1, 0, 0, 0, 0, 0, 0)]] = 2.0  # 2 u_j ū_j = 2 |x_j|²/Λ_j
    jet[space.index[(1, 0, 0, 0, 0, 0, 0, 0)]] = 1.0  # nonzero phase: dropped
    terms = to_poincare(jet, space, (1, 3), (4.0, 9.0), count=4)
    key = tuple(1 if i in (1, 5) else 0 for i in range(16))  # x_1, x̄_1 of 4 planets
    assert terms == {key: 0.5}


def test_relativity_constant_gives_mercury_perihelion_rate():
    # Einstein: Δϖ per orbit 6πGM/(c² a (1 − e²)); per century for Mercury 42.98″ (a = 0.3871 au,
    # e = 0.2056, P = 87.969 d). The model's rate is K/(Λ(1 − e²)).
    sun, gm, a, e, c = 39.476926421, 6.5536e-6, 0.38709927, 0.20563593, 63241.07708
    K = relativity_constant(sun, np.array([gm]), np.array([a]), c)[0]
    beta = sun * gm / (sun + gm)
    rate = K / (beta * np.sqrt((sun + gm) * a)) / (1 - e * e)
    einstein = 6 * np.pi * sun / (c * c * a * (1 - e * e)) / (87.969 / 365.25)
    assert rate == pytest.approx(einstein, rel=1e-4)
    assert rate / ARCSEC * 100 == pytest.approx(42.98, abs=0.02)
