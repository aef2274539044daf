"""The splitting's order and step chosen from an ``rtol`` by the probe's error model (issue 25 item 3).

The measured errors are against DOP853 at rtol 1e-13 (an independent integrator of the full
equations), at many output times.
"""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import RigidBody, State
from andoyer._limits import ToleranceWarning
from andoyer.integrate import splitting as splitting_module
from andoyer.integrate.propagation import propagate
from andoyer.integrate.splitting import DEFAULT_RTOL, SplittingState, integrate_splitting
from andoyer.integrate.splitting.probe import SAFETY, detune, distance_model
from andoyer.perturbations import CircularOrbit, GravityGradient, HeavyTop, Model, PointMass

TRIAXIAL = RigidBody(0.7, 1.0, 1.3)
SYMMETRIC = RigidBody(1.0, 1.0, 1.5)
SUN = PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4))
#: A faster, weaker perturber (period π/2): the probe (16 periods, 8π) is shorter than a span of 100.
WEAK_FAST_SUN = PointMass(0.04, CircularOrbit(2.0, 4.0, inclination=0.4))


def _state(body, regime, rng=None):
    """A state of the given rotation regime: its energy against the separatrix ``G²/(2B)``."""
    g = 1.0
    if regime == "sam":  # about the axis of largest moment
        m = g * np.array([0.2, 0.1, 0.97])
    elif regime == "lam":  # about the axis of smallest moment
        m = g * np.array([0.97, 0.1, 0.2])
    else:  # near the separatrix: close to the middle axis
        m = g * np.array([0.02, 0.9995, 0.02])
    m = m / np.linalg.norm(m)
    q = [0.1, 0.2, 0.3, np.sqrt(1 - 0.14)] if rng is None else rng.normal(size=4)
    return State.from_quaternion(q / np.linalg.norm(q), m)


def _relative_error(out, ref):
    """``max |M − M_ref| / |M_ref|`` over the outputs (``|M|`` changes little: what ``rtol`` bounds)."""
    scale = np.linalg.norm(ref.m_reference, axis=-1)
    return float(np.max(np.linalg.norm(out.m_reference - ref.m_reference, axis=-1) / scale))


CASES = {
    "gravity gradient, SAM": (Model(TRIAXIAL, GravityGradient(SUN)), _state(TRIAXIAL, "sam")),
    "gravity gradient, LAM": (Model(TRIAXIAL, GravityGradient(SUN)), _state(TRIAXIAL, "lam")),
    "gravity gradient, near separatrix": (Model(TRIAXIAL, GravityGradient(SUN)), _state(TRIAXIAL, "near")),
    "gravity gradient, axisymmetric": (Model(SYMMETRIC, GravityGradient(SUN)), _state(SYMMETRIC, "sam")),
    "heavy top": (Model(TRIAXIAL, HeavyTop(0.5, [0.0, 0.1, 0.3])), _state(TRIAXIAL, "sam")),
}


@pytest.mark.parametrize("rtol", [1e-5, 1e-8])
@pytest.mark.parametrize("case", list(CASES))
def test_splitting_rtol_met_against_dop853(case, rtol):
    model, start = CASES[case]
    t = np.linspace(0.0, 5.0, 11)
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15)
    out = propagate(model, start, t, method="splitting", rtol=rtol)
    assert isinstance(out, SplittingState)
    assert out.error_estimate <= rtol
    assert _relative_error(out, ref) <= out.error_estimate


