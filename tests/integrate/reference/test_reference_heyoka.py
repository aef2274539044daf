"""The reference integrator's backends: heyoka's Taylor integrator against DOP853; the lean DOP853 equations.

With heyoka installed, the two backends (independently written equations: heyoka
expressions and the component-wise DOP853 right-hand side) must agree to the
tolerance both claim; without it, asking for heyoka must raise the ValueError naming
the extra. The lean DOP853 right-hand side is checked against the generic hub
equations :func:`andoyer.perturbations.perturbed_rates`.
"""

from __future__ import annotations

import importlib.util
import sys

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State, bodies, propagate
from andoyer.integrate import integrate_reference
from andoyer.integrate.reference.dop853 import _rhs
from andoyer.perturbations import (
    CircularOrbit,
    GravityGradient,
    HeavyTop,
    KeplerOrbit,
    LinearDamping,
    Model,
    PointMass,
    PrecessingFrame,
    TabulatedOrbit,
    UserPotential,
    UserTorque,
    perturbed_rates,
)
from andoyer.perturbations.solar_system import DAY, OBLIQUITY, mean_perturbers

HAVE_HEYOKA = importlib.util.find_spec("heyoka") is not None
MISSING = r"^expected heyoka installed \(pip install andoyer\[heyoka\]\), got"

EARTH = bodies.get("earth")
BODY = RigidBody(1.0, 1.3, 1.7)
STRONG = [
    PointMass(30.0, KeplerOrbit(2.0, 0.3, 0.4, 0.5, 0.6, 0.1, 1.9, node_rate=0.05, periapsis_rate=-0.03)),
    PointMass(5.0, CircularOrbit(1.5, 1.2, 0.3, phase=0.7)),
]


def states(n, seed):
    rng = np.random.default_rng(seed)
    return State.from_attitude(Rotation.random(n, rng=rng), rng.normal(size=(n, 3)))


def earth_start():
    spin = EARTH.C * 2 * np.pi / 86164.0905
    return State.from_attitude(Rotation.from_euler("X", OBLIQUITY["earth"]), [0.0, 0.0, spin])


CASES = {
    # Earth + Sun + Moon (eccentric orbits, regressing lunar node), one body: scalar heyoka path.
    "earth-sun-moon": (
        Model(EARTH, GravityGradient(mean_perturbers("earth"))),
        earth_start(),
        np.array([-3.0, 5.0, 20.0]) * DAY,
        1e-11,
    ),
    # Torque comparable to the free motion, drifting node and periapsis: batch path with padding.
    "strong-triaxial": (
        Model(BODY, GravityGradient(STRONG)),
        states(3, 1),
        np.array([-2.0, 1, 10]),
        1e-10,
    ),
    "heavy-top": (Model(BODY, HeavyTop(0.5, [0.1, 0.2, 0.3])), states(5, 2), np.array([-4.0, 3, 10]), 1e-11),
    "frame+top": (
        Model(BODY, [PrecessingFrame([0.1, -0.2, 0.3]), HeavyTop(0.5, [0.1, 0.2, 0.3])]),
        states(1, 3)[0],
        np.array([-4.0, 3, 10]),
        1e-11,
    ),
    "damping": (
        Model(BODY, LinearDamping([0.1, 0.2, 0.05])),
        states(2, 4),
        np.array([-1.0, 10]),
        1e-11,
    ),
    "free": (Model(BODY), states(2, 5), np.array([-3.0, 7]), 1e-11),
}


def distance(a, b):
    """Largest relative difference of momenta, and of attitudes (≈ half the rotation angle between them)."""
    dm = np.abs(a.m_body - b.m_body).max() / np.abs(b.m_body).max()
    sign = np.sign(np.sum(a.quaternion * b.quaternion, axis=-1, keepdims=True))
    return max(dm, float(np.linalg.norm(a.quaternion - sign * b.quaternion, axis=-1).max()))


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_heyoka_agrees_with_dop853(name):
    model, start, t, tol = CASES[name]
    grid = t.reshape(-1, *([1] * len(start.shape)))
    dop = integrate_reference(model, start, grid, rtol=1e-13, atol=1e-15)
    if not HAVE_HEYOKA:
        with pytest.raises(ValueError, match=MISSING):
            integrate_reference(model, start, grid, method="heyoka")
        return
    taylor = integrate_reference(model, start, grid, method="heyoka")
    assert taylor.shape == dop.shape == grid.shape[:1] + start.shape
    assert distance(taylor, dop) <= tol
    # The perturbation is felt: the agreement is not that of two free motions.
    free = integrate_reference(Model(model.body), start, grid, rtol=1e-13, atol=1e-15)
    if model.perturbations:
        assert distance(free, dop) > 1e3 * tol


def test_heyoka_start_time_and_t0_outputs():
    model, start, _, _ = CASES["heavy-top"]
    t = np.array([[2.0], [-1.0], [0.5]])
    if not HAVE_HEYOKA:
        with pytest.raises(ValueError, match=MISSING):
            integrate_reference(model, start, t, t0=0.5, method="heyoka")
        return
    out = integrate_reference(model, start, t, t0=0.5, method="heyoka")
    np.testing.assert_array_equal(out.m_body[2], start.m_body)
    back = integrate_reference(model, out[0], 0.5, t0=2.0, method="heyoka")
    assert distance(back, start) <= 1e-12


