"""The Andoyer ⇄ Sadov maps: round trips, canonicity, conventions, degenerate bodies and bad input."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from test_sadov_support import (
    BODIES,
    CASES,
    SCALES,
    circle,
    inverse_moments,
    sample,
    scaled,
    separatrix_distance,
)

from andoyer import RigidBody, State
from andoyer.state import Andoyer, SingularChartWarning
from andoyer.state.sadov import (
    Sadov,
    andoyer_to_sadov,
    sadov_frequencies,
    sadov_hamiltonian,
    sadov_to_andoyer,
    separatrix_action,
)
from conftest import random_states, rotation_distance

J6 = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.eye(3), np.zeros((3, 3))]])
ROUND_TRIP = 1e-13


def andoyer_errors(a, ref):
    """Largest angle error on the circle and momentum error relative to G."""
    angles = max(np.max(np.abs(circle(x - y))) for x, y in zip(a[:3], ref[:3], strict=True))
    momenta = max(np.max(np.abs(x - y) / ref[4]) for x, y in zip(a[3:], ref[3:], strict=True))
    return angles, momenta


@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES)
@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_round_trip_andoyer_sadov_andoyer(name, regime, moment_scale, momentum_scale, rng):
    body = scaled(BODIES[name], moment_scale)
    a = sample(body, rng, 200, regime, G=momentum_scale)
    back = sadov_to_andoyer(body, *andoyer_to_sadov(body, *a))
    assert max(andoyer_errors(back, a)) <= ROUND_TRIP


@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_round_trip_sadov_andoyer_sadov(name, regime, rng):
    body = BODIES[name]
    s = andoyer_to_sadov(body, *sample(body, rng, 200, regime, G=2.0))
    again = andoyer_to_sadov(body, *sadov_to_andoyer(body, *s))
    assert np.max(np.abs(circle(again.phi_l - s.phi_l))) <= ROUND_TRIP
    assert np.max(np.abs(circle(again.phi_g - s.phi_g))) <= ROUND_TRIP
    assert np.max(np.abs(again.I_l - s.I_l)) <= ROUND_TRIP * 2.0


@pytest.mark.parametrize("name", [c[0] for c in CASES if c[1] == "near-separatrix"])
def test_round_trip_near_separatrix_is_bounded_by_the_conditioning(name, rng):
    """Within ``d`` of the separatrix the chart's conditioning is ``1/d``: the round trip error
    is at most ``1e-13 + 1e-16/d`` (``d`` the energy's distance relative to its region's width)."""
    body = BODIES[name]
    a = sample(body, rng, 400, "near-separatrix")
    back = sadov_to_andoyer(body, *andoyer_to_sadov(body, *a))
    d = separatrix_distance(body, a[0], a[3], a[4])
    err_l = np.abs(circle(back.l - a[0]))
    err_g = np.abs(circle(back.g - a[1]))
    err_L = np.abs(back.L - a[3]) / a[4]
    bound = ROUND_TRIP + 1e-16 / d
    assert np.all(err_l <= bound)
    assert np.all(err_g <= bound)
    assert np.all(err_L <= bound)


bodies = st.sampled_from(sorted(BODIES))
angles = st.floats(0.0, 2 * np.pi, exclude_max=True)
fractions = st.floats(-1.0, 1.0)
scales = st.sampled_from(SCALES)


@settings(max_examples=150, deadline=None)
@given(bodies, scales, angles, angles, angles, fractions, fractions)
def test_round_trip_hypothesis(name, scale, l, g, h, x, y):
    """Any state at least 1e-2 (relative) from the separatrix comes back to 1e-13."""
    body = scaled(BODIES[name], scale[0])
    G = scale[1]
    L, H = G * x, G * y
    assume(separatrix_distance(body, l, L, G) > 1e-2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularChartWarning)  # exact libration centres
        s = andoyer_to_sadov(body, l, g, h, L, G, H)
    back = sadov_to_andoyer(body, *s)
    err_angles, err_momenta = andoyer_errors(back, (l, g, h, L, G, H))
    assert err_momenta <= ROUND_TRIP
    # l is undefined at the poles L = ±G and at the libration centres.
    if abs(x) < 1 and s.I_l != 0:
        assert err_angles <= ROUND_TRIP


@settings(max_examples=150, deadline=None)
@given(bodies, scales, angles, angles, angles, fractions, fractions)
def test_round_trip_hypothesis_from_sadov(name, scale, phi_l, phi_g, phi_h, u, y):
    """Sadov → Andoyer → Sadov. φ_ℓ is undefined at the libration centres (I_ℓ = 0) and the
    poles (|I_ℓ| = G), where the orbit shrinks to a point: the state keeps the angle only to
    ``ε/√d`` with ``d`` the distance ``|I_ℓ|/G`` or ``1 − |I_ℓ|/G``."""
    body = scaled(BODIES[name], scale[0])
    G = scale[1]
    u_s = separatrix_action(body, 1.0)
    assume(abs(abs(u) - u_s) > 1e-2 * max(u_s, 1 - u_s))
    s = Sadov(phi_l, phi_g, phi_h, G * u, G, G * y)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularChartWarning)  # I_ℓ = 0 maps onto a centre
        again = andoyer_to_sadov(body, *sadov_to_andoyer(body, *s))
    assert abs(again.I_l - s.I_l) <= ROUND_TRIP * G
    assert abs(circle(again.phi_g - phi_g)) <= ROUND_TRIP
    d = min(abs(u), 1 - abs(u))
    if d > 0:
        assert abs(circle(again.phi_l - phi_l)) <= ROUND_TRIP + 1e-15 / np.sqrt(d)


def jacobians(f, x, step):
    """Richardson-extrapolated central differences at the rows of ``x`` (n, 6), all in one call
    of the vectorised ``f``; angle outputs differenced on the circle."""
    n = x.shape[0]
    eye = np.eye(6)
    # Points x ± h e_i and x ± (h/2) e_i for every column i: shape (4, 6, n, 6).
    offsets = (
        np.array([1.0, -1.0, 0.5, -0.5])[:, None, None, None] * eye[None, :, None, :] * step[None, None, :, :]
    )
    values = f((x[None, None] + offsets).reshape(-1, 6)).reshape(4, 6, n, 6)

    def diff(a, b, h):
        d = values[a] - values[b]
        d[..., :3] = circle(d[..., :3])
        return d / (2 * h)

    h = step.T[:, :, None]  # (6, n, 1)
    D = (4 * diff(2, 3, h / 2) - diff(0, 1, h)) / 3  # (column, n, output)
    return np.transpose(D, (1, 2, 0))  # (n, output, column)


@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_andoyer_to_sadov_is_canonical(name, regime, rng):
    check_canonical(BODIES[name], regime, rng, 1.0, 1.0, 4)


@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES[1:])
@pytest.mark.parametrize("regime", ["circulation", "libration"])
def test_andoyer_to_sadov_is_canonical_at_every_scale(regime, moment_scale, momentum_scale, rng):
    check_canonical(BODIES["b3-max-b1-intermediate"], regime, rng, moment_scale, momentum_scale, 2)


@pytest.mark.slow
@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES)
@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_andoyer_to_sadov_is_canonical_many_states(name, regime, moment_scale, momentum_scale, rng):
    check_canonical(BODIES[name], regime, rng, moment_scale, momentum_scale, 20)


def check_canonical(body, regime, rng, moment_scale, momentum_scale, n):
    """Mᵀ J M = J for the 6×6 Jacobian (momenta in units of G, which leaves the condition unchanged)."""
    body = scaled(body, moment_scale)
    G = momentum_scale

    def f(v):
        s = andoyer_to_sadov(body, v[:, 0], v[:, 1], v[:, 2], v[:, 3] * G, v[:, 4] * G, v[:, 5] * G)
        return np.stack([s.phi_l, s.phi_g, s.phi_h, s.I_l / G, s.I_g / G, s.I_h / G], axis=-1)

    a = sample(body, rng, 20 * n, regime)
    d = separatrix_distance(body, a[0], a[3], a[4])
    keep = np.flatnonzero((d > 0.1) & (np.abs(a[3]) < 0.98))[:n]
    assert len(keep) == n
    x = np.stack([a[0][keep], a[1][keep], a[2][keep], a[3][keep], np.ones(n), 0.9 * a[5][keep]], axis=-1)
    # The orbit's extent in L/G sets the scale of the derivatives: |L| for the tiny librations
    # of the Earth, G − |L| near the poles (where G's step moves L/G as much as L's).
    x_abs = np.abs(a[3][keep])
    step = 1e-3 * np.minimum(1.0, d[keep])[:, None] * np.ones((n, 6))
    step[:, 3:5] *= np.minimum(np.maximum(x_abs, 0.05), 1 - x_abs)[:, None]
    M = jacobians(f, x, step)
    error = np.abs(np.transpose(M, (0, 2, 1)) @ J6 @ M - J6).max()
    assert error <= 1e-8


@pytest.mark.parametrize("name", ["b3-max", "b3-min-b1-intermediate", "earth"])
def test_state_wrapper_round_trip_and_energy(name, rng):
    """The two-line wrappers State → Sadov (``andoyer_to_sadov(body, *state.as_andoyer())``) and
    Sadov → State (``State.from_andoyer(*sadov_to_andoyer(body, *s))``) on random hub states:
    H(I_ℓ, I_g) is the state's kinetic energy and the state comes back."""
    body = BODIES[name]
    q, m = random_states(rng, 2000)
    state = State.from_quaternion(q, m)
    s = andoyer_to_sadov(body, *state.as_andoyer())
    energy = state.energy(body)
    assert np.max(np.abs(sadov_hamiltonian(body, s.I_l, s.I_g) / energy - 1)) <= 1e-14
    back = State.from_andoyer(*sadov_to_andoyer(body, *s))
    a = state.as_andoyer()
    keep = separatrix_distance(body, a.l, a.L, a.G) > 1e-2
    G = np.linalg.norm(m, axis=-1)
    assert rotation_distance(back.quaternion, state.quaternion)[keep].max() <= 1e-13
    assert (np.abs(back.m_body - m).max(axis=-1) / G)[keep].max() <= 1e-13


