"""The long secular orbit model: its linear part, its flow, its invariants, and the N-body solution.

Independent checks: the quadratic part against the Laplace–Lagrange matrices of
:mod:`andoyer.planetary.orbits.laplace_lagrange` (Murray & Dermott's formulas, another code);
the integrator's order on a synthetic Hamiltonian (errors of three step sizes against a fine
run); the conservation of the secular energy and of the angular momentum deficit (exact
invariants of the averaged system); the orbit against the N-body integration (REBOUND) over
±20 kyr; the fundamental frequencies against the N-body values of
``scripts/check_outer_frequencies.py`` and La2004's confirmed ones (slow).
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from scipy.linalg import expm

from andoyer.planetary.orbits import NBodyOrbit, OrbitHistory, SecularOrbit, orbit_history
from andoyer.planetary.orbits.disturbing import pair_expansion, second_order, to_poincare
from andoyer.planetary.orbits.jets import JetSpace
from andoyer.planetary.orbits.laplace_lagrange import LA2004_G, LA2004_S, secular_matrices
from andoyer.planetary.orbits.planets import PLANETS
from andoyer.planetary.orbits.secular import MAX_SPAN, secular_model, vectors_from_poincare
from andoyer.planetary.orbits.secular_flow import (
    FlowTerms,
    default_step,
    energy,
    hermite,
    integrate,
    lawson_matrices,
)

ARCSEC = np.pi / (180.0 * 3600.0)


@pytest.fixture
def cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    return tmp_path


def run(terms: FlowTerms, w0: np.ndarray, h: float, steps: int, keep=None, samples: int = 1):
    """The state after ``steps`` steps of ``h``, and the kept samples (``samples`` per step)."""
    keep = np.arange(w0.size) if keep is None else np.asarray(keep)
    tableau = lawson_matrices(terms.linear, h, samples)
    w = np.array(w0, dtype=complex)
    out_w = np.empty((steps * samples + 1, keep.size), dtype=complex)
    out_dw = np.empty_like(out_w)
    extreme = np.zeros(w0.size)
    integrate(w, steps, h, *tableau, *terms.arrays(), terms.linear, keep, out_w, out_dw, extreme)
    return w, out_w, out_dw


def test_secular_is_an_orbit_history():
    orbit = orbit_history("secular", body="mars")
    assert isinstance(orbit, SecularOrbit)
    assert isinstance(orbit, OrbitHistory)
    assert orbit.span == (-MAX_SPAN, MAX_SPAN)
    assert orbit.has_eccentricity


def second_order_linear(model, j: int, k: int) -> np.ndarray:
    """The linear flow (2P × 2P) of the quadratic terms of pair (j, k)'s second-order Hamiltonian."""
    settings = model.settings
    expansion = pair_expansion(
        model.sun, (model.gm[j], model.gm[k]), (model.a[j], model.a[k]), settings["degree"],
        max_harmonic=settings["max_harmonic"],
    )  # fmt: skip
    # Degree 4 is enough for the quadratic terms (each product is exact to the jet's degree).
    space = JetSpace(8, settings["degree"])
    k2 = second_order(
        expansion, (model.Lambda[j], model.Lambda[k]), (model.a[j], model.a[k]), (model.n[j], model.n[k]),
        settings["degree"],
    )  # fmt: skip
    terms = to_poincare(k2, space, (j, k), (model.Lambda[j], model.Lambda[k]), len(PLANETS))
    quadratic = [key for key in terms if sum(key) == 2]
    return FlowTerms.from_polynomial(
        np.array(quadratic), np.array([terms[key] for key in quadratic]), len(PLANETS)
    ).linear


def check_pair_linear_part(model, j: int, k: int, second: np.ndarray) -> None:
    """Model's coupling of j and k, less its second-order part, against Laplace–Lagrange."""
    A, B = secular_matrices(model.a, model.gm, model.sun)
    L = model.terms.linear
    P = len(PLANETS)
    for row, col in ((j, k), (k, j)):
        # z = x/√Λ: ż_j = i A_jk (1 + m_j/m_0) z_k (Poincaré's β_j against Murray & Dermott's m_j).
        scale = np.sqrt(model.Lambda[col] / model.Lambda[row])
        factor = 1.0 + model.gm[row] / model.sun
        for shift, M in ((0, A), (P, B)):
            first = (L[shift + row, shift + col] - second[shift + row, shift + col]) * scale / 1j
            # 1e-9: Mercury–Neptune's coupling (α = 0.013, b₃/₂⁽²⁾ ∝ α²) is 4e-11 off in its last digits.
            assert first.real == pytest.approx(M[row, col] * factor, rel=1e-9), (row, col, shift)
            assert abs(first.imag) <= 1e-12 * abs(M[row, col])


