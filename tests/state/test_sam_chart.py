"""The SAM/LAM action–angle chart (Lara eqs. 18–25): formulas, Mathieu and symplectic checks,
axis relabelling (eqs. 3, 37–39), hemispheres, the pole convention and errors."""

from __future__ import annotations

import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, SingularChartWarning, bodies
from andoyer.state.andoyer import andoyer_to_hub, hub_to_andoyer
from andoyer.state.sam import (
    SAM,
    andoyer_from_sam,
    andoyer_parameters,
    hub_to_sam,
    sam_axes,
    sam_energy,
    sam_from_andoyer,
    sam_to_hub,
)

J6 = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.eye(3), np.zeros((3, 3))]])
BODIES = {
    "abc": RigidBody(0.5, 0.75, 1.0),
    "max-on-b1": RigidBody(1.0, 0.6, 0.8),
    "beta-negative": RigidBody(0.9, 0.7, 1.2),
    "eros": bodies.get("eros"),
    "earth": bodies.get("earth"),
}


def wrap(d):
    return np.angle(np.exp(1j * np.asarray(d, dtype=float)))


def jacobian(f, x, angle_outputs=(0, 1, 2), step=1e-5):
    """Richardson-extrapolated central differences, angles differenced on the circle."""

    def column(i, h):
        xp, xm = x.copy(), x.copy()
        xp[i] += h
        xm[i] -= h
        d = np.asarray(f(xp), dtype=float) - np.asarray(f(xm), dtype=float)
        d[list(angle_outputs)] = wrap(d[list(angle_outputs)])
        return d / (2 * h)

    return np.stack([(4 * column(i, step / 2) - column(i, step)) / 3 for i in range(len(x))], axis=1)


def random_andoyer(rng, hemisphere=1.0, G=None):
    G = rng.uniform(0.5, 2.0) if G is None else G
    return np.array(
        [
            *rng.uniform(0, 2 * np.pi, 3),
            hemisphere * G * rng.uniform(0.2, 0.95),
            G,
            G * rng.uniform(-0.9, 0.9),
        ]
    )


# ---------------------------------------------------------------- eq. 3 for any axis labelling


def test_andoyer_parameters_general_eq3_numeric(rng):
    # ½(sin²l/I1 + cos²l/I2)(G² − L²) + L²/(2 I3) = G²/(2 I3)[1 + α(1 − L²/G²)(1 − β cos 2l)]
    # for any positive moments, in any order (Gurfil eq. 89 against Lara eq. 3 generalised).
    moments = rng.uniform(0.2, 3.0, size=(200, 3))
    alpha, beta = andoyer_parameters(*moments.T)
    l = rng.uniform(0, 2 * np.pi, 200)
    G = rng.uniform(0.5, 2, 200)
    L = G * rng.uniform(-1, 1, 200)
    I1, I2, I3 = moments.T
    gurfil = 0.5 * (np.sin(l) ** 2 / I1 + np.cos(l) ** 2 / I2) * (G**2 - L**2) + L**2 / (2 * I3)
    lara = G**2 / (2 * I3) * (1 + alpha * (1 - L**2 / G**2) * (1 - beta * np.cos(2 * l)))
    np.testing.assert_allclose(lara, gurfil, rtol=1e-13)


def test_andoyer_parameters_general_eq3_symbolic():
    I1, I2, I3, G, L, l = sp.symbols("I1 I2 I3 G L l", positive=True)
    alpha = (I3 / I1 + I3 / I2) / 2 - 1
    beta = (I3 / I1 - I3 / I2) / (2 * alpha)
    gurfil = (sp.sin(l) ** 2 / I1 + sp.cos(l) ** 2 / I2) * (G**2 - L**2) / 2 + L**2 / (2 * I3)
    lara = G**2 / (2 * I3) * (1 + alpha * (1 - L**2 / G**2) * (1 - beta * sp.cos(2 * l)))
    assert sp.simplify(sp.expand_trig(gurfil - lara)) == 0