@pytest.mark.parametrize(
    "body", [RigidBody(1.0, 1.0, 1.5), RigidBody(2.0, 2.0, 1.5), RigidBody(1.0, 1.0, 1.0)]
)
def test_axisymmetric_about_b3_is_the_identity(body, rng):
    """I1 = I2 (and the sphere): Andoyer variables are action–angle, (φ, I) = (l, g, h, L, G, H)."""
    G = rng.uniform(0.5, 2, 50)
    a = (
        rng.uniform(0, 2 * np.pi, 50),
        rng.uniform(0, 2 * np.pi, 50),
        rng.uniform(0, 2 * np.pi, 50),
        G * rng.uniform(-1, 1, 50),
        G,
        G * rng.uniform(-1, 1, 50),
    )
    s = andoyer_to_sadov(body, *a)
    assert all(np.array_equal(x, y) for x, y in zip(s, a, strict=True))
    assert all(np.array_equal(x, y) for x, y in zip(sadov_to_andoyer(body, *s), a, strict=True))


def test_near_axisymmetric_body_is_close_to_the_identity(rng):
    """I2 = I1 (1 + 1e-12): the map is the identity up to O(λ²) = O(κ²/x²), x = L/G
    (continuity at I1 = I2 when b2 is the intermediate axis)."""
    body = RigidBody(1.0, 1.0 + 1e-12, 1.5)
    kappa2 = body.I3 * (body.I2 - body.I1) / (body.I1 * (body.I3 - body.I2))
    G = np.ones(100)
    a = (
        rng.uniform(0, 2 * np.pi, 100),
        rng.uniform(0, 2 * np.pi, 100),
        np.zeros(100),
        rng.uniform(-0.99, 0.99, 100) * G,
        G,
        0.5 * G,
    )
    keep = separatrix_distance(body, a[0], a[3], a[4]) > 1e-2
    bound = (1e-14 + kappa2 / a[3] ** 2)[keep]
    s = andoyer_to_sadov(body, *a)
    assert np.all(np.abs(circle(s.phi_l - a[0]))[keep] <= bound)
    assert np.all(np.abs(circle(s.phi_g - a[1]))[keep] <= bound)
    assert np.all(np.abs(s.I_l - a[3])[keep] <= bound)