@pytest.mark.slow
def test_secular_linear_part_reproduces_laplace_lagrange_jupiter_saturn():
    # The quadratic part of the model is the Laplace–Lagrange theory in Poincaré variables plus
    # the quadratic terms of the second-order Hamiltonian K₂ (for Jupiter and Saturn 6.7 % of the
    # eccentricities' coupling, 0.3 % of the inclinations'). With K₂'s part recomputed and taken
    # away, the rest must be Murray & Dermott's A_jk, B_jk (laplace_lagrange.secular_matrices,
    # another code) with the model's own a, masses.
    model = secular_model()
    j, k = 4, 5
    second = second_order_linear(model, j, k)
    P = len(PLANETS)
    # The second-order part matters here: without taking it away the comparison fails.
    assert abs(second[j, k] / model.terms.linear[j, k]) > 0.05
    assert abs(second[P + j, P + k] / model.terms.linear[P + j, P + k]) > 1e-3
    check_pair_linear_part(model, j, k, second)


@pytest.mark.slow
def test_secular_linear_part_reproduces_laplace_lagrange_every_pair():
    # Every pair's coupling, and every planet's own rate: the diagonal is Σ_k A_jj-parts of the
    # pairs, the pairs' second-order diagonal terms and, for the eccentricities, the Sun's
    # relativistic perihelion precession at e → 0, 3 μ^{3/2}/(c² a^{5/2}) rad/yr (Einstein).
    model = secular_model()
    A, B = secular_matrices(model.a, model.gm, model.sun)
    P = len(PLANETS)
    total_second = np.zeros((2 * P, 2 * P), dtype=complex)
    for j in range(P):
        for k in range(j + 1, P):
            second = second_order_linear(model, j, k)
            check_pair_linear_part(model, j, k, second)
            total_second += second
    c = 299792.458 * 86400.0 * 365.25 / 149597870.700  # au/yr: SI c, IAU 2012 au
    mu = model.sun + model.gm
    relativity = 3.0 * mu**1.5 / (c * c * model.a**2.5)
    L = model.terms.linear
    for j in range(P):
        factor = 1.0 + model.gm[j] / model.sun
        rate_x = (L[j, j] - total_second[j, j]) / 1j - relativity[j]
        rate_y = (L[P + j, P + j] - total_second[P + j, P + j]) / 1j
        assert rate_x.real == pytest.approx(A[j, j] * factor, rel=1e-9), j
        assert rate_y.real == pytest.approx(B[j, j] * factor, rel=1e-9), j


def test_secular_flow_terms_refuse_a_quadratic_term_without_a_conjugate():
    # x₀ y₀ is not of the form w_a w̄_b: it has no place in the linear flow.
    with pytest.raises(ValueError, match=r"expected quadratic terms of the form w_a w̄_b"):
        FlowTerms.from_polynomial(np.array([[1, 0, 1, 0]]), np.array([-0.5]), 1)


def synthetic_terms():
    """Two 'planets': a linear part and a few real quartic and sextic terms (not physical)."""
    P = 2
    rows, coefficients = [], []

    def add(pairs, c):
        m = np.zeros(4 * P, dtype=np.int64)
        for var, power in pairs:
            m[var] += power
        rows.append(m)
        coefficients.append(c)

    x0, x1, xb0, xb1, y0, y1, yb0, yb1 = range(8)
    add([(x0, 1), (xb0, 1)], -0.5)
    add([(x1, 1), (xb1, 1)], -0.2)
    add([(x0, 1), (xb1, 1)], 0.05)
    add([(x1, 1), (xb0, 1)], 0.05)
    add([(y0, 1), (yb0, 1)], 0.3)
    add([(y1, 1), (yb1, 1)], 0.1)
    add([(x0, 2), (xb0, 2)], 0.4)
    add([(x0, 1), (xb0, 1), (y1, 1), (yb1, 1)], -0.7)
    add([(x0, 2), (xb1, 1), (xb0, 1)], 0.3)
    add([(x1, 1), (x0, 1), (xb0, 2)], 0.3)
    add([(x0, 1), (xb1, 1), (y0, 1), (yb1, 1)], 0.2)
    add([(x1, 1), (xb0, 1), (y1, 1), (yb0, 1)], 0.2)
    add([(x0, 3), (xb0, 3)], -0.1)
    return FlowTerms.from_polynomial(np.array(rows), np.array(coefficients), P), np.array(
        [0.3 + 0.1j, -0.2j, 0.25, 0.1 - 0.1j]
    )


