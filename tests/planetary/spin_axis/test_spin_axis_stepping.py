"""Order, norm and accuracy of the exact-rotation compositions; the interpreted fallback."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest
from spin_cases import PrecessingOrbit, angle

import andoyer._jit as andoyer_jit
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import SpinAxisModel, default_axis, mean_pole_j2000, output_times
from andoyer.planetary.spin_axis import stepping as stepping_module
from andoyer.planetary.spin_axis.history import integrate_axis, integrate_axis_dop853

ORBIT = PrecessingOrbit(inclination=0.05, node_rate=-2 * np.pi / 40000.0, e=0.06)
MODEL = SpinAxisModel.from_precession_rate("mars", 7.597, np.radians(25.19), eccentricity=0.06)


def _colombo_energy(orbit, model, t, s):
    """K = −(α/2)(s·n)² − Ω̇ (s·z): conserved for a uniformly regressing orbit (frame turning with it)."""
    n = orbit.normal(t)
    return -0.5 * model.rate(t, orbit.e) * np.sum(s * n, -1) ** 2 - orbit.g * s[..., 2]


@pytest.mark.parametrize("order", [2, 4, 6, 8])
def test_composition_converges_at_its_order(order):
    times = np.array([-20000.0, 30000.0])
    s0 = default_axis("mars")[None, :]
    reference = integrate_axis_dop853(ORBIT, MODEL, times, s0[0], rtol=1e-13)
    steps = {2: (1000.0, 500.0), 4: (2000.0, 1000.0), 6: (8000.0, 4000.0), 8: (16000.0, 8000.0)}[order]
    errors = []
    for h in steps:
        _, axes, index = integrate_axis(ORBIT, MODEL, times, s0, step=h, order=order)
        errors.append(angle(axes[0, index], reference).max())
    observed = np.log2(errors[0] / errors[1])
    assert errors[1] > 1e-12  # above DOP853's own error, so the ratio measures the method
    assert observed == pytest.approx(order, abs=0.35)


def test_default_step_agrees_with_dop853_on_vondrak():
    times = output_times(-50000.0, 50000.0, 5000.0)
    model = SpinAxisModel.from_precession_rate("earth", 50.3848, np.arccos(mean_pole_j2000()[2]))
    _, axes, index = integrate_axis(VondrakEcliptic(), model, times, mean_pole_j2000()[None, :])
    reference = integrate_axis_dop853(VondrakEcliptic(), model, times, mean_pole_j2000(), rtol=1e-13)
    assert angle(axes[0, index], reference).max() <= 1e-10


def test_norm_and_colombo_energy_conserved_over_ten_myr():
    times = output_times(-5e6, 5e6, 1e5)
    s0 = default_axis("mars")[None, :]
    grid, axes, _ = integrate_axis(ORBIT, MODEL, times, s0)
    assert np.abs(np.linalg.norm(axes[0], axis=-1) - 1).max() <= 1e-12
    energy = _colombo_energy(ORBIT, MODEL, grid, axes[0])
    scale = abs(float(MODEL.rate(0.0, ORBIT.e)))
    assert np.abs(energy - energy[0]).max() <= 1e-12 * scale  # measured 2e-14


def _fresh_copy(monkeypatch, module, name):
    spec = importlib.util.spec_from_file_location(name, Path(module.__file__))
    copy = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, copy)
    spec.loader.exec_module(copy)
    return copy


def test_interpreted_fallback_agrees_with_compiled(monkeypatch):
    monkeypatch.setenv("ANDOYER_NUMBA", "0")
    plain_jit = _fresh_copy(monkeypatch, andoyer_jit, "andoyer_jit_interpreted")
    monkeypatch.setitem(sys.modules, "andoyer._jit", plain_jit)
    plain = _fresh_copy(monkeypatch, stepping_module, "andoyer_spin_stepping_interpreted")
    assert not plain_jit.NUMBA
    assert not hasattr(plain.rotate_stages, "py_func")
    rng = np.random.default_rng(5)
    s0 = rng.normal(size=(3, 3))
    s0 /= np.linalg.norm(s0, axis=-1, keepdims=True)
    mid, dur = stepping_module.stage_times(np.arange(20.0) * 300.0, np.full(20, 300.0), 8)
    normals = ORBIT.normal(mid)
    parameters = np.array([[MODEL.alpha_sun], [MODEL.beta], [1e-9], [2e-9], [-1e-9]])
    parameters = parameters * np.abs(rng.normal(size=(1, 3)))
    factor = np.full((mid.size, 1), (1 - 0.06**2) ** -1.5)
    compiled = np.empty((3, 20, 3))
    interpreted = np.empty((3, 20, 3))
    stepping_module.rotate_stages(s0, normals, mid, factor, parameters, dur, 15, compiled)
    plain.rotate_stages(s0, normals, mid, factor, parameters, dur, 15, interpreted)
    assert np.abs(compiled - interpreted).max() <= 1e-14
