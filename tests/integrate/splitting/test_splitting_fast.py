"""The lean free flow against FreeMotion, the compiled splitting loop against the generic one, long runs."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State
from andoyer import _jit as andoyer_jit
from andoyer.free import FreeMotion, Regime, classify
from andoyer.free import step_scalar as lean
from andoyer.integrate import integrate_reference, splitting
from andoyer.integrate.splitting import integrate_splitting
from andoyer.perturbations import CircularOrbit, GravityGradient, HeavyTop, Model, PointMass, PrecessingFrame
from conftest import REGIME_BODIES, rotation_distance

TRIAXIAL = np.array([0.7, 1.0, 1.3])


def _states(seed: int, n: int, moments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    q = Rotation.random(n, rng=rng).as_quat()
    m = rng.normal(size=(n, 3))
    return q, m * rng.uniform(0.5, 2.0, size=(n, 1)) / np.linalg.norm(m, axis=-1, keepdims=True)


def _separatrix_states(delta: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Momenta at relative distance ``delta`` (sign: SAM > 0, LAM < 0) from the separatrix."""
    A, B, C = TRIAXIAL
    rng = np.random.default_rng(7)
    ma = np.sqrt((C - B) * A / ((B - A) * C))
    m = np.tile([ma, 0.0, 1.0 + delta], (n, 1)) * rng.choice([-1.0, 1.0], size=(n, 3))
    m *= rng.uniform(0.5, 2.0, size=(n, 1))
    return Rotation.random(n, rng=rng).as_quat(), m


def _compare(moments, q, m, h):
    q1, m1 = lean.free_step(moments, q, m, h)
    m_ref, q_ref = FreeMotion(moments, m, q).propagate(h)
    scale = np.linalg.norm(m, axis=-1)
    return np.max(np.abs(m1 - m_ref).max(axis=-1) / scale), np.max(rotation_distance(q1, q_ref))


CASES = {
    "sam-lam": (TRIAXIAL, lambda: _states(1, 64, TRIAXIAL)),
    "strongly-triaxial": (REGIME_BODIES["strongly-triaxial"].moments, lambda: _states(2, 64, TRIAXIAL)),
    "unsorted-axes": (np.array([1.3, 0.7, 1.0]), lambda: _states(3, 64, TRIAXIAL)),
    "earth-near-pure-spin": (
        REGIME_BODIES["earth"].moments,
        lambda: (_states(4, 32, TRIAXIAL)[0], np.array([1e-7, -2e-7, 1.0]) + np.zeros((32, 3))),
    ),
    "near-separatrix-sam": (TRIAXIAL, lambda: _separatrix_states(1e-9, 16)),
    "near-separatrix-lam": (TRIAXIAL, lambda: _separatrix_states(-1e-9, 16)),
    "oblate": (REGIME_BODIES["oblate"].moments, lambda: _states(5, 32, TRIAXIAL)),
    "prolate": (REGIME_BODIES["prolate"].moments, lambda: _states(6, 32, TRIAXIAL)),
    "sphere": (REGIME_BODIES["spherical"].moments, lambda: _states(8, 32, TRIAXIAL)),
}


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("h", [0.01, -0.7, 3.0])
def test_lean_free_step_matches_free_motion(case, h):
    moments, make = CASES[case]
    q, m = make()
    # |m| in [1/2, 2]: steps up to a few radians of spin, up to ~1/2 polhode period (the
    # splitting's use); FreeMotion is independent (theta series in double-double, not
    # Carlson integrals and the AGM)
    dm, dq = _compare(moments, q, m, h)
    assert dm <= 1e-13
    assert dq <= 1e-13


def test_lean_free_step_covers_every_regime():
    codes = set()
    for moments, make in CASES.values():
        _, m = make()
        codes.update(int(c) for c in classify(moments, m).ravel())
    assert {Regime.SAM, Regime.LAM, Regime.AXISYMMETRIC, Regime.SPHERE} <= codes


def test_lean_free_step_steady_spins_and_rest():
    q = np.tile([0.1, 0.2, 0.3, 0.9273618495495704], (4, 1))
    m = np.array(
        [[0.0, 0.0, 2.0], [3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]]
    )  # C, A, B (separatrix), rest
    dm, dq = _compare(TRIAXIAL, q[:3], m[:3], 1.7)
    assert dm <= 1e-15
    assert dq <= 1e-14
    q1, m1 = lean.free_step(TRIAXIAL, q[3:], m[3:], 1.7)
    assert np.array_equal(m1, m[3:])
    assert rotation_distance(q1[0], q[3]) <= 1e-16