@pytest.mark.parametrize(
    ("gm", "seed", "regime"),
    [
        (0.04, 3, "sam"),
        pytest.param(0.04, 17, "lam", marks=pytest.mark.slow),
        pytest.param(4.0, 3, "sam", marks=pytest.mark.slow),  # M turns: the probe covers two turns
        pytest.param(4.0, 17, "lam", marks=pytest.mark.slow),
    ],
)
def test_splitting_estimate_bounds_error_beyond_the_probe(gm, seed, regime):
    # span 100 over a probe of 16 orbital periods (8π ≈ 25) or more: the drift is extrapolated
    rng = np.random.default_rng(seed)
    sun = PointMass(gm, CircularOrbit(2.0, 4.0, inclination=0.4))
    model, start = Model(TRIAXIAL, GravityGradient(sun)), _state(TRIAXIAL, regime, rng)
    t = np.linspace(0.0, 100.0, 41)
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15)
    out = integrate_splitting(model, start, t, rtol=1e-6)
    assert out.probe_length < 50.0
    assert _relative_error(out, ref) <= out.error_estimate <= 1e-6


def test_splitting_rtol_backwards_and_several_states():
    # two states at once, outputs on both sides of t0 (the probe runs the longer side)
    model = Model(TRIAXIAL, GravityGradient(SUN))
    q = np.array([[0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], [0.0, 0.0, 0.0, 1.0]])
    m = np.array([[0.2, 0.1, 0.97], [0.97, 0.1, 0.2]])
    start = State.from_quaternion(q, m / np.linalg.norm(m, axis=-1, keepdims=True))
    t = np.array([-6.0, -3.0, 1.0, 2.0])[:, None] + 10.0
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15, t0=10.0)
    out = propagate(model, start, t, method="splitting", rtol=1e-6, t0=10.0)
    assert out.shape == (4, 2)
    assert _relative_error(out, ref) <= out.error_estimate <= 1e-6


def test_splitting_loose_rtol_estimate_bounds_a_large_error():
    # a loose rtol takes a coarse step: its error is far above DOP853's and still bounded
    model, start = CASES["heavy top"]
    t = np.linspace(0.0, 5.0, 11)
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15)
    out = integrate_splitting(model, start, t, rtol=1e-2, order=2)
    assert 1e-6 < _relative_error(out, ref) <= out.error_estimate <= 1e-2