def flow_mpmath(exponents, coefficients, P, w, gr=None, Lambda=None):
    """``ẇ = −2i ∂H/∂w̄`` at ``w`` in 40-digit arithmetic, term by term from the exponents."""
    import mpmath

    with mpmath.workdps(40):
        z = [mpmath.mpc(v.real, v.imag) for v in w]
        values = z[:P] + [mpmath.conj(v) for v in z[:P]] + z[P:] + [mpmath.conj(v) for v in z[P:]]
        bars = list(range(P, 2 * P)) + list(range(3 * P, 4 * P))
        out = []
        for column in bars:
            total = mpmath.mpc(0)
            for m, c in zip(exponents, coefficients, strict=True):
                if m[column]:
                    term = mpmath.mpf(float(c)) * int(m[column])
                    for v, power in enumerate(m):
                        term *= values[v] ** (int(power) - (v == column))
                    total += term
            out.append(-2j * total)
        for j in range(P if gr is not None else 0):
            # H ∋ −K/(1 − |x|²/(2Λ)): ẋ = −2i ∂H/∂x̄ = i (K/Λ) x / (1 − |x|²/(2Λ))².
            s = abs(z[j]) ** 2 / (2 * mpmath.mpf(float(Lambda[j])))
            out[j] += 1j * mpmath.mpf(float(gr[j])) / mpmath.mpf(float(Lambda[j])) * z[j] / (1 - s) ** 2
        return np.array([complex(v) for v in out])


@pytest.mark.parametrize(("P", "count", "seed"), [(3, 60, 22), (1, 7, 1), (2, 23, 2), (2, 40, 3)])
def test_secular_flow_right_hand_side_matches_mpmath_on_random_terms(P, count, seed):
    # The product-tree kernel (shared partial products, groups summed four side by side) against
    # the derivative taken term by term in 40 digits: P planets, random terms of degree 2 (w_a w̄_b)
    # to 8, relativity on; group counts that do and do not fill the last batch of four.
    rng = np.random.default_rng(seed)
    exponents = []
    for a in range(2 * P):
        m = np.zeros(4 * P, dtype=np.int64)
        plain = a if a < P else P + a  # the column of x_a or y_(a−P) among x, x̄, y, ȳ
        m[plain] += 1
        m[plain + P] += 1
        exponents.append(m)
    while len(exponents) < count:
        m = np.zeros(4 * P, dtype=np.int64)
        for v in rng.integers(0, 4 * P, size=rng.integers(3, 9)):
            m[v] += 1
        if m.sum() > 2:
            exponents.append(m)
    exponents = np.array(exponents)
    coefficients = rng.normal(size=len(exponents))
    gr, Lambda = np.array([0.3, 0.0, 0.1])[:P], np.array([1.5, 2.0, 3.0])[:P]
    terms = FlowTerms.from_polynomial(exponents, coefficients, P, gr, Lambda)
    w0 = rng.normal(size=2 * P) * 0.4 + 1j * rng.normal(size=2 * P) * 0.4
    _, _, out_dw = run(terms, w0, 1.0, 0)
    expected = flow_mpmath(exponents, coefficients, P, w0, gr, Lambda)
    np.testing.assert_allclose(out_dw[0], expected, rtol=0, atol=1e-13 * np.abs(expected).max())


