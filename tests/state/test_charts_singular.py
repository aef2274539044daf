"""Exactly singular charts: a documented convention, a warning, an exact rotation round trip."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import SingularChartWarning, State
from conftest import rotation_distance


@pytest.mark.parametrize("theta", [0.0, np.pi])
def test_euler_singular_theta_sets_psi_zero_and_keeps_rotation(theta):
    rot = Rotation.from_euler("ZXZ", [0.7, theta, 0.4])
    state = State.from_attitude(rot, [0.3, -0.2, 1.0])
    with pytest.warns(SingularChartWarning, match="psi = 0"):
        e = state.as_euler()
    assert e.psi == 0.0
    assert not np.any(np.isnan(np.array(e)))
    expected_phi = (0.7 + 0.4) if theta == 0 else (0.7 - 0.4)
    assert abs(e.phi - expected_phi) <= 1e-15
    with pytest.warns(SingularChartWarning, match="set to 0"):
        back = State.from_euler(*e)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-15
    # The chart keeps Psi and Theta (= m1 with psi = 0); the component m2 is lost and set to 0.
    assert back.m_body[2] == state.m_body[2]
    assert abs(back.m_body[0] - state.m_body[0]) <= 1e-16


def test_euler_singular_rejects_inconsistent_momenta():
    with pytest.raises(ValueError, match=r"expected Phi = Psi cos\(theta\).*got"):
        State.from_euler(0.0, 0.0, 0.0, 1.0, 0.0, 0.5)


@pytest.mark.parametrize("J", [0.0, np.pi])
def test_andoyer_singular_J_sets_l_zero(J):
    G = 2.0
    state = State.from_andoyer(0.9, 0.3, 0.2, G * np.cos(J), G, 0.5)
    with pytest.warns(SingularChartWarning, match="l = 0"):
        a = state.as_andoyer()
    assert a.l == 0.0
    assert not np.any(np.isnan(np.array(a)))
    back = State.from_andoyer(*a)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-15
    assert np.abs(back.m_body - state.m_body).max() <= 1e-15 * G


@pytest.mark.parametrize("I", [0.0, np.pi])
def test_andoyer_singular_I_sets_h_zero(I):
    G = 3.0
    state = State.from_andoyer(0.9, 0.3, 0.2, 1.0, G, G * np.cos(I))
    with pytest.warns(SingularChartWarning, match="h = 0"):
        a = state.as_andoyer()
    assert a.h == 0.0
    back = State.from_andoyer(*a)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-15


def test_andoyer_singular_both_poles_identity():
    state = State.from_quaternion([0, 0, 0, 1], [0, 0, 5.0])
    with pytest.warns(SingularChartWarning) as record:
        a = state.as_andoyer()
    assert len(record) == 2
    assert (float(a.l), float(a.g), float(a.h)) == (0.0, 0.0, 0.0)


def test_singular_warning_points_at_caller():
    state = State.from_quaternion([0, 0, 0, 1], [0, 0, 5.0])
    with pytest.warns(SingularChartWarning) as record:
        state.as_euler()
    assert record[0].filename == __file__


def test_singular_warning_counts_only_singular_entries():
    q = Rotation.from_euler("ZXZ", [[0.1, 0.0, 0.2], [0.1, 0.5, 0.2], [0.3, np.pi, 0.1]]).as_quat()
    with pytest.warns(SingularChartWarning, match="^2 state"):
        e = State.from_quaternion(q, [0.0, 1.0, 1.0]).as_euler()
    assert e.psi[1] == pytest.approx(0.2, abs=1e-15)
