"""Polhode and herpolhode: on the energy ellipsoid and momentum sphere, in the invariable plane."""

import numpy as np
import pytest
from figure_checks import texts_outside, titles_and_labels
from matplotlib.lines import Line2D

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.cli.demo_report import demo_state
from andoyer.integrate import Model, integrate_reference
from andoyer.plot import herpolhode, herpolhode_data, poinsot, polhode, polhode_data

CASES = {
    "SAM": (RigidBody(1.0, 2.0, 3.0), State.from_andoyer(0.5, 0.1, 0.2, 0.9, 1.0, 0.8)),
    "LAM": (RigidBody(1.0, 2.0, 3.0), State.from_andoyer(1.4, 0.1, 0.2, 0.2, 2.0, -0.5)),
    "earth": (bodies.get("earth"), State.from_andoyer(0.3, 1.0, 0.5, 7.29e-5 * np.cos(1e-3), 7.29e-5, 7e-5)),
    "eros": (bodies.get("eros"), State.from_andoyer(2.0, 0.0, 0.0, 0.95, 1.0, 1.0)),
    "oblate": (RigidBody(1.0, 1.0, 1.5), State.from_andoyer(0.0, 0.0, 0.0, 0.9, 2.0, 1.5)),
}


@pytest.mark.parametrize("case", CASES)
def test_polhode_stays_on_energy_ellipsoid_and_momentum_sphere(case):
    body, state = CASES[case]
    data = polhode_data(body, state, n_points=301)
    G, T = np.linalg.norm(state.m_body), float(state.energy(body))
    m, w = data.m_body, data.omega_body
    assert abs(data.G - G) <= 1e-15 * G
    np.testing.assert_allclose(np.linalg.norm(m, axis=-1), G, rtol=1e-12)
    np.testing.assert_allclose(0.5 * np.sum(m * m / body.moments, axis=-1), T, rtol=1e-12)
    # ω on the inertia ellipsoid ω·Iω = 2T with |Iω| = G.
    np.testing.assert_allclose(np.sum(w * w * body.moments, axis=-1), 2 * T, rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(w * body.moments, axis=-1), G, rtol=1e-12)
    np.testing.assert_allclose(m[-1], m[0], atol=1e-12 * G)  # one period: closed curve


@pytest.mark.parametrize("case", CASES)
def test_herpolhode_lies_in_the_invariable_plane(case):
    body, state = CASES[case]
    data = herpolhode_data(body, state, n_points=401)
    G, T = np.linalg.norm(state.m_body), float(state.energy(body))
    assert data.distance == pytest.approx(2 * T / G, rel=1e-15)
    np.testing.assert_allclose(data.normal, state.m_reference / G, rtol=0, atol=1e-15)
    w = data.omega_reference
    scale = np.max(np.linalg.norm(w, axis=-1))
    np.testing.assert_allclose(w @ data.normal, data.distance, rtol=0, atol=1e-12 * scale)
    # In-plane radius: |ω|² − (2T/G)², with |ω| from the body frame (no attitude involved).
    radius2 = np.sum(data.omega_reference**2, axis=-1) - data.distance**2
    np.testing.assert_allclose(np.sum(data.xy**2, axis=-1), radius2, rtol=0, atol=1e-12 * scale**2)
    e1, e2 = data.basis
    np.testing.assert_allclose([e1 @ e1, e2 @ e2, e1 @ e2, e1 @ data.normal], [1, 1, 0, 0], atol=1e-15)
    assert np.cross(e1, e2) @ data.normal == pytest.approx(1.0, abs=1e-15)


def test_herpolhode_matches_a_numerical_integration():
    # Independent propagation: DOP853 on Euler's equations and the kinematics.
    body, state = CASES["SAM"]
    data = herpolhode_data(body, state, duration=12.0, n_points=25)
    ref = integrate_reference(Model(body), state, data.t)
    w_ref = ref.rotation.apply(ref.omega(body))
    np.testing.assert_allclose(data.omega_reference, w_ref, rtol=0, atol=1e-9)


def test_herpolhode_basis_is_the_node_of_the_invariable_plane():
    body, state = CASES["SAM"]
    data = herpolhode_data(body, state, n_points=3)
    n = data.normal
    node = np.cross([0.0, 0.0, 1.0], n)
    np.testing.assert_allclose(data.basis[0], node / np.linalg.norm(node), atol=1e-15)
    pole = State.from_andoyer(0.5, 0.1, 0.2, 0.9, 1.0, 1.0)  # m along s3: e1 = s1
    np.testing.assert_allclose(herpolhode_data(body, pole, n_points=3).basis[0], [1, 0, 0], atol=1e-12)


