"""The compiled uniform motions (regular precession, steady spins) against numpy and closed forms."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.free.common import polhode_compiled
from andoyer.free.motion import FreeMotion
from andoyer.free.uniform import evaluate_compiled as cuni_eval
from andoyer.free.uniform import evaluate_numpy as uni_eval
from andoyer.free.uniform import setup_compiled as cuni
from andoyer.free.uniform import setup_numpy as uni
from andoyer.regime import Regime


def uniform_cases(rng, n=64):
    """Seeded states: axisymmetric (oblate and prolate), spheres, steady spins, rest, any axis and sign.

    Returns the moments, momenta, regimes and attitudes, and the axis ``ŝ`` with ``I_s, I_t``
    of :func:`andoyer.free.uniform.setup_numpy.uniform_axes`.
    """
    m0 = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-3, 3, (n, 1))
    axis = rng.integers(0, 3, n)
    I_s = rng.uniform(0.5, 1.0, n)
    I_t = rng.uniform(0.5, 1.0, n)
    moments = np.repeat(I_t[:, None], 3, axis=1)
    moments[np.arange(n), axis] = I_s
    regime = np.full(n, Regime.AXISYMMETRIC)
    regime[::4] = Regime.SPHERE  # three equal moments, λ = 0
    moments[::4] = I_s[::4, None]
    spin = np.arange(n) % 4 == 1  # a steady spin about a principal axis of a triaxial body
    moments[spin] = rng.uniform(0.5, 1.0, (spin.sum(), 3))
    m0[spin] = 0.0
    m0[spin, axis[spin]] = rng.normal(size=spin.sum())
    regime[spin] = Regime.SAM
    m0[:8][~spin[:8], :2] = 0.0  # along the third axis
    m0[8:12] = 0.0  # at rest
    regime[8:12] = Regime.REST
    q0 = Rotation.random(n, rng=rng).as_quat()
    return moments, m0, regime, q0, uni.uniform_axes(moments, m0, regime)


def test_free_compiled_uniform_equals_numpy(rng):
    moments, m0, regime, q0, (axis, I_s, I_t) = uniform_cases(rng)
    ref = uni.uniform(m0, axis, I_s, I_t, q0)
    new = cuni.uniform_table(moments, m0, regime, q0)
    assert np.array_equal(new.period, ref.period)
    assert np.array_equal(new.precession_rate, ref.precession_rate)
    t = np.concatenate([np.zeros((64, 1)), rng.uniform(-1e6, 1e6, (64, 4))], axis=1)
    fields = {f: getattr(ref, f)[..., None] for f in ("m_par", "m_perp", "m_cross", "q1", "q2", "q3", "q4")}
    rows = ref._replace(
        spin=type(ref.spin)(*[x[:, None] for x in ref.spin]),
        body=type(ref.body)(*[x[:, None] for x in ref.body]),
        **fields,
    )
    m_ref, q_ref = uni_eval.evaluate(rows, t)
    m_new, q_new = cuni_eval.evaluate(new, t)
    G = np.linalg.norm(m0, axis=-1)[:, None]
    for a, b in zip(m_new, m_ref, strict=True):
        assert np.all(np.abs(a - b) <= 4e-16 * G)
    for a, b in zip(q_new, q_ref, strict=True):
        assert np.max(np.abs(a - b)) <= 1e-15


def test_free_compiled_uniform_matches_the_closed_form_rotation(rng):
    """``rot(t) = R_m̂(Ω t) rot₀ R_ŝ(λ t)``, ``m(t) = R_ŝ(−λ t) m₀``, composed by scipy."""
    moments, m0, regime, q0, (axis, I_s, I_t) = uniform_cases(rng, 32)
    t = rng.uniform(-20.0, 20.0, 32)
    m, q = cuni_eval.evaluate(cuni.uniform_table(moments, m0, regime, q0), t[:, None])
    s_hat = np.eye(3)[axis]
    G = np.linalg.norm(m0, axis=-1)
    lam = m0[np.arange(32), axis] * (1 / I_s - 1 / I_t)
    rot0 = Rotation.from_quat(q0)
    m_hat = rot0.apply(m0) / np.where(G > 0, G, 1.0)[:, None]
    spin, turn = m_hat * (G / I_t * t)[:, None], s_hat * (lam * t)[:, None]
    exact = Rotation.from_rotvec(spin) * rot0 * Rotation.from_rotvec(turn)
    m_exact = Rotation.from_rotvec(-s_hat * (lam * t)[:, None]).apply(m0)
    scale = np.maximum(G, 1.0) * np.maximum(1.0, np.abs(G / I_t * t) + np.abs(lam * t))
    assert np.all(np.abs(np.stack(m, -1)[:, 0] - m_exact).max(-1) <= 1e-14 * scale)
    diff = exact.inv() * Rotation.from_quat(np.stack(q, -1)[:, 0])
    assert np.all(diff.magnitude() <= 1e-14 * scale)


@pytest.mark.parametrize("lam", [False, True])
def test_free_compiled_uniform_polhode_limit_mpmath(lam, rng):
    """Steady spin about the polhode axis: ``ω = G √(e₁₃ e₂₃)``, period ``2π/ω``, rate ``G w₃ + s ω``.

    Against the same formulas at 30 digits (mpmath).
    """
    moments = np.sort(rng.uniform(0.5, 1.0, (8, 3)), axis=-1)[:, rng.permutation(3)]
    axis = np.argmin(moments, -1) if lam else np.argmax(moments, -1)
    m0 = np.zeros((8, 3))
    m0[np.arange(8), axis] = rng.uniform(-2.0, 2.0, 8)
    period, rate = polhode_compiled.polhode_limit(moments, m0, np.full(8, lam))
    mpmath.mp.dps = 30
    for i in range(8):
        A, B, C = (mpmath.mpf(float(x)) for x in np.sort(moments[i]))
        G = abs(mpmath.mpf(float(m0[i, axis[i]])))
        if lam:  # polhode about A: e₁₃ = 1/A − 1/C, e₂₃ = 1/A − 1/B, s = −1
            om = G * mpmath.sqrt((1 / A - 1 / C) * (1 / A - 1 / B))
            expected_rate = G / A - om
        else:
            om = G * mpmath.sqrt((1 / A - 1 / C) * (1 / B - 1 / C))
            expected_rate = G / C + om
        assert float(period[i]) == pytest.approx(float(2 * mpmath.pi / om), rel=1e-15)
        assert float(rate[i]) == pytest.approx(float(expected_rate), rel=1e-15)


@pytest.mark.parametrize(
    ("moments", "m0"),
    [
        ([0.99672, 0.99672, 1.0], [[1e-3, -2e-3, 1.0], [0.0, 0.0, -3.0]]),  # oblate, tilted and steady
        ([1.3, 1.0, 1.0], [[0.2, 0.5, -0.1], [1e-200, 0.0, 0.0]]),  # prolate, tiny momentum
        ([0.8, 0.9, 1.0], [[0.0, 0.0, 2.0], [-3.0, 0.0, 0.0]]),  # steady spins about C and A
        ([2.0, 2.0, 2.0], [[0.3, 0.4, 1.0], [0.0, 0.0, 0.0]]),  # sphere, rest
    ],
)
def test_free_compiled_uniform_free_motion_equals_numpy_path(moments, m0, rng):
    q0 = Rotation.random(2, rng=rng).as_quat()
    t = np.array([[-3e3], [0.0], [0.5], [1e4]])
    fast = FreeMotion(moments, m0, q0)  # the default backend: compiled wherever numba is
    m_fast, q_fast = fast.propagate(t)
    slow = FreeMotion(moments, m0, q0, backend="numpy")
    m_slow, q_slow = slow.propagate(t)
    for a, b in zip(fast.periods, slow.periods, strict=True):
        assert np.array_equal(a, b)
    G = np.linalg.norm(np.asarray(m0), axis=-1)
    assert np.all(np.abs(m_fast - m_slow).max(-1) <= 4e-16 * G)
    assert np.max(np.abs(q_fast - q_slow)) <= 1e-15
