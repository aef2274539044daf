"""The obliquity forced by several node modes (``andoyer.planetary.cassini.forced``).

Independent checks: the spin axis integrated in the inertial frame from the torque alone,
``ds/dt = (α s·n + β)(s × n)``, with an orbit normal ``n(t)`` that is a sum of modes (written
out here) or that comes from integrating the nonlinear averaged equations of Jupiter's
satellites; the fast least-obliquity root against the full root set; Europa's obliquity against
Baland, Yseboodt & Van Hoolst (2012).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from andoyer.planetary import cassini
from andoyer.planetary.cassini import named
from andoyer.planetary.cassini.body import CassiniBody
from andoyer.planetary.cassini.forced import ForcedObliquity, NodeMode, least_obliquity_state
from andoyer.planetary.cassini.top import ColomboTop

DEG = math.pi / 180


def tilt_to_vector(w):
    """A complex tilt about z to a unit vector (small angle, exact on the sphere)."""
    v = np.stack([np.real(w), np.imag(w), np.ones_like(np.real(w))], -1)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def integrate_spin(alpha, beta, normal, s0, t):
    """ds/dt = (α s·n + β)(s × n) with n = normal(t) (unit), inertial frame; s at the times t."""

    def rhs(time, s):
        n = normal(time)
        return (alpha * (s @ n) + beta) * np.cross(s, n)

    y = solve_ivp(rhs, (t[0], t[-1]), s0, t_eval=t, method="DOP853", rtol=1e-11, atol=1e-14).y
    return y.T


# A Titan-like body: κ = α + β ≈ 0.033 rad/yr.
BODY = CassiniBody("x", 3.18e-5, 1.0e-5, 0.34, 143.9, 0.029, 0.3 * DEG, -0.009)


@pytest.mark.parametrize(
    "modes",
    [
        # one slow, one faster than κ (state 2 branch), one near: amplitudes and phases arbitrary
        (
            NodeMode(-0.009, 0.3 * DEG, 0.4),
            NodeMode(-0.05, 0.05 * DEG, 2.0),
            NodeMode(-0.02, 0.1 * DEG, -1.0),
        ),
        (NodeMode(-0.004, 0.5 * DEG, 0.0), NodeMode(-0.0011, 0.2 * DEG, 1.3)),
    ],
)
def test_forced_obliquity_matches_inertial_integration(modes):
    forced = ForcedObliquity(BODY, modes)
    rates = np.array([m.node_rate for m in modes])
    amps = np.array([m.inclination for m in modes])
    phases = np.array([m.phase for m in modes])

    def normal(time):
        return tilt_to_vector(np.sum(amps * np.exp(1j * (phases + rates * time))))

    t = np.linspace(0.0, 2 * math.pi / min(abs(rates)), 301)
    s = integrate_spin(
        BODY.precession_constant, BODY.resonance_constant, normal, tilt_to_vector(forced.spin_axis(0.0)), t
    )
    n = np.array([normal(x) for x in t])
    obliquity = np.arccos(np.clip(np.einsum("ij,ij->i", s, n), -1, 1))
    predicted = forced.obliquity(t)
    assert np.max(np.abs(obliquity - predicted)) < 1e-3 * np.max(predicted)
    low, high = forced.obliquity_range()
    assert low - 1e-12 <= np.min(predicted)
    assert np.max(predicted) <= high + 1e-12


def test_forced_obliquity_one_mode_is_the_cassini_state():
    forced = ForcedObliquity(BODY, (NodeMode(BODY.node_rate, BODY.inclination, 0.7),))
    state = next(s for s in cassini.states(BODY) if s.number == 1)
    t = np.linspace(0.0, 1000.0, 11)
    assert np.allclose(forced.obliquity(t), state.obliquity, rtol=1e-14, atol=0)
    assert forced.obliquity_range() == pytest.approx((state.obliquity, state.obliquity), rel=1e-14)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(
    alpha=st.floats(0.01, 100.0),
    beta_fraction=st.floats(0.0, 0.5),
    ratio=st.floats(0.01, 20.0),
    i=st.floats(0.001, 1.4),
)
def test_least_obliquity_theta_is_the_least_obliquity_state(alpha, beta_fraction, ratio, i):
    beta = beta_fraction * alpha
    top = ColomboTop(alpha, beta, -ratio * (alpha + beta), i)
    best = min(top.states(), key=lambda s: s.obliquity)
    assert top.least_obliquity_theta() == pytest.approx(best.theta, abs=1e-10)


def test_galilean_end_to_end_europa_and_ganymede():
    """Jupiter's satellites' orbit normals from the nonlinear averaged equations, Europa's and
    Ganymede's spin axes from the torque equation driven by them: the obliquities over 150 years
    against the sum of the modes' Cassini states (Ganymede's with the resonant Europa mode)."""
    frame = named.satellite_system("jupiter")
    system = frame.system
    poles, phi, tilts = system.poles(), system.laplace_angles(), frame.tilts()
    e1 = np.stack([np.cos(phi), np.zeros_like(phi), -np.sin(phi)], -1)
    e2 = np.array([0.0, 1.0, 0.0])
    start = poles + tilts.real[:, None] * e1 + tilts.imag[:, None] * e2
    start /= np.linalg.norm(start, axis=-1, keepdims=True)
    names = ("europa", "ganymede")
    forced = [cassini.forced_obliquity(name) for name in names]
    index = [system.index(name) for name in names]
    spins = []
    for f, j in zip(forced, index, strict=True):
        w = f.spin_axis(0.0)
        s = poles[j] + w.real * e1[j] + w.imag * e2
        spins.append(s / np.linalg.norm(s))

    def rhs(_, y):
        h = y[:12].reshape(4, 3)
        out = [system.vector_field(h).ravel()]
        for f, j, k in zip(forced, index, (12, 15), strict=True):
            s = y[k : k + 3]
            a, b = f.body.precession_constant, f.body.resonance_constant
            out.append((a * (s @ h[j]) + b) * np.cross(s, h[j]))
        return np.concatenate(out)

    t = np.linspace(0.0, 150.0, 76)
    y0 = np.concatenate([start.ravel(), *spins])
    y = solve_ivp(rhs, (0.0, t[-1]), y0, t_eval=t, method="DOP853", rtol=1e-11, atol=1e-14).y.T
    for f, j, k in zip(forced, index, (12, 15), strict=True):
        h, s = y[:, 3 * j : 3 * j + 3], y[:, k : k + 3]
        obliquity = np.arccos(
            np.clip(np.einsum("ij,ij->i", s / np.linalg.norm(s, axis=1)[:, None], h), -1, 1)
        )
        predicted = f.obliquity(t)
        assert np.max(np.abs(obliquity - predicted)) < 5e-3 * np.max(predicted), f.body.name


def test_europa_obliquity_baland_2012():
    """Baland, Yseboodt & Van Hoolst (2012, Icarus 220, 435; arXiv:1205.3628): a solid Europa's
    mean obliquity 0.055°, almost constant in time."""
    forced = cassini.forced_obliquity("europa")
    t = np.linspace(0.0, 2000.0, 2001)
    obliquity = np.degrees(forced.obliquity(t))
    assert np.mean(obliquity) == pytest.approx(0.055, rel=0.1)
    assert np.ptp(obliquity) < 0.1 * np.mean(obliquity)
    single = cassini.forced_obliquity("europa", node="catalogue")  # JPL's 30.18-yr node
    assert math.degrees(float(single.obliquity())) == pytest.approx(0.055, rel=0.03)


def test_least_obliquity_state_numbers():
    # Mercury and the satellites in state 1, the Moon in state 2 (past the bifurcation)
    assert least_obliquity_state(cassini.get("mercury")).number == 1
    assert least_obliquity_state(cassini.get("moon")).number == 2
    assert least_obliquity_state(cassini.get("titan")).number == 1


@pytest.mark.parametrize(
    "args", [(0.1, 0.01, 0.0), (-0.1, -0.01, 0.0), (-0.1, 2.0, 0.0), (-0.1, float("nan"), 0.0)]
)
def test_node_mode_bad_input(args):
    with pytest.raises(ValueError, match="expected"):
        NodeMode(*args)


@pytest.mark.parametrize(
    ("body", "modes"), [(BODY, ()), (BODY, (NodeMode(-0.01, 0.0, 0.0),)), ("x", (NodeMode(-0.01, 0.01),))]
)
def test_forced_obliquity_bad_input(body, modes):
    with pytest.raises(ValueError, match="expected"):
        ForcedObliquity(body, modes)