def test_polhode_and_herpolhode_figures():
    body, state = CASES["SAM"]
    fig = poinsot(body, state)
    left, right = fig.axes
    p, h = fig.andoyer_data
    heavy = [ln for ln in left.get_lines() if ln.get_linewidth() == 2.0]
    assert len(heavy) == 2  # visible and hidden parts of the polhode
    drawn = [ln for ln in right.get_lines() if ln.get_label() == "herpolhode"]
    np.testing.assert_array_equal(np.column_stack(drawn[0].get_data()), h.xy)
    assert len(p.t) == 721
    assert "rad per unit time" in right.get_xlabel()
    single = polhode(body, state, duration=1.0, n_points=50)
    assert single.andoyer_data.t[-1] == 1.0
    assert herpolhode(body, state, n_points=50).andoyer_data.xy.shape == (50, 2)


def test_separatrix_state_uses_turns_of_the_body():
    # 1/A − 1/B = 1/B − 1/C = 1/12: m = (1, 0, 1) is exactly on the separatrix (T = G²/2B).
    body = RigidBody(3.0, 4.0, 6.0)
    state = State.from_quaternion([0, 0, 0, 1.0], [1.0, 0.0, 1.0])
    assert float(state.energy(body)) == 2.0 / (2 * 4.0)
    assert str(FreeRotation(body).regime(state)) == "SEPARATRIX"
    data = polhode_data(body, state, n_points=11)
    speed = np.linalg.norm(state.omega(body))
    assert data.t[-1] == pytest.approx(10 * 2 * np.pi / speed, rel=1e-14)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        (
            {"state": State.from_quaternion([0, 0, 0, 1.0], [[0, 0, 1.0], [0, 1.0, 0]])},
            "single andoyer State",
        ),
        ({"duration": -1.0}, "duration > 0"),
        ({"n_points": 1}, "n_points"),
    ],
)
def test_polhode_rejects_bad_input(kwargs, match):
    body, state = CASES["SAM"]
    args = {"state": state, **kwargs}
    with pytest.raises(ValueError, match=match):
        polhode_data(body, **args)


def test_herpolhode_rejects_zero_momentum():
    with pytest.raises(ValueError, match="nonzero angular momentum"):
        herpolhode_data(RigidBody(1.0, 2.0, 3.0), State.from_quaternion([0, 0, 0, 1.0], [0.0, 0.0, 0.0]))


@pytest.mark.parametrize("case", [*CASES, "earth-demo"])
def test_herpolhode_is_drawn_as_a_resolved_line(case):
    # A line, not a filled polygon; and sampled finely enough to be a curve: the Earth's ω turns
    # once a day about n̂ while its polhode period is ~305 days, so three polhode periods in 2001
    # points jumped ~160° per sample and the zig-zag filled a disk. Chords under 0.1 × the radius
    # mean at least ~60 points per turn.
    body, state = (bodies.get("earth"), demo_state("earth", 0.2)) if case == "earth-demo" else CASES[case]
    fig = herpolhode(body, state)
    ax = fig.axes[0]
    (line,) = [ln for ln in ax.get_lines() if ln.get_label() == "herpolhode"]
    assert isinstance(line, Line2D)
    assert line.get_linestyle() == "-"
    assert not ax.patches
    assert not ax.collections
    xy = line.get_xydata()
    radius = np.max(np.hypot(xy[:, 0], xy[:, 1]))
    assert np.max(np.hypot(*np.diff(xy, axis=0).T)) < 0.1 * radius
    # The mean rate of the herpolhode about the foot is the precession rate of the exact solution.
    turns = np.unwrap(np.arctan2(xy[:, 1], xy[:, 0]))
    rate = float(FreeRotation(body).periods(state).precession_rate)
    assert abs(turns[-1] - turns[0]) / line.figure.andoyer_data.t[-1] == pytest.approx(abs(rate), rel=0.2)


@pytest.mark.parametrize("case", ["SAM", "earth", "earth-demo"])
def test_poinsot_titles_and_labels_inside_the_figure(case):
    body, state = (bodies.get("earth"), demo_state("earth", 0.2)) if case == "earth-demo" else CASES[case]
    fig = poinsot(body, state)
    assert texts_outside(fig, titles_and_labels(fig)) == []
