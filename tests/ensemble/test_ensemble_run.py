"""Ensembles equal the direct free-flow call, on every scheduler, for any number of workers."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.ensemble import (
    AndoyerSampler,
    FreePropagator,
    InertiaSampler,
    MomentumSampler,
    run_ensemble,
)
from conftest import documented_andoyer_samples

EROS = bodies.get("eros")
TIMES = np.array([0.0, 0.37, 5.0, -12.5, 1.0e4])


def direct_states(body, seed, n, chunk, times, **ranges):
    """FreeRotation(body).propagate on the documented samples, one State per chunk."""
    return [
        FreeRotation(body).propagate(
            documented_andoyer_samples(seed, k, min(chunk, n - s), **ranges)[:, None], times
        )
        for k, s in enumerate(range(0, n, chunk))
    ]


def direct(body, seed, n, chunk, times, **ranges):
    """The direct call's quaternions and momenta, concatenated over the chunks."""
    parts = direct_states(body, seed, n, chunk, times, **ranges)
    # plain arrays: a State built from them would renormalise the quaternions (an ulp)
    return np.concatenate([p.quaternion for p in parts]), np.concatenate([p.m_body for p in parts])


@pytest.mark.parametrize("where", ["synchronous", "loopback", "loopback-1-worker-chunks-of-1"])
def test_ensemble_equals_direct_call_bitwise(where, loopback_cluster):
    n, chunk, seed = 23, 5, 11
    scheduler = "synchronous" if where == "synchronous" else loopback_cluster.scheduler_address
    if where.endswith("chunks-of-1"):
        chunk = 1
    ds = run_ensemble(
        AndoyerSampler(), n, TIMES, body=EROS, chunk=chunk, seed=seed, scheduler=scheduler, progress=False
    )
    q, m = direct(EROS, seed, n, chunk, TIMES)
    assert ds.quaternion.dims == ("sample", "time", "quaternion_component")
    np.testing.assert_array_equal(ds.quaternion.values, q)
    np.testing.assert_array_equal(ds.m_body.values, m)
    np.testing.assert_array_equal(ds.time.values, TIMES)
    initial = np.concatenate(
        [
            documented_andoyer_samples(seed, k, min(chunk, n - s)).m_body
            for k, s in enumerate(range(0, n, chunk))
        ]
    )
    np.testing.assert_array_equal(ds.m_body0.values, initial)


def test_ensemble_same_numbers_for_any_worker_count(loopback_cluster):
    kwargs = {"body": EROS, "chunk": 4, "seed": 3, "progress": False}
    one = run_ensemble(MomentumSampler(), 17, TIMES, scheduler="synchronous", **kwargs)
    two = run_ensemble(MomentumSampler(), 17, TIMES, scheduler=loopback_cluster.scheduler_address, **kwargs)
    np.testing.assert_array_equal(one.quaternion.values, two.quaternion.values)
    np.testing.assert_array_equal(one.m_body.values, two.m_body.values)


@pytest.mark.parametrize(
    "processes",
    [False, pytest.param(True, marks=pytest.mark.slow)],  # spawning worker processes takes 5-25 s here
)
def test_ensemble_default_local_cluster(processes, tmp_path):
    # The default path: a distributed.LocalCluster of two workers, closed at the end.
    ds = run_ensemble(
        AndoyerSampler(),
        9,
        TIMES,
        body=EROS,
        chunk=4,
        seed=5,
        n_workers=2,
        processes=processes,
        out=tmp_path / "e.zarr",
        progress=False,
    )
    q, m = direct(EROS, 5, 9, 4, TIMES)
    np.testing.assert_array_equal(ds.quaternion.values, q)
    np.testing.assert_array_equal(ds.m_body.values, m)


@pytest.mark.parametrize(("n_samples", "chunk", "n_workers", "cluster"), [(3, 4, 2, None), (9, 4, 8, 3)])
def test_ensemble_default_scheduler_starts_no_idle_workers(monkeypatch, n_samples, chunk, n_workers, cluster):
    # One chunk runs in this process (no cluster's start-up); fewer chunks than workers start one
    # worker per chunk. The numbers are those of the direct call either way.
    from andoyer.ensemble import runner

    started = []
    real_local_client = runner.local_client

    def recording(workers, processes):
        started.append(workers)
        return real_local_client(workers, processes)

    monkeypatch.setattr(runner, "local_client", recording)
    ds = run_ensemble(
        AndoyerSampler(), n_samples, TIMES, body=EROS, chunk=chunk, seed=5, n_workers=n_workers,
        processes=False, progress=False,
    )  # fmt: skip
    assert started == ([] if cluster is None else [cluster])
    q, m = direct(EROS, 5, n_samples, chunk, TIMES)
    np.testing.assert_array_equal(ds.quaternion.values, q)
    np.testing.assert_array_equal(ds.m_body.values, m)


def test_ensemble_scheduler_by_address_runs_there(loopback_cluster):
    prefixes = loopback_cluster.scheduler.task_prefixes
    before = (
        prefixes["andoyer_ensemble_chunk"].state_counts["memory"]
        if "andoyer_ensemble_chunk" in prefixes
        else 0
    )
    run_ensemble(
        AndoyerSampler(),
        10,
        TIMES,
        body=EROS,
        chunk=3,
        scheduler=loopback_cluster.scheduler_address,
        progress=False,
    )
    after = loopback_cluster.scheduler.task_prefixes["andoyer_ensemble_chunk"].state_counts["memory"]
    assert after - before == 4  # ceil(10 / 3) chunk tasks finished on that scheduler's workers


