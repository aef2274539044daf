"""The compiled backend of FreeMotion against the numpy backend it replaces, in every regime.

With the compiled backend (the default with numba) :class:`andoyer.free.FreeMotion` builds
the triaxial constants in a compiled per-body loop (:mod:`andoyer.free.triaxial.setup_compiled`)
instead of the vectorised double-double arithmetic of :func:`andoyer.free.triaxial.setup_numpy.triaxial`.
The accuracy tests (``test_free_accuracy.py``) check every backend against the 57-digit
reference; here both are run on the same states and compared directly: the set-up tables
(without numba the "compiled" functions run as plain Python and are compared all the same)
and ``FreeMotion(..., backend=...)`` (where the compiled backend is available).
"""

import numpy as np
import pytest
from free_backends import MOTION
from free_cases import cases, with_k2
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion, motion
from andoyer.free.common.polhode_numpy import polhode_frame
from andoyer.free.common.scaling_compiled import classify_and_scale
from andoyer.free.common.scaling_numpy import normalise
from andoyer.free.triaxial.setup_compiled import as_triaxial, triaxial_table
from andoyer.free.triaxial.setup_numpy import triaxial
from andoyer.regime import Regime, check_inputs, classify

CASES = cases()
EPS = np.finfo(float).eps


def _states():
    """Triaxial states: the seeded cases, random bodies, and the edges of the series."""
    rng = np.random.default_rng(7)
    moments = [c[1] for c in CASES]
    m0 = [c[2] for c in CASES]
    inertia = rng.uniform(1.0, 2.0, (300, 3))
    moments += list(inertia)
    m0 += list(rng.normal(size=(300, 3)) * np.exp(rng.uniform(-3, 3, (300, 1))))
    abc = np.array([1.0, 1.7, 2.3])
    for k2 in (1e-12, 0.3, 0.5 - 1e-15, 0.5 + 1e-15, 0.9, 1 - 1e-8, 1 - 1e-10, 1 - 1e-12):
        moments.append(abc)
        m0.append(with_k2(abc, k2))
    for k2 in (0.95, 1 - 1e-8, 1 - 1e-10, 1 - 1e-12):  # LAM (these m1, m2 reach k² > 0.87)
        moments.append(abc)
        m0.append(with_k2(abc, 1 / k2, m1=0.2, m2=1.0))
    moments, m0 = check_inputs(np.array(moments), np.array(m0))
    regime = classify(moments, m0)
    keep = regime <= Regime.LAM
    moments, m0, _, _ = normalise(moments[keep], m0[keep])
    q0 = Rotation.random(moments.shape[0], random_state=3).as_quat()
    return moments, m0, regime[keep] == Regime.LAM, q0


def _fields(const, prefix=""):
    for name in const._fields:
        value = getattr(const, name)
        if isinstance(value, tuple):
            yield from _fields(value, f"{prefix}{name}.")
        else:
            yield f"{prefix}{name}", np.asarray(value, dtype=float)


def test_compiled_constants_equal_numpy_constants():
    moments, m0, lam, q0 = _states()
    table, flat = triaxial_table(moments, m0, lam, q0)
    compiled = as_triaxial(table)
    assert not np.any(flat)
    numpy_ = triaxial(polhode_frame(moments, m0, lam), q0)
    got, want = dict(_fields(compiled)), dict(_fields(numpy_))
    assert got.keys() == want.keys()
    # double-doubles: the sums agree far beyond float64
    for name in ("nu", "nu_psi"):
        hi, lo = want[f"{name}.hi"], want[f"{name}.lo"]
        diff = (got[f"{name}.hi"] - hi) + (got[f"{name}.lo"] - lo)
        assert np.all(np.abs(diff) <= 1e-28 * np.abs(hi)), name
        assert np.array_equal(got[f"{name}.hh"] + got[f"{name}.hl"], got[f"{name}.hi"])
    # the working frame and the attitude anchor are the same kernels on both paths
    # (andoyer.free.common.polhode) on the same inputs: the same bits, sign included
    for name in ("quat_u", "quat_v", "v_sn", "v_cn", "G", "s"):
        assert np.array_equal(got[name], want[name]), name
    # coefficients and phases of order one: absolute; the rest relative
    absolute = {"wa": 8 * EPS, "wb": 8 * EPS, "frac0": 4 * EPS, "psi0": 8 * EPS, "slope": 4 * EPS}
    for name, value in want.items():
        if name.startswith(("nu", "quat")):
            continue
        if name in absolute:
            np.testing.assert_allclose(got[name], value, rtol=0, atol=absolute[name], err_msg=name)
        else:
            np.testing.assert_allclose(got[name], value, rtol=4 * EPS, atol=0, err_msg=name)


def test_compiled_constants_flag_a_steady_spin():
    moments = np.array([[0.5, 0.75, 0.875], [0.5, 0.75, 0.875]])
    m0 = np.array([[1e-170, 0.0, 0.5], [0.1, 0.2, 0.5]])
    table, flat = triaxial_table(moments, m0, np.array([False, False]))
    assert flat.tolist() == [True, False]
    assert table.shape == (1, 58)


