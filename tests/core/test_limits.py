"""Issue 18's numbers: no phase printed without digits, no run started that cannot fit, exact spans.

The phase rule (:mod:`andoyer._limits`): a phase ``ω t`` carries the float64 rounding of ``t``
and ``ω``, ``|ω t| 2⁻⁵²`` rad; a warning below six digits, an error once none is left. Sizes:
refused before anything is allocated, with what the request would need.
"""

from __future__ import annotations

import io
import math
import tracemalloc
import warnings

import numpy as np
import pytest

import andoyer._limits
import andoyer.planetary.precession
from andoyer import FreeRotation, RigidBody, State, bodies, propagate
from andoyer._jit import NUMBA
from andoyer._limits import (
    PHASE_ERROR_LIMIT,
    PHASE_WARN_LIMIT,
    PhasePrecisionWarning,
    check_phase,
    check_size,
    format_bytes,
    progress,
    show_progress,
    spin_rate,
)
from andoyer.free import FreeMotion
from andoyer.perturbations import HeavyTop, Model, PrecessingFrame
from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR
from andoyer.planetary.precession import precession_rates
from andoyer.theories.sam import MAX_ORDER, sam_theory
from conftest import rotation_distance

EROS = bodies.get("eros")
EROS_STATE = State.from_andoyer(0.1, 0.2, 0.3, 0.9, 1.0, 0.5)  # the issue's state
TOP = Model(RigidBody(1.0, 1.2, 1.5), HeavyTop(0.5, [0.0, 0.1, 0.3]))


@pytest.fixture
def cli(run_cli):
    """``andoyer ARGV`` in process: (exit code, stdout, stderr)."""
    return run_cli


# -- the phase rule ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("phase", "outcome"),
    [
        (0.0, "quiet"),
        (1e9, "quiet"),
        (PHASE_WARN_LIMIT * 0.999, "quiet"),
        (PHASE_WARN_LIMIT * 1.001, "warn"),
        (1e14, "warn"),
        (PHASE_ERROR_LIMIT * 0.999, "warn"),
        (PHASE_ERROR_LIMIT * 1.001, "raise"),
        (1e300, "raise"),
    ],
)
@pytest.mark.parametrize("rate", [1e-5, 4.36, 1e8])
def test_phase_check_thresholds(phase, outcome, rate):
    t = np.array([0.0, -phase / rate])
    if outcome == "raise":
        with pytest.raises(ValueError, match=r"expected times with \|ω t\| below 4.5e\+15 rad"):
            check_phase(rate, t)
    elif outcome == "warn":
        with pytest.warns(PhasePrecisionWarning) as record:
            check_phase(rate, t)
        digits = -math.log10(phase * 2.0**-52)  # the digits left, from the stated error model
        assert f"keeps only {digits:.1f} digits" in str(record[0].message)
    else:
        check_phase(rate, t)  # filterwarnings = error: any warning fails


def test_phase_thresholds_in_digits():
    # six digits left at the warning (error 1e-6 rad), none at the error (error 1 rad)
    assert pytest.approx(1e-6, rel=1e-15) == PHASE_WARN_LIMIT * 2.0**-52
    assert PHASE_ERROR_LIMIT * 2.0**-52 == 1.0


@pytest.mark.parametrize("t", [2.0**40, 1e13, 3.3e14])
def test_phase_error_model_one_ulp_of_t_turns_the_attitude_by_omega_ulp(t):
    """The error model behind the rule: one ulp of ``t`` turns the body by ``|ω(t)| ulp(t)``.

    ``|ω| = |I⁻¹ m(t)|`` is the angular speed (Euler's equations), independent of the
    phase reduction; at 2⁵² rad of phase one ulp of ``t`` is a radian, the rule's error.
    """
    motion = FreeMotion(EROS.moments, EROS_STATE.m_body, EROS_STATE.quaternion)
    later = np.nextafter(t, np.inf)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PhasePrecisionWarning)
        m, q = motion.propagate(np.array([t, later]))
    speed = np.linalg.norm(m[0] / EROS.moments)
    turned = float(rotation_distance(q[0], q[1]))
    assert turned == pytest.approx(speed * (later - t), rel=1e-3)
    # and the rule's rate bounds that speed
    assert speed <= spin_rate(EROS.moments, EROS_STATE.m_body)


def test_phase_free_rotation_issue_example_refused():
    free = FreeRotation(EROS)
    for t in (1e17, 1e33, 1e300, -1e300):
        with pytest.raises(ValueError, match="keeps at least one digit"):
            free.propagate(EROS_STATE, t)


