"""Sadov's angles advance uniformly at ∂H/∂I along trajectories integrated in Andoyer variables.

The reference is a DOP853 integration (rtol = atol = 1e-12) of Hamilton's equations of the
Andoyer Hamiltonian (``andoyer.state.andoyer.andoyer_equations``); nothing in it uses Sadov's
variables. The frequencies are also checked against the period of ``l(t)`` located by the
integrator's event finder.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from test_sadov_support import (
    BODIES,
    CASES,
    REPRESENTATIVE,
    SCALES,
    circle,
    inverse_moments,
    sample,
    scaled,
    separatrix_distance,
)

from andoyer.state import andoyer_equations
from andoyer.state.sadov import andoyer_to_sadov, sadov_frequencies


def integrate(body, y0, t_end, n_out=200, events=None, tol=1e-12):
    def rhs(_, y):
        return np.array(andoyer_equations(body, *y))

    t_eval = np.linspace(0.0, t_end, n_out)
    # Absolute tolerance per component: radians for the angles, G for the momenta.
    atol = tol * np.array([1.0, 1.0, 1.0, y0[4], y0[4], y0[4]])
    # A first step from the body's time scale 1/(G Δ(1/I)) keeps the first trial stages
    # inside |L| <= G (andoyer_equations rejects them otherwise); no Sadov variable is used.
    spread = np.ptp(1.0 / body.moments)
    first_step = min(1e-2 / (y0[4] * spread), t_end / 10) if spread > 0 else None
    return solve_ivp(
        rhs,
        (0.0, t_end),
        y0,
        method="DOP853",
        rtol=tol,
        atol=atol,
        t_eval=t_eval,
        events=events,
        first_step=first_step,
    )


def check_linear_angles(body, state, periods, tol=1e-12, per_radian=5e-11):
    """φ_ℓ(t), φ_g(t) against φ(0) + ω t: slope (least squares) and residuals.

    DOP853 at rtol = atol = 1e-12 drifts by up to a few 1e-11 per radian of the faster angle
    (measured: the residual falls with the tolerance, 1e-10 → 1.3e-11 over 19 rad from
    1e-12 to 1e-14; on the Earth the slow φ_ℓ inherits the error of the 1e4 times faster
    φ_g), so the residual is bounded by ``per_radian`` times the larger elapsed angle.
    Within ``d`` of the separatrix the integrator's error in the action becomes a frequency
    error amplified by ``1/(d log(1/d))`` (``ω_ℓ ∝ 1/K``); ``1e-12/d`` per radian covers it.
    """
    s0 = andoyer_to_sadov(body, *state)
    w = sadov_frequencies(body, s0.I_l, s0.I_g)
    t_end = periods * 2 * np.pi / abs(float(w.omega_l))
    sol = integrate(body, np.array(state, dtype=float), t_end, 400, tol=tol)
    assert sol.success
    s = andoyer_to_sadov(body, *sol.y)
    G = state[4]
    # The action is conserved to the integrator's accuracy.
    assert np.max(np.abs(s.I_l - s0.I_l)) <= 1e-10 * G
    elapsed = max(abs(float(w.omega_l)), abs(float(w.omega_g))) * t_end
    per_radian += 1e-12 / separatrix_distance(body, state[0], state[3], state[4])
    for phi, omega in ((s.phi_l, w.omega_l), (s.phi_g, w.omega_g)):
        # Residual on the circle: np.unwrap's running sum of 2π would itself drift by
        # ~1e-7 over the 1e5 turns of φ_g on the Earth.
        residual = circle(phi - (phi[0] + float(omega) * sol.t))
        drift = np.polyfit(sol.t, residual, 1)[0]
        assert abs(drift) * t_end <= per_radian * elapsed
        assert np.max(np.abs(residual)) <= per_radian * elapsed


@pytest.mark.parametrize(("name", "regime"), REPRESENTATIVE)
def test_angles_advance_at_the_frequencies(name, regime, rng):
    body = BODIES[name]
    check_linear_angles(body, [v[0] for v in sample(body, rng, 1, regime)], periods=2)


@pytest.mark.parametrize(("moment_scale", "momentum_scale"), SCALES[2:])
def test_angles_advance_at_the_frequencies_at_extreme_scales(moment_scale, momentum_scale, rng):
    body = scaled(BODIES["b3-max"], moment_scale)
    check_linear_angles(body, [v[0] for v in sample(body, rng, 1, "libration", G=momentum_scale)], periods=2)


@pytest.mark.slow
@pytest.mark.parametrize(("moment_scale", "momentum_scale"), [SCALES[0], SCALES[4]])
@pytest.mark.parametrize(("name", "regime"), CASES)
def test_angles_advance_at_the_frequencies_long(name, regime, moment_scale, momentum_scale, rng):
    body = scaled(BODIES[name], moment_scale)
    a = sample(body, rng, 2, regime, G=momentum_scale)
    for k in range(2):
        check_linear_angles(body, [v[k] for v in a], periods=10, tol=3e-14, per_radian=2e-11)


def observed_period(body, state, omega_l, l_ref):
    """Time between two successive upward zeros of ``sin(l(t) − l_ref)``, located by DOP853's
    event finder: ``l`` passes ``l_ref`` upwards once per period, in circulation (the
    Hamiltonian is π-periodic in ``l``, so ``l_ref + π`` is passed downwards in between) as in
    libration about a centre ``l_ref``."""

    def crossing(_, y):
        return np.sin(y[0] - l_ref)

    crossing.direction = 1.0
    t_max = 2.6 * 2 * np.pi / abs(omega_l)
    sol = integrate(body, np.array(state, float), t_max, n_out=2, events=[crossing])
    first, second = sol.t_events[0][:2]
    return second - first


@pytest.mark.parametrize(("name", "regime"), REPRESENTATIVE)
def test_frequency_equals_two_pi_over_period_of_l(name, regime, rng):
    body = BODIES[name]
    a1 = inverse_moments(body)[0]
    state = [v[0] for v in sample(body, rng, 1, regime)]
    l0 = state[0]
    if regime == "circulation":
        l_ref = l0 + 1.0
    elif a1 != 1.0 / body.B:  # libration about ±b1
        l_ref = np.pi / 2 if np.sin(l0) > 0 else 3 * np.pi / 2
    else:  # about ±b2
        l_ref = 0.0 if np.cos(l0) > 0 else np.pi
    s = andoyer_to_sadov(body, *state)
    omega_l = float(sadov_frequencies(body, s.I_l, s.I_g).omega_l)
    period = observed_period(body, state, omega_l, l_ref)
    assert period == pytest.approx(2 * np.pi / abs(omega_l), rel=1e-10)