@pytest.mark.parametrize("name", list(BODIES))
def test_angle_origins(name):
    """φ_ℓ = 0 where the momentum crosses the half-plane (b3, +b_i) (circulation) and where it
    crosses the meridian of σ b_e with L > 0 (libration); φ_ℓ = π on the opposite crossings."""
    body = BODIES[name]
    _, a2, a3, a_i, a_e = inverse_moments(body)
    i_is_b2 = a_i == a2
    l_i = 0.0 if i_is_b2 else np.pi / 2  # +b_i
    l_e = np.pi / 2 if i_is_b2 else 0.0  # +b_e
    G = 1.0
    if a_i != a3:  # circulation exists; on the meridian of b_i every L != 0 circulates
        for L in (0.9, -0.9, 0.1):
            s = andoyer_to_sadov(body, [l_i, l_i + np.pi], 0.0, 0.0, L, G, 0.0)
            assert np.allclose(circle(s.phi_l - [0.0, np.pi]), 0, atol=1e-14)
            assert np.allclose(circle(s.phi_g), 0, atol=1e-14)
    if a_e != a_i:  # libration exists: a state on the meridian of ±b_e, between centre and separatrix
        p = a_e
        e = a_i + 0.5 * (a_e - a_i)
        x = np.sqrt((p - e) / (p - a3))
        for l_c, sign in ((l_e, 1.0), (l_e + np.pi, -1.0)):
            s = andoyer_to_sadov(body, l_c, 0.0, 0.0, [x, -x], G, 0.0)
            assert np.all(np.sign(s.I_l) == sign)
            assert np.allclose(circle(s.phi_l - [0.0, np.pi]), 0, atol=1e-14)
            assert np.allclose(circle(s.phi_g), 0, atol=1e-14)


