"""Many epochs per body: the piecewise-polynomial representation of one period.

:mod:`andoyer.free.triaxial.periodic_numpy` replaces the per-epoch theta series of triaxial states by
polynomials of the reduced polhode phase, built once per state.  Checked here against the
57-digit Taylor reference of ``free_reference.py`` (negative times through time reversal:
``m(−t) = −n(t)``, ``q(−t) = p(t)`` where ``(n, p)`` start from ``(−m₀, q₀)``), against
the direct path (a different algorithm), against its own periodicity, and on both the
compiled and the numpy fills (the numpy backend's, built from its own constants, against the
reference too).
"""

import numpy as np
import pytest
from free_cases import cases
from free_reference import angle_between, relative_error
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion
from andoyer.free.triaxial import periodic_compiled, periodic_numpy
from andoyer.free.triaxial.periodic import DEGREE, horner, locate

BY_NAME = {c[0]: c for c in cases()}
TOL = 1e-14

SLOW = pytest.mark.slow
REGIMES = (
    "sam-0",
    "lam-1",
    pytest.param("near-separatrix-sam-1e-10", marks=SLOW),
    "near-separatrix-lam-1e-10",
    "near-separatrix-sam-1e-6",
    "k2-above-half",
    pytest.param("earth-wobble-0.3", marks=SLOW),
    "scaled-large-moments",
    "oblate",
    "sphere",
)


def _forced(moments, m0, q0=None, periodic_epochs=0.0, backend=None):
    fm = FreeMotion(moments, m0, q0, backend=backend)
    fm.periodic_epochs = periodic_epochs
    return fm


def _random_states(n, seed):
    rng = np.random.default_rng(seed)
    moments = rng.uniform(1.0, 2.0, (n, 3))
    m0 = rng.normal(size=(n, 3)) * np.exp(rng.uniform(-2, 2, (n, 1)))
    q0 = Rotation.random(n, random_state=seed).as_quat()
    return moments, m0, q0


@pytest.mark.slow
@pytest.mark.parametrize("name", REGIMES)
def test_periodic_matches_reference_in_every_regime(name, motion_backend, reference):
    _, moments, m0, q0, t_unit = BY_NAME[name]
    fm = _forced(moments, m0, q0, backend=motion_backend)
    for k in (0.0, 0.37, 2.3, -1.7):  # negative: the reference by time reversal
        m_ref, q_ref = reference(name, k)
        m, q = fm.propagate(k * t_unit)
        assert relative_error(m_ref, m) <= TOL, k
        assert angle_between(q_ref, q) <= TOL, k


def test_periodic_equals_direct_on_random_states():
    moments, m0, q0 = _random_states(100, 11)
    period = FreeMotion(moments, m0).periods.period
    rng = np.random.default_rng(5)
    t = rng.uniform(-30.0, 30.0, (100, 40)) * period[:, None]
    t[:, :7] = np.arange(-3, 4) * period[:, None]  # exact multiples of the period, and 0
    m_p, q_p = _forced(moments[:, None], m0[:, None], q0[:, None]).propagate(t)
    m_d, q_d = _forced(moments[:, None], m0[:, None], q0[:, None], np.inf).propagate(t)
    g = np.linalg.norm(m0, axis=-1)[:, None, None]
    assert np.max(np.abs(m_p - m_d) / g) <= TOL
    assert np.max(np.abs(q_p - q_d)) <= TOL  # the same quaternions, sign included


def test_periodic_returns_after_whole_periods():
    moments, m0, q0 = _random_states(50, 3)
    fm = _forced(moments[:, None], m0[:, None], q0[:, None])
    period = fm.periods.period
    k = np.array([-5.0, -1.0, 0.0, 1.0, 2.0, 5.0])  # t = kT carries k ulps of T
    m = fm.momentum(k * period)
    assert np.max(np.abs(m - m0[:, None]) / np.linalg.norm(m0, axis=-1)[:, None, None]) <= TOL


