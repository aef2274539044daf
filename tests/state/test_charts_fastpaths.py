"""The three paths of the Euler and Andoyer conversions: scalar kernel, compiled loop, numpy.

One state goes through the scalar kernel of ``andoyer.state._kernels`` in plain Python, an
array through the same kernel compiled by numba, or, without numba, through the same kernel
on whole numpy arrays (``_compiled.NUMBA`` switched off here forces it). The kernel and the
compiled loop must agree bit for bit; the numpy path within 2 ulp of the scale of each
quantity (2π for angles, ``G`` for momenta, 1 for quaternions); and all of them with
scipy's ``Rotation`` for the attitude and with Gurfil's momenta, computed here.
"""

from __future__ import annotations

import os
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer import SingularChartWarning, State
from andoyer.state import _compiled
from andoyer.state.euler import COMPILED_MIN
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
    # numba is a test dependency: the compiled path is the one measured in benchmarks/ (the
    # suite also runs under ANDOYER_NUMBA=0, where the loops stay Python).
    switched_off = os.environ.get("ANDOYER_NUMBA", "1") == "0"
    assert _compiled.NUMBA is not switched_off
    assert hasattr(_compiled._hub_to_euler_loop, "py_func") == _compiled.NUMBA


def angle_ulps(a: np.ndarray, b: np.ndarray) -> float:
    """Largest difference of angles on the circle, in ulp of 2π."""
    d = np.abs(np.asarray(a) - np.asarray(b))
    return float((np.minimum(d, 2 * np.pi - d) / ULP_2PI).max())


def momentum_ulps(a: np.ndarray, b: np.ndarray, G: np.ndarray) -> float:
    """Largest difference of momenta as an angle at the lever arm ``G``, in ulp of 2π."""
    return float((np.abs(np.asarray(a) - np.asarray(b)) / (G * ULP_2PI)).max())


def singular_counts(record: list[warnings.WarningMessage]) -> dict[str, int]:
    """States per singular-chart message, summed over the warnings."""
    counts: dict[str, int] = {}
    for w in record:
        count, message = str(w.message).split(" state(s) on a chart singularity: ")
        counts[message] = counts.get(message, 0) + int(count)
    return counts


