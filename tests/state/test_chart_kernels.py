"""The Euler and Andoyer kernels, written once, give the same numbers on every path.

Each kernel of ``andoyer.state._kernels`` runs as written (Python, ``select`` called), as its
float copy (``*_floats``: each ``select`` a conditional expression), inside the compiled loops
of ``andoyer.state._compiled`` (numba; plain Python under ``ANDOYER_NUMBA=0``) and as its
array copy (``*_arrays``: numpy's functions). The first three must agree bit for bit, the
array copy within 2 ulp (numpy's ``sin``, ``cos``, ``arctan`` against the C library's); the
singular flags (θ = 0 or π, sin J = 0, sin I = 0) and the statuses of ``euler_to_hub`` exactly,
on states drawn in every regime and on or near every pole.
"""

from __future__ import annotations

import numpy as np
from hypothesis import example, given
from hypothesis import strategies as st

from andoyer.state import _compiled, _kernels

ULP_2PI = float(np.spacing(2 * np.pi))
ULP_1 = float(np.spacing(1.0))

REGIMES = ("generic", "theta near 0", "theta near pi", "sin J near 0", "sin I near 0")


@st.composite
def states(draw) -> tuple[list[float], list[float], str]:
    """A unit quaternion and a momentum, generic or within ``tiny`` (0 included) of a chart's pole."""
    regime = draw(st.sampled_from(REGIMES))
    tiny = draw(st.sampled_from([0.0, 1e-17, 1e-16, 4e-16, 1e-15, 1e-12, 1e-8]))
    q = np.array(draw(st.lists(st.floats(-1, 1), min_size=4, max_size=4)))
    if regime == "theta near 0":  # sin(θ/2) = |x, y| small
        q[:2] *= tiny
    elif regime == "theta near pi":  # cos(θ/2) = |z, w| small
        q[2:] *= tiny
    if np.linalg.norm(q) < 0.1:
        q[3] = 1.0
    q /= np.linalg.norm(q)
    G = 10.0 ** draw(st.floats(-6, 6))
    direction = np.array(draw(st.lists(st.floats(-1, 1), min_size=3, max_size=3)))
    if regime == "sin J near 0":  # m near the body axis b3
        direction[:2] *= tiny
    if regime == "sin I near 0":  # m near the reference axis s3, seen in the body: Rᵀ e3
        x, y, z, w = q
        gamma = np.array([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)])
        direction = draw(st.sampled_from([1.0, -1.0])) * gamma + tiny * direction
    if np.linalg.norm(direction) < 0.1:
        direction[2] = 1.0
    m = G * direction / np.linalg.norm(direction)
    return q.tolist(), m.tolist(), regime


def angle_ulps(a, b) -> float:
    d = np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float))
    return float((np.minimum(d, 2 * np.pi - d) / ULP_2PI).max())


def assert_same_bits(*results) -> None:
    first = [float(v) for v in results[0]]
    for other in results[1:]:
        assert [float(v) for v in other] == first


def arrays_of(values) -> list[np.ndarray]:
    return [np.array([v], dtype=float) for v in values]


@given(states())
def test_hub_to_euler_paths_agree_hypothesis(state):
    q, m, _ = state
    written = _kernels.hub_to_euler_one(*q, *m)
    floats = _kernels.hub_to_euler_floats(*q, *m)
    out, singular = _compiled.hub_to_euler(np.array([q]), np.array([m]))
    assert_same_bits(written, floats, [*out[:, 0], singular[0]])
    *arrays, singular_arrays = _kernels.hub_to_euler_arrays(*arrays_of(q), *arrays_of(m))
    assert bool(singular_arrays[0]) == floats[6]
    G = np.linalg.norm(m)
    assert angle_ulps([v[0] for v in arrays[:3]], floats[:3]) <= 2
    assert max(abs(float(a[0]) - b) for a, b in zip(arrays[3:], floats[3:6], strict=True)) <= 2 * ULP_2PI * G
    # the convention on the singularity: ψ = 0 and θ exactly 0 or π
    if floats[6]:
        assert floats[2] == 0.0
        assert floats[1] in (0.0, np.pi)


