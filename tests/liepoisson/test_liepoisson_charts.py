"""Andoyer–Deprit coordinates on so(3), e(3), l(7) leaves against scipy's Andoyer rotation."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer.liepoisson import (
    SingularChartWarning,
    e3_from_andoyer,
    e3_to_andoyer,
    gamma_from_quaternion,
    l7_from_andoyer,
    l7_to_andoyer,
    quaternion_from_scipy,
    quaternion_to_scipy,
    so3_from_andoyer,
    so3_to_andoyer,
)

TWO_PI = 2 * np.pi


def andoyer_points(rng, n, regime):
    """Angles uniform; momenta per regime (generic, near the poles of I and J, scaled)."""
    G = rng.uniform(0.5, 2.0, n) * {"generic": 1.0, "tiny": 1e-9, "huge": 1e9}.get(regime, 1.0)
    if regime == "near-poles":
        sign = rng.choice([-1.0, 1.0], (2, n))
        L = sign[0] * G * (1 - 10 ** rng.uniform(-12, -6, n))
        H = sign[1] * G * (1 - 10 ** rng.uniform(-12, -6, n))
    else:
        L, H = G * rng.uniform(-1, 1, (2, n))
    ell, g, h = rng.uniform(0, TWO_PI, (3, n))
    return ell, g, h, L, G, H


def andoyer_rotation(ell, g, h, L, G, H):
    """Project convention rot = Rz(h) Rx(I) Rz(g) Rx(J) Rz(l), angles computed accurately."""
    inc = np.arctan2(np.sqrt((G - H) * (G + H)), H)
    J = np.arctan2(np.sqrt((G - L) * (G + L)), L)
    return Rotation.from_euler("ZXZ", np.stack([h, inc, g], -1)) * Rotation.from_euler(
        "XZ", np.stack([J, ell], -1)
    )


def angle_diff(a, b):
    return np.abs((a - b + np.pi) % TWO_PI - np.pi)


REGIMES = ["generic", "near-poles", "tiny", "huge"]


@pytest.mark.parametrize("regime", REGIMES)
def test_e3_gamma_and_m_match_andoyer_chart(regime):
    ell, g, h, L, G, H = andoyer_points(np.random.default_rng(10), 20000, regime)
    rot = andoyer_rotation(ell, g, h, L, G, H)
    m, gamma = e3_from_andoyer(ell, g, L, G, H)
    assert np.max(np.abs(gamma - rot.as_matrix()[:, 2, :])) <= 1e-14
    sI = np.sqrt((G - H) * (G + H)) / G
    m_ref = G[:, None] * np.stack([sI * np.sin(h), -sI * np.cos(h), H / G], -1)
    assert np.max(np.abs(rot.apply(m) - m_ref) / G[:, None]) <= 1e-14
    np.testing.assert_allclose(np.sum(m * gamma, -1), H, rtol=0, atol=2e-15 * G.max())


@pytest.mark.parametrize("regime", REGIMES)
def test_l7_quaternion_matches_scipy_up_to_sign(regime):
    ell, g, h, L, G, H = andoyer_points(np.random.default_rng(11), 20000, regime)
    rot = andoyer_rotation(ell, g, h, L, G, H)
    m, lam = l7_from_andoyer(ell, g, h, L, G, H)
    q = quaternion_from_scipy(rot.as_quat())
    sign = np.sign(np.sum(q * lam, -1))[:, None]
    assert np.max(np.abs(lam - sign * q)) <= 1e-14
    assert np.max(np.abs(gamma_from_quaternion(lam) - e3_from_andoyer(ell, g, L, G, H)[1])) <= 1e-14
    assert np.max(np.abs(m - e3_from_andoyer(ell, g, L, G, H)[0]) / G[:, None]) <= 1e-14


def test_l7_quaternion_is_product_of_half_angle_rotations():
    """The sign of λ: λ = q_z(h) q_x(I) q_z(g) q_x(J) q_z(l), continuous and 4π-periodic."""
    ell, g, h, L, G, H = 0.3, 1.0, -0.5, 0.2, 1.0, 0.4
    parts = [
        Rotation.from_euler("Z", h),
        Rotation.from_euler("X", np.arccos(H / G)),
        Rotation.from_euler("Z", g),
        Rotation.from_euler("X", np.arccos(L / G)),
        Rotation.from_euler("Z", ell),
    ]
    lam = quaternion_from_scipy(parts[0].as_quat())
    for p in parts[1:]:  # all these factors have w > 0, so no sign is lost here
        a, b = lam, quaternion_from_scipy(p.as_quat())
        lam = np.array([a[0] * b[0] - a[1:] @ b[1:], *(a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:]))])
    np.testing.assert_allclose(l7_from_andoyer(ell, g, h, L, G, H)[1], lam, atol=1e-15)
    shifted = l7_from_andoyer(ell, g + TWO_PI, h, L, G, H)[1]
    np.testing.assert_allclose(shifted, -lam, atol=1e-15)


@pytest.mark.parametrize("regime", ["generic", "tiny", "huge"])
def test_round_trips_coordinates(regime):
    rng = np.random.default_rng(12)
    ell, g, h, L, G, H = andoyer_points(rng, 20000, regime)
    c = e3_to_andoyer(*e3_from_andoyer(ell, g, L, G, H))
    c7 = l7_to_andoyer(*l7_from_andoyer(ell, g, h, L, G, H))
    # away from the poles, where angles are well defined
    ok = (np.abs(L) < 0.999 * G) & (np.abs(H) < 0.999 * G)
    for got, want in ((c.l, ell), (c.g, g), (c7.l, ell), (c7.g, g), (c7.h, h)):
        assert np.max(angle_diff(got, want)[ok]) <= 1e-13
    for got, want in ((c.L, L), (c.G, G), (c.H, H), (c7.L, L), (c7.G, G), (c7.H, H)):
        assert np.max(np.abs(got - want) / G) <= 1e-13
    for angles in (c.l, c.g, c7.l, c7.g, c7.h):
        assert np.all((angles >= 0) & (angles < TWO_PI))


@pytest.mark.parametrize("regime", REGIMES)
def test_round_trips_algebra_points(regime):
    """(m, γ) → coordinates → (m, γ) and (m, λ) → coordinates → (m, ±λ), everywhere.

    Near the poles the momenta fix sin J = √((G−L)(G+L))/G only to ~ε/sin J (G is a
    rounded |m|): an intrinsic limit of the Andoyer momenta, allowed for in ``bound``.
    """
    ell, g, h, L, G, H = andoyer_points(np.random.default_rng(13), 20000, regime)
    eps = np.finfo(float).eps
    sJ = np.sqrt((G - L) * (G + L)) / G
    sI = np.sqrt((G - H) * (G + H)) / G
    # ≤ 1e-13 at generic points, the intrinsic ε/sin bound near the poles
    bound = np.maximum(1e-13, 4 * eps * (1 / sJ + 1 / sI))[:, None]
    m, gamma = e3_from_andoyer(ell, g, L, G, H)
    m2, gamma2 = e3_from_andoyer(*e3_to_andoyer(m, gamma))
    assert np.all(np.abs(m2 - m) / G[:, None] <= bound)
    assert np.all(np.abs(gamma2 - gamma) <= bound)
    m, lam = l7_from_andoyer(ell, g, h, L, G, H)
    m3, lam3 = l7_from_andoyer(*l7_to_andoyer(m, lam, double_cover=True))
    assert np.all(np.abs(m3 - m) / G[:, None] <= bound)
    assert np.all(np.abs(lam3 - lam) <= bound)
    _, lam4 = l7_from_andoyer(*l7_to_andoyer(m, lam))
    sign = np.sign(np.sum(lam4 * lam, -1))[:, None]
    assert np.all(np.abs(sign * lam4 - lam) <= bound)
    assert np.all(bound[(sJ > 0.02) & (sI > 0.02)] == 1e-13)


def test_round_trip_from_random_algebra_points():
    rng = np.random.default_rng(14)
    m = rng.standard_normal((5000, 3))
    rot = Rotation.random(5000, rng=rng)
    lam = quaternion_from_scipy(rot.as_quat())
    m2, lam2 = l7_from_andoyer(*l7_to_andoyer(m, lam, double_cover=True))
    assert np.max(np.abs(m2 - m)) <= 1e-13 * np.max(np.abs(m))
    assert np.max(np.abs(lam2 - lam)) <= 1e-13
    gamma = rot.inv().apply([0.0, 0.0, 1.0])
    _, gamma3 = e3_from_andoyer(*e3_to_andoyer(m, gamma))
    assert np.max(np.abs(gamma3 - gamma)) <= 1e-13


angles = st.floats(0.0, TWO_PI, allow_nan=False)
unit = st.floats(-1.0, 1.0, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(ell=angles, g=angles, h=angles, x=unit, y=unit, G=st.floats(1e-6, 1e6))
def test_round_trip_hypothesis(ell, g, h, x, y, G):
    L, H = x * G, y * G
    m, lam = l7_from_andoyer(ell, g, h, L, G, H)
    sJ, sI = np.sqrt((1 - x) * (1 + x)), np.sqrt((1 - y) * (1 + y))
    if min(sJ, sI) < 1e-3:  # singular points and their rounding are tested separately
        return
    with np.errstate(invalid="raise", divide="raise", over="raise"):
        m2, lam2 = l7_from_andoyer(*l7_to_andoyer(m, lam, double_cover=True))
        gamma = gamma_from_quaternion(lam)
        _, gamma3 = e3_from_andoyer(*e3_to_andoyer(m, gamma))
    assert np.max(np.abs(lam2 - lam)) <= 1e-13
    assert np.max(np.abs(m2 - m)) <= 1e-13 * G
    assert np.max(np.abs(gamma3 - gamma)) <= 1e-13


def test_so3_chart():
    rng = np.random.default_rng(15)
    m = rng.standard_normal((1000, 3))
    c = so3_to_andoyer(m)
    np.testing.assert_allclose(so3_from_andoyer(*c), m, rtol=0, atol=1e-14 * np.abs(m).max())
    np.testing.assert_allclose(c.G, np.linalg.norm(m, axis=-1), rtol=1e-15)
    np.testing.assert_array_equal(c.L, m[:, 2])


def test_quaternion_conventions():
    rot = Rotation.random(100, rng=np.random.default_rng(16))
    q = rot.as_quat()
    lam = quaternion_from_scipy(q)
    np.testing.assert_array_equal(lam[:, 0], q[:, 3])
    np.testing.assert_array_equal(quaternion_to_scipy(lam), q)
    # Pavlov eq. 2.2 is the third row of rot.as_matrix() (γ = s3 in body components)
    np.testing.assert_allclose(gamma_from_quaternion(lam), rot.as_matrix()[:, 2, :], atol=1e-15)
    np.testing.assert_allclose(gamma_from_quaternion(lam), rot.inv().apply([0, 0, 1]), atol=1e-15)


def test_shapes_scalar_and_broadcast():
    m, gamma = e3_from_andoyer(0.1, 0.2, 0.3, 1.0, -0.2)
    assert m.shape == gamma.shape == (3,)
    c = e3_to_andoyer(m, gamma)
    assert all(np.ndim(v) == 0 for v in c)
    m, lam = l7_from_andoyer(np.zeros((5, 1)), np.linspace(0, 1, 4), 0.0, 0.1, 1.0, 0.2)
    assert m.shape == (5, 4, 3)
    assert lam.shape == (5, 4, 4)
    c7 = l7_to_andoyer(m[:, :1], lam)
    assert all(np.shape(v) == (5, 4) for v in c7)
    c = e3_to_andoyer(m[0], gamma_from_quaternion(lam[:1]))
    assert all(np.shape(v) == (1, 4) for v in c)


def test_singular_body_axis_warns_and_reproduces_point():
    """sin J = 0: m along b3; l is set to 0 and g carries g ± l."""
    for L in (1.3, -1.3):
        _, lam = l7_from_andoyer(0.7, 2.0, 1.0, L, 1.3, 0.4)
        m_exact = np.array([0.0, 0.0, L])
        with pytest.warns(SingularChartWarning, match="sin J"):
            c = l7_to_andoyer(m_exact, lam, double_cover=True)
        assert c.l == 0.0
        np.testing.assert_allclose(l7_from_andoyer(*c)[1], lam, atol=1e-15)
        expected_g = (2.0 + 0.7) if L > 0 else (2.0 - 0.7)
        assert angle_diff(c.g, expected_g) < 1e-14
        gamma = gamma_from_quaternion(lam)
        with pytest.warns(SingularChartWarning, match="sin J"):
            ce = e3_to_andoyer(m_exact, gamma)
        assert ce.l == 0.0
        np.testing.assert_allclose(e3_from_andoyer(*ce)[1], gamma, atol=1e-15)


def test_singular_reference_axis_warns_and_reproduces_point():
    """sin I = 0: m along s3 (l(7): h undefined) or γ parallel to m (e(3): g undefined)."""
    for H in (1.1, -1.1):
        m, lam = l7_from_andoyer(0.7, 2.0, 1.0, 0.3, 1.1, H)
        with pytest.warns(SingularChartWarning, match="sin I"):
            c = l7_to_andoyer(m, lam, double_cover=True)
        assert c.h == 0.0
        np.testing.assert_allclose(l7_from_andoyer(*c)[1], lam, atol=1e-14)
        gamma = np.sign(H) * m / np.linalg.norm(m)
        with pytest.warns(SingularChartWarning, match="sin I"):
            ce = e3_to_andoyer(m, gamma)
        assert ce.g == 0.0
        np.testing.assert_allclose(e3_from_andoyer(*ce)[1], gamma, atol=1e-14)


def test_singular_warning_points_at_caller_and_counts():
    m = np.array([[0.0, 0.0, 1.0], [0.3, 0.1, 1.0]])
    lam = np.array([1.0, 0.0, 0.0, 0.0])
    with pytest.warns(SingularChartWarning, match=r"1 of 2 points") as record:
        l7_to_andoyer(m, lam)
    assert record[0].filename == __file__


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: e3_to_andoyer([1.0, 0, 0], [0.0, 0.0, 1.1]), "expected gamma of unit norm"),
        (lambda: l7_to_andoyer([1.0, 0, 0], [1.0, 0.1, 0, 0]), "expected lam of unit norm"),
        (lambda: gamma_from_quaternion([0.5, 0.5, 0.5, 0.4]), "expected lam of unit norm"),
        (lambda: e3_from_andoyer(0, 0, 0.1, 1.0, 1.01), r"expected \|H\| ≤ G"),
        (lambda: l7_from_andoyer(0, 0, 0, -1.2, 1.0, 0.0), r"expected \|L\| ≤ G"),
        (lambda: e3_from_andoyer(0, 0, 0.0, 0.0, 0.0), "expected G > 0"),
        (lambda: so3_from_andoyer(0, 0.0, -1.0), "expected G > 0"),
        (lambda: e3_to_andoyer([0.0, 0, 0], [0.0, 0, 1]), "expected a non-zero angular momentum"),
        (lambda: e3_to_andoyer(np.ones((2, 3)), np.eye(3)), "expected broadcastable leading"),
        (lambda: l7_to_andoyer(np.ones(3), np.ones(3)), "expected lam with last axis of length 4"),
        (lambda: e3_from_andoyer(np.zeros(2), np.zeros(3), 0.1, 1.0, 0.2), "expected shapes that broadcast"),
        (lambda: l7_from_andoyer(np.nan, 0, 0, 0.1, 1.0, 0.2), "expected finite l"),
        (lambda: quaternion_to_scipy([1.0, 0.0]), "expected lam with last axis of length 4"),
    ],
)
def test_bad_inputs_raise(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_momenta_rounding_is_tolerated():
    G = 1.0
    H = G * (1 + 2e-16)
    _, gamma = e3_from_andoyer(0.1, 0.2, 0.3, G, H)
    assert np.all(np.isfinite(gamma))
