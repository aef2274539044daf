"""Physics of the exact solution: invariants, periods, precession, limits, symmetries.

On every backend (``free_backends.py``): the flow on all three, periods and limits on FreeMotion's.
"""

from functools import partial

import mpmath as mp
import numpy as np
import pytest
from free_cases import EARTH_AB, EARTH_C, SIDEREAL_DAY, cases, polhode_period
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion, Regime

CASES = cases()


def _angle(ra, rb):
    rel = (ra.inv() * rb).as_quat()
    return 2 * np.arctan2(np.linalg.norm(rel[..., :3], axis=-1), np.abs(rel[..., 3]))


def _random_states(n, seed):
    rng = np.random.default_rng(seed)
    moments = rng.uniform(1.0, 2.0, (n, 3))
    m0 = rng.normal(size=(n, 3))
    q0 = Rotation.random(n, random_state=seed).as_quat()
    return moments, m0, q0


# -- the Earth ---------------------------------------------------------------------------


def test_earth_free_wobble_period(motion_backend):
    # Earth's moments spinning once per sidereal day, small wobble: Euler's period
    # T = 2π / (Ω √((C−A)(C−B)/(AB))) (Landau–Lifshitz §33, Problem 1).  With the issue's
    # A/C = 0.9967200, B/C = 0.9967222 it is 303.98 sidereal days (see docs/errata-free.md).
    C = EARTH_C
    A, B = EARTH_AB[0] * C, EARTH_AB[1] * C
    spin = 2 * np.pi / SIDEREAL_DAY
    m0 = C * spin * np.array([1e-7, 0.0, 1.0])
    T = float(FreeMotion([A, B, C], m0, backend=motion_backend).periods.period) / SIDEREAL_DAY
    euler = 1.0 / np.sqrt((C - A) * (C - B) / (A * B))
    assert abs(T - euler) < 1e-9 * euler
    assert 303.9 < T < 304.1


# -- invariants --------------------------------------------------------------------------


def test_invariants_are_conserved_to_round_off(free_backend):
    moments, m0, q0 = _random_states(3000, 1)
    period = FreeMotion(moments, m0).periods.period  # only to spread the times
    period = np.where(np.isfinite(period), period, 50.0)
    t = np.random.default_rng(2).uniform(0, 100, 3000) * period
    m, q = free_backend.propagate(moments, m0, q0, t)
    g0 = np.linalg.norm(m0, axis=-1)
    e0 = np.sum(m0**2 / moments, axis=-1)
    assert np.max(np.abs(np.linalg.norm(m, axis=-1) / g0 - 1)) < 2e-15
    assert np.max(np.abs(np.sum(m**2 / moments, axis=-1) / e0 - 1)) < 4e-15
    # the inertial angular momentum rot(t) m(t) stays rot0 m0
    h0 = Rotation.from_quat(q0).apply(m0)
    h = Rotation.from_quat(q).apply(m)
    assert np.max(np.linalg.norm(h - h0, axis=-1) / g0) < 1e-13
    assert np.max(np.abs(np.linalg.norm(q, axis=-1) - 1)) < 2e-15


# -- periods and precession --------------------------------------------------------------


@pytest.mark.parametrize("case", [c for c in CASES if c[4] is not None][:12], ids=lambda c: c[0])
def test_period_matches_the_classical_formula(case, motion_backend):
    name, moments, m0, _, _ = case
    ref = polhode_period(moments, m0)
    if ref is None:
        pytest.fail(f"{name} has no finite polhode period")
    got = float(FreeMotion(moments, m0, backend=motion_backend).periods.period)
    assert abs(got - ref) <= 4e-16 * ref


def test_momentum_is_periodic_and_attitude_precesses_per_period(motion_backend):
    moments, m0, q0 = _random_states(200, 5)
    fm = FreeMotion(moments, m0, q0, backend=motion_backend)
    T = fm.periods.period
    t = np.random.default_rng(6).uniform(0, 20, 200) * T
    m1, q1 = fm.propagate(t)
    m2, q2 = fm.propagate(t + T)
    assert np.max(np.linalg.norm(m2 - m1, axis=-1) / np.linalg.norm(m0, axis=-1)) < 1e-13
    axis = Rotation.from_quat(q0).apply(m0)
    turn = Rotation.from_rotvec(
        axis / np.linalg.norm(axis, axis=-1)[:, None] * fm.periods.precession[:, None]
    )
    assert np.max(_angle(turn * Rotation.from_quat(q1), Rotation.from_quat(q2))) < 1e-12


