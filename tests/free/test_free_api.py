"""Array API of the exact solution: broadcasting, chunking, grouping, errors (on FreeMotion's backends)."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion, Regime, attitude, momentum, periods, propagate


def _mixed_states():
    rng = np.random.default_rng(8)
    moments = list(rng.uniform(1.0, 2.0, (6, 3)))
    m0 = list(rng.normal(size=(6, 3)))
    extra = [
        ([2.0, 2.0, 3.0], [0.3, 0.2, 1.0]),  # oblate
        ([1.5, 1.5, 1.5], [0.3, 0.2, 1.0]),  # sphere
        ([3.0, 4.0, 6.0], [1.0, 0.5, 1.0]),  # separatrix
        ([1.0, 2.0, 3.0], [0.0, 2.0, 0.0]),  # unstable steady spin
        ([1.0, 2.0, 3.0], [0.0, 0.0, 2.0]),  # stable steady spin
        ([1.0, 2.0, 3.0], [0.0, 0.0, 0.0]),  # rest
        ([1.0, 2.0, 2.9], [0.9, 0.1, 0.5]),  # a hyperbolic-series state
    ]
    for i, m in extra:
        moments.append(np.array(i))
        m0.append(np.array(m))
    q0 = Rotation.random(len(m0), random_state=4).as_quat()
    return np.array(moments), np.array(m0), q0


MOMENTS, M0, Q0 = _mixed_states()


def _one_by_one(t_per_state, backend=None):
    ms, qs = [], []
    for i in range(len(M0)):
        m, q = FreeMotion(MOMENTS[i], M0[i], Q0[i], backend=backend).propagate(t_per_state[i])
        ms.append(m)
        qs.append(q)
    return np.array(ms), np.array(qs)


def _same_rotation(qa, qb, tol):
    """Largest rotation angle of qa⁻¹ qb (robust for tiny angles) is at most tol."""
    rel = (Rotation.from_quat(qa).inv() * Rotation.from_quat(qb)).as_quat()
    angle = 2 * np.arctan2(np.linalg.norm(rel[..., :3], axis=-1), np.abs(rel[..., 3]))
    return np.max(angle) <= tol


def test_batch_of_mixed_regimes_equals_states_one_by_one(motion_backend):
    t = np.linspace(0.5, 40.0, len(M0))
    m, q = FreeMotion(MOMENTS, M0, Q0, backend=motion_backend).propagate(t)
    m1, q1 = _one_by_one(t, motion_backend)
    assert np.allclose(m, m1, rtol=0, atol=1e-15 * np.abs(M0).max())
    assert _same_rotation(q, q1, 1e-14)


def test_outer_layout_states_by_epochs(motion_backend):
    t = np.linspace(0.0, 30.0, 7)
    m, q = FreeMotion(MOMENTS[:, None], M0[:, None], Q0[:, None], backend=motion_backend).propagate(t)
    assert m.shape == (len(M0), 7, 3)
    assert q.shape == (len(M0), 7, 4)
    for k in (0, 3, 6):
        mk, qk = _one_by_one(np.full(len(M0), t[k]), motion_backend)
        assert np.allclose(m[:, k], mk, rtol=0, atol=1e-15 * np.abs(M0).max())
        assert _same_rotation(q[:, k], qk, 1e-14)


def test_per_state_epochs_in_outer_layout(motion_backend):
    t = np.arange(len(M0) * 4, dtype=float).reshape(len(M0), 4)
    m = FreeMotion(MOMENTS[:, None], M0[:, None], backend=motion_backend).momentum(t)
    for j in range(4):
        assert np.array_equal(m[:, j], FreeMotion(MOMENTS, M0, backend=motion_backend).momentum(t[:, j]))


def test_general_broadcast_layout(motion_backend):
    fm = FreeMotion(MOMENTS[:3][None, :], M0[:3][None, :], Q0[:3][None, :], backend=motion_backend)
    t = np.array([[0.0], [2.0]])  # (2, 1) against states (1, 3): no outer split
    m, q = fm.propagate(t)
    assert m.shape == (2, 3, 3)
    assert q.shape == (2, 3, 4)
    m1, _ = _one_by_one(np.full(len(M0), 2.0), motion_backend)
    assert np.allclose(m[1], m1[:3], rtol=0, atol=1e-15)


def test_scalar_shapes():
    fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], [0.0, 0.0, 0.0, 1.0])
    m, q = fm.propagate(1.0)
    assert m.shape == (3,)
    assert q.shape == (4,)
    assert fm.regime.shape == ()
    assert fm.periods.period.shape == ()


def test_long_time_series_is_chunked_consistently(motion_backend):
    fm = FreeMotion(MOMENTS[0], M0[0], Q0[0], backend=motion_backend)
    fm.periodic_epochs = np.inf  # the direct path (the periodic one: triaxial/test_free_triaxial_periodic.py)
    t = np.linspace(0.0, 1e4, 50_001)
    m, q = fm.propagate(t)
    m2, q2 = fm.propagate(t[::997])
    assert np.array_equal(m[::997], m2)
    assert np.array_equal(q[::997], q2)


def test_initial_state_is_reproduced_in_every_regime(motion_backend):
    m, q = FreeMotion(MOMENTS, M0, Q0, backend=motion_backend).propagate(0.0)
    assert np.allclose(m, M0, rtol=0, atol=4e-16 * np.abs(M0).max())
    assert _same_rotation(q, Q0, 1e-14)


def test_quaternions_are_normalised_on_input():
    a = FreeMotion(MOMENTS, M0, Q0).attitude(3.0)
    b = FreeMotion(MOMENTS, M0, 3.7 * Q0).attitude(3.0)
    assert _same_rotation(a, b, 1e-15)


def test_convenience_functions_agree_with_the_class():
    fm = FreeMotion(MOMENTS, M0, Q0)
    m, q = fm.propagate(2.5)
    assert np.array_equal(momentum(MOMENTS, M0, 2.5), m)
    assert np.array_equal(attitude(MOMENTS, M0, Q0, 2.5), q)
    m2, q2 = propagate(MOMENTS, M0, Q0, 2.5)
    assert np.array_equal(m2, m)
    assert np.array_equal(q2, q)
    assert np.array_equal(periods(MOMENTS, M0).period, fm.periods.period)


def test_regime_attribute(motion_backend):
    fm = FreeMotion(MOMENTS, M0, backend=motion_backend)
    assert fm.regime[6] == Regime.AXISYMMETRIC
    assert fm.regime[7] == Regime.SPHERE
    assert fm.regime[8] == Regime.SEPARATRIX
    assert fm.regime[11] == Regime.REST


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: FreeMotion(MOMENTS, M0).attitude(1.0), "initial attitude q0"),
        (lambda: FreeMotion(MOMENTS, M0).propagate(1.0), "initial attitude q0"),
        (lambda: FreeMotion(MOMENTS, M0, Q0[:, :3]), r"q0 with shape \(\.\.\., 4\)"),
        (lambda: FreeMotion(MOMENTS, M0, 0 * Q0), "non-zero quaternions"),
        (lambda: FreeMotion(MOMENTS, M0).momentum(np.nan), "finite times"),
        (lambda: FreeMotion(MOMENTS, M0).momentum(np.zeros(5)), "broadcast"),
    ],
)
def test_bad_input_raises(call, message):
    with pytest.raises(ValueError, match=message):
        call()


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("where", [0, 2345, 4999])
def test_bad_input_non_finite_time_among_many(bad, where):
    # the check reads only the least and greatest time: each non-finite value must still be found
    t = np.linspace(-10.0, 10.0, 5000)
    t[where] = bad
    with pytest.raises(ValueError, match="expected finite times t, got"):
        FreeMotion(MOMENTS[:2], M0[:2]).momentum(t[:, None])


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_phase_warning_from_the_extreme_time(sign):
    # one time of many with ω|t| = 1e12 rad: past the warning (1e-6 · 2⁵² rad), not the refusal (2⁵²);
    # 52 log10(2) - 12 = 3.65 digits left
    from andoyer._limits import PhasePrecisionWarning, spin_rate

    t = np.linspace(-1.0, 1.0, 5000)
    t[1234] = sign * 1e12 / spin_rate(MOMENTS[0], M0[0])
    with pytest.warns(PhasePrecisionWarning, match="keeps only 3.7 digits"):
        FreeMotion(MOMENTS[0], M0[0]).momentum(t)


@pytest.mark.parametrize(
    ("shape", "t_shape", "expected"),
    [((0, 3), (0,), (0,)), ((0, 1, 3), (0, 4), (0, 4)), ((3,), (0,), (0,)), ((2, 1, 3), (0,), (2, 0))],
)
def test_free_motion_empty_states_or_epochs_give_empty_outputs(shape, t_shape, expected, motion_backend):
    """No state or no epoch: empty outputs of the broadcast shape (it raised a reshape error)."""
    moments = np.broadcast_to([1.0, 2.0, 3.0], shape)
    m0 = np.broadcast_to([0.1, 0.2, 1.0], shape)
    q0 = np.broadcast_to([0.0, 0.0, 0.0, 1.0], (*shape[:-1], 4))
    fm = FreeMotion(moments, m0, q0, backend=motion_backend)
    m, q = fm.propagate(np.zeros(t_shape))
    assert m.shape == (*expected, 3)
    assert q.shape == (*expected, 4)
    assert fm.momentum(np.zeros(t_shape)).shape == (*expected, 3)
