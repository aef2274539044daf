"""Each chart's dynamics, read through the registry, against the exact free motion.

Every registered chart gives its free-body Hamiltonian and Hamilton's equations
(``chart.hamiltonian``, ``chart.equations``). Independent checks: the Hamiltonian equals the
kinetic energy ``½ Σ m_i²/I_i`` computed here from the hub's momenta (nil for Serret's elements
and the modified Andoyer set, Gurfil §4.1), and the equations equal the central difference of
the chart's coordinates along the exact torque-free solution (``FreeRotation``: Jacobi elliptic
functions, a different algorithm from every chart's formulas).
"""

from __future__ import annotations

import inspect

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, RigidBody, State
from andoyer.state.registry import charts

BODIES = (RigidBody(1.0, 2.0, 3.0), RigidBody(0.5, 0.8, 1.0))
STEP = 1e-4
#: (chart, options of its coordinates): the time-dependent charts at a fixed epoch.
CASES = (
    ("state", {}),
    ("euler", {}),
    ("andoyer", {}),
    ("initial_andoyer", {"epoch": 0.7}),
    ("sadov", {}),
    ("serret", {"epoch": -3.0}),
    ("sam", {"mode": "SAM"}),
    ("sam", {"mode": "LAM"}),
)
NIL = {"initial_andoyer", "serret"}  # constants of the free motion: K = 0 (Gurfil §4.1)


def _states(body: RigidBody, seed: int) -> State:
    """Seeded states of |m| = 1 in both hemispheres, away from the separatrix and the poles."""
    rng = np.random.default_rng(seed)
    kept_q, kept_m = [], []
    while len(kept_m) < 6:
        m = rng.normal(size=3)
        m /= np.linalg.norm(m)
        separatrix = abs(np.sum(m * m / body.moments) - 1 / body.moments[1])
        if separatrix < 0.05 or min(abs(m)) < 0.05:
            continue
        kept_q.append(Rotation.random(random_state=rng).as_quat())
        kept_m.append(m)
    return State.from_quaternion(np.array(kept_q), np.array(kept_m))


def _read(name: str, options: dict, state: State, body: RigidBody, t: float) -> np.ndarray:
    chart = charts()[name]
    if "t" in chart.options:
        options = {**options, "t": t}
    return np.array(chart.from_state(state, body, **options), dtype=float)


def _accepted(function, options: dict) -> dict:
    names = inspect.signature(function).parameters
    return {k: v for k, v in options.items() if k in names}


@pytest.mark.parametrize("body", BODIES, ids=("b123", "b058"))
@pytest.mark.parametrize(("name", "options"), CASES, ids=[f"{n}-{o.get('mode', '')}" for n, o in CASES])
def test_chart_equations_match_exact_flow(name, options, body):
    chart = charts()[name]
    state = _states(body, seed=24)
    flow = FreeRotation(body).propagate(state[:, None], np.array([-STEP, STEP]))
    before, after = flow[:, 0], flow[:, 1]
    now = _read(name, options, state, body, 0.0)
    minus = _read(name, options, before, body, -STEP)
    plus = _read(name, options, after, body, STEP)
    if name == "state":  # q and -q are one attitude: take the propagated quaternions on now's side
        for side in (minus, plus):
            side[:4] *= np.sign(np.sum(side[:4] * now[:4], axis=0))
    difference = plus - minus
    for i, column in enumerate(chart.columns):
        if column in chart.angles:
            difference[i] = np.remainder(difference[i] + np.pi, 2 * np.pi) - np.pi
    rates = np.array(chart.equations(body, *now, **_accepted(chart.equations, options)), dtype=float)
    assert rates.shape == now.shape
    np.testing.assert_allclose(rates, difference / (2 * STEP), rtol=0, atol=2e-7)


@pytest.mark.parametrize("body", BODIES, ids=("b123", "b058"))
@pytest.mark.parametrize(("name", "options"), CASES, ids=[f"{n}-{o.get('mode', '')}" for n, o in CASES])
def test_chart_hamiltonian_is_kinetic_energy(name, options, body):
    chart = charts()[name]
    state = _states(body, seed=26)
    coordinates = _read(name, options, state, body, 0.0)
    energy = chart.hamiltonian(body, *coordinates, **_accepted(chart.hamiltonian, options))
    m = state.m_body
    expected = 0.0 * m[:, 0] if name in NIL else 0.5 * np.sum(m * m / np.array(body.moments), axis=-1)
    np.testing.assert_allclose(energy, expected, rtol=2e-14, atol=0)


def test_chart_dynamics_given_by_every_chart():
    assert [n for n, c in charts().items() if c.hamiltonian is None or c.equations is None] == []


def test_chart_dynamics_signature_checked():
    from andoyer.state.registry import Chart

    chart = charts()["euler"]

    def wrong(body, theta, phi, psi, Phi, Theta, Psi):
        return 0.0

    with pytest.raises(ValueError, match="expected the equations of bad to take body, then the columns"):
        Chart("bad", chart.columns, chart.angles, "", chart.from_method, chart.as_method, equations=wrong)
    with pytest.raises(ValueError, match="expected the hamiltonian of bad to take 'body' first"):
        Chart("bad", chart.columns, chart.angles, "", chart.from_method, chart.as_method, hamiltonian=len)
