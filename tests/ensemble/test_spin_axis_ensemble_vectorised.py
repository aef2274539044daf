"""Many spin-axis histories in one compiled pass against one history per pass, and the ensemble API."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.ensemble import run_ensemble
from andoyer.ensemble.spin_axis import SpinAxisPropagator, SpinParameterSampler
from andoyer.planetary.orbits import LaplaceLagrangeOrbit, VondrakEcliptic
from andoyer.planetary.spin_axis import SpinAxisModel, build_model, default_axis, evolve_axes
from andoyer.planetary.spin_axis.stepping import rotate_stages, stage_times

ORBIT = LaplaceLagrangeOrbit("earth")


def _runs(rng, m):
    s0 = rng.normal(size=(m, 3))
    s0 /= np.linalg.norm(s0, axis=-1, keepdims=True)
    base = SpinAxisModel.from_precession_rate("earth", 50.0, 0.41)
    scale = np.array([base.alpha_sun, base.beta, 1e-9, 1e-9, 1e-9])[:, None]
    # slow (0.2×) to fast (5×) precession, tides and drifts of both signs
    parameters = scale * np.vstack(
        [rng.uniform(0.2, 5.0, m), rng.uniform(0.0, 3.0, m), rng.uniform(-1, 1, (3, m))]
    )
    return s0, np.ascontiguousarray(parameters)


@pytest.mark.parametrize("shared", [True, False])
def test_rotate_stages_many_runs_equal_one_run_each(shared):
    rng = np.random.default_rng(11)
    s0, parameters = _runs(rng, 7)
    mid, dur = stage_times(np.arange(30.0) * -700.0, np.full(30, -700.0), 8)
    normals = np.ascontiguousarray(ORBIT.normal(mid))
    e = rng.uniform(0.0, 0.3, (mid.size, 1 if shared else 7))
    factor = ((1 - e) * (1 + e)) ** -1.5
    many = np.empty((7, 30, 3))
    rotate_stages(s0, normals, mid, factor, parameters, dur, 15, many)
    for m in range(7):
        one = np.empty((1, 30, 3))
        column = factor if shared else np.ascontiguousarray(factor[:, m : m + 1])
        rotate_stages(
            s0[m : m + 1], normals, mid, column, np.ascontiguousarray(parameters[:, m : m + 1]), dur, 15, one
        )
        assert np.abs(many[m] - one[0]).max() <= 1e-15


def test_rotate_stages_matches_rodrigues_in_numpy():
    # independent: the axis turned stage by stage with numpy's Rodrigues formula and α written out
    rng = np.random.default_rng(3)
    s0, parameters = _runs(rng, 4)
    mid, dur = stage_times(np.arange(5.0) * 1000.0, np.full(5, 1000.0), 4)
    normals = np.ascontiguousarray(ORBIT.normal(mid))
    factor = np.full((mid.size, 1), (1 - 0.0167**2) ** -1.5)
    out = np.empty((4, 5, 3))
    rotate_stages(s0, normals, mid, factor, parameters, dur, 3, out)
    s = s0.copy()
    for k in range(mid.size):
        a, b, ts, tm, dr = parameters
        alpha = a * (1 + ts * mid[k]) * (1 + dr * mid[k]) * (factor[k, 0] + b * (1 + tm * mid[k]))
        n = normals[k]
        phi = -alpha * dur[k] * (s @ n)
        s = (
            s * np.cos(phi)[:, None]
            + np.cross(n, s) * np.sin(phi)[:, None]
            + np.outer(1 - np.cos(phi), n) * (s @ n)[:, None]
        )
    assert np.abs(out[:, -1] - s / np.linalg.norm(s, axis=-1, keepdims=True)).max() <= 1e-13


def test_rotate_stages_bad_shapes_refused():
    s0 = np.array([[0.0, 0.0, 1.0]])
    with pytest.raises(ValueError, match="expected parameters of shape"):
        rotate_stages(
            s0,
            np.ones((2, 3)),
            np.zeros(2),
            np.ones((2, 1)),
            np.ones((5, 2)),
            np.ones(2),
            1,
            np.empty((1, 2, 3)),
        )
    with pytest.raises(ValueError, match="expected normals, times and orbit factors"):
        rotate_stages(
            s0,
            np.ones((3, 3)),
            np.zeros(2),
            np.ones((2, 1)),
            np.ones((5, 1)),
            np.ones(2),
            1,
            np.empty((1, 2, 3)),
        )


def test_evolve_axes_many_models_equal_each_alone():
    rng = np.random.default_rng(7)
    s0 = default_axis("earth")
    models = [
        build_model(ORBIT, "earth", s0, float(r), None, float(t))
        for r, t in zip(rng.uniform(40, 60, 5), rng.uniform(0, 1.2, 5), strict=True)
    ]
    times = np.linspace(-2e4, 1e4, 7)
    axes, p = evolve_axes(ORBIT, models, times, s0)
    for i, model in enumerate(models):
        a1, p1 = evolve_axes(ORBIT, model, times, s0)
        assert np.abs(axes[i] - a1[0]).max() <= 1e-15
        assert np.abs(p[i] - p1[0]).max() <= 1e-12


def test_ensemble_chunks_equal_per_history_runs():
    orbit = VondrakEcliptic()
    times = np.array([-5000.0, -2000.0, 0.0])
    ds = run_ensemble(
        SpinParameterSampler("earth", precession_rate=(45.0, 55.0), tidal_dissipation=(0.0, 1.2)),
        6,
        times,
        propagator=SpinAxisPropagator(orbit, "earth"),
        chunk=3,
        output="euler",
        scheduler="synchronous",
        progress=False,
        seed=2,
    )
    s0 = default_axis("earth")
    for i in range(6):
        model = build_model(
            orbit, "earth", s0, float(ds.precession_rate[i]), None, float(ds.tidal_dissipation[i])
        )
        axes, p = evolve_axes(orbit, model, times, s0)
        obliquity = np.arccos(np.clip(np.sum(axes[0] * orbit.normal(times), -1), -1, 1))
        assert np.abs(ds.theta.values[i] - obliquity).max() <= 1e-12
        assert np.abs(ds.phi.values[i] - (np.pi - p[0])).max() <= 1e-12