@pytest.mark.slow
def test_secular_flow_right_hand_side_of_the_model_matches_mpmath():
    # The shipped Hamiltonian, every term (no pruning), at the J2000 state: the kernel's ẇ against
    # the term-by-term derivative in 40 digits.
    import json
    from importlib import resources

    from andoyer.planetary.orbits.disturbing import relativity_constant
    from andoyer.planetary.orbits.nbody import C_AU_PER_YEAR

    raw = json.loads(
        resources.files("andoyer.planetary.orbits").joinpath("data/secular_model.json").read_text("utf-8")
    )
    P = len(raw["planets"])
    exponents = np.zeros((len(raw["terms"]), 4 * P), dtype=np.int64)
    for row, (factors, _, _) in enumerate(raw["terms"]):
        for var, power in factors:
            exponents[row, var] = power
    coefficients = np.array([re for _, re, _ in raw["terms"]])
    Lambda = np.array(raw["Lambda"])
    gr = relativity_constant(raw["sun_gm"], np.array(raw["gm"]), np.array(raw["a"]), C_AU_PER_YEAR)
    terms = FlowTerms.from_polynomial(exponents, coefficients, P, gr, Lambda)
    w0 = np.array([complex(*z) for z in raw["x0"] + raw["y0"]])
    _, _, out_dw = run(terms, w0, 1.0, 0)
    expected = flow_mpmath(exponents, coefficients, P, w0, gr, Lambda)
    np.testing.assert_allclose(out_dw[0], expected, rtol=1e-12, atol=1e-15 * np.abs(expected).max())


def test_secular_flow_is_of_order_eight():
    # Lawson–DOP853: halving the step divides the error at a fixed time by 2⁸.
    terms, w0 = synthetic_terms()
    T = 8.0
    reference, _, _ = run(terms, w0, T / 512, 512)
    errors = [np.abs(run(terms, w0, T / n, n)[0] - reference).max() for n in (8, 16, 32)]
    ratios = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((ratios > 7.4) & (ratios < 9.0)), ratios


def test_secular_flow_linear_part_is_exact():
    # With only quadratic terms the Lawson step is the matrix exponential, whatever the step.
    terms, w0 = synthetic_terms()
    linear = FlowTerms.from_polynomial(np.zeros((0, 8), dtype=np.int64), np.zeros(0), 2)
    linear = FlowTerms(**{**linear.__dict__, "linear": terms.linear})
    w, _, _ = run(linear, w0, 3.0, 4)
    np.testing.assert_allclose(w, expm(12.0 * terms.linear) @ w0, atol=1e-14)


def test_secular_flow_samples_within_a_step_follow_the_linear_flow_exactly():
    # With only quadratic terms v is constant: the samples within a step are e^{Lτ} w0 and L e^{Lτ} w0.
    terms, w0 = synthetic_terms()
    linear = FlowTerms.from_polynomial(np.zeros((0, 8), dtype=np.int64), np.zeros(0), 2)
    linear = FlowTerms(**{**linear.__dict__, "linear": terms.linear})
    _, out_w, out_dw = run(linear, w0, 3.0, 2, samples=3)
    expected = np.array([expm(t * terms.linear) @ w0 for t in np.arange(7.0)])
    np.testing.assert_allclose(out_w, expected, atol=1e-14)
    np.testing.assert_allclose(out_dw, expected @ terms.linear.T, atol=1e-14)


def test_secular_flow_samples_within_a_step_match_a_finer_run():
    # The samples between the steps (from the stages) against a run at a third of the step, whose
    # steps fall on them: the model over 100 kyr at twice the default step, three samples per step.
    # The steps themselves are those of a run without samples, bit for bit.
    model = secular_model()
    terms = model.terms
    h = default_step(terms.linear, 1.0 / 5.0)
    steps = 10
    w, out_w, out_dw = run(terms, model.w0, h, steps, samples=3)
    w1, plain, _ = run(terms, model.w0, h, steps)
    assert np.array_equal(out_w[::3], plain)
    assert np.array_equal(w, w1)
    _, fine, fine_dw = run(terms, model.w0, h / 6, steps * 6)
    error = np.abs(out_w - fine[::2]).max(axis=1)
    at_steps, within = error[::3].max(), np.delete(error, np.s_[::3]).max()
    # The samples within the steps are as good as the steps themselves (measured 4.1e-7 against
    # 5.0e-7, i.e. 1.4e-5 of the largest |w|, at this twice-default step).
    assert at_steps < 2e-5 * np.abs(model.w0).max()
    assert within < 1.2 * at_steps
    rate = np.abs(terms.linear) @ np.abs(model.w0)
    assert np.all(np.abs(out_dw - fine_dw[::2]).max(axis=0) < 1e-4 * rate)  # measured 6.7e-5