def test_lean_free_step_leaves_the_separatrix_to_free_motion():
    A, B, C = TRIAXIAL
    m = np.array([[np.sqrt((C - B) * A / ((B - A) * C)), 0.3, 1.0]])  # exactly P₂ = 0 (to rounding)
    q = np.array([[0.0, 0.0, 0.0, 1.0]])
    assert int(classify(TRIAXIAL, m[0])) in (Regime.SEPARATRIX, Regime.SAM, Regime.LAM)
    dm, dq = _compare(TRIAXIAL, q, m, 2.0)
    assert dm <= 1e-15
    assert dq <= 1e-15


def _fresh_copy(monkeypatch, module, name):
    spec = importlib.util.spec_from_file_location(name, Path(module.__file__))
    copy = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, copy)
    spec.loader.exec_module(copy)
    return copy


def _load_interpreted(monkeypatch):
    """A fresh copy of ``andoyer.free.step_scalar`` imported with ``ANDOYER_NUMBA=0`` (no compilation).

    Its ``jit`` decorator comes from a fresh copy of ``andoyer._jit`` read under the same
    environment, so none of its kernels is compiled.
    """
    monkeypatch.setenv("ANDOYER_NUMBA", "0")
    plain_jit = _fresh_copy(monkeypatch, andoyer_jit, "andoyer_jit_interpreted")
    monkeypatch.setitem(sys.modules, "andoyer._jit", plain_jit)
    return _fresh_copy(monkeypatch, lean, "andoyer_lean_interpreted")


def test_lean_free_step_rejects_mismatched_shapes():
    with pytest.raises(ValueError, match=r"expected as many attitudes as momenta"):
        lean.free_step(TRIAXIAL, np.tile([0.0, 0.0, 0.0, 1.0], (2, 1)), np.ones((3, 3)), 0.1)


def test_lean_interpreted_fallback_agrees_with_compiled(monkeypatch):
    plain = _load_interpreted(monkeypatch)
    assert not plain.NUMBA
    assert not hasattr(plain._step_one, "py_func")  # plain Python, not a numba dispatcher
    q, m = _states(11, 8, TRIAXIAL)
    for moments in (TRIAXIAL, REGIME_BODIES["oblate"].moments):
        q1, m1 = plain.free_step(moments, q, m, 0.3)
        q2, m2 = lean.free_step(moments, q, m, 0.3)
        assert np.abs(m1 - m2).max() <= 1e-14 * np.abs(m).max()
        assert rotation_distance(q1, q2).max() <= 1e-14
    # large batches without numba go to FreeMotion
    q, m = _states(12, 40, TRIAXIAL)
    q1, m1 = plain.free_step(TRIAXIAL, q, m, 0.3)
    m_ref, q_ref = FreeMotion(TRIAXIAL, m, q).propagate(0.3)
    assert np.array_equal(m1, m_ref)
    assert np.array_equal(q1, q_ref)


def start():
    return State.from_attitude(Rotation.from_euler("ZXZ", [0.3, 0.9, 0.4]), [0.2, -0.3, 1.5])


def gravity_model(body=None):
    body = body or RigidBody(0.7, 1.0, 1.3)
    return Model(body, GravityGradient(PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4))))


MIXED = {
    "gravity-gradient": gravity_model,
    "two-perturbers-and-frame": lambda: Model(
        RigidBody(0.7, 1.0, 1.3),
        [
            GravityGradient(
                [
                    PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4)),
                    PointMass(1.0, CircularOrbit(3.0, -0.2)),
                ],
            ),
            PrecessingFrame(lambda t: np.stack([0.01 + 0 * t, 0.02 * np.cos(t), 0.03 + 0 * t], -1)),
        ],
    ),
    "heavy-top": lambda: Model(RigidBody(1.0, 1.2, 0.8), HeavyTop(0.8, [0.1, 0.0, 0.3])),
}


@pytest.mark.parametrize("name", list(MIXED))
@pytest.mark.parametrize("order", [2, 6])
def test_compiled_loop_equals_generic_steps(name, order, monkeypatch):
    model = MIXED[name]()
    fast = integrate_splitting(model, start(), [0.9, 2.0, -1.1], step=0.13, order=order)
    monkeypatch.setattr(splitting, "_tabulable", lambda kicks: False)
    slow = integrate_splitting(model, start(), [0.9, 2.0, -1.1], step=0.13, order=order)
    assert np.abs(fast.m_body - slow.m_body).max() <= 1e-13
    assert rotation_distance(fast.quaternion, slow.quaternion).max() <= 1e-13


