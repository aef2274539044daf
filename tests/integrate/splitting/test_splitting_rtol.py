"""The splitting's step chosen from an ``rtol`` (issue 25 item 3), against DOP853 at rtol 1e-13."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import RigidBody, State
from andoyer._limits import ToleranceWarning
from andoyer.integrate import splitting as splitting_module
from andoyer.integrate.propagation import propagate
from andoyer.integrate.splitting import SplittingState, integrate_splitting
from andoyer.perturbations import CircularOrbit, GravityGradient, HeavyTop, Model, PointMass

TRIAXIAL = RigidBody(0.7, 1.0, 1.3)
SYMMETRIC = RigidBody(1.0, 1.0, 1.5)
SUN = PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4))


def _state(body, regime):
    """A state of the given rotation regime: its energy against the separatrix ``G²/(2B)``."""
    g = 1.0
    if regime == "sam":  # about the axis of largest moment
        m = g * np.array([0.2, 0.1, 0.97])
    elif regime == "lam":  # about the axis of smallest moment
        m = g * np.array([0.97, 0.1, 0.2])
    else:  # near the separatrix: close to the middle axis
        m = g * np.array([0.02, 0.9995, 0.02])
    m = m / np.linalg.norm(m)
    return State.from_quaternion([0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], m)


def _relative_error(out, ref):
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
    t = np.array([0.0, 2.0, 5.0])
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15)
    out = propagate(model, start, t, method="splitting", rtol=rtol)
    assert isinstance(out, SplittingState)
    assert out.error_estimate <= rtol
    assert _relative_error(out, ref) <= rtol


def test_splitting_rtol_estimate_bounds_error_heavy_top():
    # a loose rtol stops at the first halving; the run's error is then well above DOP853's
    model, start = CASES["heavy top"]
    t = np.array([0.0, 5.0])
    ref = propagate(model, start, t, method="reference", rtol=1e-13, atol=1e-15)
    out = integrate_splitting(model, start, t, rtol=1e-2, order=2)
    error = _relative_error(out, ref)
    assert 1e-8 < error <= out.error_estimate


def test_splitting_first_step_quarter_orbit():
    # a quarter of the perturber's period 2π/0.3, halved once when the first pair agrees (a weak one)
    model = Model(TRIAXIAL, GravityGradient(PointMass(1e-4, CircularOrbit(2.0, 0.3, inclination=0.4))))
    out = integrate_splitting(model, _state(TRIAXIAL, "sam"), [0.0, 100.0], rtol=0.1)
    assert out.step == pytest.approx(0.25 * 2 * np.pi / 0.3 / 2, rel=1e-14)


def test_splitting_explicit_step_is_a_plain_state():
    model, start = CASES["heavy top"]
    out = propagate(model, start, [0.0, 1.0], method="splitting", step=0.1, order=4)
    same = integrate_splitting(model, start, [0.0, 1.0], 0.1, 4)
    assert type(out) is State
    assert np.array_equal(out.quaternion, same.quaternion)
    assert np.array_equal(out.m_body, same.m_body)


def test_splitting_rtol_unmet_warns(monkeypatch):
    monkeypatch.setattr(splitting_module, "MAX_HALVINGS", 1)
    model, start = CASES["heavy top"]
    with pytest.warns(ToleranceWarning, match="met no rtol"):
        out = integrate_splitting(model, start, [0.0, 5.0], rtol=1e-12)
    assert out.error_estimate > 1e-12


@pytest.mark.parametrize("bad", [0.0, -1e-6, np.nan, np.inf, 1e-16, 0.5, 1e300, "small", True])
def test_splitting_rtol_bad_input(bad):
    model, start = CASES["heavy top"]
    with pytest.raises(ValueError, match="expected a"):
        propagate(model, start, [0.0, 1.0], method="splitting", rtol=bad)