@pytest.mark.parametrize("name", ["sam-1", "lam-2", "near-separatrix-sam-1e-6"])
def test_precession_per_period_matches_the_reference(name, motion_backend, reference):
    _, moments, m0, q0, _ = next(c for c in CASES if c[0] == name)
    fm = FreeMotion(moments, m0, q0, backend=motion_backend)
    _, q_ref = reference(name, 1.0)  # one period: the time unit of these cases
    q_ref = np.array([float(x) for x in q_ref])
    axis = Rotation.from_quat(q0).apply(m0)
    turn = Rotation.from_rotvec(axis / np.linalg.norm(axis) * float(fm.periods.precession))
    assert _angle(turn * Rotation.from_quat(q0), Rotation.from_quat(q_ref)) < 1e-12


def test_secular_rate_matches_quadrature(motion_backend):
    # ψ̇ = G w₃ + (D − G² w₃)/(G + m₃) averaged over a period by mpmath quadrature of the
    # classical m₃(t) = a₃ dn(ωt + τ₀) (SAM, C = moment of axis 3); no attitude: the
    # compiled set-up computes the rate on demand
    moments, m0 = np.array([1.1, 1.6, 2.3]), np.array([0.4, -0.3, 1.1])
    fm = FreeMotion(moments, m0, backend=motion_backend)
    with mp.workdps(30):
        A, B, C = (mp.mpf(float(x)) for x in moments)
        m = [mp.mpf(float(x)) for x in m0]
        G2 = sum(x * x for x in m)
        G = mp.sqrt(G2)
        D = m[0] ** 2 / A + m[1] ** 2 / B + m[2] ** 2 / C
        k2 = (B - A) * (C * D - G2) / ((C - B) * (G2 - A * D))
        a3 = mp.sqrt((G2 - A * D) * C / (C - A))
        K = mp.ellipk(k2)
        mean = mp.quad(lambda u: 1 / (G + a3 * mp.ellipfun("dn", u, m=k2)), [0, K]) / K
        rate_psi = G / C + (D - G2 / C) * mean
        om = mp.sqrt((C - B) * (G2 - A * D) / (A * B * C))
        rate_g = rate_psi + 2 * mp.pi * om / (4 * K)  # g = ψ − l, l turns by −2π per period
    assert abs(float(fm.periods.precession_rate) - float(rate_g)) < 4e-16 * float(rate_g)


def test_axisymmetric_limit_is_continuous(motion_backend):
    # a triaxial body with B = A (1 + 1e-10) against the exact oblate body
    m0 = np.array([0.3, 0.4, 1.0])
    q0 = Rotation.random(random_state=9).as_quat()
    exact = FreeMotion([1.0, 1.0, 1.5], m0, q0, backend=motion_backend)
    near = FreeMotion([1.0, 1.0 + 1e-10, 1.5], m0, q0, backend=motion_backend)
    assert near.regime == Regime.SAM
    assert exact.regime == Regime.AXISYMMETRIC
    T = float(exact.periods.period)
    assert abs(float(near.periods.period) / T - 1) < 1e-9
    rates = float(near.periods.precession_rate), float(exact.periods.precession_rate)
    assert abs(rates[0] / rates[1] - 1) < 1e-9
    t = np.linspace(0, 3 * T, 50)
    (m1, q1), (m2, q2) = exact.propagate(t), near.propagate(t)
    assert np.max(np.abs(m1 - m2)) < 1e-8  # the frequencies differ by O(1e-10)
    assert np.max(_angle(Rotation.from_quat(q1), Rotation.from_quat(q2))) < 1e-8


def test_separatrix_motion_tends_to_the_unstable_axis(motion_backend):
    fm = FreeMotion([3.0, 4.0, 6.0], [1.0, 0.5, 1.0], backend=motion_backend)
    m = fm.momentum([1e3, -1e3])
    g = np.sqrt(2.25)
    assert np.allclose(m, [[0.0, g, 0.0], [0.0, -g, 0.0]], rtol=0, atol=1e-15)


# -- symmetries --------------------------------------------------------------------------