def test_secular_flow_interpreted_fallback_agrees_with_compiled(monkeypatch):
    # ANDOYER_NUMBA=0 runs the same kernels as plain Python (fresh copies of _jit and the module).
    import sys
    from pathlib import Path

    import andoyer._jit as andoyer_jit
    from andoyer.planetary.orbits import secular_flow as flow_module

    def fresh(module, name):
        spec = importlib.util.spec_from_file_location(name, Path(module.__file__))
        copy = importlib.util.module_from_spec(spec)
        monkeypatch.setitem(sys.modules, name, copy)
        spec.loader.exec_module(copy)
        return copy

    monkeypatch.setenv("ANDOYER_NUMBA", "0")
    monkeypatch.setitem(sys.modules, "andoyer._jit", fresh(andoyer_jit, "andoyer_jit_interpreted"))
    plain = fresh(flow_module, "andoyer_secular_flow_interpreted")
    assert not hasattr(plain.integrate, "py_func")
    terms, w0 = synthetic_terms()
    tableau = lawson_matrices(terms.linear, 0.7, 2)
    results = []
    for kernel in (integrate, plain.integrate):
        w = w0.astype(complex)
        out_w = np.empty((7, 4), dtype=complex)
        out_dw = np.empty_like(out_w)
        kernel(w, 3, 0.7, *tableau, *terms.arrays(), terms.linear, np.arange(4), out_w, out_dw, np.zeros(4))
        results.append((w, out_w, out_dw))
    for compiled, interpreted in zip(*results, strict=True):
        np.testing.assert_allclose(interpreted, compiled, rtol=0, atol=1e-15)


def test_secular_flow_conserves_energy_and_amd():
    # The secular Hamiltonian and the angular momentum deficit Σ(|x|² + |y|²)/2 are invariants of
    # the averaged flow (d'Alembert: every term is invariant under a common rotation). Over 1 Myr
    # they drift by the integrator's truncation only: below 2e-6 (energy) and 3e-7 (AMD) at the
    # default step (measured 7.4e-7 and 1.0e-7), and halving the step divides both by more than
    # 2^7 (order 8: measured 365 and 370).
    model = secular_model()
    terms = model.terms
    drift = []
    for fraction in (1.0 / 10.0, 1.0 / 20.0):
        h = default_step(terms.linear, fraction)
        w, _, _ = run(terms, model.w0, h, int(1e6 / h), keep=[0])
        e0, e1 = energy(terms, model.w0), energy(terms, w)
        amd0, amd1 = np.sum(np.abs(model.w0) ** 2) / 2, np.sum(np.abs(w) ** 2) / 2
        drift.append((abs(e1 - e0) / abs(e0), abs(amd1 - amd0) / amd0))
    (e_coarse, amd_coarse), (e_fine, amd_fine) = drift
    assert e_coarse < 2e-6
    assert amd_coarse < 3e-7
    assert e_coarse / e_fine > 128
    assert amd_coarse / amd_fine > 128


def test_hermite_interpolates_cubics_exactly():
    t = np.array([0.0, 2.0, 4.0])
    f = (t**3 - t)[:, None] + 0j
    df = (3 * t**2 - 1)[:, None] + 0j
    s = np.array([0.3, 1.7, 3.9])
    np.testing.assert_allclose(hermite(s, 0.0, 2.0, f, df)[:, 0].real, s**3 - s, rtol=1e-14)


def test_vectors_from_poincare_invert_the_elements():
    # x = √(2Λ(1 − √(1−e²))) e^{iϖ}, y = √(2Λ√(1−e²)(1 − cos i)) e^{iΩ} (the definitions).
    e, i, node, varpi, Lambda = 0.2, 0.3, 1.1, 2.5, 3.0
    root = np.sqrt(1 - e * e)
    x = np.sqrt(2 * Lambda * (1 - root)) * np.exp(1j * varpi)
    y = np.sqrt(2 * Lambda * root * (1 - np.cos(i))) * np.exp(1j * node)
    normal, ecc = vectors_from_poincare(np.array(x), np.array(y), Lambda, np.eye(3))
    np.testing.assert_allclose(
        normal, [np.sin(i) * np.sin(node), -np.sin(i) * np.cos(node), np.cos(i)], atol=1e-15
    )
    assert np.linalg.norm(ecc) == pytest.approx(e, rel=1e-14)
    assert ecc @ normal == pytest.approx(0.0, abs=1e-15)


