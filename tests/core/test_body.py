from __future__ import annotations

import dataclasses
import warnings
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import andoyer
from andoyer import Regime, RigidBody, Symmetry, bodies
from andoyer.body import NonPhysicalInertiaWarning

# Lara (2013) Table 1: beta as printed (7 significant digits).
TABLE1_BETA = {"mars": 0.0646316, "earth": 0.0003366, "moon": 0.226105, "eros": 0.977853}


@pytest.mark.parametrize(("name", "beta"), TABLE1_BETA.items())
def test_bodies_beta_matches_lara_table1(name, beta):
    assert bodies.get(name).beta == pytest.approx(beta, abs=6e-7)


@pytest.mark.parametrize("name", bodies.names())
def test_bodies_alpha_beta_satisfy_lara_eq2(name):
    body = bodies.get(name)
    A, B, C = body.A, body.B, body.C
    assert body.alpha * (1 + body.beta) == pytest.approx(C / A - 1, rel=1e-14)
    assert body.alpha * (1 - body.beta) == pytest.approx(C / B - 1, rel=1e-13)


def test_bodies_get_is_case_insensitive_and_rejects_unknown():
    assert bodies.get(" EARTH ") is bodies.get("earth")
    with pytest.raises(ValueError, match=r"expected one of .*, got 'pluto'"):
        bodies.get("pluto")


def test_body_sorted_moments_and_axis_order():
    body = RigidBody(3.0, 1.0, 2.5)
    assert body.sorted_moments == (1.0, 2.5, 3.0)
    assert body.moments[list(body.axis_order)].tolist() == [1.0, 2.5, 3.0]


@pytest.mark.parametrize(
    ("moments", "symmetry", "beta", "kappa"),
    [
        ((1.0, 2.0, 2.5), Symmetry.TRIAXIAL, (2.5 - 1.25) / (2.5 + 1.25 - 2), np.sqrt(2.5 / 0.5)),
        ((1.0, 1.0, 1.5), Symmetry.OBLATE, 0.0, 0.0),
        ((0.5, 1.0, 1.0), Symmetry.PROLATE, 1.0, np.inf),
        ((2.0, 2.0, 2.0), Symmetry.SPHERICAL, 0.0, 0.0),
    ],
)
def test_body_symmetry_beta_kappa_regimes(moments, symmetry, beta, kappa):
    body = RigidBody(*moments)
    assert body.symmetry is symmetry
    assert body.beta == pytest.approx(beta, rel=1e-15)
    assert body.kappa == pytest.approx(kappa, rel=1e-15)
    assert body.is_axisymmetric is (symmetry is not Symmetry.TRIAXIAL)


def test_body_euler_coefficients_exact_on_near_axisymmetric_earth():
    import mpmath

    mpmath.mp.dps = 40
    earth = bodies.get("earth")
    I1, I2, I3 = (mpmath.mpf(x) for x in earth.moments)
    exact = [(I2 - I3) / (I2 * I3), (I3 - I1) / (I3 * I1), (I1 - I2) / (I1 * I2)]
    got = earth.euler_coefficients
    for c, ref in zip(got, exact, strict=True):
        assert abs(c - float(ref)) <= 2e-16 * abs(float(ref))


@pytest.mark.parametrize(
    ("m", "mode"),
    [([0.01, 0.0, 1.0], "SAM"), ([1.0, 0.0, 0.01], "LAM"), ([0.0, 1.0, 0.0], "separatrix")],
)
def test_body_rotation_mode_triaxial(m, mode):
    body = RigidBody(1.0, 2.0, 2.5)
    with pytest.warns(DeprecationWarning, match="use RigidBody.regime"):
        assert body.rotation_mode(m) == mode
    # The classification agrees with the energy test 2T/G^2 vs 1/B done directly.
    two_t_over_g2 = 2 * body.energy(m) / np.dot(m, m)
    expected = (
        "SAM" if two_t_over_g2 < 1 / 2.0 - 1e-15 else "LAM" if two_t_over_g2 > 0.5 + 1e-15 else "separatrix"
    )
    assert mode == expected


