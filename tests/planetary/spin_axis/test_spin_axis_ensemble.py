"""Spin-axis ensembles over (precession rate, T_d): the runner's public entry point, Zarr, resume."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.ensemble import SpinAxisPropagator, SpinParameterSampler, chunk_rng, run_ensemble
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import spin_axis_history

TIMES = [-20000.0, -10000.0, 0.0, 5000.0]


def test_spin_ensemble_grid_matches_single_histories_and_resumes(tmp_path):
    sampler = SpinParameterSampler("earth", precession_rate=(49.0, 51.0), tidal_dissipation=(0.0, 1.0),
                                   grid=(3, 2))
    propagator = SpinAxisPropagator(VondrakEcliptic(), "earth")
    store = tmp_path / "spin.zarr"
    ds = run_ensemble(sampler, 6, TIMES, propagator=propagator, out=store, chunk=6, output="euler",
                      scheduler="synchronous", progress=False)
    rates = ds.precession_rate.values
    tides = ds.tidal_dissipation.values
    assert rates.tolist() == [49.0, 49.0, 50.0, 50.0, 51.0, 51.0]
    assert tides.tolist() == [0.0, 1.0] * 3
    for k in (0, 3, 5):
        h = spin_axis_history(VondrakEcliptic(), "earth", TIMES, precession_rate=rates[k],
                              tidal_dissipation=tides[k])
        assert np.abs(ds.theta.values[k] - h.obliquity).max() <= 1e-12
        phi = np.mod(ds.phi.values[k] - (np.pi - h.precession) + np.pi, 2 * np.pi) - np.pi
        assert np.abs(phi).max() <= 1e-11
    # a faster precession moves the equinox farther in 20 kyr; tides change the past obliquity
    assert ds.theta.values[0, 0] != ds.theta.values[1, 0]
    rerun = []
    again = run_ensemble(sampler, 6, TIMES, propagator=propagator, out=store, chunk=6, output="euler",
                         scheduler="synchronous", progress=False, on_chunk=rerun.append)
    assert rerun == []
    assert np.array_equal(again.theta.values, ds.theta.values)


def test_spin_sampler_uniform_draws_within_ranges():
    draw = SpinParameterSampler("mars", precession_rate=(7.5, 7.7)).sample(chunk_rng(3, 0), 50)
    rates = draw.parameters["precession_rate"]
    assert rates.min() >= 7.5
    assert rates.max() <= 7.7
    assert np.ptp(rates) > 0.1
    assert np.all(draw.parameters["tidal_dissipation"] == 0.0)


@pytest.mark.parametrize(
    ("kwargs", "n", "message"),
    [
        ({"grid": (3, 2)}, 6, "expected a grid with one positive size per varying parameter"),
        ({"precession_rate": (49.0, 51.0), "grid": (0,)}, 6, "one positive size"),
        ({"precession_rate": 50.0, "dynamical_ellipticity": 0.003}, 2, "got both"),
        ({"body": "venus"}, 2, "expected a body in earth, mars"),
    ],
)
def test_spin_sampler_rejects_bad_settings(kwargs, n, message):
    with pytest.raises(ValueError, match=message):
        SpinParameterSampler(**kwargs).sample(chunk_rng(0, 0), n)