@pytest.mark.parametrize(
    ("moments", "alpha_sign", "beta_sign"),
    [
        ((0.5, 0.75, 1.0), 1, 1),  # b3 maximum, I1 < I2
        ((0.75, 0.5, 1.0), 1, -1),  # b3 maximum, I1 > I2: β < 0
        ((0.75, 1.0, 0.5), -1, -1),  # b3 minimum: α < 0
        ((1.0, 0.75, 0.5), -1, 1),
        ((0.8, 0.8, 1.0), 1, 0),  # I1 = I2: β = 0
    ],
)
def test_andoyer_parameters_signs(moments, alpha_sign, beta_sign):
    alpha, beta = andoyer_parameters(*moments)
    assert np.sign(alpha) == alpha_sign
    assert np.sign(beta) == beta_sign
    # Definition (eq. 2 generalised), checked directly.
    I1, I2, I3 = moments
    assert alpha * (1 + beta) == pytest.approx(I3 / I1 - 1, rel=1e-14)
    assert alpha * (1 - beta) == pytest.approx(I3 / I2 - 1, rel=1e-14)


@pytest.mark.parametrize("name", ["earth", "mars", "moon", "eros"])
def test_sam_axes_match_lara_table_1(name):
    body = bodies.get(name)
    axes = sam_axes(body, "SAM")
    assert axes.permutation == (0, 1, 2)
    assert axes.alpha == pytest.approx(body.alpha, rel=1e-14)
    assert axes.beta == pytest.approx(body.beta, rel=1e-12)


def test_lam_parameters_eqs_37_38_symbolic():
    A, B, C = sp.symbols("A B C", positive=True)
    alpha = (C / A + C / B) / 2 - 1  # eq. 2
    beta = (C / A - C / B) / (2 * alpha)
    alpha_star = (A / C + A / B) / 2 - 1  # eq. 37
    beta_star = (A / C - A / B) / (2 * alpha_star)
    assert sp.simplify(beta_star - (1 - beta) / (1 + 3 * beta)) == 0  # eq. 38
    # The cyclic relabelling (b1', b2', b3') = (b2, b3, b1): moments (B, C, A), β' = −β*.
    alpha_c = (A / B + A / C) / 2 - 1
    beta_c = (A / B - A / C) / (2 * alpha_c)
    assert sp.simplify(alpha_c - alpha_star) == 0
    assert sp.simplify(beta_c + beta_star) == 0


@pytest.mark.parametrize("name", ["abc", "eros", "earth"])
def test_lam_parameters_eqs_37_38_numeric(name):
    body = BODIES[name]
    axes = sam_axes(body, "LAM")
    A, B, C = body.sorted_moments
    assert axes.moments == (B, C, A)
    beta = body.beta
    assert axes.beta == pytest.approx(-(1 - beta) / (1 + 3 * beta), rel=1e-9)
    assert axes.alpha * (1 - axes.beta) == pytest.approx(A / C - 1, rel=1e-13)  # eq. 37 with β' = −β*
    assert axes.alpha * (1 + axes.beta) == pytest.approx(A / B - 1, rel=1e-13)


def test_lam_hamiltonian_is_eq_39(rng):
    # H = M²/(2A)[1 + α* sin²J*(1 + β* cos 2ν*)], J*, ν* the Andoyer J and l of the frame
    # (b2, b3, b1): ν* measured from the node to the body's y axis.
    body = BODIES["abc"]
    A, B, C = body.sorted_moments
    alpha_s = (A / C + A / B) / 2 - 1
    beta_s = (A / C - A / B) / (2 * alpha_s)
    q = Rotation.random(50, rng=rng).as_quat()
    m = rng.normal(size=(50, 3))
    axes = sam_axes(body, "LAM")
    from andoyer._quaternion import multiply

    a = hub_to_andoyer(multiply(q, axes.quaternion), m[:, [1, 2, 0]])
    sin2J = 1 - (a.L / a.G) ** 2
    H = a.G**2 / (2 * A) * (1 + alpha_s * sin2J * (1 + beta_s * np.cos(2 * a.l)))
    np.testing.assert_allclose(H, body.energy(m), rtol=1e-13)


# ------------------------------------------------------------------------ the chart itself