@pytest.mark.parametrize(("name", "regime"), [c for c in CASES if c[1] != "near-separatrix"])
def test_action_sign_conventions(name, regime, rng):
    """Circulation: sign I_ℓ = sign L; libration: sign I_ℓ = sign of the momentum along b_e."""
    body = BODIES[name]
    l, g, h, L, G, H = sample(body, rng, 100, regime)
    s = andoyer_to_sadov(body, l, g, h, L, G, H)
    a2 = inverse_moments(body)[1]
    a_i = 1.0 / body.B
    m_e = np.sqrt((G - L) * (G + L)) * (np.sin(l) if a_i == a2 else np.cos(l))
    assert np.array_equal(np.sign(s.I_l), np.sign(L) if regime == "circulation" else np.sign(m_e))
    assert np.all(np.abs(s.I_l) > separatrix_action(body, G)) == (regime == "circulation")


def test_separatrix_warns_and_applies_the_convention():
    body = BODIES["b3-max"]  # b_i = b2: the hyperbolic point is l = 0, L = 0
    with pytest.warns(SingularChartWarning, match="separatrix"):
        s = andoyer_to_sadov(body, 0.0, 0.7, 0.1, 0.0, 2.0, 1.0)
    assert (float(s.phi_l), float(s.phi_g)) == (0.0, 0.7)
    assert float(s.I_l) == pytest.approx(float(separatrix_action(body, 2.0)), rel=1e-15)
    with pytest.warns(SingularChartWarning, match="separatrix"):
        a = sadov_to_andoyer(body, 1.3, 0.7, 0.1, separatrix_action(body, 2.0), 2.0, 1.0)
    assert (float(a.l), float(a.g), float(a.L)) == (0.0, 0.7, 0.0)
    with pytest.warns(SingularChartWarning, match="separatrix"):
        w = sadov_frequencies(body, separatrix_action(body, 2.0), 2.0)
    assert float(w.omega_l) == 0.0
    assert float(w.omega_g) == pytest.approx(2.0 / body.I2, rel=1e-15)
    assert float(sadov_hamiltonian(body, separatrix_action(body, 2.0), 2.0)) == pytest.approx(
        2.0 / body.I2, rel=1e-15
    )


def test_circle_of_equilibria_when_the_intermediate_moment_equals_I3():
    """I_i = I3 (b1-symmetric body): m1 = 0 is a circle of equilibria with |I_ℓ| = G."""
    body = BODIES["b1-symmetric"]
    with pytest.warns(SingularChartWarning, match="separatrix"):
        s = andoyer_to_sadov(body, 0.0, 0.2, 0.0, [0.3, -0.3], 1.0, 0.0)
    assert s.I_l.tolist() == [1.0, -1.0]
    with pytest.warns(SingularChartWarning, match="separatrix"):
        a = sadov_to_andoyer(body, 0.5, 0.2, 0.0, [1.0, -1.0], 1.0, 0.0)
    assert a.L.tolist() == [1.0, -1.0]