def test_periodic_is_chosen_from_the_epochs_per_state():
    moments, m0, q0 = _random_states(3, 2)
    t = np.linspace(-50.0, 50.0, 2000)
    many = _forced(moments[:, None], m0[:, None], q0[:, None], periodic_epochs=2000)
    m_auto, q_auto = many.propagate(t)
    assert many._periodic  # the representation was built
    few = _forced(moments[:, None], m0[:, None], q0[:, None], periodic_epochs=2000)
    m_few, _ = few.propagate(t[:1999])
    assert not few._periodic
    m_d, q_d = _forced(moments[:, None], m0[:, None], q0[:, None], np.inf).propagate(t)
    g = np.linalg.norm(m0, axis=-1)[:, None, None]
    assert np.max(np.abs(m_auto - m_d) / g) <= TOL
    assert np.max(np.abs(q_auto - q_d)) <= TOL
    assert np.array_equal(m_few, m_d[:, :1999])


def test_periodic_one_body_huge_epoch_count():
    moments, m0, q0 = _random_states(1, 4)
    fm = FreeMotion(moments[0], m0[0], q0[0])
    t = np.linspace(-1e3, 1e3, 400_001) * fm.periods.period
    m, q = fm.propagate(t)
    m_d, q_d = _forced(moments[0], m0[0], q0[0], np.inf).propagate(t[::4001])
    assert np.max(np.abs(m[::4001] - m_d)) <= TOL * np.linalg.norm(m0)
    assert np.max(np.abs(q[::4001] - q_d)) <= TOL


def test_periodic_compiled_and_numpy_fills_agree():
    moments, m0, q0 = _random_states(20, 9)
    fm = FreeMotion(moments[:, None], m0[:, None], q0[:, None])
    group = next(g for g in fm._groups if g.members.size == 20 or g.members.size > 1)
    per, rest = periodic_numpy.build(group, attitude=True)
    assert rest is None
    t = np.random.default_rng(1).uniform(-1e3, 1e3, (group.members.size, 33))
    outs = []
    for fill in (periodic_compiled.fill, periodic_numpy.fill_numpy):
        m = np.empty((*t.shape, 3))
        q = np.empty((*t.shape, 4))
        rows = np.arange(t.shape[0])
        fill(per.const, rows, rows, t, None, (m, q))
        outs.append((m, q))
    # the compiled fill fuses multiply-adds (one rounding where numpy has two): they differ by the
    # roundings of the ~2·DEGREE operations of a value's chain and the ~12 of the product after it
    tol = (2 * DEGREE + 12) * np.finfo(float).eps / 2
    assert np.max(np.abs(outs[0][0] - outs[1][0])) <= tol * np.abs(outs[0][0]).max()
    assert np.max(np.abs(outs[0][1] - outs[1][1])) <= tol


def test_periodic_leaves_states_needing_too_many_pieces_direct(monkeypatch):
    _, moments, m0, q0, t_unit = BY_NAME["near-separatrix-sam-1e-10"]
    monkeypatch.setattr(periodic_numpy, "MAX_PIECES", 8)
    fm = _forced(moments, m0, q0)
    t = np.array([0.0, 0.37, -2.3]) * t_unit
    m, q = fm.propagate(t)
    assert all(g.kernel is not periodic_numpy.evaluate for g in fm._periodic[True])
    m_d, q_d = _forced(moments, m0, q0, np.inf).propagate(t)
    assert np.array_equal(m, m_d)
    assert np.array_equal(q, q_d)


def test_periodic_chunked_consistently():
    moments, m0, q0 = _random_states(1, 8)
    fm = _forced(moments[0], m0[0], q0[0])
    t = np.linspace(-1e4, 1e4, 50_001)
    m, q = fm.propagate(t)
    m2, q2 = fm.propagate(t[::997])
    assert np.array_equal(m[::997], m2)
    assert np.array_equal(q[::997], q2)