def lara_forward(l, L, G, beta):
    """Eqs. 22 and 25 in mpmath, written independently of the code."""
    with mpmath.workdps(40):
        l, L, G, b = (mpmath.mpf(x) for x in (l, L, G, beta))
        w = mpmath.sqrt(1 - b * mpmath.cos(2 * l))
        ell = mpmath.atan2(-mpmath.sqrt(1 + b) * mpmath.sin(l) / w, mpmath.sqrt(1 - b) * mpmath.cos(l) / w)
        Ls = (G - L) * (1 - b * mpmath.cos(2 * l)) / mpmath.sqrt(1 - b**2)
        return float(ell % (2 * mpmath.pi)), float(Ls)


@pytest.mark.parametrize("beta", [-0.9, -0.3, 0.0, 0.4, 0.977853])
def test_sam_from_andoyer_matches_eqs_22_25(rng, beta):
    for _ in range(20):
        l, g, h, L, G, H = random_andoyer(rng)
        s = sam_from_andoyer(l, g, h, L, G, H, beta=beta)
        ell, Ls = lara_forward(l, L, G, beta)
        assert abs(wrap(s.sam_l - ell)) < 1e-14
        assert s.sam_L == pytest.approx(Ls, rel=1e-13)
        assert abs(wrap(s.sam_g - (g + l))) < 1e-14  # eq. 23
        assert (s.sam_G, s.h, s.H, s.sign) == (G, h % (2 * np.pi), H, 1.0)
        # Eqs. 18 and 21 (the inverse as printed), and the identity of §3.2 for cos 2ν.
        w = 1 + beta * np.cos(2 * s.sam_l)
        assert np.sin(l) == pytest.approx(-np.sqrt(1 - beta) * np.sin(s.sam_l) / np.sqrt(w), abs=1e-14)
        assert np.cos(l) == pytest.approx(np.sqrt(1 + beta) * np.cos(s.sam_l) / np.sqrt(w), abs=1e-14)
        assert abs(L - (G - s.sam_L * w / np.sqrt(1 - beta**2))) < 1e-14 * G
        assert np.cos(2 * l) == pytest.approx((beta + np.cos(2 * s.sam_l)) / w, abs=1e-14)


@settings(max_examples=200, deadline=None)
@given(
    st.floats(0, 2 * np.pi),
    st.floats(0, 2 * np.pi),
    st.floats(-0.999, 0.999),
    st.floats(-0.99, 0.99).filter(lambda x: x != 0),
    st.floats(-0.99, 0.99),
)
def test_sam_andoyer_round_trip_hypothesis(l, g, cosJ, beta, cosI):
    G = 1.7
    s = sam_from_andoyer(l, g, 0.4, G * cosJ, G, G * cosI, beta=beta)
    a = andoyer_from_sam(*s, beta=beta)
    assert abs(wrap(a.l - l)) < 1e-12 / np.sqrt(1 - abs(cosJ))
    assert abs(wrap(a.g - g)) < 1e-12 / np.sqrt(1 - abs(cosJ))
    assert abs(a.L - G * cosJ) < 1e-14 * G  # the map's conditioning: (1 ± β)/s factors
    np.testing.assert_equal([a.G, a.H], [G, G * cosI])


@pytest.mark.parametrize("name", list(BODIES))
@pytest.mark.parametrize("mode", ["SAM", "LAM"])
def test_sam_hub_round_trip_and_energy(rng, name, mode):
    body = BODIES[name]
    axes = sam_axes(body, mode)
    q = Rotation.random(500, rng=rng).as_quat()
    m = rng.normal(size=(500, 3)) * 10.0 ** rng.uniform(-2, 2, size=(500, 1))
    s = hub_to_sam(q, m, body, mode)
    assert set(np.unique(s.sign)) == {-1.0, 1.0}
    q2, m2 = sam_to_hub(*s, body=body, mode=mode)
    G = np.linalg.norm(m, axis=-1)
    assert np.max(np.linalg.norm(m2 - m, axis=-1) / G) < 1e-13  # β' ≈ −0.999 for the Earth in LAM
    dq = np.minimum(np.linalg.norm(q2 - q, axis=-1), np.linalg.norm(q2 + q, axis=-1))
    assert dq.max() < 1e-13
    K = sam_energy(s.sam_l, s.sam_L, s.sam_G, axes.alpha, axes.beta, axes.moments[2])  # eq. 27
    np.testing.assert_allclose(K, body.energy(m), rtol=1e-13)