def test_splitting_estimate_is_the_model_of_independent_probe_runs():
    # E = 2 (B + D max(T − L, 0)) recomputed from plain fixed-step runs at h and h/2
    model, start = Model(TRIAXIAL, GravityGradient(WEAK_FAST_SUN)), _state(TRIAXIAL, "sam")
    span = 100.0
    out = integrate_splitting(model, start, [span], rtol=1e-6, order=2)
    h, length = out.step, out.probe_length
    assert length < span
    count = int(np.floor(length / h + 1e-9))
    every = int(np.ceil(count / 64))
    times = h * every * np.arange(1, count // every + 1)
    coarse = integrate_splitting(model, start, times, h, 2).m_reference
    fine = integrate_splitting(model, start, times, h / 2, 2).m_reference
    delta = (coarse - fine) / np.linalg.norm(start.m_reference)
    size = np.linalg.norm(delta, axis=-1)
    # the drift: the vector's slope or the norm's, the larger
    slope = max(np.linalg.norm(np.polyfit(times, delta, 1)[0]), np.polyfit(times, size, 1)[0])
    bounded = np.max(size)
    estimate = 2.0 * (bounded + slope * (span - length))
    assert out.bounded == pytest.approx(bounded, rel=1e-12)
    assert out.error_estimate == pytest.approx(estimate, rel=1e-9)


def test_splitting_order_is_the_cheapest_that_meets_rtol():
    # the chosen order costs the fewest Strang substeps among the orders' own choices
    model, start = CASES["gravity gradient, SAM"]
    t = [0.0, 5.0]
    stages = {2: 1, 4: 3, 6: 7}
    each = {order: integrate_splitting(model, start, t, rtol=1e-8, order=order) for order in (2, 4, 6)}
    cost = {order: stages[order] / out.step for order, out in each.items()}
    assert len(set(cost.values())) == 3
    chosen = integrate_splitting(model, start, t, rtol=1e-8)
    assert chosen.order == min(cost, key=cost.get)
    assert chosen.step == each[chosen.order].step


def test_splitting_step_is_the_first_rung_that_meets_rtol():
    # asking just below the chosen step's estimate takes a smaller step; asking it, the same one
    model, start = CASES["gravity gradient, SAM"]
    out = integrate_splitting(model, start, [0.0, 5.0], rtol=1e-5, order=2)
    same = integrate_splitting(model, start, [0.0, 5.0], rtol=out.error_estimate, order=2)
    tighter = integrate_splitting(model, start, [0.0, 5.0], rtol=0.999 * out.error_estimate, order=2)
    assert same.step == out.step
    assert tighter.step < out.step
    assert tighter.error_estimate <= 0.999 * out.error_estimate


def test_splitting_rtol_python_path_matches_compiled(monkeypatch):
    # the generic (Python) step records the probe's states as the compiled loop does
    model, start = CASES["heavy top"]
    compiled = integrate_splitting(model, start, [0.0, 2.0], rtol=1e-4, order=2)
    monkeypatch.setattr(splitting_module, "_tabulable", lambda kicks: False)
    generic = integrate_splitting(model, start, [0.0, 2.0], rtol=1e-4, order=2)
    assert generic.step == compiled.step
    assert generic.error_estimate == pytest.approx(compiled.error_estimate, rel=1e-6)
    assert np.allclose(generic.m_body, compiled.m_body, rtol=0, atol=1e-12)


def test_splitting_outputs_leave_the_run_alone():
    # the state at t = 10 is the same whether or not the run stops at nine times on the way
    model, start = CASES["gravity gradient, SAM"]
    many = integrate_splitting(model, start, np.linspace(1.03, 10.0, 10), 0.37, 2)
    one = integrate_splitting(model, start, [10.0], 0.37, 2)
    assert np.array_equal(many.m_body[-1], one.m_body[0])
    assert np.array_equal(many.quaternion[-1], one.quaternion[0])


def test_splitting_default_is_rtol_default():
    model, start = CASES["heavy top"]
    out = propagate(model, start, [0.0, 1.0, 2.0], method="splitting")
    same = integrate_splitting(model, start, [0.0, 1.0, 2.0], rtol=DEFAULT_RTOL)
    assert isinstance(out, SplittingState)
    assert (out.order, out.step, out.error_estimate) == (same.order, same.step, same.error_estimate)
    assert out.error_estimate <= DEFAULT_RTOL


def test_detune_moves_a_step_off_resonance():
    # one turn per unit of time: the farthest step from a whole number of turns in [1/√2, 1]
    h, margin = detune(1.0, np.array([2 * np.pi]))
    assert h == pytest.approx(2**-0.5, rel=1e-12)
    assert margin == pytest.approx(1 - 2**-0.5, rel=1e-12)
    # 7 turns of a spin of period 1 and 3 of a period 7/3: h = 7 resonates with both
    h, margin = detune(7.0, 2 * np.pi / np.array([1.0, 7.0 / 3.0]))
    phases = h * np.array([1.0, 3.0 / 7.0])
    assert np.min(np.abs(phases - np.round(phases))) == pytest.approx(margin, rel=1e-12)
    assert margin > 0.1


def test_distance_model_against_polyfit():
    rng = np.random.default_rng(5)
    t = np.sort(rng.uniform(0.0, 10.0, 50))
    delta = np.stack([3e-7 + 2e-8 * t + 1e-7 * np.sin(3 * t), 1e-7 * np.cos(t), -1e-8 * t], axis=-1)
    bounded, drift = distance_model(t, delta[:, None, :])
    size = np.linalg.norm(delta, axis=-1)
    assert bounded == pytest.approx(np.max(size), rel=1e-14)
    slopes = np.linalg.norm(np.polyfit(t, delta, 1)[0]), np.polyfit(t, size, 1)[0]
    assert drift == pytest.approx(max(slopes), rel=1e-10)
    # a drift whose direction turns: the vector's slope misses it, the norm's does not
    turning = 1e-8 * t[:, None] * np.stack([np.cos(2 * t), np.sin(2 * t), 0 * t], axis=-1)
    assert distance_model(t, turning[:, None, :])[1] == pytest.approx(1e-8, rel=0.05)
    assert SAFETY == 2.0


def test_splitting_rtol_unmet_warns(monkeypatch):
    monkeypatch.setattr(splitting_module, "MAX_HALVINGS", 1)
    model, start = CASES["heavy top"]
    with pytest.warns(ToleranceWarning, match="met no rtol"):
        out = integrate_splitting(model, start, [0.0, 5.0], rtol=1e-12)
    assert out.error_estimate > 1e-12


def test_splitting_explicit_step_is_a_plain_state():
    model, start = CASES["heavy top"]
    out = propagate(model, start, [0.0, 1.0], method="splitting", step=0.1, order=4)
    same = integrate_splitting(model, start, [0.0, 1.0], 0.1, 4)
    assert type(out) is State
    assert np.array_equal(out.quaternion, same.quaternion)
    assert np.array_equal(out.m_body, same.m_body)


@pytest.mark.parametrize("bad", [0.0, -1e-6, np.nan, np.inf, 1e-16, 0.5, 1e300, "small", True])
def test_splitting_rtol_bad_input(bad):
    model, start = CASES["heavy top"]
    with pytest.raises(ValueError, match="expected a"):
        propagate(model, start, [0.0, 1.0], method="splitting", rtol=bad)


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"rtol": 1e-6, "order": 3}, "expected a splitting order of 2, 4 or 6, got 3"),
        ({"rtol": 1e-6, "step": -0.1}, "expected a positive finite step, got -0.1"),
        ({"rtol": 1e-6, "step": np.nan}, "expected a positive finite step"),
        ({"rtol": 1e-6, "t0": np.inf}, "expected finite"),
    ],
)
def test_splitting_rtol_bad_options(options, message):
    model, start = CASES["heavy top"]
    with pytest.raises(ValueError, match=message):
        integrate_splitting(model, start, [0.0, 1.0], **options)