@pytest.mark.parametrize("n", [4, 16])
def test_piecewise_kernels_reproduce_cos_and_sin(n):
    # pieces of cos(2πf), sin(2πf) from values at the nodes; compared with numpy's own
    u = periodic_numpy._U
    f = -0.5 + (np.arange(n)[:, None] + 0.5 * (u + 1.0)) / n
    vals = np.stack([np.cos(2 * np.pi * f), np.sin(2 * np.pi * f), f * f, np.ones_like(f)], axis=-1)
    coef = np.ascontiguousarray(periodic_numpy._fit(vals))
    assert coef.shape == (n, DEGREE + 1, 4)
    x = np.random.default_rng(0).uniform(-0.5, 0.5, 1000)
    x[:3] = (-0.5, 0.0, 0.5)
    i, t = locate(x, float(n))
    got = horner(np.moveaxis(coef[i.astype(np.intp)], (-2, -1), (0, 1)), 0, t)
    tol = 4e-15 if n == 16 else 1e-9  # a few ulps from the fit and Horner; n = 4: truncation ~1e-10
    assert np.max(np.abs(got[0] - np.cos(2 * np.pi * x))) <= tol
    assert np.max(np.abs(got[1] - np.sin(2 * np.pi * x))) <= tol
    assert np.max(np.abs(got[2] - x * x)) <= 1e-15
    scalar = [horner(coef[int(a)], 0, b)[0] for a, b in zip(i[:5], t[:5], strict=True)]
    assert np.array_equal(scalar, got[0][:5])


def _epochs(case, period, rng):
    """Epochs (unscaled) that steer the compiled fill into each of its evaluation orders."""
    if case == "sorted-one-period":  # long runs on one piece: in place
        return np.sort(rng.uniform(-0.5, 0.5, 1100)) * period
    if case == "shuffled-many":  # ≥ 16 epochs a piece: sorted by piece
        return rng.uniform(-50.0, 50.0, 1100) * period
    if case == "sorted-few":  # fewer than 16 epochs a piece, runs of ~5: runs in place
        return np.sort(rng.uniform(0.0, 0.5, 90)) * period
    if case == "shuffled-few":  # short runs: epoch by epoch
        return rng.uniform(-50.0, 50.0, 90) * period
    # descending, negative, a partial last block and runs that cross blocks
    return -np.linspace(0.0, 3.0, periodic_compiled._BLOCK + 37) * period


FILL_CASES = ["sorted-one-period", "shuffled-many", "sorted-few", "shuffled-few", "descending-tail"]


@pytest.mark.parametrize("case", FILL_CASES)
def test_periodic_fill_matches_direct_in_every_evaluation_order(case):
    # the compiled fill (plain Python without numba) against the per-epoch theta series
    moments, m0, q0 = np.array([1.0, 2.0, 3.0]), np.array([0.3, 0.2, 1.0]), np.array([0.1, -0.2, 0.3, 0.9])
    fm = FreeMotion(moments, m0, q0)
    per, rest = periodic_numpy.build(fm._groups[0], attitude=True)
    assert rest is None
    assert per.const.params[0, 6] == 32.0  # the pieces the cases above were sized for
    t = _epochs(case, float(fm.periods.period), np.random.default_rng(FILL_CASES.index(case)))
    if not periodic_numpy.NUMBA and t.size > periodic_compiled._BLOCK:
        t = t[::7]  # the interpreted loop: a sample of the same epochs
    m_d, q_d = _forced(moments, m0, q0, np.inf).propagate(t)
    for attitude in (False, True):
        m = np.empty((1, t.size, 3))
        q = np.empty((1, t.size, 4)) if attitude else None
        periodic_compiled.fill(per.const, np.array([0]), np.array([0]), t[None], None, (m, q))
        assert np.max(np.abs(m[0] - m_d)) <= TOL * np.linalg.norm(m0)
        if attitude:
            assert np.max(np.abs(q[0] - q_d)) <= TOL


@pytest.mark.parametrize("case", FILL_CASES)
def test_periodic_values_independent_of_epoch_order(case):
    # each epoch gets the same operations whatever its block: permuting the epochs permutes the values
    moments, m0, q0 = _random_states(3, 12)
    fm = _forced(moments[:, None], m0[:, None], q0[:, None])
    period = float(np.min(fm.periods.period))
    t = _epochs(case, period, np.random.default_rng(5))
    perm = np.random.default_rng(6).permutation(t.size)
    m, q = fm.propagate(t)
    m_p, q_p = fm.propagate(t[perm])
    assert np.array_equal(m[:, perm], m_p)
    assert np.array_equal(q[:, perm], q_p)
    assert np.array_equal(fm.momentum(t[perm]), m_p)


def test_periodic_coefficient_rows_cover_the_degree():
    # the compiled fill writes the DEGREE + 1 rows of a piece out by hand
    piece = np.arange((DEGREE + 1) * 12, dtype=float).reshape(DEGREE + 1, 12)
    rows = periodic_compiled._coefficients(piece, 4)
    assert np.array_equal(np.array(rows), piece[:, 4:8])
    assert np.array_equal(periodic_compiled._horner_rows(rows, 0.3), horner(piece, 4, 0.3))