def test_secular_orbit_j2000_is_the_invariable_frame_turned_back():
    # At J2000 the model's orbits are the mean orbits of the N-body solution: the Earth's normal is
    # within 0.001° of the ecliptic pole and its eccentricity 0.0167 (the ecliptic is the Earth's
    # osculating plane; the mean elements differ by the short-period terms).
    earth = SecularOrbit("earth")
    n = earth.normal(0.0)
    assert np.degrees(np.arccos(n[2])) < 1e-3
    assert np.linalg.norm(earth.eccentricity_vector(0.0)) == pytest.approx(0.0167, abs=2e-4)


@pytest.mark.slow
@pytest.mark.parametrize(("body", "normal_deg", "ecc"), [("earth", 0.003, 1.5e-4), ("mars", 0.008, 5e-4)])
def test_secular_orbit_follows_nbody_over_20_kyr(cache_dir, body, normal_deg, ecc):
    # Against the REBOUND integration of the Sun and the eight planets (osculating: its
    # short-period terms stay in the difference). Measured 2026-11-28 over ±20 kyr: Earth 0.0019°
    # and 7e-5, Mars 0.0055° and 3.2e-4.
    t = np.linspace(-2e4, 2e4, 401)
    secular, nbody = SecularOrbit(body), NBodyOrbit(body, progress=False)
    angle = np.arccos(np.clip(np.sum(secular.normal(t) * nbody.normal(t), axis=-1), -1, 1))
    assert np.degrees(angle).max() < normal_deg
    assert np.abs(secular.eccentricity_vector(t) - nbody.eccentricity_vector(t)).max() < ecc


@pytest.mark.slow
def test_secular_orbit_step_convergence_and_interpolation():
    # The default run (a 10-kyr step, two samples per step) against one at an eighth of its step
    # (its samples on the default run's samples and midpoints), over ±2 Myr: at the samples the
    # Earth's and Mars' normals differ by 0.47″ and 1.6″ (measured), e by 2e-6 and 1.1e-5 -- the
    # integration error, far below the model's distance from the N-body solution (0.1°-0.3° over
    # 1 Myr); midway between samples the cubic Hermite interpolation adds up to 1″ (Earth) and
    # 5″ (Mars), 2e-5 in e.
    for body in ("earth", "mars"):
        coarse = SecularOrbit(body)
        assert coarse.samples == 2
        fine = SecularOrbit(body, step=coarse.step / 8)
        for t, normal_arcsec, ecc in (
            (coarse.spacing * np.arange(-400, 401), 2.5, 2e-5),
            (coarse.spacing * (np.arange(-400, 400) + 0.5), 6.0, 3e-5),
        ):
            angle = np.arccos(np.clip(np.sum(coarse.normal(t) * fine.normal(t), axis=-1), -1, 1))
            assert angle.max() < normal_arcsec * ARCSEC
            assert np.abs(coarse.eccentricity_vector(t) - fine.eccentricity_vector(t)).max() < ecc


def test_secular_orbit_refuses_times_beyond_its_span():
    with pytest.raises(ValueError, match="expected times within the secular orbit's span"):
        SecularOrbit("mars").normal(-1.5e9)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"body": "pluto"}, "expected a planet among"),
        ({"step": 0.0}, "expected an integration step"),
        ({"step": np.nan}, "expected an integration step"),
        ({"max_span": 2e9}, "expected 0 < max_span"),
    ],
)
def test_secular_orbit_rejects_bad_options(kwargs, match):
    with pytest.raises(ValueError, match=match):
        SecularOrbit(**kwargs)


