"""A Dask cluster on loopback shared by the ensemble tests, and the documented sampling rule."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import State


@pytest.fixture(scope="session")
def loopback_cluster():
    """Two single-threaded workers in this process, scheduler on 127.0.0.1 at a random port (TCP)."""
    from distributed import LocalCluster

    with LocalCluster(
        n_workers=2,
        threads_per_worker=1,
        processes=False,
        protocol="tcp://",
        host="127.0.0.1",
        scheduler_port=0,
        dashboard_address="127.0.0.1:0",  # the HTTP server always starts; 8787 may be taken (a warning)
    ) as cluster:
        yield cluster


def documented_andoyer_samples(seed, index, n, G=(1.0, 1.0), cos_J=(-1.0, 1.0), cos_I=(-1.0, 1.0)):
    """The sampling rule as the documentation states it, written out independently of the sampler."""
    rng = np.random.default_rng(np.random.SeedSequence(seed).spawn(index + 1)[index])
    u = rng.random((n, 6))
    two_pi = 2.0 * np.pi
    l, g, h = two_pi * u[:, 0], two_pi * u[:, 1], two_pi * u[:, 2]
    Gs = G[0] + (G[1] - G[0]) * u[:, 3]
    L = Gs * (cos_J[0] + (cos_J[1] - cos_J[0]) * u[:, 4])
    H = Gs * (cos_I[0] + (cos_I[1] - cos_I[0]) * u[:, 5])
    return State.from_andoyer(l, g, h, L, Gs, H)