@given(states())
def test_hub_to_andoyer_paths_agree_hypothesis(state):
    q, m, _ = state
    written = _kernels.hub_to_andoyer_one(*q, *m)
    floats = _kernels.hub_to_andoyer_floats(*q, *m)
    out, on_pole_j, on_pole_i, zero = _compiled.hub_to_andoyer(np.array([q]), np.array([m]))
    assert zero == 0
    assert_same_bits(written, floats, [*out[:, 0], on_pole_j[0], on_pole_i[0]])
    *arrays, pole_j, pole_i = _kernels.hub_to_andoyer_arrays(*arrays_of(q), *arrays_of(m))
    assert (bool(pole_j[0]), bool(pole_i[0])) == floats[6:]
    G = np.linalg.norm(m)
    assert angle_ulps([v[0] for v in arrays[:3]], floats[:3]) <= 2
    assert max(abs(float(a[0]) - b) for a, b in zip(arrays[3:], floats[3:6], strict=True)) <= 2 * ULP_2PI * G
    # the conventions on the poles: l = 0, L = ±G; h = 0, H = ±G
    if floats[6]:
        assert floats[0] == 0.0
        assert abs(floats[3]) == floats[4]
    if floats[7]:
        assert floats[2] == 0.0
        assert abs(floats[5]) == floats[4]


@given(states(), st.sampled_from([0.0, 1e-12, 1.0]))
def test_euler_to_hub_paths_agree_hypothesis(state, push):
    # Euler variables of the drawn state, with Φ pushed off Ψ cos θ (infinite momentum on the poles).
    q, m, _ = state
    euler = list(_kernels.hub_to_euler_floats(*q, *m)[:6])
    euler[3] += push * np.linalg.norm(m)
    written = _kernels.euler_to_hub_one(*euler)
    floats = _kernels.euler_to_hub_floats(*euler)
    qc, mc, status = _compiled.euler_to_hub(arrays_of(euler))
    assert_same_bits(written, floats, [*qc[0], *mc[0], status[0]])
    arrays = _kernels.euler_to_hub_arrays(*arrays_of(euler))
    assert int(arrays[7][0]) == floats[7]
    singular = abs(np.sin(euler[1])) <= 2 * ULP_1
    expected = _kernels.SINGULAR if singular else _kernels.REGULAR
    if singular and push > 0:  # beyond the 8ε (|Φ| + |Ψ| + |Θ|) that round-off can give
        expected = _kernels.INFINITE_MOMENTUM
    assert floats[7] == expected
    assert max(abs(float(a[0]) - b) for a, b in zip(arrays[:4], floats[:4], strict=True)) <= 2 * ULP_1
    scale = abs(euler[3]) + abs(euler[4]) + abs(euler[5])
    if floats[7] != _kernels.INFINITE_MOMENTUM:
        # X = (Φ - Ψ cos θ)/sin θ amplifies the last bits of Φ, Ψ by 1/sin θ (the chart's conditioning)
        lever = scale if singular else scale / abs(np.sin(euler[1]))
        error = max(abs(float(a[0]) - b) for a, b in zip(arrays[4:7], floats[4:7], strict=True))
        assert error <= 4 * ULP_1 * lever


@given(states())
@example(  # sin I = 2.8e-8: the round trip is good to ε/sin I there, not to 1e-8
    ([-0.5723969480632974, 0.0, 0.5623742444033327, -0.5967385885625323],
     [-45.60081934492178, 48.38729519354221, 24.41691368968995], "sin I near 0")
)
def test_andoyer_to_hub_paths_agree_hypothesis(state):
    q, m, _ = state
    andoyer = list(_kernels.hub_to_andoyer_floats(*q, *m)[:6])
    written = _kernels.andoyer_to_hub_one(*andoyer)
    floats = _kernels.andoyer_to_hub_floats(*andoyer)
    qc, mc = _compiled.andoyer_to_hub(arrays_of(andoyer))
    assert_same_bits(written, floats, [*qc[0], *mc[0]])
    arrays = _kernels.andoyer_to_hub_arrays(*arrays_of(andoyer))
    assert max(abs(float(a[0]) - b) for a, b in zip(arrays[:4], floats[:4], strict=True)) <= 2 * ULP_1
    G = andoyer[4]
    assert max(abs(float(a[0]) - b) for a, b in zip(arrays[4:], floats[4:], strict=True)) <= 2 * ULP_1 * G
    # and the attitude comes back (an independent check of the pair of kernels): q or -q, to the
    # chart's conditioning near its poles (h and g, or g and l, mix as ε/sin I or ε/sin J)
    back = np.array(floats[:4])
    L, H = andoyer[3], andoyer[5]
    sines = [np.sqrt(max((G - x) * (G + x), 0.0)) / G for x in (L, H)]
    lever = max([1.0] + [1.0 / s for s in sines if s > 0])
    assert min(np.abs(back - q).max(), np.abs(back + q).max()) <= max(1e-8, 8 * ULP_1 * lever)