def test_ensemble_existing_client_is_used_and_left_open(loopback_cluster):
    from distributed import Client

    with Client(loopback_cluster.scheduler_address) as client:
        ds = run_ensemble(AndoyerSampler(), 4, TIMES, body=EROS, scheduler=client, progress=False)
        assert client.status == "running"
    assert ds.quaternion.shape == (4, TIMES.size, 4)


@pytest.mark.parametrize("output", ["andoyer", "euler"])
def test_ensemble_chart_outputs_match_state_conversion(output):
    kwargs = {"body": EROS, "chunk": 6, "seed": 2, "scheduler": "synchronous", "progress": False}
    ranges = {"cos_J": (-0.9, 0.9), "cos_I": (-0.9, 0.9)}  # away from the charts' singular sets
    ds = run_ensemble(AndoyerSampler(**ranges), 12, TIMES, output=output, **kwargs)
    states = direct_states(EROS, 2, 12, 6, TIMES, **ranges)
    charts = [s.as_andoyer() if output == "andoyer" else s.as_euler() for s in states]
    for name in charts[0]._fields:
        assert ds[name].dims == ("sample", "time")
        np.testing.assert_array_equal(ds[name].values, np.concatenate([getattr(c, name) for c in charts]))


def test_ensemble_inertia_sampler_moves_each_sample_with_its_own_body():
    sampler = InertiaSampler(AndoyerSampler(), low=(0.5, 0.8, 1.0), high=(0.7, 1.0, 1.3))
    ds = run_ensemble(
        sampler,
        8,
        TIMES,
        propagator=FreePropagator(),
        chunk=3,
        seed=4,
        scheduler="synchronous",
        progress=False,
    )
    moments = ds.moments.values
    assert ds.moments.dims == ("sample", "axis")
    assert np.all((moments >= [0.5, 0.8, 1.0]) & (moments <= [0.7, 1.0, 1.3]))
    for i in range(8):  # one FreeRotation per body: the scalar path, not the vectorised one
        s0 = State.from_quaternion(ds.quaternion0.values[i], ds.m_body0.values[i])
        ref = FreeRotation(RigidBody(*moments[i])).propagate(s0, TIMES)
        np.testing.assert_allclose(
            ds.m_body.values[i], ref.m_body, rtol=0, atol=1e-15 * np.abs(ref.m_body).max()
        )
        np.testing.assert_allclose(ds.quaternion.values[i], ref.quaternion, rtol=0, atol=1e-15)


def test_ensemble_custom_propagator_plugs_in(loopback_cluster):
    def frozen(state, times):  # a closure shipped to the workers by cloudpickle
        return State.from_quaternion(
            np.broadcast_to(state.quaternion[:, None], (state.size, times.size, 4)),
            np.broadcast_to(state.m_body[:, None], (state.size, times.size, 3)),
        )

    ds = run_ensemble(
        MomentumSampler(),
        7,
        [0.0, 1.0],
        propagator=frozen,
        chunk=2,
        scheduler=loopback_cluster.scheduler_address,
        progress=False,
    )
    np.testing.assert_array_equal(ds.m_body.values[:, 1], ds.m_body0.values)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"n_samples": 0}, "positive integer n_samples"),
        ({"chunk": 0}, "positive integer chunk"),
        ({"seed": -1}, "non-negative integer seed"),
        ({"times": []}, "non-empty one-dimensional array of finite times"),
        ({"times": [0.0, np.nan]}, "finite times"),
        ({"output": "sadov"}, "expected output in"),
        ({"propagator": FreePropagator(EROS)}, "exactly one of body= or propagator="),
        ({"out": "e.csv"}, r"ending in \.zarr or \.nc"),
        ({"scheduler": "nonsense"}, "reachable Dask scheduler"),
        ({"scheduler": None, "n_workers": 0}, "positive integer number of workers"),
    ],
)
def test_ensemble_bad_arguments_raise_one_message(kwargs, match):
    args = {"n_samples": 4, "times": [0.0, 1.0], "body": EROS, "scheduler": "synchronous", "progress": False}
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        run_ensemble(AndoyerSampler(), **args)


def test_ensemble_propagator_with_wrong_shape_is_reported():
    with pytest.raises(ValueError, match=r"expected the propagator to return a State of shape \(4, 2\)"):
        run_ensemble(
            AndoyerSampler(),
            4,
            [0.0, 1.0],
            propagator=lambda s, t: s,
            scheduler="synchronous",
            progress=False,
        )


@pytest.mark.slow  # spawns a worker process (5-25 s here)
def test_local_client_workers_are_quiet_and_keep_their_allocator():
    import os

    import dask

    from andoyer.ensemble import local_client
    from andoyer.ensemble.runner import QUIET_CLUSTER_CONFIG

    def worker_settings():
        return {key: dask.config.get(key) for key in QUIET_CLUSTER_CONFIG}, os.environ.get(
            "MALLOC_TRIM_THRESHOLD_"
        )

    with local_client(1) as client:
        ((settings, trim),) = client.run(worker_settings).values()
    # read back inside the spawned worker process: the nanny hands it the settings of local_client
    assert settings == QUIET_CLUSTER_CONFIG
    assert trim is None


def test_ensemble_default_chunk_is_about_two_to_the_18_pairs():
    from andoyer.ensemble.layout import EnsembleSpec

    for n_times in (1, 10, 37, 2**18, 2**19):
        spec = EnsembleSpec.build(AndoyerSampler(), FreePropagator(EROS), 10**7, np.zeros(n_times))
        assert spec.chunk == max(1, 2**18 // n_times)
