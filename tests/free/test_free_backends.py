"""The backends of the free solution: their names and errors, and that they agree in every regime.

Each backend (``compiled`` with numba, ``numpy``, ``scalar``; ``free_backends.py``) against the
57-digit Taylor reference of ``free_reference.py`` (the accuracy documented in
``test_free_accuracy.py``: 1e-13 in ``m``, 1e-12 rad), and against each other, over the regimes.
"""

import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest
from free_backends import AVAILABLE, Backend, pairs
from free_cases import cases
from free_reference import angle_between, relative_error
from scipy.spatial.transform import Rotation

from andoyer.free import FreeMotion, backends
from andoyer.free import step_scalar as lean
from andoyer.free.triaxial import evaluate_compiled as ceval
from andoyer.free.triaxial import evaluate_numpy as series
from andoyer.free.triaxial import periodic_numpy as periodic

BY_NAME = {c[0]: c for c in cases()}
M_TOL = 1e-13
Q_TOL = 1e-12

#: One case per regime (``free_cases.py``).
REGIMES = (
    "sam-0",
    "lam-1",
    "near-separatrix-lam-1e-10",
    "k2-above-half",  # the hyperbolic theta series
    "near-pure-spin",
    "oblate",
    "prolate",
    "sphere",
    "separatrix",  # FreeMotion's backends only: the scalar kernel refuses it
)
TIMES = (0.01, 0.37, 2.3)  # time units of the case: a short step, and a few periods


def _angle(qa, qb):
    rel = (Rotation.from_quat(qa).inv() * Rotation.from_quat(qb)).as_quat()
    return 2 * np.arctan2(np.linalg.norm(rel[..., :3], axis=-1), np.abs(rel[..., 3]))


def _run(backend, name):
    """``{k: (m, q)}`` of ``backend`` on case ``name`` at its times."""
    _, moments, m0, q0, t_unit = BY_NAME[name]
    times = backend.times(name, TIMES)
    assert times, (name, backend)
    m, q = backend.propagate(moments, m0, q0, [k * t_unit for k in times])
    return {k: (m[j], q[j]) for j, k in enumerate(times)}


@pytest.mark.parametrize(("name", "free_backend"), pairs(REGIMES), indirect=["free_backend"])
def test_backend_matches_the_reference_in_every_regime(name, free_backend, reference):
    for k, (m, q) in _run(free_backend, name).items():
        m_ref, q_ref = reference(name, k)
        assert relative_error(m_ref, m) <= M_TOL, (name, free_backend, k)
        assert angle_between(q_ref, q) <= Q_TOL, (name, free_backend, k)


def _applicable(name):
    return [b for b in AVAILABLE if not (b == "scalar" and name == "separatrix")]


# where two backends or more apply (the separatrix without numba has only numpy)
@pytest.mark.parametrize("name", [n for n in REGIMES if len(_applicable(n)) >= 2])
def test_backends_agree_with_each_other(name):
    _, _, m0, _, _ = BY_NAME[name]
    runs = {b: _run(Backend(b), name) for b in _applicable(name)}
    names = list(runs)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            common = runs[a].keys() & runs[b].keys()
            assert common, (a, b)
            for k in common:
                (ma, qa), (mb, qb) = runs[a][k], runs[b][k]
                assert np.linalg.norm(ma - mb) <= M_TOL * np.linalg.norm(m0), (name, a, b, k)
                assert _angle(qa, qb) <= Q_TOL, (name, a, b, k)


def test_scalar_kernel_refuses_the_separatrix():
    # P₂ = m₃²(1/B − 1/C) − m₁²(1/A − 1/B) = 0 exactly (free_cases.py): left to FreeMotion
    _, moments, m0, q0, _ = BY_NAME["separatrix"]
    m, q = np.array(m0), np.array(q0)
    assert not lean._step_one(np.array(moments), q, m, 1.0)
    with pytest.raises(AssertionError, match="refuses"):
        Backend("scalar").propagate(moments, m0, q0, 1.0)


# -- names, defaults, errors ----------------------------------------------------------------


def _numba_usable():
    """numba importable and not switched off: found independently of andoyer._jit."""
    return importlib.util.find_spec("numba") is not None and os.environ.get("ANDOYER_NUMBA", "1") != "0"


def test_backend_names_and_availability():
    assert backends.BACKENDS == ("compiled", "numpy", "scalar")
    assert backends.MOTION_BACKENDS == ("compiled", "numpy")
    want = ("compiled", "numpy", "scalar") if _numba_usable() else ("numpy", "scalar")
    assert backends.available() == want
    assert backends.default() == want[0]


def test_default_backend_is_the_fastest_available_and_unchanged():
    moments, m0 = [1.0, 2.0, 3.0], [0.3, 0.2, 1.0]
    q0 = [0.1, 0.2, 0.3, 0.9]
    fm = FreeMotion(moments, m0, q0)
    assert fm.backend == ("compiled" if _numba_usable() else "numpy")
    explicit = FreeMotion(moments, m0, q0, backend=fm.backend)
    t = np.linspace(-40.0, 40.0, 9)
    for got, want in zip(fm.propagate(t), explicit.propagate(t), strict=True):
        assert np.array_equal(got, want)


def test_backends_use_their_own_kernels():
    # the dispatch itself: each backend's triaxial groups and periodic fill
    rng = np.random.default_rng(3)
    moments, m0 = rng.uniform(1.0, 2.0, (8, 3)), rng.normal(size=(8, 3))
    q0 = Rotation.random(8, random_state=3).as_quat()
    kernels = {}
    for name in ("compiled", "numpy"):
        if name not in AVAILABLE:
            continue
        fm = FreeMotion(moments, m0, q0, backend=name)
        fm.periodic_epochs = 0.0
        fm.propagate(1.0)
        fills = {getattr(g.kernel, "fill", None) for g in fm._periodic[True]}
        kernels[name] = {g.kernel for g in fm._groups}, fills
    direct, fills = kernels["numpy"]
    assert direct == {series.evaluate}
    assert fills == {periodic.fill_numpy}
    assert FreeMotion(moments, m0, backend="numpy").periodic_epochs == np.inf
    if "compiled" in kernels:
        direct, fills = kernels["compiled"]
        assert direct == {ceval.evaluate}
        assert fills == {periodic.evaluate.fill}


@pytest.mark.parametrize(
    ("backend", "message"),
    [
        ("fortran", r"^expected backend one of 'compiled', 'numpy' \(or None.*\), got 'fortran'$"),
        ("Compiled", "got 'Compiled'"),
        (3, "got 3"),
        ("scalar", r"expected backend 'compiled' or 'numpy' for FreeMotion, got 'scalar'.*free_step"),
    ],
)
def test_bad_backend_raises(backend, message):
    with pytest.raises(ValueError, match=message):
        FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], backend=backend)


def test_compiled_backend_without_numba_raises():
    # a fresh interpreter with numba switched off, as an installation without it
    code = (
        "from andoyer.free import FreeMotion, backends\n"
        "print(backends.available(), FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0]).backend)\n"
        "FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0], backend='compiled')\n"
    )
    env = {**os.environ, "ANDOYER_NUMBA": "0"}
    command = [sys.executable, "-c", code]
    run = subprocess.run(command, check=False, env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 1
    assert run.stdout == "('numpy', 'scalar') numpy\n"
    last = run.stderr.strip().splitlines()[-1]
    assert last == (
        "ValueError: expected backend 'numpy' (or None), got 'compiled': the compiled backend needs numba, "
        "which is not installed or is switched off by ANDOYER_NUMBA=0"
    )
