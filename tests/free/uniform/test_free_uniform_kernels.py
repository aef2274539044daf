"""The uniform-motion kernels (andoyer.free.uniform.setup): one text, the same bits on arrays and per state.

The numpy path (:mod:`andoyer.free.uniform`) applies the kernels to whole arrays, one per
component; the compiled path (:mod:`andoyer.free.uniform.evaluate_compiled`, and a loop here) calls them
per state, compiled when numba is (plain Python on floats with ``ANDOYER_NUMBA=0``).  Both must
agree bit for bit, the sign of zeros included; the values themselves are checked against
closed forms in ``test_free_uniform_compiled.py`` and against a Taylor reference in
``test_free_accuracy.py``.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.free.uniform import evaluate_compiled as cuni_eval
from andoyer.free.uniform import evaluate_numpy as uni_eval
from andoyer.free.uniform import setup_compiled as cuni
from andoyer.free.uniform import setup_numpy as uni
from andoyer.free.uniform.evaluate import attitude, momentum, turn
from andoyer.regime import Regime

CASES = ("oblate", "prolate", "sphere", "steady_spin", "rest")
# decimal exponents of the momentum and of the moments: the squares of the momentum stay
# normal (no underflow of the error-free products, which Dekker's split and the fused
# multiply-add then still give alike)
SCALES = {"tiny": (-120, -40), "unit": (0, 0), "huge": (120, 40)}


def uniform_states(case, scale, rng, n=48):
    """Seeded states of one kind: moments, momenta, regime codes and unit attitudes.

    Ties of the largest momentum components (``|m₀| = |m₁|``) exercise the first-of-equals
    axis of spheres, and a third of the axisymmetric states have ``m₀`` on the symmetry axis.
    """
    m_exp, i_exp = SCALES[scale]
    rows = np.arange(n)
    axis = rng.integers(0, 3, n)
    I_t = rng.uniform(0.5, 1.0, n)
    I_s = I_t * (rng.uniform(1.0001, 1.5, n) if case == "oblate" else rng.uniform(0.5, 0.9999, n))
    moments = np.repeat(I_t[:, None], 3, axis=1)
    moments[rows, axis] = I_s
    m0 = rng.normal(size=(n, 3))
    regime = np.full(n, Regime.AXISYMMETRIC)
    if case in ("oblate", "prolate"):
        m0[::3] = 0.0
        m0[::3, axis[::3]] = rng.normal(size=m0[::3].shape[0])
    elif case == "sphere":
        moments[:] = I_t[:, None]
        m0[::3, 1] = -m0[::3, 0]
        regime[:] = Regime.SPHERE
    elif case == "steady_spin":  # about a principal axis of a triaxial body
        moments = rng.uniform(0.5, 1.0, (n, 3))
        m0[:] = 0.0
        m0[rows, axis] = rng.normal(size=n)
        regime[:] = np.where(rng.random(n) < 0.5, Regime.SAM, Regime.LAM)
    else:
        m0[:] = 0.0
        regime[:] = Regime.REST
    q0 = Rotation.random(n, rng=rng).as_quat()
    return moments * 10.0**i_exp, m0 * 10.0**m_exp, regime, q0


def assert_same_bits(a, b):
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    assert a.shape == b.shape
    assert np.array_equal(a.view(np.int64), b.view(np.int64))


@functools.cache
def _motion_loop():
    """The motion kernels per state, in a loop compiled when numba is."""
    from andoyer._jit import jit

    @jit
    def loop(f_body, f_spin, c, m, q):
        for i in range(c.shape[0]):
            row = c[i]
            cb, sb = turn(f_body[i])
            ca, sa = turn(f_spin[i])
            m[i, 0], m[i, 1], m[i, 2] = momentum(cb, sb, row[4:7], row[7:10], row[10:13])
            q[i, 0], q[i, 1], q[i, 2], q[i, 3] = attitude(
                cb, sb, ca, sa, row[13:17], row[17:21], row[21:25], row[25:29]
            )

    return loop


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("case", CASES)
def test_uniform_kernels_setup_arrays_equal_per_state(case, scale, rng):
    """Axis, moments, frequencies, decomposition and quaternions: numpy arrays against the compiled loop."""
    moments, m0, regime, q0 = uniform_states(case, scale, rng)
    axis, I_s, I_t = uni.uniform_axes(moments, m0, regime)
    arrays = uni.uniform(m0, axis, I_s, I_t, q0)
    table = cuni.uniform_table(moments, m0, regime, q0)
    columns = np.concatenate(
        [
            np.stack([arrays.spin.hi, arrays.spin.lo, arrays.body.hi, arrays.body.lo]),
            arrays.m_par,
            arrays.m_perp,
            arrays.m_cross,
            arrays.q1,
            arrays.q2,
            arrays.q3,
            arrays.q4,
        ]
    )
    assert_same_bits(columns.T, table.table)
    assert_same_bits(arrays.period, table.period)
    assert_same_bits(arrays.precession_rate, table.precession_rate)
    # the axis is the one the case implies: the distinct moment, else the largest |m|, first of equals
    if case in ("oblate", "prolate"):
        expected = np.argmax(moments != np.median(moments, axis=1, keepdims=True), axis=1)
    else:
        expected = np.argmax(np.abs(m0), axis=1)
    assert np.array_equal(axis, expected)
    assert np.all((I_t == I_s) == (case not in ("oblate", "prolate")))


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("case", CASES)
def test_uniform_kernels_motion_arrays_equal_per_state(case, scale, rng):
    """``m(t)`` and ``q(t)`` from the same phases: numpy arrays against the compiled loop."""
    moments, m0, regime, q0 = uniform_states(case, scale, rng)
    table = cuni.uniform_table(moments, m0, regime, q0).table
    n = table.shape[0]
    f_body, f_spin = rng.uniform(-0.5, 0.5, (2, n))
    f_body[:4] = (0.0, -0.5, 0.5, 0.25)
    m, q = np.empty((n, 3)), np.empty((n, 4))
    _motion_loop()(f_body, f_spin, table, m, q)
    c = table.T  # one array per column, as the numpy path holds them
    cb, sb = turn(f_body)
    ca, sa = turn(f_spin)
    assert_same_bits(np.stack(momentum(cb, sb, c[4:7], c[7:10], c[10:13]), axis=-1), m)
    assert_same_bits(np.stack(attitude(cb, sb, ca, sa, c[13:17], c[17:21], c[21:25], c[25:29]), axis=-1), q)


@pytest.mark.parametrize("case", CASES)
def test_uniform_kernels_evaluate_numpy_equals_compiled(case, rng):
    """The two drivers end to end, phases included (pre-split Dekker products against fused multiply-add)."""
    moments, m0, regime, q0 = uniform_states(case, "unit", rng)
    arrays = uni.uniform(m0, *uni.uniform_axes(moments, m0, regime), q0)
    table = cuni.uniform_table(moments, m0, regime, q0)
    t = np.concatenate([np.zeros((48, 1)), rng.uniform(-1e6, 1e6, (48, 3))], axis=1)
    per_row = arrays._replace(
        spin=type(arrays.spin)(*(x[:, None] for x in arrays.spin)),
        body=type(arrays.body)(*(x[:, None] for x in arrays.body)),
        **{f: getattr(arrays, f)[..., None] for f in ("m_par", "m_perp", "m_cross", "q1", "q2", "q3", "q4")},
    )
    m_np, q_np = uni_eval.evaluate(per_row, t)
    m_c, q_c = cuni_eval.evaluate(table, t)
    for a, b in zip(m_np + q_np, m_c + q_c, strict=True):
        assert np.array_equal(a, b)  # equal values (numpy's phase adds +0.0: a zero's sign may differ)