def test_sam_hub_matches_andoyer_of_relabelled_frame(rng):
    body = BODIES["max-on-b1"]  # b1 is the axis of maximum inertia: frame (b2, b3, b1)
    q = Rotation.random(20, rng=rng).as_quat()
    m = rng.normal(size=(20, 3))
    m[:, 0] = np.abs(m[:, 0]) + 0.1
    axes = sam_axes(body, "SAM")
    assert axes.permutation == (1, 2, 0)
    # Independent route: the relabelled attitude from rotation matrices (columns b2, b3, b1).
    R = Rotation.from_quat(q).as_matrix()[:, :, [1, 2, 0]]
    a = hub_to_andoyer(Rotation.from_matrix(R).as_quat(), m[:, [1, 2, 0]])
    expected = sam_from_andoyer(*a, beta=axes.beta)
    got = hub_to_sam(q, m, body, "SAM")
    for field in ("sam_l", "sam_g", "h"):
        assert np.max(np.abs(wrap(getattr(got, field) - getattr(expected, field)))) < 1e-13
    np.testing.assert_allclose(got.sam_L, expected.sam_L, rtol=1e-11)


def test_sam_negative_hemisphere_is_the_body_turned_about_b1(rng):
    body = BODIES["abc"]
    q = Rotation.random(30, rng=rng).as_quat()
    m = rng.normal(size=(30, 3))
    m[:, 2] = -np.abs(m[:, 2]) - 0.1
    s = hub_to_sam(q, m, body)
    assert np.all(s.sign == -1)
    # The same body seen from the frame (b1, −b2, −b3) rotates about +b3', charted with sign +1.
    turned_q = (Rotation.from_quat(q) * Rotation.from_euler("x", np.pi)).as_quat()
    t = hub_to_sam(turned_q, m * [1, -1, -1], body)
    assert np.all(t.sign == 1)
    for field in ("sam_l", "sam_g", "h"):
        assert np.max(np.abs(wrap(getattr(s, field) - getattr(t, field)))) < 1e-13
    np.testing.assert_allclose(s.sam_L, t.sam_L, rtol=1e-12)
    # The Andoyer-level flip (ν, μ, N) → (π − ν, μ + π, −N) agrees with the hub.
    a = hub_to_andoyer(q, m)
    np.testing.assert_allclose(sam_from_andoyer(*a, beta=body.beta).sam_L, s.sam_L, rtol=1e-11)


# ------------------------------------------------------------------ canonical: Mathieu, MᵀJM


@pytest.mark.parametrize("hemisphere", [1.0, -1.0])
@pytest.mark.parametrize("beta", [-0.6, 0.2, 0.95])
def test_sam_liouville_form_random_tangents(rng, hemisphere, beta):
    # N dν + M dμ + Λ dλ = L dℓ + G dg + H dh on random tangent vectors (a Mathieu map).
    def f(x):
        return np.array(sam_from_andoyer(*x, beta=beta)[:6], dtype=float)

    for _ in range(10):
        x = random_andoyer(rng, hemisphere)
        y = f(x)
        M = jacobian(f, x)
        for v in rng.normal(size=(5, 6)):
            dy = M @ v
            old = x[3] * v[0] + x[4] * v[1] + x[5] * v[2]
            new = y[3] * dy[0] + y[4] * dy[1] + y[5] * dy[2]
            assert abs(old - new) < 1e-9 * x[4] * np.linalg.norm(v)


def test_sam_liouville_form_symbolic():
    # L dℓ/dν = N − M exactly (with dℓ/dμ = 0 and g = μ + ν the forms agree).  Rational
    # parametrisation: β = (1 − τ²)/(1 + τ²), √((1 + β)/(1 − β)) = 1/τ, t = tan ν.
    tau, t, M, N = sp.symbols("tau t M N", positive=True)
    b = (1 - tau**2) / (1 + tau**2)
    ell = sp.atan(-t / tau)  # eq. 22: tan ℓ = −√((1 + β)/(1 − β)) tan ν
    dell_dnu = sp.diff(ell, t) * (1 + t**2)
    cos_2nu = (1 - t**2) / (1 + t**2)
    L = (M - N) * (1 - b * cos_2nu) / (2 * tau / (1 + tau**2))  # eq. 25
    assert sp.cancel(L * dell_dnu + (M - N)) == 0


