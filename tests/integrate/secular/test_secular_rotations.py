"""The exact-rotation composition of the secular model: accuracy, order, conservation, control."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import RigidBody, bodies
from andoyer.integrate.secular import propagate_momentum
from andoyer.integrate.secular.rotations import propagate_controlled, propagate_rotations
from andoyer.perturbations import KeplerOrbit, PointMass
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers

ARCSEC = np.pi / 648000
YEARS_1000 = 1000 * JULIAN_YEAR


def planet_start(planet):
    body = bodies.get(planet)
    G = body.C * 2 * np.pi / bodies.info(planet).rotation_period
    eps = OBLIQUITY[planet]
    return body, G, G * np.array([0.0, -np.sin(eps), np.cos(eps)])


def node(M):
    return np.arctan2(M[..., 0], -M[..., 1])


def strong_model():
    """Rates comparable to the node drifts: one fixed and two drifting normals."""

    def orbit(a, i, node, rate):
        return KeplerOrbit(a, 0.1, i, node, 0.3, 0.0, 1.0, node_rate=rate)

    perturbers = [
        PointMass(1.0, orbit(1.0, 0.0, 0.0, 0.0)),
        PointMass(1.0, orbit(1.2, 0.4, 0.3, -0.7)),
        PointMass(0.5, orbit(0.9, 0.9, 1.0, 0.5)),
    ]
    return SecularGravityGradient(RigidBody(1.0, 1.1, 1.5), perturbers)


def strong_arguments(model, G=1.0, L=0.9):
    """The arguments of :func:`propagate_rotations` for ``strong_model`` (outer: the first)."""
    coef = np.array([2 * model.strength(p, L, G) / G**2 for p in model.perturbers])
    orbits = [p.orbit for p in model.perturbers[1:]]
    normals = tuple(
        np.array(v)
        for v in (
            [np.sin(o.inclination) for o in orbits],
            [np.cos(o.inclination) for o in orbits],
            [o.node for o in orbits],
            [o.node_rate for o in orbits],
        )
    )
    M0 = np.array([[0.3, -0.5, 0.8]]) / np.linalg.norm([0.3, -0.5, 0.8]) * G
    return M0, coef[:1], np.array([0.0, 0.0, 1.0]), coef[1:, None], normals


@pytest.mark.parametrize("planet", ["earth", "mars"])
def test_secular_fast_rotations_agree_with_dop853_over_1000_years(planet):
    body, G, M0 = planet_start(planet)
    model = SecularGravityGradient(body, mean_perturbers(planet))
    t = np.linspace(0.0, YEARS_1000, 41)
    fast = propagate_momentum(model, M0, G, t, rtol=1e-12)
    slow = propagate_momentum(model, M0, G, t, rtol=1e-12, method="dop853")
    # DOP853 at rtol 1e-12 is itself good to ~1e-12 over 1000 years (it agrees with rtol 1e-13 so).
    assert np.max(np.linalg.norm(fast - slow, axis=-1)) / G < 5e-12
    assert np.max(np.abs(node(fast) - node(slow))) < 1e-6 * ARCSEC


def test_secular_fast_mars_equals_the_closed_form_rotation():
    """The Sun alone in the reference plane: M turns about s3 at 2κ M₃/G², κ from its formula."""
    body, G, M0 = planet_start("mars")
    sun = mean_perturbers("mars")[0]
    a, e = sun.orbit.semi_major_axis, sun.orbit.eccentricity
    kappa = -3 * sun.gm / (4 * a**3 * (1 - e * e) ** 1.5) * (body.C - 0.5 * (body.A + body.B))
    t = np.linspace(0.0, YEARS_1000, 7)
    angle = 2 * kappa * M0[2] / G**2 * t
    c, s = np.cos(angle), np.sin(angle)
    exact = np.stack([c * M0[0] - s * M0[1], s * M0[0] + c * M0[1], M0[2] + 0 * t], -1)
    M = propagate_momentum(SecularGravityGradient(body, sun), M0, G, t)
    assert np.max(np.linalg.norm(M - exact, axis=-1)) / G < 1e-14


def test_secular_fast_conserves_the_momentum_norm():
    body, G, M0 = planet_start("earth")
    model = SecularGravityGradient(body, mean_perturbers("earth"))
    M = propagate_momentum(model, M0, G, np.linspace(0.0, YEARS_1000, 2001))
    assert np.max(np.abs(np.linalg.norm(M, axis=-1) / G - 1)) <= 1e-15


@pytest.mark.parametrize("order", [2, 4, 6, 8])
def test_secular_fast_convergence_order(order):
    model = strong_model()
    M0, c0, k0, coef, normals = strong_arguments(model)
    times = np.array([20.0])
    # order 8 at a 0.05 step is good to ~1e-15 here (its error falls as h^8 from 1e-10 at 0.27)
    reference = propagate_rotations(M0, c0, k0, coef, normals, times, 0.05, order=8)
    steps = {2: (0.4, 0.2), 4: (0.4, 0.2), 6: (0.4, 0.2), 8: (0.5, 0.25)}[order]
    errors = [
        np.linalg.norm(propagate_rotations(M0, c0, k0, coef, normals, times, h, order=order) - reference)
        for h in steps
    ]
    slope = np.log2(errors[0] / errors[1])
    assert order - 0.3 < slope < order + 0.6


def test_secular_fast_interpreted_loop_agrees_with_compiled():
    model = strong_model()
    M0, c0, k0, coef, normals = strong_arguments(model)
    rng = np.random.default_rng(3)
    M0 = rng.standard_normal((4, 3))
    c0, coef = np.repeat(c0, 4), np.repeat(coef, 4, axis=1) * rng.uniform(0.5, 1.5, 4)
    times = np.array([0.0, 1.5, 1.5, 7.0])
    compiled = propagate_rotations(M0, c0, k0, coef, normals, times, 0.3, compiled=True)
    interpreted = propagate_rotations(M0, c0, k0, coef, normals, times, 0.3, compiled=False)
    # the compiled loop takes small-angle sines from series and the drifting nodes by the addition
    # theorem: round-off differences, amplified by the M-dependent rates of this strong model (6e-14)
    assert np.max(np.abs(compiled - interpreted)) < 2e-13
    assert np.array_equal(compiled[0], M0)
    assert np.array_equal(compiled[1], compiled[2])


@pytest.mark.parametrize("order", [2, 8])
@pytest.mark.parametrize(
    "times",
    [np.array([7.0]), np.array([0.0, 1.5, 1.5, 7.0]), np.array([0.1, 0.35, 3.3, 3.35, 6.99, 7.0])],
    ids=["one", "repeated", "off-grid"],
)
def test_secular_fast_richardson_pair_equals_two_runs(order, times):
    """The coarse and fine runs overlapped in one compiled loop: bit for bit the two separate runs."""
    from andoyer.integrate.secular.rotations import _run_pair

    model = strong_model()
    M0, c0, k0, coef, normals = strong_arguments(model)
    rng = np.random.default_rng(5)
    M0 = rng.standard_normal((3, 3))
    c0, coef = np.repeat(c0, 3), np.repeat(coef, 3, axis=1) * rng.uniform(0.5, 1.5, 3)
    steps = 9  # a coarse step of 7/9: the outputs fall between the steps of both runs
    fine, coarse = _run_pair(M0, c0, k0, coef, normals, times, steps, order, True)
    h = times[-1] / steps
    assert np.array_equal(fine, propagate_rotations(M0, c0, k0, coef, normals, times, h / 2 * 1.0000001,
                                                    order, compiled=True))  # fmt: skip
    assert np.array_equal(coarse, propagate_rotations(M0, c0, k0, coef, normals, times, h * 1.0000001,
                                                      order, compiled=True))  # fmt: skip


@pytest.mark.parametrize("rtol", [1e-5, 1e-8, 1e-11])
def test_secular_fast_controller_meets_rtol(rtol):
    model = strong_model()
    M0, c0, k0, coef, normals = strong_arguments(model)
    times = np.linspace(0.0, 50.0, 6)[1:]
    reference = propagate_rotations(M0, c0, k0, coef, normals, times, 0.05)
    fastest = float(np.max(np.abs(np.concatenate([c0, coef.ravel(), normals[3]]))))
    M, estimate = propagate_controlled(M0, c0, k0, coef, normals, times, fastest, rtol)
    error = np.max(np.linalg.norm(M - reference, axis=-1))
    assert estimate <= rtol
    assert error <= 3 * rtol
    assert error >= 1e-3 * rtol or rtol < 1e-10  # not wastefully small steps


def test_secular_fast_vectorised_states_and_start_time():
    body, G, M0 = planet_start("earth")
    model = SecularGravityGradient(body, mean_perturbers("earth"))
    rng = np.random.default_rng(11)
    states = rng.standard_normal((2, 3, 3)) * G
    L = G * rng.uniform(0.9, 1.0, (2, 3))
    t = np.array([50.0, 300.0]) * JULIAN_YEAR
    together = propagate_momentum(model, states, L, t)
    assert together.shape == (2, 2, 3, 3)
    one = propagate_momentum(model, states[1, 2], L[1, 2], t)
    dop = propagate_momentum(model, states[1, 2], L[1, 2], t, method="dop853")
    scale = np.linalg.norm(states[1, 2])
    # the step follows the fastest of the states: not the same for one state alone
    assert np.max(np.abs(together[:, 1, 2] - one)) / scale < 2e-12
    assert np.max(np.abs(one - dop)) / scale < 5e-12
    assert np.array_equal(propagate_momentum(model, M0, G, [0.0])[0], M0)


def test_secular_fast_bad_input():
    body, G, M0 = planet_start("earth")
    model = SecularGravityGradient(body, mean_perturbers("earth"))
    with pytest.raises(ValueError, match="expected method 'rotations' or 'dop853'"):
        propagate_momentum(model, M0, G, [1.0], method="rk4")
    with pytest.raises(ValueError, match=r"expected order in \[2, 4, 6, 8\]"):
        propagate_momentum(model, M0, G, [1.0], order=5)
    with pytest.raises(ValueError, match="expected positive rtol and max_step"):
        propagate_momentum(model, M0, G, [1.0], rtol=0.0)
    with pytest.raises(ValueError, match="expected positive rtol and max_step"):
        propagate_momentum(model, M0, G, [1.0], max_step=-1.0)
