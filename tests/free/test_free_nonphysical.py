"""Bodies whose moments break the triangle inequality ``A + B ≥ C``: the exact solution still holds.

No mass distribution has such moments, but Euler's equations and the attitude kinematics hold
for any positive moments (other solvers' test suites use e.g. ``(3, 3, 9)``). A
:class:`RigidBody` warns and the exact solution must stay right: it is checked against the
57-digit Taylor integration of the equations of motion (:mod:`free_reference`, no code shared
with ``andoyer.free``) in every regime. A prolate body cannot break the inequality
(``B = C`` gives ``A + B > C``), nor can a sphere.
"""

import warnings

import numpy as np
import pytest
from free_cases import complementary_parameter, polhode_period, with_k2
from free_reference import TaylorReference, angle_between, relative_error
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, RigidBody, State
from andoyer.body import NonPhysicalInertiaWarning
from andoyer.free import Regime
from andoyer.state import andoyer_hamiltonian
from andoyer.state.sadov import andoyer_to_sadov, sadov_hamiltonian, sadov_to_andoyer
from andoyer.state.sam import sam_axes, sam_energy
from conftest import random_states, rotation_distance

M_TOL = 1e-13
Q_TOL = 1e-12


def _case(name, moments, m0, regime, t_unit=None, seed=0):
    moments, m0 = np.asarray(moments, dtype=float), np.asarray(m0, dtype=float)
    perm = np.random.default_rng(seed).permutation(3)  # exercise the relabelling of the axes
    moments, m0 = moments[perm], m0[perm]
    q0 = Rotation.random(random_state=seed + 1).as_quat()
    if t_unit is None:
        t_unit = polhode_period(moments, m0)
    return pytest.param(moments, m0, q0, regime, t_unit, id=name)


ABC = np.array([1.0, 1.7, 4.0])  # A + B = 2.7 < C
CASES = [
    _case("sam", [1.0, 2.0, 4.0], [0.3, -0.5, 1.0], "SAM", seed=1),
    _case("lam", [1.0, 2.0, 4.0], [1.0, 0.4, -0.3], "LAM", seed=2),
    _case("near-separatrix-sam-1e-8", ABC, with_k2(ABC, 1 - 1e-8), "SAM", seed=3),
    _case("near-separatrix-lam-1e-8", ABC, with_k2(ABC, 1 / (1 - 1e-8)), "LAM", seed=4),
    _case("near-pure-spin", [1.0, 2.0, 4.0], [1e-6, -2e-6, 1.0], "SAM", seed=5),
    _case("far-from-physical", [0.5, 0.7, 20.0], [0.2, 0.1, 1.0], "SAM", seed=6),
    # m_C² (C − B) A = m_A² (B − A) C exactly (4·3 = 2·6): on the separatrix, no period. The
    # approach to the saddle G b_B goes as exp(−λt), λ = G √((1/A − 1/B)(1/B − 1/C)) = 0.76: by
    # t ≈ 100 the reference's 57 digits are spent and it leaves for the other saddle, so the
    # times stay below 90 (λt < 70).
    _case("separatrix", [1.0, 3.0, 6.0], [1.0, 0.5, 2.0], "SEPARATRIX", t_unit=3.0, seed=7),
    # regular precession of m about b3 at (1/A − 1/C) m₃: period 2π / (0.7 (1/3 − 1/9))
    _case("oblate-3-3-9", [3.0, 3.0, 9.0], [0.5, -0.2, 0.7], "AXISYMMETRIC", 2 * np.pi / (0.7 * 2 / 9), 8),
]


def _body(moments):
    with pytest.warns(NonPhysicalInertiaWarning, match="triangle inequality"):
        return RigidBody(*moments)


def _check(moments, m0, q0, regime, multiples):
    body = _body(moments)
    assert not body.is_physical
    free = FreeRotation(body)
    state = State.from_quaternion(q0, m0)
    assert str(free.regime(state)) == regime
    ref = TaylorReference(moments, m0, q0)
    path = free.propagate(state, np.array(multiples))
    for k, t in enumerate(multiples):
        m_ref, q_ref = ref.advance_to(t)
        assert relative_error(m_ref, path.m_body[k]) <= M_TOL, t
        assert angle_between(q_ref, path.quaternion[k]) <= Q_TOL, t


@pytest.mark.parametrize(("moments", "m0", "q0", "regime", "t_unit"), CASES)
def test_exact_solution_of_nonphysical_body_matches_taylor_reference(moments, m0, q0, regime, t_unit):
    _check(moments, m0, q0, regime, (0.37 * t_unit,))


@pytest.mark.slow
@pytest.mark.parametrize(("moments", "m0", "q0", "regime", "t_unit"), CASES)
def test_exact_solution_of_nonphysical_body_matches_taylor_reference_to_30_periods(
    moments, m0, q0, regime, t_unit
):
    _check(moments, m0, q0, regime, (2.3 * t_unit, 9.71 * t_unit, 30.0 * t_unit))


def test_near_separatrix_cases_have_the_intended_modulus():
    for k2, expected in ((1 - 1e-8, 1e-8), (1 / (1 - 1e-8), 1e-8)):
        assert complementary_parameter(ABC, with_k2(ABC, k2)) == pytest.approx(expected, rel=1e-6)