def test_heyoka_absent_raises_and_dop853_still_runs(monkeypatch):
    monkeypatch.setitem(sys.modules, "heyoka", None)  # import heyoka now raises ImportError
    model, start, t, _ = CASES["heavy-top"]
    with pytest.raises(ValueError, match=MISSING):
        integrate_reference(model, start, t[:, None], method="heyoka")
    with pytest.raises(ValueError, match=MISSING):
        propagate(model, start, t[:, None], integrator="heyoka")
    assert integrate_reference(model, start, t[:, None]).shape == (3, 5)


@pytest.mark.parametrize(
    "part",
    [
        UserTorque(lambda t, rot, w: -0.1 * w),
        UserPotential(lambda rot, t: rot.apply([0.0, 0.0, 1.0])[..., 2]),
        PrecessingFrame(lambda t: np.stack([0 * t, 0 * t, 0.1 + 0 * t], -1)),
        GravityGradient(PointMass(1.0, TabulatedOrbit(lambda t: np.stack([t, 1 + 0 * t, 0 * t], -1)))),
    ],
    ids=["user-torque", "user-potential", "time-dependent-frame", "tabulated-orbit"],
)
def test_heyoka_rejects_models_it_cannot_express(part):
    model = Model(BODY, [HeavyTop(0.5, [0, 0, 0.3]), part])
    with pytest.raises(
        ValueError, match=r"^expected gravity gradients of Kepler/circular orbits.*got .*dop853"
    ):
        integrate_reference(model, states(1, 0)[0], 1.0, method="heyoka")


@pytest.mark.parametrize(
    ("options", "match"),
    [
        ({"method": "rk45"}, r"^expected method in \('dop853', 'heyoka'\), got 'rk45'"),
        ({"method": "heyoka", "atol": 1e-12}, r"^expected (atol=None with method='heyoka'|heyoka installed)"),
        ({"t0": np.nan}, r"^expected finite t0"),
    ],
)
def test_reference_rejects_bad_options(options, match):
    with pytest.raises(ValueError, match=match):
        integrate_reference(Model(BODY), states(1, 0)[0], 1.0, **options)


def test_propagate_takes_the_integrator_option():
    model, start, t, _ = CASES["damping"]
    grid = t[:, None]
    default = propagate(model, start, grid, rtol=1e-13, atol=1e-15)
    np.testing.assert_array_equal(
        default.m_body, integrate_reference(model, start, grid, rtol=1e-13, atol=1e-15).m_body
    )
    with pytest.raises(ValueError, match=r"^expected method in"):
        propagate(model, start, grid, integrator="rk4")
    with pytest.raises(ValueError, match=r"^expected options of method='splitting'.*integrator"):
        propagate(model, start, grid, method="splitting", step=0.1, integrator="heyoka")
    if not HAVE_HEYOKA:
        with pytest.raises(ValueError, match=MISSING):
            propagate(model, start, grid, integrator="heyoka")
        return
    taylor = propagate(model, start, grid, integrator="heyoka")
    assert distance(taylor, default) <= 1e-11


RHS_MODELS = {
    "earth-sun-moon": CASES["earth-sun-moon"][0],
    "strong-triaxial": CASES["strong-triaxial"][0],
    "frame+top+damping": Model(
        BODY, [PrecessingFrame([0.1, -0.2, 0.3]), HeavyTop(0.5, [0.1, 0.2, 0.3]), LinearDamping(0.2)]
    ),
    "time-dependent-frame": Model(
        BODY, PrecessingFrame(lambda t: np.stack([0.1 * np.sin(t), 0 * t, 0.2 + 0 * t], -1))
    ),
    "user-torque": Model(BODY, UserTorque(lambda t, rot, w: -0.1 * w + rot.apply([0.0, 0.0, 1.0]))),
    "user-potential": Model(BODY, UserPotential(lambda rot, t: 0.3 * rot.apply([0.0, 0.0, 1.0])[..., 2])),
    "tabulated-orbit": Model(
        BODY,
        GravityGradient(
            PointMass(2.0, TabulatedOrbit(lambda t: np.stack([np.cos(t), np.sin(t), 0.3 + 0 * t], -1)))
        ),
    ),
}


@pytest.mark.parametrize("n", [1, 4])
@pytest.mark.parametrize("name", list(RHS_MODELS))
def test_lean_rhs_matches_generic_hub_equations(name, n):
    model = RHS_MODELS[name]
    rng = np.random.default_rng(7)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    m = rng.normal(size=(n, 3))
    for t in (0.3, -41.0, 1.7e6):
        dq, dm = perturbed_rates(model.body, model.perturbation, t, q, m)
        lean = _rhs(model, n)(t, np.concatenate([q.ravel(), m.ravel()]))
        expected = np.concatenate([dq.ravel(), dm.ravel()])
        np.testing.assert_allclose(lean, expected, rtol=0, atol=1e-14 * np.abs(expected).max())


@pytest.mark.slow
def test_heyoka_agrees_with_dop853_over_a_year_of_earth_precession():
    model, start, _, _ = CASES["earth-sun-moon"]
    t = np.array([-90.0, 365.25]) * DAY
    dop = integrate_reference(model, start, t, rtol=1e-13, atol=1e-15)
    if not HAVE_HEYOKA:
        with pytest.raises(ValueError, match=MISSING):
            integrate_reference(model, start, t, method="heyoka")
        return
    assert distance(integrate_reference(model, start, t, method="heyoka"), dop) <= 1e-9