def test_phase_warning_points_at_the_caller():
    with pytest.warns(PhasePrecisionWarning) as record:
        FreeRotation(EROS).propagate(EROS_STATE, 1e14)
    assert record[0].filename == __file__
    # a top so light that a step of 1e9 resolves its torque (2π|M|/|τ| ~ 1e31)
    light = Model(RigidBody(1.0, 1.2, 1.5), HeavyTop(1e-30, [0.0, 0.1, 0.3]))
    with pytest.warns(PhasePrecisionWarning) as record:
        propagate(light, State.from_andoyer(0.1, 0.2, 0.3, 1.8, 2.0, 1.5), 3e9, method="splitting", step=1e9)
    assert record[0].filename == __file__


@pytest.mark.parametrize("method", ["reference", "splitting", "secular"])
def test_phase_every_method_refuses_a_phase_without_digits(method):
    model = TOP if method != "secular" else Model(RigidBody(1.0, 1.0, 1.2), PrecessingFrame([0.0, 0.0, 0.01]))
    options = {"step": 0.1} if method == "splitting" else {}
    with pytest.raises(ValueError, match="keeps at least one digit"):
        propagate(model, EROS_STATE, [0.0, 1e300], method=method, **options)


# -- sizes -------------------------------------------------------------------------------------


@pytest.fixture(autouse=True)
def sixteen_gib(monkeypatch):
    """The same memory limit on every machine: 16 GiB."""
    monkeypatch.setattr(andoyer._limits, "memory_limit", lambda: 16 * 2**30)


def _peak_while_refused(call, match):
    tracemalloc.start()
    try:
        with pytest.raises(ValueError, match=match) as info:
            call()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    return peak, str(info.value)


def test_size_splitting_issue_example_refused_before_allocating():
    # 1e15 steps: 7.11 PiB of step lengths alone before the fix
    peak, message = _peak_while_refused(
        lambda: propagate(TOP, EROS_STATE, [0.0, 1e6], method="splitting", step=1e-9, order=2),
        # the limit is an hour's work: 1e10 compiled steps, fewer interpreted (ANDOYER_NUMBA=0)
        "expected a splitting run of at most " + ("1e\\+10" if NUMBA else "2.3e\\+08") + " steps",
    )
    assert "got 1e+15 steps" in message
    assert peak < 2**20


def test_size_precession_issue_example_refused_with_its_size():
    peak, message = _peak_while_refused(lambda: precession_rates("earth", integrate=1e9), "would need")
    # one output of 4 states × 7 floats × 3 copies (+ the time) per step of 2.2439 days
    steps = 1e9 * JULIAN_YEAR / andoyer.planetary.precession.default_step("earth")
    assert format_bytes(steps * (8 + 2 * 3 * 7 * 8 * 4)) in message
    assert peak < 2**22


@pytest.mark.parametrize(("t", "rtol"), [(1e9, 1e-12), (1e8, 1e-4)])
def test_size_reference_refused_from_its_step_estimate(t, rtol):
    # 2.5 (1e-12/rtol)^(1/8) steps per radian, |m|/min(I) = 2 rad per unit time, 1050 bytes a step
    steps = 2.5 * (1e-12 / rtol) ** 0.125 * 2.0 * t
    with pytest.raises(ValueError, match=r"expected a DOP853 run of at most 16 GiB") as info:
        propagate(TOP, State.from_andoyer(0.1, 0.2, 0.3, 1.8, 2.0, 1.5), t, rtol=rtol)
    assert str(info.value).endswith(f"would need {format_bytes(steps * 1050)}")


def test_size_secular_refused_from_its_step_estimate():
    # the Moon's mean motion 2.66e-6 rad/s over 1e8 years: 0.007 steps per radian of 0.5 ms, 8.6 hours
    model, states = andoyer.planetary.precession.precession_problem("earth")
    moon = max(p.orbit.mean_motion for p in model.perturbation.perturbers)
    hours = 0.007 * moon * 1e8 * JULIAN_YEAR * 5e-4 / 3600
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PhasePrecisionWarning)  # 2.3e11 rad of spin: warned, not refused
        with pytest.raises(ValueError, match="expected a secular run of at most") as info:
            propagate(model, states[:1], [0.0, 1e8 * JULIAN_YEAR], method="secular")
    assert f"(about {hours:.2g} hours)" in str(info.value)


def test_size_check_names_what_it_would_need():
    with pytest.raises(ValueError, match=r"would need 7\.11 PiB$"):
        check_size("a test", nbytes=8e15)
    assert format_bytes(1.18 * 2**40) == "1.18 TiB"
    check_size("a test", steps=1e9, nbytes=1e6)