@pytest.mark.parametrize(("moments", "m0", "q0", "regime", "t_unit"), CASES)
def test_period_of_nonphysical_body_returns_the_momentum(moments, m0, q0, regime, t_unit):
    # The period of m(t) against the classical 4K(k²)/ω in mpmath (free_cases.polhode_period).
    free = FreeRotation(_body(moments))
    state = State.from_quaternion(q0, m0)
    period = float(free.periods(state).period)
    if regime == "SEPARATRIX":
        assert period == np.inf
        return
    assert period == pytest.approx(t_unit, rel=1e-12)
    back = free.propagate(state, 3 * period).m_body
    np.testing.assert_allclose(back, m0, rtol=0, atol=1e-12 * np.linalg.norm(m0))
    assert free.regime(state) == Regime[regime].name


# --------------------------------------------------------------------------- charts
NONPHYSICAL = {
    "1-2-4": (1.0, 2.0, 4.0),
    "b3-min": (2.0, 5.0, 1.0),  # C along b2, A along b3
    "disk-3-3-9": (3.0, 3.0, 9.0),
    "far-from-physical": (0.5, 0.7, 20.0),
}


def _separatrix_distance(body, m):
    """``|2T/G² − 1/B|`` relative to ``1/A − 1/C`` (0 on the separatrix)."""
    A, B, C = body.sorted_moments
    e = np.sum(m * m / body.moments, axis=-1) / np.sum(m * m, axis=-1)  # 2T/G², in [1/C, 1/A]
    return np.abs(e - 1 / B) / (1 / A - 1 / C)


def _states(body, n, seed):
    """Random states away from the separatrix (where the charts are ill-conditioned)."""
    q, m = random_states(np.random.default_rng(seed), n)
    keep = _separatrix_distance(body, m) > 1e-2
    return State.from_quaternion(q[keep], m[keep])


def _energy(body, m):
    """``½ Σ mᵢ²/Iᵢ`` written out here, not taken from the code."""
    I1, I2, I3 = body.moments
    return 0.5 * (m[..., 0] ** 2 / I1 + m[..., 1] ** 2 / I2 + m[..., 2] ** 2 / I3)


def _same_states(back, state, tol=1e-13):
    G = np.linalg.norm(state.m_body, axis=-1)
    assert np.max(np.abs(back.m_body - state.m_body).max(axis=-1) / G) <= tol
    assert np.max(rotation_distance(back.quaternion, state.quaternion)) <= tol


@pytest.mark.parametrize("name", NONPHYSICAL)
def test_andoyer_chart_of_nonphysical_body_round_trip_and_energy(name):
    body = _body(NONPHYSICAL[name])
    state = _states(body, 400, 11)
    a = state.as_andoyer()
    _same_states(State.from_andoyer(*a), state)
    energy = _energy(body, state.m_body)
    np.testing.assert_allclose(andoyer_hamiltonian(body, a.l, a.L, a.G), energy, rtol=1e-13)


@pytest.mark.parametrize("name", [n for n in NONPHYSICAL if n != "b3-min"])  # Sadov needs b3 = A or C
def test_sadov_chart_of_nonphysical_body_round_trip_and_energy(name):
    body = _body(NONPHYSICAL[name])
    state = _states(body, 400, 12)
    s = andoyer_to_sadov(body, *state.as_andoyer())
    np.testing.assert_allclose(sadov_hamiltonian(body, s.I_l, s.I_g), _energy(body, state.m_body), rtol=1e-13)
    _same_states(State.from_andoyer(*sadov_to_andoyer(body, *s)), state)


@pytest.mark.parametrize("mode", ["SAM", "LAM"])
@pytest.mark.parametrize("name", NONPHYSICAL)
def test_sam_chart_of_nonphysical_body_round_trip_and_energy(name, mode):
    body = _body(NONPHYSICAL[name])
    state = _states(body, 400, 13)
    if body.is_axisymmetric and mode == "LAM":  # no unique axis of minimum inertia: refused
        with pytest.raises(ValueError, match="unique axis of minimum inertia"):
            state.as_sam(body, mode)
        return
    sam = state.as_sam(body, mode)
    axes = sam_axes(body, mode)
    energy = sam_energy(sam.sam_l, sam.sam_L, sam.sam_G, axes.alpha, axes.beta, axes.moments[2])
    np.testing.assert_allclose(energy, _energy(body, state.m_body), rtol=1e-12)
    _same_states(State.from_sam(*sam, body=body, mode=mode), state, tol=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    q=st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(lambda v: np.linalg.norm(v) > 0.1),
    m=st.lists(st.floats(-10, 10), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 1e-3),
)
def test_sadov_chart_of_nonphysical_body_round_trip_hypothesis(q, m):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NonPhysicalInertiaWarning)  # asserted in the tests above
        body = RigidBody(1.0, 2.0, 4.0)
    state = State.from_quaternion(np.asarray(q) / np.linalg.norm(q), m)
    G = np.linalg.norm(m)
    # away from the charts' poles (sin J = 0, sin I = 0) and from the separatrix
    assume(abs(m[2]) < 0.999 * G and abs(float(state.m_reference[2])) < 0.999 * G)
    assume(float(_separatrix_distance(body, np.asarray(m))) > 1e-2)
    s = andoyer_to_sadov(body, *state.as_andoyer())
    _same_states(State.from_andoyer(*sadov_to_andoyer(body, *s)), state, tol=1e-12)