@pytest.mark.slow
def test_secular_frequencies_match_nbody_and_la2004():
    # FMFT over 19.7 Myr (65536 samples every 300 yr), as scripts/secular_frequencies.py does.
    # References: the N-body frequencies of the giant planets from DE421's states
    # (scripts/check_outer_frequencies.py, 8.2 Myr: g5 4.2454, g6 28.2583, g7 3.0880, g8 0.6727,
    # s6 −26.3384, s7 −2.9941, s8 −0.6924) and La2004's confirmed inner ones (g2, g3, g4, s3, s4).
    from andoyer.planetary.orbits.frequencies import fundamental_frequencies

    model = secular_model()
    t = -300.0 * np.arange(65536)[::-1]
    z = np.empty((8, t.size), complex)
    zeta = np.empty_like(z)
    for j, body in enumerate(PLANETS):
        x, y = SecularOrbit(body).poincare(t)
        z[j], zeta[j] = x / np.sqrt(model.Lambda[j]), y / np.sqrt(model.Lambda[j])
    g, s = fundamental_frequencies(z, zeta, 300.0, LA2004_G, LA2004_S)
    nbody_g = {5: 4.2454, 6: 28.2583, 7: 3.0880, 8: 0.6727}
    nbody_s = {6: -26.3384, 7: -2.9941, 8: -0.6924}
    # g6 is the model's worst frequency: 0.162″/yr below the N-body solution (docs/orbits.md,
    # the degree-4 truncation of the Jupiter-Saturn near-resonance); the others within 0.06″/yr.
    tolerance = {6: 0.2}
    for label, value in nbody_g.items():
        assert g[label - 1] == pytest.approx(value, abs=tolerance.get(label, 0.1))
    for label, value in nbody_s.items():
        assert s[label - 1] == pytest.approx(value, abs=0.1)
    for label in (2, 3, 4):
        assert g[label - 1] == pytest.approx(LA2004_G[label - 1], abs=0.1)
    for label in (3, 4):
        assert s[label - 1] == pytest.approx(LA2004_S[label - 1], abs=0.1)


@pytest.mark.parametrize("source", ["secular", "laplace-lagrange"])
def test_obliquity_command_takes_both_secular_sources(capsys, source):
    # The long model is what --orbit secular means; the linear theory keeps its own name. Mars'
    # obliquity at J2000 is its initial value, and the two sources' orbits differ by less than
    # 0.2° over 20 kyr (the linear theory's distance from the N-body orbit, docs/orbits.md).
    import json

    from andoyer.cli import main

    assert main(["obliquity", "mars", "--orbit", source, "--span", "-20000", "0", "--step", "10000",
                 "--format", "json"]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    normals = np.array(out["orbit_normal"])
    reference = SecularOrbit("mars").normal(np.array(out["t"]))
    angle = np.degrees(np.arccos(np.clip(np.sum(normals * reference, axis=-1), -1, 1)))
    assert angle.max() < (1e-9 if source == "secular" else 0.2)


def _secular_module():
    """The module of the long secular model (monkeypatched below), from ``sys.modules``."""
    return importlib.import_module("andoyer.planetary.orbits.secular")


def test_secular_orbit_extends_in_chunks_bit_for_bit(monkeypatch):
    # A run extended in small chunks (the unit of interruption), or by successive requests, is the
    # same run as one made at once.
    secular_module = _secular_module()

    t = np.linspace(-3e5, 3e5, 61)
    whole = SecularOrbit("venus").normal(t)
    monkeypatch.setattr(secular_module, "CHUNK_STEPS", 7)
    pieces = SecularOrbit("venus")
    pieces.normal(-1e5)
    pieces.normal(2e5)
    np.testing.assert_array_equal(pieces.normal(t), whole)


def test_secular_orbit_warns_then_refuses_beyond_its_expansion(monkeypatch):
    # Beyond e = 0.35 or i = 20° the degree-4 expansion loses accuracy (a warning, once per planet);
    # beyond e = 0.6 or i = 40° the run stops with a clear message (the bounds are lowered here,
    # below Mercury's e = 0.21, to see both).
    secular_module = _secular_module()

    monkeypatch.setattr(secular_module, "E_WARN", 0.1)
    with pytest.warns(RuntimeWarning, match=r"mercury reached e = 0\.2.*beyond e = 0\.1"):
        SecularOrbit("earth").normal(1e4)
    monkeypatch.setattr(secular_module, "E_MAX", 0.15)
    message = r"expected the planets' eccentricities below 0\.15.*got mercury at e = 0\.2"
    with pytest.raises(ValueError, match=message):
        SecularOrbit("earth").normal(1e4)


@pytest.mark.slow
def test_secular_inner_planets_are_chaotic():
    # The largest Lyapunov exponent over the 50 Myr before J2000 (Benettin's two-trajectory
    # method): Laskar (1989, Nature 338, 237) found a Lyapunov time of about 5 Myr in his secular
    # equations, Sussman & Wisdom (1992, Science 257, 56) 4-5 Myr in N-body integrations.
    # Measured here 5.6 Myr (and 9.1 Myr over 200 Myr before J2000, 4.0 Myr over 200 Myr after).
    from andoyer.planetary.orbits import lyapunov_exponent

    result = lyapunov_exponent(span=-5e7, interval=1e6)
    assert 3e6 < result.lyapunov_time < 1e7