def hub_to_charts(q: np.ndarray, m: np.ndarray, counts: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Euler (6, n) and Andoyer (6, n) variables of the states; ``counts`` gets the singular warnings."""
    state = State.from_quaternion(q, m)
    with warnings.catch_warnings(record=True) as record:
        warnings.simplefilter("always", SingularChartWarning)
        out = np.array(state.as_euler()), np.array(state.as_andoyer())
    if counts is not None:
        counts.update(singular_counts(record))
    return out


def one_by_one(q: np.ndarray, m: np.ndarray, counts: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The same, one state at a time."""
    with warnings.catch_warnings(record=True) as record:
        warnings.simplefilter("always", SingularChartWarning)
        states = [State.from_quaternion(q[i], m[i]) for i in range(len(q))]
        out = (
            np.array([np.array(s.as_euler()) for s in states]).T,
            np.array([np.array(s.as_andoyer()) for s in states]).T,
        )
    if counts is not None:
        counts.update(singular_counts(record))
    return out


def assert_charts_close(a: tuple[np.ndarray, ...], b: tuple[np.ndarray, ...], G: np.ndarray) -> None:
    for x, y in zip(a, b, strict=True):
        assert angle_ulps(x[:3], y[:3]) <= 2
        assert momentum_ulps(x[3:], y[3:], G) <= 2
    # ψ = 0 exactly where θ = 0 or π: the Euler chart's convention, on the same states
    (euler_a, _), (euler_b, _) = a, b
    on_a, on_b = np.isin(euler_a[1], (0.0, np.pi)), np.isin(euler_b[1], (0.0, np.pi))
    assert np.array_equal(on_a, on_b)
    assert np.all(euler_a[2][on_a] == 0)
    assert np.all(euler_b[2][on_b] == 0)


def test_single_state_equals_compiled_array_bitwise_hub_to_charts(rng):
    # The compiled loop runs the single state's kernel: the same bits.
    q, m = edge_states(rng, COMPILED_MIN + 500)
    counts_one, counts_many = {}, {}
    single, arrays = one_by_one(q, m, counts_one), hub_to_charts(q, m, counts_many)
    if _compiled.NUMBA:
        for one, many in zip(single, arrays, strict=True):
            assert np.array_equal(one, many)
    else:  # ANDOYER_NUMBA=0: the arrays go through numpy's functions
        assert_charts_close(single, arrays, np.linalg.norm(m, axis=-1))
    assert counts_one == counts_many
    assert len(counts_one) == 3  # θ = 0 or π, sin J = 0, sin I = 0 all met


def test_single_state_agrees_with_numpy_array_path_hub_to_charts(rng, monkeypatch):
    q, m = edge_states(rng, 2000)
    monkeypatch.setattr(_compiled, "NUMBA", False)
    counts_one, counts_many = {}, {}
    charts = one_by_one(q, m, counts_one), hub_to_charts(q, m, counts_many)
    assert_charts_close(*charts, np.linalg.norm(m, axis=-1))
    assert counts_one == counts_many


def test_numpy_path_agrees_with_compiled_hub_to_charts(rng, monkeypatch):
    # The numpy path runs the same kernels on whole arrays: the fallback without numba.
    q, m = edge_states(rng, 20_000)
    counts_compiled, counts_numpy = {}, {}
    compiled = hub_to_charts(q, m, counts_compiled)
    monkeypatch.setattr(_compiled, "NUMBA", False)
    assert_charts_close(compiled, hub_to_charts(q, m, counts_numpy), np.linalg.norm(m, axis=-1))
    assert counts_compiled == counts_numpy


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
    if _compiled.NUMBA:
        assert np.array_equal(np.array([s.quaternion for s in ones]), compiled.quaternion[:400])
        assert np.array_equal(np.array([s.m_body for s in ones]), compiled.m_body[:400])
    else:  # ANDOYER_NUMBA=0: the arrays go through numpy's functions
        assert angle_ulps(np.array([s.quaternion for s in ones]), compiled.quaternion[:400]) <= 2
        assert momentum_ulps(np.array([s.m_body for s in ones]), compiled.m_body[:400], G[:400, None]) <= 2
    assert angle_ulps(plain.quaternion, compiled.quaternion) <= 2
    assert momentum_ulps(plain.m_body, compiled.m_body, G[:, None]) <= 2


def test_small_arrays_take_numpy_path(rng, monkeypatch):
    q, m = random_states(rng, COMPILED_MIN - 1)
    small = hub_to_charts(q, m)
    monkeypatch.setattr(_compiled, "NUMBA", False)
    for x, y in zip(small, hub_to_charts(q, m), strict=True):
        assert np.array_equal(x, y)


def test_single_state_fields_are_numpy_scalars():
    s = State.from_euler(0.1, 0.5, 0.2, 1.0, 0.3, 0.8)
    assert s.shape == ()
    for chart in (s.as_euler(), s.as_andoyer()):
        assert all(isinstance(v, np.float64) and v.shape == () for v in chart)


def scipy_reference(q: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Euler and Andoyer variables from scipy's ZXZ angles and Gurfil's momenta (eqs. 25-32, 83-88)."""
    rot = Rotation.from_quat(q)
    phi, theta, psi = np.mod(rot.as_euler("ZXZ"), 2 * np.pi).T
    M = rot.apply(m)  # reference components
    m1, m2, m3 = m.T
    Theta = m1 * np.cos(psi) - m2 * np.sin(psi)  # eq. 41
    G = np.linalg.norm(m, axis=-1)
    g = np.arctan2(-G * Theta * np.sin(theta), m3 * M[:, 2] - G * G * np.cos(theta))
    l, h = np.arctan2(m1, m2), np.arctan2(M[:, 0], -M[:, 1])
    wrap = lambda a: np.mod(a, 2 * np.pi)  # noqa: E731
    return (
        np.array([phi, theta, psi, M[:, 2], Theta, m3]),
        np.array([wrap(l), wrap(g), wrap(h), m3, G, M[:, 2]]),
    )


@pytest.mark.parametrize("path", ["single", "compiled", "numpy"])
def test_conversions_agree_with_scipy_and_gurfil(rng, monkeypatch, path):
    q, m = random_states(rng, 400 if path == "single" else 20_000)
    rot = Rotation.from_quat(q)
    # away from the charts' singularities, where angles are well conditioned
    keep = (np.sin(rot.as_euler("ZXZ")[:, 1]) > 1e-3) & (np.abs(m[:, 2]) < 0.999 * np.linalg.norm(m, axis=-1))
    keep &= np.abs(rot.apply(m)[:, 2]) < 0.999 * np.linalg.norm(m, axis=-1)
    q, m = q[keep], m[keep]
    G = np.linalg.norm(m, axis=-1)
    if path == "numpy":
        monkeypatch.setattr(_compiled, "NUMBA", False)
    ours = one_by_one(q, m) if path == "single" else hub_to_charts(q, m)
    reference = scipy_reference(q, m)
    euler, andoyer = ours
    euler_ref, andoyer_ref = reference
    assert angle_ulps(euler[:3], euler_ref[:3]) <= 2
    assert momentum_ulps(euler[3:], euler_ref[3:], G) <= 2
    assert momentum_ulps(andoyer[3:], andoyer_ref[3:], G) <= 2
    assert angle_ulps(andoyer[[0, 2]], andoyer_ref[[0, 2]]) <= 8  # the reference rotates m first
    # g's reference, atan2(-G Θ sin θ, L H - G² cos θ), loses digits to cancellation (measured: 19 ulp)
    assert angle_ulps(andoyer[1], andoyer_ref[1]) <= 64


BAD_EULER = [
    (np.nan, 0.5, 0.2, 1.0, 0.3, 0.8),
    (0.1, np.inf, 0.2, 1.0, 0.3, 0.8),
    (0.1, -0.1, 0.2, 1.0, 0.3, 0.8),
    (0.1, 4.0, 0.2, 1.0, 0.3, 0.8),
    (0.1, 0.5, 0.2, 1.0, 0.3, -np.inf),
    (0.0, 0.0, 0.0, 1.0, 0.0, 0.5),  # Φ ≠ Ψ at θ = 0: infinite momentum
    (0.0, 0.5, 0.0, 1e308, 0.0, 0.0),  # the momentum overflows
]
BAD_ANDOYER = [
    (np.nan, 0.2, 0.3, 0.5, 1.0, 0.5),
    (0.1, 0.2, 0.3, 0.5, np.inf, 0.5),
    (0.1, 0.2, 0.3, 0.0, 0.0, 0.0),
    (0.1, 0.2, 0.3, 0.5, -1.0, 0.5),
    (0.1, 0.2, 0.3, 1.5, 1.0, 0.5),
    (0.1, 0.2, 0.3, 0.5, 1.0, -2.0),
]


@pytest.mark.parametrize(
    ("build", "values"),
    [(State.from_euler, v) for v in BAD_EULER] + [(State.from_andoyer, v) for v in BAD_ANDOYER],
)
def test_single_state_rejects_bad_input_as_arrays_do(build, values):
    with pytest.raises(ValueError, match=r"^expected") as single:
        build(*values)
    # (numpy's overflow warning on the way to the overflow's ValueError is not the point here)
    with pytest.raises(ValueError, match=r"^expected") as array, np.errstate(all="ignore"):
        build(*([v] for v in values))
    assert str(single.value) == str(array.value)


def test_zero_momentum_has_no_andoyer_chart_every_path():
    large = np.ones((COMPILED_MIN, 3))
    large[-1] = 0.0
    for m in ([0.0, 0.0, 0.0], [[0.0, 0.0, 0.0]], large):
        with pytest.raises(ValueError, match=r"expected a non-zero angular momentum, got \|m\| = 0"):
            State.from_quaternion([0.0, 0.0, 0.0, 1.0], m).as_andoyer()


def test_single_state_accepts_momenta_within_round_off_of_the_poles():
    G = 3.0
    L = G * (1 + 2 * np.finfo(float).eps)  # |L| - G within the 4ε G slack: clipped to G
    with pytest.warns(SingularChartWarning, match="sin\\(J\\) = 0"):
        a = State.from_andoyer(0.1, 0.2, 0.3, L, G, 1.0).as_andoyer()
    assert a.L == G
    assert np.array_equal(State.from_andoyer(0.1, 0.2, 0.3, L, G, 1.0).m_body, [0.0, 0.0, G])


CONVERSIONS = {
    "as_euler, theta = 0": (lambda s: s.as_euler(), ([0.0, 0.0, 0.3, 1.0], [0.3, 0.2, 1.0]), "psi = 0"),
    "as_andoyer, sin J = 0": (lambda s: s.as_andoyer(), ([0.1, 0.2, 0.3, 1.0], [0.0, 0.0, 2.0]), "l = 0"),
    "as_andoyer, sin I = 0": (lambda s: s.as_andoyer(), ([0.0, 0.0, 0.6, 0.8], [0.0, 0.0, -2.0]), "h = 0"),
}


@pytest.mark.parametrize("shape", [(), (1,), (3,)])
@pytest.mark.parametrize("case", list(CONVERSIONS))
def test_singular_warning_same_text_and_caller_every_path(case, shape):
    convert, (q, m), what = CONVERSIONS[case]
    q = np.broadcast_to(np.array(q) / np.linalg.norm(q), (*shape, 4))
    state = State.from_quaternion(q, np.broadcast_to(m, (*shape, 3)))
    count = int(np.prod(shape))
    with pytest.warns(SingularChartWarning, match=f"^{count} state\\(s\\) on a chart singularity") as record:
        convert(state)
    assert all(r.filename == __file__ for r in record)
    assert any(what in str(r.message) for r in record)


@pytest.mark.parametrize("theta", [0.0, np.pi])
@pytest.mark.parametrize("shape", [(), (2,)])
def test_from_euler_singular_warning_every_path(theta, shape):
    values = [np.full(shape, v) if shape else v for v in (0.2, theta, 0.4, np.cos(theta), 0.3, 1.0)]
    with pytest.warns(SingularChartWarning, match="was set to 0") as record:
        state = State.from_euler(*values)
    assert record[0].filename == __file__
    # X = 0 there: m = (Θ cos ψ, -Θ sin ψ, Ψ)
    expected = [0.3 * np.cos(0.4), -0.3 * np.sin(0.4), 1.0]
    assert np.abs(state.m_body - expected).max() <= 2 * np.spacing(1.0)


def test_conversions_without_numba_match_numpy_path_in_process(rng, monkeypatch, tmp_path):
    # ANDOYER_NUMBA=0 (as where numba is not installed), read at import in a fresh interpreter.
    q, m = random_states(rng, COMPILED_MIN + 10)
    np.save(tmp_path / "q.npy", q)
    np.save(tmp_path / "m.npy", m)
    script = (
        "import sys, numpy as np\n"
        "from andoyer import State\n"
        "from andoyer.state import _compiled\n"
        "assert not _compiled.NUMBA\n"
        f"d = {str(tmp_path)!r}\n"
        "s = State.from_quaternion(np.load(d + '/q.npy'), np.load(d + '/m.npy'))\n"
        "e, a = np.array(s.as_euler()), np.array(s.as_andoyer())\n"
        "back = State.from_euler(*e), State.from_andoyer(*a)\n"
        "np.save(d + '/out.npy', np.concatenate([e, a, *(b.quaternion.T for b in back)]))\n"
    )
    env = {**os.environ, "ANDOYER_NUMBA": "0"}
    subprocess.run([sys.executable, "-c", script], check=True, env=env, timeout=120)
    monkeypatch.setattr(_compiled, "NUMBA", False)
    s = State.from_quaternion(q, m)
    e, a = np.array(s.as_euler()), np.array(s.as_andoyer())
    back = State.from_euler(*e), State.from_andoyer(*a)
    expected = np.concatenate([e, a, *(b.quaternion.T for b in back)])
    assert np.array_equal(np.load(tmp_path / "out.npy"), expected)


@settings(max_examples=150, deadline=None)
@given(
    q=st.lists(st.floats(-1, 1, allow_nan=False), min_size=4, max_size=4).filter(
        lambda v: np.linalg.norm(v) > 0.1
    ),
    m=st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=3, max_size=3).filter(
        lambda v: np.linalg.norm(v) > 1e-6
    ),
)
def test_single_state_agrees_with_array_path_hypothesis(q, m):
    # Any state, on or near the singular charts too: the scalar kernel against numpy's path.
    q = np.asarray(q) / np.linalg.norm(q)
    m = np.asarray(m, dtype=float)
    G = np.linalg.norm(m)
    counts_one, counts_many = {}, {}
    single = one_by_one(q[None], m[None], counts_one)
    assert_charts_close(single, hub_to_charts(q[None], m[None], counts_many), G)
    assert counts_one == counts_many
    euler, andoyer = single
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularChartWarning)
        for chart, build in ((euler, State.from_euler), (andoyer, State.from_andoyer)):
            one, many = build(*map(float, chart[:, 0])), build(*chart)
            assert angle_ulps(one.quaternion, many.quaternion[0]) <= 2
            assert momentum_ulps(one.m_body, many.m_body[0], G) <= 2


@pytest.mark.parametrize("path", ["compiled", "numpy"])
def test_from_euler_singular_arrays_every_path(rng, monkeypatch, path):
    if path == "numpy":
        monkeypatch.setattr(_compiled, "NUMBA", False)
    n = COMPILED_MIN + 1
    phi, psi, Theta, Psi = rng.uniform(0, 2 * np.pi, (2, n)).tolist() + rng.normal(size=(2, n)).tolist()
    theta = rng.uniform(0, np.pi, n)
    theta[:7], theta[7:10] = 0.0, np.pi  # on the singularity, with Φ = Ψ cos θ
    Phi = np.asarray(Psi) * np.cos(theta) + rng.normal(size=n) * (np.arange(n) >= 10)
    with pytest.warns(SingularChartWarning, match=r"^10 state\(s\).*was set to 0") as record:
        state = State.from_euler(phi, theta, psi, Phi, Theta, Psi)
    assert record[0].filename == __file__
    expected = np.stack([np.asarray(Theta) * np.cos(psi), -np.asarray(Theta) * np.sin(psi), Psi], -1)[:10]
    assert np.abs(state.m_body[:10] - expected).max() <= 2 * np.spacing(np.abs(expected).max())
    Phi[3] += 1.0  # Φ ≠ Ψ cos θ at θ = 0: infinite momentum
    with pytest.raises(ValueError, match=r"expected Phi = Psi cos\(theta\) where sin\(theta\) = 0"):
        State.from_euler(phi, theta, psi, Phi, Theta, Psi)