@pytest.mark.parametrize("case", FILL_CASES)
def test_periodic_streamed_outputs_equal_cached_ones(case, monkeypatch):
    # large outputs are written by non-temporal stores through flat views: the same values, every order
    moments, m0, q0 = _random_states(3, 14)
    fm = FreeMotion(moments[:, None], m0[:, None], q0[:, None])
    group = fm._groups[0]  # all three states, or two on the numpy backend (one per series)
    per, rest = periodic_numpy.build(group, attitude=True)
    assert rest is None
    t = _epochs(case, float(np.min(fm.periods.period)), np.random.default_rng(7))
    if not periodic_numpy.NUMBA and t.size > periodic_compiled._BLOCK:
        t = t[::7]  # the interpreted loop: a sample of the same epochs
    t = np.stack([np.full_like(t, np.nan), t, -t[::-1], 0.5 * t])  # times per output row; row 0 unused
    k = group.members.size
    pos, rows = np.arange(k), k - np.arange(k)  # state j into output row k - j
    got = {}
    for limit in (np.inf, 0):
        monkeypatch.setattr(periodic_compiled, "_STREAM_BYTES", limit)
        for attitude in (False, True):
            m = np.full((4, t.shape[1], 3), np.nan)  # rows left alone: the flat indices stay in their rows
            q = np.full((4, t.shape[1], 4), np.nan) if attitude else None
            periodic_compiled.fill(per.const, pos, rows, t, None, (m, q))
            got[limit, attitude] = (m, q)
    for attitude in (False, True):
        (m, q), (m_s, q_s) = got[np.inf, attitude], got[0, attitude]
        assert np.all(np.isnan(m_s[0]))
        assert not np.any(np.isnan(m_s[1 : k + 1]))
        assert np.array_equal(m, m_s, equal_nan=True)
        if attitude:
            assert np.array_equal(q, q_s, equal_nan=True)
    i = group.members[0]  # state 0 of the group filled output row k at times t[k]
    m_d, q_d = _forced(moments[i], m0[i], q0[i], np.inf).propagate(t[k])
    assert np.max(np.abs(got[0, True][0][k] - m_d)) <= TOL * np.linalg.norm(m0[i])
    assert np.max(np.abs(got[0, True][1][k] - q_d)) <= TOL


AXIS_CASES = ["random", "near-separatrix-lam-1e-10", "scaled-large-moments", "k2-above-half"]


@pytest.mark.parametrize("name", AXIS_CASES)
def test_periodic_axis_is_the_reference_momentum_direction(name):
    # the attitude is Q ⊗ (sin(πg) e_z, cos(πg)) ⊗ a(f) with R(Q) e_z = n and the momentum G R(a)ᵀ e_z:
    # Q's axis and G against scipy's rotation of m0 by q0 and its norm
    if name == "random":
        moments, m0, q0 = _random_states(6, 21)
    else:
        _, moments, m0, q0, _ = BY_NAME[name]
        moments, m0, q0 = (np.atleast_2d(a) for a in (moments, m0, q0))
    fm = FreeMotion(moments[:, None], m0[:, None], q0[:, None])
    for group in fm._groups:
        per, rest = periodic_numpy.build(group, attitude=True)
        assert rest is None
        want = Rotation.from_quat(q0[group.members]).apply(m0[group.members])
        want /= np.linalg.norm(want, axis=-1, keepdims=True)
        frame = Rotation.from_quat(per.const.params[:, 8:12])
        assert np.max(np.abs(frame.apply([0.0, 0.0, 1.0]) - want)) <= 5e-15  # the kernels carry ~10 ulps
        assert np.max(np.abs(np.linalg.norm(per.const.params[:, 8:12], axis=1) - 1.0)) <= 4e-16
        g = np.linalg.norm(m0[group.members], axis=-1)
        assert np.max(np.abs(per.const.params[:, 12] - g) / g) <= 4e-16
        momentum_only, _ = periodic_numpy.build(group, attitude=False)
        assert np.array_equal(momentum_only.const.params[:, 8:13], np.zeros((group.members.size, 5)))