@pytest.mark.parametrize("weight", [1e150, 1e300])
def test_splitting_rtol_torque_beyond_any_step_refused_before_the_probe(weight, monkeypatch):
    # a heavy top of weight 1e150 swings with period 2π√(I/τ) ~ 1e-74: no run resolves it, and
    # the probe must not try its 24 halvings first (CI ran this for hours)
    def no_probe(*args, **kwargs):
        raise AssertionError("the probe ran")

    monkeypatch.setattr(splitting_module, "choose", no_probe)
    model = Model(TRIAXIAL, HeavyTop(weight, [0.0, 0.1, 0.3]))
    with pytest.raises(ValueError, match=r"expected a torque whose time scale .* got a time scale of"):
        integrate_splitting(model, CASES["heavy top"][1], [0.0, 1.0], rtol=1e-6)


@pytest.mark.parametrize("weight", [1e150, 1e300])
def test_splitting_fixed_step_beyond_the_torque_time_scale_refused(weight):
    # a step of 0.1 against a swing of period ~1e-74: it gave |m| ~ 1e149 (a wrong number)
    model = Model(TRIAXIAL, HeavyTop(weight, [0.0, 0.1, 0.3]))
    with pytest.raises(ValueError, match=r"expected a step of at most the torque's time scale .* got 0\.1"):
        integrate_splitting(model, CASES["heavy top"][1], [0.0, 1.0], step=0.1)
    # the time scale of the suite's heavy top (|τ| ~ 0.16, |M| = 1): a step just past it is refused
    model, start = CASES["heavy top"]
    scale = splitting_module._torque_period(
        splitting_module._torque_sizes(
            splitting_module.splitting_parts(model)[0], 0.0, start.quaternion[None], start.m_body[None]
        ),
        start.m_body[None],
        model.body.moments,
    )
    # |τ| = W |r × ĝ| ≤ W |r| = 0.5 √0.1 at any attitude, |M| = 1: the turn's period is at least
    # 2π / (0.5 √0.1), longer than the swing's 2π √(1.3 / |τ|); the sampled attitudes (turns by
    # an eighth and a quarter about each axis) find at least half of the largest torque
    bound = 2 * np.pi / (0.5 * np.sqrt(0.1))
    assert bound <= scale <= 2.0 * bound
    integrate_splitting(model, start, [0.0, scale], step=scale)
    with pytest.raises(ValueError, match="torque's time scale"):
        integrate_splitting(model, start, [0.0, 1.0], step=1.01 * scale)