# the backends other than numpy, each against it: the compiled one, where numba is available
# (without it this test has no parameter, and pytest reports it skipped once)
@pytest.mark.parametrize(
    ("case", "motion_backend"),
    [pytest.param(c, b, id=f"{c[0]}-{b}") for b in MOTION if b != "numpy" for c in CASES],
    indirect=["motion_backend"],
)
def test_compiled_freemotion_equals_numpy_freemotion(case, motion_backend):
    _name, moments, m0, q0, t_unit = case
    t = np.array([0.0, 0.37, 9.71, 100.0]) * t_unit
    m_c, q_c = FreeMotion(moments, m0, q0, backend=motion_backend).propagate(t)
    lazy = FreeMotion(moments, m0, backend=motion_backend)  # the compiled set-up skips the precession rate
    m_l, p_l = lazy.momentum(t), lazy.periods
    m_n, q_n = FreeMotion(moments, m0, q0, backend="numpy").propagate(t)
    p_n = FreeMotion(moments, m0, backend="numpy").periods
    for got, want in zip(p_l, p_n, strict=True):
        np.testing.assert_allclose(got, want, rtol=1e-14, atol=0)
    assert np.max(np.abs(m_l - m_c)) <= 4 * EPS * np.linalg.norm(m0)
    err_m = np.linalg.norm(m_c - m_n, axis=-1) / np.linalg.norm(m0)
    rel = Rotation.from_quat(q_c).inv() * Rotation.from_quat(q_n)
    assert np.max(err_m) <= 1e-13
    assert np.max(rel.magnitude()) <= 1e-12


def test_compiled_classification_equals_classify_and_normalise():
    rng = np.random.default_rng(11)
    moments = rng.uniform(1.0, 2.0, (400, 3))
    moments[:, 2] = np.minimum(moments[:, 2], moments[:, 0] + moments[:, 1])
    moments *= np.exp(rng.uniform(-30, 30, (400, 1)))
    m0 = rng.normal(size=(400, 3)) * np.exp(rng.uniform(-30, 30, (400, 1)))
    m0[::7, rng.integers(3)] = 0.0
    m0[::11, :2] = 0.0
    edge = [
        ([3.0, 4.0, 6.0], [1.0, 0.5, 1.0]),  # exactly on the separatrix
        ([6.0, 3.0, 4.0], [1.0, 1.0, -0.5]),  # the same, axes permuted
        ([1.0, 2.0, 2.0], [0.3, 0.2, 1.0]),  # axisymmetric
        ([2.0, 2.0, 2.0], [0.3, 0.2, 1.0]),  # sphere
        ([1.0, 2.0, 3.0], [0.0, 0.0, 0.0]),  # rest
        ([1.0, 1.7, 2.3], list(with_k2(np.array([1.0, 1.7, 2.3]), 1 - 1e-15))),
        ([1.0, 2.0, 3.0], [1e-170, 0.0, 1e-160]),
        ([1e300, 1.5e300, 2e300], [1e-300, 2e-300, 3e-300]),
    ]
    moments = np.vstack([moments, [e[0] for e in edge]])
    m0 = np.vstack([m0, [e[1] for e in edge]])
    moments, m0 = check_inputs(moments, m0)
    regime, Is, ms, a, b = classify_and_scale(moments, m0)
    Iw, mw, aw, bw = normalise(moments, m0)
    assert np.array_equal(regime, classify(moments, m0))
    assert set(regime.tolist()) == {int(r) for r in Regime}
    assert np.array_equal(Is, Iw)
    assert np.array_equal(ms, mw)
    assert np.array_equal(a, aw)
    assert np.array_equal(b, bw)


def test_numpy_setup_in_blocks_equals_setup_at_once(monkeypatch):
    # the vectorised set-up runs in blocks of states (issue 17: cost per state independent
    # of the batch); steady spins whose wobble underflows fall in several blocks
    moments, m0, _, q0 = _states()
    moments, m0, q0 = moments[:40].copy(), m0[:40].copy(), q0[:40]
    spins = [3, 17, 18, 31]
    for i in spins:  # about the axis of largest moment, with a wobble that underflows
        j = int(np.argmax(moments[i]))
        m0[i] = 0.0
        m0[i, j], m0[i, (j + 1) % 3] = 0.5, 1e-170
    t = np.array([[0.0, 0.37, -9.71, 100.0]])
    m_one, q_one = FreeMotion(moments[:, None], m0[:, None], q0[:, None], backend="numpy").propagate(t)
    monkeypatch.setattr(motion, "_SETUP_BLOCK", 7)
    fm = FreeMotion(moments[:, None], m0[:, None], q0[:, None], backend="numpy")
    m_blk, q_blk = fm.propagate(t)
    assert np.array_equal(m_one, m_blk)
    assert np.array_equal(q_one, q_blk)
    assert np.array_equal(m_blk[spins], np.broadcast_to(m0[spins, None], (4, 4, 3)))