@pytest.mark.parametrize("hemisphere", [1.0, -1.0])
def test_sam_from_andoyer_is_symplectic(rng, hemisphere):
    for beta in (-0.5, 0.3, 0.9):
        for _ in range(5):
            x = random_andoyer(rng, hemisphere)
            M = jacobian(lambda x, b=beta: np.array(sam_from_andoyer(*x, beta=b)[:6], float), x)
            assert np.abs(M.T @ J6 @ M - J6).max() < 1e-8


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_andoyer_from_sam_is_symplectic(rng, sign):
    for beta in (-0.5, 0.3, 0.9):
        for _ in range(5):
            G = rng.uniform(0.5, 2)
            y = np.array(
                [*rng.uniform(0, 2 * np.pi, 3), G * rng.uniform(0.01, 0.4), G, G * rng.uniform(-0.9, 0.9)]
            )
            M = jacobian(lambda y, b=beta: np.array(andoyer_from_sam(*y, sign, beta=b), float), y)
            assert np.abs(M.T @ J6 @ M - J6).max() < 1e-8


@pytest.mark.parametrize(("name", "mode"), [("abc", "SAM"), ("abc", "LAM"), ("max-on-b1", "SAM")])
def test_state_andoyer_to_sam_through_hub_is_symplectic(rng, name, mode):
    # Andoyer chart of the original frame → hub → SAM chart of the relabelled frame.
    body = BODIES[name]

    def f(x):
        q, m = andoyer_to_hub(*x)
        return np.array(hub_to_sam(q, m, body, mode)[:6], dtype=float)

    for _ in range(8):
        M = jacobian(f, random_andoyer(rng, rng.choice([-1.0, 1.0])))
        assert np.abs(M.T @ J6 @ M - J6).max() < 1e-7


def test_symplectic_check_detects_a_non_mathieu_map(rng):
    def broken(x):
        y = np.array(sam_from_andoyer(*x, beta=0.3)[:6], float)
        y[3] *= 1.001
        return y

    M = jacobian(broken, random_andoyer(rng))
    assert np.abs(M.T @ J6 @ M - J6).max() > 1e-4


# ------------------------------------------------------------------------ pole and accuracy


def as_sam_wrapper(q, m, body):
    """Stands for ``State.as_sam``: the warning must point at the wrapper's caller."""
    return hub_to_sam(q, m, body, "SAM", stacklevel=2)


@pytest.mark.parametrize("m3", [2.0, -2.0])
def test_sam_pole_convention_warns_at_the_caller(m3):
    body = BODIES["abc"]
    q = Rotation.from_euler("ZXZ", [0.3, 0.7, 1.1]).as_quat()
    with pytest.warns(SingularChartWarning, match="sam_l = 0") as record:
        s = as_sam_wrapper(q, [0.0, 0.0, m3], body)
    assert record[0].filename == __file__
    assert (float(s.sam_l), float(s.sam_L), float(s.sign)) == (0.0, 0.0, np.sign(m3))
    q2, m2 = sam_to_hub(*s, body=body)
    assert np.allclose(m2, [0, 0, m3], atol=1e-15)
    assert min(np.linalg.norm(q2 - q), np.linalg.norm(q2 + q)) < 1e-15
    with pytest.warns(SingularChartWarning, match="sam_l = 0") as record:
        sam_from_andoyer(0.7, 0.1, 0.2, 1.0, 1.0, 0.5, beta=0.3)
    assert record[0].filename == __file__