def test_body_rotation_mode_axisymmetric_is_steady_and_vectorised():
    with pytest.warns(DeprecationWarning, match="rotation_mode is deprecated"):
        modes = RigidBody(1.0, 1.0, 1.5).rotation_mode(np.ones((4, 2, 3)))
    assert modes.shape == (4, 2)
    assert set(modes.ravel().tolist()) == {"steady"}


@pytest.mark.parametrize(
    ("moments", "m", "regime", "mode"),
    [
        ((1.0, 2.0, 3.0), (0.1, 0.2, 1.0), Regime.SAM, "SAM"),
        ((1.0, 2.0, 3.0), (1.0, 0.2, 0.1), Regime.LAM, "LAM"),
        ((3.0, 4.0, 6.0), (1.0, 0.7, -1.0), Regime.SEPARATRIX, "separatrix"),
        ((2.0, 2.0, 3.0), (0.3, 0.1, 1.0), Regime.AXISYMMETRIC, "steady"),
        ((2.0, 3.0, 3.0), (0.3, 0.1, 1.0), Regime.AXISYMMETRIC, "steady"),
        ((2.0, 2.0, 2.0), (0.3, 0.1, 1.0), Regime.SPHERE, "steady"),
        ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0), Regime.REST, "steady"),
    ],
)
def test_body_rotation_mode_is_a_view_of_regime(moments, m, regime, mode):
    # (3, 4, 6), |m1| = |m3|: m_C^2 (C - B) A = m_A^2 (B - A) C = 6 exactly
    body = RigidBody(*moments)
    assert body.regime(m) == regime
    with pytest.warns(DeprecationWarning, match="rotation_mode is deprecated"):
        got = body.rotation_mode(m)
    assert got.shape == ()
    assert str(got) == mode


def test_body_regime_broadcasts_leading_shape():
    body = RigidBody(1.0, 2.0, 3.0)
    m = np.zeros((4, 2, 3))
    m[..., 2] = 1.0
    m[0, 1] = (1.0, 0.0, 0.0)
    got = body.regime(m)
    assert got.shape == (4, 2)
    assert got.dtype == np.int8
    assert got[0, 1] == Regime.LAM
    assert np.count_nonzero(got == Regime.SAM) == 7
    with pytest.raises(ValueError, match=r"m_body with shape \(\.\.\., 3\)"):
        body.regime([1.0, 2.0])
    with pytest.raises(ValueError, match="m_body"):
        body.regime([1.0, np.nan, 2.0])


def test_body_rotation_mode_enum_is_deprecated_where_used():
    with pytest.warns(DeprecationWarning, match="RotationMode is deprecated") as caught:
        mode = andoyer.RotationMode
    assert caught[0].filename == __file__
    with pytest.warns(DeprecationWarning, match="RotationMode is deprecated") as caught:
        from andoyer.body import RotationMode
    assert caught[0].filename == __file__
    assert mode is RotationMode
    assert RotationMode.STEADY.value == "steady"
    with pytest.warns(DeprecationWarning, match="rotation_mode is deprecated") as caught:
        RigidBody(1.0, 2.0, 3.0).rotation_mode([0.0, 0.0, 1.0])
    assert caught[0].filename == __file__
    assert "RotationMode" not in andoyer.__all__