def test_size_sam_order_refused_with_its_estimate():
    with pytest.raises(ValueError, match=r"got 200 \(would take about 32 days\)"):
        sam_theory(200)
    with pytest.raises(ValueError, match=f"between 1 and {MAX_ORDER}"):
        sam_theory(MAX_ORDER + 1)


# -- item 7: the integration span is honoured exactly --------------------------------------------


@pytest.mark.parametrize(("years", "days"), [(0.2, 8.227), (0.05, 8.227), (0.1, 2.0)])
def test_precession_span_is_honoured_exactly(monkeypatch, years, days):
    seen = []
    real = andoyer.planetary.precession.propagate

    def spy(model, states, t, method="reference", **options):
        seen.append((method, np.asarray(t).ravel(), options))
        return real(model, states, t, method=method, **options)

    monkeypatch.setattr(andoyer.planetary.precession, "propagate", spy)
    rates = precession_rates("earth", integrate=years, step=days * DAY, secular_years=1.0)
    method, t, options = seen[-1]
    assert method == "splitting"
    assert t[-1] == years * JULIAN_YEAR
    assert np.all(np.diff(t) <= days * DAY * (1 + 1e-12))
    assert np.all(np.diff(t) > 0)
    assert options["step"] == days * DAY
    assert rates.years == years


def test_precession_too_few_samples_for_the_fit_refused():
    # 0.1 yr at 8.227 d: six node samples, but the Moon's orbit is covered, so the fit has eight
    # unknowns (offset, rate, three harmonics): a rate from it would mean nothing.
    with pytest.raises(ValueError, match="expected at least 8 times for the fit, got 6"):
        precession_rates("earth", integrate=0.1, step=8.227 * DAY, secular_years=1.0)


def test_precession_step_over_half_the_span_refused():
    with pytest.raises(ValueError, match="at most half the span"):
        precession_rates("earth", integrate=1.0, step=0.6 * JULIAN_YEAR)


# -- the command line: one line, exit 2 for refusals, one warning line -------------------------

EROS_ARGS = ("--body", "eros", "--values", "0.1", "0.2", "0.3", "0.9", "1.0", "0.5")


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (("propagate", *EROS_ARGS, "--times", "1e300"), "keeps at least one digit"),
        (("propagate", *EROS_ARGS, "--times", "1e17"), "keeps at least one digit"),
        (("propagate", *EROS_ARGS, "--range", "0", "10", "100000000"), "would need"),
        (
            ("propagate", *EROS_ARGS, "--times", "0", "1e6", "--method", "splitting", "--step", "1e-9"),
            "expected a splitting run of at most",
        ),
        (("precession", "earth", "--integrate", "1e9"), "would need"),
        (("precession", "earth", "--integrate", "1", "--step", "1e6"), "at most half of --integrate"),
        (("series", "sam", "--order", "200"), "would take about 33 days"),
        (
            ("portrait", "precession", "--moments", "1", "2", "3", "--duration", "1e300", "--out", "x.png"),
            "keeps at least one digit",
        ),
        (
            ("ensemble", "--body", "eros", "--samples", "10", "--times", "1e300", "--out", "e.zarr"),
            "keeps at least one digit",
        ),
    ],
    ids=lambda v: v[0] if isinstance(v, tuple) else None,
)
def test_cli_refuses_in_one_line(cli, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)
    code, out, err = cli(*argv)
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1
    assert err.startswith(f"andoyer {argv[0]}: error: expected")
    assert message in err
    assert list(tmp_path.iterdir()) == []


def test_cli_phase_warning_is_one_line(cli):
    code, out, err = cli("propagate", *EROS_ARGS, "--times", "1e14")
    assert code == 0
    assert "1e+14" in out
    assert err.count("\n") == 1
    assert err.startswith("andoyer propagate: warning: the phase of the free motion keeps only 1.0 digits")


# -- progress ----------------------------------------------------------------------------------


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_only_on_a_terminal_inside_show_progress():
    with progress(10, "library", stream=_Terminal()) as bar:
        assert bar is None  # library calls stay silent
    with show_progress(), progress(10, "file", stream=io.StringIO()) as bar:
        assert bar is None  # not a terminal
    terminal = _Terminal()
    with show_progress(), progress(10, "cli", stream=terminal) as bar:
        assert bar is not None
        bar.update(10)
    with progress(10, "after", stream=_Terminal()) as bar:
        assert bar is None  # show_progress is scoped