def test_sam_near_pole_keeps_relative_precision():
    # A tiny transverse momentum (δ ~ 1e-18): M − N must not be formed by subtraction.
    body = bodies.get("earth")
    m = np.array([3e-9, -4e-9, 1.0])
    q = Rotation.from_euler("ZXZ", [0.2, 0.4, 0.6]).as_quat()
    s = hub_to_sam(q, m, body)
    with mpmath.workdps(50):
        m1, m2, m3 = (mpmath.mpf(x) for x in m)
        G = mpmath.sqrt(m1**2 + m2**2 + m3**2)
        nu = mpmath.atan2(m1, m2)
        b = mpmath.mpf(body.beta)
        expected = (G - m3) * (1 - b * mpmath.cos(2 * nu)) / mpmath.sqrt(1 - b**2)
    assert float(s.sam_L) == pytest.approx(float(expected), rel=1e-14, abs=0)  # sam_L ~ 1e-17
    _, m_back = sam_to_hub(*s, body=body)
    np.testing.assert_allclose(m_back[:2], m[:2], rtol=1e-12)


def test_sam_chart_shapes_broadcast():
    body = BODIES["abc"]
    s = sam_from_andoyer(np.zeros((2, 1)), 0.0, 0.0, [0.5, 0.9, -0.9], 1.0, 0.2, beta=0.4)
    assert all(np.shape(v) == (2, 3) for v in s)
    assert isinstance(s, SAM)
    q, m = sam_to_hub(0.1, 0.2, 0.3, [[0.01], [0.02]], 1.0, 0.5, [1.0, -1.0], body=body)
    assert q.shape == (2, 2, 4)
    assert m.shape == (2, 2, 3)
    scalar = hub_to_sam(q[0, 0], m[0, 0], body)
    assert all(np.shape(v) == () for v in scalar)


# -------------------------------------------------------------------------------- errors


@pytest.mark.parametrize(
    ("body", "mode", "match"),
    [
        (RigidBody(0.5, 1.0, 1.0), "SAM", "unique axis of maximum"),
        (RigidBody(1.0, 1.0, 1.5), "LAM", "unique axis of minimum"),
        (RigidBody(1.0, 1.0, 1.0), "SAM", "unique axis"),
        (RigidBody(1.0, 2.0, 2.5), "XAM", "mode 'SAM' or 'LAM'"),
    ],
)
def test_sam_axes_errors(body, mode, match):
    with pytest.raises(ValueError, match=match):
        sam_axes(body, mode)


def test_sam_chart_errors():
    body = BODIES["abc"]
    with pytest.raises(ValueError, match="expected -1 < beta < 1"):
        sam_from_andoyer(0, 0, 0, 0.5, 1, 0, beta=1.0)
    with pytest.raises(ValueError, match=r"expected \|L\| <= G"):
        sam_from_andoyer(0, 0, 0, 1.5, 1, 0, beta=0.2)
    with pytest.raises(ValueError, match="sam_L >= 0"):
        andoyer_from_sam(0, 0, 0, -0.1, 1, 0, beta=0.2)
    with pytest.raises(ValueError, match="sign = "):
        andoyer_from_sam(0, 0, 0, 0.1, 1, 0, 0.0, beta=0.2)
    with pytest.raises(ValueError, match="N >= -G"):
        sam_to_hub(0, 0, 0, 5.0, 1, 0, body=body)
    with pytest.raises(ValueError, match="sam_G > 0"):
        sam_to_hub(0, 0, 0, 0.1, 0.0, 0, body=body)
    with pytest.raises(ValueError, match="non-zero angular momentum"):
        hub_to_sam([0, 0, 0, 1.0], [0.0, 0.0, 0.0], body)
    with pytest.raises(ValueError, match="RigidBody"):
        hub_to_sam([0, 0, 0, 1.0], [0.0, 0.0, 1.0], "earth")
    with pytest.raises(ValueError, match="harmonic mean"):
        andoyer_parameters(1.0, 3.0, 1.5)
    with pytest.raises(ValueError, match="finite"):
        sam_from_andoyer(np.nan, 0, 0, 0.5, 1, 0, beta=0.2)


def test_sam_chart_no_warning_off_the_pole(rng):
    body = BODIES["eros"]
    q = Rotation.random(100, rng=rng).as_quat()
    m = rng.normal(size=(100, 3))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = hub_to_sam(q, m, body)
    assert np.all(np.isfinite(np.array(s[:6], dtype=float)))
