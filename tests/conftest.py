"""Shared fixtures: seeded random states and comparison helpers."""

from __future__ import annotations

import os
import stat
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import settings
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State, bodies
from andoyer.free import backends as free_backends

# Seeded like every other test: hypothesis draws the same examples on every run and machine.
settings.register_profile("andoyer", derandomize=True, deadline=None)
settings.load_profile("andoyer")

REGIME_BODIES = {
    "triaxial": RigidBody(0.7, 1.0, 1.3),
    "strongly-triaxial": RigidBody(0.229427, 0.963754, 1.0),
    "earth": bodies.get("earth"),
    "oblate": RigidBody(1.0, 1.0, 1.5),
    "prolate": RigidBody(0.5, 1.0, 1.0),
    "spherical": RigidBody(1.0, 1.0, 1.0),
}


def rotation_distance(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Angle (radians) of the rotation between two attitudes given as quaternions (..., 4)."""
    # |q1 - q2| = 2 sin(angle/4) for the nearer sign of q2: accurate for small angles, unlike acos.
    diff = np.minimum(np.linalg.norm(q1 - q2, axis=-1), np.linalg.norm(q1 + q2, axis=-1))
    return 4.0 * np.arcsin(np.clip(diff / 2.0, 0.0, 1.0))


def random_states(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Uniform random attitudes and momenta with |m| spread over decades."""
    q = Rotation.random(n, rng=rng).as_quat()
    m = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1))
    return q, m


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261121)


# --- ensembles (tests/ensemble) ---


@pytest.fixture(scope="module")
def loopback_cluster():
    """Two single-threaded workers in this process, scheduler on 127.0.0.1 at a random port (TCP).

    Module-scoped: the cluster's threads draw from the global ``random`` module, which
    hypothesis (rightly) reports as flaky data generation if they outlive the ensemble tests.
    """
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


# --- command-line outputs (tests/cli/test_cli_*.py) ---


def _make_device(path) -> None:
    """A character device at ``path``: a copy of /dev/full's node where allowed (root), else a link.

    A regression of the output checks must damage this copy, never the machine's /dev/full: as
    root, the code of issue 18 replaced the system's node with a regular file. Without the right
    to make nodes, a link to /dev/full is as good, and the system's node is out of reach anyway.
    """
    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 7))
    except PermissionError:
        path.symlink_to("/dev/full")


@pytest.fixture
def make_device():
    """The function that makes a character device at a path (see :func:`_make_device`)."""
    return _make_device


# --- the command line, in process ---


@pytest.fixture
def run_cli(capsys):
    """Run ``andoyer ARGV`` in this process: ``run_cli(*argv) -> (exit code, stdout, stderr)``."""
    from andoyer.cli import main

    def run(*argv):
        try:
            code = main(list(argv))
        except SystemExit as exc:  # argparse's own errors exit from parse_args
            code = exc.code
        out, err = capsys.readouterr()
        return code, out, err

    return run


# --- the free solution's backends (tests/free; the drivers in tests/free/free_backends.py) ---
# Here rather than in tests/free/conftest.py: a second module named conftest would replace this
# one for every test that imports its helpers with ``from conftest import ...``.
# The helpers of tests/free (free_backends, free_cases, free_reference) serve its subfolders
# too (tests/free/triaxial, ...), whichever test is collected first.
if str(Path(__file__).parent / "free") not in sys.path:
    sys.path.append(str(Path(__file__).parent / "free"))

_MOTION_BACKENDS = [b for b in free_backends.available() if b in free_backends.MOTION_BACKENDS]


@pytest.fixture(scope="session", params=free_backends.available())
def free_backend(request):
    """Every available backend of the free solution (``compiled`` with numba, ``numpy``, ``scalar``).

    A ``free_backends.Backend``: the flow ``(m(t), q(t))`` from initial states, the one thing
    the scalar backend computes, so only for tests of the flow on states off the separatrix
    (which the scalar kernel refuses), in units where its squares neither overflow nor
    underflow, near the separatrix over short steps only and elsewhere over at most ten
    periods (``Backend.times``, ``Backend.step_error``); see ``tests/free/free_backends.py``.
    A test that applies to only some backends parametrises it itself
    (``indirect=["free_backend"]``, e.g. with ``free_backends.pairs``).
    """
    from free_backends import Backend  # tests/free is on the path of the tests that use it

    return Backend(request.param)


@pytest.fixture(scope="session", params=_MOTION_BACKENDS)
def motion_backend(request) -> str:
    """Every available backend of ``FreeMotion`` (``compiled`` with numba, ``numpy``), by name.

    For ``FreeMotion(..., backend=motion_backend)`` in the tests of what only ``FreeMotion``
    offers: periods, regime, the separatrix, layouts, extreme units, the periodic representation.
    """
    return request.param


@pytest.fixture(scope="session")
def reference():
    """``reference(name, k)``: the 57-digit solution of a case of ``tests/free/free_cases.py``.

    At ``k`` of the case's time units, integrated once per case and time for the session
    (``free_reference.References``).
    """
    from free_cases import cases
    from free_reference import References

    return References(cases())