@pytest.mark.parametrize(("a", "b"), [(-20, 40), (40, -20), (0, 0), (-20, -20)])
def test_scale_covariance_with_exact_scalings(a, b, free_backend):
    # I → 2^a I, m → 2^b m, t → 2^(a−b) t leaves the motion invariant (m scaled by 2^b)
    moments, m0, q0 = _random_states(40, 7)
    t = np.random.default_rng(8).uniform(0, 500, 40)
    m1, q1 = free_backend.propagate(moments, m0, q0, t)
    m2, q2 = free_backend.propagate(moments * 2.0**a, m0 * 2.0**b, q0, t * 2.0 ** (a - b))
    assert np.max(np.abs(m2 / 2.0**b - m1)) < 1e-15 * np.max(np.abs(m0))
    assert np.max(_angle(Rotation.from_quat(q1), Rotation.from_quat(q2))) < 1e-14


@pytest.mark.parametrize(("mu_i", "mu_m"), [(1e-150, 1e150), (1e150, 1e-150), (1e-300, 1e-300)])
def test_extreme_units_neither_overflow_nor_underflow(mu_i, mu_m, motion_backend):
    # m(t; μ_I I, μ_m m₀) = μ_m m(μ_m t/μ_I; I, m₀): squares like m²/I would overflow here
    # (FreeMotion's backends scale exactly by powers of two; the scalar kernel does not)
    moments, m0, q0 = _random_states(20, 11)
    t = np.random.default_rng(12).uniform(0, 50, 20)
    m1, q1 = FreeMotion(moments, m0, q0, backend=motion_backend).propagate(t)
    m2, q2 = FreeMotion(moments * mu_i, m0 * mu_m, q0, backend=motion_backend).propagate(t * (mu_i / mu_m))
    assert np.all(np.isfinite(m2))
    assert np.max(np.abs(m2 / mu_m - m1)) < 1e-13 * np.max(np.abs(m0))
    assert np.max(_angle(Rotation.from_quat(q1), Rotation.from_quat(q2))) < 1e-12


def _sensitivity(backend, moments, m, q, t):
    """Change of the state at t when one component of (m, q) moves by one ulp."""
    mm, qq = np.tile(m, (8, 1)), np.tile(q, (8, 1))  # the state, then one ulp on each component
    for k in range(7):
        if k < 3:
            mm[k + 1, k] = np.nextafter(mm[k + 1, k], np.inf)
        else:
            qq[k + 1, k - 3] = np.nextafter(qq[k + 1, k - 3], np.inf)
    pm, pq = backend.propagate(moments, mm, qq, t)
    dm = np.max(np.linalg.norm(pm[1:] - pm[0], axis=-1))
    dq = np.max(_angle(Rotation.from_quat(pq[1:]), Rotation.from_quat(pq[0])))
    return dm, dq


@given(
    st.integers(min_value=0, max_value=2**32 - 1),
    st.floats(min_value=-500.0, max_value=500.0),
    st.floats(min_value=-500.0, max_value=500.0),
)
@settings(max_examples=30, deadline=None)
def test_flow_composes_and_reverses(free_backend, seed, t1, t2):
    # φ(t1 + t2) = φ(t2) ∘ φ(t1) and φ(−t1) ∘ φ(t1) = id on a random state.  The state at
    # t1 is rounded to doubles, so the comparison allows a few times the change that one
    # ulp of that state makes (the conditioning of the flow, which grows with time), on top
    # of the errors of three evaluations and a rebuild (each ~1e-15 rad, ~1e-16 |m|).
    moments, m0, q0 = _random_states(1, seed % 1000)
    run = free_backend.propagate
    m1, q1 = run(moments[0], m0[0], q0[0], t1)
    m12, q12 = run(moments[0], m1, q1, t2)
    m_direct, q_direct = run(moments[0], m0[0], q0[0], t1 + t2)
    back_m, back_q = run(moments[0], m1, q1, -t1)
    g = np.linalg.norm(m0[0])
    step = partial(free_backend.step_error, moments[0], m0[0])  # the scalar kernel's float64 phase
    for t, (m_a, q_a), (m_b, q_b), steps in (
        (t2, (m12, q12), (m_direct, q_direct), step(t1) + step(t2) + step(t1 + t2)),
        (-t1, (back_m, back_q), (m0[0], q0[0]), 2 * step(t1)),
    ):
        dm, dq = _sensitivity(free_backend, moments[0], m1, q1, t)
        assert np.linalg.norm(m_a - m_b) < (1e-14 + steps) * g + 4 * dm
        assert _angle(Rotation.from_quat(q_a), Rotation.from_quat(q_b)) < 5e-14 + steps + 4 * dq