def test_splitting_torque_period_is_the_longer_of_turn_and_swing():
    moments = np.array([1.0, 2.0, 4.0])
    # |M| = 3, |τ| = 2: the turn 2π·3/2 is longer than the swing 2π√(4/2)
    assert splitting_module._torque_period(np.array([2.0]), np.array([[0.0, 0.0, 3.0]]), moments) == (
        pytest.approx(3 * np.pi, rel=1e-15)
    )
    # at rest the swing sets it; the shortest over the states; no torque: none
    sizes, m = np.array([2.0, 50.0]), np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    period = splitting_module._torque_period
    assert period(sizes, m, moments) == pytest.approx(2 * np.pi * np.sqrt(4 / 50), rel=1e-15)
    assert period(sizes[:1], m[:1], moments) == pytest.approx(2 * np.pi * np.sqrt(2), rel=1e-15)
    assert splitting_module._torque_period(np.zeros(1), m[:1], moments) == np.inf
    with pytest.raises(ValueError, match="got nan"):
        splitting_module._torque_period(np.array([np.nan]), m[:1], moments)


def test_splitting_probe_total_cost_is_bounded(monkeypatch):
    # each run of the ladder alone is within the limit of one run, their sum is not: the probe
    # stops with the limit's message in time, not in steps (check_size's `seconds`)
    from andoyer import _limits

    budget = _limits.MAX_STEPS * _limits.STEP_SECONDS
    monkeypatch.setattr(splitting_module, "STEP_SECONDS", budget / 6000.0)
    model, start = CASES["heavy top"]
    message = r"expected the splitting's probe of at most about .* got one of about"
    with pytest.raises(ValueError, match=message):
        integrate_splitting(model, start, [0.0, 5.0], rtol=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("rtol", [1e-3, 1e-5])
def test_splitting_estimate_bounds_earth_precession_error(rtol):
    # the Earth under the Sun and the Moon over 200 years, 100 outputs, against order 4 at
    # 0.37 sidereal days (2.4e-10 from heyoka at tol 1e-15 over 2 years: benchmarks/RESULTS.md)
    from scipy.spatial.transform import Rotation

    from andoyer import bodies
    from andoyer.catalogue.units import JULIAN_YEAR
    from andoyer.perturbations.solar_system import OBLIQUITY, mean_perturbers

    earth, sidereal_day = bodies.get("earth"), bodies.info("earth").rotation_period
    model = Model(earth, GravityGradient(mean_perturbers("earth")))
    spin = earth.C * 2 * np.pi / sidereal_day
    start = State.from_attitude(Rotation.from_euler("X", OBLIQUITY["earth"]), [0.0, 0.0, spin])
    t = np.linspace(2.0, 200.0, 100) * JULIAN_YEAR
    fine = integrate_splitting(model, start, t, 0.37 * sidereal_day, 4)
    out = integrate_splitting(model, start, t, rtol=rtol)
    assert out.probe_length < 200 * JULIAN_YEAR
    assert _relative_error(out, fine) <= out.error_estimate <= rtol
