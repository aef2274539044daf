"""Spin axes on perturbed secular orbits against the library's own path on the same orbit."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.orbits import SecularOrbit
from andoyer.planetary.spin_axis import (
    default_axis,
    member_obliquities,
    member_times,
    perturbed_states,
    spin_axis_history,
)
from andoyer.planetary.spin_axis.members import member_models


def test_member_unperturbed_matches_spin_axis_history_on_secular_orbit():
    """The compiled pass against SecularOrbit + spin_axis_history (numpy interpolation, rotate_stages)."""
    end, dt = -2e6, 2e4
    run = member_obliquities("mars", end, dt, np.zeros((1, 16), complex), default_axis("mars"))
    assert run.orbit_step == pytest.approx(10000.0)  # SecularOrbit's step: a fifth of the shortest period
    assert run.spin_step == pytest.approx(1000.0)
    orbit = SecularOrbit("mars", step=run.orbit_step)
    assert orbit.spacing == pytest.approx(5000.0)  # the samples: every half step, as the members'
    history = spin_axis_history(orbit, "mars", run.t[::-1], step=run.spin_step)
    assert np.abs(history.obliquity[::-1] - run.obliquity[0]).max() < 1e-11


def test_member_seeds_reproduce_and_differ():
    a = perturbed_states(2, 1e-6, np.random.default_rng(5))
    b = perturbed_states(2, 1e-6, np.random.default_rng(5))
    c = perturbed_states(2, 1e-6, np.random.default_rng(6))
    assert np.array_equal(a, b)
    assert not np.array_equal(a, c)
    ra = member_obliquities("mars", -2e5, 5e4, a, default_axis("mars"))
    rb = member_obliquities("mars", -2e5, 5e4, b, default_axis("mars"))
    assert np.array_equal(ra.obliquity, rb.obliquity)
    assert ra.obliquity.shape == (2, 5)
    assert np.all(np.isfinite(ra.obliquity))


def test_member_perturbation_size_in_dimensionless_variables():
    """Δw/√Λ has the requested RMS size (each complex component: E|z|² = size²)."""
    from andoyer.planetary.orbits.secular import secular_model

    size = 1e-6
    d = perturbed_states(4000, size, np.random.default_rng(0))
    lam = secular_model().Lambda
    u = d / np.sqrt(np.concatenate([lam, lam]))
    assert np.sqrt(np.mean(np.abs(u) ** 2)) == pytest.approx(size, rel=0.02)


def test_member_moonless_earth_precession_rate_from_first_principles():
    """ψ̇ = (3/2) (n²/ω) H cos ε (1−e²)^{-3/2}: the Sun alone, today's spin and H (IERS 2010)."""
    H = 0.0032737949
    year = 365.25636  # sidereal year, days
    day = 86164.0905 / 86400.0  # sidereal day, days
    n, omega = 2 * np.pi / year, 2 * np.pi / day  # rad/day
    eps, e = np.radians(23.4393), 0.0167
    normal = np.array([0.0, 0.0, 1.0])
    axis = np.array([0.0, np.sin(eps), np.cos(eps)])
    (model,) = member_models("moonless-earth", normal[None], np.array([e]), axis)
    expected = 1.5 * n**2 / omega * H * 365.25 * np.cos(eps) * (1 - e**2) ** -1.5 * 206264.806
    assert model.beta == 0.0
    assert model.precession_rate(eps, e) == pytest.approx(expected, rel=2e-3)
    (full,) = member_models("earth", normal[None], np.array([e]), axis)
    assert full.beta > 2.0  # the Moon's torque is the larger part with the Moon


def test_member_times_grid():
    assert member_times(3e5, 1e5).tolist() == [0.0, 1e5, 2e5, 3e5]


def test_member_shared_orbit_matches_members_of_their_own():
    """Members with equal perturbations share one integration: each is the member computed alone."""
    rng = np.random.default_rng(11)
    delta = np.repeat(perturbed_states(2, 1e-6, rng), 2, axis=0)  # orbits a, a, b, b
    rates = np.array([7.59, 7.61, 7.60, 7.595])
    axis = default_axis("mars")
    together = member_obliquities("mars", -4e5, 1e5, delta, axis, precession_rate=rates)
    for i in range(4):
        alone = member_obliquities("mars", -4e5, 1e5, delta[i : i + 1], axis, precession_rate=rates[i])
        assert np.array_equal(together.obliquity[i], alone.obliquity[0])
    assert not np.array_equal(together.obliquity[0], together.obliquity[1])


def test_member_axes_one_per_member():
    axis = default_axis("mars")
    tilted = np.array([axis, [0.0, np.sin(0.5), np.cos(0.5)]])
    run = member_obliquities("mars", -1e5, 1e5, np.zeros((2, 16), complex), tilted)
    alone = member_obliquities("mars", -1e5, 1e5, np.zeros((1, 16), complex), tilted[1])
    assert np.array_equal(run.obliquity[1], alone.obliquity[0])
    with pytest.raises(
        ValueError, match=r"expected a finite axis of shape \(3,\) or \(2, 3\), got shape \(3, 3\)"
    ):
        member_obliquities("mars", -1e5, 1e5, np.zeros((2, 16), complex), np.ones((3, 3)))


class _ProtocolOnly:
    """An orbit seen through the OrbitHistory protocol alone (no samples handed over)."""

    def __init__(self, orbit):
        self.orbit, self.name, self.span, self.has_eccentricity = orbit, orbit.name, orbit.span, True

    def normal(self, t):
        return self.orbit.normal(t)

    def eccentricity_vector(self, t):
        return self.orbit.eccentricity_vector(t)


@pytest.mark.parametrize("end", [-1e6, 1e6])
def test_rotate_on_samples_matches_the_stage_arrays(end):
    """The compiled interpolation inside the rotations against the stage arrays of the numpy path."""
    orbit = SecularOrbit("mars")
    times = np.linspace(min(end, 0.0), max(end, 0.0), 11)
    fused = spin_axis_history(orbit, "mars", times, step=500.0)
    arrays = spin_axis_history(_ProtocolOnly(orbit), "mars", times, step=500.0)
    assert np.abs(fused.axis - arrays.axis).max() < 1e-13
    assert np.abs(fused.precession - arrays.precession).max() < 1e-12
