"""The three paths of the Euler and Andoyer conversions: scalar kernel, compiled loop, numpy.

One state goes through the scalar kernel of ``andoyer.charts._kernels`` in plain Python, an
array through the same kernel compiled by numba, or, without numba, through the numpy
expressions that the conversions had before (``_compiled.NUMBA`` switched off here forces
them). The kernel and the compiled loop must agree bit for bit; the numpy path within 2 ulp
of the scale of each quantity (2π for angles, ``G`` for momenta, 1 for quaternions); and all
of them with scipy's ``Rotation`` for the attitude and with Gurfil's momenta, computed here.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import SingularChartWarning, State
from andoyer.charts import _compiled
from conftest import random_states

ULP_2PI = np.spacing(2 * np.pi)


def edge_states(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Random states; an eighth each within 1e-17 .. 1e-8 of (or on) θ = 0, θ = π, sin J = 0, sin I = 0."""
    q, m = random_states(rng, n)
    k = n // 8
    tiny = 10.0 ** rng.uniform(-17, -8, size=(k, 1))
    tiny[:3] = 0.0  # exactly on the singularity
    for block, (a, b) in enumerate([(0, 1), (2, 3)]):  # sin(θ/2) or cos(θ/2) small: θ near 0 or π
        rows = slice(block * k, (block + 1) * k)
        q[rows, a] *= tiny[:, 0]
        q[rows, b] *= tiny[:, 0]
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    rows = slice(2 * k, 3 * k)  # m near the body axis b3: sin J small
    m[rows, :2] *= tiny
    rows = slice(3 * k, 4 * k)  # m near the reference axis s3 (γ in the body): sin I small
    gamma = Rotation.from_quat(q[rows]).as_matrix()[:, 2, :]
    G = np.linalg.norm(m[rows], axis=-1, keepdims=True)
    m[rows] = G * gamma + G * tiny * rng.normal(size=(k, 3))
    return q, m


def test_compiled_kernel_present():
    # numba is a test dependency: the compiled path is the one measured in benchmarks/.
    assert _compiled.NUMBA
    assert hasattr(_compiled._hub_to_euler_one, "py_func")


def angle_ulps(a: np.ndarray, b: np.ndarray) -> float:
    """Largest difference of angles on the circle, in ulp of 2π."""
    d = np.abs(np.asarray(a) - np.asarray(b))
    return float((np.minimum(d, 2 * np.pi - d) / ULP_2PI).max())


def momentum_ulps(a: np.ndarray, b: np.ndarray, G: np.ndarray) -> float:
    """Largest difference of momenta as an angle at the lever arm ``G``, in ulp of 2π."""
    return float((np.abs(np.asarray(a) - np.asarray(b)) / (G * ULP_2PI)).max())


def hub_to_charts(q: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Euler (6, n) and Andoyer (6, n) variables of the states, singular ones included."""
    state = State.from_quaternion(q, m)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularChartWarning)
        return np.array(state.as_euler()), np.array(state.as_andoyer())


def one_by_one(q: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularChartWarning)
        states = [State.from_quaternion(q[i], m[i]) for i in range(len(q))]
        return (
            np.array([np.array(s.as_euler()) for s in states]).T,
            np.array([np.array(s.as_andoyer()) for s in states]).T,
        )


def assert_charts_close(a: tuple[np.ndarray, ...], b: tuple[np.ndarray, ...], G: np.ndarray) -> None:
    for x, y in zip(a, b, strict=True):
        assert angle_ulps(x[:3], y[:3]) <= 2
        assert momentum_ulps(x[3:], y[3:], G) <= 2
        # the singular conventions (ψ = 0, l = 0, h = 0) hold for the same states
        assert np.array_equal(x[:3] == 0, y[:3] == 0)


@pytest.mark.parametrize("path", ["compiled", "numpy"])
def test_single_state_agrees_with_array_path_hub_to_charts(rng, monkeypatch, path):
    # The compiled loop runs the single state's kernel; LLVM's code for the loop may round
    # a product or an elementary function differently (measured: within 1.2 ulp of 2π).
    q, m = edge_states(rng, 2000)
    if path == "numpy":
        monkeypatch.setattr(_compiled, "NUMBA", False)
    assert_charts_close(one_by_one(q, m), hub_to_charts(q, m), np.linalg.norm(m, axis=-1))


def test_numpy_path_agrees_with_compiled_hub_to_charts(rng, monkeypatch):
    # The numpy path is the implementation before the compiled kernels, kept as the fallback.
    q, m = edge_states(rng, 20_000)
    compiled = hub_to_charts(q, m)
    monkeypatch.setattr(_compiled, "NUMBA", False)
    assert_charts_close(compiled, hub_to_charts(q, m), np.linalg.norm(m, axis=-1))


@pytest.mark.parametrize("chart", ["euler", "andoyer"])
def test_all_paths_agree_charts_to_hub(rng, monkeypatch, chart):
    q, m = random_states(rng, 3000)
    G = np.linalg.norm(m, axis=-1)
    variables = hub_to_charts(q, m)[0 if chart == "euler" else 1]
    build = State.from_euler if chart == "euler" else State.from_andoyer
    compiled = build(*variables)
    ones = [build(*map(float, variables[:, i])) for i in range(400)]
    monkeypatch.setattr(_compiled, "NUMBA", False)
    plain = build(*variables)
    for other, k in ((plain, slice(None)), (ones, slice(0, 400))):
        q_other = other.quaternion if isinstance(other, State) else np.array([s.quaternion for s in other])
        m_other = other.m_body if isinstance(other, State) else np.array([s.m_body for s in other])
        assert angle_ulps(q_other, compiled.quaternion[k]) <= 2
        assert momentum_ulps(m_other, compiled.m_body[k], G[k, None]) <= 2


def test_single_state_fields_are_numpy_scalars():
    s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    assert s.shape == ()
    for chart in (s.as_euler(), s.as_andoyer()):
        assert all(isinstance(v, np.float64) and v.shape == () for v in chart)