def test_splitting_agrees_with_dop853_to_its_accuracy():
    """Order 4 at h and h/2 bracket the error; DOP853 (rtol 1e-12) must sit within it."""
    model = gravity_model()
    t = np.array([0.5, 1.5, 3.0])
    ref = integrate_reference(model, start(), t, rtol=1e-12, atol=1e-14)
    coarse = integrate_splitting(model, start(), t, step=0.05, order=4)
    fine = integrate_splitting(model, start(), t, step=0.025, order=4)
    # the splitting's own error estimate (Richardson: e(h) ≈ 16/15 |x_h − x_{h/2}|)
    claimed = 16 / 15 * np.abs(coarse.m_body - fine.m_body).max()
    assert claimed <= 1e-6
    assert np.abs(coarse.m_body - ref.m_body).max() <= 1.5 * claimed + 1e-11
    assert rotation_distance(fine.quaternion, ref.quaternion).max() <= claimed / 8 + 1e-11


def test_splitting_ensemble_matches_single_states():
    model = gravity_model()
    q, m = _states(21, 5, TRIAXIAL)
    states = State.from_quaternion(q, m)
    together = integrate_splitting(model, states, [1.0], step=0.1, order=4)
    for i in range(5):
        alone = integrate_splitting(model, states[i], [1.0], step=0.1, order=4)
        assert np.abs(together.m_body[i] - alone.m_body[0]).max() <= 1e-15 * np.abs(m[i]).max() + 1e-300
        assert rotation_distance(together.quaternion[i], alone.quaternion[0]) <= 1e-15


def _energy(model, state, t):
    pert = model.perturbation
    return state.energy(model.body) + pert.potential(t, state.quaternion, state.m_body)


@pytest.mark.slow
def test_splitting_energy_bounded_over_a_million_steps():
    """Gravity gradient of a fixed perturber (``ΔH`` autonomous): ``H`` oscillates, no drift."""
    body = RigidBody(0.7, 1.0, 1.3)
    model = Model(body, GravityGradient(PointMass(4.0, CircularOrbit(2.0, 0.0, inclination=0.4))))
    step, n_steps = 0.05, 1_000_000
    t = step * np.linspace(0, n_steps, 2001)
    out = integrate_splitting(model, start(), t, step=step, order=2)
    error = _energy(model, out, t) - _energy(model, start(), 0.0)
    tenth = t.size // 10
    first, last = np.abs(error[:tenth]).max(), np.abs(error[-tenth:]).max()
    assert first > 1e-8  # the splitting's O(h²) oscillation is resolved ...
    assert last <= 1.5 * first  # ... and bounded
    slope = np.polyfit(t, error, 1)[0]
    assert abs(slope) * t[-1] <= 0.05 * first  # negligible linear trend


@pytest.mark.slow
def test_heavy_top_integrals_over_a_million_steps():
    """Heavy top: energy bounded, Casimirs ``|γ| = 1`` and ``M·γ`` conserved to round-off."""
    body = RigidBody(1.0, 1.2, 0.8)
    top = HeavyTop(0.8, [0.1, 0.05, 0.3])
    model = Model(body, top)
    step, n_steps = 0.02, 1_000_000
    s0 = start()
    q, m = splitting._run_steps(
        model,
        splitting._Tables([top], [], 2),
        s0.quaternion[None],
        s0.m_body[None],
        0.0,
        step,
        n_steps,
        0.0,
        2,
    )
    assert abs(np.linalg.norm(q[0]) - 1.0) <= 1e-12  # |γ| = |q|²
    final = State.from_quaternion(q[0] / np.linalg.norm(q[0]), m[0])
    casimir0 = float(np.dot(s0.m_body, s0.gamma))
    # every substep conserves M·γ exactly (kick: τ ⊥ γ; free flow: M fixed), so only
    # round-off accumulates: below n·eps = 2.2e-10 relative (measured: 8e-12)
    roundoff = n_steps * np.finfo(float).eps * np.linalg.norm(s0.m_body)
    assert abs(float(np.dot(final.m_body, final.gamma)) - casimir0) <= roundoff
    t = step * np.linspace(0, n_steps, 1001)
    out = integrate_splitting(model, s0, t, step=step, order=2)
    error = _energy(model, out, t) - _energy(model, s0, 0.0)
    tenth = t.size // 10
    assert np.abs(error[-tenth:]).max() <= 1.5 * np.abs(error[:tenth]).max()
    assert np.abs(np.einsum("...i,...i", out.m_body, out.gamma) - casimir0).max() <= roundoff
