"""SAMRotation: Lara's SAM/LAM theory evaluated on states, against DOP853 integrations of the
hub equations (rtol = atol = 1e-13), with the error fitted as a power of δ."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from andoyer import RigidBody, State, bodies
from andoyer.integrate import integrate_reference
from andoyer.perturbations import Model
from andoyer.series import lie_sum
from andoyer.state.sam import hub_to_sam, sam_axes, sam_to_hub
from andoyer.theories.sam_rotation import SAMFrequencies, SAMRotation

STRONG = RigidBody(0.4, 0.7, 1.0, name="strongly triaxial")
BODIES = {
    "strong": STRONG,
    "eros": bodies.get("eros"),
    "earth": bodies.get("earth"),
    "moon": bodies.get("moon"),
    "max-on-b1": RigidBody(1.0, 0.45, 0.7),
    "beta-negative": RigidBody(0.7, 0.45, 1.0),
}


def wrap(d):
    return np.angle(np.exp(1j * d))


def initial_states(name, mode, deltas, sign=1.0):
    """States with osculating δ = L/(G s) given, at ℓ = 0.3, g = 0.1, h = 0.4, H = 0.6 G."""
    body = BODIES[name]
    axes = sam_axes(body, mode)
    s = np.sqrt(1 - axes.beta**2)
    q, m = sam_to_hub(0.3, 0.1, 0.4, np.asarray(deltas) * s, 1.0, 0.6, sign, body=body, mode=mode)
    return State(q, m)


def l_period(name, mode):
    axes = sam_axes(BODIES[name], mode)
    return 2 * np.pi * axes.moments[2] / (abs(axes.alpha) * np.sqrt(1 - axes.beta**2))


@cache
def reference(name, mode, deltas, t_end, sign=1.0):
    state = initial_states(name, mode, deltas, sign)
    t = np.linspace(0.0, t_end, 7)
    return state, t, integrate_reference(Model(BODIES[name]), state[:, None], t, rtol=1e-13, atol=1e-13)


def errors(name, mode, order, deltas, t_end, sign=1.0):
    """Max over time of the SAM-variable error (ℓ, g, L/L) and of the hub error (|Δm|/G, attitude)."""
    body = BODIES[name]
    state, t, ref = reference(name, mode, tuple(deltas), t_end, sign)
    out = SAMRotation(body, order=order, mode=mode).propagate(state[:, None], t)
    a = hub_to_sam(ref.quaternion, ref.m_body, body, mode)
    b = hub_to_sam(out.quaternion, out.m_body, body, mode)
    sam_err = np.max(
        [
            np.abs(wrap(a.sam_l - b.sam_l)).max(-1),
            np.abs(wrap(a.sam_g - b.sam_g)).max(-1),
            (np.abs(a.sam_L - b.sam_L) / a.sam_L).max(-1),
        ],
        axis=0,
    )
    dm = np.linalg.norm(ref.m_body - out.m_body, axis=-1).max(-1)
    qa, qb = ref.quaternion, out.quaternion
    dq = np.minimum(np.linalg.norm(qa - qb, axis=-1), np.linalg.norm(qa + qb, axis=-1)).max(-1)
    return sam_err, np.maximum(dm, 2 * dq)


def slope(deltas, errs):
    return np.polyfit(np.log(deltas), np.log(errs), 1)[0]


FAST_CASES = [
    ("strong", "SAM", (0.04, 0.02, 0.01, 0.005)),
    ("eros", "SAM", (0.04, 0.02, 0.01, 0.005)),
    ("strong", "LAM", (0.04, 0.02, 0.01, 0.005)),
    ("eros", "LAM", (0.16, 0.08, 0.04, 0.02)),
]


@pytest.mark.parametrize("order", [1, 2, 4])
@pytest.mark.parametrize(("name", "mode", "deltas"), FAST_CASES)
def test_sam_rotation_error_is_delta_to_the_n_plus_1(name, mode, deltas, order):
    # Over one ℓ-period: O(δ^(N+1)) in (ℓ, g, L/L); in the body momentum and the attitude the
    # ℓ error is multiplied by the transverse momentum ~ √δ, hence δ^(N+3/2).
    sam_err, hub_err = errors(name, mode, order, deltas, l_period(name, mode))
    assert slope(deltas, sam_err) == pytest.approx(order + 1, abs=0.3), sam_err
    assert slope(deltas, hub_err) == pytest.approx(order + 1.5, abs=0.3), hub_err


@pytest.mark.parametrize(
    ("name", "mode"), [("max-on-b1", "SAM"), ("beta-negative", "SAM"), ("strong", "LAM")]
)
def test_sam_rotation_relabelled_axes_and_negative_hemisphere(name, mode):
    deltas = (0.04, 0.02, 0.01)
    for sign in (1.0, -1.0):
        sam_err, _ = errors(name, mode, 3, deltas, l_period(name, mode), sign)
        assert slope(deltas, sam_err) == pytest.approx(4, abs=0.3), sam_err


@pytest.mark.parametrize("name", ["earth", "moon"])
def test_sam_rotation_earth_moon_short_span(name):
    # Three spin periods (a full ℓ-period is in the slow test): the inverse and direct maps and
    # the frequencies, O(δ^(N+1)).
    deltas = (0.16, 0.08, 0.04, 0.02)
    for order in (2, 3):
        sam_err, _ = errors(name, "SAM", order, deltas, 6 * np.pi)
        assert slope(deltas, sam_err) == pytest.approx(order + 1, abs=0.35), sam_err


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "deltas"), [("earth", (0.16, 0.08, 0.04)), ("moon", (0.16, 0.08, 0.04, 0.02))]
)
def test_sam_rotation_earth_moon_full_period(name, deltas):
    for order in (1, 2, 3, 4):
        sam_err, _ = errors(name, "SAM", order, deltas, l_period(name, "SAM"))
        assert slope(deltas, sam_err) == pytest.approx(order + 1, abs=0.45), (order, sam_err)


@pytest.mark.parametrize("order", [6, 8, 10])
def test_sam_rotation_high_order_strong_body(order):
    deltas = (0.16, 0.12, 0.08)
    sam_err, _ = errors("strong", "SAM", order, deltas, l_period("strong", "SAM"))
    assert slope(deltas, sam_err) == pytest.approx(order + 1, abs=0.5), sam_err


@pytest.mark.parametrize(
    ("body", "mode"), [(RigidBody(1.0, 1.0, 1.5), "SAM"), (RigidBody(0.5, 1.0, 1.0), "LAM")]
)
def test_sam_rotation_is_exact_for_axisymmetric_bodies(body, mode):
    # β' = 0: the averaged Hamiltonian is the Hamiltonian, whatever δ (J up to 60°).
    axes = sam_axes(body, mode)
    assert axes.beta == 0
    q, m = sam_to_hub(0.3, 0.1, 0.4, np.array([0.5, 0.2, 0.01]), 1.0, 0.6, body=body, mode=mode)
    state = State(q, m)
    t = np.linspace(0, 30.0, 5)
    ref = integrate_reference(Model(body), state[:, None], t, rtol=1e-13, atol=1e-13)
    out = SAMRotation(body, order=2, mode=mode).propagate(state[:, None], t)
    assert np.abs(out.m_body - ref.m_body).max() < 1e-11
    dq = np.minimum(
        np.linalg.norm(out.quaternion - ref.quaternion, axis=-1),
        np.linalg.norm(out.quaternion + ref.quaternion, axis=-1),
    )
    assert dq.max() < 1e-10


@pytest.mark.parametrize(
    ("order", "deltas"), [(2, (0.08, 0.04, 0.02, 0.01)), (5, (0.08, 0.04, 0.02)), (8, (0.16, 0.12, 0.08))]
)
def test_sam_direct_inverse_is_identity_to_order(order, deltas):
    # direct(inverse(x)) − x = O(δ^(N+1)), numerically (the exact series identity is in
    # tests/series): the chain state → mean → state at t = 0.
    deltas = np.array(deltas)
    rotation = SAMRotation(STRONG, order=order)
    state = initial_states("strong", "SAM", deltas)
    back = rotation.propagate(state, 0.0)
    a, b = (
        hub_to_sam(state.quaternion, state.m_body, STRONG),
        hub_to_sam(back.quaternion, back.m_body, STRONG),
    )
    err = np.max(
        [
            np.abs(wrap(a.sam_l - b.sam_l)),
            np.abs(wrap(a.sam_g - b.sam_g)),
            np.abs(a.sam_L - b.sam_L) / a.sam_L,
        ],
        axis=0,
    )
    assert slope(deltas, err) == pytest.approx(order + 1, abs=0.3), err


@pytest.mark.parametrize("order", [2, 3, 5])
def test_sam_truncated_transformation_is_canonical_to_order(order):
    # Jacobian of (ℓ', g', L', G') ↦ (ℓ, g, L, G) from exact derivatives of the series; the
    # brackets of the old variables, Mᵀ J M − J, are O(δ^(N+1)).
    rotation = SAMRotation(STRONG, order=order)
    T = rotation.theory.transform
    parts = {
        "l": lie_sum(T.direct_angle("l")),
        "g": lie_sum(T.direct_angle("g")),
        "L": lie_sum(T.direct("L")),
    }
    derivatives = {(f, v): parts[f].diff(v).compile() for f in parts for v in ("l", "L", "G")}
    p = rotation._params
    beta = p["beta"]
    args = {"alpha": p["alpha"], "beta": beta, "s": np.sqrt(1 - beta**2), "C": p["C"], "g": 0.0}
    J4 = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.eye(2), np.zeros((2, 2))]])
    deltas = np.array([0.08, 0.04, 0.02, 0.01])
    worst = []
    for delta in deltas:
        bad = 0.0
        for ell in (0.3, 1.1, 2.5):
            v = {"l": ell, "L": delta * np.sqrt(1 - beta**2), "G": 1.0, **args}
            d = {k: float(f(**v)) for k, f in derivatives.items()}
            M = np.array(
                [
                    [1 + d["l", "l"], 0, d["l", "L"], d["l", "G"]],
                    [d["g", "l"], 1, d["g", "L"], d["g", "G"]],
                    [d["L", "l"], 0, d["L", "L"], d["L", "G"]],
                    [0, 0, 0, 1],
                ]
            )
            bad = max(bad, np.abs(M.T @ J4 @ M - J4).max())
        worst.append(bad)
    assert slope(deltas, worst) == pytest.approx(order + 1, abs=0.3), worst


@pytest.mark.parametrize("order", [2, 3, 5])
def test_sam_secular_hamiltonian_is_the_energy(order):
    deltas = np.array([0.08, 0.04, 0.02, 0.01])
    state = initial_states("strong", "SAM", deltas)
    rotation = SAMRotation(STRONG, order=order)
    err = np.abs(rotation.secular_hamiltonian(state) - state.energy(STRONG))
    assert slope(deltas, err) == pytest.approx(order + 2, abs=0.3), err


def test_sam_rotation_keeps_the_reference_momentum_exactly():
    # h, H and G are constant: M = 𝓡 m is reproduced to round-off at every time.
    state = initial_states("eros", "SAM", (0.02, 0.002))
    out = SAMRotation(BODIES["eros"], order=6).propagate(state[:, None], np.linspace(0, 100, 11))
    np.testing.assert_allclose(
        out.m_reference, np.broadcast_to(state.m_reference[:, None], (2, 11, 3)), atol=2e-15
    )


def test_sam_rotation_shapes_times_and_frequencies():
    rotation = SAMRotation(STRONG, order=3)
    states = initial_states("strong", "SAM", [0.01, 0.02])
    assert rotation.propagate(states, np.zeros((3, 1))).shape == (3, 2)
    assert rotation.propagate(states[0], 1.0).shape == ()
    a = rotation.propagate(states, np.array([2.0, 7.0]), t0=1.0)
    b = rotation.propagate(states, np.array([1.0, 6.0]))
    np.testing.assert_allclose(a.m_body, b.m_body, atol=1e-15)
    n = rotation.frequencies(states)
    assert isinstance(n, SAMFrequencies)
    assert n.n_l.shape == (2,)
    mean = rotation.mean_elements(states)
    expected = rotation.theory.frequencies(mean.sam_L, mean.sam_G, **rotation._params)
    np.testing.assert_array_equal(n.n_g, expected[1])
    np.testing.assert_allclose(rotation.delta(states), [0.01, 0.02], rtol=0.02)
    assert repr(rotation) == f"SAMRotation({STRONG!r}, order=3, mode='SAM')"


def test_sam_rotation_steady_spin_has_no_warning():
    state = State.from_quaternion([0, 0, 0, 1.0], [0.0, 0.0, 2.0])
    out = SAMRotation(STRONG, order=4).propagate(state, np.pi / 2)  # ω = G/C = 2
    np.testing.assert_allclose(out.m_body, [0.0, 0.0, 2.0], atol=1e-15)
    np.testing.assert_allclose(np.abs(out.quaternion), [0, 0, 1.0, 0], atol=1e-15)  # a half turn about b3


def test_sam_rotation_errors():
    lam_state = State.from_quaternion([0, 0, 0, 1.0], [1.0, 0.1, 0.0])
    with pytest.raises(ValueError, match="expected states in SAM rotation"):
        SAMRotation(STRONG).propagate(lam_state, 1.0)
    with pytest.raises(ValueError, match="expected states in LAM rotation"):
        SAMRotation(STRONG, mode="LAM").propagate(initial_states("strong", "SAM", [0.01]), 1.0)
    with pytest.raises(ValueError, match="unique axis"):
        SAMRotation(RigidBody(0.5, 1.0, 1.0))
    with pytest.raises(ValueError, match="andoyer State"):
        SAMRotation(STRONG).propagate("state", 1.0)
    with pytest.raises(ValueError, match="order >= 1"):
        SAMRotation(STRONG, order=0)
    with pytest.raises(ValueError, match="broadcastable"):
        SAMRotation(STRONG).propagate(initial_states("strong", "SAM", [0.01, 0.02]), [1.0, 2.0, 3.0])