def test_libration_centre_warns_and_inverse_uses_the_sign_bit():
    body = BODIES["b3-max-b1-intermediate"]  # b_e = b2: the centres are l = 0 and l = π
    with pytest.warns(SingularChartWarning, match="centre"):
        s = andoyer_to_sadov(body, 0.0, 0.4, 0.0, 0.0, 1.0, 0.0)
    assert (float(s.phi_l), float(s.phi_g), float(s.I_l)) == (0.0, 0.4, 0.0)
    a = sadov_to_andoyer(body, 0.3, 0.4, 0.0, [0.0, -0.0], 1.0, 0.0)
    assert np.allclose(circle(a.l - [0.0, np.pi]), 0, atol=1e-15)
    assert np.all(a.L == 0.0)
    assert np.allclose(a.g, 0.4, atol=1e-15)


def test_scalar_and_broadcast_shapes():
    body = BODIES["b3-max"]
    s = andoyer_to_sadov(body, 0.3, 0.2, 0.1, 0.9, 1.0, 0.5)
    assert all(np.shape(v) == () for v in s)
    s = andoyer_to_sadov(body, np.linspace(0, 1, 3)[:, None], 0.2, 0.1, np.linspace(-0.9, 0.9, 4), 1.0, 0.5)
    assert all(np.shape(v) == (3, 4) for v in s)
    a = sadov_to_andoyer(body, *s)
    assert isinstance(a, Andoyer)
    assert all(np.shape(v) == (3, 4) for v in a)
    assert np.shape(sadov_hamiltonian(body, np.zeros((2, 1)), np.ones(5))) == (2, 5)
    assert all(np.shape(w) == (2, 5) for w in sadov_frequencies(body, np.zeros((2, 1)), np.ones(5)))


BAD_ANDOYER = [
    ((0.1, 0.2, 0.3, 0.5, 0.0, 0.1), "expected G > 0"),
    ((0.1, 0.2, 0.3, 0.5, -1.0, 0.1), "expected G > 0"),
    ((0.1, 0.2, 0.3, 1.5, 1.0, 0.1), "expected |L| <= G"),
    ((0.1, 0.2, 0.3, 0.5, 1.0, -1.5), "expected |H| <= G"),
    ((np.nan, 0.2, 0.3, 0.5, 1.0, 0.1), "expected finite l"),
    ((0.1, 0.2, 0.3, np.inf, 1.0, 0.1), "expected finite L"),
    ((np.zeros(2), 0.2, 0.3, np.zeros(3), 1.0, 0.1), "expected shapes that broadcast together"),
]
BAD_SADOV = [
    ((0.1, 0.2, 0.3, 0.5, 0.0, 0.1), "expected I_g > 0"),
    ((0.1, 0.2, 0.3, 1.5, 1.0, 0.1), "expected |I_l| <= I_g"),
    ((0.1, 0.2, 0.3, -1.5, 1.0, 0.1), "expected |I_l| <= I_g"),
    ((0.1, 0.2, 0.3, 0.5, 1.0, 1.5), "expected |I_h| <= I_g"),
    ((0.1, np.nan, 0.3, 0.5, 1.0, 0.1), "expected finite phi_g"),
    ((0.1, 0.2, 0.3, np.nan, 1.0, 0.1), "expected finite I_l"),
    ((0.1, 0.2, 0.3, np.zeros(2), np.ones(3), 0.1), "expected shapes that broadcast together"),
]


@pytest.mark.parametrize(("args", "match"), BAD_ANDOYER)
def test_bad_andoyer_input_raises(args, match):
    with pytest.raises(ValueError, match=match.replace("|", r"\|")):
        andoyer_to_sadov(BODIES["b3-max"], *args)


@pytest.mark.parametrize(("args", "match"), BAD_SADOV)
def test_bad_sadov_input_raises(args, match):
    with pytest.raises(ValueError, match=match.replace("|", r"\|")):
        sadov_to_andoyer(BODIES["b3-max"], *args)


@pytest.mark.parametrize("function", [sadov_hamiltonian, sadov_frequencies, separatrix_action])
def test_bad_actions_raise(function):
    args = (2.0, 1.0) if function is not separatrix_action else (-1.0,)
    with pytest.raises(ValueError, match="expected"):
        function(BODIES["b3-max"], *args)


@pytest.mark.parametrize("moments", [(1.0, 3.0, 2.0), (3.0, 1.0, 2.0)])
def test_b3_of_intermediate_moment_is_rejected(moments):
    with pytest.raises(ValueError, match="expected a body whose axis b3 has the smallest or the largest"):
        andoyer_to_sadov(RigidBody(*moments), 0.1, 0.2, 0.3, 0.5, 1.0, 0.1)