@settings(max_examples=200, deadline=None)
@given(alpha=st.floats(0.0, 50.0), beta=st.floats(0.0, 1.0), C=st.floats(1e-6, 1e12))
def test_body_from_alpha_beta_round_trip(alpha, beta, C):
    # A + B >= C  <=>  1/(1 + α(1 + β)) + 1/(1 + α(1 − β)) >= 1  <=>  α²(1 − β²) <= 1 (exact
    # rationals, away from the boundary where rounding decides)
    a, b = Fraction(alpha), Fraction(beta)
    margin = 1 - a * a * (1 - b * b)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        body = RigidBody.from_alpha_beta(alpha, beta, C)
    if abs(margin) > Fraction(1, 10**9):
        assert bool(caught) is (margin < 0)
        assert body.is_physical is (margin > 0)
    assert all(issubclass(w.category, NonPhysicalInertiaWarning) for w in caught)
    assert body.alpha == pytest.approx(alpha, rel=1e-12, abs=1e-15)
    if alpha > 1e-6:
        assert body.beta == pytest.approx(beta, rel=1e-9, abs=1e-9)


NONPHYSICAL_MAKERS = {
    "init": lambda: RigidBody(3.0, 3.0, 9.0),
    "from_moments": lambda: RigidBody.from_moments([1.0, 2.0, 4.0]),
    "from_ratios": lambda: RigidBody.from_ratios(0.2, 0.5),
    "from_alpha_beta": lambda: RigidBody.from_alpha_beta(3.0, 0.5),
    "replace": lambda: dataclasses.replace(RigidBody(1.0, 2.0, 3.0), I3=9.0),
}


@pytest.mark.parametrize("maker", NONPHYSICAL_MAKERS)
def test_body_breaking_triangle_inequality_warns_at_the_callers_line(maker):
    with pytest.warns(NonPhysicalInertiaWarning, match=r"A \+ B = .* < C = .* triangle inequality") as caught:
        body = NONPHYSICAL_MAKERS[maker]()
    assert len(caught) == 1
    # the user's line (the lambda above), not a line inside andoyer or dataclasses
    assert caught[0].filename == __file__
    assert caught[0].lineno == NONPHYSICAL_MAKERS[maker].__code__.co_firstlineno
    assert not body.is_physical
    assert issubclass(NonPhysicalInertiaWarning, UserWarning)


@pytest.mark.parametrize(
    "moments",
    [(1.0, 2.0, 3.0), (1.0, 1.0, 2.0), (0.3, 0.7, 1.0), (0.1, 0.2, 0.3), (1.0, 5.0, 5.0), (2.0, 2.0, 2.0)],
)
def test_body_physical_and_lamina_moments_do_not_warn(moments):
    # Laminas A + B = C, also where A + B rounds below C in floating point (0.1 + 0.2 = 0.30000000000000004
    # but 0.3 + 0.7 = 0.9999999999999999); prolate bodies and spheres always satisfy the inequality.
    body = RigidBody(*moments)  # filterwarnings = error: a warning would fail here
    assert body.is_physical


@pytest.mark.parametrize("moments", [(3.0, 3.0, 9.0), (1.0, 2.0, 4.0), (4.0, 0.5, 0.7), (1.0, 1.5, 100.0)])
def test_body_parameters_of_nonphysical_body(moments):
    # Lara eq. 2 and Gurfil eq. 139 solved in exact rationals from the sorted moments.
    with pytest.warns(NonPhysicalInertiaWarning):
        body = RigidBody(*moments)
    A, B, C = (Fraction(x) for x in sorted(moments))
    alpha = (C / A + C / B) / 2 - 1
    beta = (C / A - C / B) / (2 * alpha)
    assert body.alpha == pytest.approx(float(alpha), rel=1e-15)
    assert body.beta == pytest.approx(float(beta), rel=1e-14, abs=1e-16)
    assert 0 <= body.beta < 1
    assert body.kappa == pytest.approx(np.sqrt(float(C * (B - A) / (A * (C - B)))), rel=1e-15)
    assert body.symmetry is (Symmetry.OBLATE if A == B else Symmetry.TRIAXIAL)


def test_body_repr_is_readable():
    assert repr(RigidBody(1.0, 2.0, 2.5, name="x")) == "RigidBody(I1=1.0, I2=2.0, I3=2.5, name='x')"
    assert "Earth" in repr(bodies.get("earth"))
